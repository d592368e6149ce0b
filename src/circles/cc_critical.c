/* SPDX-License-Identifier: MIT */
/* The critical-angle service of circle-circle (used by circle-disk and the arcs): every
 * critical angle of theta -> dist^2(c0(theta), c1), from the engine (docs/circles.md). */
#include <math.h>

#include "circles/circles-priv.h"

/* Angles where A crosses B's axis (w(t) = 0), the non-smooth points of F. */
CD_INLINE int axis_crossings(const cdist__cc_frame *f, double *t)
{
    /* 2D coordinates in the plane orthogonal to m. */
    vec3 e1, e2;
    v_basis(f->m, &e1, &e2);
    double ax = v_dot(f->rg.al, e1), ay = v_dot(f->rg.al, e2), bx = v_dot(f->rg.be, e1), by = v_dot(f->rg.be, e2);
    double gx = -v_dot(f->rg.ga, e1), gy = -v_dot(f->rg.ga, e2); /* solve a c + b s = -ga */
    double det = ax * by - ay * bx, tol = CD_CC_AXIS_UNIT_REL;
    double an = hypot(ax, ay), bn = hypot(bx, by);
    if (fabs(det) > CD_CC_AXIS_DET_REL * an * bn) {
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
    double phi = atan2(pb, pa), dlt = acos(cdist__fmax(-1.0, cdist__fmin(1.0, pg / amp)));
    int n = 0;
    double cand[2] = {phi + dlt, phi - dlt};
    for (int i = 0; i < (dlt == 0 ? 1 : 2); i++) {
        double x = remainder(cand[i], 2 * M_PI);
        if (x <= -M_PI) x += 2 * M_PI;
        t[n++] = x;
    }
    return n;
}

/* c0 at the origin and c1 relative to it, scaled as the robust method scales
 * (cdist__circles_scale, half = 1); returns the factor. Angles do not change under scaling. */
CD_INLINE double scaled_pair(const cdist__circle *c0, const cdist__circle *c1, cdist__circle *a, cdist__circle *b)
{
    vec3 C = v_sub(c1->c, c0->c);
    double up, sc;
    cdist__circles_scale(cdist__fmax(cdist__fmax(c0->r, c1->r), v_norm(C)), 1, &sc, &up);
    *a = *c0;
    *b = *c1;
    a->c = v3(0, 0, 0);
    a->r *= sc;
    b->c = v_scale(sc, C);
    b->r *= sc;
    return sc;
}

CD_FMA_CLONES int cdist__cc_quick_frame(const cdist__circle *c0, const cdist__circle *c1, cdist__cc_frame *f, double *sc)
{
    if (c0->r == 0.0 || c1->r == 0.0) return 0;
    cdist__circle a, b;
    *sc = scaled_pair(c0, c1, &a, &b);
    cdist__cc_frame_ring(f, &a, b.c, &b);
    return f->quick;
}

CD_FMA_CLONES double cdist__cc_quick_distance(const cdist__cc_frame *f, double sc, double c, double s)
{
    return cdist__cc_quick_unscale(cdist__cc_point_d2(&f->rg, f->s, c, s), sc);
}

CD_FMA_CLONES int cdist__circle_circle_critical(cdist_query *q, const cdist__circle *c0, const cdist__circle *c1, double dcap, double *theta0,
                                  int cap, int *sampled)
{
    (void)q;
    if (sampled) *sampled = 0;
    if (cap < 0) cap = 0;
    if (c0->r == 0.0) return -1; /* a point: every angle gives the same point */
    cdist__circle a, b;
    double sc = scaled_pair(c0, c1, &a, &b);
    c0 = &a;
    c1 = &b;
    vec3 C = b.c;
    cdist__cc_frame f;
    cdist__cc_frame_init(&f, c0, C, c1);
    /* Minima mode: the scan prunes against dmin, seeded with the cap (in the scaled units). */
    int minima = dcap < INFINITY;
    cdist__cc_sink k = {.f = &f, .want_max = !minima, .prune = minima, .out = theta0, .cap = cap, .A = c0, .B = c1,
                 .Fmin = INFINITY, .dmin = minima ? sc * dcap : INFINITY, .rho_min = INFINITY};
    double Fmax, tp[4];
    int np = cdist__cc_parallel_critical(&f, tp);
    if (np > 0) {
        double dlo = INFINITY, dhi = 0;
        for (int i = 0; i < np; i++) {
            cdist__cc_pt p;
            double c, s;
            sincos(tp[i], &s, &c);
            cdist__cc_eval_lean(&f, tp[i], c, s, &p);
            dlo = cdist__fmin(dlo, p.d);
            dhi = cdist__fmax(dhi, p.d);
            if (i < cap) theta0[i] = tp[i];
        }
        if (dhi - dlo <= CD_CC_EQUI_ULPS * DBL_EPSILON * f.L) return -1;
        return np < cap ? np : cap;
    }
    cdist__cc_scan(&f, &k, &Fmax);
    if (sampled) *sampled = k.sampled;
    int n = k.count < cap ? k.count : cap;
    double L = cdist__fmax(cdist__fmax(c0->r, c1->r), v_norm(C));
    /* Constant F (also when F' never changes sign: a periodic F that is not constant has a
     * bracketed minimum and maximum). */
    double tol = CD_CC_EQUI_ULPS * DBL_EPSILON * L;
    if (!minima) {
        if (k.count == 0 || sqrt(Fmax) - k.dmin <= tol) return -1;
    } else if (sqrt(Fmax) - sqrt(k.Fmin) <= tol && (k.count == 0 || sqrt(Fmax) - k.dmin <= tol)) {
        return -1; /* else no count means no minimum up to the cap */
    }
    /* The axis crossings, in the critical-angle mode only: transversal, F = smooth - 2 s rho has
     * a concave kink there (its left derivative exceeds its right one), never a minimum; tangent,
     * F is C^1 and the scan brackets its minima like any other. */
    double tk[2];
    int nk = c1->r > 0 && !minima ? axis_crossings(&f, tk) : 0;
    for (int i = 0; i < nk; i++) {
        if (n < cap) theta0[n] = tk[i];
        n++;
    }
    return n < cap ? n : cap;
}

/* Parallel planes (distance-to-circles-3d §5.2; docs/circles.md, "Parallel planes"): F's
 * critical angles in closed form. Writes them (up to 4), returns the count, or -1 when the
 * planes are not parallel (A's height over B's plane varies by more than CD_CC_PARALLEL_ULPS
 * eps L). */
int cdist__cc_parallel_critical(const cdist__cc_frame *f, double *t)
{
    if (!f->parallel) return -1;
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
