/* SPDX-License-Identifier: MIT */
/* Point-circle and point-disk (Eberly, distance-to-circles-3d §2; point-curve-circle-to-disk §2).
 * Work relative to the centre; the distance to the axis is |N x D| (accurate near the axis, where
 * sqrt(|D|^2 - h^2) would cancel). */
#include <math.h>

#include "api/api-priv.h"
#include "point/point-priv.h"

/* Circle angle of the in-plane direction w without the basis: with k the basis index of
 * v_basis (smallest |n_k|), u = (e_k - n_k n)/s and v = n x u for s = |e_k - n_k n| > 0, so
 * u . w = w_k / s and v . w = u . (w x n) = (p x n)_k / s = -(n x p)_k / s for w = (n x p) x n;
 * s cancels in atan2. k is an index, not a branch: a random normal's k is unpredictable. */
CD_INLINE double plane_angle(vec3 n, vec3 w, vec3 np)
{
    double ax = fabs(n.x), ay = fabs(n.y), az = fabs(n.z);
    int x_least = (ax <= ay) & (ax <= az);
    int k = x_least ? 0 : 1 + (ay > az);
    const double wk[3] = {w.x, w.y, w.z}, npk[3] = {np.x, np.y, np.z};
    return cdist__polar_angle(wk[k], -npk[k]);
}

/* The representative circle point (angle 0) for a point on the axis: r u. */
CD_INLINE vec3 axis_representative(const cdist__circle *c)
{
    vec3 u, v;
    v_basis(c->n, &u, &v);
    return v_scale(c->r, u);
}

/* The point is on the axis when its axis distance is below the rounding noise of |N x D|
 * (compared squared: no square root). Scaled, nothing underflows; unscaled (the fast path) a
 * point within about 2^-537 of the centre underflows to "on the axis" (known; the distance is
 * unaffected). */
CD_INLINE int on_axis(vec3 p, double rho)
{
    const double k = CD_ON_AXIS_ULPS * DBL_EPSILON;
    return rho * rho <= (k * k) * v_sqr(p);
}

/* Split p (relative to the centre) into height h along n, in-plane part w and axis distance rho.
 * w = (n x p) x n is the in-plane part; built from the cross product it stays in the plane and
 * keeps its direction accurate even within a few ulps of the axis, where p - h n would cancel. */
CD_INLINE void split(vec3 p, vec3 n, double *h, vec3 *w, vec3 *np, double *rho)
{
    *np = v_cross(n, p);
    *h = v_dot(n, p);
    *w = v_cross(*np, n);
    *rho = v_norm(*np);
}

CD_INLINE cdist__point_pair circle_pair(vec3 p, const cdist__circle *c, double h, vec3 w, vec3 np, double rho)
{
    cdist__point_pair q;
    q.equidistant = 0;
    if (c->r == 0.0) {
        q.k = v3(0, 0, 0);
        q.angle = NAN;
    } else if (on_axis(p, rho)) {
        /* Every circle point is closest; angle 0 is the representative. */
        q.k = axis_representative(c);
        q.angle = 0.0;
        q.equidistant = 1;
    } else {
        /* |w|, not rho: near the axis the rounding of n x p leaves it slightly off
         * perpendicular to n, and only w (which is perpendicular) scaled by its own length
         * lands on the circle. */
        /* A point within 1e-150 of the scale from the axis has a w whose squares are
         * subnormal: normalise a copy scaled to its largest component there. */
        vec3 ws = w;
        double m = v_maxabs(w);
        if (m < CD_MIN_NORMAL_FAST) ws = v3(w.x / m, w.y / m, w.z / m);
        q.k = v_scale(c->r / v_norm(ws), ws);
        q.angle = plane_angle(c->n, w, np);
    }
    double dr = rho - c->r;
    q.d2 = fma(dr, dr, h * h);
    return q;
}

/* The disk point of p (relative to the centre) over the disk (rho <= r): its projection. */
CD_INLINE cdist__point_pair disk_inside(const cdist__circle *c, double h, vec3 w, vec3 np, double rho, vec3 p)
{
    cdist__point_pair q;
    int axis = on_axis(p, rho);
    q.angle = axis ? NAN : plane_angle(c->n, w, np);
    q.k = axis ? v3(0, 0, 0) : w;
    q.d2 = h * h;
    q.equidistant = 0;
    return q;
}

/* The pair of p (relative to the centre) from its split: on a disk the projection where p is
 * over it (rho <= r), else the circle's point. */
CD_INLINE cdist__point_pair pair_of_split(vec3 p, const cdist__circle *c, int disk, double h, vec3 w, vec3 np, double rho)
{
    if (disk && !(rho > c->r)) return disk_inside(c, h, w, np, rho, p);
    return circle_pair(p, c, h, w, np, rho);
}

CD_INLINE cdist__point_pair pair_at(vec3 p, const cdist__circle *c, int disk)
{
    double h, rho;
    vec3 w, np;
    split(p, c->n, &h, &w, &np, &rho);
    return pair_of_split(p, c, disk, h, w, np, rho);
}

CD_FMA_CLONES cdist__point_pair cdist__point_circle_pair(vec3 p, const cdist__circle *c) { return pair_at(p, c, 0); }
CD_FMA_CLONES cdist__point_pair cdist__point_disk_pair(vec3 p, const cdist__circle *c) { return pair_at(p, c, 1); }

void cdist__point_circle_core(vec3 p, const cdist__circle *c, cdist__best *b, int swap)
{
    cdist__point_pair q = cdist__point_circle_pair(p, c);
    if (swap) cdist__best_offer_flag(b, q.equidistant, q.d2, q.k, p, q.angle, NAN);
    else cdist__best_offer_flag(b, q.equidistant, q.d2, p, q.k, NAN, q.angle);
}

void cdist__point_disk_core(vec3 p, const cdist__circle *c, cdist__best *b, int swap)
{
    cdist__point_pair q = cdist__point_disk_pair(p, c);
    if (swap) cdist__best_offer_flag(b, q.equidistant, q.d2, q.k, p, q.angle, NAN);
    else cdist__best_offer_flag(b, q.equidistant, q.d2, p, q.k, NAN, q.angle);
}

/* The result of a pair k (relative to the centre c, of a problem scaled by 2^-e: up = 2^e) of p.
 * The unused fields are written here with the rest: one pass over the result. */
CD_INLINE void write_result(vec3 p, vec3 c, double up, const cdist__point_pair *k, cdist_result *r)
{
    r->distance = sqrt(k->d2) * up;
    r->sqr_distance = (k->d2 * up) * up;
    r->num_pairs = 1;
    r->equidistant = k->equidistant;
    r->pairs[0].point[0] = p; /* exactly the caller's point */
    r->pairs[0].point[1] = v_axpy(c, up, k->k);
    r->pairs[0].param[0] = NAN;
    r->pairs[0].param[1] = k->angle;
    cdist__result_finish(r, 1);
}

/* Frame (translate to the centre) and scale (by 2^-e, exact, so that the scale is in [1, 2):
 * no underflow or overflow in squares for any accepted input), core, result. */
CD_FMA_CLONES void cdist__point_result(vec3 p, const cdist__circle *c, int disk, cdist_result *r)
{
    vec3 rel = v_sub(p, c->c);
    int e = cdist__scale_exponent(cdist__fmax(c->r, v_maxabs(rel)));
    double down = cdist__pow2(-e), up = cdist__pow2(e);
    vec3 ps = v_scale(down, rel);
    cdist__circle sc = *c;
    sc.r = c->r * down;
    cdist__point_pair k = pair_at(ps, &sc, disk);
    write_result(p, c->c, up, &k, r);
}

/* The whole query for inputs of the usual kind, fused in one FMA clone: the fast validation
 * (cdist__circle_fast_body), the core unscaled (scale at least CD_POINT_MIN_SCALE: the same
 * roundings as scaled) and the result, with no call, no copy of the circle and no pre-filled
 * result. 0 when any check is in doubt: the checked and scaled path then answers or reports.
 * The distance's arithmetic and the checks are the batch point kernel's
 * (src/batch/point_kernel.c), operation by operation: the kernel takes exactly these entries
 * and its distances are bit-identical. */
CD_FMA_CLONES CD_NO_SLP static int point_fast(double unit_tol, const cdist_vec3 *P, const cdist_circle *C, int disk,
                                              cdist_result *r)
{
    vec3 p = *P;
    cdist__circle c;
    if (!cdist__in_range(p) || !cdist__circle_fast_body(unit_tol, C, &c))
        return 0;
    double h, rho;
    vec3 w, np, rel = v_sub(p, c.c);
    split(rel, c.n, &h, &w, &np, &rho);
    /* the batch kernel's scale guard: |rel|^2 = |n x rel|^2 + h^2, or r^2 */
    if (!(cdist__fmax(v_sqr(np) + h * h, c.r * c.r) >= CD_POINT_MIN_SCALE * CD_POINT_MIN_SCALE)) return 0;
    cdist__point_pair k = pair_of_split(rel, &c, disk, h, w, np, rho);
    write_result(p, c.c, 1.0, &k, r);
    return 1;
}

/* The checked and scaled path: every input the fast path doubts (reports or answers it). */
static __attribute__((noinline)) cdist_status point_checked(cdist_query *q, const cdist_vec3 *p, const cdist_circle *c,
                                                            cdist_result *r, int disk)
{
    cdist__circle cc;
    cdist_status st = cdist__check_point(q, p, "point");
    if (!st) st = cdist__check_circle_nobasis(q, c, disk ? "disk" : "circle", &cc);
    if (!st) cdist__point_result(*p, &cc, disk, r);
    return st;
}

static inline cdist_status point_query(cdist_query *q, const cdist_vec3 *p, const cdist_circle *c, cdist_result *r,
                                       int disk)
{
    cdist_status st = cdist__enter(q, r);
    if (st) return st;
    if (!p || !c || !point_fast(q->unit_tol, p, c, disk, r)) st = point_checked(q, p, c, r, disk);
    return cdist__leave(q, r, st, CDIST_METHOD_AUTO);
}

cdist_status cdist_point_circle(cdist_query *q, const cdist_vec3 *p, const cdist_circle *c, cdist_result *r)
{
    return point_query(q, p, c, r, 0);
}

cdist_status cdist_point_disk(cdist_query *q, const cdist_vec3 *p, const cdist_circle *d, cdist_result *r)
{
    return point_query(q, p, d, r, 1);
}
