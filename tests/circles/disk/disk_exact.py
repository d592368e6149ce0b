#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""High-precision brute force for the disk queries (ld, rd, sd, cd, dd), for the doubles as given.

Independent of the library's algorithms: mpmath (40 digits), normals normalised exactly, the
point-disk distance in closed form with |N x D| for the axis distance.
- ld, rd, sd: the distance from a point of the line to a disk is convex in the line parameter,
  so a golden-section search over a window that must contain the minimum finds it.
- cd: the circle parameter is sampled (default 2048 samples) and every sampled local minimum is
  refined by golden section.
- dd: the distance from a point to disk 1 is convex in the point, and disk 0 is convex, so a
  nested golden-section search over disk 0 (outer x, inner y over the chord) finds the minimum.
usage: disk_exact.py [--samples=N] QUERIES > EXPECTED   (one distance per query line)"""
import sys

from mpmath import mp, mpf, sqrt, cos, sin, pi

mp.dps = 40
GOLD = (sqrt(5) - 1) / 2


def vec(v):
    return [mpf(float(x)) for x in v]


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def add(a, b):
    return [a[i] + b[i] for i in range(3)]


def scale(s, a):
    return [s * x for x in a]


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def norm(a):
    return sqrt(dot(a, a))


def unit(a):
    return scale(1 / norm(a), a)


class Disk:
    def __init__(self, c, n, r):
        self.c, self.n, self.r = vec(c), unit(vec(n)), mpf(float(r))
        e = min(range(3), key=lambda k: abs(self.n[k]))
        ek = [mpf(0)] * 3
        ek[e] = mpf(1)
        self.u = unit(sub(ek, scale(self.n[e], self.n)))
        self.v = cross(self.n, self.u)

    def dist(self, p):
        d = sub(p, self.c)
        h = dot(self.n, d)
        rho = norm(cross(self.n, d))
        if rho <= self.r:
            return abs(h)
        return sqrt((rho - self.r) ** 2 + h * h)

    def circle_point(self, t, s=None):
        s = self.r if s is None else s
        return add(self.c, add(scale(s * cos(t), self.u), scale(s * sin(t), self.v)))


def golden(f, a, b, tol):
    """Minimum value of a unimodal f on [a, b]."""
    c, d = b - GOLD * (b - a), a + GOLD * (b - a)
    fc, fd = f(c), f(d)
    best = min(f(a), f(b), fc, fd)
    while b - a > tol:
        if fc <= fd:
            b, d, fd = d, c, fc
            c = b - GOLD * (b - a)
            fc = f(c)
        else:
            a, c, fc = c, d, fd
            d = a + GOLD * (b - a)
            fd = f(d)
        best = min(best, fc, fd)
    return best


def linear(B, M, tmin, tmax, disk):
    """min over t in [tmin, tmax] of disk.dist(B + t M) (convex in t)."""
    mm = dot(M, M)
    tc = dot(sub(disk.c, B), M) / mm
    d0 = norm(sub(add(B, scale(tc, M)), disk.c))
    w = (d0 + 2 * disk.r) / sqrt(mm) + 1
    lo, hi = max(tmin, tc - w), min(tmax, tc + w)
    if lo > hi:  # the window misses the range: the nearest range end is the minimum
        t = tmin if tc < tmin else tmax
        return disk.dist(add(B, scale(t, M)))
    f = lambda t: disk.dist(add(B, scale(t, M)))
    return golden(f, lo, hi, (hi - lo) * mpf(10) ** -30)


def circle_disk(circ, disk, samples):
    f = lambda t: disk.dist(circ.circle_point(t))
    if circ.r == 0:
        return f(mpf(0))
    h = 2 * pi / samples
    vals = [f(i * h) for i in range(samples)]
    best = min(vals)
    for i in range(samples):
        if vals[i] <= vals[i - 1] and vals[i] <= vals[(i + 1) % samples]:
            best = min(best, golden(f, (i - 1) * h, (i + 1) * h, mpf(10) ** -28))
    return best


def disk_disk(d0, d1):
    R = d0.r
    if R == 0:
        return d1.dist(d0.c)

    def inner(x):
        w = sqrt(max(R * R - x * x, mpf(0)))
        f = lambda y: d1.dist(add(d0.c, add(scale(x, d0.u), scale(y, d0.v))))
        if w == 0:
            return f(mpf(0))
        return golden(f, -w, w, w * mpf(10) ** -22)

    return golden(inner, -R, R, R * mpf(10) ** -22)


def exact(fields, samples=2048):
    kind, v = fields[0], [float(x) for x in fields[1:]]
    if kind in ("ld", "rd", "sd"):
        disk = Disk(v[6:9], v[9:12], v[12])
        if kind == "sd":
            P0, P1 = vec(v[0:3]), vec(v[3:6])
            M = sub(P1, P0)
            if norm(M) == 0:
                return disk.dist(P0)
            return linear(P0, M, mpf(0), mpf(1), disk)
        B, M = vec(v[0:3]), unit(vec(v[3:6]))
        return linear(B, M, -mp.inf if kind == "ld" else mpf(0), mp.inf, disk)
    a = Disk(v[0:3], v[3:6], v[6])
    b = Disk(v[7:10], v[10:13], v[13])
    if kind == "cd":
        return circle_disk(a, b, samples)
    if kind == "dd":
        return disk_disk(a, b)
    raise ValueError("kind " + kind)


def main():
    samples = 2048
    args = []
    for a in sys.argv[1:]:
        if a.startswith("--samples="):
            samples = int(a[10:])
        else:
            args.append(a)
    for line in open(args[0]):
        f = line.split("#")[0].split()
        if f:
            print(mp.nstr(exact(f, samples), 25))


if __name__ == "__main__":
    main()
