#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""The public header compiles cleanly (-pedantic -Werror) as C89, C99, C11, C17, C++98, C++11
and C++17, with the project's compilers and with clang/clang++ when installed.

usage: check_header_std.py SOURCE INCLUDE_DIR GENERATED_INCLUDE_DIR 'CC CMD' 'CXX CMD'
"""
import os
import shlex
import shutil
import subprocess
import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from checks import check, finish  # noqa: E402

source, inc, geninc, cc, cxx = sys.argv[1:6]
flags = ["-fsyntax-only", "-pedantic", "-Werror", "-Wall", "-Wextra", "-I", inc, "-I", geninc]
compilers = [(shlex.split(cc), "c", ["c89", "c99", "c11", "c17"]),
             (shlex.split(cxx), "c++", ["c++98", "c++11", "c++17"])]
for name, lang, stds in (("clang", "c", ["c89", "c11"]), ("clang++", "c++", ["c++98", "c++17"])):
    if shutil.which(name):
        compilers.append(([name], lang, stds))

for cmd, lang, stds in compilers:
    for std in stds:
        args = cmd + ["-x", lang, "-std=" + std] + flags + [source]
        p = subprocess.run(args, capture_output=True, text=True)
        check(p.returncode == 0, "%s -std=%s:\n%s" % (cmd[-1], std, p.stderr.strip()))
        print("%s -std=%s: %s" % (" ".join(cmd), std, "ok" if p.returncode == 0 else "FAILED"))
finish("check_header_std")
