/* SPDX-License-Identifier: MIT */
/* Small internal 3D vector and frame module. Header-only: every function is static inline. */
#ifndef CDIST_VEC_H
#define CDIST_VEC_H

#include <math.h>

#include "circledist.h"
#include "base/numeric.h"

typedef cdist_vec3 vec3;

CD_INLINE vec3 v3(double x, double y, double z) { vec3 r = {x, y, z}; return r; }
CD_INLINE vec3 v_add(vec3 a, vec3 b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
CD_INLINE vec3 v_sub(vec3 a, vec3 b) { return v3(a.x - b.x, a.y - b.y, a.z - b.z); }
CD_INLINE vec3 v_scale(double s, vec3 a) { return v3(s * a.x, s * a.y, s * a.z); }
CD_INLINE vec3 v_neg(vec3 a) { return v3(-a.x, -a.y, -a.z); }
/* a + s b */
CD_INLINE vec3 v_axpy(vec3 a, double s, vec3 b) { return v3(fma(s, b.x, a.x), fma(s, b.y, a.y), fma(s, b.z, a.z)); }
CD_INLINE double v_dot(vec3 a, vec3 b) { return fma(a.x, b.x, fma(a.y, b.y, a.z * b.z)); }
CD_INLINE vec3 v_cross(vec3 a, vec3 b)
{
    return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
CD_INLINE double v_sqr(vec3 a) { return v_dot(a, a); }
CD_INLINE double v_norm(vec3 a) { return sqrt(v_sqr(a)); }
CD_INLINE double v_dist(vec3 a, vec3 b) { return v_norm(v_sub(a, b)); }
CD_INLINE double v_maxabs(vec3 a)
{
    double m = fabs(a.x);
    if (fabs(a.y) > m) m = fabs(a.y);
    if (fabs(a.z) > m) m = fabs(a.z);
    return m;
}
/* a / |a|, or 0 for a = 0; divided by its largest component first, so |a|^2 neither overflows
 * nor underflows. A subnormal largest component is first scaled up by a power of two (exact),
 * so that 1 / m does not overflow. */
CD_INLINE vec3 v_unit_or_zero(vec3 a)
{
    double m = v_maxabs(a);
    if (m == 0.0) return v3(0, 0, 0);
    if (m < DBL_MIN) {
        a = v_scale(0x1p600, a);
        m *= 0x1p600;
    }
    a = v_scale(1.0 / m, a);
    return v_scale(1.0 / v_norm(a), a);
}
/* |a| from a scaled to its largest component's power of two (exact: the same value wherever the
 * squares are normal doubles), so that the squares of a tiny or huge a neither underflow nor
 * overflow; 0 for a = 0. */
CD_INLINE double v_norm_scaled(vec3 a)
{
    int e = cdist__scale_exponent(v_maxabs(a));
    return v_norm(v_scale(cdist__pow2(-e), a)) * cdist__pow2(e);
}
CD_INLINE int v_isfinite(vec3 a) { return isfinite(a.x) && isfinite(a.y) && isfinite(a.z); }

/* The documented basis rule of cdist_circle_basis(): k = index of the smallest |n_k| (first on
 * ties), u = normalise(e_k - n_k n), v = n x u. n must be unit. Choosing the smallest component
 * keeps e_k far from parallel to n, so u is well conditioned. */
CD_INLINE void v_basis(vec3 n, vec3 *u, vec3 *v)
{
    double ax = fabs(n.x), ay = fabs(n.y), az = fabs(n.z);
    vec3 e;
    if (ax <= ay && ax <= az) e = v3(1, 0, 0);
    else if (ay <= az) e = v3(0, 1, 0);
    else e = v3(0, 0, 1);
    vec3 w = v_axpy(e, -v_dot(e, n), n);
    vec3 uu = v_scale(1.0 / v_norm(w), w);
    *u = uu;
    *v = v_cross(n, uu);
}

/* A validated circle: unit normal n, basis u, v (cdist_circle_basis rule), radius r. */
typedef struct cdist__circle {
    vec3 c, n, u, v;
    double r;
} cdist__circle;

/* Angle of a point given relative to the circle centre, in (-pi, pi]; NaN when undefined. */
CD_INLINE double cdist__circle_angle(const cdist__circle *c, vec3 rel)
{
    return cdist__polar_angle(v_dot(c->u, rel), v_dot(c->v, rel));
}

#endif
