/* SPDX-License-Identifier: MIT */
/* Gradients of the distance with respect to the objects' parameters, from the closest pair
 * (envelope theorem; the rules are documented in circledist.h). */
#include <math.h>
#include <string.h>

#include "swept-priv.h"
#include "base/point_circle.h"

/* Component of g orthogonal to the unit vector n. */
static vec3 perp(vec3 g, vec3 n) { return v_axpy(g, -v_dot(g, n), n); }

void cdist__grad_set_error(cdist_grad *g)
{
    if (!g) return;
    memset(g, 0, sizeof *g);
    for (int k = 0; k < 2; k++) {
        cdist_grad_object *o = &g->obj[k];
        vec3 nanv = v3(NAN, NAN, NAN);
        o->d_center = o->d_normal = o->d_origin = o->d_direction = o->d_p0 = o->d_p1 = o->d_zero_direction = nanv;
        o->d_radius = o->d_radius_swept = o->d_start = o->d_end = NAN;
    }
}

/* X (on disk c, unit normal N) is clearly inside the rim (tolerances.h). */
static int disk_interior(const cdist_circle *c, vec3 N, vec3 X)
{
    double rho = cdist__point_circle(N, v_sub(X, c->center), c->radius).rho;
    double slack = CD_GRAD_RIM_REL * c->radius + CD_GRAD_RIM_ULPS * DBL_EPSILON * (v_maxabs(X) + v_maxabs(c->center));
    return c->radius - rho > slack;
}

/* Circle or disk at point X (on it) with outward gradient vector w (dD = w . dX). */
static void circle_like(const cdist_circle *c, vec3 X, vec3 w, int disk, cdist_grad_object *o)
{
    vec3 N = v_unit_or_zero(c->normal);
    vec3 rel = v_sub(X, c->center);
    o->d_center = w;
    if (c->radius == 0.0) {
        /* From the right: the circle grows towards -w's in-plane part. */
        o->d_radius = -v_norm(perp(w, N));
        return;
    }
    cdist__pc_parts pc = cdist__point_circle(N, rel, c->radius);
    double rho = pc.rho;
    double s = disk ? fmin(rho / c->radius, 1.0) : 1.0;
    if (disk && disk_interior(c, N, X)) {
        /* interior point: w is along N, the radius does not move the point's neighbourhood */
        o->d_radius = 0.0;
        o->d_normal = v_scale(-v_dot(w, N), rel);
        o->d_normal = perp(o->d_normal, N);
        return;
    }
    vec3 relp = cdist__pc_inplane(pc.np, N);
    vec3 e = v_maxabs(relp) > 0.0 ? cdist__pc_along(relp, 1.0) : v3(0, 0, 0);
    o->d_radius = s * v_dot(w, e);
    /* dX = -r s (e . dN) N  =>  d_normal = -r s (w . N) e (orthogonal to N). */
    o->d_normal = v_scale(-c->radius * s * v_dot(w, N), e);
}

/* Arc: X = C + r (cos a U + sin a V), U = unit(z - (z.N)N), V = N x U; a held fixed. */
static void arc_grad(const cdist_arc *arc, vec3 X, double a, vec3 w, cdist_grad_object *o)
{
    const cdist_circle *c = &arc->circle;
    vec3 N = v_unit_or_zero(c->normal);
    vec3 z = arc->zero_direction;
    vec3 Pz = perp(z, N);
    double pz = v_norm(Pz);
    vec3 U = v_scale(1.0 / pz, Pz), V = v_cross(N, U);
    double r = c->radius;
    o->d_center = w;
    if (r == 0.0) {
        /* Every angle is the centre (the query's angle is NaN): only the centre moves X, and
         * the radius is differentiated from the right (r -> 0+), where X leaves along the arc
         * direction that decreases the distance most: min over the span of w . (cos a U + sin a V). */
        double wu = v_dot(w, U), wv = v_dot(w, V);
        double best = fmin(wu * cos(arc->start) + wv * sin(arc->start), wu * cos(arc->end) + wv * sin(arc->end));
        double am = atan2(-wv, -wu); /* direction of -w in the plane */
        am += 2.0 * M_PI * ceil((arc->start - am) / (2.0 * M_PI));
        if (am <= arc->end) best = fmin(best, -hypot(wu, wv));
        o->d_radius = best;
        o->d_normal = o->d_zero_direction = v3(0, 0, 0);
        o->d_start = o->d_end = 0.0;
        return;
    }
    double ca = cos(a), sa = sin(a);
    o->d_radius = v_dot(w, v_add(v_scale(ca, U), v_scale(sa, V)));
    (void)X;
    /* w . dX through dU and dN: the derivation is in docs/swept.md, "An arc's gradient". */
    vec3 h = v_scale(r, v_add(v_scale(ca, w), v_scale(sa, v_cross(w, N))));
    vec3 k = v_scale(1.0 / pz, perp(h, U));
    double kN = v_dot(k, N), zN = v_dot(z, N);
    o->d_zero_direction = perp(k, N);
    vec3 gN = v_add(v_scale(r * sa, v_cross(U, w)), v_add(v_scale(-zN, k), v_scale(-kN, z)));
    o->d_normal = perp(gN, N);
    /* End angles: active only when the closest point is that end. */
    double dA = r * (v_dot(w, v_sub(v_scale(ca, V), v_scale(sa, U))));
    o->d_start = a == arc->start ? dA : 0.0;
    o->d_end = a == arc->end && a != arc->start ? dA : 0.0;
}

/* Gradient of one object whose closest point is X with parameter t, dD = w . dX. */
static void object_grad(const cdist__core_obj *ob, vec3 X, double t, vec3 w, cdist_grad_object *o)
{
    switch (ob->type) {
    case CD_CORE_POINT: o->d_center = w; break;
    case CD_CORE_LINE:
    case CD_CORE_RAY: {
        vec3 dir = ob->type == CD_CORE_LINE ? ((const cdist_line *)ob->obj)->direction
                                            : ((const cdist_ray *)ob->obj)->direction;
        vec3 d = v_unit_or_zero(dir);
        o->d_origin = w;
        o->d_direction = v_scale(t, perp(w, d));
        break;
    }
    case CD_CORE_SEGMENT: {
        o->d_p0 = v_scale(1.0 - t, w);
        o->d_p1 = v_scale(t, w);
        break;
    }
    case CD_CORE_CIRCLE: circle_like(ob->obj, X, w, 0, o); break;
    case CD_CORE_DISK: circle_like(ob->obj, X, w, 1, o); break;
    case CD_CORE_ARC: arc_grad(ob->obj, X, t, w, o); break;
    }
    if (ob->swept) o->d_radius_swept = -1.0;
}

/* Two disks (unit normals N0, N1) in transversal planes, both containing X: is there a point
 * of their intersection clearly inside both rims? Their intersection is a segment on the
 * planes' common line (the overlap of the two chords); a closest pair reported there can be its
 * end (on one rim) while its middle is inside both. */
static int disks_cross_inside(const cdist_circle *d0, vec3 N0, const cdist_circle *d1, vec3 N1, vec3 X)
{
    vec3 u = v_unit_or_zero(v_cross(N0, N1));
    const cdist_circle *d[2] = {d0, d1};
    vec3 N[2] = {N0, N1};
    double lo = -INFINITY, hi = INFINITY;
    for (int k = 0; k < 2; k++) {
        /* X + t u is in disk k for t in the chord [m - h, m + h] */
        vec3 p = cdist__pc_inplane(cdist__point_circle(N[k], v_sub(X, d[k]->center), d[k]->radius).np, N[k]);
        double m = -v_dot(p, u), h2 = d[k]->radius * d[k]->radius - (v_sqr(p) - m * m);
        if (!(h2 > 0.0)) return 0;
        lo = fmax(lo, m - sqrt(h2));
        hi = fmin(hi, m + sqrt(h2));
    }
    if (!(hi > lo)) return 0;
    vec3 M = v_axpy(X, 0.5 * (lo + hi), u);
    return disk_interior(d0, N0, M) && disk_interior(d1, N1, M);
}

/* At zero distance: is the distance 0 on a whole neighbourhood of the inputs? Yes when one
 * object is a disk met at a point clearly inside its rim, and the other is a curve crossing
 * the disk's plane transversally there, away from its ends, or a second disk in a transversal
 * plane whose intersection with the first reaches inside both rims. Any closest pair may show
 * it: one stable crossing keeps the distance 0 whatever the other pairs do. */
static int zero_on_neighbourhood(const cdist__core_obj *a, const cdist__core_obj *b, const cdist_result *r)
{
    const cdist__core_obj *ob[2] = {a, b};
    for (int i = 0; i < r->num_pairs; i++)
        for (int k = 0; k < 2; k++) {
            if (ob[k]->type != CD_CORE_DISK) continue;
            const cdist_circle *dk = ob[k]->obj;
            vec3 N = v_unit_or_zero(dk->normal);
            const cdist__core_obj *o = ob[1 - k];
            vec3 X = r->pairs[i].point[1 - k];
            if (o->type == CD_CORE_DISK) {
                const cdist_circle *d2 = o->obj;
                vec3 N2 = v_unit_or_zero(d2->normal);
                if (v_norm(v_cross(N, N2)) > CD_GRAD_TRANSVERSAL_SIN && disks_cross_inside(dk, N, d2, N2, X)) return 1;
                continue;
            }
            if (!disk_interior(dk, N, r->pairs[i].point[k])) continue;
            int interior;
            vec3 t = cdist__core_tangent(o, X, r->pairs[i].param[1 - k], &interior);
            if (interior && fabs(v_dot(t, N)) > CD_GRAD_TRANSVERSAL_SIN) return 1;
        }
    return 0;
}

/* The one decision of the flag CDIST_GRAD_NOT_DIFFERENTIABLE (the rules of circledist.h): at
 * zero distance the distance is differentiable exactly where it stays 0 nearby, whatever the
 * number of pairs or the equidistant flag (a stable crossing is both); elsewhere it is not
 * differentiable with two closest pairs, an equidistant set, an arc of radius 0 (a
 * derivative from the right), or a segment of length 0: moving one end point along w leaves
 * the other where the closest point was (derivative 0), against w it moves that point (-1). */
static int not_differentiable(const cdist__core_obj *a, const cdist__core_obj *b, const cdist_result *r)
{
    if (cdist__cores_touch(r, 0)) return !zero_on_neighbourhood(a, b, r);
    if (r->num_pairs == 2 || r->equidistant) return 1;
    const cdist__core_obj *ob[2] = {a, b};
    for (int k = 0; k < 2; k++) {
        if (ob[k]->type == CD_CORE_ARC && ((const cdist_arc *)ob[k]->obj)->circle.radius == 0.0) return 1;
        if (ob[k]->type == CD_CORE_SEGMENT) {
            const cdist_segment *s = ob[k]->obj;
            if (s->p0.x == s->p1.x && s->p0.y == s->p1.y && s->p0.z == s->p1.z) return 1;
        }
    }
    return 0;
}

/* FMA clone: its fma() are instructions there, not calls. */
CD_FMA_CLONES void cdist__grad_fill(const cdist__core_obj *a, const cdist__core_obj *b, const cdist_result *r, cdist_grad *g)
{
    memset(g, 0, sizeof *g);
    if (a->swept) g->obj[0].d_radius_swept = -1.0;
    if (b->swept) g->obj[1].d_radius_swept = -1.0;
    if (not_differentiable(a, b, r)) g->flags |= CDIST_GRAD_NOT_DIFFERENTIABLE;
    /* At zero distance the gradient is 0 (in the Clarke subdifferential; the true, two-sided
     * derivative where the distance stays 0 nearby). */
    if (cdist__cores_touch(r, 0)) return;
    vec3 P = r->pairs[0].point[0], Q = r->pairs[0].point[1];
    vec3 w = v_unit_or_zero(v_sub(P, Q));
    /* At a disk's interior point w is exactly along the disk's normal (first-order optimality);
     * P - Q loses the direction's accuracy when the distance is tiny against the coordinates,
     * so take it from the structure. */
    const cdist__core_obj *ob[2] = {a, b};
    vec3 X[2] = {P, Q};
    for (int k = 0; k < 2; k++) {
        if (ob[k]->type != CD_CORE_DISK) continue;
        const cdist_circle *c = ob[k]->obj;
        vec3 N = v_unit_or_zero(c->normal);
        if (disk_interior(c, N, X[k])) w = v_dot(w, N) >= 0.0 ? N : v_neg(N);
    }
    object_grad(a, P, r->pairs[0].param[0], w, &g->obj[0]);
    object_grad(b, Q, r->pairs[0].param[1], v_neg(w), &g->obj[1]);
}

size_t cdist_grad_size(void) { return sizeof(cdist_grad); }
int cdist_grad_flag_not_differentiable(void) { return CDIST_GRAD_NOT_DIFFERENTIABLE; }

/* A NULL output pointer, found before any query runs: reported on the handle under its in-use
 * flag (a busy handle is left untouched); r (may be NULL) gets the error state. */
static cdist_status null_output(cdist_query *q, cdist_result *r, const char *what)
{
    cdist_result scratch;
    if (!r) r = &scratch;
    cdist_status st = cdist__enter(q, r);
    if (st) return st;
    st = cdist__fail(q, CDIST_ERR_NULL_ARGUMENT, "%s pointer is NULL", what);
    return cdist__leave(q, r, st, CDIST_METHOD_AUTO);
}

static cdist_status grad_query(cdist_query *q, cdist__core_obj a, cdist__core_obj b, cdist_result *r, cdist_grad *g)
{
    cdist__grad_set_error(g);
    if (!r) return null_output(q, NULL, "result");
    if (!g) return null_output(q, r, "gradient");
    cdist_status st = cdist__core_query(q, &a, &b, r);
    if (st) return st;
    cdist__grad_fill(&a, &b, r, g);
    return CDIST_OK;
}

#define GRAD_QUERY(name, TA, TB, ka, kb)                                                                           \
    cdist_status name(cdist_query *q, const TA *a, const TB *b, cdist_result *r, cdist_grad *g)                    \
    {                                                                                                              \
        cdist__core_obj oa = {ka, a, 0.0, 0}, ob = {kb, b, 0.0, 0};                                                    \
        return grad_query(q, oa, ob, r, g);                                                                        \
    }

GRAD_QUERY(cdist_point_circle_grad, cdist_vec3, cdist_circle, CD_CORE_POINT, CD_CORE_CIRCLE)
GRAD_QUERY(cdist_point_disk_grad, cdist_vec3, cdist_circle, CD_CORE_POINT, CD_CORE_DISK)
GRAD_QUERY(cdist_line_circle_grad, cdist_line, cdist_circle, CD_CORE_LINE, CD_CORE_CIRCLE)
GRAD_QUERY(cdist_ray_circle_grad, cdist_ray, cdist_circle, CD_CORE_RAY, CD_CORE_CIRCLE)
GRAD_QUERY(cdist_segment_circle_grad, cdist_segment, cdist_circle, CD_CORE_SEGMENT, CD_CORE_CIRCLE)
GRAD_QUERY(cdist_circle_circle_grad, cdist_circle, cdist_circle, CD_CORE_CIRCLE, CD_CORE_CIRCLE)
GRAD_QUERY(cdist_line_disk_grad, cdist_line, cdist_circle, CD_CORE_LINE, CD_CORE_DISK)
GRAD_QUERY(cdist_ray_disk_grad, cdist_ray, cdist_circle, CD_CORE_RAY, CD_CORE_DISK)
GRAD_QUERY(cdist_segment_disk_grad, cdist_segment, cdist_circle, CD_CORE_SEGMENT, CD_CORE_DISK)
GRAD_QUERY(cdist_circle_disk_grad, cdist_circle, cdist_circle, CD_CORE_CIRCLE, CD_CORE_DISK)
GRAD_QUERY(cdist_disk_disk_grad, cdist_circle, cdist_circle, CD_CORE_DISK, CD_CORE_DISK)
GRAD_QUERY(cdist_arc_circle_grad, cdist_arc, cdist_circle, CD_CORE_ARC, CD_CORE_CIRCLE)
GRAD_QUERY(cdist_arc_arc_grad, cdist_arc, cdist_arc, CD_CORE_ARC, CD_CORE_ARC)
GRAD_QUERY(cdist_segment_arc_grad, cdist_segment, cdist_arc, CD_CORE_SEGMENT, CD_CORE_ARC)
GRAD_QUERY(cdist_arc_disk_grad, cdist_arc, cdist_circle, CD_CORE_ARC, CD_CORE_DISK)

/* ---- swept objects ---- */

static cdist_status swept_grad_query(cdist_query *q, cdist__core_obj a, cdist__core_obj b, cdist_contact *c, cdist_grad *g)
{
    cdist__grad_set_error(g);
    if (!g) {
        if (c) cdist__contact_set_error(c);
        return null_output(q, NULL, c ? "gradient" : "contact");
    }
    cdist_result core;
    cdist_status st = cdist__swept_query(q, &a, &b, c, &core);
    if (st) return st;
    cdist__grad_fill(&a, &b, &core, g);
    return CDIST_OK;
}

/* The contact queries' gradients, one per contact kind of the registry. */
#define CD_CONTACT_KIND(KIND, number, name, letters, TA, TB, A, B, core, swap, help)                               \
    cdist_status cdist_##name##_grad(cdist_query *q, const TA *a, const TB *b, cdist_contact *c, cdist_grad *g)    \
    {                                                                                                              \
        return swept_grad_query(q, CD_SWEPT_##A(a), CD_SWEPT_##B(b), c, g);                                        \
    }
#include "api/kinds.def"
