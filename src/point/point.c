/* SPDX-License-Identifier: MIT */
/* Point-circle and point-disk (Eberly, distance-to-circles-3d §2; point-curve-circle-to-disk §2).
 * Work relative to the centre; the distance to the axis is |N x D| (accurate near the axis, where
 * sqrt(|D|^2 - h^2) would cancel). */
#include <math.h>

#include "api/api-priv.h"
#include "base/point_circle.h"
#include "point/point-priv.h"

/* The fast path (point_body.h) in one lane, on the scalar evaluator's instance. */
#define CD_LANES 1
#include "base/lanes/lanes_def.h"
#undef KN
#define KN(name) CD_LANE1_KN(name)
#include "api/circle_fast_lanes.h"
#include "point_body.h"
#include "base/lanes/lanes_undef.h"

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

/* The pair of p (relative to the centre) from its evaluation e against c and its squared
 * distance d2 (point_d2): on a disk the projection where p is over it (rho <= r), else the
 * circle's point; every circle point (angle 0 the representative) for p on the axis. */
CD_INLINE cdist__point_pair pair_of(vec3 p, const cdist__circle *c, int disk, const cdist__pc_parts *e, double d2)
{
    cdist__point_pair q;
    vec3 w = cdist__pc_inplane(e->np, c->n);
    int axis = on_axis(p, e->rho);
    q.d2 = d2;
    q.equidistant = 0;
    if (disk && !(e->rho > c->r)) {
        q.angle = axis ? NAN : plane_angle(c->n, w, e->np);
        q.k = axis ? v3(0, 0, 0) : w;
    } else if (c->r == 0.0) {
        q.k = v3(0, 0, 0);
        q.angle = NAN;
    } else if (axis) {
        q.k = axis_representative(c);
        q.angle = 0.0;
        q.equidistant = 1;
    } else {
        q.k = cdist__pc_along(w, c->r);
        q.angle = plane_angle(c->n, w, e->np);
    }
    return q;
}

CD_INLINE cdist__point_pair pair_at(vec3 p, const cdist__circle *c, int disk)
{
    cdist__pc_parts e = cdist__point_circle(c->n, p, c->r);
    return pair_of(p, c, disk, &e, cdist__point_d2_lane1(e.rho, e.hh, e.d2, c->r, disk));
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

/* The whole query for inputs of the usual kind, fused in one FMA clone: the fast path of
 * point_body.h (validation and distance, unscaled: scale at least CD_POINT_MIN_SCALE gives the
 * same roundings as scaled; the batch point kernel runs the same body in lanes), the pair and
 * the result, with no call, no copy of the circle and no pre-filled result. 0 when any check is
 * in doubt: the checked and scaled path then answers or reports. */
CD_FMA_CLONES CD_NO_SLP static int point_fast(double unit_tol, const cdist_vec3 *P, const cdist_circle *C, int disk,
                                              cdist_result *r)
{
    const double p[3] = {P->x, P->y, P->z}, c[3] = {C->center.x, C->center.y, C->center.z},
                 d[3] = {C->normal.x, C->normal.y, C->normal.z};
    cdist__point_lane_lane1 f = cdist__point_fast_lane1(p, c, d, C->radius, unit_tol, disk);
    if (!f.ok) return 0;
    cdist__circle cc;
    cc.c = C->center;
    cc.n = v3(f.n[0], f.n[1], f.n[2]);
    cc.r = C->radius;
    cdist__pc_parts e = cdist__pc_parts_of_lane(&f.e);
    cdist__point_pair k = pair_of(v3(f.rel[0], f.rel[1], f.rel[2]), &cc, disk, &e, f.d2);
    write_result(*P, cc.c, 1.0, &k, r);
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
