#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""References of the near-crossing grid's regressions (cc_kink.txt, ac_kink.txt), independently
of the library: mpmath, 60 digits, the inputs taken exactly as the doubles in the files.

Every critical point of F(t) = dist^2(P(t), c1), P(t) = c + r (cos t u + sin t v) on c0, is a
root of the trigonometric polynomial H = Q sigma^2 - s^2 (w.w')^2 of degree 4 (w = m x D, its
norm rho the distance to c1's axis, D = P - C1, sigma = D.P', s and m c1's radius and unit normal:
F'/2 = sigma - s w.w' / rho and H = (rho sigma - s w.w') (rho sigma + s w.w')). H's Fourier
coefficients come from 16 samples, its roots z = e^(it) from the polynomial z^4 H of degree 8
(polyroots); between consecutive real roots F' keeps its sign, so the critical points are the
roots where the sign of F' (at the midpoints) changes: a minimum (-, +) or a maximum (+, -).

cc_kink.critical: for each line of cc_kink.txt and each circle parameterised (order 0: the first,
basis u, v by the library's public rule, cdist_circle_basis), "LINE ORDER N" and N lines
"angle min|max distance".
ac_kink.exact: the arc-circle distance of each line of ac_kink.txt: the smallest distance at
the arc's ends and at the minima of F inside the arc (angles from the arc's zero direction).

usage: cc_kink_exact.py   (writes both files next to this script)
"""
import os

from mpmath import mp, mpf, cos, sin, sqrt, pi, exp, polyroots, arg, fabs, nstr

mp.dps = 60


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def unit(a):
    n = sqrt(dot(a, a))
    return [x / n for x in a]


def basis(n, e=None):
    """u, v of the plane of unit normal n: u = e projected (e: the library's rule when None)."""
    if e is None:
        ax, ay, az = abs(n[0]), abs(n[1]), abs(n[2])
        e = [1, 0, 0] if (ax <= ay and ax <= az) else ([0, 1, 0] if ay <= az else [0, 0, 1])
    u = unit([e[i] - dot(e, n) * n[i] for i in range(3)])
    return u, cross(n, u)


class Pair:
    """F(t) and F'(t)/2 for the point at angle t of circle (C0, r0, u, v) against (C1, m, s)."""

    def __init__(self, C0, r0, u, v, C1, m, s):
        self.C0, self.r0, self.u, self.v, self.C1, self.m, self.s = C0, r0, u, v, C1, m, s

    def parts(self, t):
        P = [self.C0[i] + self.r0 * (cos(t) * self.u[i] + sin(t) * self.v[i]) for i in range(3)]
        Pd = [self.r0 * (-sin(t) * self.u[i] + cos(t) * self.v[i]) for i in range(3)]
        D = [P[i] - self.C1[i] for i in range(3)]
        return D, Pd, cross(self.m, D), cross(self.m, Pd)

    def F(self, t):
        D, Pd, w, wd = self.parts(t)
        h = dot(self.m, D)
        return (sqrt(dot(w, w)) - self.s) ** 2 + h * h

    def F1(self, t):
        D, Pd, w, wd = self.parts(t)
        return dot(D, Pd) - self.s * dot(w, wd) / sqrt(dot(w, w))

    def H(self, t):
        D, Pd, w, wd = self.parts(t)
        return dot(w, w) * dot(D, Pd) ** 2 - self.s ** 2 * dot(w, wd) ** 2

    def critical(self):
        """[(angle in (-pi, pi], +1 minimum / -1 maximum)], in increasing angle."""
        M = 16
        hs = [self.H(2 * pi * j / M) for j in range(M)]
        c = [sum(hs[j] * exp(-2j * pi * k * j / M) for j in range(M)) / M for k in range(-4, 5)]
        roots = polyroots(c[::-1], maxsteps=4000, extraprec=600)
        ts = sorted(set(arg(z) for z in roots if fabs(abs(z) - 1) < mpf(10) ** -25))
        out = []
        for i, t in enumerate(ts):
            lo = ts[i - 1] if i else ts[-1] - 2 * pi
            hi = ts[i + 1] if i + 1 < len(ts) else ts[0] + 2 * pi
            fl, fr = self.F1((lo + t) / 2), self.F1((t + hi) / 2)
            if (fl < 0) != (fr < 0):
                out.append((t, 1 if fl < 0 else -1))
        return out


def circle(v):
    return v[0:3], unit(v[3:6]), v[6]


def doubles(words):
    return [mpf(float(x)) for x in words]  # exactly the doubles of the file


def lines(path):
    for k, line in enumerate(open(path), 1):
        s = line.split()
        if s and not s[0].startswith("#"):
            yield k, s


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    out = []
    for k, s in lines(os.path.join(here, "cc_kink.txt")):
        assert s[0] == "cc" and len(s) == 15, s
        v = doubles(s[1:])
        cs = [circle(v[0:7]), circle(v[7:14])]
        for order in (0, 1):
            (C0, n0, r0), (C1, n1, r1) = cs[order], cs[1 - order]
            u, w = basis(n0)
            p = Pair(C0, r0, u, w, C1, n1, r1)
            crit = p.critical()
            out.append("%d %d %d" % (k, order, len(crit)))
            for t, d in crit:
                out.append("%s %s %s" % (nstr(t, 25), "min" if d > 0 else "max", nstr(sqrt(p.F(t)), 25)))
    with open(os.path.join(here, "cc_kink.critical"), "w") as f:
        f.write("\n".join(out) + "\n")
    out = []
    for k, s in lines(os.path.join(here, "ac_kink.txt")):
        assert s[0] == "ac" and len(s) == 20, s
        v = doubles(s[1:])
        C0, n0, r0 = circle(v[0:7])
        u, w = basis(n0, v[7:10])
        start, end = v[10], v[11]
        C1, n1, r1 = circle(v[12:19])
        p = Pair(C0, r0, u, w, C1, n1, r1)
        cand = [start, end]
        for t, d in p.critical():
            for t2 in (t - 2 * pi, t, t + 2 * pi):
                if d > 0 and start <= t2 <= end:
                    cand.append(t2)
        out.append(nstr(min(sqrt(p.F(t)) for t in cand), 21, min_fixed=-60, max_fixed=60))
    with open(os.path.join(here, "ac_kink.exact"), "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
