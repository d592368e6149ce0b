/* SPDX-License-Identifier: MIT */
/* Circle-circle by geometric iteration (Li, Wu, Wang, Zhang 2015; English summary in
 * ../shared/refs/README.md): alternating projections from several starts, each fixed point
 * polished on the true distance. The algorithms and the guards: docs/circles.md. */
#include <math.h>

#include "internal.h"

#define CC_STARTS 8
#define CC_CHECKS 16

/* Orthogonal projection of x (relative to the origin = c0's centre) onto circle c centred at
 * cc. On the axis every point is a foot; the basis direction u is taken. Forced inline: it is
 * the loop's whole body, and a call there costs more than the projection. */
CD_INLINE vec3 project(const cdist__circle *c, vec3 cc, vec3 x)
{
    /* plain arithmetic: the inner loop (fma() is a library call without hardware FMA flags) */
    double dx = x.x - cc.x, dy = x.y - cc.y, dz = x.z - cc.z;
    vec3 n = c->n;
    double ax = n.y * dz - n.z * dy, ay = n.z * dx - n.x * dz, az = n.x * dy - n.y * dx; /* n x d */
    double rho = sqrt(ax * ax + ay * ay + az * az);
    if (!(rho > 0.0)) return v3(cc.x + c->r * c->u.x, cc.y + c->r * c->u.y, cc.z + c->r * c->u.z);
    double k = c->r / rho; /* (n x d) x n is the in-plane part of d, length rho */
    return v3(cc.x + k * (ay * n.z - az * n.y), cc.y + k * (az * n.x - ax * n.z), cc.z + k * (ax * n.y - ay * n.x));
}

/* Alternating projection starting from the point x1 of c1. Returns the angle of the final
 * point of c0 and the number of iterations. */
static double iterate(const cdist__cc *g, vec3 x1, int cap, int *count)
{
    const cdist__circle *c0 = g->c[0], *c1 = g->c[1];
    vec3 zero = v3(0, 0, 0);
    vec3 k0 = project(c0, zero, x1);
    double d2 = INFINITY;
    int k = 0;
    while (k < cap) {
        k++;
        vec3 p1 = project(c1, g->D, k0);
        vec3 k0n = project(c0, zero, p1);
        double ex = k0n.x - p1.x, ey = k0n.y - p1.y, ez = k0n.z - p1.z;
        double mx = k0n.x - k0.x, my = k0n.y - k0.y, mz = k0n.z - k0.z;
        double d2n = ex * ex + ey * ey + ez * ez;
        double move = sqrt(mx * mx + my * my + mz * mz);
        int stop = move <= CD_CC_ITER_TOL * g->L || !(d2n < d2);
        if (d2n <= d2) k0 = k0n;
        d2 = fmin(d2, d2n);
        if (stop) break;
    }
    *count = k;
    double a = cdist__circle_angle(c0, k0);
    return isnan(a) ? 0.0 : a;
}

typedef struct fixed_pt {
    double t, F;
    int iters;
} fixed_pt;

static cdist_status iteration(cdist_query *q, const cdist__circle *c0, const cdist__circle *c1, cdist__best *b, int *iterations);

cdist_status cdist__cc_iteration(cdist_query *q, const cdist__circle *c0, const cdist__circle *c1, cdist__best *b, int *iterations)
{
    cdist__circle a, bb;
    double s;
    cdist__cc_scale(c0, c1, b->scale, &a, &bb, &s);
    cdist__best sb;
    cdist__best_init(&sb, b->scale * s);
    cdist_status st = iteration(q, &a, &bb, &sb, iterations);
    if (st == CDIST_OK) cdist__cc_unscale(&sb, s, b);
    return st;
}

static cdist_status iteration(cdist_query *q, const cdist__circle *c0, const cdist__circle *c1, cdist__best *b, int *iterations)
{
    cdist__cc g = {{c0, c1}, c1->c, b->scale};
    int dummy;
    if (!iterations) iterations = &dummy;
    *iterations = 0;
    if (cdist__cc_closed_form(&g, b)) return CDIST_OK; /* points; §2.4 coincident axes */
    double sn = v_norm(v_cross(c0->n, c1->n));
    if (sn <= CD_CC_POLY_PARALLEL) { /* §2.3: parallel axes, closed forms, polished */
        double t0[4];
        int k = cdist__cc_parallel_candidates(&g, t0);
        int sd[4] = {0, 0, 0, 0};
        double F[4];
        for (int i = 0; i < k; i++) t0[i] = cdist__cc_polish(&g, 0, t0[i], &F[i]);
        cdist__cc_offer_minima(&g, k, sd, t0, F, b);
        return CDIST_OK;
    }
    int cap = q->max_iterations > 0 ? q->max_iterations : CD_DEFAULT_MAX_ITERATIONS;
    fixed_pt fp[CC_STARTS + 4 + 2 * (CC_STARTS + 4)];
    int nf = 0;
    double best = INFINITY;
    for (int s = 0; s < CC_STARTS + 4; s++) {
        vec3 x1;
        double a;
        if (s < 4) { /* a point of c1 */
            a = 0.5 * M_PI * s;
            x1 = v_add(c1->c, v_axpy(v_scale(c1->r * cos(a), c1->u), c1->r * sin(a), c1->v));
        } else if (s < 8) { /* a point of c0, first projected onto c1 */
            a = 0.25 * M_PI + 0.5 * M_PI * (s - 4);
            x1 = project(c1, g.D, v_axpy(v_scale(c0->r * cos(a), c0->u), c0->r * sin(a), c0->v));
        } else if (s == 8) {
            /* the final check: the lowest of CC_CHECKS samples of F on c0, if it is below every
             * fixed point found (a basin no start reached) */
            double Fs = INFINITY, ts = 0.0;
            for (int i = 0; i < CC_CHECKS; i++) {
                double t = -M_PI + (2.0 * M_PI / CC_CHECKS) * (i + 0.5);
                double F = cdist__cc_eval(&g, 0, t, NULL, NULL, NULL, NULL);
                if (F < Fs) Fs = F, ts = t;
            }
            if (!(Fs < best)) break;
            x1 = project(c1, g.D, v_axpy(v_scale(c0->r * cos(ts), c0->u), c0->r * sin(ts), c0->v));
        } else {
            break;
        }
        int cnt;
        double t = iterate(&g, x1, cap, &cnt);
        double F;
        t = cdist__cc_polish(&g, 0, t, &F);
        /* distinct fixed points only (after the Newton finish, so distinct close minima stay) */
        int dup = -1;
        for (int i = 0; i < nf; i++) {
            double dt = fabs(remainder(t - fp[i].t, 2.0 * M_PI));
            if (dt <= CD_CC_ITER_SAME) dup = i;
        }
        if (dup >= 0) {
            if (cnt < fp[dup].iters) fp[dup].iters = cnt;
            continue;
        }
        fp[nf].t = t, fp[nf].F = F, fp[nf].iters = cnt, nf++;
        if (F < best) best = F;
    }
    /* Axes meeting: the mirror image of every near-best pair (the paper's second pair). */
    vec3 m;
    if (cdist__cc_mirror(&g, &m)) {
        int n0 = nf;
        double margin = CD_CC_KEEP_REL * best + CD_CC_ITER_KEEP_ABS * g.L * g.L;
        for (int i = 0; i < n0; i++) {
            if (!(fp[i].F <= best + margin)) continue;
            vec3 p = v_axpy(v_scale(cos(fp[i].t), c0->u), sin(fp[i].t), c0->v);
            p = v_axpy(p, -2.0 * v_dot(p, m), m);
            double a = cdist__circle_angle(c0, p), F;
            if (isnan(a)) continue;
            a = cdist__cc_polish(&g, 0, a, &F);
            fp[nf].t = a, fp[nf].F = F, fp[nf].iters = fp[i].iters, nf++;
        }
    }
    int ib = 0, sd[sizeof fp / sizeof fp[0]];
    double ft[sizeof fp / sizeof fp[0]], fF[sizeof fp / sizeof fp[0]];
    for (int i = 0; i < nf; i++) {
        sd[i] = 0, ft[i] = fp[i].t, fF[i] = fp[i].F;
        if (fp[i].F < fp[ib].F) ib = i;
    }
    cdist__cc_offer_minima(&g, nf, sd, ft, fF, b);
    *iterations = nf ? fp[ib].iters : 0;
    return CDIST_OK;
}
