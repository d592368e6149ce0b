/* SPDX-License-Identifier: MIT */
/* Circle to circle: public entry points, the one scaling rule of the family, method dispatch
 * (AUTO = the robust method of cc_robust.c, also the fallback of the polynomial and iteration
 * methods), and the method-independent equidistance tests and same-basin filter described in
 * docs/circles.md. */
#include <math.h>
#include <stdio.h>

#include "base/point_circle.h"
#include "circles/circles-priv.h"

/* Distance from X to circle c (closed form, |N x D| for the axis distance). */
static double pc_dist(vec3 X, const cdist__circle *c, double *rho_out)
{
    cdist__pc_parts e = cdist__point_circle(c->n, v_sub(X, c->c), c->r);
    if (rho_out) *rho_out = e.rho;
    return sqrt(e.d2);
}

/* The equidistance tests (a) and (b) of the header comment, method independent, applied to the
 * answer of the polynomial and iteration methods: (b) a closest point on the other circle's
 * axis; (a) 16 equally spaced points of either circle all at the minimum distance (the scan
 * stops at the first point that is not, so a generic query pays two evaluations). */
static void cc_equidistant_post(const cdist__circle *c0, const cdist__circle *c1, cdist__best *b)
{
    if (b->equidistant || b->n == 0) return;
    const cdist__circle *cs[2] = {c0, c1};
    double d = sqrt(b->c[0].d2), Cn = v_norm(v_sub(c1->c, c0->c));
    double L = fmax(fmax(c0->r, c1->r), Cn), tol = CD_CC_EQUI_ULPS * DBL_EPSILON * L;
    for (int side = 0; side < 2; side++) {
        const cdist__circle *me = cs[side], *other = cs[1 - side];
        if (other->r > 0 && me->r >= 0) {
            double rho;
            pc_dist(b->c[0].p[side], other, &rho);
            if (rho <= CD_CC_AXIS_ULPS * DBL_EPSILON * (me->r + other->r + Cn) * fmin(1.0, other->r / L)) {
                b->equidistant = 1;
                return;
            }
        }
        if (me->r == 0) continue;
        int j;
        for (j = 0; j < 16; j++) {
            double t = j * (M_PI / 8), c = cos(t), sn = sin(t);
            vec3 X = v_add(me->c, v_add(v_scale(me->r * c, me->u), v_scale(me->r * sn, me->v)));
            if (fabs(pc_dist(X, other, NULL) - d) > tol) break;
        }
        if (j == 16) {
            b->equidistant = 1;
            return;
        }
    }
}

/* Whether both arcs of circle c between the points at angles a and b rise above the tie level
 * (sampled at their midpoints) as seen from the other circle: then a and b are separate minima. */
static int arcs_rise(const cdist__circle *c, const cdist__circle *other, double a, double b, double dbest, double tie)
{
    if (isnan(a) || isnan(b)) return 0;
    double mid = b + 0.5 * remainder(a - b, 2.0 * M_PI);
    for (int k = 0; k < 2; k++) {
        double t = mid + k * M_PI;
        vec3 X = v_add(c->c, v_add(v_scale(c->r * cos(t), c->u), v_scale(c->r * sin(t), c->v)));
        if (!(pc_dist(X, other, NULL) - dbest > tie)) return 0;
    }
    return 1;
}

/* Method independent: two tied candidates are two closest pairs only when they are separate
 * minima, i.e. the distance rises between them along both arcs of the first circle or along both
 * arcs of the second. Otherwise they are two points of one flat minimum (e.g. circles in
 * parallel planes whose projections touch, where F is flat to fourth order) and the best
 * represents it. */
static void cc_same_basin_filter(const cdist__circle *c0, const cdist__circle *c1, cdist__best *b)
{
    double tie = cdist__best_tie_tol(b);
    while (b->n >= 2 && !cdist__best_is_equidistant(b)) {
        double dbest = sqrt(b->c[0].d2);
        if (sqrt(b->c[1].d2) - dbest > tie) return;
        const cdist__cand *x = &b->c[0], *y = &b->c[1];
        double a0 = cdist__circle_angle(c0, v_sub(x->p[0], c0->c)), b0 = cdist__circle_angle(c0, v_sub(y->p[0], c0->c));
        double a1 = cdist__circle_angle(c1, v_sub(x->p[1], c1->c)), b1 = cdist__circle_angle(c1, v_sub(y->p[1], c1->c));
        if (arcs_rise(c0, c1, a0, b0, dbest, tie) || arcs_rise(c1, c0, a1, b1, dbest, tie)) return;
        for (int j = 1; j + 1 < b->n; j++) b->c[j] = b->c[j + 1];
        b->n--;
    }
}

/* Runs `method`; the robust method answers AUTO and is the fallback of a method that fails.
 * *answered: the method that produced the result. */
static cdist_status cc_core(cdist_query *q, cdist_method method, const cdist__circle *c0, const cdist__circle *c1,
                            cdist__best *b, int *iterations, cdist_method *answered)
{
    if (iterations) *iterations = 0;
    cdist_status st = CDIST_ERR_INTERNAL;
    if (method == CDIST_METHOD_POLYNOMIAL) st = cdist__cc_polynomial(q, c0, c1, b);
    else if (method == CDIST_METHOD_ITERATION) st = cdist__cc_iteration(q, c0, c1, b, iterations);
    *answered = method;
    if (method == CDIST_METHOD_AUTO || method == CDIST_METHOD_ROBUST || st != CDIST_OK) {
        /* AUTO is the robust method (measured fastest and as exact); it is also the fallback. */
        cdist__best_init(b, b->scale);
        if (iterations) *iterations = 0;
        *answered = CDIST_METHOD_ROBUST;
        st = cdist__cc_robust(q, c0, c1, b);
    } else {
        cc_equidistant_post(c0, c1, b);
    }
    if (st == CDIST_OK) cc_same_basin_filter(c0, c1, b);
    return st;
}

CD_FMA_CLONES int cdist__circles_frame(cdist__circle *a, cdist__circle *b, vec3 *offset, cdist__best *best)
{
    *offset = a->c;
    a->c = v3(0, 0, 0);
    b->c = v_sub(b->c, *offset);
    double down, up;
    int e = cdist__circles_scale(cdist__fmax(cdist__fmax(a->r, b->r), v_maxabs(b->c)), 0, &down, &up);
    a->r *= down;
    b->r *= down;
    b->c = v_scale(down, b->c);
    cdist__best_init(best, cdist__fmax(cdist__fmax(a->r, b->r), v_norm(b->c)));
    return e;
}

void cdist__circles_result(const cdist__best *best, int swap, int e, vec3 offset, cdist_result *r)
{
    cdist__best_to_result(best, v3(0, 0, 0), swap, r);
    cdist__result_finish(r, r->num_pairs);
    /* x * 2^e is x scaled by 2^e correctly rounded, like ldexp, when 2^e is a double (e is
     * within CD_SCALE_MAX_EXP); 2e may not be */
    double up = cdist__pow2(e);
    r->distance *= up;
    r->sqr_distance = 2 * e >= -1022 && 2 * e <= 1023 ? r->sqr_distance * cdist__pow2(2 * e) : ldexp(r->sqr_distance, 2 * e);
    for (int i = 0; i < r->num_pairs; i++)
        for (int j = 0; j < 2; j++) r->pairs[i].point[j] = v_add(v_scale(up, r->pairs[i].point[j]), offset);
}

/* r written in full from the collector of the scaled problem (cdist__circles_frame's e and
 * offset). */
static cdist_status cc_write(cdist_query *q, const cdist__best *best, int swap, int e, vec3 offset, int iterations,
                             cdist_result *r)
{
    if (best->n == 0) return cdist__fail(q, CDIST_ERR_INTERNAL, "circle-circle found no candidate");
    cdist__circles_result(best, swap, e, offset, r);
    r->iterations = iterations;
    return CDIST_OK;
}

/* The scaled problem (a at the origin): the core, then r written in full. swap: a and b are
 * the caller's second and first circles. */
static cdist_status cc_query(cdist_query *q, cdist_method method, cdist__circle a, cdist__circle b, int swap,
                             cdist_result *r, cdist_method *answered)
{
    vec3 offset;
    cdist__best best;
    int e = cdist__circles_frame(&a, &b, &offset, &best);
    int iterations = 0;
    cdist_status st = cc_core(q, method, &a, &b, &best, &iterations, answered);
    return st ? st : cc_write(q, &best, swap, e, offset, iterations, r);
}

/* FMA clones: the inlined checks and bases are chains of fma() calls outside a clone. */
CD_FMA_CLONES int cdist__cc_staged_start(cdist_query *q, const cdist_circle *c0, const cdist_circle *c1, cdist__cc_staged *s)
{
    if (!q) return 0;
    cdist_method m = cdist__family_method(q, CD_FAM_CIRCLE_CIRCLE);
    if (m != CDIST_METHOD_AUTO && m != CDIST_METHOD_ROBUST) return 0;
    /* the fast check accepts what cdist__check_circle accepts, with the same circle */
    if (!cdist__circle_fast_basis(q->unit_tol, c0, &s->a) || !cdist__circle_fast_basis(q->unit_tol, c1, &s->b)) return 0;
    s->e = cdist__circles_frame(&s->a, &s->b, &s->offset, &s->best); /* and s->best empty */
    return cdist__cc_robust_start(&s->a, &s->b, &s->best, &s->rs) == CDIST__CC_SEARCH;
}

CD_FMA_CLONES cdist_status cdist__cc_staged_finish(cdist_query *q, cdist__cc_staged *s, int found, double t, double c, double sn,
                                     cdist_result *r)
{
    cdist_status st = cdist__enter(q, r);
    if (st) return st;
    if (found) cdist__cc_pair_final(&s->rs.f, t, c, sn, &s->rs.k);
    else st = cdist__cc_robust_engine(q, &s->rs);
    if (st == CDIST_OK) {
        cc_same_basin_filter(&s->a, &s->b, &s->best);
        st = cc_write(q, &s->best, 0, s->e, s->offset, 0, r);
    }
    return cdist__leave(q, r, st, CDIST_METHOD_ROBUST);
}

cdist_status cdist_circle_circle(cdist_query *q, const cdist_circle *c0, const cdist_circle *c1, cdist_result *r)
{
    cdist_status st = cdist__enter(q, r);
    if (st) return st;
    cdist__circle a, b;
    cdist_method answered = CDIST_METHOD_ROBUST;
    if (!(st = cdist__check_circle(q, c0, "first circle", &a)) && !(st = cdist__check_circle(q, c1, "second circle", &b))) {
        /* The robust method (AUTO) runs the same computation in both orders by construction
         * (docs/circles.md); the polynomial and iteration methods are given the circles in
         * lexicographic order, so that their ties, pair counts and equidistant decisions do not
         * depend on the argument order either. */
        cdist_method m = cdist__family_method(q, CD_FAM_CIRCLE_CIRCLE);
        int swap = (m == CDIST_METHOD_POLYNOMIAL || m == CDIST_METHOD_ITERATION) && cdist__circle_less(c1, c0);
        st = swap ? cc_query(q, m, b, a, 1, r, &answered) : cc_query(q, m, a, b, 0, r, &answered);
    }
    return cdist__leave(q, r, st, answered);
}
