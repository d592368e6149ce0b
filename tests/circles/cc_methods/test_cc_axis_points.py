# SPDX-License-Identifier: MIT
"""A tiny circle whose centre lies on (or within a little of) a big circle's axis: the closest
points of the big circle then come from an axis distance that is mostly rounding noise. Every
method, both argument orders: each reported point lies on its circle, each pair realises the
reported distance (both to a few ulps of the scale, in 50-digit mpmath), and the distance is
the 50-digit brute force of ccmp.py to 1e-13 of scale.
usage: test_cc_axis_points.py CIRCLEDIST_TOOL"""
import math
import os
import random
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ccmp  # noqa: E402

mp = ccmp.mp
ON_ULPS = 16  # points and pair lengths, in eps times the scale
DIST_TOL = 1e-13


def on_circle(p, c):
    """50-digit distance from the point p (doubles) to the circle c (ccmp.Circle)."""
    d = [mp.mpf(p[i]) - c.c[i] for i in range(3)]
    h = sum(c.n[i] * d[i] for i in range(3))
    rho = mp.sqrt(max(sum(x * x for x in d) - h * h, 0))
    return mp.sqrt(h * h + (rho - c.r) ** 2)


def configs(rng, n):
    """Big circle at the origin, tiny one near its axis: normals equal to 1/sqrt(3) up to a few
    ulps (as a user's (1,1,1)/sqrt(3) comes out), centres on the axis up to a relative offset."""
    out = []
    s = 1 / math.sqrt(3)
    for i in range(n):
        n0 = [s + rng.randint(-8, 8) * 2.0**-53 for _ in range(3)]
        n1 = [s + rng.randint(-8, 8) * 2.0**-53 for _ in range(3)]
        r0 = rng.uniform(0.5, 10)
        t = rng.uniform(0.5, 10)
        off = 0.0 if i % 4 == 0 else 10 ** rng.uniform(-16, -6)
        c1 = [t * (1 + rng.uniform(-1, 1) * off) for _ in range(3)]
        r1 = 10 ** rng.uniform(-300, -20)
        out.append([0.0, 0.0, 0.0] + n0 + [r0] + c1 + n1 + [r1])
    return out


def main():
    tool = sys.argv[1]
    # the fuzzer's finding first, then seeded variations of it
    cases = [[0, 0, 0, 0.57735026918962362, 0.57735026918962595, 0.57735026918962595, 5.2566334730813842,
              5.2566334730813842, 5.2566334730813842, 5.2566334730813842, 0.57735026918962584,
              0.57735026918962584, 0.57735026918962584, 1e-140]]
    cases += configs(random.Random(20261126), 40)
    cases += [v[7:14] + v[0:7] for v in cases]  # the other argument order
    exact = [ccmp.distance((v[0:3], v[3:6], v[6]), (v[7:10], v[10:13], v[13]), samples=64)[0] for v in cases]
    text = "".join("cc " + " ".join(repr(float(x)) for x in v) + "\n" for v in cases)
    failed = 0
    for method in ("polynomial", "iteration", "robust", "auto"):
        res = subprocess.run([tool, "--method=" + method, "-"], input=text, capture_output=True, text=True)
        outs = res.stdout.strip().split("\n")
        if res.returncode != 0 or len(outs) != len(cases):
            print("tool failed (%s): %s" % (method, res.stderr))
            failed += 1
            continue
        worst_on = worst_d = 0.0
        for i, (v, d, out) in enumerate(zip(cases, exact, outs)):
            w = [float(x) for x in out.split()]
            dist, npairs = w[0], int(w[1])
            circ = (ccmp.Circle(v[0:3], v[3:6], v[6]), ccmp.Circle(v[7:10], v[10:13], v[13]))
            L = max(abs(x) for x in v)
            err_d = float(abs(mp.mpf(dist) - d)) / L
            worst_d = max(worst_d, err_d)
            bad = [] if err_d <= DIST_TOL else ["distance %.17g vs mpmath %s" % (dist, mp.nstr(d, 20))]
            if not 1 <= npairs <= 2:
                bad.append("%d pairs" % npairs)
            for k in range(min(npairs, 2)):
                p, q = w[3 + 6 * k:6 + 6 * k], w[6 + 6 * k:9 + 6 * k]
                offs = [float(on_circle(p, circ[0])) / L, float(on_circle(q, circ[1])) / L]
                span = float(abs(mp.sqrt(sum((mp.mpf(p[j]) - q[j]) ** 2 for j in range(3))) - dist)) / L
                worst_on = max(worst_on, *offs, span)
                for j, e in enumerate(offs):
                    if not e <= ON_ULPS * sys.float_info.epsilon:
                        bad.append("pair %d: point %d is %.3g of scale off its circle" % (k, j, e))
                if not span <= ON_ULPS * sys.float_info.epsilon:
                    bad.append("pair %d does not realise the distance (%.3g of scale)" % (k, span))
            if bad:
                failed += 1
                print("FAIL %s case %d (cc %s): %s" % (method, i, " ".join(repr(float(x)) for x in v), "; ".join(bad)))
        print("%s: %d cases, points off their circles <= %.3g, distance error <= %.3g of scale"
              % (method, len(cases), worst_on, worst_d))
    print("cc_axis_points: %d failed" % failed)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
