/* SPDX-License-Identifier: MIT */
/* Circle to circle, the robust method (the AUTO answer), on the larger circle: parallel planes
 * in closed form; else first the certified search with its angles in lanes (cdist__cc_quick,
 * cc_search.c: a grid, concave hull bounds, a zoomed basin certified convex, Newton), which
 * answers when the closest point is certified unique and not
 * on or near the other's axis (97% of random pairs); else the root-isolation engine of
 * docs/circles.md, which also answers every tie, equidistant set and touching pair. The search is
 * not tried where it cannot certify (the frame's quick, ring_lanes.h). */
#include <math.h>

#include "circles/circles-priv.h"

/* The antisymmetric choice of the circle to parameterise: 1 when it is c1. */
static int param_second(const cdist__circle *c0, const cdist__circle *c1, vec3 C)
{
    if (c0->r != c1->r) return c1->r > c0->r;
    const double x[3] = {c0->n.x, c0->n.y, c0->n.z}, y[3] = {c1->n.x, c1->n.y, c1->n.z};
    for (int i = 0; i < 3; i++)
        if (x[i] != y[i]) return y[i] > x[i];
    /* Same radius and normal: decide on the sign of the centre offset, which flips on a swap. */
    const double z[3] = {C.x, C.y, C.z};
    for (int i = 0; i < 3; i++)
        if (z[i] != 0.0) return z[i] < 0.0;
    return 0;
}

CD_FMA_CLONES int cdist__cc_prepare(const cdist__circle *c0, const cdist__circle *c1, cdist__cc_problem *p)
{
    vec3 C = v_sub(c1->c, c0->c); /* c0->c is the origin here; kept general */
    p->C = C;
    p->swapped = param_second(c0, c1, C);
    const cdist__circle *A = p->swapped ? c1 : c0, *B = p->swapped ? c0 : c1;
    if (A->r == 0.0 || B->r == 0.0) return 0;
    /* H has terms of order L^6 */
    double sc;
    cdist__circles_scale(cdist__fmax(cdist__fmax(c0->r, c1->r), v_norm(C)), 1, &sc, &p->unscale);
    p->A = *A;
    p->B = *B;
    p->A.c = v_scale(sc, A->c);
    p->A.r = sc * A->r;
    p->B.c = v_scale(sc, B->c);
    p->B.r = sc * B->r;
    p->CB = v_scale(sc, p->swapped ? v_neg(C) : C);
    return 1;
}

/* The robust method up to its certified search (the state in *s, which the sink points into:
 * not to be moved): CDIST__CC_ANSWERED (a radius 0: b holds the answer), CDIST__CC_SEARCH (the
 * search is to run on s->f, then cdist__cc_pair_final or, when it does not certify,
 * cdist__cc_robust_engine) or CDIST__CC_ENGINE (the search cannot certify here). */
int cdist__cc_robust_start(const cdist__circle *c0, const cdist__circle *c1, cdist__best *b, cdist__cc_robust_state *s)
{
    cdist__cc_problem *pb = &s->pb;
    if (!cdist__cc_prepare(c0, c1, pb)) {
        vec3 C = pb->C;
        int sw = pb->swapped;
        const cdist__circle *A = sw ? c1 : c0;
        if (A->r == 0.0) {
            /* Both are points. */
            cdist__best_offer(b, v_sqr(C), c0->c, c1->c, NAN, NAN);
            return CDIST__CC_ANSWERED;
        }
        /* B is a point: the point-circle core (equidistant when it is on A's axis). */
        if (!sw) {
            cdist__point_circle_core(C, c0, b, 1);
        } else {
            cdist__best t;
            cdist__best_init(&t, b->scale);
            cdist__point_circle_core(v_neg(C), c1, &t, 0);
            for (int i = 0; i < t.n; i++)
                cdist__best_offer_flag(b, t.c[i].equidistant, t.c[i].d2, v_add(t.c[i].p[0], C), v_add(t.c[i].p[1], C),
                                   t.c[i].param[0], t.c[i].param[1]);
        }
        return CDIST__CC_ANSWERED;
    }
    cdist__cc_frame_ring(&s->f, &pb->A, pb->CB, &pb->B);
    s->k = (cdist__cc_sink){.f = &s->f, .best = b, .prune = 1, .unscale = pb->unscale, .swapped = pb->swapped,
                            .A = &pb->A, .B = &pb->B, .Fmin = INFINITY, .dmin = INFINITY, .rho_min = INFINITY};
    s->np = cdist__cc_parallel_critical(&s->f, s->tp);
    return s->f.quick ? CDIST__CC_SEARCH : CDIST__CC_ENGINE;
}

/* The robust method after its search (or without it): the closed forms of parallel planes, else
 * the root-isolation engine. */
cdist_status cdist__cc_robust_engine(cdist_query *q, cdist__cc_robust_state *s)
{
    cdist__cc_frame *fp = &s->f;
    cdist__cc_sink *k = &s->k;
    cdist__best *b = k->best;
    double Fmax;
    int np = s->np;
    if (np < 0) cdist__cc_frame_bounds(fp);
    if (np > 0) {
        /* Closed form; F's extremes are at rho's extremes (the first two angles). */
        Fmax = 0;
        for (int i = 0; i < np; i++) {
            cdist__cc_pt p;
            double c, sn;
            sincos(s->tp[i], &sn, &c);
            cdist__cc_eval_lean(fp, s->tp[i], c, sn, &p);
            if (p.F > Fmax) Fmax = p.F;
            cdist__cc_pair_at(fp, s->tp[i], k);
        }
    } else {
        cdist__cc_scan(fp, k, &Fmax);
    }
    /* F' never went from - to +: F is constant to rounding; any point is a closest one. */
    if (b->n == 0 && isfinite(k->Fmin)) cdist__cc_pair_at(fp, k->tmin, k);
    if (b->n == 0 || !isfinite(k->dmin)) return cdist__fail(q, CDIST_ERR_INTERNAL, "circle-circle: no minimum found");
    cdist__cc_settle_d2(fp, k);
    /* (a) F constant on A; (b) the closest point of A on B's axis. */
    if (sqrt(Fmax) - k->dmin <= CD_CC_EQUI_ULPS * DBL_EPSILON * fp->L) b->equidistant = 1;
    if (k->rho_min <= CD_CC_AXIS_ULPS * fp->epsL * cdist__fmin(1.0, fp->s / fp->L)) b->equidistant = 1;
    return CDIST_OK;
}

/* The robust method (see the header comment). */
cdist_status cdist__cc_robust(cdist_query *q, const cdist__circle *c0, const cdist__circle *c1, cdist__best *b)
{
    cdist__cc_robust_state s;
    int next = cdist__cc_robust_start(c0, c1, b, &s);
    if (next == CDIST__CC_ANSWERED) return CDIST_OK;
    double tq, cq, sq;
    if (next == CDIST__CC_SEARCH && cdist__cc_quick(&s.f, &tq, &cq, &sq)) {
        /* One certified minimum, not tiny: its pair. Neither equidistance test of the engine can
         * hold: (a) F rises by the certificate's margin elsewhere, and (b) the convex basin keeps
         * B's axis more than 3 W1 h >= 2e-3 R away (ck_convex), far above its threshold. */
        cdist__cc_pair_final(&s.f, tq, cq, sq, &s.k);
        return CDIST_OK;
    }
    return cdist__cc_robust_engine(q, &s);
}
