/* SPDX-License-Identifier: MIT */
/* Swept objects (torus, capsule, sphere, rounded disk): the signed distance is the core
 * distance minus the radii; every closest pair, the equidistant flag and the method come from
 * the core query. Point-point, point-segment and segment-segment have no public core query and
 * are answered here in closed form. */
#include <math.h>
#include <string.h>

#include "swept-priv.h"

/* ---- closed-form cores ---- */

static void result_fill(cdist_result *r, double d, int equidistant, vec3 p0, vec3 p1, double a0, double a1)
{
    r->distance = d;
    r->sqr_distance = d * d;
    r->num_pairs = 1;
    r->equidistant = equidistant;
    r->pairs[0].point[0] = p0;
    r->pairs[0].point[1] = p1;
    r->pairs[0].param[0] = a0;
    r->pairs[0].param[1] = a1;
}

/* Parameter in [0, 1] of the point of segment p0 + s d closest to p. In units of d's largest
 * component (a power of two: exact, and the same quotient wherever d . d is a normal double),
 * so that d . d of a tiny segment does not underflow to 0. */
static double segment_clamp(vec3 p0, vec3 d, vec3 p)
{
    int e = cdist__scale_exponent(v_maxabs(d));
    vec3 dn = v_scale(cdist__pow2(-e), d);
    double dd = v_sqr(dn);
    if (dd == 0.0) return 0.0;
    double s = v_dot(v_sub(p, p0), dn) / dd * cdist__pow2(-e);
    return s < 0.0 ? 0.0 : (s > 1.0 ? 1.0 : s);
}

static vec3 segment_at(vec3 p0, vec3 d, double s) { return v_axpy(p0, s, d); }

static cdist_status point_point(cdist_query *q, const cdist_vec3 *a, const cdist_vec3 *b, cdist_result *r)
{
    cdist_status st = cdist__enter(q, r);
    if (st) return st;
    if (!(st = cdist__check_point(q, a, "point")) && !(st = cdist__check_point(q, b, "point")))
        result_fill(r, v_norm_scaled(v_sub(*a, *b)), 0, *a, *b, NAN, NAN);
    return cdist__leave(q, r, st, CDIST_METHOD_AUTO);
}

static cdist_status point_segment(cdist_query *q, const cdist_vec3 *p, const cdist_segment *s, cdist_result *r)
{
    cdist_status st = cdist__enter(q, r);
    if (st) return st;
    if ((st = cdist__check_point(q, p, "point")) || (st = cdist__check_segment(q, s)))
        return cdist__leave(q, r, st, CDIST_METHOD_AUTO);
    vec3 d = v_sub(s->p1, s->p0);
    double t = segment_clamp(s->p0, d, *p);
    vec3 x = t == 1.0 ? s->p1 : segment_at(s->p0, d, t);
    result_fill(r, v_norm_scaled(v_sub(*p, x)), 0, *p, x, NAN, t);
    return cdist__leave(q, r, CDIST_OK, CDIST_METHOD_AUTO);
}

/* Lexicographic order of two segments' coordinates (p0 then p1): 1 when a comes first. */
static int segment_first(const cdist_segment *a, const cdist_segment *b)
{
    const double xa[6] = {a->p0.x, a->p0.y, a->p0.z, a->p1.x, a->p1.y, a->p1.z};
    const double xb[6] = {b->p0.x, b->p0.y, b->p0.z, b->p1.x, b->p1.y, b->p1.z};
    for (int i = 0; i < 6; i++)
        if (xa[i] != xb[i]) return xa[i] < xb[i];
    return 1;
}

/* Parallel segments (squared lengths A, E > 0): do their projections on the common direction
 * overlap over a positive length? Then every point of the overlap gives a closest pair, a flat
 * valley. Measured along the longer segment's direction from the shorter one's start, so the
 * overlap's ends are computed from coordinates near them (a segment of length 1e100 against
 * one of length 7 keeps the 7), and with the roles chosen from the segments themselves (the
 * longer, ties by coordinates) the decision is the same in both argument orders. */
static int parallel_overlap(const cdist_segment *a, const cdist_segment *b, double A, double E)
{
    int a_long = A > E || (A == E && segment_first(a, b));
    const cdist_segment *lg = a_long ? a : b, *sh = a_long ? b : a;
    vec3 u = v_unit_or_zero(v_sub(lg->p1, lg->p0));
    double l0 = v_dot(v_sub(lg->p0, sh->p0), u), l1 = v_dot(v_sub(lg->p1, sh->p0), u);
    double s1 = v_dot(v_sub(sh->p1, sh->p0), u);
    double lo = fmax(fmin(l0, l1), fmin(0.0, s1)), hi = fmin(fmax(l0, l1), fmax(0.0, s1));
    return hi - lo > CD_SEG_OVERLAP_ULPS * DBL_EPSILON * fmax(fabs(lo), fabs(hi));
}

/* Segment-segment: the interior critical point (s inside [0, 1], t its projection on b) and
 * the four end-point-to-segment candidates, each measured on the true distance. The squared
 * distance is convex in (s, t), so the smallest candidate is the minimum; two distinct minima
 * only exist along a flat valley (parallel segments), which is flagged equidistant. */
static cdist_status segment_segment(cdist_query *q, const cdist_segment *a, const cdist_segment *b, cdist_result *r)
{
    cdist_status st = cdist__enter(q, r);
    if (st) return st;
    if ((st = cdist__check_segment(q, a)) || (st = cdist__check_segment(q, b)))
        return cdist__leave(q, r, st, CDIST_METHOD_AUTO);
    vec3 da = v_sub(a->p1, a->p0), db = v_sub(b->p1, b->p0);
    double best = INFINITY, bs = 0, bt = 0;
    vec3 bp = a->p0, bq = b->p0;
#define CAND(s_, t_)                                                                                                \
    do {                                                                                                           \
        double s__ = (s_), t__ = (t_);                                                                             \
        vec3 P = s__ == 1.0 ? a->p1 : segment_at(a->p0, da, s__);                                                  \
        vec3 Q = t__ == 1.0 ? b->p1 : segment_at(b->p0, db, t__);                                                  \
        double dd = v_norm_scaled(v_sub(P, Q));                                                                    \
        if (dd < best) { best = dd; bs = s__; bt = t__; bp = P; bq = Q; }                                          \
    } while (0)
    double A = v_sqr(da), E = v_sqr(db);
    /* Interior critical point, backward stable for nearly parallel segments (docs/swept.md,
     * "Segment to segment"). */
    vec3 w = v_sub(b->p0, a->p0);
    double m = fmax(v_maxabs(w), fmax(v_maxabs(da), v_maxabs(db)));
    double down = m > 0.0 ? cdist__pow2(-cdist__scale_exponent(m)) : 1.0;
    vec3 sa = v_scale(down, da), sb = v_scale(down, db), sw = v_scale(down, w);
    double sA = v_sqr(sa);
    if (sA > 0.0) {
        vec3 c = v_axpy(sb, -v_dot(sb, sa) / sA, sa);
        double mu = v_dot(sw, sa) / sA;
        vec3 wp = v_axpy(sw, -mu, sa);
        vec3 n = v_cross(sa, c);
        double den = v_sqr(n);
        if (den > 0.0) {
            double s = mu + v_dot(v_cross(wp, sb), n) / den;
            if (s >= 0.0 && s <= 1.0) {
                vec3 P = s == 1.0 ? a->p1 : segment_at(a->p0, da, s);
                CAND(s, segment_clamp(b->p0, db, P));
            }
        }
    }
    /* The four end-point candidates always: they carry the answer when den is tiny or 0. */
    CAND(0.0, segment_clamp(b->p0, db, a->p0));
    CAND(1.0, segment_clamp(b->p0, db, a->p1));
    CAND(segment_clamp(a->p0, da, b->p0), 0.0);
    CAND(segment_clamp(a->p0, da, b->p1), 1.0);
#undef CAND
    /* Parallel: from the two unit directions, each normalised on its own (a segment far shorter
     * than the other keeps its direction), and their cross product, which only changes sign when
     * a and b swap: the decision does not depend on the argument order. */
    int parallel = !(v_sqr(v_cross(v_unit_or_zero(da), v_unit_or_zero(db))) > CD_SEG_PARALLEL_SIN2);
    int equi = parallel && A > 0.0 && E > 0.0 && parallel_overlap(a, b, A, E);
    result_fill(r, best, equi, bp, bq, bs, bt);
    return cdist__leave(q, r, CDIST_OK, CDIST_METHOD_AUTO);
}

/* ---- core dispatch ---- */

/* The core query for (ta, tb) in this order, or -1 when that order has none. */
static int core_direct(cdist_query *q, cdist__core_type ta, const void *a, cdist__core_type tb, const void *b,
                       cdist_result *r, cdist_status *st)
{
#define PAIR(x, y) ((x) * 16 + (y))
    switch (PAIR(ta, tb)) {
    case PAIR(CD_CORE_POINT, CD_CORE_POINT): *st = point_point(q, a, b, r); return 0;
    case PAIR(CD_CORE_POINT, CD_CORE_SEGMENT): *st = point_segment(q, a, b, r); return 0;
    case PAIR(CD_CORE_POINT, CD_CORE_CIRCLE): *st = cdist_point_circle(q, a, b, r); return 0;
    case PAIR(CD_CORE_POINT, CD_CORE_DISK): *st = cdist_point_disk(q, a, b, r); return 0;
    case PAIR(CD_CORE_SEGMENT, CD_CORE_SEGMENT): *st = segment_segment(q, a, b, r); return 0;
    case PAIR(CD_CORE_SEGMENT, CD_CORE_CIRCLE): *st = cdist_segment_circle(q, a, b, r); return 0;
    case PAIR(CD_CORE_SEGMENT, CD_CORE_DISK): *st = cdist_segment_disk(q, a, b, r); return 0;
    case PAIR(CD_CORE_LINE, CD_CORE_CIRCLE): *st = cdist_line_circle(q, a, b, r); return 0;
    case PAIR(CD_CORE_LINE, CD_CORE_DISK): *st = cdist_line_disk(q, a, b, r); return 0;
    case PAIR(CD_CORE_RAY, CD_CORE_CIRCLE): *st = cdist_ray_circle(q, a, b, r); return 0;
    case PAIR(CD_CORE_RAY, CD_CORE_DISK): *st = cdist_ray_disk(q, a, b, r); return 0;
    case PAIR(CD_CORE_CIRCLE, CD_CORE_CIRCLE): *st = cdist_circle_circle(q, a, b, r); return 0;
    case PAIR(CD_CORE_CIRCLE, CD_CORE_DISK): *st = cdist_circle_disk(q, a, b, r); return 0;
    case PAIR(CD_CORE_DISK, CD_CORE_DISK): *st = cdist_disk_disk(q, a, b, r); return 0;
    case PAIR(CD_CORE_ARC, CD_CORE_CIRCLE): *st = cdist_arc_circle(q, a, b, r); return 0;
    case PAIR(CD_CORE_ARC, CD_CORE_ARC): *st = cdist_arc_arc(q, a, b, r); return 0;
    case PAIR(CD_CORE_SEGMENT, CD_CORE_ARC): *st = cdist_segment_arc(q, a, b, r); return 0;
    case PAIR(CD_CORE_ARC, CD_CORE_DISK): *st = cdist_arc_disk(q, a, b, r); return 0;
    default: return -1;
    }
#undef PAIR
}

cdist_status cdist__core_query(cdist_query *q, const cdist__core_obj *a, const cdist__core_obj *b, cdist_result *r)
{
    cdist_status st = CDIST_ERR_INTERNAL;
    if (core_direct(q, a->type, a->obj, b->type, b->obj, r, &st) == 0) return st;
    if (core_direct(q, b->type, b->obj, a->type, a->obj, r, &st) == 0) {
        if (st == CDIST_OK) cdist__result_swap(r);
        return st;
    }
    if ((st = cdist__enter(q, r))) return st;
    return cdist__leave(q, r, cdist__fail(q, CDIST_ERR_INTERNAL, "no core query for this pair of objects"),
                        CDIST_METHOD_AUTO);
}

/* ---- contact ---- */

/* A pair that is not given: NaN throughout. */
static void contact_pair_unset(cdist_contact_pair *p)
{
    for (int k = 0; k < 2; k++) {
        p->point[k] = v3(NAN, NAN, NAN);
        p->core_point[k] = v3(NAN, NAN, NAN);
        p->param[k] = NAN;
    }
    p->normal = v3(NAN, NAN, NAN);
}

void cdist__contact_set_error(cdist_contact *c)
{
    memset(c, 0, sizeof *c);
    c->distance = NAN;
    c->core_distance = NAN;
    for (int i = 0; i < 2; i++) contact_pair_unset(&c->pairs[i]);
}

/* Reference point of a core (for the orientation of a touch normal). */
static vec3 core_reference(const cdist__core_obj *o)
{
    switch (o->type) {
    case CD_CORE_POINT: return *(const cdist_vec3 *)o->obj;
    case CD_CORE_SEGMENT: {
        const cdist_segment *s = o->obj;
        return v_scale(0.5, v_add(s->p0, s->p1));
    }
    case CD_CORE_LINE: return ((const cdist_line *)o->obj)->origin;
    case CD_CORE_RAY: return ((const cdist_ray *)o->obj)->origin;
    case CD_CORE_CIRCLE:
    case CD_CORE_DISK: return ((const cdist_circle *)o->obj)->center;
    case CD_CORE_ARC: return ((const cdist_arc *)o->obj)->circle.center;
    }
    return v3(0, 0, 0);
}

vec3 cdist__core_tangent(const cdist__core_obj *o, vec3 X, double t, int *interior)
{
    const cdist_circle *c = NULL;
    vec3 d = v3(0, 0, 0);
    int in = 1;
    switch (o->type) {
    case CD_CORE_LINE: d = ((const cdist_line *)o->obj)->direction; break;
    case CD_CORE_RAY:
        d = ((const cdist_ray *)o->obj)->direction;
        in = t > 0.0;
        break;
    case CD_CORE_SEGMENT: {
        const cdist_segment *sg = o->obj;
        d = v_sub(sg->p1, sg->p0);
        in = t > 0.0 && t < 1.0;
        break;
    }
    case CD_CORE_CIRCLE: c = o->obj; break;
    case CD_CORE_ARC: {
        const cdist_arc *a = o->obj;
        c = &a->circle;
        in = t > a->start && t < a->end;
        break;
    }
    default: in = 0; break;
    }
    if (interior) *interior = in;
    if (c) d = v_cross(v_unit_or_zero(c->normal), v_sub(X, c->center));
    return v_unit_or_zero(d);
}

static vec3 core_plane_normal(const cdist__core_obj *o)
{
    if (o->type == CD_CORE_CIRCLE || o->type == CD_CORE_DISK)
        return v_unit_or_zero(((const cdist_circle *)o->obj)->normal);
    if (o->type == CD_CORE_ARC) return v_unit_or_zero(((const cdist_arc *)o->obj)->circle.normal);
    return v3(0, 0, 0);
}

static vec3 core_line_perp(const cdist__core_obj *o, vec3 p)
{
    if (o->type != CD_CORE_SEGMENT && o->type != CD_CORE_LINE && o->type != CD_CORE_RAY) return v3(0, 0, 0);
    vec3 t = cdist__core_tangent(o, p, NAN, NULL);
    if (v_sqr(t) == 0.0) return t;
    vec3 u, v;
    v_basis(t, &u, &v);
    return u;
}

/* The documented normal when the cores touch (CDIST_CONTACT_CORE_TOUCH). */
static vec3 touch_normal(const cdist__core_obj *a, const cdist__core_obj *b, vec3 pa, vec3 pb)
{
    vec3 n = v3(0, 0, 0);
    vec3 ta = cdist__core_tangent(a, pa, NAN, NULL), tb = cdist__core_tangent(b, pb, NAN, NULL);
    if (v_sqr(ta) > 0.0 && v_sqr(tb) > 0.0) {
        vec3 x = v_cross(ta, tb);
        if (v_norm(x) > CD_CONTACT_TANGENT_SIN) n = v_unit_or_zero(x);
    }
    if (v_sqr(n) == 0.0) n = core_plane_normal(a);
    if (v_sqr(n) == 0.0) n = core_plane_normal(b);
    if (v_sqr(n) == 0.0) n = core_line_perp(a, pa);
    if (v_sqr(n) == 0.0) n = core_line_perp(b, pb);
    if (v_sqr(n) == 0.0) n = v3(0, 0, 1);
    double s = v_dot(n, v_sub(core_reference(b), core_reference(a)));
    if (s == 0.0) s = n.x != 0.0 ? n.x : (n.y != 0.0 ? n.y : n.z);
    return s < 0.0 ? v_neg(n) : n;
}

static cdist_status check_radius(cdist_query *q, const cdist__core_obj *o, const char *what)
{
    return o->swept ? cdist__check_radius(q, o->radius, what) : CDIST_OK;
}

/* The contact of a swept query from its core result r (the core query succeeded). FMA clone:
 * its fma() (v_axpy, the touch normal) are instructions there, not calls. */
CD_FMA_CLONES void cdist__contact_of_core(const cdist__core_obj *a, const cdist__core_obj *b, const cdist_result *r,
                                         cdist_contact *c)
{
    c->core_distance = r->distance;
    c->distance = r->distance - (a->radius + b->radius);
    c->num_pairs = r->num_pairs;
    c->equidistant = r->equidistant;
    c->method = r->method;
    c->flags = 0;
    memset(c->reserved, 0, sizeof c->reserved);
    for (int i = r->num_pairs; i < 2; i++) contact_pair_unset(&c->pairs[i]);
    for (int i = 0; i < r->num_pairs; i++) {
        cdist_contact_pair *cp = &c->pairs[i];
        vec3 pa = r->pairs[i].point[0], pb = r->pairs[i].point[1];
        vec3 d = v_sub(pb, pa);
        vec3 n;
        if (cdist__cores_touch(r, i)) {
            n = touch_normal(a, b, pa, pb);
            c->flags |= CDIST_CONTACT_CORE_TOUCH;
        } else {
            n = v_unit_or_zero(d);
        }
        cp->core_point[0] = pa;
        cp->core_point[1] = pb;
        cp->normal = n;
        cp->point[0] = v_axpy(pa, a->radius, n);
        cp->point[1] = v_axpy(pb, -b->radius, n);
        cp->param[0] = r->pairs[i].param[0];
        cp->param[1] = r->pairs[i].param[1];
    }
}

/* The contact of a swept query whose core query answered with status st and result r. */
static cdist_status contact_of_answer(const cdist__core_obj *a, const cdist__core_obj *b, cdist_status st,
                                      const cdist_result *r, cdist_contact *c)
{
    if (st) {
        cdist__contact_set_error(c);
        return st;
    }
    cdist__contact_of_core(a, b, r, c);
    return CDIST_OK;
}

cdist_status cdist__swept_query(cdist_query *q, const cdist__core_obj *a, const cdist__core_obj *b, cdist_contact *c,
                            cdist_result *core)
{
    cdist_result local;
    cdist_result *r = core ? core : &local;
    cdist_status st;
    /* Valid arguments go straight to the core query (which takes the handle's in-use flag
     * itself). Otherwise the failure is reported under the flag (a busy handle is left
     * untouched); afterwards only c is written: every field, in the error state on failure. */
    if (!(c && cdist__contact_ready(a, b))) {
        if (c) cdist__contact_set_error(c);
        if ((st = cdist__enter(q, r))) return st;
        if (!c) st = cdist__fail(q, CDIST_ERR_NULL_ARGUMENT, "contact pointer is NULL");
        else if (!a->obj) st = cdist__fail(q, CDIST_ERR_NULL_ARGUMENT, "first object pointer is NULL");
        else if (!b->obj) st = cdist__fail(q, CDIST_ERR_NULL_ARGUMENT, "second object pointer is NULL");
        else if (!(st = check_radius(q, a, "first object's radius"))) st = check_radius(q, b, "second object's radius");
        if (st) return cdist__leave(q, r, st, CDIST_METHOD_AUTO);
        cdist__leave_setter(q); /* releases the flag only: r is written by the core query */
    }
    return contact_of_answer(a, b, cdist__core_query(q, a, b, r), r, c);
}

cdist_status cdist__contact_of_core_query(cdist_query *q, const cdist__core_obj *a, const cdist__core_obj *b,
                                          cdist_status st, cdist_result *core, cdist_contact *c)
{
    if (!cdist__contact_ready(a, b)) /* the query reports it */
        return cdist__swept_query(q, a, b, c, core);
    return contact_of_answer(a, b, st, core, c);
}

/* ---- public entry points ---- */

size_t cdist_contact_size(void) { return sizeof(cdist_contact); }
int cdist_contact_flag_core_touch(void) { return CDIST_CONTACT_CORE_TOUCH; }

size_t cdist_swept_size(int which)
{
    switch (which) {
    case 0: return sizeof(cdist_sphere);
    case 1: return sizeof(cdist_capsule);
    case 2: return sizeof(cdist_torus);
    case 3: return sizeof(cdist_rounded_disk);
    default: return 0;
    }
}

/* The contact queries, one per contact kind of the registry. */
#define CD_CONTACT_KIND(KIND, number, name, letters, TA, TB, A, B, core, swap, help)                               \
    cdist_status cdist_##name(cdist_query *q, const TA *a, const TB *b, cdist_contact *c)                         \
    {                                                                                                              \
        cdist__core_obj oa = CD_SWEPT_##A(a), ob = CD_SWEPT_##B(b);                                              \
        return cdist__swept_query(q, &oa, &ob, c, NULL);                                                           \
    }
#include "api/kinds.def"
