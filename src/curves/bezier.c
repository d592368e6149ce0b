/* SPDX-License-Identifier: MIT */
/* Cubic Bezier curve to circle and to disk: the engine with certification, the derivative
 * bounds from the hodographs' control points. */
#include <math.h>

#include "curve_scan.h"

typedef struct bez_x {
    vec3 p[4]; /* relative to the circle's centre */
} bez_x;

static inline vec3 bez_point(const bez_x *b, double t)
{
    double mt = 1.0 - t;
    double b0 = mt * mt * mt, b1 = 3.0 * mt * mt * t, b2 = 3.0 * mt * t * t, b3 = t * t * t;
    return v_axpy(v_axpy(v_axpy(v_scale(b0, b->p[0]), b1, b->p[1]), b2, b->p[2]), b3, b->p[3]);
}

CD_FMA_CLONES static vec3 bez_pos(const void *ctx, double t) { return bez_point(ctx, t); }

CD_FMA_CLONES static cdist_status bez_eval(cdist_query *q, const void *ctx, double t, vec3 *p, vec3 *dp)
{
    (void)q;
    const bez_x *b = ctx;
    double mt = 1.0 - t;
    *p = bez_point(b, t);
    vec3 d0 = v_sub(b->p[1], b->p[0]), d1 = v_sub(b->p[2], b->p[1]), d2 = v_sub(b->p[3], b->p[2]);
    *dp = v_axpy(v_axpy(v_scale(3.0 * mt * mt, d0), 6.0 * mt * t, d1), 3.0 * t * t, d2);
    return CDIST_OK;
}

static cdist_status bezier_query(cdist_query *q, const void *obj, const cdist_circle *c, cdist_result *r, int disk)
{
    const cdist_bezier3 *bz = obj;
    cdist_status st;
    if (!bz) return cdist__fail(q, CDIST_ERR_NULL_ARGUMENT, "Bezier pointer is NULL");
    static const char *names[4] = {"Bezier control point 0", "Bezier control point 1", "Bezier control point 2",
                                   "Bezier control point 3"};
    for (int i = 0; i < 4; i++)
        if ((st = cdist__check_point(q, &bz->p[i], names[i]))) return st;
    cdist__circle cc;
    if ((st = cdist__check_circle(q, c, disk ? "disk" : "circle", &cc))) return st;
    vec3 origin = cc.c;
    bez_x bx;
    double scale = cc.r;
    for (int i = 0; i < 4; i++) {
        bx.p[i] = v_sub(bz->p[i], origin);
        scale = fmax(scale, v_maxabs(bx.p[i]));
    }
    int e = cdist__scale_exponent(scale);
    double down = cdist__pow2(-e);
    for (int i = 0; i < 4; i++) bx.p[i] = v_scale(down, bx.p[i]);
    cc.r *= down;
    cc.c = v3(0, 0, 0);
    /* Bounds of P' and P'' from their control points (the hodographs' convex hulls). */
    double S = 0.0, K = 0.0, Kn = 0.0, Kp = 0.0;
    for (int i = 0; i < 3; i++) S = fmax(S, 3.0 * v_norm(v_sub(bx.p[i + 1], bx.p[i])));
    for (int i = 0; i < 2; i++) {
        vec3 a2 = v_scale(6.0, v_add(v_sub(bx.p[i + 2], v_scale(2.0, bx.p[i + 1])), bx.p[i]));
        K = fmax(K, v_norm(a2));
        Kn = fmax(Kn, fabs(v_dot(cc.n, a2)));
        Kp = fmax(Kp, v_norm(v_cross(cc.n, a2)));
    }
    double bounds[4] = {S, K, Kn, Kp};
    return cdist__cs_run_curve(q, bez_eval, bez_pos, &bx, 0.0, 1.0, &cc, disk, origin, scale * down, 0.0, cdist__pow2(e), bounds, r);
}

cdist_status cdist_bezier3_circle(cdist_query *q, const cdist_bezier3 *b, const cdist_circle *c, cdist_result *r)
{
    return cdist__cs_entry(q, bezier_query, b, c, r, 0);
}

cdist_status cdist_bezier3_disk(cdist_query *q, const cdist_bezier3 *b, const cdist_circle *d, cdist_result *r)
{
    return cdist__cs_entry(q, bezier_query, b, d, r, 1);
}
