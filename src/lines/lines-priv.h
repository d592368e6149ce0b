/* SPDX-License-Identifier: MIT */
/* Lines family cores (src/lines): lines, rays and segments to circles and disks. */
#ifndef CDIST_LINES_PRIV_H
#define CDIST_LINES_PRIV_H

#include "circledist.h"
#include "api/api-priv.h"
#include "base/best.h"
#include "base/vec.h"
#include "point/point-priv.h"

/* ---- lines family (src/lines/line_circle.c) ----
 * cdist__linear_circle_ex: points B + t M, t in [tmin, tmax] (infinite ends allowed), M unit, B
 * relative to the centre of c (c->c ignored). Semantics: candidates are every local minimum of the squared distance inside
 * [tmin, tmax] plus the finite ends (point-circle), with param[1] the circle angle. method is
 * POLYNOMIAL or anything else (= ROBUST). b->equidistant is set when the closest point found is
 * on the circle's axis (the line is the axis, or a ray/segment end or clamped point lies on it)
 * and that candidate is then the best in b. cdist__linear_circle_ex also reports the method that
 * answered (ROBUST when the polynomial module failed and the robust path took over). */
cdist_status cdist__linear_circle_ex(cdist_query *q, cdist_method method, vec3 B, vec3 M, double tmin, double tmax,
                                 const cdist__circle *c, cdist__best *b, cdist_method *used);
/* Accuracy: the core is exact for the B it gets, so B should be near the centre. For a caller's
 * origin + t D, t in [tmin, tmax] (D as passed, any length), this returns B = (origin + t0 D) - C
 * for the point of the range nearest C, with origin - C kept exact (TwoSum) and one rounding at
 * the scale of B, and t0 (in units of D). Then call the core with M = D/|D| and the range
 * (tmin - t0)|D| .. (tmax - t0)|D|; a candidate's parameter in units of D is t0 + t/|D|. */
vec3 cdist__line_near_centre(vec3 origin, vec3 D, vec3 C, double tmin, double tmax, double *t0);

/* Scale exponent of a linear query (origin, optional segment end p1, circle c): from
 * max(r, |origin - C|, |p1 - C|), see cdist__scale_exponent. The cores take the origin and the
 * centre scaled as they are (their difference is taken exactly there), so a problem far smaller
 * than its coordinates (A / L beyond ~2^1023, A the largest |coordinate|) would have them
 * overflow to infinity: then the exponent is raised so that 2^-e A is below 2^(CD_LINES_ABS_MAX_EXP + 1).
 * Only where the plain exponent overflows, so every other query is scaled exactly as before. */
static inline int cdist__lines_scale_exponent(vec3 origin, const vec3 *p1, const cdist__circle *c)
{
    double L = cdist__fmax(c->r, v_maxabs(v_sub(origin, c->c)));
    if (p1) L = cdist__fmax(L, v_maxabs(v_sub(*p1, c->c)));
    int e = cdist__scale_exponent(L);
    if (e < CD_LINES_OVERFLOW_EXP) {
        double A = cdist__fmax(v_maxabs(origin), v_maxabs(c->c));
        if (p1) A = cdist__fmax(A, v_maxabs(*p1));
        if (!(A * cdist__pow2(-e) <= DBL_MAX)) e = cdist__scale_exponent(A) - CD_LINES_ABS_MAX_EXP;
    }
    return e;
}

/* The length of the direction Ds = 2^-e D of a scaled query, given len = |D|: len 2^-e, except
 * for a subnormal len, whose few significant bits would make the conversion of the range to arc
 * length inexact (off by 1e-5 for a direction of 1e-319): then |Ds|, from Ds scaled exactly to
 * its largest component (its squares may be subnormal too). */
static inline double cdist__lines_scaled_length(double len, vec3 Ds, double down)
{
    if (len >= 0x1p-1022 || !(v_maxabs(Ds) > 0.0)) return len * down;
    return v_norm_scaled(Ds);
}

/* The core of a line or ray query: origin + t Ds, t in [tmin, tmax] (origin, Ds and c scaled
 * by 2^-e, M the unit direction, len = |Ds|), into r and the method that answered. */
typedef cdist_status (*cdist__linear_core_fn)(cdist_query *q, vec3 origin, vec3 Ds, vec3 M, double len, double tmin,
                                              double tmax, const cdist__circle *c, cdist_result *r,
                                              cdist_method *used);

/* A line or ray query (to a circle, disk 0, or a disk, 1) from its entry to its result: the
 * validation, the scaling by 2^-e (exact; t is unchanged, D being scaled with the origin), the
 * core, the result scaled back. The circle's normal and basis (two divisions and a square root
 * each) are the longest chain before the core: started first. The fast check has no side
 * effects; a circle it does not accept is checked, and reported, after the line. Inlined into
 * each entry (an FMA clone: the inlined basis is a chain of fma() calls), the core with it. */
CD_INLINE cdist_status cdist__linear_query(cdist_query *q, const void *obj, const cdist_vec3 *origin,
                                           const cdist_vec3 *dir, int is_ray, const cdist_circle *c, int disk,
                                           cdist__linear_core_fn core, cdist_result *r)
{
    cdist_status st = cdist__enter(q, r);
    if (st) return st;
    cdist__circle cc;
    vec3 M;
    double len;
    cdist_method used = CDIST_METHOD_ROBUST;
    int fast = cdist__circle_fast_basis(q->unit_tol, c, &cc);
    if (!(st = cdist__check_line_ray(q, obj, origin, dir, is_ray, &M, &len)) &&
        (fast || !(st = cdist__check_circle(q, c, disk ? "disk" : "circle", &cc)))) {
        int e = cdist__lines_scale_exponent(*origin, NULL, &cc);
        double down = cdist__pow2(-e);
        cdist__circle_scale(&cc, down);
        vec3 Ds = v_scale(down, *dir);
        st = core(q, v_scale(down, *origin), Ds, M, cdist__lines_scaled_length(len, Ds, down), is_ray ? 0.0 : -INFINITY,
                  INFINITY, &cc, r, &used);
        if (st == CDIST_OK) cdist__result_unscale(r, cdist__pow2(e));
    }
    return cdist__leave(q, r, st, used);
}

/* The core of a segment query: the segment p0 + t Ds, t in [0, 1] (p0, p1 = p0 + Ds and c
 * scaled by 2^-e, M = Ds / len), into r and the method that answered. */
typedef cdist_status (*cdist__segment_core_fn)(cdist_query *q, vec3 p0, vec3 p1, vec3 Ds, vec3 M, double len,
                                               const cdist__circle *c, cdist_result *r, cdist_method *used);

/* A segment query (segment-circle, disk 0; segment-disk, 1) from its entry to its result: the
 * validation, a segment that is a point (point-circle or point-disk with s = 0), the scaling
 * (before D is normalised, so that 2^k times the input gives exactly 2^k times the answer; the
 * normalisation of a tiny D takes another path), the core, and end points that are exactly the
 * caller's. Inlined into each entry, the core with it. */
CD_INLINE cdist_status cdist__segment_query(cdist_query *q, const cdist_segment *s, const cdist_circle *c, int disk,
                                            cdist__segment_core_fn core, cdist_result *r)
{
    cdist_status st = cdist__enter(q, r);
    if (st) return st;
    cdist__circle cc;
    cdist_method used = cdist__family_method(q, disk ? CD_FAM_SEGMENT_DISK : CD_FAM_SEGMENT_CIRCLE);
    if ((st = cdist__check_segment(q, s)) || (st = cdist__check_circle(q, c, disk ? "disk" : "circle", &cc)))
        return cdist__leave(q, r, st, used);
    vec3 D = v_sub(s->p1, s->p0);
    if (D.x == 0.0 && D.y == 0.0 && D.z == 0.0) {
        cdist__point_result(s->p0, &cc, disk, r);
        r->pairs[0].param[0] = 0.0;
        return cdist__leave(q, r, CDIST_OK, used);
    }
    int e = cdist__lines_scale_exponent(s->p0, &s->p1, &cc);
    double down = cdist__pow2(-e);
    cdist__circle_scale(&cc, down);
    vec3 Ds = v_scale(down, D), M;
    double len;
    if (!(st = cdist__check_direction(q, &Ds, "segment direction p1 - p0", 0, &M, &len)) &&
        !(st = core(q, v_scale(down, s->p0), v_scale(down, s->p1), Ds, M, len, &cc, r, &used))) {
        cdist__result_unscale(r, cdist__pow2(e));
        for (int i = 0; i < r->num_pairs; i++) {
            if (r->pairs[i].param[0] == 0.0) r->pairs[i].point[0] = s->p0;
            if (r->pairs[i].param[0] == 1.0) r->pairs[i].point[0] = s->p1;
        }
    }
    return cdist__leave(q, r, st, used);
}

#endif
