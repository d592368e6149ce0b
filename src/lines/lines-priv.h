/* SPDX-License-Identifier: MIT */
/* Lines family cores (src/lines): lines, rays and segments to circles and disks. */
#ifndef CDIST_LINES_PRIV_H
#define CDIST_LINES_PRIV_H

#include "circledist.h"
#include "api/api-priv.h"
#include "base/best.h"
#include "base/vec.h"

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

/* Line-disk core: cdist__linear_circle_ex semantics against a disk (src/lines/line_disk.c). */
cdist_status cdist__linear_disk_ex(cdist_query *q, cdist_method method, vec3 B, vec3 M, double tmin, double tmax,
                               const cdist__circle *d, cdist__best *b, cdist_method *used);

/* Scale exponent of a linear query (origin, optional segment end p1, circle c): from
 * max(r, |origin - C|, |p1 - C|), see cdist__scale_exponent. */
static inline int cdist__lines_scale_exponent(vec3 origin, const vec3 *p1, const cdist__circle *c)
{
    double L = cdist__fmax(c->r, v_maxabs(v_sub(origin, c->c)));
    if (p1) L = cdist__fmax(L, v_maxabs(v_sub(*p1, c->c)));
    return cdist__scale_exponent(L);
}

/* The length of the direction Ds = 2^-e D of a scaled query, given len = |D|: len 2^-e, except
 * for a subnormal len, whose few significant bits would make the conversion of the range to arc
 * length inexact (off by 1e-5 for a direction of 1e-319): then |Ds|, from Ds scaled exactly to
 * its largest component (its squares may be subnormal too). */
static inline double cdist__lines_scaled_length(double len, vec3 Ds, double down)
{
    double m = v_maxabs(Ds);
    if (len >= 0x1p-1022 || !(m > 0.0)) return len * down;
    int k = cdist__scale_exponent(m);
    return v_norm(v_scale(cdist__pow2(-k), Ds)) * cdist__pow2(k);
}

#endif
