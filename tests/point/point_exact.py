#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Exact point-circle / point-disk distances of a query file, for the doubles as given.

An independent reference for tests (mpmath, 50 digits, closed form with |N x D| for the
axis distance and the normal normalised exactly). usage: point_exact.py QUERIES > EXPECTED"""
import sys

from mpmath import mp, mpf, sqrt

mp.dps = 50
for line in open(sys.argv[1]):
    f = line.split("#")[0].split()
    if not f:
        continue
    kind, v = f[0], [mpf(float(x)) for x in f[1:]]
    P, C, N, r = v[0:3], v[3:6], v[6:9], v[9]
    nn = sqrt(sum(x * x for x in N))
    N = [x / nn for x in N]
    D = [P[i] - C[i] for i in range(3)]
    h = sum(D[i] * N[i] for i in range(3))
    X = [N[1] * D[2] - N[2] * D[1], N[2] * D[0] - N[0] * D[2], N[0] * D[1] - N[1] * D[0]]
    rho = sqrt(sum(x * x for x in X))
    if kind == "pd" and rho <= r:
        d = abs(h)
    else:
        d = sqrt((rho - r) ** 2 + h * h)
    print(mp.nstr(d, 25))
