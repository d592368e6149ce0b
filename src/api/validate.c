/* Input validation: every public query checks its inputs here before any family core runs. */
#include <math.h>
#include <stdio.h>

#include "internal.h"

cdist_status cd_check_handle(cdist_query *q, cdist_result *r)
{
    cd_begin(q, r);
    if (!q) return CDIST_ERR_NULL_ARGUMENT;
    if (!r) return cd_fail(q, CDIST_ERR_NULL_ARGUMENT, "result pointer is NULL");
    return CDIST_OK;
}

cdist_status cd_check_ptr(cdist_query *q, const void *p, const char *what)
{
    return p ? CDIST_OK : cd_fail(q, CDIST_ERR_NULL_ARGUMENT, "%s pointer is NULL", what);
}

cdist_status cd_check_scalar(cdist_query *q, double x, const char *what)
{
    if (!isfinite(x)) return cd_fail(q, CDIST_ERR_NOT_FINITE, "%s is not finite (%g)", what, x);
    if (fabs(x) > CD_MAX_ABS) return cd_fail(q, CDIST_ERR_OUT_OF_RANGE, "%s exceeds 1e150 in magnitude (%g)", what, x);
    return CDIST_OK;
}

cdist_status cd_check_point(cdist_query *q, const cdist_vec3 *p, const char *what)
{
    if (!p) return cd_fail(q, CDIST_ERR_NULL_ARGUMENT, "%s pointer is NULL", what);
    if (!v_isfinite(*p))
        return cd_fail(q, CDIST_ERR_NOT_FINITE, "%s is not finite (%g, %g, %g)", what, p->x, p->y, p->z);
    if (v_maxabs(*p) > CD_MAX_ABS)
        return cd_fail(q, CDIST_ERR_OUT_OF_RANGE, "%s exceeds 1e150 in magnitude (%g, %g, %g)", what, p->x, p->y,
                       p->z);
    return CDIST_OK;
}

cdist_status cd_check_direction(cdist_query *q, const cdist_vec3 *d, const char *what, int unit_required, vec3 *unit,
                                double *length)
{
    cdist_status st = cd_check_point(q, d, what);
    if (st) return st;
    /* Scale first so the length neither overflows nor underflows. */
    double m = v_maxabs(*d);
    if (m == 0.0) return cd_fail(q, CDIST_ERR_ZERO_VECTOR, "%s has zero length", what);
    vec3 s = v_scale(1.0 / m, *d);
    double ns = v_norm(s);
    double len = m * ns;
    if (unit_required && q && !(fabs(len - 1.0) <= q->unit_tol))
        return cd_fail(q, CDIST_ERR_NOT_UNIT,
                       "%s has length %.17g, not 1 (tolerance %g; see cdist_query_set_unit_tolerance)", what, len,
                       q->unit_tol);
    if (unit) *unit = v_scale(1.0 / ns, s);
    if (length) *length = len;
    return CDIST_OK;
}

/* Validation without message formatting: a valid circle formats no strings (that was a fifth
 * of a random circle-circle query). Returns 0 on any doubt; cd_check_circle then finds and
 * reports the problem. */
static int circle_fast(const cdist_query *q, const cdist_circle *c, cd_circle *out)
{
    vec3 p = c->center, d = c->normal;
    double r = c->radius;
    if (!v_isfinite(p) || !v_isfinite(d) || !isfinite(r)) return 0;
    if (v_maxabs(p) > CD_MAX_ABS || v_maxabs(d) > CD_MAX_ABS || fabs(r) > CD_MAX_ABS || r < 0.0) return 0;
    double m = v_maxabs(d);
    if (m == 0.0) return 0;
    vec3 sd = v_scale(1.0 / m, d); /* same arithmetic as cd_check_direction */
    double ns = v_norm(sd), len = m * ns;
    if (!(fabs(len - 1.0) <= q->unit_tol)) return 0;
    out->n = v_scale(1.0 / ns, sd);
    out->c = p;
    out->r = r;
    v_basis(out->n, &out->u, &out->v);
    return 1;
}

cdist_status cd_check_circle(cdist_query *q, const cdist_circle *c, const char *what, cd_circle *out)
{
    if (!c) return cd_fail(q, CDIST_ERR_NULL_ARGUMENT, "%s pointer is NULL", what);
    if (q && circle_fast(q, c, out)) return CDIST_OK;
    char buf[64];
    snprintf(buf, sizeof buf, "%s centre", what);
    cdist_status st = cd_check_point(q, &c->center, buf);
    if (st) return st;
    snprintf(buf, sizeof buf, "%s normal", what);
    st = cd_check_direction(q, &c->normal, buf, 1, &out->n, NULL);
    if (st) return st;
    snprintf(buf, sizeof buf, "%s radius", what);
    st = cd_check_scalar(q, c->radius, buf);
    if (st) return st;
    if (c->radius < 0.0) return cd_fail(q, CDIST_ERR_NEGATIVE_RADIUS, "%s radius is negative (%g)", what, c->radius);
    out->c = c->center;
    out->r = c->radius;
    v_basis(out->n, &out->u, &out->v);
    return CDIST_OK;
}

cdist_method cd_pick_method(const cdist_query *q, unsigned available_mask, cdist_method fallback)
{
    cdist_method m = q->method;
    if (m == CDIST_METHOD_AUTO || !(available_mask & CD_HAS(m))) return fallback;
    return m;
}

