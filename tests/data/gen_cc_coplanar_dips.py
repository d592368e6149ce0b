#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Expected distances of tests/data/cc_coplanar_dips.txt, independently of the library.

Nearly coplanar circles where one passes near the other's centre (so near its axis) and crosses
its rim: the distance has narrow dips (width ~ |h| / R rad) at the rim crossings, next to the
kink at the axis crossing. Each line's minimum is computed in mpmath (60 digits) from the
closed-form point-circle distance, with the inputs taken exactly as the doubles in the file:
both circles are parameterised in turn, the angle sampled at N points, and every sampled local
minimum polished by golden-section search (the distance is unimodal between the neighbours of a
sampled local minimum: near a rim crossing it is sqrt((rho - s)^2 + h^2) with rho - s and h
nearly linear). The smaller of the two parameterisations' minima is the expected distance.

usage: tests/data/gen_cc_coplanar_dips.py [QUERIES [EXPECTED]]   (defaults: the files next to
this script; writes EXPECTED, one distance a line, 21 significant digits)
"""
import os
import sys

from mpmath import mp, mpf, cos, sin, sqrt, pi

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "circles", "disk"))
from disk_exact import golden  # noqa: E402  (the mpmath references' golden-section search)

mp.dps = 60
N = 4096          # samples per parameterisation
GOLDEN_SHRINK = mpf("0.618") ** 200  # of the 2-sample bracket: far below the answer's resolution


def unit(a):
    n = sqrt(sum(x * x for x in a))
    return [x / n for x in a]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def min_over(Cp, Np, rp, Cf, Nf, rf):
    """Minimum over the circle (Cp, Np, rp) of its distance to the circle (Cf, Nf, rf)."""
    Np, Nf = unit(Np), unit(Nf)
    e = [1, 0, 0] if abs(Np[0]) < 0.6 else [0, 1, 0]
    U = unit([e[i] - dot(e, Np) * Np[i] for i in range(3)])
    V = cross(Np, U)

    def d(t):
        P = [Cp[i] + rp * (cos(t) * U[i] + sin(t) * V[i]) - Cf[i] for i in range(3)]
        h = dot(P, Nf)
        w = cross(Nf, P)  # |w| = distance to the axis, without cancellation
        return sqrt(h * h + (sqrt(dot(w, w)) - rf) ** 2)

    step = 2 * pi / N
    vals = [d(k * step) for k in range(N)]
    best = min(vals)
    for k in range(N):
        if vals[k] <= vals[k - 1] and vals[k] <= vals[(k + 1) % N]:
            best = min(best, golden(d, (k - 1) * step, (k + 1) * step, GOLDEN_SHRINK * 2 * step))
    return best


def expected(nums):
    v = [mpf(float(x)) for x in nums]  # exactly the doubles of the file
    C0, N0, r0, C1, N1, r1 = v[0:3], v[3:6], v[6], v[7:10], v[10:13], v[13]
    return min(min_over(C0, N0, r0, C1, N1, r1), min_over(C1, N1, r1, C0, N0, r0))


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    qf = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "cc_coplanar_dips.txt")
    ef = sys.argv[2] if len(sys.argv) > 2 else os.path.join(here, "cc_coplanar_dips.expected")
    out = []
    for line in open(qf):
        s = line.split()
        if not s or s[0].startswith("#"):
            continue
        assert s[0] == "cc" and len(s) == 15, line
        out.append(mp.nstr(expected(s[1:]), 21, min_fixed=-60, max_fixed=60))
        print(out[-1], file=sys.stderr)
    with open(ef, "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
