#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""The built library keeps the ABI of the committed baseline (abi/libcircledist.so.1.abi).

usage: check_abi.py BASELINE LIBRARY PUBLIC_HEADERS_DIR
abidiff compares every function and type of the baseline with the library: a removed function,
a changed signature, a moved or retyped struct field or a renumbered enumerator fails.
Added functions, types and appended enumerators pass (--no-added-syms; abidiff counts an
appended enumerator as harmless). Exits 77 (skipped) when abigail-tools is not installed.
"""
import os
import shutil
import subprocess
import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from checks import check, finish  # noqa: E402

baseline, lib, headers = sys.argv[1:4]
if shutil.which("abidiff") is None:
    print("SKIP: abidiff not found; install abigail-tools (scripts/install-deps.sh) to check the ABI")
    sys.exit(77)

# Without DWARF, abidiff sees symbols only and reports a swapped struct field as no change.
sections = subprocess.run(["readelf", "-S", "-W", lib], capture_output=True, text=True, check=True).stdout
check(".debug_info" in sections, "%s has no debug info, so abidiff could not see its types" % lib)
base = open(baseline).read()
check("<class-decl name='cdist_result'" in base and "layout-offset-in-bits" in base,
      "%s holds no struct layouts (generate it from a library with debug info: "
      "scripts/update-abi-baseline.sh)" % baseline)

p = subprocess.run(["abidiff", "--no-added-syms", "--drop-private-types", "--headers-dir2", headers,
                    baseline, lib], capture_output=True, text=True)
print(p.stdout + p.stderr, end="")
bits = {1: "abidiff error", 2: "abidiff usage error", 4: "ABI change of a baseline function or type",
        8: "incompatible ABI change (removed function or variable)"}
check(p.returncode == 0, "abidiff exit %d: %s; if the change is intended for a new soname, update the "
      "baseline (docs/abi.md)" % (p.returncode, ", ".join(v for k, v in bits.items() if p.returncode & k)))
finish("check_abi")
