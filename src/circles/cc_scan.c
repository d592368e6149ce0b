/* SPDX-License-Identifier: MIT */
/* The scan of the circle-circle engine (docs/circles.md): [-pi, pi) subdivided until every
 * interval is certified, every critical bracket of F refined (Newton/bisection on F') and handed
 * to the sink. */
#include <math.h>

#include "circles/circles-priv.h"

#define CC_EVAL_BUDGET 48 /* per subdivided interval */
#define CC_MAX_LEVEL 31 /* the scan's deepest level (cdist__cc_half_sec) */
#define CC_STACK 32 /* > the deepest level; grid intervals: widths 0.2 down to 2^-30 take 28 levels */

/* F'/2, F''/2 and rho only (for the refinement). */
static void cc_deriv(const cdist__cc_frame *f, double c, double s, double *F1, double *F2, double *rho)
{
    cdist__ring_val v;
    cdist__ring_eval(&f->rg, f->s, c, s, 2, &v);
    *F1 = v.F1;
    *F2 = v.F2;
    *rho = v.rho;
}

/* A root of F' in [a, b] where F'(a) and F'(b) have opposite signs (dir = +1 for (-,+), -1 for
 * (+,-)): safeguarded Newton on the true F', falling back to bisection. */
static double refine(const cdist__cc_frame *f, const cdist__cc_pt *a, const cdist__cc_pt *b, int dir)
{
    double lo = a->t, hi = b->t; /* dir * F'(lo) < 0 <= dir * F'(hi) */
    double fa = dir * a->F1, fb = dir * b->F1;
    if (fb == 0.0) return hi; /* the bracket's end is the root (a partition point on a symmetry) */
    /* Start from the secant point of the bracket. */
    double x = (fb > fa) ? lo + (hi - lo) * (-fa / (fb - fa)) : 0.5 * (lo + hi);
    if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
    double dxold = hi - lo;
    for (int it = 0; it < 100; it++) {
        double c, s, F1, F2, rho;
        sincos(x, &s, &c);
        cc_deriv(f, c, s, &F1, &F2, &rho);
        F1 *= dir;
        F2 *= dir;
        if (F1 == 0.0) return x;
        if (F1 < 0) lo = x;
        else hi = x;
        double step = F1 / F2;
        /* Converged: the Newton step is below the resolution of x. */
        if (F2 > 0 && fabs(step) <= 2 * DBL_EPSILON * cdist__fmax(1.0, fabs(x))) return x;
        double xn = x - step;
        int newton = 1;
        if (!(F2 > 0) || !(xn > lo && xn < hi) || fabs(2 * (x - xn)) > dxold) {
            xn = 0.5 * (lo + hi);
            newton = 0;
        }
        double dx = fabs(xn - x);
        /* Quadratic convergence: after a Newton step dx the error is about dx^2 / l, l the width
         * of F's features, min(1, rho / W1) rad (each derivative of rho = |w| brings W1 / rho):
         * below rounding by CD_CC_REFINE_QUAD. Not a fixed cut of dx: beside a tiny B the
         * minimum sits at rho ~ s, and dx <= 1e-9 left it 5e-12 rad off (tolerances.h). */
        if (newton && dx * dx * cdist__fmax(1.0, f->W1 / rho) <= CD_CC_REFINE_QUAD) return xn;
        dxold = dx;
        if (dx <= 4 * DBL_EPSILON || hi - lo <= 4 * DBL_EPSILON) return xn;
        x = xn;
    }
    return x;
}

double cdist__cc_emit(cdist__cc_sink *k, const cdist__cc_pt *a, const cdist__cc_pt *b)
{
    int dir = 0;
    if (a->F1 < 0 && b->F1 >= 0) dir = 1;
    else if (k->want_max && a->F1 > 0 && b->F1 <= 0) dir = -1;
    if (!dir) return NAN;
    double t = refine(k->f, a, b, dir);
    if (dir == k->skip_dir && fabs(t - k->skip_t) <= CD_CC_SAME_ROOT_ULPS * DBL_EPSILON * cdist__fmax(1.0, fabs(t))) {
        k->skip_dir = 0;
        return NAN;
    }
    if (!k->best) {
        double ta = cdist__cc_param(t);
        if (k->count < k->cap) k->out[k->count] = ta;
        k->count++;
        cdist__cc_pt p;
        double c, s;
        sincos(t, &s, &c);
        cdist__cc_eval_lean(k->f, t, c, s, &p);
        double d = sqrt(p.F);
        if (d < k->dmin) k->dmin = d;
    } else {
        cdist__cc_pair_at(k->f, t, k);
    }
    return t;
}

/* The scan's own state that the subdivision of its initial intervals reads: the smallest sampled
 * distance (at the initial points) and the near-crossing windows (centres, core half-widths) it
 * leaves to their grids. */
typedef struct scan_state {
    double dbest;
    int nk;
    double tk[2], core[2];
} scan_state;

/* 1 / (2 cos(w / 2)) of a piece of width w at `level` (below). */
CD_INLINE double half_secant(const scan_state *sc, int level, double w)
{
    return sc ? cdist__cc_half_sec[cdist__cc_hs_index(level)] : cdist__cc_half_secant(w);
}

/* Subdivision of [a, b] until each piece is pruned, certified or a leaf (its F' sign pair
 * emitted), sampled past the budget of evaluations. Depth-first, left to right, so consecutive
 * leaves share their endpoints (one value per point: a sign read at rounding level still
 * brackets every transition exactly once): the current interval is refined in place, right
 * halves wait on the stack. Points are referred to, never copied: the midpoints in pool[]. With
 * sc, [a, b] is an initial interval of the scan: dyadic pieces (half secants from
 * cdist__cc_half_sec by level), pruned against the initial samples, skipped inside the windows.
 * Without, an interval of a near-crossing grid: any width, pruned against every sample so far.
 * Inlined into the scan, where sc is known. */
CD_INLINE void subdivide(const cdist__cc_frame *f, cdist__cc_sink *k, cdist__cc_pt *a, cdist__cc_pt *b, double *Fmax,
                         cdist__cc_deferred *df, const scan_state *sc)
{
    struct {
        cdist__cc_pt *b;
        int level;
    } st[CC_STACK];
    cdist__cc_pt pool[CC_EVAL_BUDGET];
    int level = 0, sp = 0, evals = 0;
    for (;;) {
        double w = b->t - a->t, hs = half_secant(sc, level, w);
        /* Pruning (robust and minima modes): the distance is R-Lipschitz in the angle, so on
         * [a, b] it is at least (d(a) + d(b) - R w) / 2, and F is at least the hull bound;
         * above the attained distance (a sample or a refined minimum) by more than a tie,
         * the interval holds no closest pair, not even a tied one. */
        double dth = cdist__fmin(sc ? sc->dbest : sqrt(k->Fmin), k->dmin) * (1 + 8 * DBL_EPSILON) + CD_TIE_ULPS * DBL_EPSILON * f->L;
        int done = k->prune && (0.5 * (a->d + b->d - f->R * w) > dth ||
                                ((!sc || level < CC_MAX_LEVEL) && cdist__cc_hull_bound(f, a, b, hs) > dth * dth));
        for (int j = 0; sc && j < sc->nk && !done; j++) {
            /* within twice a near-crossing's core: the geometric grid covers it */
            double lo = remainder(a->t - sc->tk[j], 2 * M_PI), hi = lo + w;
            done = lo >= -2 * sc->core[j] && hi <= 2 * sc->core[j];
        }
        if (!done) {
            /* A grid interval reaching B's axis (to rounding: the grid records those clear of
             * it) is a leaf: the F certificates need rho > 0. */
            int leaf = w <= CD_CC_MIN_WIDTH || sp + 1 >= CC_STACK ||
                       (sc ? level >= CC_MAX_LEVEL : 0.5 * (a->rho + b->rho - f->W1 * w) <= 0) ||
                       cdist__cc_certified(f, a, b) || cdist__cc_monotone(f, a, b) || cdist__cc_convex(f, a, b);
            if (leaf) {
                cdist__cc_emit(k, a, b);
            } else if (evals >= CC_EVAL_BUDGET) {
                /* Past the budget (multiple roots of H at rounding level: tangencies, A passing
                 * within rounding of B's axis) the rest is sampled, keeping the resolution
                 * already reached around the trouble spot. */
                cdist__cc_emit_sampled(f, k, a, b, Fmax, df);
            } else {
                /* Midpoint from the endpoint cosines/sines: (a + b) / (2 cos(w / 2)). */
                cdist__cc_pt *mid = &pool[evals++];
                cdist__cc_eval_lean(f, 0.5 * (a->t + b->t), (a->c + b->c) * hs, (a->s + b->s) * hs, mid);
                cdist__cc_track(k, mid, Fmax);
                level++;
                st[sp].b = b;
                st[sp++].level = level;
                b = mid;
                continue;
            }
        }
        if (sp == 0) break;
        a = b;
        b = st[--sp].b;
        level = st[sp].level;
    }
}

void cdist__cc_subdivide_grid(const cdist__cc_frame *f, cdist__cc_sink *k, cdist__cc_pt *a, cdist__cc_pt *b,
                              double *Fmax, cdist__cc_deferred *df)
{
    subdivide(f, k, a, b, Fmax, df, NULL);
}

/* Walks [-pi, pi) (see the header comment) and hands every critical bracket to the sink.
 * Fmax: largest F at the partition points. Returns 1 when the certification gave up and the
 * sink does not allow the dense scan (nothing was emitted then), else 0. */
int cdist__cc_scan(const cdist__cc_frame *f, cdist__cc_sink *k, double *Fmax)
{
    *Fmax = 0;
    cdist__cc_pt init[CC_INIT_INTERVALS + 1];
    /* cos and sin of -pi + i pi / 8 (exact to rounding). */
    static const double ic[16] = {-1, -0.92387953251128674, -0.70710678118654757, -0.38268343236508978, 0,
                                  0.38268343236508978, 0.70710678118654757, 0.92387953251128674, 1,
                                  0.92387953251128674, 0.70710678118654757, 0.38268343236508978, 0,
                                  -0.38268343236508978, -0.70710678118654757, -0.92387953251128674};
    for (int i = 0; i < CC_INIT_INTERVALS; i++) {
        double t = -M_PI + i * (2 * M_PI / CC_INIT_INTERVALS);
        int j = i * 16 / CC_INIT_INTERVALS;
        cdist__cc_eval_lean(f, t, ic[j], -ic[(j + 4) % 16], &init[i]);
    }
    init[CC_INIT_INTERVALS] = init[0];
    init[CC_INIT_INTERVALS].t = M_PI;
    /* H vanishing to rounding (coaxial circles, constant F): certificates are meaningless. When
     * the samples show F constant to the equidistance tolerance, one of them is the answer. */
    if (f->Hc <= 16 * f->eH) {
        double lo = INFINITY, hi = 0;
        int arg = 0;
        for (int i = 0; i < CC_INIT_INTERVALS; i++) {
            if (init[i].F < lo) lo = init[i].F, arg = i;
            if (init[i].F > hi) hi = init[i].F;
        }
        if (sqrt(hi) - sqrt(lo) <= CD_CC_EQUI_ULPS * DBL_EPSILON * f->L) {
            *Fmax = hi;
            k->Fmin = lo;
            k->tmin = init[arg].t;
            return 0;
        }
        cdist__cc_scan_dense(f, k, Fmax);
        return 0;
    }

    scan_state sc;
    cdist__cc_deferred deferred;
    deferred.n = 0;
    cdist__cc_kink_rec krec;
    krec.n = 0;
    sc.dbest = INFINITY;
    for (int i = 0; i < CC_INIT_INTERVALS; i++) {
        if (init[i].d < sc.dbest) sc.dbest = init[i].d;
        cdist__cc_track(k, &init[i], Fmax);
    }
    sc.nk = cdist__cc_near_kinks(f, init, sc.tk);
    for (int i = 0; i < sc.nk; i++) {
        sc.core[i] = cdist__cc_kink_core(f, sc.tk[i]);
        /* Pruning (robust and minima modes): a window (covering the grid) whose hull bound lies
         * above the attained distance needs no grid (near-touching linked circles: the crossing
         * is far above). */
        double dth = sc.dbest * (1 + 8 * DBL_EPSILON) + CD_TIE_ULPS * DBL_EPSILON * f->L;
        if (k->prune && cdist__cc_window_hull_bound(f, sc.tk[i], 2 * sc.core[i]) > dth * dth) continue;
        cdist__cc_scan_kink(f, k, sc.tk[i], sc.core[i], Fmax, &deferred, &krec);
    }
    /* a cluster of roots exhausts the budget of its own interval only */
    for (int i = 0; i < CC_INIT_INTERVALS; i++) subdivide(f, k, &init[i], &init[i + 1], Fmax, &deferred, &sc);
    cdist__cc_kink_recheck(f, k, &krec, Fmax, &deferred);
    cdist__cc_deferred_offer(f, k, &deferred);
    return 0;
}
