#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Exact line-circle distances of a query file, for the doubles as given.

An independent reference (mpmath, 60 digits): the line B + t M (M normalised exactly), the
circle normal normalised exactly. Every critical point of the squared distance
F(t) = (N.D)^2 + (|N x D| - r)^2, D = B + t M - C, is a root of the quartic
H(t) = |N x D|^2 (t + M.(B-C))^2 - r^2 (N x M . N x D)^2 (Eberly eq. (9)); all roots are found
with mpmath.polyroots at 60 digits, each real part is refined by Newton on F' in 60 digits and
F is evaluated there; dense sampling (4096 points over [-R, R] around the point nearest the
centre) plus golden-section refinement cross-checks the minimum. usage:
lc_exact.py QUERIES [LINE...]   (prints one distance per query, or only the listed lines)"""
import sys

from mpmath import mp, mpf, sqrt, polyroots, fabs

mp.dps = 60


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def unit(a):
    n = sqrt(dot(a, a))
    return [x / n for x in a]


def solve(v):
    B, M, C, N, r = v[0:3], unit(v[3:6]), v[6:9], unit(v[9:12]), v[12]
    D0 = [B[i] - C[i] for i in range(3)]
    t0 = -dot(D0, M)
    D0 = [D0[i] + t0 * M[i] for i in range(3)]  # nearest point to the centre, exactly

    def F(t):
        D = [D0[i] + t * M[i] for i in range(3)]
        h = dot(N, D)
        rho = sqrt(dot(cross(N, D), cross(N, D)))
        return h * h + (rho - r) ** 2

    def Fp(t):  # F'/2
        D = [D0[i] + t * M[i] for i in range(3)]
        nd, nm = cross(N, D), cross(N, M)
        rho = sqrt(dot(nd, nd))
        if rho == 0:
            return dot(D, M)
        return dot(D, M) - r * dot(nm, nd) / rho

    nm, nd = cross(N, M), cross(N, D0)
    w2, p1, p0, q = dot(nm, nm), dot(nm, nd), dot(nd, nd), dot(M, D0)
    # (w2 t^2 + 2 p1 t + p0)(t + q)^2 - r^2 (w2 t + p1)^2
    c = [w2, 2 * p1 + 2 * q * w2, p0 + 4 * q * p1 + q * q * w2 - r * r * w2 * w2,
         2 * q * p0 + 2 * q * q * p1 - 2 * r * r * w2 * p1, q * q * p0 - r * r * p1 * p1]
    while c and fabs(c[0]) < mpf(10) ** -50:
        c = c[1:]
    cands = [mpf(0)]
    if len(c) > 1:
        for z in polyroots(c, maxsteps=400, extraprec=200):
            t = mp.re(z)
            for _ in range(100):
                h = mpf(10) ** -30 * (1 + fabs(t))
                d = (Fp(t + h) - Fp(t - h)) / (2 * h)
                if d == 0:
                    break
                tn = t - Fp(t) / d
                if not (F(tn) <= F(t)):
                    break
                t = tn
            cands.append(t)
    best = min(F(t) for t in cands)
    # cross-check: dense sampling and golden section
    R = 2 * (r + sqrt(dot(D0, D0))) + 1
    n = 4096
    ts = [-R + 2 * R * k / n for k in range(n + 1)]
    fs = [F(t) for t in ts]
    for k in range(1, n):
        if fs[k] <= fs[k - 1] and fs[k] <= fs[k + 1]:
            a, b = ts[k - 1], ts[k + 1]
            g = (sqrt(5) - 1) / 2
            for _ in range(160):
                x1, x2 = b - g * (b - a), a + g * (b - a)
                if F(x1) < F(x2):
                    b = x2
                else:
                    a = x1
            fb = F((a + b) / 2)
            if fb < best:
                best = fb
    return sqrt(best)


def main():
    lines = [int(x) for x in sys.argv[2:]]
    k = 0
    for line in open(sys.argv[1]):
        f = line.split("#")[0].split()
        if not f:
            continue
        k += 1
        if lines and k not in lines:
            continue
        d = solve([mpf(float(x)) for x in f[1:]])
        print(("%d " % k if lines else "") + mp.nstr(d, 25))


if __name__ == "__main__":
    main()
