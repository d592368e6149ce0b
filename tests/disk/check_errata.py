#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Recomputes the cd_* and ld_* lines of tests/data/errata.txt with the mpmath brute force of
disk_exact.py and checks each erratum (to 1e-20 of scale) and that the shared value it replaces
is really off by more than 1e-14 of scale.
usage: check_errata.py DATA_DIR"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import disk_exact as X  # noqa: E402
from mpmath import mpf  # noqa: E402


def main():
    data = sys.argv[1]
    fails = n = 0
    for line in open(os.path.join(data, "errata.txt")):
        f = line.split("#")[0].split()
        if len(f) < 3 or not (f[0].startswith("cd_") or f[0].startswith("ld_")):
            continue
        name, ln, val = f[0], int(f[1]), mpf(f[2])
        q = open(os.path.join(data, name)).read().splitlines()[ln - 1].split()
        shared = mpf(open(os.path.join(data, name.replace(".txt", ".expected"))).read().split()[ln - 1])
        ex = X.exact(q, 4096)
        v = [float(x) for x in q[1:]]
        if q[0] == "cd":
            L = max(float(ex), v[6], v[13], math.dist(v[0:3], v[7:10]))
        else:
            M, C = v[3:6], v[6:9]
            t = sum((C[i] - v[i]) * M[i] for i in range(3)) / sum(x * x for x in M)
            L = max(float(ex), v[12], math.dist([v[i] + t * M[i] for i in range(3)], C))
        e_err, s_err = float(abs(ex - val)) / L, float(abs(shared - ex)) / L
        n += 1
        ok = e_err <= 1e-20 and s_err > 1e-14
        fails += not ok
        print("%s %s line %d: erratum off by %.2g, shared off by %.2g of scale" % ("ok" if ok else "FAIL", name, ln, e_err, s_err))
    print("check_errata: %d lines, %d failed" % (n, fails))
    return 1 if fails or n == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
