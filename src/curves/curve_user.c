/* SPDX-License-Identifier: MIT */
/* Curves given by a caller's callback (cdist_curve_circle, cdist_curve_disk): scanned by the
 * engine without certification (no bound of the callback's derivatives is known; what is and
 * is not guaranteed: docs/curves.md). */
#include <math.h>
#include <stdio.h>

#include "curve_scan.h"

typedef struct user_curve {
    cdist_curve_fn f;
    void *user;
    vec3 origin;
    double down; /* the power-of-two scale of the query's frame */
} user_curve;

static cdist_status user_eval(cdist_query *q, const void *ctx, double t, vec3 *p, vec3 *dp)
{
    const user_curve *u = ctx;
    cdist_vec3 P = {NAN, NAN, NAN}, D = {NAN, NAN, NAN};
    int rc = u->f(u->user, t, &P, &D);
    if (rc) return cdist__fail(q, CDIST_ERR_CALLBACK_FAILED, "curve callback returned %d at t = %.17g", rc, t);
    if (!v_isfinite(P) || !v_isfinite(D))
        return cdist__fail(q, CDIST_ERR_CALLBACK_NOT_FINITE,
                       "curve callback gave a non-finite %s at t = %.17g", v_isfinite(P) ? "derivative" : "position",
                       t);
    if (v_maxabs(P) > CD_MAX_ABS || v_maxabs(D) > CD_MAX_ABS)
        return cdist__fail(q, CDIST_ERR_OUT_OF_RANGE, "curve callback gave a value beyond 1e150 at t = %.17g", t);
    *p = v_scale(u->down, v_sub(P, u->origin));
    *dp = v_scale(u->down, D);
    return CDIST_OK;
}

static cdist_status curve_query(cdist_query *q, const void *obj, const cdist_circle *c, cdist_result *r, int disk)
{
    const cdist_curve *cv = obj;
    cdist_curve_fn f = cv->fn;
    double t0 = cv->t0, t1 = cv->t1;
    cdist_status st;
    if (!f) return cdist__fail(q, CDIST_ERR_NULL_ARGUMENT, "curve callback is NULL");
    cdist__circle cc;
    if ((st = cdist__check_circle(q, c, disk ? "disk" : "circle", &cc))) return st;
    if ((st = cdist__cs_check_interval(q, t0, t1, "curve"))) return st;
    user_curve u = {f, cv->user, cc.c, 1.0};
    vec3 origin = cc.c;
    cc.c = v3(0, 0, 0);
    /* The scale of the frame from a few positions (the callback's positions are only known as
     * it is called): squares stay free of overflow even where the curve reaches 2^400 times
     * farther between these positions, and of underflow for tiny curves. */
    double L = cc.r;
    for (int i = 0; i <= CD_CURVE_SCALE_PROBES; i++) {
        vec3 P = v3(0, 0, 0), D; /* set by user_eval on success (gcc 12 cannot see it) */
        double t = i == CD_CURVE_SCALE_PROBES ? t1 : t0 + (t1 - t0) * ((double)i / CD_CURVE_SCALE_PROBES);
        if ((st = user_eval(q, &u, t, &P, &D))) return st;
        L = fmax(L, v_maxabs(P));
    }
    int e = cdist__scale_exponent(L);
    u.down = cdist__pow2(-e);
    cc.r *= u.down;
    /* The callback's positions are absolute: their rounding is relative to |origin| too. */
    return cdist__cs_run_curve(q, user_eval, NULL, &u, t0, t1, &cc, disk, origin, cc.r, v_maxabs(origin) * u.down, cdist__pow2(e), NULL,
                     r);
}

cdist_status cdist_curve_circle(cdist_query *q, cdist_curve_fn f, void *user, double t0, double t1,
                                const cdist_circle *c, cdist_result *r)
{
    const cdist_curve cv = {f, user, t0, t1};
    return cdist__cs_entry(q, curve_query, &cv, c, r, 0);
}

cdist_status cdist_curve_disk(cdist_query *q, cdist_curve_fn f, void *user, double t0, double t1,
                              const cdist_circle *d, cdist_result *r)
{
    const cdist_curve cv = {f, user, t0, t1};
    return cdist__cs_entry(q, curve_query, &cv, d, r, 1);
}
