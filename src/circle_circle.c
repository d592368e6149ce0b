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
 * M_j = sum |k|^j |c_k| >= |H^(j)|. [-pi, pi) is split into 8 intervals and each interval is
 * bisected until it is certified to hold
 *   - no root of H: from each end over half the interval, the Taylor lower bound
 *     |H(a)| - |H'(a)| x - M2 x^2/2 (or, second order, with H''(a) and M3 x^3/6) stays positive,
 *     or |H(a)| + |H(b)| > M1 (b - a); or
 *   - at most one root: H' keeps its sign (the same tests one derivative up),
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
 * Pruning: the distance sqrt(F) is R-Lipschitz in t, so an interval whose lower bound
 * (d(a) + d(b) - R (b - a)) / 2 exceeds an attained distance (a sample, a refined minimum)
 * cannot hold the global minimum and is dropped (not in the critical-angle mode).
 * Where certification is impossible (it is NOT claimed there):
 *   - H vanishing to rounding (coaxial circles, constant F): when the samples show F constant,
 *     a sample is the answer; else F' is sampled on 512 points.
 *   - Near-crossings of B's axis (rho <= 1e-6 L, found by bisection on Q' with a Lipschitz
 *     early exit): H is below its rounding there; a core window (up to 0.05 rad) is skipped by
 *     the subdivision and covered by a geometric grid t_k +- 0.1 * 2^(-j/2) down to 1e-17.
 *   - An initial interval that uses up its budget of 48 evaluations (a cluster of roots at
 *     rounding level, e.g. near-tangent circles): its leftover intervals are sampled (>= 64
 *     points each).
 *   In each of these, F' brackets are refined as above and, because F' is noise where F is
 *   flat while F itself (from accurate rho - s and h) keeps its relative accuracy, a
 *   golden-section search of F around the lowest sample is offered too.
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
 *   (b) The closest point of A lies on B's axis (rho <= 8 eps (R + |C|)): all of B is equally
 *       close to it (e.g. the meridian case seen from the larger circle).
 * The tolerances are relative to L, so a configuration that is equidistant only up to the
 * rounding of coordinates much larger than L (far from the origin) may come out with one or two
 * pairs instead (the distance is right either way). The same two tests (with 16 samples per
 * circle for (a), stopping at the first that differs) are applied to the answers of the
 * polynomial and iteration methods (cc_equidistant_post).
 * Radius 0: a zero-radius circle is a point and the point-circle core answers. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "internal.h"

#define CC_INIT_INTERVALS 8 /* half_sec[] below is tabulated for this value */
#define CC_MIN_WIDTH (1.0 / 1073741824.0) /* 2^-30 rad */
#define CC_EVAL_BUDGET 48 /* per initial interval */
#define CC_DENSE_SAMPLES 512
#define CC_STACK 40 /* > the deepest level (31) */
#define CC_EQUI_ULPS 32.0

/* The parameterised circle A at the origin and the other circle B. */
typedef struct cc_frame {
    double R, s;       /* radii of A and B */
    vec3 u, v;         /* A's basis */
    vec3 C, m;         /* B's centre relative to A's centre, B's unit normal */
    vec3 al, be, ga;   /* w(t) = m x (P(t) - C) = al cos t + be sin t + ga */
    double ha, hb, hc; /* h(t) = m.(P(t) - C) = ha cos t + hb sin t + hc */
    double Cu, Cv;     /* sigma = D.D' = R (Cu sin t - Cv cos t) */
    double M1, M2, M3; /* |H'| <= M1, |H''| <= M2, |H'''| <= M3 */
    double eH, eH1, eH2; /* rounding bounds of the computed H, H', H'' */
    double Hc;         /* sum of |Fourier coefficients| of H */
    double epsL;       /* eps * (R + |C|): absolute rounding of positions */
    double L;          /* problem scale max(R, s, |C|) */
    double Lw, W1, nga; /* magnitudes of the terms of w, of |w'|, |ga| (rounding bounds) */
} cc_frame;

/* Values at one angle. */
typedef struct cc_pt {
    double t, c, s;
    double H, H1, H2; /* H, H', H'' */
    double eH, eH1, eH2; /* their rounding bounds at this point */
    double F1;    /* F'/2 */
    double F;     /* F */
    double d;     /* sqrt(F) */
    double Q, g;  /* rho^2 and w.w' */
} cc_pt;

static inline double dot3(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

/* ---- trigonometric polynomials of degree <= 4 as complex coefficients c_k, k = -4..4 ---- */
typedef struct tpoly {
    double re[9], im[9];
} tpoly;

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

static void frame_init(cc_frame *f, const cd_circle *A, vec3 C, const cd_circle *B)
{
    f->R = A->r;
    f->s = B->r;
    f->u = A->u;
    f->v = A->v;
    f->C = C;
    f->m = B->n;
    vec3 m = B->n;
    f->al = v_scale(f->R, v_cross(m, A->u));
    f->be = v_scale(f->R, v_cross(m, A->v));
    f->ga = v_neg(v_cross(m, C));
    f->ha = f->R * dot3(m, A->u);
    f->hb = f->R * dot3(m, A->v);
    f->hc = -dot3(m, C);
    f->Cu = dot3(C, A->u);
    f->Cv = dot3(C, A->v);

    /* Fourier coefficients of Q, sigma, g = w.w' and H = Q sigma^2 - s^2 g^2. */
    double aa = dot3(f->al, f->al), bb = dot3(f->be, f->be), ab = dot3(f->al, f->be);
    double ag = dot3(f->al, f->ga), bg = dot3(f->be, f->ga), gg = dot3(f->ga, f->ga);
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
    double Wn = sqrt(aa) + sqrt(bb) + sqrt(gg), W1 = sqrt(aa) + sqrt(bb);
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
    f->epsL = eps * (f->R + Lc);
    f->L = fmax(fmax(f->R, f->s), Lc);
    f->Lw = 2 * f->R + Lc;
    f->W1 = W1;
    f->nga = sqrt(gg);
}

/* Hot-path arithmetic without fma(): the library is built for baseline x86-64, where fma() is a
 * libm call; plain products are accurate enough for sampling and Newton steps (the final
 * distance of each pair is recomputed in pair_at). */
/* w = al c + be s + ga and w' = be c - al s */
static inline void w_at(const cc_frame *f, double c, double s, vec3 *w, vec3 *w1)
{
    w->x = f->al.x * c + f->be.x * s + f->ga.x;
    w->y = f->al.y * c + f->be.y * s + f->ga.y;
    w->z = f->al.z * c + f->be.z * s + f->ga.z;
    w1->x = f->be.x * c - f->al.x * s;
    w1->y = f->be.y * c - f->al.y * s;
    w1->z = f->be.z * c - f->al.z * s;
}

/* Everything at angle t with (c, s) = (cos t, sin t). */
static void cc_eval(const cc_frame *f, double t, double c, double s, cc_pt *p)
{
    vec3 w, w1;
    w_at(f, c, s, &w, &w1);
    double Q = dot3(w, w), g = dot3(w, w1);
    double g1 = dot3(w1, w1) + dot3(w, f->ga) - Q; /* w'.w' + w.w'', w'' = ga - w */
    double sig = f->R * (f->Cu * s - f->Cv * c), sig1 = f->R * (f->Cu * c + f->Cv * s);
    double s2 = f->s * f->s;
    p->t = t;
    p->c = c;
    p->s = s;
    p->H = Q * sig * sig - s2 * g * g;
    p->H1 = 2 * g * sig * sig + 2 * Q * sig * sig1 - 2 * s2 * g * g1;
    double g2 = 3 * (dot3(w1, f->ga) - g) - g; /* 3 w'.w'' + w.w''' with w''' = -w' */
    p->H2 = 2 * g1 * sig * sig + 8 * g * sig * sig1 + 2 * Q * (sig1 * sig1 - sig * sig) - 2 * s2 * (g1 * g1 + g * g2);
    double rho = sqrt(Q);
    double h = f->ha * c + f->hb * s + f->hc, h1 = f->hb * c - f->ha * s;
    double rp = rho > 0 ? g / rho : 0.0;
    double dr = rho - f->s;
    p->F1 = dr * rp + h * h1;
    p->F = dr * dr + h * h;
    p->d = sqrt(p->F);
    p->Q = Q;
    p->g = g;
    /* Rounding bounds at this point, first order with margin: eps times the magnitudes Xb of
     * the terms each quantity is summed from (w carries eps (2R + |C|) absolutely, w' eps 2R).
     * Local bounds keep H certifiable near A's crossing of B's axis, where every term of H is
     * tiny but accurate (relative error eps L / rho). */
    double W1 = f->W1, Lw = f->Lw, ga = f->nga + f->Lw - 2 * f->R;
    double Qb = Q + 2 * rho * Lw, gb = fabs(g) + W1 * Lw + rho * 2 * f->R;
    double g1b = 2 * W1 * W1 + (rho + Lw) * ga + Qb, g2b = 3 * (W1 * ga + gb) + gb;
    double sb = f->R * (fabs(f->Cu) + fabs(f->Cv)), sb2 = sb * sb;
    double e8 = 8 * DBL_EPSILON, ag = fabs(g), ag1 = fabs(g1);
    p->eH = e8 * (Qb * sb * (fabs(sig) + sb) + 3 * s2 * ag * gb);
    p->eH1 = e8 * (2 * gb * sb2 + 4 * Qb * sb2 + 2 * s2 * (gb * (ag1 + g1b) + ag * g1b));
    p->eH2 = e8 * (4 * g1b * sb2 + 16 * gb * sb2 + 8 * Qb * sb2 +
                   2 * s2 * (3 * g1b * (ag1 + g1b) + gb * (fabs(g2) + g2b) + ag * g2b));
}

/* F'/2 and F''/2 only (for the refinement). */
static void cc_deriv(const cc_frame *f, double c, double s, double *F1, double *F2)
{
    vec3 w, w1;
    w_at(f, c, s, &w, &w1);
    double Q = dot3(w, w), g = dot3(w, w1);
    double rho = sqrt(Q);
    double h = f->ha * c + f->hb * s + f->hc, h1 = f->hb * c - f->ha * s, h2 = f->hc - h;
    double dr = rho - f->s;
    double rp = rho > 0 ? g / rho : 0.0;
    *F1 = dr * rp + h * h1;
    double g1 = dot3(w1, w1) + dot3(w, f->ga) - Q;
    double rpp = rho > 0 ? (g1 - rp * rp) / rho : 0.0;
    *F2 = rp * rp + dr * rpp + h1 * h1 + h * h2;
}

/* A root of F' in [a, b] where F'(a) and F'(b) have opposite signs (dir = +1 for (-,+), -1 for
 * (+,-)): safeguarded Newton on the true F', falling back to bisection. */
static double refine(const cc_frame *f, const cc_pt *a, const cc_pt *b, int dir)
{
    double lo = a->t, hi = b->t; /* dir * F'(lo) < 0 <= dir * F'(hi) */
    double fa = dir * a->F1, fb = dir * b->F1;
    /* Start from the secant point of the bracket. */
    double x = (fb > fa) ? lo + (hi - lo) * (-fa / (fb - fa)) : 0.5 * (lo + hi);
    if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
    double dxold = hi - lo;
    for (int it = 0; it < 100; it++) {
        double c, s, F1, F2;
        sincos(x, &s, &c);
        cc_deriv(f, c, s, &F1, &F2);
        F1 *= dir;
        F2 *= dir;
        if (F1 == 0.0) return x;
        if (F1 < 0) lo = x;
        else hi = x;
        double step = F1 / F2;
        /* Converged: the Newton step is below the resolution of x. */
        if (F2 > 0 && fabs(step) <= 2 * DBL_EPSILON * fmax(1.0, fabs(x))) return x;
        double xn = x - step;
        int newton = 1;
        if (!(F2 > 0) || !(xn > lo && xn < hi) || fabs(2 * (x - xn)) > dxold) {
            xn = 0.5 * (lo + hi);
            newton = 0;
        }
        double dx = fabs(xn - x);
        /* Quadratic convergence: after a Newton step this small the error is below rounding. */
        if (newton && dx <= 1e-9) return xn;
        dxold = dx;
        if (dx <= 4 * DBL_EPSILON || hi - lo <= 4 * DBL_EPSILON) return xn;
        x = xn;
    }
    return x;
}

/* Receiver of the critical points found by the scan. */
typedef struct cc_sink {
    const cc_frame *f;
    int want_max;   /* also report local maxima (critical-angle mode) */
    double *out;    /* critical mode: angles */
    int cap, count; /* critical mode: room and number found (may exceed cap) */
    cd_best *best;  /* robust mode */
    int swapped;    /* robust mode: A is the second circle */
    const cd_circle *A, *B;
    double unscale; /* robust mode: the factor undoing the problem's scaling */
    double tmin, Fmin; /* partition point with the smallest F */
    double dmin;  /* smallest refined distance */
    double rho_min; /* axis distance of the point giving dmin */
} cc_sink;

/* Evaluate F at angle t and track the extremes seen by the scan. */
static void cc_sample(const cc_frame *f, cc_sink *k, double t, cc_pt *cur, double *Fmax)
{
    double c, s;
    sincos(t, &s, &c);
    cc_eval(f, t, c, s, cur);
    if (cur->F > *Fmax) *Fmax = cur->F;
    if (cur->F < k->Fmin) {
        k->Fmin = cur->F;
        k->tmin = cur->t;
    }
}

static void pair_at(const cc_frame *f, double t, cc_sink *k)
{
    double c, s;
    sincos(t, &s, &c);
    vec3 P = v_axpy(v_scale(f->R * c, f->u), f->R * s, f->v);
    vec3 D = v_sub(P, f->C);
    vec3 w = v_cross(f->m, D);
    double h = v_dot(f->m, D), rho = v_norm(w);
    double dr = rho - f->s;
    double d2 = fma(dr, dr, h * h);
    vec3 dir;
    double tb;
    if (rho > 0) {
        dir = v_cross(w, f->m);
        dir = v_scale(f->s / v_norm(dir), dir);
        tb = cd_circle_angle(k->B, dir);
    } else {
        dir = v_scale(f->s, k->B->u);
        tb = 0.0;
    }
    vec3 K = v_add(f->C, dir);
    double ta = (t <= -M_PI) ? t + 2 * M_PI : (t > M_PI ? t - 2 * M_PI : t);
    if (k->B->r == 0.0) tb = NAN;
    double u = k->unscale, d = sqrt(d2);
    if (!k->swapped) cd_best_offer(k->best, d2 * u * u, v_scale(u, P), v_scale(u, K), ta, tb);
    else cd_best_offer(k->best, d2 * u * u, v_scale(u, v_sub(K, f->C)), v_scale(u, v_sub(P, f->C)), tb, ta);
    if (d < k->dmin) {
        k->dmin = d;
        k->rho_min = rho;
    }
}

static void emit(cc_sink *k, const cc_pt *a, const cc_pt *b)
{
    int dir = 0;
    if (a->F1 < 0 && b->F1 >= 0) dir = 1;
    else if (k->want_max && a->F1 > 0 && b->F1 <= 0) dir = -1;
    if (!dir) return;
    double t = refine(k->f, a, b, dir);
    if (!k->best) {
        double ta = (t <= -M_PI) ? t + 2 * M_PI : (t > M_PI ? t - 2 * M_PI : t);
        if (k->count < k->cap) k->out[k->count] = ta;
        k->count++;
        cc_pt p;
        double c, s;
        sincos(t, &s, &c);
        cc_eval(k->f, t, c, s, &p);
        double d = sqrt(p.F);
        if (d < k->dmin) k->dmin = d;
    } else {
        pair_at(k->f, t, k);
    }
}

#define POS(x) ((x) > 0 ? (x) : 0.0)
/* Certificates on [a, b] (see the header comment). 1: resolved (<= 1 root of H). First order
 * with the global bounds M1, M2; second order with the endpoint values of H'' and M3 (from each
 * end over half the interval, the cubic lower bound taken at its worst, x = w/2). */
static int certified(const cc_frame *f, const cc_pt *a, const cc_pt *b)
{
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

/* Golden-section search of F on [lo, hi]; offers the best point (robust mode). F is computed
 * from accurate rho - s and h, so it keeps its relative accuracy even where F' is noise. */
static void golden_offer(const cc_frame *f, cc_sink *k, double lo, double hi)
{
    const double g = 0.6180339887498949;
    double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo), c, s;
    cc_pt p1, p2;
    sincos(x1, &s, &c);
    cc_eval(f, x1, c, s, &p1);
    sincos(x2, &s, &c);
    cc_eval(f, x2, c, s, &p2);
    for (int it = 0; it < 100 && hi - lo > 4 * DBL_EPSILON; it++) {
        if (p1.F < p2.F) {
            hi = x2, x2 = x1, p2 = p1, x1 = hi - g * (hi - lo);
            sincos(x1, &s, &c);
            cc_eval(f, x1, c, s, &p1);
        } else {
            lo = x1, x1 = x2, p1 = p2, x2 = lo + g * (hi - lo);
            sincos(x2, &s, &c);
            cc_eval(f, x2, c, s, &p2);
        }
    }
    pair_at(f, p1.F < p2.F ? x1 : x2, k);
}

/* Dense sampling fallback: F' signs on CC_DENSE_SAMPLES points. */
static void scan_dense(const cc_frame *f, cc_sink *k, double *Fmax)
{
    cc_pt first = {0}, prev = {0}, cur;
    double step = 2 * M_PI / CC_DENSE_SAMPLES;
    for (int i = 0; i <= CC_DENSE_SAMPLES; i++) {
        if (i == CC_DENSE_SAMPLES) {
            cur = first;
            cur.t = M_PI;
        } else {
            double t = -M_PI + i * step;
            cc_sample(f, k, t, &cur, Fmax);
        }
        if (i == 0) first = cur;
        else emit(k, &prev, &cur);
        prev = cur;
    }
    /* F nearly flat (why we are here): also search F itself around the lowest sample. */
    if (k->best && isfinite(k->Fmin)) golden_offer(f, k, k->tmin - step, k->tmin + step);
}

/* Near-crossings of B's axis: the minima of Q = |w|^2 = rho^2 (a trigonometric polynomial of
 * degree 2, at most two minima) with rho <= CC_KINK_REL L. There F = smooth - 2 s rho has features
 * of width about rho / |w'| (A crossing the axis) or sqrt(rho / curvature) (A tangent to it),
 * where H is below its rounding and cannot be certified: those windows are scanned on a
 * geometric grid instead (see scan). Writes the angles, returns the count. */
#define CC_KINK_REL 1e-6
static int near_kinks(const cc_frame *f, const cc_pt *init, double *tk)
{
    enum { N = CC_INIT_INTERVALS };
    vec3 w, w1;
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
            double hc = it == 0 ? 0.70710678118654752 /* 0.5 / cos(pi / 4), N = 8 */
                                : half_sec[it - 1 < 31 ? it - 1 : 31];
            double cm = (cl + ch) * hc, sm = (sl + sh) * hc;
            w_at(f, cm, sm, &w, &w1);
            rho = sqrt(dot3(w, w));
            if (rho - 0.5 * f->W1 * width > thr) {
                miss = 1;
                break;
            }
            double m = 0.5 * (lo + hi);
            if (dot3(w, w1) < 0) lo = m, cl = cm, sl = sm;
            else hi = m, ch = cm, sh = sm;
            width *= 0.5;
        }
        if (!miss && rho <= thr) tk[n++] = remainder(0.5 * (lo + hi), 2 * M_PI);
    }
    return n;
}

/* Half-width of the window around a near-crossing that only the geometric grid covers. */
static double kink_core(const cc_frame *f, double t)
{
    double c, s;
    sincos(t, &s, &c);
    vec3 w, w1;
    w_at(f, c, s, &w, &w1);
    double r = sqrt(sqrt(dot3(w, w)) / f->L);
    return fmin(0.05, 1e3 * r + 1e-12);
}

/* The geometric grid around a near-crossing t: t +- 0.1 * 2^(-j/2) down to 1e-17, and t. */
static void scan_kink(const cc_frame *f, cc_sink *k, double t, double *Fmax)
{
    enum { NG = 110 };
    cc_pt prev, cur;
    int first = 1;
    for (int side = -1; side <= 1; side += 2)
        for (int jj = 0; jj < NG; jj++) {
            int j = side < 0 ? jj : NG - 1 - jj; /* increasing angle */
            double h = 0.1 * pow(2.0, -0.5 * j), x = t + side * h, c, s;
            if (side > 0 && jj == 0) {
                sincos(t, &s, &c);
                cc_eval(f, t, c, s, &cur);
                emit(k, &prev, &cur);
                prev = cur;
            }
            cc_sample(f, k, x, &cur, Fmax);
            if (!first) emit(k, &prev, &cur);
            first = 0;
            prev = cur;
        }
    /* Within about sqrt(eps) of the crossing, F' = 2 (rho - s) w.w'/rho + ... carries the
     * relative rounding eps L / rho of w.w' / rho and its sign is unreliable; F itself is
     * accurate (d to eps L). Polish the lowest grid neighbourhood by golden section on F. */
    if (k->best) golden_offer(f, k, t - 1e-3, t + 1e-3);
}

/* An interval left uncertified when the evaluation budget ran out (a cluster of roots of H at
 * rounding level, where F is flat and may hold close minima): F' signs on a grid as fine as the
 * dense scan's and of at least 64 points, and in robust mode a golden-section search of F
 * around the lowest grid point. */
static void emit_sampled(const cc_frame *f, cc_sink *k, const cc_pt *a, const cc_pt *b, double *Fmax)
{
    double w = b->t - a->t;
    int n = (int)ceil(w / (2 * M_PI / CC_DENSE_SAMPLES));
    if (n < 64) n = 64;
    cc_pt prev = *a, cur;
    double Fbest = a->F, tbest = a->t;
    for (int j = 1; j < n; j++) {
        double t = a->t + w * j / n;
        cc_sample(f, k, t, &cur, Fmax);
        if (cur.F < Fbest) Fbest = cur.F, tbest = cur.t;
        emit(k, &prev, &cur);
        prev = cur;
    }
    emit(k, &prev, b);
    if (b->F < Fbest) tbest = b->t;
    if (k->best) golden_offer(f, k, tbest - w / n, tbest + w / n);
}

/* Walks [-pi, pi) (see the header comment) and hands every critical bracket to the sink.
 * Fmax: largest F at the partition points. Returns 1 when the certification gave up and the
 * sink does not allow the dense scan (nothing was emitted then), else 0. */
static int scan(const cc_frame *f, cc_sink *k, double *Fmax)
{
    *Fmax = 0;
    cc_pt init[CC_INIT_INTERVALS + 1];
    /* cos and sin of -pi + i pi / 8 (exact to rounding). */
    static const double ic[16] = {-1, -0.92387953251128674, -0.70710678118654757, -0.38268343236508978, 0,
                                  0.38268343236508978, 0.70710678118654757, 0.92387953251128674, 1,
                                  0.92387953251128674, 0.70710678118654757, 0.38268343236508978, 0,
                                  -0.38268343236508978, -0.70710678118654757, -0.92387953251128674};
    for (int i = 0; i < CC_INIT_INTERVALS; i++) {
        double t = -M_PI + i * (2 * M_PI / CC_INIT_INTERVALS);
        int j = i * (16 / CC_INIT_INTERVALS);
        cc_eval(f, t, ic[j], -ic[(j + 4) % 16], &init[i]);
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

    /* Depth-first, left to right, so consecutive leaves share their endpoints: the current
     * interval is refined in place, right halves wait on the stack. */
    typedef struct {
        cc_pt b;
        int level;
    } ival;
    ival st[CC_STACK];
    int evals = 0;
    double tk[2], core[2];
    int nk = near_kinks(f, init, tk);
    for (int i = 0; i < nk; i++) {
        core[i] = kink_core(f, tk[i]);
        scan_kink(f, k, tk[i], Fmax);
    }
    double dbest = INFINITY; /* smallest sampled distance: the minimum is at most this */
    for (int i = 0; i < CC_INIT_INTERVALS; i++)
        if (init[i].d < dbest) dbest = init[i].d;
    for (int i = 0; i < CC_INIT_INTERVALS; i++) {
        cc_pt a = init[i], b = init[i + 1];
        int level = 0, sp = 0;
        evals = 0; /* a cluster of roots exhausts the budget of its own interval only */
        for (;;) {
            if (a.F > *Fmax) *Fmax = a.F;
            if (a.F < k->Fmin) {
                k->Fmin = a.F;
                k->tmin = a.t;
            }
            double w = b.t - a.t;
            /* Robust mode prunes: the distance is R-Lipschitz in the angle, so on [a, b] it is at
             * least (d(a) + d(b) - R w) / 2; above an attained distance (a sample or a refined
             * minimum) the interval cannot hold the global minimum. */
            if (k->best && 0.5 * (a.d + b.d - f->R * w) > fmin(dbest, k->dmin) * (1 + 8 * DBL_EPSILON)) {
                if (sp == 0) break;
                a = b;
                b = st[--sp].b;
                level = st[sp].level;
                continue;
            }
            int inside = 0; /* within a near-crossing's core: the geometric grid covers it */
            for (int i = 0; i < nk; i++) {
                double lo = a.t - tk[i], hi = b.t - tk[i];
                lo = remainder(lo, 2 * M_PI);
                hi = lo + w;
                if (lo >= -core[i] && hi <= core[i]) inside = 1;
            }
            if (inside) {
                if (sp == 0) break;
                a = b;
                b = st[--sp].b;
                level = st[sp].level;
                continue;
            }
            int leaf = certified(f, &a, &b) || w <= CC_MIN_WIDTH || sp + 1 >= CC_STACK || level >= 31;
            if (leaf || evals >= CC_EVAL_BUDGET) {
                /* Past the budget (multiple roots of H at rounding level: tangencies, A passing
                 * within rounding of B's axis) the rest is sampled, keeping the resolution
                 * already reached around the trouble spot. */
                if (leaf) emit(k, &a, &b);
                else emit_sampled(f, k, &a, &b, Fmax);
                if (sp == 0) break;
                a = b;
                b = st[--sp].b;
                level = st[sp].level;
                continue;
            }
            /* Midpoint from the endpoint cosines/sines (no transcendental call). */
            double hc = half_sec[level];
            double cm = (a.c + b.c) * hc, sm = (a.s + b.s) * hc;
            cc_pt mid;
            cc_eval(f, 0.5 * (a.t + b.t), cm, sm, &mid);
            evals++;
            level++;
            st[sp].b = b;
            st[sp++].level = level;
            b = mid;
        }
    }
    return 0;
}

/* The antisymmetric choice of the circle to parameterise: 1 when it is c1. */
static int param_second(const cd_circle *c0, const cd_circle *c1, vec3 C)
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

/* The robust method (see the header comment). */
static cdist_status cc_robust(cdist_query *q, const cd_circle *c0, const cd_circle *c1, cd_best *b)
{
    vec3 C = v_sub(c1->c, c0->c); /* c0->c is the origin here; kept general */
    int sw = param_second(c0, c1, C);
    const cd_circle *A = sw ? c1 : c0, *B = sw ? c0 : c1;
    vec3 CB = sw ? v_neg(C) : C; /* B's centre relative to A's */
    double L = fmax(fmax(c0->r, c1->r), v_norm(C));
    if (A->r == 0.0) {
        /* Both are points. */
        cd_best_offer(b, v_sqr(C), c0->c, c1->c, NAN, NAN);
        return CDIST_OK;
    }
    if (B->r == 0.0) {
        /* B is a point: the point-circle core (equidistant when it is on A's axis). */
        if (!sw) {
            cd_point_circle_core(C, c0, b, 1);
        } else {
            cd_best t;
            cd_best_init(&t, b->scale);
            cd_point_circle_core(CB, c1, &t, 0);
            for (int i = 0; i < t.n; i++)
                cd_best_offer_flag(b, t.c[i].equidistant, t.c[i].d2, v_add(t.c[i].p[0], C), v_add(t.c[i].p[1], C),
                                   t.c[i].param[0], t.c[i].param[1]);
        }
        return CDIST_OK;
    }
    /* Scale the problem by a power of two (exact) so that L is about 1: H has terms of order
     * L^6, which would overflow or underflow for coordinates near the 1e150 limit. */
    int ex;
    frexp(L, &ex);
    double sc = ldexp(1.0, -ex), unsc = ldexp(1.0, ex);
    cd_circle As = *A, Bs = *B;
    As.c = v_scale(sc, A->c);
    As.r = sc * A->r;
    Bs.c = v_scale(sc, B->c);
    Bs.r = sc * B->r;
    CB = v_scale(sc, CB);
    A = &As;
    B = &Bs;
    cc_frame f;
    frame_init(&f, A, CB, B);
    cc_sink k = {.f = &f, .best = b, .unscale = unsc, .swapped = sw, .A = A, .B = B,  .Fmin = INFINITY,
                 .dmin = INFINITY, .rho_min = INFINITY};
    double Fmax;
    scan(&f, &k, &Fmax);
    /* F' never went from - to +: F is constant to rounding; any point is a closest one. */
    if (b->n == 0 && isfinite(k.Fmin)) pair_at(&f, k.tmin, &k);
    if (b->n == 0 || !isfinite(k.dmin)) return cd_fail(q, CDIST_ERR_INTERNAL, "circle-circle: no minimum found");
    /* (a) F constant on A; (b) the closest point of A on B's axis. */
    if (sqrt(Fmax) - k.dmin <= CC_EQUI_ULPS * DBL_EPSILON * f.L) b->equidistant = 1;
    if (k.rho_min <= 8 * f.epsL) b->equidistant = 1;
    return CDIST_OK;
}

/* Distance from X to circle c (closed form, |N x D| for the axis distance). */
static double pc_dist(vec3 X, const cd_circle *c, double *rho_out)
{
    vec3 D = v_sub(X, c->c);
    vec3 w = v_cross(c->n, D);
    double rho = v_norm(w), h = v_dot(c->n, D), dr = rho - c->r;
    if (rho_out) *rho_out = rho;
    return sqrt(fma(dr, dr, h * h));
}

/* The equidistance tests (a) and (b) of the header comment, method independent, applied to the
 * answer of the polynomial and iteration methods: (b) a closest point on the other circle's
 * axis; (a) 16 equally spaced points of either circle all at the minimum distance (the scan
 * stops at the first point that is not, so a generic query pays two evaluations). */
static void cc_equidistant_post(const cd_circle *c0, const cd_circle *c1, cd_best *b)
{
    if (b->equidistant || b->n == 0) return;
    const cd_circle *cs[2] = {c0, c1};
    double d = sqrt(b->c[0].d2), Cn = v_norm(v_sub(c1->c, c0->c));
    double L = fmax(fmax(c0->r, c1->r), Cn), tol = CC_EQUI_ULPS * DBL_EPSILON * L;
    for (int side = 0; side < 2; side++) {
        const cd_circle *me = cs[side], *other = cs[1 - side];
        if (other->r > 0 && me->r >= 0) {
            double rho;
            pc_dist(b->c[0].p[side], other, &rho);
            if (rho <= 8 * DBL_EPSILON * (me->r + other->r + Cn)) {
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
static int arcs_rise(const cd_circle *c, const cd_circle *other, double a, double b, double dbest, double tie)
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
static void cc_same_basin_filter(const cd_circle *c0, const cd_circle *c1, cd_best *b)
{
    double tie = CD_TIE_ULPS * DBL_EPSILON * b->scale;
    while (b->n >= 2 && !cd_best_is_equidistant(b)) {
        double dbest = sqrt(b->c[0].d2);
        if (sqrt(b->c[1].d2) - dbest > tie) return;
        const cd_cand *x = &b->c[0], *y = &b->c[1];
        double a0 = cd_circle_angle(c0, v_sub(x->p[0], c0->c)), b0 = cd_circle_angle(c0, v_sub(y->p[0], c0->c));
        double a1 = cd_circle_angle(c1, v_sub(x->p[1], c1->c)), b1 = cd_circle_angle(c1, v_sub(y->p[1], c1->c));
        if (arcs_rise(c0, c1, a0, b0, dbest, tie) || arcs_rise(c1, c0, a1, b1, dbest, tie)) return;
        for (int j = 1; j + 1 < b->n; j++) b->c[j] = b->c[j + 1];
        b->n--;
    }
}

/* Runs `method`; the robust method answers AUTO and is the fallback of a method that fails.
 * *answered: the method that produced the result. */
static cdist_status cc_core(cdist_query *q, cdist_method method, const cd_circle *c0, const cd_circle *c1,
                            cd_best *b, int *iterations, cdist_method *answered)
{
    if (iterations) *iterations = 0;
    cdist_status st = CDIST_ERR_INTERNAL;
    if (method == CDIST_METHOD_POLYNOMIAL) st = cd_cc_polynomial(q, c0, c1, b);
    else if (method == CDIST_METHOD_ITERATION) st = cd_cc_iteration(q, c0, c1, b, iterations);
    *answered = method;
    if (method == CDIST_METHOD_AUTO || method == CDIST_METHOD_ROBUST || st != CDIST_OK) {
        /* AUTO is the robust method (measured fastest and as exact); it is also the fallback. */
        cd_best_init(b, b->scale);
        if (iterations) *iterations = 0;
        *answered = CDIST_METHOD_ROBUST;
        st = cc_robust(q, c0, c1, b);
    } else {
        cc_equidistant_post(c0, c1, b);
    }
    if (st == CDIST_OK) cc_same_basin_filter(c0, c1, b);
    return st;
}

cdist_status cd_circle_circle_core(cdist_query *q, cdist_method method, const cd_circle *c0, const cd_circle *c1,
                                   cd_best *b, int *iterations)
{
    cdist_method answered;
    return cc_core(q, method, c0, c1, b, iterations, &answered);
}

/* Angles where A crosses B's axis (w(t) = 0), the non-smooth points of F. */
static int axis_crossings(const cc_frame *f, double *t)
{
    /* 2D coordinates in the plane orthogonal to m. */
    vec3 e1, e2;
    v_basis(f->m, &e1, &e2);
    double ax = v_dot(f->al, e1), ay = v_dot(f->al, e2), bx = v_dot(f->be, e1), by = v_dot(f->be, e2);
    double gx = -v_dot(f->ga, e1), gy = -v_dot(f->ga, e2); /* solve a c + b s = -ga */
    double det = ax * by - ay * bx, tol = 1e-9;
    double an = hypot(ax, ay), bn = hypot(bx, by);
    if (fabs(det) > 1e-12 * an * bn) {
        double c = (gx * by - gy * bx) / det, s = (ax * gy - ay * gx) / det;
        double r = hypot(c, s);
        if (fabs(r - 1) <= tol) {
            t[0] = atan2(s, c);
            return 1;
        }
        return 0;
    }
    /* a and b parallel: w(t) moves on a segment through ga along e. */
    double ex = an >= bn ? ax : bx, ey = an >= bn ? ay : by, en = hypot(ex, ey);
    if (!(en > 0)) return 0;
    ex /= en;
    ey /= en;
    double perp = -gx * ey + gy * ex; /* component of -ga across the segment */
    if (fabs(perp) > tol * (f->R + v_norm(f->C))) return 0;
    double pa = ax * ex + ay * ey, pb = bx * ex + by * ey, pg = gx * ex + gy * ey;
    double amp = hypot(pa, pb);
    if (!(amp > 0) || fabs(pg) > amp * (1 + tol)) return 0;
    double phi = atan2(pb, pa), dlt = acos(fmax(-1.0, fmin(1.0, pg / amp)));
    int n = 0;
    double cand[2] = {phi + dlt, phi - dlt};
    for (int i = 0; i < (dlt == 0 ? 1 : 2); i++) {
        double x = remainder(cand[i], 2 * M_PI);
        if (x <= -M_PI) x += 2 * M_PI;
        t[n++] = x;
    }
    return n;
}

int cd_circle_circle_critical(cdist_query *q, const cd_circle *c0, const cd_circle *c1, double *theta0, int cap)
{
    (void)q;
    if (cap < 0) cap = 0;
    if (c0->r == 0.0) return -1; /* a point: every angle gives the same point */
    vec3 C = v_sub(c1->c, c0->c);
    /* Angles do not change under scaling: work at L ~ 1 (see cc_robust). */
    int ex;
    frexp(fmax(fmax(c0->r, c1->r), v_norm(C)), &ex);
    double sc = ldexp(1.0, -ex);
    cd_circle a = *c0, b = *c1;
    a.c = v3(0, 0, 0);
    a.r *= sc;
    b.c = v_scale(sc, C);
    b.r *= sc;
    c0 = &a;
    c1 = &b;
    C = b.c;
    cc_frame f;
    frame_init(&f, c0, C, c1);
    cc_sink k = {.f = &f, .want_max = 1, .out = theta0, .cap = cap, .A = c0, .B = c1,
                 .Fmin = INFINITY, .dmin = INFINITY, .rho_min = INFINITY};
    double Fmax;
    scan(&f, &k, &Fmax);
    int n = k.count < cap ? k.count : cap;
    double L = fmax(fmax(c0->r, c1->r), v_norm(C));
    /* Constant F (also when F' never changes sign: a periodic F that is not constant has a
     * bracketed minimum and maximum). */
    if (k.count == 0 || sqrt(Fmax) - k.dmin <= CC_EQUI_ULPS * DBL_EPSILON * L) return -1;
    double tk[2];
    int nk = c1->r > 0 ? axis_crossings(&f, tk) : 0;
    for (int i = 0; i < nk; i++) {
        if (n < cap) theta0[n] = tk[i];
        n++;
    }
    return n < cap ? n : cap;
}

cdist_status cdist_circle_circle(cdist_query *q, const cdist_circle *c0, const cdist_circle *c1, cdist_result *r)
{
    cdist_status st = cd_check_handle(q, r);
    if (st) return st;
    cd_circle a, b;
    if ((st = cd_check_circle(q, c0, "first circle", &a)) || (st = cd_check_circle(q, c1, "second circle", &b)))
        return st;
    /* Work relative to the first centre. */
    vec3 offset = a.c;
    a.c = v3(0, 0, 0);
    b.c = v_sub(b.c, offset);
    cd_best best;
    cd_best_init(&best, fmax(fmax(a.r, b.r), v_norm(b.c)));
    cdist_method m = cd_pick_method(q, CD_HAS(CDIST_METHOD_POLYNOMIAL) | CD_HAS(CDIST_METHOD_ROBUST) |
                                           CD_HAS(CDIST_METHOD_ITERATION),
                                    CDIST_METHOD_AUTO);
    int iterations = 0;
    cdist_method answered;
    st = cc_core(q, m, &a, &b, &best, &iterations, &answered);
    if (st) return st;
    cd_best_to_result(&best, offset, 0, r);
    r->iterations = iterations;
    return cd_ok(q, r, answered);
}
