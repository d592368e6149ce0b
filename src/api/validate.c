/* SPDX-License-Identifier: MIT */
/* Input validation: every public query checks its inputs here before any family core runs. */
#include <math.h>
#include <stdio.h>

#include "internal.h"

cdist_status cdist__check_handle(cdist_query *q, cdist_result *r)
{
    if (q && atomic_load_explicit(&q->busy, memory_order_acquire)) {
        if (r) cdist__result_set_error(r);
        return CDIST_ERR_HANDLE_BUSY; /* a call through cdist__enter holds the handle */
    }
    cdist__begin(q, r);
    if (!q) return CDIST_ERR_NULL_ARGUMENT;
    if (!r) return cdist__fail(q, CDIST_ERR_NULL_ARGUMENT, "result pointer is NULL");
    return CDIST_OK;
}

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

cdist_status cdist__check_point_slow(cdist_query *q, const cdist_vec3 *p, const char *what)
{
    if (!p) return cdist__fail(q, CDIST_ERR_NULL_ARGUMENT, "%s pointer is NULL", what);
    if (!v_isfinite(*p))
        return cdist__fail(q, CDIST_ERR_NOT_FINITE, "%s is not finite (%g, %g, %g)", what, p->x, p->y, p->z);
    if (v_maxabs(*p) > CD_MAX_ABS)
        return cdist__fail(q, CDIST_ERR_OUT_OF_RANGE, "%s exceeds 1e150 in magnitude (%g, %g, %g)", what, p->x, p->y,
                       p->z);
    return CDIST_OK;
}

/* A non-zero vector d (finite, |components| <= CD_MAX_ABS) scaled exactly by a power of two so
 * that its largest component is about 1: its squared length neither overflows nor underflows,
 * also for subnormal components (1 / max|d_i| would overflow there). */
CD_INLINE vec3 scaled_direction(vec3 d, double m, double *down)
{
    if (m >= 0x1p-500) {
        *down = m; /* 1 / m is finite: the original arithmetic, kept bit for bit */
        return v_scale(1.0 / m, d);
    }
    int e = cdist__scale_exponent(m);
    *down = cdist__pow2(e);
    return v_scale(cdist__pow2(-e), d);
}

CD_FMA_CLONES cdist_status cdist__check_direction(cdist_query *q, const cdist_vec3 *d, const char *what, int unit_required, vec3 *unit,
                                double *length)
{
    cdist_status st = cdist__check_point(q, d, what);
    if (st) return st;
    double m = v_maxabs(*d);
    if (m == 0.0) return cdist__fail(q, CDIST_ERR_ZERO_VECTOR, "%s has zero length", what);
    double down;
    vec3 s = scaled_direction(*d, m, &down);
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

/* Validation without message formatting: a valid circle formats no strings. One comparison
 * per number covers NaN, infinity and the range (|x| <= CD_MAX_ABS is false for all three);
 * the normal's squared length is taken directly when it is safely in range. Returns 0 on any
 * doubt; the slow path then finds and reports the problem, or accepts the circle. */
CD_INLINE int circle_fast(double unit_tol, const cdist_circle *c, cdist__circle *out)
{
    vec3 p = c->center, d = c->normal;
    double r = c->radius;
    if (!(fabs(p.x) <= CD_MAX_ABS && fabs(p.y) <= CD_MAX_ABS && fabs(p.z) <= CD_MAX_ABS && r >= 0.0 &&
          r <= CD_MAX_ABS))
        return 0;
    double m = v_maxabs(d);
    if (!(m >= 0x1p-500 && m <= CD_MAX_ABS)) return 0; /* also NaN or infinite components */
    /* The arithmetic of cdist__check_direction before its scaling fix, bit for bit: the batch
     * point kernel (src/batch/point_kernel.c) repeats it and must agree with single calls. */
    vec3 sd = v_scale(1.0 / m, d);
    double ns = v_norm(sd), len = m * ns;
    if (!(fabs(len - 1.0) <= unit_tol)) return 0;
    out->n = v_scale(1.0 / ns, sd);
    out->c = p;
    out->r = r;
    return 1;
}

static cdist_status circle_slow(cdist_query *q, const cdist_circle *c, const char *what, cdist__circle *out)
{
    char buf[64];
    snprintf(buf, sizeof buf, "%s centre", what);
    cdist_status st = cdist__check_point(q, &c->center, buf);
    if (st) return st;
    snprintf(buf, sizeof buf, "%s normal", what);
    st = cdist__check_direction(q, &c->normal, buf, 1, &out->n, NULL);
    if (st) return st;
    snprintf(buf, sizeof buf, "%s radius", what);
    st = cdist__check_scalar(q, c->radius, buf);
    if (st) return st;
    if (c->radius < 0.0) return cdist__fail(q, CDIST_ERR_NEGATIVE_RADIUS, "%s radius is negative (%g)", what, c->radius);
    out->c = c->center;
    out->r = c->radius;
    return CDIST_OK;
}

CD_FMA_CLONES cdist_status cdist__check_circle_nobasis(cdist_query *q, const cdist_circle *c, const char *what, cdist__circle *out)
{
    if (!c) return cdist__fail(q, CDIST_ERR_NULL_ARGUMENT, "%s pointer is NULL", what);
    if (q && circle_fast(q->unit_tol, c, out)) return CDIST_OK;
    return circle_slow(q, c, what, out);
}

CD_FMA_CLONES int cdist__circle_fast(double unit_tol, const cdist_circle *c, cdist__circle *out)
{
    return circle_fast(unit_tol, c, out);
}

CD_FMA_CLONES int cdist__circle_fast_basis(double unit_tol, const cdist_circle *c, cdist__circle *out)
{
    if (!c || !circle_fast(unit_tol, c, out)) return 0;
    cdist__frame_basis(out);
    return 1;
}

CD_FMA_CLONES cdist_status cdist__check_circle(cdist_query *q, const cdist_circle *c, const char *what, cdist__circle *out)
{
    cdist_status st = cdist__check_circle_nobasis(q, c, what, out);
    if (st == CDIST_OK) cdist__frame_basis(out);
    return st;
}

