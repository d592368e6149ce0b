/* SPDX-License-Identifier: MIT */
/* Circle to circle: public entry points, method dispatch, the robust method and the critical
 * angles used by the arc families.
 *
 * ---- The robust method (distance-to-circles-3d §3 with the circle as the curve) ----
 * One circle A (radius R, centre at the origin, basis u, v) is parameterised, P(t) = R(cos t u +
 * sin t v); the other, B (centre C, unit normal m, radius s), enters through the closed-form
 * point-circle distance. With D = P - C, w = m x D (|w| = rho, the distance to B's axis, free of
 * the cancellation of sqrt(|D|^2 - h^2)) and h = m.D:
 *     F(t) = (rho - s)^2 + h^2,                      squared distance from P(t) to B
 *     F'/2 = (rho - s) rho' + h h',   rho' = w.w'/rho
 * w(t) = al cos t + be sin t + ga (al = R m x u, be = R m x v, ga = -m x C) and h(t) are
 * first-degree trigonometric polynomials, Q = rho^2 has degree 2, and D.D' = -C.P' =: sigma has
 * degree 1 (|P| is constant). F' vanishes or is undefined only where rho sigma = s w.w'
 * (because D.D' = w.w' + h h'), so every critical point of F, including the non-smooth points
 * where A crosses B's axis (rho = 0), is a root of the degree-4 trigonometric polynomial
 *     H(t) = Q sigma^2 - s^2 (w.w')^2              (paper eq. (8)),
 * which has at most 8 roots unless it vanishes identically.
 *
 * Root bounding (no polynomial is solved): H's Fourier coefficients c_k are formed by exact
 * products of the coefficient arrays of Q, sigma and w.w', which gives rigorous bounds
 * M_j = sum |k|^j |c_k| >= |H^(j)|. [-pi, pi) is split into 16 intervals and each interval is
 * bisected until it is certified to hold
 *   - no root of H: from each end over half the interval, the Taylor lower bound
 *     |H(a)| - |H'(a)| x - M2 x^2/2 (or, second order, with H''(a) and M3 x^3/6) stays positive,
 *     or |H(a)| + |H(b)| > M1 (b - a); or
 *   - at most one root: H' keeps its sign (the same tests one derivative up); or
 *   - no critical point of F: F' keeps a sign certified by its end values and a bound of F''
 *     (monotone()); or at most one, a minimum: F'' > 0 certified by its end values and a bound
 *     of F''' (convex()). These two read the true F and answer where H has a root cluster that
 *     is no minimum of F (H = (rho sigma - s w.w')(rho sigma + s w.w'): both factors vanishing
 *     nearby, e.g. at near-touching linked circles),
 * with every value reduced by a first-order bound of its rounding error, or until it is
 * narrower than 2^-30 rad. Between two consecutive partition points F' then changes sign at most
 * once, so every local minimum of F is bracketed by a (-,+) sign pair of the true F' at
 * consecutive points (the partition points share their values, so a sign read at rounding level
 * still brackets every transition exactly once); it is refined by safeguarded Newton/bisection
 * on the true F' and offered with the point-circle closest point on B. Intervals narrower than
 * 2^-30 rad that stay uncertified (multiple roots of H: symmetric configurations, tangencies,
 * A crossing B's axis, where H has a double root) are only sign-checked; a further min/max pair
 * of F hidden inside one would lie within 2^-30 rad. A concave kink of F (A crossing B's axis
 * transversally: F = smooth - 2 s |linear|) is never a local minimum; when A is tangent to B's
 * axis, F is C^1 and the minimum there is bracketed like any other.
 * Pruning (robust mode, and the minima mode of circle-disk): the distance sqrt(F) is R-Lipschitz
 * in t, so an interval whose lower bound (d(a) + d(b) - R (b - a)) / 2 exceeds an attained
 * distance (a sample, a refined minimum) by more than a tie cannot hold a closest pair and is
 * dropped; so is one whose concave hull bound does (hull_bound(): F extends to a concave
 * function of (cos t, sin t), so on an arc it is at least min(F(a), F(b), G(T)), T the
 * tangents' intersection; the gap to min F shrinks as the square of the width). Not in the
 * critical-angle mode, which reports every critical angle.
 * Where certification is impossible (it is NOT claimed there):
 *   - H vanishing to rounding (coaxial circles, constant F): when the samples show F constant,
 *     a sample is the answer; else F' is sampled on 512 points.
 *   - Near-crossings of B's axis (rho <= 1e-6 L, found by bisection on Q' with a Lipschitz
 *     early exit): H is below its rounding there; a core window (up to 0.05 rad) is skipped by
 *     the subdivision and covered by a geometric grid t_k +- 0.1 * 2^(-j/2) from twice the core
 *     down to 1e-17.
 *   - An initial interval that uses up its budget of 48 evaluations (a cluster of roots at
 *     rounding level, e.g. near-tangent circles): its leftover intervals are sampled (>= 64
 *     points each).
 *   In each of these, F' brackets are refined as above and, because F' is noise where F is
 *   flat while F itself (from accurate rho - s and h) keeps its relative accuracy, a
 *   golden-section search of F around the lowest sample is offered too, after the whole scan
 *   and only where the Lipschitz bound leaves room below the attained minimum (cc_deferred).
 * The rounding bounds of H, H', H'' are local (eps times the magnitudes of the summed terms
 * at the point), which keeps H certifiable close to an axis crossing.
 * AUTO is this method: it was measured the fastest (1.5 us against 6.3 us for the polynomial
 * method and 9 us for the iteration on the random reference queries) and as exact.
 * The problem is scaled by a power of two (exact) to L ~ 1 first: H has terms of order L^6.
 *
 * Which circle is parameterised: the larger one (ties broken by a rule that is antisymmetric
 * in the arguments), translated to the origin. With the dispatcher translating to the first
 * centre, f(a,b) and f(b,a) then run bit-identical computations.
 *
 * Equidistant configurations (infinitely many closest pairs), detected with tolerances relative
 * to the scale L = max(r0, r1, |C1 - C0|):
 *   (a) F constant on A: every point of A is equally far from B. The level sets of the distance
 *       to B are tori, so this holds for coaxial circles (incl. concentric coplanar), for A a
 *       meridian of the torus (A centred on B, in B's normal plane there, R <= s) and for A a
 *       Villarceau circle of it (R = s). Test: max over the partition points of sqrt(F) minus
 *       the minimum distance <= 32 eps L.
 *   (b) The closest point of A lies on B's axis (rho <= 8 eps (R + |C|) min(1, s / L)): all of B
 *       is equally close to it (e.g. the meridian case seen from the larger circle). The factor
 *       s / L keeps a tiny B beside a huge A (s = 1e-8, L = 1e8) from being called equidistant
 *       when its axis is missed by more than its own radius.
 * The tolerances are relative to L, so a configuration that is equidistant only up to the
 * rounding of coordinates much larger than L (far from the origin) may come out with one or two
 * pairs instead (the distance is right either way). The same two tests (with 16 samples per
 * circle for (a), stopping at the first that differs) are applied to the answers of the
 * polynomial and iteration methods (cc_equidistant_post).
 * Radius 0: a zero-radius circle is a point and the point-circle core answers. */
#include <math.h>
#include <string.h>

#include "circles/circles-priv.h"

#define CC_INIT_INTERVALS 16 /* a power of two >= 8 (half_sec[] below); the init table holds 16 angles */
#define CC_LEVEL0 1 /* log2(CC_INIT_INTERVALS / 8): half_sec[] index of the initial intervals */
#define CC_MIN_WIDTH (1.0 / 1073741824.0) /* 2^-30 rad */
#define CC_EVAL_BUDGET 48 /* per initial interval */
#define CC_DENSE_SAMPLES 512
#define CC_STACK 40 /* > the deepest level (31) */
#define CC_MIN_ITER 100 /* Brent minimisation steps (a golden step shrinks by 0.618: 100 reach any width) */

/* ---- trigonometric polynomials of degree <= 4 as complex coefficients c_k, k = -4..4 ---- */
typedef struct tpoly {
    double re[9], im[9];
} tpoly;


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

static void tp_zero(tpoly *p) { memset(p, 0, sizeof *p); }
/* Add a cos(k t) + b sin(k t). */
static void tp_term(tpoly *p, int k, double a, double b)
{
    if (k == 0) {
        p->re[4] += a;
        return;
    }
    p->re[4 + k] += 0.5 * a;
    p->im[4 + k] -= 0.5 * b;
    p->re[4 - k] += 0.5 * a;
    p->im[4 - k] += 0.5 * b;
}
/* z = x y for x of degree dx and y of degree dy (dx + dy <= 4); only the coefficients k >= 0
 * are formed (c_{-k} = conj(c_k) for real functions; every user reads k >= 0 only). */
static void tp_mul(const tpoly *x, int dx, const tpoly *y, int dy, tpoly *z)
{
    tpoly r;
    tp_zero(&r);
    for (int k = 0; k <= dx + dy; k++) {
        int lo = k - dy > -dx ? k - dy : -dx, hi = k + dy < dx ? k + dy : dx;
        double re = 0, im = 0;
        for (int i = lo; i <= hi; i++) {
            int j = k - i;
            re += x->re[4 + i] * y->re[4 + j] - x->im[4 + i] * y->im[4 + j];
            im += x->re[4 + i] * y->im[4 + j] + x->im[4 + i] * y->re[4 + j];
        }
        r.re[4 + k] = re;
        r.im[4 + k] = im;
        r.re[4 - k] = re;
        r.im[4 - k] = -im;
    }
    *z = r;
}

CD_FMA_CLONES void cdist__cc_frame_ring(cdist__cc_frame *f, const cdist__circle *A, vec3 C, const cdist__circle *B)
{
    f->R = A->r;
    f->s = B->r;
    f->u = A->u;
    f->v = A->v;
    f->C = C;
    f->m = B->n;
    vec3 m = B->n;
    cdist__ring_init(&f->rg, f->R, A->u, A->v, C, m);
    f->Cu = cdist__cc_dot3(C, A->u);
    f->Cv = cdist__cc_dot3(C, A->v);
    double aa = cdist__cc_dot3(f->rg.al, f->rg.al), bb = cdist__cc_dot3(f->rg.be, f->rg.be);
    double gg = cdist__cc_dot3(f->rg.ga, f->rg.ga), Lc = v_norm(C);
    f->epsL = DBL_EPSILON * (f->R + Lc);
    f->L = cdist__fmax(cdist__fmax(f->R, f->s), Lc);
    f->Lw = 2 * f->R + Lc;
    f->W1 = sqrt(aa) + sqrt(bb);
    f->nga = sqrt(gg);
    f->Hh = fabs(f->rg.ha) + fabs(f->rg.hb);
    f->Hc0 = fabs(f->rg.hc);
}

void cdist__cc_frame_bounds(cdist__cc_frame *f)
{
    vec3 C = f->C;
    /* Fourier coefficients of Q, sigma, g = w.w' and H = Q sigma^2 - s^2 g^2. */
    double aa = cdist__cc_dot3(f->rg.al, f->rg.al), bb = cdist__cc_dot3(f->rg.be, f->rg.be), ab = cdist__cc_dot3(f->rg.al, f->rg.be);
    double ag = cdist__cc_dot3(f->rg.al, f->rg.ga), bg = cdist__cc_dot3(f->rg.be, f->rg.ga), gg = cdist__cc_dot3(f->rg.ga, f->rg.ga);
    tpoly Q, S, G, T, H;
    tp_zero(&Q);
    tp_term(&Q, 0, 0.5 * (aa + bb) + gg, 0);
    tp_term(&Q, 1, 2 * ag, 2 * bg);
    tp_term(&Q, 2, 0.5 * (aa - bb), ab);
    tp_zero(&S);
    tp_term(&S, 1, -f->R * f->Cv, f->R * f->Cu);
    tp_zero(&G);
    tp_term(&G, 1, bg, -ag);
    tp_term(&G, 2, ab, 0.5 * (bb - aa));
    tp_mul(&S, 1, &S, 1, &T);
    tp_mul(&Q, 2, &T, 2, &H);
    tp_mul(&G, 2, &G, 2, &T);
    double s2 = f->s * f->s;
    f->M1 = f->M2 = f->M3 = f->Hc = 0;
    for (int i = 4; i < 9; i++) {
        double cr = H.re[i] - s2 * T.re[i], ci = H.im[i] - s2 * T.im[i];
        /* the problem is scaled to L ~ 1: no overflow; c_{-k} has the same modulus */
        double c = (i == 4 ? 1 : 2) * sqrt(cr * cr + ci * ci);
        double k = (double)(i - 4);
        f->Hc += c;
        f->M1 += k * c;
        f->M2 += k * k * c;
        f->M3 += k * k * k * c;
    }
    /* Rounding of the coefficient arithmetic, then a margin. */
    double eps = DBL_EPSILON;
    f->M1 = f->M1 * (1 + 1e-9) + 1e-300;
    f->M2 = f->M2 * (1 + 1e-9) + 1e-300;
    f->M3 = f->M3 * (1 + 1e-9) + 1e-300;

    /* First-order rounding bounds of H and H' as evaluated in cc_eval (all terms). */
    double Lc = v_norm(C);
    double W1 = f->W1, Wn = W1 + f->nga;
    double ew = 4 * eps * (2 * f->R + Lc), ew1 = 8 * eps * f->R;
    double sm = f->R * (fabs(f->Cu) + fabs(f->Cv)), dsm = 4 * eps * (sm + f->R * Lc);
    double Qm = Wn * Wn, gm = Wn * W1, g1m = W1 * W1 + Wn * W1;
    double dQ = 2 * Wn * ew + ew * ew + 4 * eps * Qm;
    double dg = ew * W1 + Wn * ew1 + 4 * eps * gm;
    double dg1 = 2 * W1 * ew1 + ew * W1 + Wn * ew1 + 4 * eps * g1m;
    f->eH = 2 * (dQ * sm * sm + 2 * Qm * sm * dsm + 2 * s2 * gm * dg + 6 * eps * (Qm * sm * sm + s2 * gm * gm));
    f->eH1 = 2 * (2 * (dg * sm * sm + 2 * gm * sm * dsm) + 2 * (dQ * sm * sm + 2 * Qm * sm * dsm) +
                  2 * s2 * (dg * g1m + gm * dg1) + 10 * eps * (gm * sm * sm + Qm * sm * sm + s2 * gm * g1m));
    /* H'' has the terms of H' with one more derivative (factors <= 4 on each): */
    f->eH2 = 4 * (f->eH1 + f->eH);
}

void cdist__cc_frame_init(cdist__cc_frame *f, const cdist__circle *A, vec3 C, const cdist__circle *B)
{
    cdist__cc_frame_ring(f, A, C, B);
    cdist__cc_frame_bounds(f);
}

/* The certificates' values at p, from one evaluation of order 2: H, H', H'' (from the same w', g,
 * g1 as the ring evaluator) with their rounding bounds, F''/2, and the rounding bounds of F'/2
 * and F''/2. */
static void cc_detail(const cdist__cc_frame *f, cdist__cc_pt *p)
{
    if (p->detail) return;
    p->detail = 1;
    double c = p->c, s = p->s;
    cdist__ring_val v;
    cdist__ring_eval(&f->rg, f->s, c, s, 2, &v);
    double Q = v.Q, g = v.g, g1 = v.g1, rho = v.rho;
    double sig = f->R * (f->Cu * s - f->Cv * c), sig1 = f->R * (f->Cu * c + f->Cv * s);
    double s2 = f->s * f->s;
    p->H = Q * sig * sig - s2 * g * g;
    p->H1 = 2 * g * sig * sig + 2 * Q * sig * sig1 - 2 * s2 * g * g1;
    double g2 = 3 * (cdist__cc_dot3(v.w1, f->rg.ga) - g) - g; /* 3 w'.w'' + w.w''' with w''' = -w' */
    p->H2 = 2 * g1 * sig * sig + 8 * g * sig * sig1 + 2 * Q * (sig1 * sig1 - sig * sig) - 2 * s2 * (g1 * g1 + g * g2);
    /* Rounding bounds, first order with margin: eps times the magnitudes Xb of the terms each
     * quantity is summed from (w carries eps (2R + |C|) absolutely, w' eps 2R). Local bounds
     * keep H certifiable near A's crossing of B's axis, where every term of H is tiny but
     * accurate (relative error eps L / rho). */
    double W1 = f->W1, Lw = f->Lw, ga = f->nga + f->Lw - 2 * f->R, ar = fabs(v.dr), irho = rho > 0 ? 1 / rho : INFINITY;
    double Qb = Q + 2 * rho * Lw, gb = fabs(g) + W1 * Lw + rho * 2 * f->R;
    double g1b = 2 * W1 * W1 + (rho + Lw) * ga + Qb, g2b = 3 * (W1 * ga + gb) + gb;
    double sb = f->R * (fabs(f->Cu) + fabs(f->Cv)), sb2 = sb * sb;
    double e8 = 8 * DBL_EPSILON, ag = fabs(g), ag1 = fabs(g1);
    p->eH = e8 * (Qb * sb * (fabs(sig) + sb) + 3 * s2 * ag * gb);
    p->eH1 = e8 * (2 * gb * sb2 + 4 * Qb * sb2 + 2 * s2 * (gb * (ag1 + g1b) + ag * g1b));
    p->eH2 = e8 * (4 * g1b * sb2 + 16 * gb * sb2 + 8 * Qb * sb2 +
                   2 * s2 * (3 * g1b * (ag1 + g1b) + gb * (fabs(g2) + g2b) + ag * g2b));
    /* F'/2 = dr g / rho + h h': dr and h carry eps Lw absolutely, g eps Lw W1 (relative eps L
     * / rho after the division), each product and sum eps relatively; doubled for margin. */
    p->eF1 = 16 * DBL_EPSILON * (Lw * W1 * (1 + ar * irho) + ar * fabs(v.g) * (rho > 0 ? irho : 0.0) +
                                 fabs(v.h) * fabs(v.h1) + Lw * (fabs(v.h1) + W1));
    /* F''/2 = rho'^2 + dr rho'' + h'^2 + h h'', rho'' = (g1 - rho'^2) / rho: the absolute
     * errors of dr, h (eps Lw), of g1 = w'.w' + w.ga - Q (eps (Lw W1 + (rho + Lw) |ga| + Q)) and
     * g / rho carried through, with margin. */
    p->F2 = v.F2;
    double g1e = fabs(v.g1) + W1 * W1 + Lw * W1 + (rho + Lw) * f->nga + Q;
    p->eF2 = 64 * DBL_EPSILON * (W1 * W1 + (Lw + ar) * g1e * irho + f->Hh * f->Hh + (fabs(v.h) + Lw) * f->Hh);
}

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

/* Track the extremes of F seen by the scan. */
static inline void cc_track(cdist__cc_sink *k, const cdist__cc_pt *cur, double *Fmax)
{
    if (cur->F > *Fmax) *Fmax = cur->F;
    if (cur->F < k->Fmin) {
        k->Fmin = cur->F;
        k->tmin = cur->t;
    }
}

/* The pair at angle t of A ((c, s) = (cos t, sin t)) with its squared distance: plain, or
 * (final) the double-double formula of the answer (cdist__cc_point_d2). */
CD_INLINE void cc_pair(const cdist__cc_frame *f, double t, double c, double s, int final, cdist__cc_sink *k)
{
    vec3 P = v_axpy(v_scale(f->R * c, f->u), f->R * s, f->v);
    vec3 D = v_sub(P, f->C);
    vec3 w = v_cross(f->m, D);
    double h = v_dot(f->m, D), rho = v_norm(w);
    double dr = rho - f->s;
    double d2 = final ? cdist__cc_point_d2(&f->rg, f->s, c, s) : fma(dr, dr, h * h);
    vec3 dir;
    double tb;
    if (rho > 0) {
        dir = v_cross(w, f->m);
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

static void emit(cdist__cc_sink *k, const cdist__cc_pt *a, const cdist__cc_pt *b)
{
    int dir = 0;
    if (a->F1 < 0 && b->F1 >= 0) dir = 1;
    else if (k->want_max && a->F1 > 0 && b->F1 <= 0) dir = -1;
    if (!dir) return;
    double t = refine(k->f, a, b, dir);
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
}

/* Bounds rho_lo <= rho <= rho_hi on [a, b] (rho is W1-Lipschitz in t); 0 when rho_lo <= 0 (the
 * F certificates below divide by it). */
static int rho_range(const cdist__cc_frame *f, const cdist__cc_pt *a, const cdist__cc_pt *b, double *rlo, double *rhi)
{
    double hw = 0.5 * f->W1 * (b->t - a->t);
    *rlo = 0.5 * (a->rho + b->rho) - hw;
    *rhi = cdist__fmax(a->rho, b->rho) + hw;
    return *rlo > 0;
}

/* No critical point of F on [a, b]: F' keeps one sign, certified by its values at the ends
 * (less their rounding bounds) and a bound M >= |F''/2| on [a, b] (from each end F' cannot reach
 * 0 within |F'|/M). With rho_lo <= rho <= rho_hi on [a, b] (rho is W1-Lipschitz) and
 * F''/2 = rho'^2 + (rho - s) rho'' + h'^2 + h h'', |rho'| <= |w'| <= W1,
 * |rho''| = |w.w'' + |w'|^2 - rho'^2| / rho <= (rho_hi W1 + 2 W1^2) / rho_lo. Needs rho_lo > 0:
 * it answers where H's certificates cannot, at roots of H's spurious factor rho sigma + s w.w'
 * (H = (rho sigma - s w.w')(rho sigma + s w.w') and F'/2 = sigma - s w.w' / rho). */
static int monotone(const cdist__cc_frame *f, cdist__cc_pt *a, cdist__cc_pt *b)
{
    if (!((a->F1 > 0 && b->F1 > 0) || (a->F1 < 0 && b->F1 < 0))) return 0;
    cc_detail(f, a);
    cc_detail(f, b);
    double A = fabs(a->F1) - a->eF1, B = fabs(b->F1) - b->eF1;
    if (!(A > 0 && B > 0)) return 0;
    double w = b->t - a->t, W1 = f->W1, rlo, rhi;
    if (!rho_range(f, a, b, &rlo, &rhi)) return 0;
    double M = W1 * W1 + (rhi + f->s) * (rhi * W1 + 2 * W1 * W1) / rlo + f->Hh * (2 * f->Hh + f->Hc0);
    return A + B > M * w * (1 + 1e-12);
}

/* At most one critical point of F on [a, b], a minimum: F is convex there, certified by F''/2 at
 * the ends (less rounding) and M3 >= |F'''/2| on [a, b]. With the bounds of monotone() and
 * F'''/2 = 3 rho' rho'' + (rho - s) rho''' + 3 h' h'' + h h''',
 * rho''' = (3 w'.w'' + w.w''' - 3 rho' rho'') / rho. Answers at a minimum where H has a root
 * cluster (both of its factors vanish nearby) and its certificates fail. */
static int convex(const cdist__cc_frame *f, cdist__cc_pt *a, cdist__cc_pt *b)
{
    cc_detail(f, a);
    cc_detail(f, b);
    double A = a->F2 - a->eF2, B = b->F2 - b->eF2;
    if (!(A > 0 && B > 0)) return 0;
    double w = b->t - a->t, W1 = f->W1, rlo, rhi;
    if (!rho_range(f, a, b, &rlo, &rhi)) return 0;
    double B2 = (rhi * W1 + 2 * W1 * W1) / rlo;
    double B3 = (3 * W1 * W1 + rhi * W1 + 3 * W1 * B2) / rlo;
    double M3 = 3 * W1 * B2 + (rhi + f->s) * B3 + f->Hh * (4 * f->Hh + f->Hc0);
    return cdist__fmin(A, B) > 0.5 * M3 * w * (1 + 1e-12);
}

#define POS(x) ((x) > 0 ? (x) : 0.0)
/* Certificates on [a, b] (see the header comment). 1: resolved (<= 1 root of H). First order
 * with the global bounds M1, M2; second order with the endpoint values of H'' and M3 (from each
 * end over half the interval, the cubic lower bound taken at its worst, x = w/2). */
static int certified(const cdist__cc_frame *f, cdist__cc_pt *a, cdist__cc_pt *b)
{
    cc_detail(f, a);
    cc_detail(f, b);
    double w = b->t - a->t, x = 0.5 * w;
    if ((a->H > 0 && b->H > 0) || (a->H < 0 && b->H < 0)) {
        double sg = a->H > 0 ? 1.0 : -1.0;
        double A = fabs(a->H) - a->eH, B = fabs(b->H) - b->eH;
        if (A > 0 && B > 0) {
            if (A + B > f->M1 * w) return 1;
            double la = A + (sg * a->H1 - a->eH1) * x - 0.5 * f->M2 * x * x;
            double lb = B - (sg * b->H1 + b->eH1) * x - 0.5 * f->M2 * x * x;
            if (la > 0 && lb > 0) return 1;
            double c3 = f->M3 * x * x * x / 6;
            la = A - (POS(-sg * a->H1) + a->eH1) * x - (POS(-sg * a->H2) + a->eH2) * 0.5 * x * x - c3;
            lb = B - (POS(sg * b->H1) + b->eH1) * x - (POS(-sg * b->H2) + b->eH2) * 0.5 * x * x - c3;
            if (la > 0 && lb > 0) return 1;
        }
    }
    if ((a->H1 > 0 && b->H1 > 0) || (a->H1 < 0 && b->H1 < 0)) {
        double sg = a->H1 > 0 ? 1.0 : -1.0;
        double A = fabs(a->H1) - a->eH1, B = fabs(b->H1) - b->eH1;
        if (A > 0 && B > 0) {
            if (A + B > f->M2 * w) return 1;
            double c2 = 0.5 * f->M3 * x * x;
            double la = A - (POS(-sg * a->H2) + a->eH2) * x - c2;
            double lb = B - (POS(sg * b->H2) + b->eH2) * x - c2;
            if (la > 0 && lb > 0) return 1;
        }
    }
    return 0;
}


/* 1 / (2 cos(w/2)) for the interval width 2 pi / CC_INIT_INTERVALS / 2^level: the values of
 * 0.5 / cos(M_PI / CC_INIT_INTERVALS / 2^level) for CC_INIT_INTERVALS = 8, as literals (a static
 * initializer cannot call cos in standard C; clang rejects it). Printed with %.17g from
 * 0.5 / math.cos(math.pi / 8 / 2**level). */
static const double half_sec[] = {
    0.54119610014619701, 0.50979557910415918, 0.50241928618815568, 0.50060299823519627,
    0.50015063602065102, 0.50003765191554772, 0.50000941253588782, 0.50000235310628605,
    0.50000058827484117, 0.50000014706860219, 0.50000003676714377, 0.50000000919178555,
    0.50000000229794639, 0.50000000057448657, 0.50000000014362167, 0.50000000003590539,
    0.50000000000897638, 0.50000000000224409, 0.500000000000561, 0.50000000000014033,
    0.50000000000003508, 0.50000000000000877, 0.50000000000000222, 0.50000000000000056,
    0.50000000000000011, 0.50000000000000011, 0.5, 0.5,
    0.5, 0.5, 0.5, 0.5,
};

/* cos h and sin h for |h| <= 0.1 by their Taylor series (truncation below 1e-26 there): the kink
 * grid's offsets, combined with cos t, sin t of the centre by the addition theorem, so the grid
 * costs no transcendental call. */
static inline void small_sincos(double h, double *sn, double *cs)
{
    double x = h * h;
    *sn = h * (1 - x / 6 * (1 - x / 20 * (1 - x / 42 * (1 - x / 72 * (1 - x / 110 * (1 - x / 156))))));
    *cs = 1 - x / 2 * (1 - x / 12 * (1 - x / 30 * (1 - x / 56 * (1 - x / 90 * (1 - x / 132 * (1 - x / 182))))));
}

/* half_sec[] index of a subdivision level (clamped: the entries are 0.5 from 26 on). */
static inline int hs_index(int level) { return level + CC_LEVEL0 < 31 ? level + CC_LEVEL0 : 31; }

/* A lower bound of F on the arc [a, b] of width 2 pi / CC_INIT_INTERVALS / 2^level. In the
 * plane of z = (cos t, sin t), F extends to G(z) = |D|^2 + s^2 - 2 s |w| with |D|^2 replaced by
 * its affine part (R^2 + |C|^2 - 2 R C.(u, v) z): affine minus a norm of an affine map, so G is
 * concave, and on the unit circle G = F. The arc lies in the triangle of its ends and T, the
 * intersection of the tangents there (T = (z_a + z_b) / (2 cos^2(w/2))), so on the arc
 * F >= min(F(a), F(b), G(T)), and G(T) = (rho_T - s)^2 + h_T^2 - R^2 tan^2(w/2) (|D|^2 at T
 * exceeds its affine part by R^2 (|T|^2 - 1)). The gap to min F shrinks as w^2, against w for
 * the Lipschitz bound. Rounding: the absolute errors of rho_T - s and h_T (dw, a few eps of the
 * magnitudes of w's terms) and of T itself (an eps-relative move of T moves G by eps |grad G|).
 * Returns min(F(a), F(b), G(T)) minus that margin (may be negative). */
static double arc_hull_bound(const cdist__cc_frame *f, double ca, double sa, double cb, double sb, double Fmin_ends, double hs)
{
    double k = 2 * hs * hs; /* 1 / (2 cos^2(w/2)) */
    double cT = (ca + cb) * k, sT = (sa + sb) * k;
    cdist__ring_val v;
    cdist__ring_eval(&f->rg, f->s, cT, sT, 0, &v);
    double tan2 = 4 * hs * hs - 1, R2 = f->R * f->R;
    double GT = v.F - R2 * tan2;
    double dw = 16 * DBL_EPSILON * f->Lw, dT = sqrt(v.F) + f->Lw;
    double err = 4 * dT * dw + 16 * DBL_EPSILON * (v.F + R2 * tan2 + f->Lw * f->Lw);
    return cdist__fmin(Fmin_ends, GT) - err;
}

/* The bound on an interval of the subdivision at `level`. */
static double hull_bound(const cdist__cc_frame *f, const cdist__cc_pt *a, const cdist__cc_pt *b, int level)
{
    return arc_hull_bound(f, a->c, a->s, b->c, b->s, cdist__fmin(a->F, b->F), half_sec[hs_index(level)]);
}

/* The bound on the window [t - h, t + h] (h <= 0.1) around a near-crossing. */
static double window_hull_bound(const cdist__cc_frame *f, double t, double h)
{
    double ct, st, ch, sh;
    sincos(t, &st, &ct);
    small_sincos(h, &sh, &ch);
    cdist__cc_pt a, b;
    cdist__cc_eval_lean(f, t - h, ct * ch + st * sh, st * ch - ct * sh, &a);
    cdist__cc_eval_lean(f, t + h, ct * ch - st * sh, st * ch + ct * sh, &b);
    return arc_hull_bound(f, a.c, a.s, b.c, b.s, cdist__fmin(a.F, b.F), 0.5 / ch);
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
        small_sincos(h, &sh, &ch);
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
static void scan_dense(const cdist__cc_frame *f, cdist__cc_sink *k, double *Fmax)
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
            cc_track(k, &cur, Fmax);
        }
        if (i == 0) first = cur;
        else emit(k, &prev, &cur);
        prev = cur;
    }
    /* F nearly flat (why we are here): also search F itself around the lowest sample. */
    if (k->best && isfinite(k->Fmin)) min_offer(f, k, k->tmin - step, k->tmin + step);
}

/* Near-crossings of B's axis: the minima of Q = |w|^2 = rho^2 (a trigonometric polynomial of
 * degree 2, at most two minima) with rho <= CC_KINK_REL L. There F = smooth - 2 s rho has features
 * of width about rho / |w'| (A crossing the axis) or sqrt(rho / curvature) (A tangent to it),
 * where H is below its rounding and cannot be certified: those windows are scanned on a
 * geometric grid instead (see scan). Writes the angles, returns the count. */
#define CC_KINK_REL 1e-6
static int near_kinks(const cdist__cc_frame *f, const cdist__cc_pt *init, double *tk)
{
    enum { N = CC_INIT_INTERVALS };
    double thr = CC_KINK_REL * f->L;
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
        double width = 2 * (2 * M_PI / N), rho = 0; /* twice the width of half_sec[0] */
        int miss = 0;
        for (int it = 0; it < 52; it++) {
            /* 1 / (2 cos(width / 2)); width = 2 pi / N * 2^(1 - it) */
            int hi_ = it + CC_LEVEL0 - 1; /* width / 2 = pi / 8 / 2^hi_ */
            double hc = hi_ < 0 ? 0.70710678118654752 /* 0.5 / cos(pi / 4) */ : half_sec[hi_ < 31 ? hi_ : 31];
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
static double kink_core(const cdist__cc_frame *f, double t)
{
    double c, s;
    sincos(t, &s, &c);
    cdist__ring_val v;
    cdist__ring_eval(&f->rg, f->s, c, s, 0, &v);
    double r = sqrt(v.rho / f->L);
    double core = cdist__fmin(0.05, 1e3 * r + 1e-12);
    /* A tangent to B's axis keeps rho tiny over a wider window (rho ~ rho0 + k x^2 / 2), where H
     * stays below its rounding too: widen the core (doubling) while rho at both of its ends is
     * still below the near-crossing threshold. */
    double thr = CC_KINK_REL * f->L;
    while (core < 0.05) {
        double sh, ch;
        small_sincos(core, &sh, &ch);
        cdist__ring_val lo, hi;
        cdist__ring_eval(&f->rg, f->s, c * ch + s * sh, s * ch - c * sh, 0, &lo);
        cdist__ring_eval(&f->rg, f->s, c * ch - s * sh, s * ch + c * sh, 0, &hi);
        if (cdist__fmax(lo.rho, hi.rho) > thr) break;
        core = cdist__fmin(0.05, 2 * core);
    }
    return core;
}

/* The neighbourhoods of the lowest grid points of the sampled intervals, minimised only after the
 * whole circle is scanned: then the attained minimum is known, and a neighbourhood whose
 * Lipschitz lower bound (d is R-Lipschitz in the angle) lies above it by more than the tie
 * tolerance cannot hold the closest pair or a second one, and costs nothing. */
#define CC_DEFER 32
typedef struct cc_deferred {
    int n;
    double t[CC_DEFER], hw[CC_DEFER], d[CC_DEFER]; /* lowest grid point, half-width, its distance */
} cc_deferred;

static void deferred_offer(const cdist__cc_frame *f, cdist__cc_sink *k, const cc_deferred *df)
{
    double dbest = cdist__fmin(sqrt(k->Fmin), k->dmin);
    double tie = CD_TIE_ULPS * DBL_EPSILON * f->L + 8 * DBL_EPSILON * (f->L + dbest);
    for (int i = 0; i < df->n; i++)
        if (df->d[i] - f->R * df->hw[i] <= dbest + tie) min_offer(f, k, df->t[i] - df->hw[i], df->t[i] + df->hw[i]);
}

/* The geometric grid around a near-crossing t: t +- 0.1 * 2^-j down to the angular resolution
 * at t (offsets below 2 ulps of t name no new angle), and t. */
static void scan_kink(const cdist__cc_frame *f, cdist__cc_sink *k, double t, double core, double *Fmax, cc_deferred *df)
{
    k->sampled = 1;
    enum { NG = 64 }; /* 0.1 * 2^-63 is below any angular resolution */
    cdist__cc_pt prev, cur;
    double ct, st;
    sincos(t, &st, &ct);
    int first = 1;
    /* The grid starts at the first offset within twice the core: beyond the core the
     * subdivision covers F (overlapping it a little). */
    int j0 = 0, j1 = NG;
    while (j0 < NG - 1 && ldexp(0.1, -j0) > 2 * core) j0++;
    double res = 4 * DBL_EPSILON * cdist__fmax(1.0, fabs(t));
    while (j1 > j0 + 1 && ldexp(0.1, -(j1 - 1)) < res) j1--;
    for (int side = -1; side <= 1; side += 2)
        for (int jj = j0; jj < j1; jj++) {
            int j = side < 0 ? jj : j1 - 1 - (jj - j0); /* increasing angle */
            double h = side * ldexp(0.1, -j), ch, sh;
            if (side > 0 && jj == j0) {
                cdist__cc_eval_lean(f, t, ct, st, &cur);
                emit(k, &prev, &cur);
                prev = cur;
            }
            small_sincos(h, &sh, &ch);
            cdist__cc_eval_lean(f, t + h, ct * ch - st * sh, st * ch + ct * sh, &cur);
            cc_track(k, &cur, Fmax);
            if (!first) emit(k, &prev, &cur);
            first = 0;
            prev = cur;
        }
    /* Within about sqrt(eps) of the crossing, F' = 2 (rho - s) w.w'/rho + ... carries the
     * relative rounding eps L / rho of w.w' / rho and its sign is unreliable; F itself is
     * accurate (d to eps L). Polish the lowest grid neighbourhood by a minimisation of F. */
    if (!k->best) return;
    /* Each side of the crossing separately (a minimum on either side: symmetric
     * configurations), over the core at least. */
    double hw = cdist__fmax(1e-3, 2 * core);
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
static void emit_sampled(const cdist__cc_frame *f, cdist__cc_sink *k, const cdist__cc_pt *a, const cdist__cc_pt *b, double *Fmax,
                         cc_deferred *df)
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
    small_sincos(w / n, &sh, &ch);
    for (int j = 1; j < n; j++) {
        double t = a->t + w * j / n;
        grid_sincos(t, j % 8 == 0 || w / n > 0.1, ch, sh, &s, &c);
        cdist__cc_eval_lean(f, t, c, s, &cur);
        cc_track(k, &cur, Fmax);
        if (cur.F < Fbest) Fbest = cur.F, tbest = cur.t;
        emit(k, &prev, &cur);
        prev = cur;
    }
    emit(k, &prev, b);
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
        if (sqrt(hi) - sqrt(lo) <= CC_EQUI_ULPS * DBL_EPSILON * f->L) {
            *Fmax = hi;
            k->Fmin = lo;
            k->tmin = init[arg].t;
            return 0;
        }
        scan_dense(f, k, Fmax);
        return 0;
    }

    /* Depth-first, left to right, so consecutive leaves share their endpoints (one value per
     * point: a sign read at rounding level still brackets every transition exactly once): the
     * current interval is refined in place, right halves wait on the stack. Points are referred
     * to, never copied: the initial ones in init[], the midpoints of the current initial
     * interval in pool[] (at most the evaluation budget of them). */
    struct {
        cdist__cc_pt *b;
        int level;
    } st[CC_STACK];
    cdist__cc_pt pool[CC_EVAL_BUDGET + 1];
    double tk[2], core[2];
    cc_deferred deferred;
    deferred.n = 0;
    double dbest = INFINITY; /* smallest sampled distance: the minimum is at most this */
    for (int i = 0; i < CC_INIT_INTERVALS; i++) {
        if (init[i].d < dbest) dbest = init[i].d;
        if (init[i].F > *Fmax) *Fmax = init[i].F;
        if (init[i].F < k->Fmin) {
            k->Fmin = init[i].F;
            k->tmin = init[i].t;
        }
    }
    int nk = near_kinks(f, init, tk);
    for (int i = 0; i < nk; i++) {
        core[i] = kink_core(f, tk[i]);
        /* Pruning (robust and minima modes): a window (covering the grid) whose hull bound lies
         * above the attained distance needs no grid (near-touching linked circles: the crossing
         * is far above). */
        double dth = dbest * (1 + 8 * DBL_EPSILON) + CD_TIE_ULPS * DBL_EPSILON * f->L;
        if (k->prune && window_hull_bound(f, tk[i], 2 * core[i]) > dth * dth) continue;
        scan_kink(f, k, tk[i], core[i], Fmax, &deferred);
    }
    for (int i = 0; i < CC_INIT_INTERVALS; i++) {
        cdist__cc_pt *a = &init[i], *b = &init[i + 1];
        int level = 0, sp = 0, evals = 0; /* a cluster of roots exhausts the budget of its own interval only */
        for (;;) {
            double w = b->t - a->t;
            /* Pruning (robust and minima modes): the distance is R-Lipschitz in the angle, so on
             * [a, b] it is at least (d(a) + d(b) - R w) / 2, and F is at least the hull bound;
             * above the attained distance (a sample or a refined minimum) by more than a tie,
             * the interval holds no closest pair, not even a tied one. */
            double dth = cdist__fmin(dbest, k->dmin) * (1 + 8 * DBL_EPSILON) + CD_TIE_ULPS * DBL_EPSILON * f->L;
            int done = k->prune && (0.5 * (a->d + b->d - f->R * w) > dth || (level < 31 && hull_bound(f, a, b, level) > dth * dth));
            for (int j = 0; j < nk && !done; j++) {
                /* within twice a near-crossing's core: the geometric grid covers it */
                double lo = remainder(a->t - tk[j], 2 * M_PI), hi = lo + w;
                done = lo >= -2 * core[j] && hi <= 2 * core[j];
            }
            if (!done) {
                int leaf = certified(f, a, b) || monotone(f, a, b) || convex(f, a, b) || w <= CC_MIN_WIDTH || sp + 1 >= CC_STACK ||
                           level >= 31;
                if (leaf || evals >= CC_EVAL_BUDGET) {
                    /* Past the budget (multiple roots of H at rounding level: tangencies, A
                     * passing within rounding of B's axis) the rest is sampled, keeping the
                     * resolution already reached around the trouble spot. */
                    if (leaf) emit(k, a, b);
                    else emit_sampled(f, k, a, b, Fmax, &deferred);
                } else {
                    /* Midpoint from the endpoint cosines/sines (no transcendental call). */
                    double hc = half_sec[hs_index(level)];
                    cdist__cc_pt *mid = &pool[evals++];
                    cdist__cc_eval_lean(f, 0.5 * (a->t + b->t), (a->c + b->c) * hc, (a->s + b->s) * hc, mid);
                    if (mid->F > *Fmax) *Fmax = mid->F;
                    if (mid->F < k->Fmin) {
                        k->Fmin = mid->F;
                        k->tmin = mid->t;
                    }
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
    deferred_offer(f, k, &deferred);
    return 0;
}

/* Parallel planes (distance-to-circles-3d §5.2): when A's height over B's plane varies by at most
 * CD_CC_PARALLEL_ULPS eps L along A, F = (rho - s)^2 + h^2 with h constant to that level and
 * rho^2 = R^2 + e^2 - 2 R e cos(t - t0), where (e, t0) are the polar coordinates of B's centre
 * projected into A's plane. F's critical angles are then rho's extremes t0 and t0 + pi and the
 * angles where rho = s (the projections cross), in closed form. Writes them (up to 4), returns
 * the count, or -1 when the planes are not parallel. The distances at these angles are
 * evaluated on the true F, so the tilt below the threshold moves the answer by at most
 * 2 CD_CC_PARALLEL_ULPS eps L. */
int cdist__cc_parallel_critical(const cdist__cc_frame *f, double *t)
{
    if (!(cdist__norm2(f->rg.ha, f->rg.hb) <= CD_CC_PARALLEL_ULPS * DBL_EPSILON * f->L)) return -1;
    double e = cdist__norm2(f->Cu, f->Cv), R = f->R, s = f->s;
    double t0 = e > 0 ? atan2(f->Cv, f->Cu) : 0.0;
    int n = 0;
    t[n++] = t0;
    t[n++] = cdist__wrap_angle(t0 + M_PI);
    if (e > 0 && fabs(R - e) < s && s < R + e) {
        /* rho = s: cos(t - t0) = (R^2 + e^2 - s^2) / (2 R e), by the half angle (acos lost
         * the crossing of a tiny B across A's rim, the cosine rounding to 1) */
        double a = cdist__crossing_angle(R, e, s);
        t[n++] = cdist__wrap_angle(t0 + a);
        t[n++] = cdist__wrap_angle(t0 - a);
    }
    return n;
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
