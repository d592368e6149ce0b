#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""The static archive defines no global name outside the library's namespace: every defined
global symbol is exported by the version script (circledist.map) or starts with the reserved
internal prefix cdist__ (a static link has no version script to hide internal names, so they
must not collide with the application's). Nor does it reference GSL: the library depends on libc
and libm only (GSL is the tests' reference for the polynomial solver).

usage: check_static_symbols.py ARCHIVE VERSION_SCRIPT
"""
import os
import re
import subprocess
import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "common"))
from checks import check, finish  # noqa: E402

archive, mapfile = sys.argv[1:3]
maptext = re.sub(r"/\*.*?\*/", "", open(mapfile).read(), flags=re.S)
exported = set()
for body in re.findall(r"{(.*?)}", maptext, re.S):
    exported |= set(re.findall(r"\b(cdist_\w+)\s*;", body.split("local:")[0]))
out = subprocess.run(["nm", "-g", "--defined-only", archive], capture_output=True, text=True, check=True).stdout
defined = set()
for line in out.splitlines():
    parts = line.split()
    if len(parts) == 3:
        defined.add(parts[2])
check(len(exported) > 10, "exported names in %s: %d" % (mapfile, len(exported)))
check(exported <= defined, "in the map but not defined in the archive: %s" % sorted(exported - defined))
# (names the sanitizers add for instrumented globals, e.g. __odr_asan.NAME, are not ours)
stray = sorted(s for s in defined if s not in exported and not s.startswith("cdist__")
               and not s.startswith(("__odr_asan", "___asan_gen_", "__asan_", "__ubsan_")))
check(not stray, "%d global names neither exported nor cdist__-prefixed: %s" % (len(stray), " ".join(stray)))
undefined = subprocess.run(["nm", "-g", "--undefined-only", archive], capture_output=True, text=True,
                           check=True).stdout.split()
gsl = sorted(set(u for u in undefined if u.startswith("gsl_")))
check(not gsl, "the archive references GSL: %s" % " ".join(gsl))
finish("check_static_symbols")
