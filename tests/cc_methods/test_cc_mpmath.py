"""Polynomial and iteration methods against our own 50-digit mpmath brute force (ccmp.py) on
random linked and near-degenerate configurations not in the shared files: linked rings, nearly
touching, nearly coplanar, nearly coaxial, centre near the other's axis, axes nearly meeting,
radius ratios up to 1e6, circles far apart. Runs the circledist tool.
usage: test_cc_mpmath.py CIRCLEDIST_TOOL"""
import math
import os
import random
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ccmp  # noqa: E402

TOL = 1e-13


def unit(v):
    n = math.sqrt(sum(x * x for x in v))
    return [x / n for x in v]


def rand_unit(rng):
    while True:
        v = [rng.uniform(-1, 1) for _ in range(3)]
        n = math.sqrt(sum(x * x for x in v))
        if 0.1 < n <= 1:
            return [x / n for x in v]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def configs(rng, n):
    out = []
    for i in range(n):
        kind = i % 8
        c0 = [rng.uniform(-1, 1) for _ in range(3)]
        n0 = rand_unit(rng)
        r0 = rng.uniform(0.2, 1.5)
        u = unit(cross(n0, rand_unit(rng)))
        v = cross(n0, u)
        t = rng.uniform(0, 2 * math.pi)
        on = [c0[k] + r0 * (math.cos(t) * u[k] + math.sin(t) * v[k]) for k in range(3)]
        e = 10 ** rng.uniform(-13, -3)
        n1 = rand_unit(rng)
        r1 = rng.uniform(0.2, 1.5)
        if kind == 0:  # linked
            c1 = [on[k] + 0.3 * rng.uniform(-1, 1) for k in range(3)]
        elif kind == 1:  # nearly touching: c1 through a point of c0, nudged
            w = unit(cross(n1, rand_unit(rng)))
            c1 = [on[k] + r1 * w[k] + e * v[k] for k in range(3)]
        elif kind == 2:  # nearly coplanar
            c1 = [c0[k] + rng.uniform(-2, 2) * u[k] + e * n0[k] for k in range(3)]
            n1 = unit([n0[k] + e * n1[k] for k in range(3)])
        elif kind == 3:  # nearly coaxial
            s = rng.uniform(-2, 2)
            c1 = [c0[k] + s * n0[k] + e * u[k] for k in range(3)]
            n1 = unit([n0[k] + e * n1[k] for k in range(3)])
        elif kind == 4:  # centre near c0's axis
            s = rng.uniform(-2, 2)
            c1 = [c0[k] + s * n0[k] + e * u[k] for k in range(3)]
        elif kind == 5:  # axes nearly meeting
            s, m = rng.uniform(-1, 1), rng.uniform(-1, 1)
            c1 = [c0[k] + s * n0[k] + m * n1[k] + e * v[k] for k in range(3)]
        elif kind == 6:  # radius ratio up to 1e6, small circle near the big one
            r1 = r0 * 10 ** rng.uniform(-6, -2)
            c1 = [on[k] + r1 * rng.uniform(-3, 3) * n0[k] for k in range(3)]
        else:  # far apart
            far = 10 ** rng.uniform(2, 6)
            d = rand_unit(rng)
            c1 = [c0[k] + far * d[k] for k in range(3)]
        out.append((c0, n0, r0, c1, n1, r1))
    return out


def main():
    tool = sys.argv[1]
    rng = random.Random(20240611)
    cfgs = configs(rng, 40)
    lines = []
    for c0, n0, r0, c1, n1, r1 in cfgs:
        vals = c0 + n0 + [r0] + c1 + n1 + [r1]
        lines.append("cc " + " ".join("%.17g" % x for x in vals))
    # the doubles exactly as written
    parsed = [[float(x) for x in ln.split()[1:]] for ln in lines]
    exact = [ccmp.distance((v[0:3], v[3:6], v[6]), (v[7:10], v[10:13], v[13]))[0] for v in parsed]
    failed = 0
    for method in ("polynomial", "iteration"):
        res = subprocess.run([tool, "--method=" + method, "-"], input="\n".join(lines) + "\n",
                             capture_output=True, text=True)
        outs = res.stdout.strip().split("\n")
        if res.returncode != 0 or len(outs) != len(lines):
            print("tool failed (%s): %s" % (method, res.stderr))
            failed += 1
            continue
        worst = 0.0
        for i, (v, d, out) in enumerate(zip(parsed, exact, outs)):
            got = float(out.split()[0])
            D = [v[7 + k] - v[k] for k in range(3)]
            L = max(v[6], v[13], float(d), math.sqrt(sum(x * x for x in D)))
            err = float(abs(ccmp.mp.mpf(got) - d)) / L
            worst = max(worst, err)
            if not err <= TOL:
                failed += 1
                print("FAIL %s config %d (kind %d): %.17g vs mpmath %s, error %.3g of scale"
                      % (method, i, i % 8, got, ccmp.mp.nstr(d, 20), err))
        print("%s: %d configurations, max error %.3g of scale vs mpmath" % (method, len(lines), worst))
    print("cc_mpmath: %d failed" % failed)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
