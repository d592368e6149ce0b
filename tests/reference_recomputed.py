#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""The shared reference checked against mpmath where it changed: every line listed in
tests/data/revision2_recomputed.txt (the 68 hard lines recomputed in revision 2) is recomputed
here with the project's own high-precision brute forces (point_exact.py, lc_exact.py,
disk_exact.py, cc_exact.py; 40..60 digits) and the expected value must agree to TOL of scale
(scale as ../shared/cases/README.md defines it). usage: reference_recomputed.py DATA_DIR [TOL]"""
import math
from decimal import Decimal
import os
import subprocess
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "common"))
from checks import check, finish  # noqa: E402

# Brute force per kind: command (before the query file) and whether it prints "LINE VALUE".
EXACT = {
    "pc": ([os.path.join(here, "point", "point_exact.py")], False),
    "pd": ([os.path.join(here, "point", "point_exact.py")], False),
    "lc": ([os.path.join(here, "lines", "lc_exact.py")], False),
    "ld": ([os.path.join(here, "circles", "disk", "disk_exact.py")], False),
    "cd": ([os.path.join(here, "circles", "disk", "disk_exact.py"), "--samples=4096"], False),
    "cc": ([os.path.join(here, "circles", "circle_circle", "cc_exact.py")], True),
}


def scale(kind, v, d):
    """README.md's L: largest of the radii, the distance and the centres' separation (a line
    contributes its point nearest the circle's centre)."""
    if kind in ("pc", "pd"):
        return max(d, v[9], math.dist(v[0:3], v[3:6]))
    if kind in ("lc", "ld"):
        B, M, C = v[0:3], v[3:6], v[6:9]
        t = sum((C[i] - B[i]) * M[i] for i in range(3)) / sum(x * x for x in M)
        return max(d, v[12], math.dist([B[i] + t * M[i] for i in range(3)], C))
    return max(d, v[6], v[13], math.dist(v[0:3], v[7:10]))


def main():
    data = sys.argv[1]
    tol = float(sys.argv[2]) if len(sys.argv) > 2 else 2.5e-15
    wanted = {}
    for line in open(os.path.join(data, "revision2_recomputed.txt")):
        f = line.split("#")[0].split()
        if f:
            wanted.setdefault(f[0], []).append(int(f[1]))
    check(sum(len(x) for x in wanted.values()) == 68, "68 recomputed lines listed")
    worst = 0.0
    for name, lines in sorted(wanted.items()):
        kind = name[:2]
        queries = open(os.path.join(data, name)).read().splitlines()
        expected = open(os.path.join(data, name.replace(".txt", ".expected"))).read().split()
        with tempfile.NamedTemporaryFile("w", suffix=".txt", delete=False) as tmp:
            tmp.write("".join(queries[ln - 1] + "\n" for ln in lines))
        cmd, numbered = EXACT[kind]
        out = subprocess.run([sys.executable] + cmd + [tmp.name], capture_output=True, text=True,
                             check=True).stdout.split("\n")
        os.unlink(tmp.name)
        values = [x.split()[-1] for x in out if x.strip()]
        check(len(values) == len(lines), "%s: %d exact values for %d lines" % (name, len(values), len(lines)))
        for ln, exact in zip(lines, values):
            f = queries[ln - 1].split()
            check(f[0] == kind, "%s line %d is a %s query" % (name, ln, kind))
            v = [float(x) for x in f[1:]]
            # the difference in decimal: both are given to more digits than a double holds
            diff = abs(Decimal(expected[ln - 1]) - Decimal(exact))
            err = float(diff) / scale(kind, v, float(exact))
            worst = max(worst, err)
            check(err <= tol, "%s line %d: expected %s, mpmath %s, off by %.3g of scale"
                  % (name, ln, expected[ln - 1], exact, err))
    print("reference_recomputed: worst %.3g of scale (tol %.3g)" % (worst, tol))
    finish("reference_recomputed")


if __name__ == "__main__":
    main()
