#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Point queries against exact values computed here (tests/point/point_exact.py, mpmath 50 digits).
usage: point_exact_check.py REFCHECK DATA_DIR"""
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from checks import check, finish  # noqa: E402

refcheck, data = sys.argv[1], sys.argv[2]
here = os.path.dirname(os.path.abspath(__file__))
for kind in ("pc", "pd"):
    for s in ("hard", "random"):
        q = os.path.join(data, "%s_%s.txt" % (kind, s))
        exact = subprocess.run([sys.executable, os.path.join(here, "point_exact.py"), q],
                               capture_output=True, text=True, check=True).stdout
        with tempfile.NamedTemporaryFile("w", suffix=".expected", delete=False) as f:
            f.write(exact)
        r = subprocess.run([refcheck, "--tol=1e-15", q, f.name], capture_output=True, text=True)
        os.unlink(f.name)
        print(r.stdout.strip().splitlines()[-2] if r.stdout else r.stderr)
        check(r.returncode == 0, "%s against exact values:\n%s" % (q, r.stderr[-2000:]))
finish("point_exact_check")
