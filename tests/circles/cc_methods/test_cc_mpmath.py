# SPDX-License-Identifier: MIT
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


# Cases found by stress testing (methods against each other): large radius ratios with a circle
# nearly through a point of the other, and nearly coplanar overlapping circles far from the origin.
FIXED = [
    "cc 0.19614522673253276 -0.93453015028745723 -0.94095590767759885 -0.9963563553358169 -0.056413823425980669 -0.063964784908492431 0.85932445365426124 586.69617564185137 0.10616365561591912 -10.075951266604633 -0.0041649538911418624 0.99780792517847183 -0.066045420811119956 586.5588108833465",
    "cc -0.36434539262003951 -0.61908822511525297 0.5611326218600361 0.026571947807933972 0.67232823383553164 0.73977609962561452 0.64290840957327899 -0.79554058285363738 -0.96385216379851446 0.89045801400918545 -0.21555499808681686 -0.16776450400298368 0.96197251207943835 0.0006468170265176358",
    "cc 0.25721366215222163 0.57544671514117351 -0.45519382288811672 -0.98584005690264809 0.01073574085082033 0.16734433385856698 0.33234387839699531 129.22646628921007 -63.180114923072594 172.42878762313478 0.81749677644908303 0.25432802407480937 -0.5167361770435287 224.63737449530993",
    "cc -2997.1944588826632 3437.6731687584206 1552.8745159667367 -0.67740772195167831 0.68084266212814704 0.27851758951006206 31.297509521868129 -3006.0039383499311 3419.1777647558379 1576.6386433024209 -0.7207380723458674 0.61997193533579098 0.31011518903007118 0.079311431533566984",
    "cc 864.38666859867737 1437.9177154121619 1127.3542102794365 -0.89943051826596454 -0.41186226141594406 0.14626763289656131 16.33511792410626 9952.7666134980973 1628.9909962527124 14247.799585625453 0.54608324442920919 0.74193802705726464 -0.38900006961444378 15952.504866812484",
    "cc 2.9368356841831482 4.7479266927957102 -2.083669375650802 -0.40753672600826185 -0.55819017183296182 0.72272923631437225 0.078836229095138349 2.9368356841841097 4.7479266927995507 -2.0836693756472937 0.51384541626788582 0.27605729705515591 -0.81225319754562042 0.078836229100625668",
    "cc 8356.2686475893006 -381.66957929993509 2844.1919778138217 0.76909818137855435 -0.18398715163472648 -0.61207574321609926 123.01567705614073 8281.0860370908395 -442.04863093311542 2767.8060915990841 0.76906770035413852 -0.1838698528825943 -0.6121492869169497 123.0319943181189",
]


def main():
    tool = sys.argv[1]
    rng = random.Random(20240611)
    cfgs = configs(rng, 40)
    lines = list(FIXED)
    for c0, n0, r0, c1, n1, r1 in cfgs:
        vals = c0 + n0 + [r0] + c1 + n1 + [r1]
        lines.append("cc " + " ".join("%.17g" % x for x in vals))
    # the doubles exactly as written
    parsed = [[float(x) for x in ln.split()[1:]] for ln in lines]
    exact = [ccmp.distance((v[0:3], v[3:6], v[6]), (v[7:10], v[10:13], v[13]), samples=1024)[0] for v in parsed]
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
                print("FAIL %s line %d: %.17g vs mpmath %s, error %.3g of scale"
                      % (method, i + 1, got, ccmp.mp.nstr(d, 20), err))
        print("%s: %d configurations, max error %.3g of scale vs mpmath" % (method, len(lines), worst))
    print("cc_mpmath: %d failed" % failed)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
