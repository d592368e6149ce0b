/* SPDX-License-Identifier: MIT */
/* Private declarations of the circles family (src/circles): the trigonometric root-isolation
 * engine of circle-circle (docs/circles.md; cc_frame.c, cc_certify.c, cc_kink.c, cc_scan.c,
 * cc_pair.c) shared by the robust method
 * (cc_robust.c), the critical-angle service (cc_critical.c) and the dispatcher
 * (circle_circle.c). Everything is in the units of a problem scaled by cdist__circles_scale. */
#ifndef CDIST_CIRCLES_PRIV_H
#define CDIST_CIRCLES_PRIV_H

#include "internal.h"
#include "circles/ring_eval.h"

/* The parameterised circle A at the origin and the other circle B. */
typedef struct cdist__cc_frame {
    double R, s;       /* radii of A and B */
    vec3 u, v;         /* A's basis */
    vec3 C, m;         /* B's centre relative to A's centre, B's unit normal */
    cdist__ring rg;        /* w(t) = m x (P(t) - C) and h(t) = m.(P(t) - C) (ring_eval.h) */
    double Cu, Cv;     /* sigma = D.D' = R (Cu sin t - Cv cos t) */
    double M1, M2, M3; /* |H'| <= M1, |H''| <= M2, |H'''| <= M3 */
    double eH, eH1, eH2; /* rounding bounds of the computed H, H', H'' */
    double Hc;         /* sum of |Fourier coefficients| of H */
    double epsL;       /* eps * (R + |C|): absolute rounding of positions */
    double L;          /* problem scale max(R, s, |C|) */
    double Lw, W1, nga; /* magnitudes of the terms of w, of |w'|, |ga| (rounding bounds) */
    double Hh, Hc0;    /* |ha| + |hb| (bounds |h'|, |h''|) and |hc| */
    int parallel;      /* parallel planes (cdist__cc_parallel_critical answers) */
    int quick;         /* the certified search (cdist__cc_quick) is worth trying (ring_lanes.h) */
} cdist__cc_frame;

/* Values at one angle. */
typedef struct cdist__cc_pt {
    double t, c, s;
    int detail;   /* the certificates' values below are set (cc_certify.c computes them on demand) */
    double H, H1, H2; /* H, H', H'' */
    double eH, eH1, eH2; /* their rounding bounds at this point */
    double F1, eF1; /* F'/2 and its rounding bound */
    double F2, eF2; /* F''/2 and its rounding bound */
    double rho;   /* distance to B's axis */
    double F;     /* F */
    double d;     /* sqrt(F) */
    double Q, g;  /* rho^2 and w.w' */
} cdist__cc_pt;

/* Receiver of the critical points found by the scan. */
typedef struct cdist__cc_sink {
    const cdist__cc_frame *f;
    int want_max;   /* also report local maxima (critical-angle mode) */
    int prune;      /* drop intervals whose lower bound of the distance exceeds the attained one (dmin) */
    double *out;    /* critical mode: angles */
    int cap, count; /* critical mode: room and number found (may exceed cap) */
    cdist__best *best;  /* robust mode */
    int swapped;    /* robust mode: A is the second circle */
    const cdist__circle *A, *B;
    double unscale; /* robust mode: the factor undoing the problem's scaling */
    double tmin, Fmin; /* partition point with the smallest F */
    double dmin;  /* smallest refined distance */
    double rho_min; /* axis distance of the point giving dmin */
    int sampled;    /* some region was only sampled (emit_sampled, scan_kink, scan_dense) */
    int skip_dir;   /* 1 or -1: the next root of this direction refined to skip_t (CD_CC_SAME_ROOT_ULPS)
                     * is not emitted (0: none) */
    double skip_t;  /* (cdist__cc_kink_recheck: the root the grid already emitted) */
} cdist__cc_sink;

static inline double cdist__cc_dot3(vec3 a, vec3 b) { return cdist__ring_dot(a, b); }

/* The one evaluation of a point of the engine at angle t with (c, s) = (cos t, sin t): F, its
 * root d, F'/2, rho, Q, g (what pruning, bracketing and the sampled regions read). The
 * certificates' values (H's, F''s and the rounding bounds) come on demand, in cc_certify.c: most
 * intervals are pruned first. */
static inline void cdist__cc_eval_lean(const cdist__cc_frame *f, double t, double c, double s, cdist__cc_pt *p)
{
    cdist__ring_val v;
    cdist__ring_eval(&f->rg, f->s, c, s, 1, &v);
    p->t = t;
    p->c = c;
    p->s = s;
    p->detail = 0;
    p->rho = v.rho;
    p->F1 = v.F1;
    p->F = v.F;
    p->d = sqrt(v.F);
    p->Q = v.Q;
    p->g = v.g;
}

/* The squared distance from A's point at (c, sn) = (cos t, sin t) to B (radius s) as the robust
 * method reports it, from the ring rg of the pair (ring_eval.h; cc_search_body.h). The one formula
 * of the answer: of the robust method's (applied to the candidates it keeps,
 * cdist__cc_settle_d2) and of the batch kernel's (src/batch/cc_kernel.c).
 * Evaluated in double-double: its rounding (far below an ulp of the scale) then leaves the
 * answer depending on the angle only to second order at a minimum d* > 0 (by about
 * (R dt)^2 / (2 d*) for an angle error dt), so two searches settling on the same minimum report
 * the same distance to an ulp while d* is not tiny (the kernel leaves d* < 1e-12 of the scale,
 * touching or crossing circles, to the single query). */
double cdist__cc_point_d2(const cdist__ring *rg, double s, double c, double sn);

/* The one scaling rule of the family: the problem scale L (max of the radii and the centre
 * offset) times *down = 2^-e lies in [2^-half, 2^(1 - half)) ([1, 2) for half = 0, [0.5, 1) for
 * half = 1), *up = 2^e; returns e. Exact (powers of two): squares neither overflow nor underflow,
 * and answers scale back exactly. e is cdist__scale_exponent(L) + half, so clamped to
 * CD_SCALE_MAX_EXP (+ 1): an L outside [2^-1000, 2^1000) lands outside the range but far from
 * overflow and underflow. half = 1 for the robust engine (cdist__cc_prepare, the critical-angle
 * service): its rounding bounds and certificate thresholds are absolute in these units, so
 * moving its range would move results; half = 0 elsewhere (the frame of every query, the
 * polynomial and iteration methods). */
static inline int cdist__circles_scale(double L, int half, double *down, double *up)
{
    int e = cdist__scale_exponent(L) + half;
    *down = cdist__pow2(-e);
    *up = cdist__pow2(e);
    return e;
}

/* The reported parameter of an angle t on A in (-3 pi, 3 pi): t wrapped to (-pi, pi] (the
 * distance is recomputed at this value, cdist__cc_settle_d2, so the batch kernel uses it too). */
static inline double cdist__cc_param(double t)
{
    return (t <= -M_PI) ? t + 2 * M_PI : (t > M_PI ? t - 2 * M_PI : t);
}

/* The frame of A (parameterised, centre at the origin) and B (centre C relative to A's):
 * cdist__cc_frame_ring sets everything but the bounds of H (M1..M3, eH..eH2, Hc), which
 * cdist__cc_frame_bounds adds for cdist__cc_scan; cdist__cc_frame_init does both. */
void cdist__cc_frame_init(cdist__cc_frame *f, const cdist__circle *A, vec3 C, const cdist__circle *B);
void cdist__cc_frame_ring(cdist__cc_frame *f, const cdist__circle *A, vec3 C, const cdist__circle *B);
void cdist__cc_frame_bounds(cdist__cc_frame *f);
/* The certified search (cc_search.c, shared with the batch kernel) for the one pair of frame f (only
 * its ring part is read), with the angles in lanes: 1, the angle *t of the closest point on A
 * and its cosine *c and sine *s when the closest point is certified unique (every other region
 * of A at least CD_CCK_CERT_MARGIN farther in F) and the distance is not tiny
 * (>= sqrt(CD_CCK_MIN_F)); else 0 (then cdist__cc_scan decides). */
int cdist__cc_quick(const cdist__cc_frame *f, double *t, double *c, double *s);

/* The public entry of circle-disk and disk-disk: the handle taken, both objects validated
 * (named what0, what1), then query(q, a, b, swap, r, &used) with used the family's method and
 * swap 1 when c1 comes before c0 in lexicographic order (cdist__circle_less). */
typedef cdist_status (*cdist__circles_query_fn)(cdist_query *q, cdist__circle a, cdist__circle b, int swap,
                                                cdist_result *r, cdist_method *used);
cdist_status cdist__circles_entry(cdist_query *q, const cdist_circle *c0, const char *what0, const cdist_circle *c1,
                                  const char *what1, int family, cdist__circles_query_fn query, cdist_result *r);

/* The same search for circles c0 (parameterised) and c1 as given (no choice of the larger, any
 * centres), for circle-disk, whose rim needs only F's global minimum: cdist__cc_quick_frame
 * sets the frame *f of the pair scaled by *sc and returns whether the search is to run on it
 * (not when a radius is 0, nor where the frame's quick is 0); cdist__cc_quick_distance is the distance at the point (c, s) =
 * (cos t, sin t) of c0 it finds, in c0's units. */
int cdist__cc_quick_frame(const cdist__circle *c0, const cdist__circle *c1, cdist__cc_frame *f, double *sc);
double cdist__cc_quick_distance(const cdist__cc_frame *f, double sc, double c, double s);
/* The distance of cdist__cc_quick_distance from the squared distance d2 in the frame's units. */
static inline double cdist__cc_quick_unscale(double d2, double sc) { return sqrt(d2) / sc; }
/* Walks [-pi, pi) and hands every critical bracket of F to the sink (docs/circles.md). Fmax:
 * largest F seen at the partition points. */
int cdist__cc_scan(const cdist__cc_frame *f, cdist__cc_sink *k, double *Fmax);
/* The distances of the best candidate kept by the sink's collector (robust mode) and of those
 * that may tie with it, offered with the plain formula, recomputed by cdist__cc_point_d2 at
 * their angles on A (and re-ordered); the others are never reported. */
void cdist__cc_settle_d2(const cdist__cc_frame *f, const cdist__cc_sink *k);
/* Offer the pair at angle t of A to the sink's collector (robust mode), its distance by the
 * plain formula (cdist__cc_settle_d2 settles it); cdist__cc_pair_final offers the pair at the
 * point (c, s) = (cos t, sin t) (as cdist__cc_quick found them) with the parameter
 * cdist__cc_param(t) and the final distance there (cdist__cc_point_d2). */
void cdist__cc_pair_at(const cdist__cc_frame *f, double t, cdist__cc_sink *k);
void cdist__cc_pair_final(const cdist__cc_frame *f, double t, double c, double s, cdist__cc_sink *k);
/* Parallel planes: F's critical angles in closed form (up to 4), or -1 when not parallel. */
int cdist__cc_parallel_critical(const cdist__cc_frame *f, double *t);
/* The robust method's problem: A, the circle it parameterises (the larger; ties by a rule
 * antisymmetric in the arguments), and B, both scaled by unscale^-1 (cdist__circles_scale, half
 * = 1) so that L = max(r0, r1, |C|) is in [0.5, 1); CB: B's centre relative to A's, scaled; C: c1's centre
 * relative to c0's, unscaled. */
typedef struct cdist__cc_problem {
    int swapped; /* A is c1 */
    cdist__circle A, B;
    vec3 CB, C;
    double unscale;
} cdist__cc_problem;
/* Fills p from c0 (centre at the origin) and c1; returns 0 (only C and swapped set) when A or B
 * has radius 0, which the robust method answers with the point-circle core. Shared by the robust
 * method and the batch distance kernel (src/batch/cc_kernel.c). */
int cdist__cc_prepare(const cdist__circle *c0, const cdist__circle *c1, cdist__cc_problem *p);
/* The robust method (c0 at the origin). */
cdist_status cdist__cc_robust(cdist_query *q, const cdist__circle *c0, const cdist__circle *c1, cdist__best *b);
/* The robust method in stages (cc_robust.c): its state up to the certified search, the start
 * and the engine that follows a search that does not certify. */
typedef struct cdist__cc_robust_state {
    cdist__cc_problem pb;
    cdist__cc_frame f;
    cdist__cc_sink k;
    double tp[4];
    int np;
} cdist__cc_robust_state;
enum { CDIST__CC_ANSWERED, CDIST__CC_SEARCH, CDIST__CC_ENGINE };
int cdist__cc_robust_start(const cdist__circle *c0, const cdist__circle *c1, cdist__best *b, cdist__cc_robust_state *s);
cdist_status cdist__cc_robust_engine(cdist_query *q, cdist__cc_robust_state *s);

/* cdist_circle_circle() in stages, for batches that run many entries' certified searches in
 * lanes (src/batch): cdist__cc_staged_start returns 1 when the query (method AUTO or ROBUST,
 * both circles accepted by the fast check) reaches the search with frame s->rs.f, and writes
 * nothing else (0: the caller asks cdist_circle_circle); cdist__cc_staged_finish, given what
 * the search found (found, its angle t and cos, sin), completes r and returns the status exactly
 * as cdist_circle_circle() does. *s is not to be moved in between (the sink points into it). */
typedef struct cdist__cc_staged {
    cdist__circle a, b;
    vec3 offset;
    int e;
    cdist__best best;
    cdist__cc_robust_state rs;
} cdist__cc_staged;
int cdist__cc_staged_start(cdist_query *q, const cdist_circle *c0, const cdist_circle *c1, cdist__cc_staged *s);
cdist_status cdist__cc_staged_finish(cdist_query *q, cdist__cc_staged *s, int found, double t, double c, double sn,
                                     cdist_result *r);
/* Circle c (centre at the origin) to disk d, solved into a fresh collector and merged into b
 * (an equidistant sub-result makes b equidistant only where it attains b's minimum); dcap: a
 * distance attained elsewhere (INFINITY: none), like b's best: minima of the rim distance above
 * it cannot be the answer and are pruned. rim = 0 leaves out the minima of the distance from c
 * to d's rim (the candidates over d's face and the parallel closed forms remain): disk-disk,
 * whose other half has found them already. *used: the method that answered; *rim_certified
 * (may be NULL): the rim minima were found by the certified search, the engine without a
 * sampled region, a bound or a closed form (not the sampling fallback). */
cdist_status cdist__circle_disk_core_ex(cdist_query *q, cdist_method method, const cdist__circle *c, const cdist__circle *d,
                                        double dcap, int rim, cdist__best *b, cdist_method *used, int *rim_certified);

/* The circle P(t) = rho (cos t A + sin t B) (centre at the origin) in the disk's frame:
 * x(t) = X[0] + X[1] cos t + X[2] sin t, the same for y, z, over lanes of type V with masks M
 * (cd_body.h); E0 = X0^2 + Y0^2 - R^2 to the last bit (see its rim excess), R the disk's radius,
 * rho the circle's, small: rho <= R (the rim excess expands around the circle's centre). */
#define CDK_LANES_FIELDS(V, M)                                                                                 \
    V X[3], Y[3], Z[3];                                                                                        \
    V E0, R, rho;                                                                                              \
    M small;
typedef struct cdk_lanes_1 {
    CDK_LANES_FIELDS(double, int)
} cdk_lanes_1;

/* The circle and disk of a circle-disk query (circle_disk.c): g, and S(t) = Delta . Delta' (the
 * polynomial method's), the ring of the rim distance (w = (x, y, 0), h = z), the bases. */
typedef struct cdist__cdk {
    cdk_lanes_1 g;
    double S[3];
    cdist__ring rg;
    vec3 A, B, D, n, u, v;
    const cdist__circle *c, *d; /* the circle (centre at the origin) and the disk */
} cdist__cdk;

/* The distance of cdist__circle_disk_core_ex (ROBUST method, cap INFINITY, a fresh collector
 * of scale bscale) in stages, for the batch kernel (src/batch/cd_kernel.c), which frames the
 * circle c and the disk d, computes the candidates over the face (cd_body.h: k.g, their
 * smallest squared distance d2, the cap dcap = sqrt(d2) and the scale), the bound that spares
 * the rim and the rim search's frame f (cdist__cc_quick_frame's: its ring, and the scaling sc)
 * of many entries in lanes: cdist__cd_stage_ring sets k's ring (and its circles' pointers) from
 * k.g; with the angle t the search (cdist__cc_quick) finds and cdist__cc_point_d2 there,
 * cdist__cd_stage_finish completes d2 as the single query does (the cut-off, the flat scan, the
 * offers). */
typedef struct cdist__cd_stage {
    cdist__circle c, d;
    cdist__cdk k;
    double d2, bscale, scale, dcap, sc;
    cdist__cc_frame f;
} cdist__cd_stage;
void cdist__cd_stage_ring(cdist__cd_stage *st);
void cdist__cd_stage_finish(cdist__cd_stage *st, double t, double d2);

/* ---- the engine's parts (cc_frame.c, cc_certify.c, cc_kink.c, cc_scan.c, cc_pair.c) ---- */

#define CC_INIT_INTERVALS 16 /* a power of two >= 8 (cdist__cc_half_sec); the scan's table holds 16 angles */
#define CC_LEVEL0 1 /* log2(CC_INIT_INTERVALS / 8): cdist__cc_half_sec index of the initial intervals */

/* Track the extremes of F seen by the scan. */
CD_INLINE void cdist__cc_track(cdist__cc_sink *k, const cdist__cc_pt *cur, double *Fmax)
{
    if (cur->F > *Fmax) *Fmax = cur->F;
    if (cur->F < k->Fmin) {
        k->Fmin = cur->F;
        k->tmin = cur->t;
    }
}

/* cos h and sin h for |h| <= 0.1 by their Taylor series (truncation below 1e-26 there): the kink
 * grid's offsets, combined with cos t, sin t of the centre by the addition theorem, so the grid
 * costs no transcendental call. */
CD_INLINE void cdist__cc_small_sincos(double h, double *sn, double *cs)
{
    double x = h * h;
    *sn = h * (1 - x / 6 * (1 - x / 20 * (1 - x / 42 * (1 - x / 72 * (1 - x / 110 * (1 - x / 156))))));
    *cs = 1 - x / 2 * (1 - x / 12 * (1 - x / 30 * (1 - x / 56 * (1 - x / 90 * (1 - x / 132 * (1 - x / 182))))));
}

/* 1 / (2 cos(w/2)) for a width w <= 0.2 rad. */
CD_INLINE double cdist__cc_half_secant(double w)
{
    double sh, ch;
    cdist__cc_small_sincos(0.5 * w, &sh, &ch);
    return 0.5 / ch;
}

/* The same for the interval width w = 2 pi / 8 / 2^i (cc_certify.c), and the index i of a
 * subdivision level (clamped: the entries are 0.5 from 26 on). */
extern const double cdist__cc_half_sec[32];
CD_INLINE int cdist__cc_hs_index(int level) { return level + CC_LEVEL0 < 31 ? level + CC_LEVEL0 : 31; }

/* The neighbourhoods of the lowest grid points of the sampled intervals, minimised only after the
 * whole circle is scanned: then the attained minimum is known, and a neighbourhood whose
 * Lipschitz lower bound (d is R-Lipschitz in the angle) lies above it by more than the tie
 * tolerance cannot hold the closest pair or a second one, and costs nothing. */
#define CC_DEFER 32
typedef struct cdist__cc_deferred {
    int n;
    double t[CC_DEFER], hw[CC_DEFER], d[CC_DEFER]; /* lowest grid point, half-width, its distance */
} cdist__cc_deferred;

/* The intervals of the near-crossing grids (cdist__cc_scan_kink) that are clear of B's axis and
 * wider than CD_CC_MIN_WIDTH, where F may hold features narrower than the grid (rim crossings):
 * certified, or subdivided, after the whole circle is scanned (cdist__cc_kink_recheck), when the
 * attained minimum prunes most of them without an evaluation. Per interval: the window's centre,
 * the ends' offsets from it and their distances, and the root the grid emitted for its own F' sign
 * pair (direction dir, 0: none). At most 2 windows of 2 x 65 intervals (260). */
#define CC_KINK_REC 264
typedef struct cdist__cc_kink_rec {
    int n;
    double tc[CC_KINK_REC], ha[CC_KINK_REC], hb[CC_KINK_REC], da[CC_KINK_REC], db[CC_KINK_REC], root[CC_KINK_REC];
    signed char dir[CC_KINK_REC];
} cdist__cc_kink_rec;

/* An interval [a, b] of a near-crossing grid (cdist__cc_kink_recheck), of any width up to 0.2
 * rad, subdivided as the scan's initial intervals are (cc_scan.c). */
void cdist__cc_subdivide_grid(const cdist__cc_frame *f, cdist__cc_sink *k, cdist__cc_pt *a, cdist__cc_pt *b,
                              double *Fmax, cdist__cc_deferred *df);

/* Certificates on [a, b] (cc_certify.c): at most one root of H; no critical point of F; F
 * convex. Each reads (and completes on demand) the detail of a and b. */
int cdist__cc_certified(const cdist__cc_frame *f, cdist__cc_pt *a, cdist__cc_pt *b);
int cdist__cc_monotone(const cdist__cc_frame *f, cdist__cc_pt *a, cdist__cc_pt *b);
int cdist__cc_convex(const cdist__cc_frame *f, cdist__cc_pt *a, cdist__cc_pt *b);
/* Lower bounds of F: on an arc [a, b] with half secant hs (cdist__cc_half_sec, cdist__cc_half_secant),
 * and on [t - h, t + h]. */
double cdist__cc_hull_bound(const cdist__cc_frame *f, const cdist__cc_pt *a, const cdist__cc_pt *b, double hs);
double cdist__cc_window_hull_bound(const cdist__cc_frame *f, double t, double h);
/* A critical bracket [a, b] of F (a sign change of F'), refined and handed to the sink (cc_scan.c).
 * Returns the refined angle, NAN when [a, b] is no bracket or the sink drops its root (skip_dir). */
double cdist__cc_emit(cdist__cc_sink *k, const cdist__cc_pt *a, const cdist__cc_pt *b);
/* The uncertifiable regions (cc_kink.c): near-crossings of B's axis (angles and core
 * half-widths), their geometric grids, an interval past its budget, the dense fallback, and the
 * deferred minimisations and re-checks. */
int cdist__cc_near_kinks(const cdist__cc_frame *f, const cdist__cc_pt *init, double *tk);
double cdist__cc_kink_core(const cdist__cc_frame *f, double t);
void cdist__cc_scan_kink(const cdist__cc_frame *f, cdist__cc_sink *k, double t, double core, double *Fmax,
                         cdist__cc_deferred *df, cdist__cc_kink_rec *kr);
void cdist__cc_kink_recheck(const cdist__cc_frame *f, cdist__cc_sink *k, const cdist__cc_kink_rec *kr, double *Fmax,
                            cdist__cc_deferred *df);
void cdist__cc_emit_sampled(const cdist__cc_frame *f, cdist__cc_sink *k, const cdist__cc_pt *a, const cdist__cc_pt *b,
                            double *Fmax, cdist__cc_deferred *df);
void cdist__cc_scan_dense(const cdist__cc_frame *f, cdist__cc_sink *k, double *Fmax);
void cdist__cc_deferred_offer(const cdist__cc_frame *f, cdist__cc_sink *k, const cdist__cc_deferred *df);

#endif
