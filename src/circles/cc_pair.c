/* SPDX-License-Identifier: MIT */
/* The answers of the circle-circle engine: the pair at an angle offered to the sink's
 * collector, and the distances of the kept candidates settled in double-double. */
#include <math.h>

#include "base/point_circle.h"
#include "circles/circles-priv.h"

/* The pair at angle t of A ((c, s) = (cos t, sin t)) with its squared distance: plain, or
 * (final) the double-double formula of the answer (cdist__cc_point_d2). */
CD_INLINE void cc_pair(const cdist__cc_frame *f, double t, double c, double s, int final, cdist__cc_sink *k)
{
    vec3 P = v_axpy(v_scale(f->R * c, f->u), f->R * s, f->v);
    cdist__pc_parts e = cdist__point_circle(f->m, v_sub(P, f->C), f->s);
    double rho = e.rho;
    double d2 = final ? cdist__cc_point_d2(&f->rg, f->s, c, s) : e.d2;
    vec3 dir;
    double tb;
    if (rho > 0) {
        dir = cdist__pc_inplane(e.np, f->m);
        /* within 1e-150 of B's axis |dir|^2 is subnormal: normalised from its largest component */
        dir = rho < 0x1p-500 ? v_scale(f->s, v_unit_or_zero(dir)) : v_scale(f->s / v_norm(dir), dir);
        tb = cdist__circle_angle(k->B, dir);
    } else {
        dir = v_scale(f->s, k->B->u);
        tb = 0.0;
    }
    vec3 K = v_add(f->C, dir);
    double ta = cdist__cc_param(t);
    if (k->B->r == 0.0) tb = NAN;
    double u = k->unscale, d = sqrt(d2);
    if (!k->swapped) cdist__best_offer(k->best, d2 * u * u, v_scale(u, P), v_scale(u, K), ta, tb);
    else cdist__best_offer(k->best, d2 * u * u, v_scale(u, v_sub(K, f->C)), v_scale(u, v_sub(P, f->C)), tb, ta);
    if (d < k->dmin) {
        k->dmin = d;
        k->rho_min = rho;
    }
}

CD_FMA_CLONES void cdist__cc_pair_at(const cdist__cc_frame *f, double t, cdist__cc_sink *k)
{
    double c, s;
    sincos(t, &s, &c);
    /* plain: the kept candidates' distances are recomputed in double-double at the end
     * (cdist__cc_settle_d2) */
    cc_pair(f, t, c, s, 0, k);
}

CD_FMA_CLONES void cdist__cc_pair_final(const cdist__cc_frame *f, double t, double c, double s, cdist__cc_sink *k)
{
    cc_pair(f, cdist__cc_param(t), c, s, 1, k);
}

void cdist__cc_settle_d2(const cdist__cc_frame *f, const cdist__cc_sink *k)
{
    cdist__best *b = k->best;
    double u = k->unscale, near = sqrt(b->c[0].d2) + (CD_TIE_ULPS + CD_CC_SETTLE_ULPS) * DBL_EPSILON * b->scale;
    for (int i = 0; i < b->n && sqrt(b->c[i].d2) <= near; i++) {
        double t = b->c[i].param[k->swapped ? 1 : 0], c, s;
        sincos(t, &s, &c);
        b->c[i].d2 = cdist__cc_point_d2(&f->rg, f->s, c, s) * u * u;
    }
    for (int i = 1; i < b->n; i++) /* ties may swap places */
        for (int j = i; j > 0 && b->c[j].d2 < b->c[j - 1].d2; j--) {
            cdist__cand x = b->c[j];
            b->c[j] = b->c[j - 1];
            b->c[j - 1] = x;
        }
}

