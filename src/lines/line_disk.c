/* SPDX-License-Identifier: MIT */
/* Lines, rays and segments to disks (point-curve-circle-to-disk §2-§4, line-circle-disk §2;
 * derivations in docs/disk.md). The lemma the split rests on (the distance to a disk is |h|
 * over the disk and the rim-circle distance elsewhere) is stated at the top of src/circles/circle_disk.c and in docs/disk.md. */
#include <math.h>

#include "base/point_circle.h"
#include "internal.h"

/* ------------------------------------------------------------------------------------------ */
/* Lines, rays and segments to a disk                                                           */

/* B + t M, t in [tmin, tmax], M unit, B relative to the disk centre (d->c ignored), split where
 * the projection enters and leaves the disk (docs/disk.md, "Lines, rays, segments to a disk");
 * the split points are offered too (cheap, and they protect against a split a few ulps off). */
CD_INLINE void lin_offer(vec3 B, vec3 M, double t, const cdist__circle *d, cdist__best *b)
{
    vec3 p = v_axpy(B, t, M);
    cdist__point_pair k = cdist__point_disk_pair(p, d); /* offered without its on-axis flag */
    cdist__best_offer(b, k.d2, p, k.k, t, k.angle);
}

/* An outer piece [t0, t1] of the line (beyond the disk's rim): line-circle's candidates, merged
 * into loc; *eq_d2 the smallest equidistant distance. */
CD_INLINE cdist_status outer_piece(cdist_query *q, cdist_method method, vec3 B, vec3 M, double t0, double t1,
                                   const cdist__circle *d, cdist__best *loc, double *eq_d2, cdist_method *used)
{
    cdist__best t;
    cdist_method u1;
    cdist__best_init(&t, loc->scale);
    cdist_status st = cdist__linear_circle_ex(q, method, B, M, t0, t1, d, &t, &u1);
    if (st) return st;
    if (u1 == CDIST_METHOD_ROBUST) *used = u1;
    double m2 = cdist__best_merge(loc, &t, v3(0, 0, 0), 0);
    if (cdist__best_is_equidistant(&t) && m2 < *eq_d2) *eq_d2 = m2;
    return CDIST_OK;
}

CD_FMA_CLONES static cdist_status linear_disk(cdist_query *q, cdist_method method, vec3 B, vec3 M, double tmin, double tmax,
                                const cdist__circle *d, cdist__best *b, cdist_method *used)
{
    *used = method == CDIST_METHOD_POLYNOMIAL ? method : CDIST_METHOD_ROBUST;
    cdist_method u1 = *used;
    double R = d->r;
    double mn = v_dot(d->n, M), hB = v_dot(d->n, B);
    /* In-plane parts of B and M. */
    vec3 Mp = cdist__pc_inplane(v_cross(d->n, M), d->n), Bp = cdist__pc_inplane(v_cross(d->n, B), d->n);
    double mp2 = v_sqr(Mp);
    double eq_d2 = INFINITY;
    /* Candidates are collected in loc, then merged into b; into b itself when b is still
     * empty (the usual case), which is the same result without the copy. */
    cdist__best loc_store, *loc = b;
    int direct = b->n == 0 && !b->equidistant;
    if (!direct) {
        loc = &loc_store;
        cdist__best_init(loc, b->scale);
    }
    double t1 = INFINITY, t2 = -INFINITY; /* the projection is over the disk for t in [t1, t2] */
    if (mp2 > 0.0) {
        double mpn = sqrt(mp2);
        double tc = -v_dot(Bp, Mp) / mp2;
        /* Distance of the projected line from the centre: |Mp x Bp| / |Mp| (no cancellation). */
        double dist = v_norm(v_cross(Mp, Bp)) / mpn;
        if (dist <= R) {
            double half = sqrt((R - dist) * (R + dist)) / mpn;
            t1 = tc - half;
            t2 = tc + half;
        }
    } else if (v_norm(Bp) <= R) {
        t1 = -INFINITY;
        t2 = INFINITY;
    }
    double lo = cdist__fmax(tmin, t1), hi = cdist__fmin(tmax, t2);
    cdist_status st;
    if (lo <= hi) {
        /* The piece over the disk. */
        if (fabs(mn) <= CD_LD_PARALLEL_ULPS * DBL_EPSILON) {
            /* Parallel to the plane (within rounding): |h| constant over a stretch. */
            double tt = isfinite(lo) ? lo : isfinite(hi) ? hi : cdist__fmin(cdist__fmax(0.0, lo), hi);
            if (isfinite(lo) && isfinite(hi)) tt = 0.5 * (lo + hi);
            lin_offer(B, M, tt, d, loc);
            if (hi > lo && R > 0.0) eq_d2 = loc->n ? loc->c[0].d2 : INFINITY;
        } else {
            double tz = -hB / mn;
            if (tz >= lo && tz <= hi) {
                /* Crossing point: polish once on h, clamp into the piece. */
                double hz = v_dot(d->n, v_axpy(B, tz, M));
                tz = cdist__fmin(cdist__fmax(tz - hz / mn, lo), hi);
                lin_offer(B, M, tz, d, loc);
            }
            if (isfinite(lo)) lin_offer(B, M, lo, d, loc);
            if (isfinite(hi)) lin_offer(B, M, hi, d, loc);
        }
        /* The outer pieces. When both exist and the ends lo, hi were offered above, one
         * line-circle run over the whole range gives their minima at half the cost: its local
         * minima outside (lo, hi) are those of the pieces, and a piece minimum clamped to lo or
         * hi is the end already offered. */
        int both = tmin < lo && hi < tmax && !(fabs(mn) <= CD_LD_PARALLEL_ULPS * DBL_EPSILON);
        if (both) {
            cdist__best all;
            cdist__best_init(&all, b->scale);
            if ((st = cdist__linear_circle_ex(q, method, B, M, tmin, tmax, d, &all, &u1))) return st;
            if (u1 == CDIST_METHOD_ROBUST) *used = u1;
            /* straight into loc: `all` is sorted by d2, so the first kept candidate is the
             * pieces' best (what merging a collector of them would report) */
            int first = 1;
            for (int i = 0; i < all.n; i++) {
                const cdist__cand *k = &all.c[i];
                if (!(k->param[0] <= lo || k->param[0] >= hi)) continue;
                if (first && k->equidistant && k->d2 < eq_d2) eq_d2 = k->d2;
                first = 0;
                cdist__best_offer_flag(loc, k->equidistant, k->d2, k->p[0], k->p[1], k->param[0], k->param[1]);
            }
        }
        /* else each outer piece on its own */
        if (!both && tmin < lo && (st = outer_piece(q, method, B, M, tmin, lo, d, loc, &eq_d2, used))) return st;
        if (!both && hi < tmax && (st = outer_piece(q, method, B, M, hi, tmax, d, loc, &eq_d2, used))) return st;
    } else {
        /* loc is empty here: the core offers into it directly */
        if ((st = cdist__linear_circle_ex(q, method, B, M, tmin, tmax, d, loc, &u1))) return st;
        if (u1 == CDIST_METHOD_ROBUST) *used = u1;
        if (cdist__best_is_equidistant(loc)) eq_d2 = loc->c[0].d2;
    }
    if (isfinite(tmin)) lin_offer(B, M, tmin, d, loc);
    if (isfinite(tmax)) lin_offer(B, M, tmax, d, loc);
    cdist__best_settle_equidistant(loc, eq_d2);
    cdist__best_convex_contact(loc);
    if (!direct) {
        double d2 = cdist__best_merge(b, loc, v3(0, 0, 0), 0);
        if (cdist__best_is_equidistant(loc)) cdist__best_settle_equidistant(b, d2);
    }
    return CDIST_OK;
}

/* The point of the segment p0 + s (p1 - p0), s in [0, 1], nearest C, relative to C, from the
 * exact differences p0 - C and p1 - p0 (a rounded p1 - p0 would tilt the segment: 1e-8 off at
 * 1e8 from its start); one rounding at the scale of the result. */
CD_FMA_CLONES static vec3 segment_near_centre(vec3 p0, vec3 p1, vec3 C, double *s0)
{
    double a[3], al[3], dd[3], dl[3];
    const double P0[3] = {p0.x, p0.y, p0.z}, P1[3] = {p1.x, p1.y, p1.z}, CC[3] = {C.x, C.y, C.z};
    for (int i = 0; i < 3; i++) {
        a[i] = cdist__two_diff(P0[i], CC[i], &al[i]);
        dd[i] = cdist__two_diff(P1[i], P0[i], &dl[i]);
    }
    double m = cdist__fmax(fabs(dd[0]), cdist__fmax(fabs(dd[1]), fabs(dd[2])));
    double num = 0.0, den = 0.0;
    for (int i = 0; i < 3; i++) {
        num += (a[i] / m) * (dd[i] / m);
        den += (dd[i] / m) * (dd[i] / m);
    }
    double t = (den > 0.0) ? -num / den : 0.0;
    t = cdist__fmin(cdist__fmax(t, 0.0), 1.0);
    *s0 = t;
    double B[3];
    for (int i = 0; i < 3; i++) B[i] = fma(t, dd[i], a[i]) + fma(t, dl[i], al[i]);
    return v3(B[0], B[1], B[2]);
}

/* Shared driver: the linear object is origin + t D for t in [tmin, tmax], D exactly as the
 * caller gave it (|D| = len, unit direction M = D / len). The parameter reported is t.
 * p1 (segments only): the end point, so that origin - C and p1 - origin are taken exactly.
 * Writes r (without its method) and the method that answered. */
CD_FMA_CLONES static cdist_status linear_disk_query(cdist_query *q, vec3 origin, vec3 D, double len, vec3 M, double tmin,
                                      double tmax, const vec3 *p1, const cdist__circle *dk, cdist_result *r,
                                      cdist_method *used)
{
    cdist__circle d = *dk;
    vec3 offset = d.c;
    d.c = v3(0, 0, 0);
    /* Move the origin to the point of the range nearest the centre, with origin - C kept exact
     * and the line as given (not its rounded unit direction, which would tilt it by ~1e-16 rad,
     * i.e. move it by 1e-8 at a distance of 1e8): see cdist__line_near_centre in line_circle.c. */
    double t0;
    vec3 B = p1 ? segment_near_centre(origin, *p1, offset, &t0) : cdist__line_near_centre(origin, D, offset, tmin, tmax, &t0);
    double lo = (tmin == t0) ? 0.0 : (tmin - t0) * len, hi = (tmax == t0) ? 0.0 : (tmax - t0) * len;
    double L = cdist__fmax(d.r, v_norm(B));
    cdist__best best;
    cdist__best_init(&best, L);
    cdist_status st = linear_disk(q, cdist__family_method(q, CD_FAM_LINE_DISK), B, M, lo, hi, &d, &best, used);
    if (st) return st;
    if (best.n == 0) return cdist__fail(q, CDIST_ERR_INTERNAL, "line-disk found no candidate");
    for (int i = 0; i < best.n; i++) best.c[i].param[0] = cdist__fmin(cdist__fmax(t0 + best.c[i].param[0] / len, tmin), tmax);
    cdist__best_to_result(&best, offset, 0, r);
    cdist__result_finish(r, r->num_pairs);
    return CDIST_OK;
}

/* The line's or ray's core, the query scaled (cdist__linear_query). */
CD_INLINE cdist_status linear_core(cdist_query *q, vec3 origin, vec3 Ds, vec3 M, double len, double tmin, double tmax,
                                const cdist__circle *dk, cdist_result *r, cdist_method *used)
{
    return linear_disk_query(q, origin, Ds, len, M, tmin, tmax, NULL, dk, r, used);
}

/* FMA clone: as line_circle.c's linear_public (the inlined basis is a chain of fma() calls). */
CD_FMA_CLONES static cdist_status line_ray_disk(cdist_query *q, const void *obj, const cdist_vec3 *origin,
                                                const cdist_vec3 *dir, int is_ray, const cdist_circle *d,
                                                cdist_result *r)
{
    return cdist__linear_query(q, obj, origin, dir, is_ray, d, 1, linear_core, r);
}

cdist_status cdist_line_disk(cdist_query *q, const cdist_line *l, const cdist_circle *d, cdist_result *r)
{
    return line_ray_disk(q, l, l ? &l->origin : NULL, l ? &l->direction : NULL, 0, d, r);
}

cdist_status cdist_ray_disk(cdist_query *q, const cdist_ray *l, const cdist_circle *d, cdist_result *r)
{
    return line_ray_disk(q, l, l ? &l->origin : NULL, l ? &l->direction : NULL, 1, d, r);
}

/* The segment's core: the line's, on t in [0, 1], with its end point p1. */
CD_INLINE cdist_status segment_core(cdist_query *q, vec3 p0, vec3 p1, vec3 Ds, vec3 M, double len,
                                 const cdist__circle *dk, cdist_result *r, cdist_method *used)
{
    return linear_disk_query(q, p0, Ds, len, M, 0.0, 1.0, &p1, dk, r, used);
}

cdist_status cdist_segment_disk(cdist_query *q, const cdist_segment *s, const cdist_circle *d, cdist_result *r)
{
    return cdist__segment_query(q, s, d, 1, segment_core, r);
}
