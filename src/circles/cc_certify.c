/* SPDX-License-Identifier: MIT */
/* The certificates of the circle-circle scan (docs/circles.md): on an interval of the
 * subdivision, at most one root of H (certified), no critical point of F (monotone), one minimum
 * of F (convex), and the concave hull lower bound of F (hull bounds). */
#include <math.h>
#include <string.h>

#include "circles/circles-priv.h"

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
 * (less their rounding bounds) and a bound M >= |F''/2| on [a, b] (the bounds: docs/circles.md,
 * "The bounds of F's derivatives"). */
int cdist__cc_monotone(const cdist__cc_frame *f, cdist__cc_pt *a, cdist__cc_pt *b)
{
    if (!((a->F1 > 0 && b->F1 > 0) || (a->F1 < 0 && b->F1 < 0))) return 0;
    cc_detail(f, a);
    cc_detail(f, b);
    double A = fabs(a->F1) - a->eF1, B = fabs(b->F1) - b->eF1;
    if (!(A > 0 && B > 0)) return 0;
    double w = b->t - a->t, W1 = f->W1, rlo, rhi;
    if (!rho_range(f, a, b, &rlo, &rhi)) return 0;
    double M = W1 * W1 + (rhi + f->s) * (rhi * W1 + 2 * W1 * W1) / rlo + f->Hh * (2 * f->Hh + f->Hc0);
    return A + B > M * w * (1 + CD_CC_CERT_REL);
}

/* At most one critical point of F on [a, b], a minimum: F is convex there, certified by F''/2 at
 * the ends (less rounding) and M3 >= |F'''/2| on [a, b] (docs/circles.md, as above). Answers at
 * a minimum where H has a root cluster (both of its factors vanish nearby). */
int cdist__cc_convex(const cdist__cc_frame *f, cdist__cc_pt *a, cdist__cc_pt *b)
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
    return cdist__fmin(A, B) > 0.5 * M3 * w * (1 + CD_CC_CERT_REL);
}

#define POS(x) ((x) > 0 ? (x) : 0.0)
/* Certificates on [a, b] (see the header comment). 1: resolved (<= 1 root of H). First order
 * with the global bounds M1, M2; second order with the endpoint values of H'' and M3 (from each
 * end over half the interval, the cubic lower bound taken at its worst, x = w/2). */
int cdist__cc_certified(const cdist__cc_frame *f, cdist__cc_pt *a, cdist__cc_pt *b)
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
const double cdist__cc_half_sec[32] = {
    0.54119610014619701, 0.50979557910415918, 0.50241928618815568, 0.50060299823519627,
    0.50015063602065102, 0.50003765191554772, 0.50000941253588782, 0.50000235310628605,
    0.50000058827484117, 0.50000014706860219, 0.50000003676714377, 0.50000000919178555,
    0.50000000229794639, 0.50000000057448657, 0.50000000014362167, 0.50000000003590539,
    0.50000000000897638, 0.50000000000224409, 0.500000000000561, 0.50000000000014033,
    0.50000000000003508, 0.50000000000000877, 0.50000000000000222, 0.50000000000000056,
    0.50000000000000011, 0.50000000000000011, 0.5, 0.5,
    0.5, 0.5, 0.5, 0.5,
};

/* A lower bound of F on the arc [a, b] of width 2 pi / CC_INIT_INTERVALS / 2^level:
 * min(F(a), F(b), G(T)) of F's concave extension G at the tangents' intersection T, minus a
 * margin for rounding (may be negative); why: docs/circles.md, "The hull bound". */
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

/* The bound on an arc [a, b] with half secant hs = 1 / (2 cos((b - a) / 2)). */
double cdist__cc_hull_bound(const cdist__cc_frame *f, const cdist__cc_pt *a, const cdist__cc_pt *b, double hs)
{
    return arc_hull_bound(f, a->c, a->s, b->c, b->s, cdist__fmin(a->F, b->F), hs);
}

/* The bound on the window [t - h, t + h] (h <= 0.1) around a near-crossing. */
double cdist__cc_window_hull_bound(const cdist__cc_frame *f, double t, double h)
{
    double ct, st, ch, sh;
    sincos(t, &st, &ct);
    cdist__cc_small_sincos(h, &sh, &ch);
    cdist__cc_pt a, b;
    cdist__cc_eval_lean(f, t - h, ct * ch + st * sh, st * ch - ct * sh, &a);
    cdist__cc_eval_lean(f, t + h, ct * ch - st * sh, st * ch + ct * sh, &b);
    return arc_hull_bound(f, a.c, a.s, b.c, b.s, cdist__fmin(a.F, b.F), 0.5 / ch);
}
