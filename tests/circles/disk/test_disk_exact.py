#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""rd, sd, ld, dd, cd against the mpmath brute force of disk_exact.py on random and
near-degenerate inputs (moved by random rotations, scales and translations), through the
circledist tool. Checks the distance within 1e-12 of scale, that every pair lies on its objects
and realises the distance, and that dd(a, b) and dd(b, a) agree.
usage: test_disk_exact.py CIRCLEDIST_TOOL"""
import math
import os
import random
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import disk_exact as X  # noqa: E402
from mpmath import mpf  # noqa: E402

rng = random.Random(20261122)
TOL = 1e-12


def unit(v):
    n = math.sqrt(sum(x * x for x in v))
    return [x / n for x in v]


def rotation():
    a = unit([rng.gauss(0, 1) for _ in range(3)])
    b = [rng.gauss(0, 1) for _ in range(3)]
    d = sum(a[i] * b[i] for i in range(3))
    b = unit([b[i] - d * a[i] for i in range(3)])
    c = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
    return [a, b, c]


def mover():
    R = rotation()
    s = 10 ** rng.uniform(-2, 2)
    t = [rng.uniform(-1, 1) * (1e4 if rng.random() < 0.3 else 3) for _ in range(3)]
    rot = lambda v: [sum(R[i][j] * v[j] for j in range(3)) for i in range(3)]
    pt = lambda p: [s * x + t[i] for i, x in enumerate(rot(p))]
    return pt, rot, s


def tiny():
    return 10 ** rng.uniform(-15, -4) * rng.choice([-1, 1])


def fmt(kind, vals):
    return kind + " " + " ".join("%.17g" % v for v in vals)


def cases():
    out = []
    for i in range(70):
        pt, rot, s = mover()
        R = rng.uniform(0.3, 1.5)
        C, N = [0, 0, 0], [0, 0, 1]
        fam = i % 7
        if fam == 0:  # ray starting just above the face, pointing away or along
            B, M = [R * rng.uniform(-0.9, 0.9), 0.1, abs(tiny())], unit([rng.uniform(-1, 1), 0.3, tiny()])
        elif fam == 1:  # nearly parallel to the plane over the face
            B, M = [-2 * R, R * rng.uniform(-1, 1), 0.4 * rng.uniform(-1, 1)], unit([1, tiny(), tiny()])
        elif fam == 2:  # aimed at the rim
            B, M = [R + tiny(), 0, 1.0], unit([tiny(), tiny(), -1])
        elif fam == 3:  # crossing the plane just outside the rim
            B, M = [R + abs(tiny()), 0.0, 0.5], unit([0.0, 0.3, -1])
        elif fam == 4:  # in the plane within rounding, tangent-ish to the rim
            B, M = [-2.0, R + tiny(), tiny()], unit([1, 0, tiny()])
        elif fam == 5:  # generic
            B, M = [rng.uniform(-2, 2) for _ in range(3)], unit([rng.gauss(0, 1) for _ in range(3)])
        else:  # through the centre region, steep
            B, M = [tiny(), tiny(), 1.0], unit([rng.uniform(-1, 1), rng.uniform(-1, 1), -2])
        disk = pt(C) + unit(rot(N)) + [s * R]
        Bm, Mm = pt(B), unit(rot(M))
        kind = ("ld", "rd", "sd")[i % 3]
        if kind == "sd":
            L = rng.uniform(0.2, 3)
            P1 = pt([B[k] + L * M[k] for k in range(3)])
            out.append(fmt("sd", Bm + P1 + disk))
        else:
            out.append(fmt(kind, Bm + Mm + disk))
    for i in range(9):
        # far origins: the line passes the disk 1e5..1e9 from its origin (segments: both ends far)
        N = unit([rng.gauss(0, 1) for _ in range(3)])
        M = unit([rng.gauss(0, 1) for _ in range(3)])
        P = [rng.uniform(-1, 1) for _ in range(3)]
        T, T2 = 10 ** rng.uniform(5, 9), 10 ** rng.uniform(5, 9)
        B = [P[k] - T * M[k] for k in range(3)]
        disk = [0.0, 0.0, 0.0] + N + [rng.uniform(0.3, 1.5)]
        if i % 3 == 2:
            out.append(fmt("sd", B + [P[k] + T2 * M[k] for k in range(3)] + disk))
        else:
            out.append(fmt(("ld", "rd")[i % 3], B + M + disk))
    for i in range(24):
        pt, rot, s = mover()
        R0, R1 = rng.uniform(0.3, 1.5), rng.uniform(0.3, 1.5)
        fam = i % 6
        if fam == 0:  # nearly parallel, stacked
            c1, n1 = [rng.uniform(-1, 1), 0, 0.5], unit([tiny(), tiny(), 1])
        elif fam == 1:  # rims nearly touching, coplanar within rounding
            c1, n1 = [R0 + R1 + tiny(), 0, tiny()], unit([tiny(), 0, 1])
        elif fam == 2:  # perpendicular, touching the face near the centre
            c1, n1 = [0.1, 0.2, R1 + tiny()], [1, 0, 0]
        elif fam == 3:  # perpendicular, rim over rim
            c1, n1 = [R0 + abs(tiny()), 0, R1 + abs(tiny())], [0, 1, 0]
        elif fam == 4:  # tilted, nearly touching the face
            th = rng.uniform(0.2, 1.2)
            c1, n1 = [0.2, 0, R1 * math.sin(th) + tiny()], [0, math.sin(th), math.cos(th)]
            c1 = [0.2, 0, R1 * math.sin(th) + abs(tiny())]
            n1 = unit([0, math.sin(th), math.cos(th)])
        else:  # generic
            c1, n1 = [rng.uniform(-2, 2) for _ in range(3)], unit([rng.gauss(0, 1) for _ in range(3)])
        d0 = pt([0, 0, 0]) + unit(rot([0, 0, 1])) + [s * R0]
        d1 = pt(c1) + unit(rot(n1)) + [s * R1]
        out.append(fmt("dd", d0 + d1))
        if i % 3 == 0:
            out.append(fmt("cd", d1 + d0))
    return out


def main():
    tool = sys.argv[1]
    lines = cases()
    with tempfile.NamedTemporaryFile("w", suffix=".txt", delete=False) as f:
        f.write("\n".join(lines) + "\n")
        path = f.name
    res = subprocess.run([tool, path], capture_output=True, text=True)
    os.unlink(path)
    outs = res.stdout.splitlines()
    fails, worst = 0, {}
    for line, o in zip(lines, outs):
        fl = line.split()
        kind, v = fl[0], [float(x) for x in fl[1:]]
        w = o.split()
        d, npairs = float(w[0]), int(w[1])
        ex = X.exact(fl)
        if kind in ("cd", "dd"):
            L = max(abs(float(ex)), v[6], v[13], math.dist(v[0:3], v[7:10]))
            objs = (X.Disk(v[0:3], v[3:6], v[6]), X.Disk(v[7:10], v[10:13], v[13]))
        else:
            M = [v[3 + i] - v[i] for i in range(3)] if kind == "sd" else v[3:6]
            mm = sum(x * x for x in M)
            t = sum((v[6 + i] - v[i]) * M[i] for i in range(3)) / mm
            L = max(abs(float(ex)), v[12], math.dist([v[i] + t * M[i] for i in range(3)], v[6:9]))
            objs = (None, X.Disk(v[6:9], v[9:12], v[12]))
        err = float(abs(mpf(w[0]) - ex)) / L
        worst[kind] = max(worst.get(kind, 0), err)
        mag = max(abs(x) for x in v)
        ptol = TOL * L + 32 * 2.2e-16 * mag
        ok = err <= TOL
        for p in range(npairs):
            P = [mpf(x) for x in w[3 + 6 * p: 6 + 6 * p]]
            Q = [mpf(x) for x in w[6 + 6 * p: 9 + 6 * p]]
            if float(objs[1].dist(Q)) > ptol:
                ok = False
                print("pair %d: second point off the disk (%g)" % (p, float(objs[1].dist(Q))))
            if kind == "dd" and float(objs[0].dist(P)) > ptol:
                ok = False
                print("pair %d: first point off its disk" % p)
            if abs(float(X.norm(X.sub(P, Q))) - d) > ptol:
                ok = False
                print("pair %d does not realise the distance" % p)
        if not ok:
            fails += 1
            print("FAIL %s\n  got %s exact %s error %.3g of scale %.3g" % (line, w[0], X.mp.nstr(ex, 20), err, L))
    # dd symmetry through the tool: swapped arguments give the same distance.
    dd = [l for l in lines if l.startswith("dd")]
    sw = []
    for l in dd:
        f = l.split()
        sw.append(" ".join(["dd"] + f[8:15] + f[1:8]))
    with tempfile.NamedTemporaryFile("w", suffix=".txt", delete=False) as f:
        f.write("\n".join(dd + sw) + "\n")
        path = f.name
    o2 = subprocess.run([tool, path], capture_output=True, text=True).stdout.splitlines()
    os.unlink(path)
    for i in range(len(dd)):
        if o2[i].split()[0] != o2[len(dd) + i].split()[0]:
            fails += 1
            print("FAIL dd symmetry: %s vs %s for %s" % (o2[i].split()[0], o2[len(dd) + i].split()[0], dd[i]))
    print("max error of scale per kind: " + ", ".join("%s %.3g" % kv for kv in sorted(worst.items())))
    print("test_disk_exact: %d queries, %d failed" % (len(lines), fails))
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
