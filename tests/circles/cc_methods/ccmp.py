# SPDX-License-Identifier: MIT
"""High-precision circle-circle distance (mpmath), independent of the library's algorithms.

The circles are taken exactly as the given doubles (normals normalised in high precision).
theta -> dist(c0(theta), c1) is the closed-form point-circle distance (|N x Delta| for the
axis distance). Both parameterisations (c0 against c1 and c1 against c0) are sampled densely;
every sampled local minimum is refined by bisection on the analytic derivative at 50 digits.
Returns the minimum distance and the list of distinct local minima near it."""
import mpmath as mp

mp.mp.dps = 50


def _vec(a):
    return [mp.mpf(x) for x in a]


def _dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def _cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def _norm(a):
    return mp.sqrt(_dot(a, a))


def _basis(n):
    e = [mp.mpf(1), mp.mpf(0), mp.mpf(0)] if abs(n[0]) <= min(abs(n[1]), abs(n[2])) else (
        [mp.mpf(0), mp.mpf(1), mp.mpf(0)] if abs(n[1]) <= abs(n[2]) else [mp.mpf(0), mp.mpf(0), mp.mpf(1)])
    d = _dot(e, n)
    u = [e[i] - d * n[i] for i in range(3)]
    un = _norm(u)
    u = [x / un for x in u]
    return u, _cross(n, u)


class Circle:
    def __init__(self, c, n, r):
        self.c = _vec(c)
        n = _vec(n)
        nn = _norm(n)
        self.n = [x / nn for x in n]
        self.r = mp.mpf(r)
        self.u, self.v = _basis(self.n)

    def point(self, t):
        ct, st = mp.cos(t), mp.sin(t)
        return [self.c[i] + self.r * (ct * self.u[i] + st * self.v[i]) for i in range(3)]

    def dpoint(self, t):
        ct, st = mp.cos(t), mp.sin(t)
        return [self.r * (-st * self.u[i] + ct * self.v[i]) for i in range(3)]


def _F(m, f, t):
    """squared distance from m(t) to circle f, and its derivative"""
    p = m.point(t)
    d = [p[i] - f.c[i] for i in range(3)]
    h = _dot(f.n, d)
    nd = _cross(f.n, d)
    rho = _norm(nd)
    e = rho - f.r
    F = e * e + h * h
    if rho == 0:
        return F, mp.mpf(0)
    w = _cross(nd, f.n)
    E = [h * f.n[i] + e / rho * w[i] for i in range(3)]
    return F, 2 * _dot(E, m.dpoint(t))


def _minima(m, f, samples):
    ts = [2 * mp.pi * k / samples for k in range(samples)]
    vals = [_F(m, f, t) for t in ts]
    out = []
    for k in range(samples):
        Fa, ga = vals[k]
        Fb, gb = vals[(k + 1) % samples]
        if ga <= 0 <= gb and not (ga == 0 and gb == 0):
            a, b = ts[k], ts[k] + 2 * mp.pi / samples
            for _ in range(200):
                mid = (a + b) / 2
                if _F(m, f, mid)[1] < 0:
                    a = mid
                else:
                    b = mid
                if b - a < mp.mpf(10) ** -45:
                    break
            t = (a + b) / 2
            out.append((mp.sqrt(_F(m, f, t)[0]), t))
    return out


def distance(c0, c1, samples=256):
    """c0, c1: (centre, normal, radius) tuples of doubles. Returns (distance, minima) with
    minima = [(d, t, side)] of both parameterisations."""
    a, b = Circle(*c0), Circle(*c1)
    mins = []
    if a.r == 0 or b.r == 0:
        m, f = (a, b) if b.r > 0 or a.r == 0 else (b, a)
        if f.r == 0:
            return _norm([a.c[i] - b.c[i] for i in range(3)]), []
        F, _ = _F(m, f, mp.mpf(0))
        return mp.sqrt(F), []
    mins += [(d, t, 0) for d, t in _minima(a, b, samples)]
    mins += [(d, t, 1) for d, t in _minima(b, a, samples)]
    if not mins:  # constant (coaxial): any point
        return mp.sqrt(_F(a, b, mp.mpf(0))[0]), []
    return min(d for d, _, _ in mins), mins


if __name__ == "__main__":
    import sys
    for line in sys.stdin:
        w = line.split()
        if not w or w[0] != "cc":
            continue
        v = [float(x) for x in w[1:]]
        d, _ = distance((v[0:3], v[3:6], v[6]), (v[7:10], v[10:13], v[13]))
        print(mp.nstr(d, 25))
