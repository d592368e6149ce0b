/* SPDX-License-Identifier: MIT */
/* The regions of the circle-circle scan where H cannot be certified (docs/circles.md): near
 * crossings of B's axis (a geometric grid), intervals past their evaluation budget and the dense
 * fallback (sampled F' signs), each polished by a minimisation of F itself. */
#include <math.h>

#include "circles/circles-priv.h"

#define CC_DENSE_SAMPLES 512
#define CC_MIN_ITER 100 /* Brent minimisation steps (a golden step shrinks by 0.618: 100 reach any width) */

/* cos and sin of the next point of an even grid: exact (sincos) when `exact`, else the previous
 * pair (*s, *c) rotated by the step (cos ch, sin sh). Rotation drifts by an ulp or so a step. */
static inline void grid_sincos(double t, int exact, double ch, double sh, double *s, double *c)
{
    if (exact) {
        sincos(t, s, c);
    } else {
        double cn = *c * ch - *s * sh;
        *s = *s * ch + *c * sh;
        *c = cn;
    }
}

/* F on a window around tc, whose cosine and sine are known: cos and sin of t by the addition
 * theorem with small_sincos of the offset (no transcendental call per step). */
typedef struct cc_window {
    const cdist__cc_frame *f;
    double tc, cc, sc;
} cc_window;

static double cc_F_at(const void *ctx, double t)
{
    const cc_window *wd = ctx;
    double h = t - wd->tc, c, s;
    if (fabs(h) <= 0.1) {
        double ch, sh;
        cdist__cc_small_sincos(h, &sh, &ch);
        c = wd->cc * ch - wd->sc * sh;
        s = wd->sc * ch + wd->cc * sh;
    } else {
        sincos(t, &s, &c);
    }
    cdist__cc_pt p;
    cdist__cc_eval_lean(wd->f, t, c, s, &p);
    return p.F;
}

/* Brent minimisation of F on [lo, hi] (src/base/roots.h); offers the best point (robust mode).
 * F is computed from accurate rho - s and h, so it keeps its relative accuracy even where F' is
 * noise, and near a minimum it is smooth at the scale of the bracket (parabolic steps). */
static void min_offer(const cdist__cc_frame *f, cdist__cc_sink *k, double lo, double hi)
{
    cc_window wd = {f, 0.5 * (lo + hi), 0, 0};
    sincos(wd.tc, &wd.sc, &wd.cc);
    double t = cdist__min_brent(cc_F_at, &wd, lo, hi, CD_ROOT_REL_ULPS * DBL_EPSILON, CD_ROOT_ABS, CC_MIN_ITER, NULL);
    if (t == t) cdist__cc_pair_at(f, t, k);
}

/* Dense sampling fallback: F' signs on CC_DENSE_SAMPLES points. */
void cdist__cc_scan_dense(const cdist__cc_frame *f, cdist__cc_sink *k, double *Fmax)
{
    k->sampled = 1;
    cdist__cc_pt first = {0}, prev = {0}, cur;
    double step = 2 * M_PI / CC_DENSE_SAMPLES, ch, sh, c = 0, s = 0;
    sincos(step, &sh, &ch);
    for (int i = 0; i <= CC_DENSE_SAMPLES; i++) {
        if (i == CC_DENSE_SAMPLES) {
            cur = first;
            cur.t = M_PI;
        } else {
            /* cos and sin by rotation, re-synchronised every 8 steps (drift of a few ulps) */
            double t = -M_PI + i * step;
            grid_sincos(t, i % 8 == 0, ch, sh, &s, &c);
            cdist__cc_eval_lean(f, t, c, s, &cur);
            cdist__cc_track(k, &cur, Fmax);
        }
        if (i == 0) first = cur;
        else cdist__cc_emit(k, &prev, &cur);
        prev = cur;
    }
    /* F nearly flat (why we are here): also search F itself around the lowest sample. */
    if (k->best && isfinite(k->Fmin)) min_offer(f, k, k->tmin - step, k->tmin + step);
}

/* Near-crossings of B's axis: the minima of Q = |w|^2 = rho^2 (a trigonometric polynomial of
 * degree 2, at most two minima) with rho <= CD_CC_KINK_REL L. There F = smooth - 2 s rho has features
 * of width about rho / |w'| (A crossing the axis) or sqrt(rho / curvature) (A tangent to it),
 * where H is below its rounding and cannot be certified: those windows are scanned on a
 * geometric grid instead (see scan). Writes the angles, returns the count. */
int cdist__cc_near_kinks(const cdist__cc_frame *f, const cdist__cc_pt *init, double *tk)
{
    enum { N = CC_INIT_INTERVALS };
    double thr = CD_CC_KINK_REL * f->L;
    int n = 0;
    for (int i = 0; i < N && n < 2; i++) {
        int ip = (i + N - 1) % N, in = (i + 1) % N;
        if (!(init[i].Q <= init[ip].Q && init[i].Q < init[in].Q)) continue;
        /* Bisection on g = Q'/2 over [t(i-1), t(i+1)] with the midpoints' cosines and sines from
         * the ends (no transcendental call); stop as soon as the W1-Lipschitz bound of rho
         * shows the bracket clear of the axis (a generic query stops after a few steps). */
        if (!(init[ip].g < 0 && init[in].g > 0)) continue;
        double lo = init[ip].t, hi = lo + 2 * (2 * M_PI / N);
        double cl = init[ip].c, sl = init[ip].s, ch = init[in].c, sh = init[in].s;
        double width = 2 * (2 * M_PI / N), rho = 0; /* twice the width of cdist__cc_half_sec[0] */
        int miss = 0;
        for (int it = 0; it < 52; it++) {
            /* 1 / (2 cos(width / 2)); width = 2 pi / N * 2^(1 - it) */
            int hi_ = it + CC_LEVEL0 - 1; /* width / 2 = pi / 8 / 2^hi_ */
            double hc = hi_ < 0 ? 0.70710678118654752 /* 0.5 / cos(pi / 4) */ : cdist__cc_half_sec[cdist__cc_hs_index(it - 1)];
            double cm = (cl + ch) * hc, sm = (sl + sh) * hc;
            cdist__ring_val v;
            cdist__ring_eval(&f->rg, f->s, cm, sm, 1, &v);
            rho = v.rho;
            if (rho - 0.5 * f->W1 * width > thr) {
                miss = 1;
                break;
            }
            double m = 0.5 * (lo + hi);
            if (v.g < 0) lo = m, cl = cm, sl = sm;
            else hi = m, ch = cm, sh = sm;
            width *= 0.5;
        }
        if (!miss && rho <= thr) tk[n++] = remainder(0.5 * (lo + hi), 2 * M_PI);
    }
    return n;
}

/* Half-width of the window around a near-crossing that only the geometric grid covers. */
double cdist__cc_kink_core(const cdist__cc_frame *f, double t)
{
    double c, s;
    sincos(t, &s, &c);
    cdist__ring_val v;
    cdist__ring_eval(&f->rg, f->s, c, s, 0, &v);
    double r = sqrt(v.rho / f->L);
    double core = cdist__fmin(CD_CC_KINK_CORE_MAX, CD_CC_KINK_CORE_GAIN * r + CD_CC_KINK_CORE_MIN);
    /* A tangent to B's axis keeps rho tiny over a wider window (rho ~ rho0 + k x^2 / 2), where H
     * stays below its rounding too: widen the core (doubling) while rho at both of its ends is
     * still below the near-crossing threshold. */
    double thr = CD_CC_KINK_REL * f->L;
    while (core < CD_CC_KINK_CORE_MAX) {
        double sh, ch;
        cdist__cc_small_sincos(core, &sh, &ch);
        cdist__ring_val lo, hi;
        cdist__ring_eval(&f->rg, f->s, c * ch + s * sh, s * ch - c * sh, 0, &lo);
        cdist__ring_eval(&f->rg, f->s, c * ch - s * sh, s * ch + c * sh, 0, &hi);
        if (cdist__fmax(lo.rho, hi.rho) > thr) break;
        core = cdist__fmin(CD_CC_KINK_CORE_MAX, 2 * core);
    }
    return core;
}

/* The deferred neighbourhoods (cdist__cc_deferred) whose Lipschitz bound leaves room below the
 * attained minimum, minimised. */
void cdist__cc_deferred_offer(const cdist__cc_frame *f, cdist__cc_sink *k, const cdist__cc_deferred *df)
{
    double dbest = cdist__fmin(sqrt(k->Fmin), k->dmin);
    double tie = CD_TIE_ULPS * DBL_EPSILON * f->L + 8 * DBL_EPSILON * (f->L + dbest);
    for (int i = 0; i < df->n; i++)
        if (df->d[i] - f->R * df->hw[i] <= dbest + tie) min_offer(f, k, df->t[i] - df->hw[i], df->t[i] + df->hw[i]);
}

/* The recorded grid intervals (cdist__cc_kink_rec), after the scan: those the Lipschitz bound
 * does not prune are evaluated again (the grid's formula, so the same values), and subdivided
 * unless certified. Their own F' sign pair was handed to the sink by the grid already, and the
 * subdivision's leaves, which chain from a to b, bracket that root again. Where each emitted root
 * is an entry of the answer (critical and minima modes), the sink drops the one root of the
 * grid's direction that refines to the grid's root again: every root is listed once, the roots
 * the grid could not see still are (also in a leaf that holds more than one), and the grid's
 * refinement stays the one listed. The robust mode's collector merges two offers of one minimum
 * (it keeps the closer): in a rim-crossing dip, narrower than the features refine() sizes its
 * stopping rule for, the two refinements land ulps apart and either may be the closer, so
 * dropping one there would move answers in their last bits. Not dropped there. */
void cdist__cc_kink_recheck(const cdist__cc_frame *f, cdist__cc_sink *k, const cdist__cc_kink_rec *kr, double *Fmax,
                            cdist__cc_deferred *df)
{
    double tc = NAN, ct = 0, st = 0;
    for (int i = 0; i < kr->n; i++) {
        double w = kr->hb[i] - kr->ha[i];
        double dth = cdist__fmin(sqrt(k->Fmin), k->dmin) * (1 + 8 * DBL_EPSILON) + CD_TIE_ULPS * DBL_EPSILON * f->L;
        if (k->prune && 0.5 * (kr->da[i] + kr->db[i] - f->R * w) > dth) continue;
        if (kr->tc[i] != tc) {
            tc = kr->tc[i];
            sincos(tc, &st, &ct);
        }
        cdist__cc_pt a, b;
        double sh, ch;
        cdist__cc_small_sincos(kr->ha[i], &sh, &ch);
        cdist__cc_eval_lean(f, tc + kr->ha[i], ct * ch - st * sh, st * ch + ct * sh, &a);
        cdist__cc_small_sincos(kr->hb[i], &sh, &ch);
        cdist__cc_eval_lean(f, tc + kr->hb[i], ct * ch - st * sh, st * ch + ct * sh, &b);
        if ((k->prune && cdist__cc_hull_bound(f, &a, &b, cdist__cc_half_secant(b.t - a.t)) > dth * dth) ||
            cdist__cc_certified(f, &a, &b) || cdist__cc_monotone(f, &a, &b) || cdist__cc_convex(f, &a, &b))
            continue;
        k->skip_dir = k->best ? 0 : kr->dir[i];
        k->skip_t = kr->root[i];
        cdist__cc_subdivide_grid(f, k, &a, &b, Fmax, df);
        k->skip_dir = 0;
    }
}

/* The grid interval [a, b] = [t + ha, t + hb]: its F' sign pair emitted, and the interval recorded
 * for cdist__cc_kink_recheck when wider than CD_CC_MIN_WIDTH and certified clear of the axis (rho
 * is W1-Lipschitz; the F certificates need rho > 0): most of the grid is narrower or on the axis. */
static void kink_interval(cdist__cc_sink *k, cdist__cc_kink_rec *kr, double t, double ha, double hb,
                          const cdist__cc_pt *a, const cdist__cc_pt *b)
{
    double root = cdist__cc_emit(k, a, b);
    if (!(hb - ha > CD_CC_MIN_WIDTH && a->rho + b->rho > k->f->W1 * (hb - ha))) return;
    if (kr->n >= CC_KINK_REC) return; /* cannot happen: at most 2 windows of 2 x 65 intervals */
    kr->tc[kr->n] = t;
    kr->ha[kr->n] = ha;
    kr->hb[kr->n] = hb;
    kr->da[kr->n] = a->d;
    kr->db[kr->n] = b->d;
    kr->root[kr->n] = root;
    kr->dir[kr->n++] = root == root ? (a->F1 < 0 ? 1 : -1) : 0;
}

/* The geometric grid around a near-crossing t: t +- 0.1 * 2^-j down to the angular resolution
 * at t (offsets below 2 ulps of t name no new angle), and t, closed by t +- 2 core (the edges of
 * the window the scan leaves to the grid). Its intervals clear of the axis are recorded for
 * cdist__cc_kink_recheck; nearer the axis the grid's F' sign pairs and the polish below are all
 * there is (docs/circles.md). */
void cdist__cc_scan_kink(const cdist__cc_frame *f, cdist__cc_sink *k, double t, double core, double *Fmax,
                         cdist__cc_deferred *df, cdist__cc_kink_rec *kr)
{
    k->sampled = 1;
    enum { NG = 64 }; /* 0.1 * 2^-63 is below any angular resolution */
    cdist__cc_pt prev, cur;
    double ct, st;
    sincos(t, &st, &ct);
    int first = 1;
    /* The geometric offsets start at the first within twice the core. */
    int j0 = 0, j1 = NG;
    while (j0 < NG - 1 && ldexp(0.1, -j0) > 2 * core) j0++;
    double res = 4 * DBL_EPSILON * cdist__fmax(1.0, fabs(t));
    while (j1 > j0 + 1 && ldexp(0.1, -(j1 - 1)) < res) j1--;
    /* The window's edge, when the widest offset falls short of it (else no point: the scan
     * only covers intervals reaching beyond 2 core). */
    int edge = 2 * core > ldexp(0.1, -j0);
    double hp = 0; /* offset of prev */
    for (int side = -1; side <= 1; side += 2)
        for (int jj = j0 - edge; jj < j1; jj++) {
            int j = side < 0 ? jj : j1 - 1 - (jj - j0) - edge; /* increasing angle */
            double h = side * (j < j0 ? 2 * core : ldexp(0.1, -j)), ch, sh;
            if (side > 0 && jj == j0 - edge) {
                cdist__cc_eval_lean(f, t, ct, st, &cur);
                kink_interval(k, kr, t, hp, 0.0, &prev, &cur);
                prev = cur;
                hp = 0.0;
            }
            cdist__cc_small_sincos(h, &sh, &ch);
            cdist__cc_eval_lean(f, t + h, ct * ch - st * sh, st * ch + ct * sh, &cur);
            cdist__cc_track(k, &cur, Fmax);
            if (!first) kink_interval(k, kr, t, hp, h, &prev, &cur);
            first = 0;
            prev = cur;
            hp = h;
        }
    /* Within about sqrt(eps) of the crossing, F' = 2 (rho - s) w.w'/rho + ... carries the
     * relative rounding eps L / rho of w.w' / rho and its sign is unreliable; F itself is
     * accurate (d to eps L). Polish the lowest grid neighbourhood by a minimisation of F. */
    if (!k->best) return;
    /* Each side of the crossing separately (a minimum on either side: symmetric
     * configurations), over the core at least. */
    double hw = cdist__fmax(CD_CC_KINK_POLISH_MIN, 2 * core);
    cdist__cc_pt p;
    cdist__cc_eval_lean(f, t, ct, st, &p);
    for (int side = -1; side <= 1; side += 2) {
        double m = t + side * 0.5 * hw;
        if (df->n < CC_DEFER) {
            df->t[df->n] = m;
            df->hw[df->n] = 0.5 * hw;
            df->d[df->n++] = p.d;
        } else {
            min_offer(f, k, m - 0.5 * hw, m + 0.5 * hw);
        }
    }
}

/* An interval left uncertified when the evaluation budget ran out (a cluster of roots of H at
 * rounding level, where F is flat and may hold close minima): F' signs on a grid as fine as the
 * dense scan's and of at least 64 points, and in robust mode a minimisation of F
 * around the lowest grid point. */
void cdist__cc_emit_sampled(const cdist__cc_frame *f, cdist__cc_sink *k, const cdist__cc_pt *a, const cdist__cc_pt *b, double *Fmax,
                         cdist__cc_deferred *df)
{
    k->sampled = 1;
    double w = b->t - a->t;
    int n = (int)ceil(w / (2 * M_PI / CC_DENSE_SAMPLES));
    if (n < 64) n = 64;
    cdist__cc_pt prev = *a, cur;
    double Fbest = a->F, tbest = a->t;
    /* cos and sin on the grid by rotation from the last exact pair (re-synchronised every 8
     * steps, so the drift stays at a few ulps). */
    double ch, sh, c = a->c, s = a->s;
    cdist__cc_small_sincos(w / n, &sh, &ch);
    for (int j = 1; j < n; j++) {
        double t = a->t + w * j / n;
        grid_sincos(t, j % 8 == 0 || w / n > 0.1, ch, sh, &s, &c);
        cdist__cc_eval_lean(f, t, c, s, &cur);
        cdist__cc_track(k, &cur, Fmax);
        if (cur.F < Fbest) Fbest = cur.F, tbest = cur.t;
        cdist__cc_emit(k, &prev, &cur);
        prev = cur;
    }
    cdist__cc_emit(k, &prev, b);
    if (b->F < Fbest) tbest = b->t;
    if (!k->best) return;
    if (df->n < CC_DEFER) {
        df->t[df->n] = tbest;
        df->hw[df->n] = w / n;
        df->d[df->n++] = sqrt(cdist__fmin(Fbest, b->F));
    } else {
        min_offer(f, k, tbest - w / n, tbest + w / n);
    }
}

