#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Independent high-precision circle-circle distance (mpmath, 50 digits) for the doubles of a
query file, as an arbiter for the shared reference: for each line, both parameterisations are
sampled densely in float64 (numpy), every sampled local minimum is refined in mpmath by
bracketed root finding on the exact derivative of the closed-form point-circle squared distance
F(t) = (|N x D| - r)^2 + (N.D)^2 (golden section when the bracket shows no sign change), and
the smallest value is the distance.
usage: cc_exact.py QUERIES [LINE ...]   prints "LINE DISTANCE" (all lines when none given)."""
import sys
import numpy as np
import mpmath as mp

mp.mp.dps = 50
NS = 8192


def basis(n):
    a = [abs(x) for x in n]
    k = 0 if (a[0] <= a[1] and a[0] <= a[2]) else (1 if a[1] <= a[2] else 2)
    e = [mp.mpf(0)] * 3
    e[k] = mp.mpf(1)
    d = sum(e[i] * n[i] for i in range(3))
    w = [e[i] - d * n[i] for i in range(3)]
    wn = mp.sqrt(sum(x * x for x in w))
    u = [x / wn for x in w]
    v = [n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2], n[0] * u[1] - n[1] * u[0]]
    return u, v


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def one_way(cA, nA, rA, cB, nB, rB):
    """min over t of dist(A(t), B)."""
    if rA == 0:
        D = [cA[i] - cB[i] for i in range(3)]
        return mp.sqrt((mp.sqrt(dot(cross(nB, D), cross(nB, D))) - rB) ** 2 + dot(nB, D) ** 2)
    u, v = basis(nA)

    def parts(t):
        c, s = mp.cos(t), mp.sin(t)
        D = [cA[i] - cB[i] + rA * (c * u[i] + s * v[i]) for i in range(3)]
        D1 = [rA * (-s * u[i] + c * v[i]) for i in range(3)]
        return D, D1

    def F(t):
        D, _ = parts(t)
        w = cross(nB, D)
        return (mp.sqrt(dot(w, w)) - rB) ** 2 + dot(nB, D) ** 2

    def dF(t):
        D, D1 = parts(t)
        w, w1 = cross(nB, D), cross(nB, D1)
        rho = mp.sqrt(dot(w, w))
        rp = dot(w, w1) / rho if rho > 0 else 0
        return (rho - rB) * rp + dot(nB, D) * dot(nB, D1)

    # float64 sampling
    f = lambda x: np.array([float(y) for y in x])
    U, V, CA, CB, NB = f(u), f(v), f(cA), f(cB), f(nB)
    t = np.linspace(-np.pi, np.pi, NS, endpoint=False)
    P = CA[None, :] + float(rA) * (np.cos(t)[:, None] * U + np.sin(t)[:, None] * V)
    D = P - CB
    w = np.cross(NB, D)
    Fs = (np.linalg.norm(w, axis=1) - float(rB)) ** 2 + (D @ NB) ** 2
    idx = [i for i in range(NS) if Fs[i] <= Fs[i - 1] and Fs[i] <= Fs[(i + 1) % NS]]
    order = sorted(idx, key=lambda i: Fs[i])[:12]
    best = None
    h = mp.mpf(2) * mp.pi / NS
    for i in order:
        a, b = mp.mpf(t[i]) - h, mp.mpf(t[i]) + h
        fa, fb = dF(a), dF(b)
        if fa < 0 < fb:
            for _ in range(200):  # bisection + secant safeguard, to 1e-45
                m = (a + b) / 2
                fm = dF(m)
                if fm < 0:
                    a = m
                else:
                    b = m
                if b - a < mp.mpf(10) ** -45:
                    break
            x = (a + b) / 2
            val = min(F(x), F(a), F(b))
        else:  # golden section on F
            g = (mp.sqrt(5) - 1) / 2
            x1, x2 = b - g * (b - a), a + g * (b - a)
            f1, f2 = F(x1), F(x2)
            for _ in range(240):
                if f1 < f2:
                    b, x2, f2 = x2, x1, f1
                    x1 = b - g * (b - a)
                    f1 = F(x1)
                else:
                    a, x1, f1 = x1, x2, f2
                    x2 = a + g * (b - a)
                    f2 = F(x2)
            val = min(f1, f2)
        if best is None or val < best:
            best = val
    return mp.sqrt(best)


def exact(vals):
    v = [mp.mpf(x) for x in vals]
    c0, n0, r0 = v[0:3], v[3:6], v[6]
    c1, n1, r1 = v[7:10], v[10:13], v[13]
    n0 = [x / mp.sqrt(dot(n0, n0)) for x in n0]
    n1 = [x / mp.sqrt(dot(n1, n1)) for x in n1]
    return min(one_way(c0, n0, r0, c1, n1, r1), one_way(c1, n1, r1, c0, n0, r0))


def main():
    lines = open(sys.argv[1]).read().splitlines()
    want = [int(x) for x in sys.argv[2:]] or list(range(1, len(lines) + 1))
    for ln in want:
        parts = lines[ln - 1].split()
        if not parts or parts[0] != 'cc':
            continue
        print(ln, mp.nstr(exact([float(x) for x in parts[1:]]), 25))


if __name__ == '__main__':
    main()
