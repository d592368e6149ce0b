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
 * Root bounding (no polynomial is solved): H's nine Fourier coefficients are formed by exact
 * products of the coefficient arrays of Q, sigma and w.w', which gives rigorous bounds
 * M1 >= |H'|, M2 >= |H''| (sums of |k| |c_k| and k^2 |c_k|). [-pi, pi) is split into 16
 * intervals and each interval is subdivided until it is certified to hold
 *   - no root of H: a root t would need |H(a) + H'(a)(t-a)| <= M2 (t-a)^2 / 2 from both ends
 *     (tested at the midpoint, where the concave lower bounds are weakest), or |H(a)|+|H(b)| <=
 *     M1 (b-a); or
 *   - at most one root: H' keeps its sign, |H'(a)| + |H'(b)| > M2 (b-a),
 * with every value reduced by a first-order bound of its rounding error, or until it is
 * narrower than 2^-30 rad. Between two consecutive partition points F' then changes sign at most
 * once, so every local minimum of F is bracketed by a (-,+) sign pair of the true F' at
 * consecutive points; it is refined by safeguarded Newton/bisection on the true F' and offered
 * with the point-circle closest point on B. A narrow unresolved interval (near a multiple root,
 * e.g. where A crosses B's axis, a double root of H) can hide a min/max pair of F only with a
 * dip of order |F'''| (2^-30)^3, far below rounding. A concave kink of F (A crossing B's axis
 * transversally: F = smooth - 2 s |linear|) is never a local minimum; when A is tangent to
 * B's axis F is C^1 and the minimum there is bracketed like any other.
 * When H vanishes to rounding (coaxial circles, the constant cases below) or the subdivision
 * exceeds its budget, F' is sampled on 512 points instead.
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
 * Radius 0: a zero-radius circle is a point and the point-circle core answers. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "internal.h"

#define CC_INIT_INTERVALS 8
#define CC_MIN_WIDTH (1.0 / 1073741824.0) /* 2^-30 rad */
#define CC_EVAL_BUDGET 200
#define CC_DENSE_SAMPLES 512
#define CC_STACK 96
#define CC_EQUI_ULPS 32.0

#ifdef CC_STATS
long cc_stat_evals, cc_stat_refine_its, cc_stat_brackets, cc_stat_dense, cc_stat_leaves_narrow;
#define STAT(x) (x)
#else
#define STAT(x) ((void)0)
#endif

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
} cc_frame;

/* Values at one angle. */
typedef struct cc_pt {
    double t, c, s;
    double H, H1, H2; /* H, H', H'' */
    double F1;    /* F'/2 */
    double F;     /* F */
} cc_pt;

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
static void tp_mul(const tpoly *x, const tpoly *y, tpoly *z)
{
    tpoly r;
    tp_zero(&r);
    for (int i = 0; i < 9; i++) {
        if (x->re[i] == 0.0 && x->im[i] == 0.0) continue;
        for (int j = 0; j < 9; j++) {
            int k = i + j - 4;
            if (k < 0 || k > 8) continue;
            r.re[k] += x->re[i] * y->re[j] - x->im[i] * y->im[j];
            r.im[k] += x->re[i] * y->im[j] + x->im[i] * y->re[j];
        }
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
    f->ha = f->R * v_dot(m, A->u);
    f->hb = f->R * v_dot(m, A->v);
    f->hc = -v_dot(m, C);
    f->Cu = v_dot(C, A->u);
    f->Cv = v_dot(C, A->v);

    /* Fourier coefficients of Q, sigma, g = w.w' and H = Q sigma^2 - s^2 g^2. */
    double aa = v_dot(f->al, f->al), bb = v_dot(f->be, f->be), ab = v_dot(f->al, f->be);
    double ag = v_dot(f->al, f->ga), bg = v_dot(f->be, f->ga), gg = v_dot(f->ga, f->ga);
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
    tp_mul(&S, &S, &T);
    tp_mul(&Q, &T, &H);
    tp_mul(&G, &G, &T);
    double s2 = f->s * f->s;
    f->M1 = f->M2 = f->M3 = f->Hc = 0;
    for (int i = 0; i < 9; i++) {
        double c = hypot(H.re[i] - s2 * T.re[i], H.im[i] - s2 * T.im[i]);
        double k = fabs((double)(i - 4));
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
}

/* Hot-path arithmetic without fma(): the library is built for baseline x86-64, where fma() is a
 * libm call; plain products are accurate enough for sampling and Newton steps (the final
 * distance of each pair is recomputed in pair_at). */
static inline double dot3(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
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
        STAT(cc_stat_refine_its++);
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
#ifdef CC_TRACE
        fprintf(stderr, "it %d x %.17g F1 %.3g F2 %.3g newton %d dx %.3g\n", it, x, F1, F2, newton, dx);
#endif
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
    int dense_ok; /* on budget overflow: sample densely (else report the overflow) */
    double tmin, Fmin; /* partition point with the smallest F */
    double dmin;  /* smallest refined distance */
    double rho_min; /* axis distance of the point giving dmin */
} cc_sink;

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
    if (!k->swapped) cd_best_offer(k->best, d2, P, K, ta, tb);
    else cd_best_offer(k->best, d2, v_sub(K, f->C), v_sub(P, f->C), tb, ta); /* + c1's centre */
    double d = sqrt(d2);
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
    STAT(cc_stat_brackets++);
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

/* Certificates on [a, b] (see the header comment). 1: resolved (<= 1 root of H). First order
 * with the global bounds M1, M2; second order with the endpoint values of H'' and M3 (from each
 * end over half the interval, the cubic lower bound taken at its worst, x = w/2). */
static int certified(const cc_frame *f, const cc_pt *a, const cc_pt *b)
{
    double w = b->t - a->t, x = 0.5 * w;
    if ((a->H > 0 && b->H > 0) || (a->H < 0 && b->H < 0)) {
        double sg = a->H > 0 ? 1.0 : -1.0;
        double A = fabs(a->H) - f->eH, B = fabs(b->H) - f->eH;
        if (A > 0 && B > 0) {
            if (A + B > f->M1 * w) return 1;
            double la = A + (sg * a->H1 - f->eH1) * x - 0.5 * f->M2 * x * x;
            double lb = B - (sg * b->H1 + f->eH1) * x - 0.5 * f->M2 * x * x;
            if (la > 0 && lb > 0) return 1;
            double c3 = f->M3 * x * x * x / 6;
            la = A - (fmax(0.0, -sg * a->H1) + f->eH1) * x - (fmax(0.0, -sg * a->H2) + f->eH2) * 0.5 * x * x - c3;
            lb = B - (fmax(0.0, sg * b->H1) + f->eH1) * x - (fmax(0.0, -sg * b->H2) + f->eH2) * 0.5 * x * x - c3;
            if (la > 0 && lb > 0) return 1;
        }
    }
    if ((a->H1 > 0 && b->H1 > 0) || (a->H1 < 0 && b->H1 < 0)) {
        double sg = a->H1 > 0 ? 1.0 : -1.0;
        double A = fabs(a->H1) - f->eH1, B = fabs(b->H1) - f->eH1;
        if (A > 0 && B > 0) {
            if (A + B > f->M2 * w) return 1;
            double c2 = 0.5 * f->M3 * x * x;
            double la = A - (fmax(0.0, -sg * a->H2) + f->eH2) * x - c2;
            double lb = B - (fmax(0.0, sg * b->H2) + f->eH2) * x - c2;
            if (la > 0 && lb > 0) return 1;
        }
    }
    return 0;
}

/* Dense sampling fallback: F' signs on CC_DENSE_SAMPLES points. */
static void scan_dense(const cc_frame *f, cc_sink *k, double *Fmax)
{
    STAT(cc_stat_dense++);
    cc_pt first = {0}, prev = {0}, cur;
    double step = 2 * M_PI / CC_DENSE_SAMPLES;
    for (int i = 0; i <= CC_DENSE_SAMPLES; i++) {
        if (i == CC_DENSE_SAMPLES) {
            cur = first;
            cur.t = M_PI;
        } else {
            double t = -M_PI + i * step, c, s;
            sincos(t, &s, &c);
            cc_eval(f, t, c, s, &cur);
            if (cur.F > *Fmax) *Fmax = cur.F;
            if (cur.F < k->Fmin) {
                k->Fmin = cur.F;
                k->tmin = cur.t;
            }
        }
        if (i == 0) first = cur;
        else emit(k, &prev, &cur);
        prev = cur;
    }
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
        if (!k->dense_ok) return 1;
        scan_dense(f, k, Fmax);
        return 0;
    }

    /* Depth-first, left to right, so consecutive leaves share their endpoints: the current
     * interval is refined in place, right halves wait on the stack. */
    typedef struct {
        cc_pt b;
        int level;
    } ival;
    /* 1 / (2 cos(w/2)) for the interval width 2 pi / CC_INIT_INTERVALS / 2^level. */
    static const double half_sec[] = {
#define HS(l) 0.5 / cos(M_PI / CC_INIT_INTERVALS / (double)(1L << (l)))
        HS(0),  HS(1),  HS(2),  HS(3),  HS(4),  HS(5),  HS(6),  HS(7),  HS(8),  HS(9),  HS(10),
        HS(11), HS(12), HS(13), HS(14), HS(15), HS(16), HS(17), HS(18), HS(19), HS(20), HS(21),
        HS(22), HS(23), HS(24), HS(25), HS(26), HS(27), HS(28), HS(29), HS(30), HS(31)
#undef HS
    };
    ival st[CC_STACK];
    int evals = 0, over = 0;
    int saved_count = k->count;
    cd_best saved_best;
    double saved_dmin = k->dmin, saved_rho = k->rho_min;
    if (k->best) saved_best = *k->best;
    for (int i = 0; i < CC_INIT_INTERVALS && !over; i++) {
        cc_pt a = init[i], b = init[i + 1];
        int level = 0, sp = 0;
        for (;;) {
            if (a.F > *Fmax) *Fmax = a.F;
            if (a.F < k->Fmin) {
                k->Fmin = a.F;
                k->tmin = a.t;
            }
            double w = b.t - a.t;
            if (certified(f, &a, &b) || (w <= CC_MIN_WIDTH && (STAT(cc_stat_leaves_narrow++), 1))) {
                emit(k, &a, &b);
                if (sp == 0) break;
                a = b;
                b = st[--sp].b;
                level = st[sp].level;
                continue;
            }
            if (evals >= CC_EVAL_BUDGET || sp + 1 > CC_STACK || level >= 31) {
                over = 1;
                break;
            }
            /* Midpoint from the endpoint cosines/sines (no transcendental call). */
            double hc = half_sec[level];
            double cm = (a.c + b.c) * hc, sm = (a.s + b.s) * hc;
            cc_pt mid;
            cc_eval(f, 0.5 * (a.t + b.t), cm, sm, &mid);
            evals++;
            STAT(cc_stat_evals++);
            level++;
            st[sp].b = b;
            st[sp++].level = level;
            b = mid;
        }
    }
    if (over) {
        k->count = saved_count;
        k->dmin = saved_dmin;
        k->rho_min = saved_rho;
        k->Fmin = INFINITY;
        if (k->best) *k->best = saved_best;
        if (!k->dense_ok) return 1;
        scan_dense(f, k, Fmax);
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

/* The robust method. dense_ok = 0: when the certified scan gives up (multiple roots at the
 * rounding level, e.g. tangent circles), return with *over = 1 and b untouched so that AUTO can
 * ask the polynomial method; dense_ok = 1: fall back to dense sampling. */
static cdist_status cc_robust(cdist_query *q, const cd_circle *c0, const cd_circle *c1, cd_best *b, int dense_ok,
                              int *over)
{
    *over = 0;
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
                cd_best_offer(b, t.c[i].d2, v_add(t.c[i].p[0], C), v_add(t.c[i].p[1], C), t.c[i].param[0],
                              t.c[i].param[1]);
            if (t.equidistant) b->equidistant = 1;
        }
        return CDIST_OK;
    }
    cc_frame f;
    frame_init(&f, A, CB, B);
    cc_sink k = {.f = &f, .best = b, .swapped = sw, .A = A, .B = B, .dense_ok = dense_ok, .Fmin = INFINITY,
                 .dmin = INFINITY, .rho_min = INFINITY};
    double Fmax;
    if (scan(&f, &k, &Fmax)) {
        *over = 1;
        return CDIST_OK;
    }
    /* F' never went from - to +: F is constant to rounding; any point is a closest one. */
    if (b->n == 0 && isfinite(k.Fmin)) pair_at(&f, k.tmin, &k);
    if (b->n == 0 || !isfinite(k.dmin)) return cd_fail(q, CDIST_ERR_INTERNAL, "circle-circle: no minimum found");
    /* (a) F constant on A; (b) the closest point of A on B's axis. */
    if (sqrt(Fmax) - k.dmin <= CC_EQUI_ULPS * DBL_EPSILON * L) b->equidistant = 1;
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
    if (method == CDIST_METHOD_AUTO) {
        /* The certified robust scan; where it gives up (degenerate multiple roots) the
         * polynomial method, and the dense robust scan if that fails too. */
        int over;
        cd_best_init(b, b->scale);
        *answered = CDIST_METHOD_ROBUST;
        st = cc_robust(q, c0, c1, b, 0, &over);
        if (st != CDIST_OK || !over) return st;
        st = cd_cc_polynomial(q, c0, c1, b);
        if (st == CDIST_OK) {
            *answered = CDIST_METHOD_POLYNOMIAL;
            cc_equidistant_post(c0, c1, b);
            return st;
        }
        method = CDIST_METHOD_ROBUST;
    }
    if (method == CDIST_METHOD_ROBUST || st != CDIST_OK) {
        int over;
        cd_best_init(b, b->scale);
        if (iterations) *iterations = 0;
        *answered = CDIST_METHOD_ROBUST;
        st = cc_robust(q, c0, c1, b, 1, &over);
    } else {
        cc_equidistant_post(c0, c1, b);
    }
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
    cc_frame f;
    frame_init(&f, c0, C, c1);
    cc_sink k = {.f = &f, .want_max = 1, .out = theta0, .cap = cap, .A = c0, .B = c1, .dense_ok = 1,
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

cdist_status cdist_circle_circle_batch(cdist_query *q, size_t n, const cdist_circle *c0, const cdist_circle *c1,
                                       cdist_result *results, cdist_status *statuses)
{
    if (!q) return CDIST_ERR_NULL_ARGUMENT;
    if (n == 0) return cd_ok(q, &(cdist_result){0}, q->method);
    if (!c0 || !c1 || !results)
        return cd_fail(q, CDIST_ERR_NULL_ARGUMENT, "batch: circles or results pointer is NULL");
    cdist_status first = CDIST_OK;
    char first_msg[CD_MESSAGE_LEN] = "";
    for (size_t i = 0; i < n; i++) {
        cdist_status st = cdist_circle_circle(q, &c0[i], &c1[i], &results[i]);
        if (statuses) statuses[i] = st;
        if (st != CDIST_OK && first == CDIST_OK) {
            first = st;
            snprintf(first_msg, sizeof first_msg, "batch entry %zu: %.200s", i, q->message);
        }
    }
    if (first != CDIST_OK) return cd_fail(q, first, "%s", first_msg);
    return first;
}
