#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""The exported symbols, the version script and the public header agree.

usage: check_symbols.py LIBRARY VERSION_SCRIPT HEADER
- every function declared CDIST_API in the header is in the version script and vice versa;
- the library exports exactly those, each with a version node from the script;
- the soname is libcircledist.so.<major>;
- it needs no GSL (no NEEDED entry, no undefined gsl_ symbol): libc and libm only.
"""
import os
import re
import subprocess
import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "common"))
from checks import check, finish  # noqa: E402

lib, mapfile, header = sys.argv[1:4]
if lib.endswith(".a"):
    print("SKIP: %s is a static archive (-Ddefault_library=static): no dynamic symbol table or "
          "soname to check (check_static_symbols.py checks the archive's names)" % lib)
    sys.exit(77)
hdr = open(header).read()
declared = set(re.findall(r"CDIST_API\s[^;(]*?\b(cdist_\w+)\s*\(", hdr, re.S))
maptext = re.sub(r"/\*.*?\*/", "", open(mapfile).read(), flags=re.S)
nodes = {}
for node, body in re.findall(r"([\w.]+)\s*{(.*?)}", maptext, re.S):
    glob = body.split("local:")[0].replace("global:", "")
    for sym in re.findall(r"\b(cdist_\w+)\s*;", glob):
        nodes[sym] = node
out = subprocess.run(["objdump", "-T", lib], capture_output=True, text=True, check=True).stdout
exported = {}
for line in out.splitlines():
    parts = line.split()
    if len(parts) >= 7 and " .text" in line and "DF" in line:
        exported[parts[-1]] = parts[-2]
dyn = subprocess.run(["objdump", "-p", lib], capture_output=True, text=True, check=True).stdout
soname = re.search(r"SONAME\s+(\S+)", dyn)


check(len(declared) > 10, "header declarations found: %d" % len(declared))
check(declared == set(nodes), "header vs map: only header %s, only map %s"
      % (sorted(declared - set(nodes)), sorted(set(nodes) - declared)))
check(set(exported) == set(nodes), "exports vs map: only exported %s, only map %s"
      % (sorted(set(exported) - set(nodes)), sorted(set(nodes) - set(exported))))
for sym, ver in exported.items():
    check(ver.strip("()") == nodes.get(sym), "%s has version %s, map says %s" % (sym, ver, nodes.get(sym)))
check(soname is not None and soname.group(1) == "libcircledist.so.1", "soname %s" % (soname and soname.group(1)))
needed = re.findall(r"NEEDED\s+(\S+)", dyn)
check(not [n for n in needed if "gsl" in n], "the library needs %s" % needed)
undefined = [line.split()[-1] for line in out.splitlines() if "*UND*" in line]
check(len(undefined) > 0, "undefined symbols listed (libc's)")
check(not [u for u in undefined if u.startswith("gsl_")], "the library calls GSL: %s"
      % sorted(u for u in undefined if u.startswith("gsl_")))
finish("check_symbols")
