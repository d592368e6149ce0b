/* SPDX-License-Identifier: MIT */
/* The point-circle and point-disk fast path, written once over a lane type: the single queries'
 * fast path (src/point/point.c) is its one-lane instance, the batch point kernel
 * (src/batch/point_kernel.c) its 4- and 8-lane instances, so that the kernel's distances are the
 * single query's bit for bit. The includer defines the lanes (src/base/lanes/lanes_def.h) and
 * includes lanes_vec.h, base/point_circle_lanes.h and api/circle_fast_lanes.h before this file.
 * No include guard. */

/* The squared distance of a point to the circle of radius r, or (disk) to the disk, from its
 * evaluation (point_circle_lanes.h: rho, hh, d2): h^2 where it is over the disk (rho <= r), else
 * the circle's d2. */
CD_INLINE V KN(point_d2)(V rho, V hh, V d2, V r, int disk) { return disk ? vsel(vgt(rho, r), d2, hh) : d2; }

/* The fast path of point p against the circle or disk of centre c, normal d (as given) and
 * radius r: the lanes it answers (ok), the unit normal n, p - c (rel), its evaluation e and the
 * squared distance d2. A lane fails when its entry fails the single query's fast validation
 * (cdist__in_range of p and cdist__circle_fast_body, src/api/api-priv.h, with their arithmetic)
 * or when its scale L = max(r, |p - c|) is below CD_POINT_MIN_SCALE (it must be scaled first). */
typedef struct KN(point_lane) {
    M ok;
    V n[3], rel[3];
    KN(pc_parts) e;
    V d2;
} KN(point_lane);

CD_INLINE KN(point_lane) KN(point_fast)(const V p[3], const V c[3], const V d[3], V r, double unit_tol, int disk)
{
    KN(point_lane) f;
    M ok = KN(circle_fast)(c, d, r, unit_tol, f.n);
    ok = mand(KN(in_range)(p[0], p[1], p[2]), ok);
    f.rel[0] = vsub(p[0], c[0]), f.rel[1] = vsub(p[1], c[1]), f.rel[2] = vsub(p[2], c[2]);
    f.e = KN(point_circle)(f.n, f.rel, r);
    /* |rel|^2 = |n x rel|^2 + h^2 */
    V L2 = KN(fmax)(vadd(f.e.q2, f.e.hh), vmul(r, r));
    f.ok = mand(ok, vge(L2, vset(CD_POINT_MIN_SCALE * CD_POINT_MIN_SCALE)));
    f.d2 = KN(point_d2)(f.e.rho, f.e.hh, f.e.d2, r, disk);
    return f;
}
