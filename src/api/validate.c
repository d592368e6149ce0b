/* SPDX-License-Identifier: MIT */
/* Input validation: every public query checks its inputs here before any family core runs. */
#include <math.h>
#include <stdio.h>

#include "api/api-priv.h"

cdist_status cdist__check_ptr(cdist_query *q, const void *p, const char *what)
{
    return p ? CDIST_OK : cdist__fail(q, CDIST_ERR_NULL_ARGUMENT, "%s pointer is NULL", what);
}

cdist_status cdist__check_scalar(cdist_query *q, double x, const char *what)
{
    if (!isfinite(x)) return cdist__fail(q, CDIST_ERR_NOT_FINITE, "%s is not finite (%g)", what, x);
    if (fabs(x) > CD_MAX_ABS) return cdist__fail(q, CDIST_ERR_OUT_OF_RANGE, "%s exceeds 1e150 in magnitude (%g)", what, x);
    return CDIST_OK;
}

cdist_status cdist__check_radius(cdist_query *q, double r, const char *what)
{
    cdist_status st = cdist__check_scalar(q, r, what);
    if (st) return st;
    if (r < 0.0) return cdist__fail(q, CDIST_ERR_NEGATIVE_RADIUS, "%s is negative (%g)", what, r);
    return CDIST_OK;
}

/* Why a point (not NULL) is refused: not finite, or out of range; CDIST_OK when neither. */
static cdist_status point_problem(cdist_query *q, const cdist_vec3 *p, const char *what)
{
    if (!v_isfinite(*p))
        return cdist__fail(q, CDIST_ERR_NOT_FINITE, "%s is not finite (%g, %g, %g)", what, p->x, p->y, p->z);
    if (v_maxabs(*p) > CD_MAX_ABS)
        return cdist__fail(q, CDIST_ERR_OUT_OF_RANGE, "%s exceeds 1e150 in magnitude (%g, %g, %g)", what, p->x, p->y,
                           p->z);
    return CDIST_OK;
}

cdist_status cdist__check_point_slow(cdist_query *q, const cdist_vec3 *p, const char *what)
{
    if (!p) return cdist__fail(q, CDIST_ERR_NULL_ARGUMENT, "%s pointer is NULL", what);
    return point_problem(q, p, what);
}

/* A non-zero vector d (finite, |components| <= CD_MAX_ABS) whose squared length might
 * underflow (largest component m below CD_MIN_NORMAL_FAST), scaled exactly by a power of two so
 * that m is about 1 (1 / m would overflow for subnormal components). */
CD_INLINE vec3 scaled_direction(vec3 d, double m, double *down)
{
    int e = cdist__scale_exponent(m);
    *down = cdist__pow2(e);
    return v_scale(cdist__pow2(-e), d);
}

/* The one length rule of a direction or normal d, finite and in range (cdist__direction_fast_body
 * is its fast part): from d itself when its largest component m >= CD_MIN_NORMAL_FAST (|d|^2
 * finite and normal), else from a rescaled copy. */
CD_INLINE cdist_status direction_length(cdist_query *q, const cdist_vec3 *d, const char *what, int unit_required,
                                        vec3 *unit, double *length)
{
    double m = v_maxabs(*d);
    if (m == 0.0) return cdist__fail(q, CDIST_ERR_ZERO_VECTOR, "%s has zero length", what);
    double down = 1.0;
    vec3 s = m >= CD_MIN_NORMAL_FAST ? *d : scaled_direction(*d, m, &down);
    double ns = v_norm(s);
    double len = ns * down; /* may underflow for a subnormal vector: only reported, never divided by */
    if (unit_required && q && !(fabs(len - 1.0) <= q->unit_tol))
        return cdist__fail(q, CDIST_ERR_NOT_UNIT,
                       "%s has length %.17g, not 1 (tolerance %g; see cdist_query_set_unit_tolerance)", what, len,
                       q->unit_tol);
    if (unit) *unit = v_scale(1.0 / ns, s);
    if (length) *length = len;
    return CDIST_OK;
}

CD_FMA_CLONES cdist_status cdist__check_direction(cdist_query *q, const cdist_vec3 *d, const char *what, int unit_required, vec3 *unit,
                                double *length)
{
    if (!d) return cdist__fail(q, CDIST_ERR_NULL_ARGUMENT, "%s pointer is NULL", what);
    if (!cdist__in_range(*d)) return point_problem(q, d, what);
    return direction_length(q, d, what, unit_required, unit, length);
}

/* What the fast path (cdist__circle_fast_body) did not accept, in one pass: the centre, the
 * normal, the radius, each checked once and the first problem reported; or the circle accepted
 * (a normal too small for the fast length rule). */
static cdist_status circle_slow(cdist_query *q, const cdist_circle *c, const char *what, cdist__circle *out)
{
    char buf[64];
    if (!cdist__in_range(c->center)) {
        snprintf(buf, sizeof buf, "%s centre", what);
        return point_problem(q, &c->center, buf);
    }
    snprintf(buf, sizeof buf, "%s normal", what);
    if (!cdist__in_range(c->normal)) return point_problem(q, &c->normal, buf);
    cdist_status st = direction_length(q, &c->normal, buf, 1, &out->n, NULL);
    if (st) return st;
    snprintf(buf, sizeof buf, "%s radius", what);
    st = cdist__check_radius(q, c->radius, buf);
    if (st) return st;
    out->c = c->center;
    out->r = c->radius;
    return CDIST_OK;
}

CD_FMA_CLONES cdist_status cdist__check_circle_nobasis(cdist_query *q, const cdist_circle *c, const char *what, cdist__circle *out)
{
    if (!c) return cdist__fail(q, CDIST_ERR_NULL_ARGUMENT, "%s pointer is NULL", what);
    if (q && cdist__circle_fast_body(q->unit_tol, c, out)) return CDIST_OK;
    return circle_slow(q, c, what, out);
}

CD_FMA_CLONES int cdist__circle_fast(double unit_tol, const cdist_circle *c, cdist__circle *out)
{
    return cdist__circle_fast_body(unit_tol, c, out);
}

CD_FMA_CLONES cdist_status cdist__check_circle(cdist_query *q, const cdist_circle *c, const char *what, cdist__circle *out)
{
    cdist_status st = cdist__check_circle_nobasis(q, c, what, out);
    if (st == CDIST_OK) cdist__frame_basis(out);
    return st;
}

cdist_status cdist__check_line_ray_slow(cdist_query *q, const void *obj, const cdist_vec3 *origin, const cdist_vec3 *dir,
                                       int is_ray, vec3 *M, double *len)
{
    cdist_status st;
    if ((st = cdist__check_ptr(q, obj, is_ray ? "ray" : "line")) ||
        (st = cdist__check_point(q, origin, is_ray ? "ray origin" : "line origin")))
        return st;
    return cdist__check_direction(q, dir, is_ray ? "ray direction" : "line direction", 1, M, len);
}

cdist_status cdist__check_segment(cdist_query *q, const cdist_segment *s)
{
    cdist_status st;
    if ((st = cdist__check_ptr(q, s, "segment")) || (st = cdist__check_point(q, &s->p0, "segment p0")))
        return st;
    return cdist__check_point(q, &s->p1, "segment p1");
}
