# SPDX-License-Identifier: MIT
"""Linking numbers of circles against an independent count in high precision (mpmath).

    link_check.py N [SEED]

N pairs from random and degenerate families (coplanar, concentric, one through the other's
centre, tiny vs huge, near-touching at 1e-3 .. 1e-14 of scale, nearly parallel planes,
intersecting) go through circledist.link_details in one C call per family. The reference
counts, in mpmath at 50 digits, the crossings of circle b through the open disk of circle a:
b(theta) = Cb + rb (cos theta U + sin theta V) meets a's plane where
    (Cb - Ca).Na + rb (cos theta U.Na + sin theta V.Na) = 0,
solved in closed form; a crossing counts sign(b'(theta) . Na) when |b(theta) - Ca| < ra. This
parametrises b, not the line where the planes meet (the library's method).

Checks: for every pair farther apart than 1e-12 of the scale L = max(ra, rb, |Cb - Ca|) (by the
library's certified circle-circle distance), the library's number equals the reference (no
TOUCHING, no UNRESOLVED); pairs at most 2^-40 L apart are TOUCHING; pairs between the two are
either TOUCHING or right; lk(a, b) = lk(b, a); reversing a's normal negates the number; the tori
rule (tube radii around the core distance). Exit 0 on success, 1 with the first failures."""
import os
import sys

import mpmath as mp
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import circledist as cd  # noqa: E402

mp.mp.dps = 50
TOUCH_REL = 2.0 ** -40
APART_REL = 1e-12


def unit(v):
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def random_unit(rng, n):
    return unit(rng.normal(size=(n, 3)))


def perp(rng, nrm):
    """Random unit vectors orthogonal to the rows of nrm."""
    e = random_unit(rng, len(nrm))
    e = e - np.sum(e * nrm, axis=1)[:, None] * nrm
    return unit(e)


def tilt(rng, nrm, angle):
    """nrm rotated by `angle` (per row) towards a random perpendicular direction."""
    p = perp(rng, nrm)
    return unit(np.cos(angle)[:, None] * nrm + np.sin(angle)[:, None] * p)


def families(rng, n):
    """Dict family -> (Ca, Na, ra, Cb, Nb, rb) arrays, about n pairs in all."""
    k = max(n // 10, 1)
    out = {}
    # Random: centres near each other at scale 1, radii 0.1 .. 2.
    out["random"] = (rng.normal(size=(k, 3)) * 0.5, random_unit(rng, k), rng.uniform(0.1, 2, k),
                     rng.normal(size=(k, 3)) * 0.5, random_unit(rng, k), rng.uniform(0.1, 2, k))
    # b centred near a's rim (about half linked).
    Ca = rng.normal(size=(k, 3)); Na = random_unit(rng, k); ra = rng.uniform(0.5, 2, k)
    rim = Ca + ra[:, None] * perp(rng, Na)
    out["near_rim"] = (Ca, Na, ra, rim + rng.normal(size=(k, 3)) * 0.3, random_unit(rng, k),
                       rng.uniform(0.1, 1.5, k))
    # Coplanar (b in a's plane, any position and size) and parallel planes.
    Ca = rng.normal(size=(k, 3)); Na = random_unit(rng, k)
    off = perp(rng, Na) * rng.uniform(0, 3, k)[:, None]
    h = np.where(rng.random(k) < 0.5, 0.0, rng.normal(size=k) * 1e-3)
    out["coplanar"] = (Ca, Na, rng.uniform(0.1, 2, k), Ca + off + h[:, None] * Na,
                       np.where(rng.random(k) < 0.5, 1, -1)[:, None] * Na, rng.uniform(0.1, 2, k))
    # Concentric, any normals and radii (equal radii: the circles meet in two points).
    Ca = rng.normal(size=(k, 3)); ra = rng.uniform(0.2, 2, k)
    rb = np.where(rng.random(k) < 0.2, ra, rng.uniform(0.2, 2, k))
    out["concentric"] = (Ca, random_unit(rng, k), ra, Ca.copy(), random_unit(rng, k), rb)
    # b through a's centre: Cb = Ca + rb e with e in b's plane.
    Ca = rng.normal(size=(k, 3)); Nb = random_unit(rng, k); rb = rng.uniform(0.2, 2, k)
    out["through_centre"] = (Ca, random_unit(rng, k), rng.uniform(0.2, 2, k),
                             Ca + rb[:, None] * perp(rng, Nb), Nb, rb)
    # Tiny ring around a huge ring's wire (linked) or beside it, and far-apart scales.
    Ca = rng.normal(size=(k, 3)) * 1e6; Na = random_unit(rng, k); ra = rng.uniform(0.5, 2, k) * 1e6
    e = perp(rng, Na)
    tang = np.cross(Na, e)
    rb = 10.0 ** rng.uniform(-6, 0, k)
    Nb = np.where(rng.random(k) < 0.5, 1, -1)[:, None] * tilt(rng, tang, rng.uniform(0, 1.4, k))
    Cb = Ca + ra[:, None] * e + (rng.normal(size=(k, 3)) * rb[:, None] * 0.5)
    out["tiny_huge"] = (Ca, Na, ra, Cb, Nb, rb)
    # Nearly parallel planes, b centred near a's rim: the line where the planes meet is far or
    # ill-conditioned.
    Ca = rng.normal(size=(k, 3)); Na = random_unit(rng, k); ra = rng.uniform(0.5, 2, k)
    ang = 10.0 ** rng.uniform(-12, -1, k)
    out["near_parallel"] = (Ca, Na, ra, Ca + ra[:, None] * perp(rng, Na) + rng.normal(size=(k, 3)) * 1e-3,
                            tilt(rng, Na, ang), rng.uniform(0.5, 2, k))
    # b nearly tangent to a's plane (its lowest point 10^-j above or below it) at a point
    # 10^-j inside or outside a's rim: two crossings close together, the rim between them or
    # not; with nearly parallel planes for a third of them.
    Ca = rng.normal(size=(k, 3)); Na = random_unit(rng, k); ra = rng.uniform(0.5, 2, k)
    sgn = lambda: np.where(rng.random(k) < 0.5, 1.0, -1.0)
    X = Ca + (ra + sgn() * 10.0 ** -rng.uniform(2, 13, k))[:, None] * perp(rng, Na)
    ang = np.where(rng.random(k) < 0.33, 10.0 ** -rng.uniform(1, 9, k), rng.uniform(0.1, 1.5, k))
    Nb = tilt(rng, Na, ang); rb = rng.uniform(0.3, 1.5, k)
    low = unit(-Na + np.sum(Na * Nb, axis=1)[:, None] * Nb)
    eps = sgn() * 10.0 ** -rng.uniform(2, 14, k)
    out["tangent"] = (Ca, Na, ra, X - rb[:, None] * low + eps[:, None] * Na, Nb, rb)
    # The same with b 1e-13.5 .. 1e-12 below a's plane (crossings about 1e-7 apart) and the rim
    # 1e-12 .. 3e-11 from them: chords near the rounding of their squares (mostly touching).
    X = Ca + (ra + sgn() * 10.0 ** -rng.uniform(10.5, 12, k))[:, None] * perp(rng, Na)
    eps = -10.0 ** -rng.uniform(12, 13.5, k)
    out["tangent_close"] = (Ca, Na, ra, X - rb[:, None] * low + eps[:, None] * Na, Nb, rb)
    # Nearly parallel planes (1e-11 .. 1e-6 rad) with an end of b's chord on the common line
    # 1e-12 .. 1e-6 from an end of a's: the line's position is ill-conditioned (error ~ eps / angle;
    # mostly touching, the rims cross within the angle times the gap).
    Ca = rng.normal(size=(k, 3)); Na = random_unit(rng, k); ra = rng.uniform(0.5, 2, k)
    D = perp(rng, Na); m0 = np.cross(Na, D)
    dela = rng.uniform(-0.9, 0.9, k) * ra
    E = Ca + dela[:, None] * m0 + np.sqrt(ra ** 2 - dela ** 2)[:, None] * D
    ang = 10.0 ** -rng.uniform(6, 11, k)
    Nb = np.cos(ang)[:, None] * Na + np.sin(ang)[:, None] * m0
    m = np.cross(Nb, D)
    hb = rng.uniform(0.2, 1, k); delb = rng.uniform(-0.5, 0.5, k)
    end = E + (sgn() * 10.0 ** -rng.uniform(6, 12, k))[:, None] * D
    out["parallel_chord"] = (Ca, Na, ra, end - hb[:, None] * D + delb[:, None] * m, Nb,
                             np.sqrt(hb ** 2 + delb ** 2))
    # Intersecting: b through a point of a.
    Ca = rng.normal(size=(k, 3)); Na = random_unit(rng, k); ra = rng.uniform(0.2, 2, k)
    X = Ca + ra[:, None] * perp(rng, Na)
    Nb = random_unit(rng, k); rb = rng.uniform(0.2, 2, k)
    out["intersecting"] = (Ca, Na, ra, X + rb[:, None] * perp(rng, Nb), Nb, rb)
    return out


def near_touching(rng, k):
    """Pairs moved to distance 10^-j L (j = 3 .. 14) along their closest pair's direction."""
    Ca = rng.normal(size=(k, 3)); Na = random_unit(rng, k); ra = rng.uniform(0.5, 2, k)
    Cb = Ca + ra[:, None] * perp(rng, Na) + rng.normal(size=(k, 3)) * 0.3
    Nb = random_unit(rng, k); rb = rng.uniform(0.3, 1.5, k)
    res = cd.circle_circle(cd.Circle(Ca, Na, ra), cd.Circle(Cb, Nb, rb))
    P = res.points[:, 0, 0]; Q = res.points[:, 0, 1]
    d = res.distance
    L = np.maximum(np.maximum(ra, rb), np.linalg.norm(Cb - Ca, axis=1))
    want = L * 10.0 ** -rng.uniform(3, 14, k)
    dirn = (Q - P) / np.where(d > 0, d, 1)[:, None]
    Cb = Cb - ((d - want)[:, None] * dirn)
    return Ca, Na, ra, Cb, Nb, rb


def reference(ca, na, ra, cb, nb, rb):
    """The crossing count in mpmath (see the module docstring)."""
    Ca = [mp.mpf(float(x)) for x in ca]
    Cb = [mp.mpf(float(x)) for x in cb]
    Na = [mp.mpf(float(x)) for x in na]
    Nb = [mp.mpf(float(x)) for x in nb]
    ra = mp.mpf(float(ra)); rb = mp.mpf(float(rb))
    la = mp.sqrt(sum(x * x for x in Na)); lb = mp.sqrt(sum(x * x for x in Nb))
    Na = [x / la for x in Na]; Nb = [x / lb for x in Nb]
    i = min(range(3), key=lambda j: abs(Nb[j]))
    e = [mp.mpf(1) if j == i else mp.mpf(0) for j in range(3)]
    en = sum(e[j] * Nb[j] for j in range(3))
    U = [e[j] - en * Nb[j] for j in range(3)]
    lu = mp.sqrt(sum(x * x for x in U)); U = [x / lu for x in U]
    V = [Nb[1] * U[2] - Nb[2] * U[1], Nb[2] * U[0] - Nb[0] * U[2], Nb[0] * U[1] - Nb[1] * U[0]]
    h0 = sum((Cb[j] - Ca[j]) * Na[j] for j in range(3))
    al = rb * sum(U[j] * Na[j] for j in range(3)); be = rb * sum(V[j] * Na[j] for j in range(3))
    R = mp.sqrt(al * al + be * be)
    if R == 0 or abs(h0) >= R:
        return 0, mp.inf
    phi = mp.atan2(be, al)
    g = mp.acos(-h0 / R)
    lk = 0
    gap = mp.inf
    for th in (phi + g, phi - g):
        c, s = mp.cos(th), mp.sin(th)
        X = [Cb[j] + rb * (c * U[j] + s * V[j]) for j in range(3)]
        rho = mp.sqrt(sum((X[j] - Ca[j]) ** 2 for j in range(3)))
        gap = min(gap, abs(rho - ra))
        tang = sum((-s * U[j] + c * V[j]) * Na[j] for j in range(3))
        if rho < ra:
            lk += 1 if tang > 0 else -1
    return lk, gap


def main():
    n = int(sys.argv[1])
    seed = int(sys.argv[2]) if len(sys.argv) > 2 else 28
    rng = np.random.default_rng(seed)
    fams = families(rng, n)
    fams["near_touching"] = near_touching(rng, max(n // 5, 1))
    # Tiny and huge copies: every family scaled by 2^k, k in -600 .. 400 (exact).
    total = 0
    failures = []
    stats = {}
    for name, (Ca, Na, ra, Cb, Nb, rb) in list(fams.items()):
        for variant in ("", "_scaled"):
            if variant:
                s = 2.0 ** rng.integers(-600, 400, len(ra)).astype(float)
                Ca, ra, Cb, rb = Ca * s[:, None], ra * s, Cb * s[:, None], rb * s
            A = cd.Circle(Ca, Na, ra); B = cd.Circle(Cb, Nb, rb)
            rec, st = cd.link_details(A, B)
            rev, st2 = cd.link_details(B, A)
            neg, st3 = cd.link_details(cd.Circle(Ca, -Na, ra), B)
            # Tori: tube radii straddling the core distance.
            frac = rng.choice([0.3, 0.499, 0.5, 0.7], len(ra))
            tr = rec["core_distance"] * frac
            tor, st4 = cd.link_details(cd.Torus(A, tr), cd.Torus(B, tr))
            fam_stats = stats.setdefault(name + variant, {})
            for i in range(len(ra)):
                total += 1
                where = "%s%s[%d]" % (name, variant, i)
                if st[i] or st2[i] or st3[i] or st4[i]:
                    failures.append("%s: status %d %d %d %d" % (where, st[i], st2[i], st3[i], st4[i]))
                    continue
                d = rec["distance"][i]; L = rec["scale"][i]; lk = int(rec["linking"][i])
                ref, gap = reference(Ca[i], Na[i], ra[i], Cb[i], Nb[i], rb[i])
                key = "touching" if lk == cd.LINK_TOUCHING else "lk=%d" % lk
                fam_stats[key] = fam_stats.get(key, 0) + 1
                if rec["flags"][i] & cd.LINK_FLAG_EXTENDED:
                    fam_stats["extended"] = fam_stats.get("extended", 0) + 1
                if d > APART_REL * L:
                    if lk != ref:
                        failures.append("%s: linking %d, reference %d (distance %.3g L, crossing gap %s)"
                                        % (where, lk, ref, d / L, mp.nstr(gap, 5)))
                elif d <= TOUCH_REL * L:
                    if lk != cd.LINK_TOUCHING:
                        failures.append("%s: distance %.3g L but linking %d, not touching" % (where, d / L, lk))
                elif lk != cd.LINK_TOUCHING and lk != ref:
                    failures.append("%s: linking %d, reference %d (distance %.3g L)" % (where, lk, ref, d / L))
                if int(rev["linking"][i]) != lk:
                    failures.append("%s: lk(b, a) = %d != lk(a, b) = %d" % (where, rev["linking"][i], lk))
                nl = int(neg["linking"][i])
                if (lk in (-1, 0, 1) and nl != -lk) or (lk == cd.LINK_TOUCHING and nl != lk):
                    failures.append("%s: reversing a's normal gave %d for %d" % (where, nl, lk))
                tl = int(tor["linking"][i])
                want = cd.LINK_OVERLAP if (tr[i] > 0 and not (d - 2 * tr[i] > 0)) else lk
                if tl != want or int(tor["core_linking"][i]) != lk:
                    failures.append("%s: tori (tube %g of core distance) gave %d/%d, want %d/%d"
                                    % (where, frac[i], tl, tor["core_linking"][i], want, lk))
    for name in sorted(stats):
        print("%-24s %s" % (name, " ".join("%s:%d" % kv for kv in sorted(stats[name].items()))))
    print("%d pairs, %d failures" % (total, len(failures)))
    for f in failures[:30]:
        print("FAIL", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
