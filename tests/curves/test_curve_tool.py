#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""The circledist tool on the curve kinds ac aa sa ad hc hd bc bd.

usage: test_curve_tool.py CIRCLEDIST
Expected distances come from this script's own brute force (numpy sampling of the closed-form
point distances, every sampled local minimum polished by golden section in mpmath at 30 digits),
never from the tool or the library."""
import json
import math
import os
import random
import subprocess
import sys

import mpmath as mp
import numpy as np
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../common"))
from checks import check, finish  # noqa: E402

mp.mp.dps = 30
tool = sys.argv[1]


# ---- geometry, generic in the number type (numpy arrays or mpmath numbers) ----

def unit(v):
    n = mp.sqrt(sum(mp.mpf(x) ** 2 for x in v))
    return [mp.mpf(x) / n for x in v]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


class Circle:
    def __init__(self, v):
        self.c = [mp.mpf(x) for x in v[0:3]]
        self.n = unit(v[3:6])
        self.r = mp.mpf(v[6])
        self.cf = np.array([float(x) for x in self.c])
        self.nf = np.array([float(x) for x in self.n])


class Arc:
    def __init__(self, v):
        self.k = Circle(v[0:7])
        z = [mp.mpf(x) for x in v[7:10]]
        zn = dot(z, self.k.n)
        self.u = unit([z[i] - zn * self.k.n[i] for i in range(3)])
        self.v = cross(self.k.n, self.u)
        self.a0, self.a1 = mp.mpf(v[10]), mp.mpf(v[11])
        self.uf = np.array([float(x) for x in self.u])
        self.vf = np.array([float(x) for x in self.v])

    def point(self, t, lib):
        if lib is np:
            return self.k.cf[:, None] + float(self.k.r) * (np.cos(t) * self.uf[:, None] + np.sin(t) * self.vf[:, None])
        return [self.k.c[i] + self.k.r * (mp.cos(t) * self.u[i] + mp.sin(t) * self.v[i]) for i in range(3)]


def split(p, k, lib):
    """height and axis distance of point(s) p relative to circle k"""
    if lib is np:
        d = p - k.cf[:, None]
        h = (k.nf[:, None] * d).sum(0)
        w = np.cross(k.nf[:, None], d, axis=0)
        return h, np.sqrt((w * w).sum(0))
    d = [p[i] - k.c[i] for i in range(3)]
    w = cross(k.n, d)
    return dot(k.n, d), mp.sqrt(dot(w, w))


def d_circle(p, k, lib):
    h, rho = split(p, k, lib)
    return lib.sqrt((rho - k.r if lib is mp else rho - float(k.r)) ** 2 + h * h)


def d_disk(p, k, lib):
    h, rho = split(p, k, lib)
    r = k.r if lib is mp else float(k.r)
    if lib is np:
        out = np.sqrt(np.maximum(rho - r, 0) ** 2 + h * h)
        return out
    return mp.sqrt(max(rho - r, 0) ** 2 + h * h)


def d_point_arc(p, a, lib):
    """point(s) to arc: closest circle point if its angle is in range, else an endpoint"""
    e0, e1 = a.point(a.a0 if lib is mp else float(a.a0), lib), a.point(a.a1 if lib is mp else float(a.a1), lib)
    if lib is np:
        e0, e1 = e0[:, 0][:, None], e1[:, 0][:, None]
        best = np.minimum(np.sqrt(((p - e0) ** 2).sum(0)), np.sqrt(((p - e1) ** 2).sum(0)))
        d = p - a.k.cf[:, None]
        ang = np.arctan2((a.vf[:, None] * d).sum(0), (a.uf[:, None] * d).sum(0))
        k = np.mod(ang - float(a.a0), 2 * math.pi)
        inside = float(a.a0) + k <= float(a.a1)
        return np.where(inside, np.minimum(best, d_circle(p, a.k, np)), best)
    best = min(mp.sqrt(sum((p[i] - e0[i]) ** 2 for i in range(3))), mp.sqrt(sum((p[i] - e1[i]) ** 2 for i in range(3))))
    d = [p[i] - a.k.c[i] for i in range(3)]
    x, y = dot(a.u, d), dot(a.v, d)
    if x == 0 and y == 0:
        return min(best, d_circle(p, a.k, mp))
    k = mp.fmod(mp.atan2(y, x) - a.a0, 2 * mp.pi)
    if k < 0:
        k += 2 * mp.pi
    if a.a0 + k <= a.a1:
        best = min(best, d_circle(p, a.k, mp))
    return best


def d_point_segment(p, s0, s1, lib):
    if lib is np:
        a, b = np.array([float(x) for x in s0])[:, None], np.array([float(x) for x in s1])[:, None]
        m = b - a
        mm = float((m * m).sum())
        s = np.clip(((p - a) * m).sum(0) / mm, 0, 1) if mm > 0 else np.zeros(p.shape[1])
        return np.sqrt(((p - (a + s * m)) ** 2).sum(0))
    m = [s1[i] - s0[i] for i in range(3)]
    mm = dot(m, m)
    s = dot([p[i] - s0[i] for i in range(3)], m) / mm if mm > 0 else 0
    s = min(max(s, 0), 1)
    return mp.sqrt(sum((p[i] - s0[i] - s * m[i]) ** 2 for i in range(3)))


def minimise(f, t0, t1, n=20000, keep=6):
    """min of f over [t0, t1]: numpy samples, golden section (mpmath) around the best local minima"""
    t0, t1 = mp.mpf(t0), mp.mpf(t1)
    if t0 == t1:
        return f(t0, mp)
    ts = np.linspace(float(t0), float(t1), n + 1)
    fs = f(ts, np)
    idx = [i for i in range(n + 1) if (i == 0 or fs[i] <= fs[i - 1]) and (i == n or fs[i] <= fs[i + 1])]
    idx = sorted(idx, key=lambda i: fs[i])[:keep]
    best = min(f(t0, mp), f(t1, mp))
    g = (mp.sqrt(5) - 1) / 2
    for i in idx:
        a = t0 + (t1 - t0) * max(i - 1, 0) / n
        b = t0 + (t1 - t0) * min(i + 1, n) / n
        x1, x2 = b - g * (b - a), a + g * (b - a)
        f1, f2 = f(x1, mp), f(x2, mp)
        for _ in range(90):
            if f1 < f2:
                b, x2, f2 = x2, x1, f1
                x1 = b - g * (b - a)
                f1 = f(x1, mp)
            else:
                a, x1, f1 = x1, x2, f2
                x2 = a + g * (b - a)
                f2 = f(x2, mp)
        best = min(best, f1, f2)
    return best


# ---- brute force per kind (v = the numbers of the query line) ----

def helix_point(v, t, lib):
    c, n = [mp.mpf(x) for x in v[0:3]], unit(v[3:6])
    z = [mp.mpf(x) for x in v[6:9]]
    zn = dot(z, n)
    u = unit([z[i] - zn * n[i] for i in range(3)])
    w = cross(n, u)
    r, rise = mp.mpf(v[9]), mp.mpf(v[10]) / (2 * mp.pi)
    if lib is np:
        f = lambda a: np.array([float(x) for x in a])[:, None]
        return f(c) + float(r) * (np.cos(t) * f(u) + np.sin(t) * f(w)) + float(rise) * t * f(n)
    return [c[i] + r * (mp.cos(t) * u[i] + mp.sin(t) * w[i]) + rise * t * n[i] for i in range(3)]


def bezier_point(v, t, lib):
    p = [[mp.mpf(x) for x in v[3 * i:3 * i + 3]] for i in range(4)]
    if lib is np:
        m = 1 - t
        b = [m ** 3, 3 * m * m * t, 3 * m * t * t, t ** 3]
        return sum(np.array([float(x) for x in p[i]])[:, None] * b[i] for i in range(4))
    m = 1 - t
    b = [m ** 3, 3 * m * m * t, 3 * m * t * t, t ** 3]
    return [sum(b[i] * p[i][j] for i in range(4)) for j in range(3)]


def brute(kind, v):
    if kind in ("ac", "ad"):
        a, k = Arc(v[0:12]), Circle(v[12:19])
        dk = d_circle if kind == "ac" else d_disk
        return minimise(lambda t, lib: dk(a.point(t, lib), k, lib), a.a0, a.a1)
    if kind == "aa":
        a, b = Arc(v[0:12]), Arc(v[12:24])
        return min(minimise(lambda t, lib: d_point_arc(a.point(t, lib), b, lib), a.a0, a.a1),
                   minimise(lambda t, lib: d_point_arc(b.point(t, lib), a, lib), b.a0, b.a1))
    if kind == "sa":
        s0, s1 = [mp.mpf(x) for x in v[0:3]], [mp.mpf(x) for x in v[3:6]]
        a = Arc(v[6:18])

        def seg(t, lib):
            if lib is np:
                f = lambda q: np.array([float(x) for x in q])[:, None]
                return f(s0) + t * (f(s1) - f(s0))
            return [s0[i] + t * (s1[i] - s0[i]) for i in range(3)]
        return min(minimise(lambda t, lib: d_point_arc(seg(t, lib), a, lib), 0, 1),
                   minimise(lambda t, lib: d_point_segment(a.point(t, lib), s0, s1, lib), a.a0, a.a1))
    if kind in ("hc", "hd"):
        k = Circle(v[13:20])
        dk = d_circle if kind == "hc" else d_disk
        turns = (v[12] - v[11]) / (2 * math.pi)
        return minimise(lambda t, lib: dk(helix_point(v, t, lib), k, lib), v[11], v[12], n=int(4000 * (1 + turns)))
    if kind in ("bc", "bd"):
        k = Circle(v[12:19])
        dk = d_circle if kind == "bc" else d_disk
        return minimise(lambda t, lib: dk(bezier_point(v, t, lib), k, lib), 0, 1)
    raise ValueError(kind)


def scale(kind, v, e):
    """the problem scale (as the tool's query_io cdq_scale defines it)"""
    dist = lambda a, b: math.dist(a, b)
    L = abs(e)
    if kind in ("ac", "ad", "aa"):
        return max(L, v[6], v[18], dist(v[0:3], v[12:15]))
    if kind == "sa":
        return max(L, v[12], dist(v[0:3], v[6:9]), dist(v[3:6], v[6:9]))
    if kind[0] == "h":
        ext = abs(v[10]) * max(abs(v[11]), abs(v[12])) / (2 * math.pi)
        return max(L, v[9], v[19], dist(v[0:3], v[13:16]) + ext)
    return max(L, v[18], *(dist(v[3 * i:3 * i + 3], v[12:15]) for i in range(4)))


# ---- cases ----

rng = random.Random(20261122)


def rvec(s=1.0):
    return [s * rng.uniform(-1, 1) for _ in range(3)]


def runit():
    while True:
        v = rvec()
        n = math.sqrt(sum(x * x for x in v))
        if 0.1 < n <= 1:
            return [x / n for x in v]


def rcircle():
    return rvec() + runit() + [rng.uniform(0.1, 1.5)]


def rarc():
    s = rng.uniform(-math.pi, math.pi)
    return rcircle() + runit() + [s, s + rng.uniform(0.05, 2 * math.pi)]


cases = [
    # hand-made: endpoint minima, cut-out closest pairs, coplanar and coaxial configurations
    ("ac", [0, 0, 0, 0, 0, 1, 1, 1, 0, 0, math.pi / 2, 3 * math.pi / 2, 3, 0, 0, 0, 0, 1, 1]),
    ("ac", [0, 0, 0, 0, 0, 1, 1, 1, 0, 0, 0.4, 2 * math.pi - 0.3, 2.2, 0.3, 0.7, 0.6, 0, 0.8, 0.9]),
    ("ac", [0, 0, 0, 0, 0, 1, 1, 1, 0, 0, 0.5, 2 * math.pi - 0.5, 1, 0, 0, 0, 1, 0, 1]),
    ("aa", [0, 0, 0, 0, 0, 1, 1, 1, 0, 0, 0.5, 2 * math.pi - 0.5, 1, 0, 0, 0, 1, 0, 1, 0, 0, 1, -1, 1]),
    ("aa", [0, 0, 0, 0, 0, 1, 2, 1, 0, 0, 0, 1, 0, 0, 0, 0, 0, 1, 1, 1, 0, 0, 2, 3]),
    ("sa", [2, -0.2, 0, -2, 0.1, 0.05, 0, 0, 0, 0, 0, 1, 1, 1, 0, 0, 0.4, 2 * math.pi - 0.3]),
    ("sa", [-100, 1 + 1e-9, 1e-7, 100, 1 + 1e-9, 1e-7, 0, 0, 0, 0, 0, 1, 1, 1, 0, 0, 0.5, 2.0]),
    ("ad", [0.3, 0, 0.5, 0, 1, 0, 0.8, 1, 0, 0, -1, 5, 0, 0, 0, 0, 0, 1, 1.5]),
    ("ad", [2.5, 0, 0.2, 0, 1, 0, 0.6, 1, 0, 0, 0, 6, 0, 0, 0, 0, 0, 1, 1.5]),
    ("hc", [0, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0.5, -20, 20, 0, 0, 1, 0, 0, 1, 1]),
    ("hd", [0, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0.5, 0, 20, 3, 0, 1, 1, 0, 0, 1.5]),
    ("bc", [0, 0, 0, 1, 1, 0, 2, -1, 0, 3, 0, 0, 1.5, 0, 0.3, 0, 0, 1, 0.2]),
    ("bd", [0, 0, 1, 1, 1, -1, 2, -1, 1, 3, 0, 2, 1.5, 0, 0, 0, 0, 1, 0.7]),
]
for _ in range(5):
    cases.append(("ac", rarc() + rcircle()))
    cases.append(("ad", rarc() + rcircle()))
    cases.append(("aa", rarc() + rarc()))
    cases.append(("sa", rvec(2) + rvec(2) + rarc()))
    t0 = rng.uniform(-10, 0)
    for k in ("hc", "hd"):
        cases.append((k, rvec() + runit() + runit() + [rng.uniform(0.1, 1.1), rng.uniform(-2, 2), t0,
                                                        t0 + rng.uniform(0, 15)] + rcircle()))
    cases.append(("bc", rvec(2) + rvec(2) + rvec(2) + rvec(2) + rcircle()))
    cases.append(("bd", rvec(2) + rvec(2) + rvec(2) + rvec(2) + rcircle()))

text = "".join("%s %s\n" % (k, " ".join("%.17g" % x for x in v)) for k, v in cases)
p = subprocess.run([tool, "-"], input=text, capture_output=True, text=True, timeout=120)
check(p.returncode == 0, "exit status %d: %s" % (p.returncode, p.stderr))
out = p.stdout.splitlines()
check(len(out) == len(cases), "one answer per query")
kinds_seen = set()
worst = {}
for (k, v), o in zip(cases, out):
    f = o.split()
    d = float(f[0])
    npairs = int(f[1])
    check(len(f) == 3 + 6 * npairs and npairs in (1, 2), "fields: " + o)
    e = brute(k, [float(x) for x in v])
    L = scale(k, v, float(e))
    err = float(abs(mp.mpf(d) - e) / L)
    worst[k] = max(worst.get(k, 0.0), err)
    check(err <= 1e-12, "%s %s: tool %r brute force %s error %.3g of scale" % (k, v, d, mp.nstr(e, 20), err))
    # each pair realises the distance
    for i in range(npairs):
        pts = [float(x) for x in f[3 + 6 * i:9 + 6 * i]]
        check(abs(math.dist(pts[0:3], pts[3:6]) - d) <= 1e-12 * L, "%s pair %d realises the distance" % (k, i))
    kinds_seen.add(k)
check(kinds_seen == {"ac", "aa", "sa", "ad", "hc", "hd", "bc", "bd"}, "every curve kind exercised")

# JSON output carries the arc params within the arc's own range.
line = "ac 0 0 0 0 0 1 1 0 1 0 3 9.2831853071795862 3 0 0 0 0 1 1\n"
p = subprocess.run([tool, "--format=json", "-"], input=line, capture_output=True, text=True, timeout=60)
j = json.loads(p.stdout.splitlines()[0])
check(abs(j["distance"] - 1) < 1e-15, "json distance %r" % j["distance"])
t = j["pairs"][0]["params"][0]
check(3 <= t <= 9.2831853071795862 and abs(t - 1.5 * math.pi) < 1e-12, "arc param in its own frame: %r" % t)

# Bad arcs, helices and curves give the documented error per line; the others are answered.
bad = """ac 0 0 0 0 0 1 1 1 0 0 2 1  3 0 0 0 0 1 1
aa 0 0 0 0 0 1 1 0 0 5 0 1  0 0 0 0 0 1 2 1 0 0 0 1
sa 0 0 0 1 1 1  0 0 0 0 0 1 1 1 0 0 0 7
hc 0 0 0 0 0 1 1 0 0 1 0.5 10 0  0 0 0 0 0 1 1
bd nan 0 0 1 1 1 2 -1 1 3 0 2  1.5 0 0 0 0 1 0.7
ad 0 0 0 0 0 1 1 1 0 0 0 1  0 0 -1 0 0 1 2
"""
p = subprocess.run([tool, "-"], input=bad, capture_output=True, text=True, timeout=60)
o = p.stdout.splitlines()
check(p.returncode == 1 and len(o) == 6, "bad lines: rc %d, %d answers" % (p.returncode, len(o)))
want = ["CDIST_ERR_BAD_INTERVAL", "CDIST_ERR_ZERO_VECTOR", "CDIST_ERR_BAD_INTERVAL", "CDIST_ERR_BAD_INTERVAL",
        "CDIST_ERR_NOT_FINITE"]
for i, w in enumerate(want):
    check(i < len(o) and o[i].startswith("error: line %d:" % (i + 1)) and w in o[i], "bad line %d: %r" % (i + 1, o[i] if i < len(o) else None))
check(len(o) == 6 and abs(float(o[5].split()[0]) - 1) < 1e-15, "good line after bad ones")

# Arcs with a huge start (1e17: an offset from it rounds by whole radians) against a coaxial arc,
# in both orders: the brute force's distance, and no equidistant flag (one point arc).
huge = ["0 0 0 0 0 1 1 1 0 0 1e17 1e17", "0 0 0.5 0 0 1 1 1 0 0 0 0.001"]
lines = "aa %s  %s\naa %s  %s\n" % (huge[0], huge[1], huge[1], huge[0])
p = subprocess.run([tool, "-"], input=lines, capture_output=True, text=True, timeout=60)
o = p.stdout.splitlines()
e = brute("aa", [float(x) for x in (huge[0] + " " + huge[1]).split()])
for i, line in enumerate(o):
    f = line.split()
    check(abs(mp.mpf(f[0]) - e) < 1e-14 and f[2] == "0", "huge arc start, order %d: %s (brute force %s)" % (i, line, mp.nstr(e, 17)))
check(len(o) == 2, "huge arc start: two answers")

for k in sorted(worst):
    print("%s: max error %.3g of scale" % (k, worst[k]))
finish("curve-tool")
