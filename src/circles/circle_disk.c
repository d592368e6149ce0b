/* SPDX-License-Identifier: MIT */
/* Circle to disk (point-curve-circle-to-disk §2-§4; derivations in docs/disk.md). Disk to disk
 * (disk_disk.c) runs this twice, rim of each against the other disk (the second time without
 * the rim-to-rim minima, which the first has found). The lemma it rests on (minima of the disk
 * distance are minima of the rim distance, or zeros or critical points of the height):
 * docs/circles.md. */
#include <math.h>
#include <pthread.h>
#include <string.h>

#include "circles/circles-priv.h"

/* ------------------------------------------------------------------------------------------ */
/* Circle to disk                                                                               */

typedef cdist__cdk cdk;

/* Half squared rim distance F = ((rho - R)^2 + z^2) / 2 along the circle: value, F', F''
 * (the ring evaluator; on the disk's axis F has a cusp, a maximum, where F'' is set to 1). */
static double cdk_rim_cs(const cdk *k, double cs, double sn, double *f1, double *f2)
{
    cdist__ring_val v;
    v.F1 = v.F2 = 0.0;
    cdist__ring_eval(&k->rg, k->g.R, cs, sn, f2 ? 2 : f1 ? 1 : 0, &v);
    if (f1) *f1 = v.F1;
    if (f2) *f2 = v.rho > 0.0 ? v.F2 : 1.0;
    return 0.5 * v.F;
}

static double cdk_rim(const cdk *k, double t, double *f1, double *f2)
{
    double sn, cs;
    sincos(t, &sn, &cs);
    return cdk_rim_cs(k, cs, sn, f1, f2);
}

/* Where the candidates go: b (the single query: pairs, points, angles) or, b NULL, only their
 * smallest squared distance (the batch kernel); d2 is b's best so far either way (the offers
 * drop only candidates above it), scale b's scale. */
typedef struct cdk_sink {
    const cdk *k;
    cdist__best *b;
    double d2, scale;
} cdk_sink;

/* The pair of an offer (cd_body.h): the circle point and its closest disk point (the
 * projection onto the plane, or the rim point over it). */
CD_INLINE void cdk_offer_pair(void *ctx, double t, double cs, double sn, double x, double y, double z, double ex,
                              double rho, double d2)
{
    const cdk_sink *o = ctx;
    const cdk *k = o->k;
    vec3 P = v_axpy(v_scale(k->g.rho * cs, k->A), k->g.rho * sn, k->B);
    vec3 K;
    if (ex <= 0.0) {
        K = v_axpy(P, -z, k->n); /* the projection onto the plane */
    } else {
        double s = k->g.R / rho;
        K = v_axpy(v_axpy(k->D, s * x, k->u), s * y, k->v);
    }
    cdist__best_offer(o->b, d2, P, K, k->g.rho > 0.0 ? cdist__wrap_angle(t) : NAN, cdist__polar_angle(x, y));
}

#define CDK_OFFER_PAIR cdk_offer_pair
#define CD_LANES 1
#include "base/lanes/lanes_def.h"
#include "base/lanes/lanes_vec.h"
#include "circles/cd_body.h"
#include "base/lanes/lanes_undef.h"

/* The circle as the ring evaluator sees it (w = (x, y, 0), h = z). */
CD_INLINE void cdk_ring(cdk *k)
{
    k->rg = (cdist__ring){v3(k->g.X[1], k->g.Y[1], 0.0), v3(k->g.X[2], k->g.Y[2], 0.0), v3(k->g.X[0], k->g.Y[0], 0.0),
                          k->g.Z[1], k->g.Z[2], k->g.Z[0]};
}

CD_INLINE void cdk_init(cdk *k, const cdist__circle *c, const cdist__circle *d)
{
    vec3 D = d->c;
    k->c = c;
    k->d = d;
    k->D = D;
    k->n = d->n;
    k->u = d->u;
    k->v = d->v;
    k->A = c->u;
    k->B = c->v;
    const double Dv[3] = {D.x, D.y, D.z}, dn[3] = {d->n.x, d->n.y, d->n.z}, du[3] = {d->u.x, d->u.y, d->u.z},
                 dv[3] = {d->v.x, d->v.y, d->v.z}, cu[3] = {c->u.x, c->u.y, c->u.z}, cv[3] = {c->v.x, c->v.y, c->v.z};
    cdk_lanes_init_1(&k->g, Dv, dn, du, dv, cu, cv, c->r, d->r);
    cdk_ring(k);
    /* Delta . Delta' = (P - D) . P' = -D . P' since |P| is constant. */
    double r = c->r;
    k->S[0] = 0.0; k->S[1] = -r * v_dot(D, c->v); k->S[2] = r * v_dot(D, c->u);
}

/* Offer the circle point at angle t, (cs, sn) = (cos t, sin t), with its closest disk point (the
 * true point-disk distance); nothing when its distance is far above the best (CD_CD_FAR_REL). */
CD_INLINE void cdk_offer_cs(const cdk *k, double t, double cs, double sn, cdk_sink *o)
{
    cdk_offer_1(&k->g, 1, t, cs, sn, &o->d2, o->scale, o->b ? o : NULL);
}

CD_INLINE void cdk_offer(const cdk *k, double t, cdk_sink *o)
{
    double sn, cs;
    sincos(t, &sn, &cs);
    cdk_offer_cs(k, t, cs, sn, o);
}

/* Bracketed root of F' in [a, b] with sg F'(a) < 0 < sg F'(b) (sg = 1: a minimum of F, -1: a
 * maximum): Newton steps kept inside the bracket, bisection otherwise. */
static double cdk_bracket_sg(const cdk *k, double a, double b, double sg, double fa, double fb)
{
    /* Start from the secant point when the end values are known. */
    double t = 0.5 * (a + b);
    if (isfinite(fa) && isfinite(fb) && fb != fa) {
        double ts = a - fa * (b - a) / (fb - fa);
        if (ts > a && ts < b) t = ts;
    }
    for (int it = 0; it < 100; it++) {
        double f1, f2;
        cdk_rim(k, t, &f1, &f2);
        f1 *= sg;
        f2 *= sg;
        if (f1 == 0.0) return t;
        if (f1 < 0.0) a = t;
        else b = t;
        double tn = (f2 > 0.0) ? t - f1 / f2 : 0.5 * (a + b);
        if (!(tn > a && tn < b)) tn = 0.5 * (a + b);
        if (fabs(tn - t) <= 2.0 * DBL_EPSILON * (1.0 + fabs(t)) || b - a <= 4.0 * DBL_EPSILON * (1.0 + fabs(t))) {
            t = tn;
            break;
        }
        t = tn;
    }
    return t;
}

static double cdk_bracket(const cdk *k, double a, double b) { return cdk_bracket_sg(k, a, b, 1.0, NAN, NAN); }

/* (c0 + c1 cos t + c2 sin t)(1 + tau^2) as a quadratic in tau = tan(t/2), ascending. */
static void trig_to_quad(const double *c, double s, double *q)
{
    q[0] = (c[0] + c[1]) * s;
    q[1] = 2.0 * c[2] * s;
    q[2] = (c[0] - c[1]) * s;
}

/* Critical points of F by the degree-8 polynomial (point-curve-circle-to-disk §4.3, in the
 * half-angle variable): F' = 0 <=> S rho = R T, squared: (x^2+y^2) S^2 - R^2 T^2 = 0, with
 * T = x x' + y y'. Returns the number of angles written, or -1 when F is constant, -2 on failure. */
static int cdk_poly_critical(cdist_query *q, const cdk *k, double *ts)
{
    double s = cdist__fmax(cdist__fmax(k->g.rho, k->g.R), cdist__fmax(fabs(k->g.X[0]), cdist__fmax(fabs(k->g.Y[0]), fabs(k->g.Z[0]))));
    if (!(s > 0.0)) return 0;
    s = 1.0 / s;
    double dX[3] = {0.0, k->g.X[2], -k->g.X[1]}, dY[3] = {0.0, k->g.Y[2], -k->g.Y[1]};
    double qx[3], qy[3], qxp[3], qyp[3], qs[3];
    trig_to_quad(k->g.X, s, qx);
    trig_to_quad(k->g.Y, s, qy);
    trig_to_quad(dX, s, qxp);
    trig_to_quad(dY, s, qyp);
    trig_to_quad(k->S, s * s, qs);
    double xx[5], yy[5], xxp[5], yyp[5], rho2[5], T[5], S2[5], a[9], bq[9];
    cdist__poly_mul(qx, 2, qx, 2, 1, xx);
    cdist__poly_mul(qy, 2, qy, 2, 1, yy);
    cdist__poly_mul(qx, 2, qxp, 2, 1, xxp);
    cdist__poly_mul(qy, 2, qyp, 2, 1, yyp);
    for (int i = 0; i < 5; i++) {
        rho2[i] = xx[i] + yy[i];
        T[i] = xxp[i] + yyp[i];
    }
    cdist__poly_mul(qs, 2, qs, 2, 1, S2);
    cdist__poly_mul(rho2, 4, S2, 4, 1, a);
    cdist__poly_mul(T, 4, T, 4, 1, bq);
    double R2 = (k->g.R * s) * (k->g.R * s);
    for (int i = 0; i < 9; i++) a[i] = fma(-R2, bq[i], a[i]);
    double roots[8];
    int nr = cdist__poly_real_roots(q->poly, a, 8, CD_CD_POLY_IMAG_TOL, roots);
    if (nr == CD_POLY_ZERO) return -1;
    if (nr < 0) return -2;
    int n = 0;
    for (int i = 0; i < nr; i++) ts[n++] = 2.0 * atan(roots[i]);
    ts[n++] = M_PI; /* tau = infinity is not a root of the polynomial in tau */
    return n;
}

/* The local minimum of F reached by walking downhill from t: steps doubling from h0 (CD_CD_SHELL) until F'
 * changes sign, then the bracketed solver on the true derivative. */
static double cdk_descend(const cdk *k, double t, double h0)
{
    double f1;
    cdk_rim(k, t, &f1, NULL);
    if (f1 == 0.0) return t;
    double dir = f1 < 0.0 ? 1.0 : -1.0, prev = t;
    for (double h = h0; h < 4.0; h *= 2.0) {
        double tn = t + dir * h, g;
        cdk_rim(k, tn, &g, NULL);
        if (dir > 0.0 ? g >= 0.0 : g <= 0.0) return dir > 0.0 ? cdk_bracket(k, prev, tn) : cdk_bracket(k, tn, prev);
        prev = tn;
    }
    return prev;
}

/* cos and sin of the shells' offsets CD_CD_SHELL 2^j, j < 36 (cdk_scan), computed once */
static struct {
    double c[36], s[36];
} cdk_shell;
static pthread_once_t cdk_shell_once = PTHREAD_ONCE_INIT;
static void cdk_shell_init(void)
{
    for (int j = 0; j < 36; j++) sincos(CD_CD_SHELL * cdist__pow2(j), &cdk_shell.s[j], &cdk_shell.c[j]);
}

/* Minima of F hidden in [a, b] next to the critical point t1 (a minimum-maximum-minimum cluster
 * narrower than the sampling): F' at t1 -+ CD_CD_SHELL 2^j covers every dyadic shell around t1,
 * so the sign change of a neighbour at distance >= 2 CD_CD_SHELL is seen (closer ones differ
 * from F(t1) by ~1e-36 of scale^2). Every - to + change away from t1 is bracketed and solved. */
static int cdk_scan(const cdk *k, double t1, double a, double b, double *out, int cap)
{
    double p[2 * 36 + 3], f[2 * 36 + 3];
    int m = 0, jl = 0, jr = 0;
    pthread_once(&cdk_shell_once, cdk_shell_init);
    /* F' at the shells from cos and sin of t1 by rotation (exact to rounding, one sincos
     * instead of one per point: this scan was most of a flat query's time) */
    double c1, s1;
    sincos(t1, &s1, &c1);
    p[m++] = a;
    cdk_rim(k, a, &f[0], NULL);
    while (jl < 34 && CD_CD_SHELL * cdist__pow2(jl + 1) < t1 - a) jl++;
    for (int j = jl; j >= 0; j--)
        if (t1 - CD_CD_SHELL * cdist__pow2(j) > a) {
            cdk_rim_cs(k, c1 * cdk_shell.c[j] + s1 * cdk_shell.s[j], s1 * cdk_shell.c[j] - c1 * cdk_shell.s[j], &f[m], NULL);
            p[m++] = t1 - CD_CD_SHELL * cdist__pow2(j);
        }
    int i1 = m;
    cdk_rim_cs(k, c1, s1, &f[m], NULL);
    p[m++] = t1;
    while (jr < 34 && CD_CD_SHELL * cdist__pow2(jr + 1) < b - t1) jr++;
    for (int j = 0; j <= jr; j++)
        if (t1 + CD_CD_SHELL * cdist__pow2(j) < b) {
            cdk_rim_cs(k, c1 * cdk_shell.c[j] - s1 * cdk_shell.s[j], s1 * cdk_shell.c[j] + c1 * cdk_shell.s[j], &f[m], NULL);
            p[m++] = t1 + CD_CD_SHELL * cdist__pow2(j);
        }
    cdk_rim(k, b, &f[m], NULL);
    p[m++] = b;
    int n = 0;
    for (int i = 0; i + 1 < m && n < cap; i++) {
        if (i == i1 - 1 || i == i1) continue; /* the brackets touching t1 hold t1 itself */
        if (f[i] < 0.0 && f[i + 1] >= 0.0) out[n++] = cdk_bracket(k, p[i], p[i + 1]);
    }
    return n;
}

/* Critical points of F by sampling F' on a uniform grid, and a bracketed Newton/bisection on
 * every sign change from - to + (a minimum of F). Returns the number of angles written. */
#define CDK_SAMPLES 48
#define CDK_CAP 48
static const double cdk_grid_cs[CDK_SAMPLES][2] = {
    {-1, -1.2246467991473532e-16},
    {-0.99144486137381038, -0.13052619222005157},
    {-0.9659258262890682, -0.25881904510252102},
    {-0.92387953251128674, -0.38268343236508989},
    {-0.86602540378443871, -0.49999999999999994},
    {-0.79335334029123505, -0.60876142900872088},
    {-0.70710678118654746, -0.70710678118654757},
    {-0.60876142900872066, -0.79335334029123517},
    {-0.50000000000000022, -0.86602540378443849},
    {-0.38268343236508973, -0.92387953251128674},
    {-0.25881904510252063, -0.96592582628906831},
    {-0.1305261922200516, -0.99144486137381038},
    {6.123233995736766e-17, -1},
    {0.13052619222005171, -0.99144486137381038},
    {0.25881904510252074, -0.96592582628906831},
    {0.38268343236508962, -0.92387953251128685},
    {0.49999999999999989, -0.86602540378443871},
    {0.60876142900872077, -0.79335334029123505},
    {0.70710678118654757, -0.70710678118654746},
    {0.79335334029123505, -0.60876142900872077},
    {0.86602540378443871, -0.49999999999999983},
    {0.92387953251128674, -0.38268343236508978},
    {0.9659258262890682, -0.25881904510252091},
    {0.99144486137381038, -0.13052619222005188},
    {1, 0},
    {0.99144486137381038, 0.13052619222005188},
    {0.9659258262890682, 0.25881904510252091},
    {0.92387953251128674, 0.38268343236508978},
    {0.86602540378443871, 0.49999999999999983},
    {0.79335334029123505, 0.60876142900872077},
    {0.70710678118654791, 0.70710678118654724},
    {0.60876142900872077, 0.79335334029123505},
    {0.50000000000000033, 0.86602540378443849},
    {0.38268343236508939, 0.92387953251128696},
    {0.25881904510252052, 0.96592582628906831},
    {0.13052619222005149, 0.99144486137381038},
    {6.123233995736766e-17, 1},
    {-0.13052619222005138, 0.99144486137381049},
    {-0.25881904510252041, 0.96592582628906842},
    {-0.38268343236508928, 0.92387953251128696},
    {-0.50000000000000022, 0.86602540378443849},
    {-0.60876142900871999, 0.79335334029123572},
    {-0.70710678118654746, 0.70710678118654757},
    {-0.79335334029123505, 0.60876142900872088},
    {-0.86602540378443849, 0.50000000000000033},
    {-0.92387953251128685, 0.38268343236508945},
    {-0.96592582628906809, 0.25881904510252146},
    {-0.99144486137381038, 0.13052619222005157},
};
static int cdk_robust_critical(const cdk *k, double *ts, int cap, double scale)
{
    double f1s[CDK_SAMPLES + 1], Fs[CDK_SAMPLES + 1];
    const double h = CD_TWO_PI / CDK_SAMPLES;
    for (int i = 0; i < CDK_SAMPLES; i++) Fs[i] = cdk_rim_cs(k, cdk_grid_cs[i][0], cdk_grid_cs[i][1], &f1s[i], NULL);
    f1s[CDK_SAMPLES] = f1s[0];
    Fs[CDK_SAMPLES] = Fs[0];
    double Fmin = Fs[0];
    for (int i = 1; i < CDK_SAMPLES; i++) Fmin = cdist__fmin(Fmin, Fs[i]);
    /* A cluster can only hold the global minimum where F is within this margin of the best. */
    double margin = Fmin + 0.01 * scale * scale;
    double flat = CD_CD_FLAT_REL * k->g.rho * scale;
    int n = 0;
    for (int i = 0; i < CDK_SAMPLES && n < cap; i++) {
        double a = -M_PI + i * h, b = a + h;
        double t1;
        if (f1s[i] < 0.0 && f1s[i + 1] >= 0.0) {
            t1 = (f1s[i + 1] == 0.0) ? b : cdk_bracket_sg(k, a, b, 1.0, f1s[i], f1s[i + 1]);
            ts[n++] = t1;
        } else if (f1s[i] > 0.0 && f1s[i + 1] <= 0.0 && cdist__fmin(Fs[i], Fs[i + 1]) <= margin) {
            /* A maximum: minima may hide on both sides of it. */
            t1 = cdk_bracket_sg(k, a, b, -1.0, -f1s[i], -f1s[i + 1]);
        } else {
            continue;
        }
        /* Only a flat extremum can have a hidden neighbour: F' ~ c (t - t1)(t - m)(t - t2) gives
         * |F''(t1)| ~ c w^2 for a cluster of width w below the grid step. */
        double f2;
        cdk_rim(k, t1, NULL, &f2);
        if (cdist__fmin(Fs[i], Fs[i + 1]) <= margin && fabs(f2) <= flat) n += cdk_scan(k, t1, a, b, ts + n, cap - n);
    }
    /* Safety net: downhill from the smallest sample. */
    int im = 0;
    for (int i = 1; i < CDK_SAMPLES; i++)
        if (Fs[i] < Fs[im]) im = i;
    if (n < cap) ts[n++] = cdk_descend(k, -M_PI + im * h, h / 256);
    return n;
}

/* The polynomial candidates, each walked downhill to a true minimum of F; the best ones are
 * scanned for hidden neighbours (a root cluster that the QR resolves only to ~eps^(1/3)). */
static int cdk_poly_minima(cdist_query *q, const cdk *k, double *ts, int cap, double scale)
{
    double roots[16];
    int nr = cdk_poly_critical(q, k, roots);
    if (nr < 0) return nr;
    int n = 0;
    double Fbest = INFINITY;
    double Fv[16], f2v[16], flat = CD_CD_FLAT_REL * k->g.rho * scale;
    for (int i = 0; i < nr && n < cap; i++) {
        double f1, f2;
        cdk_rim(k, roots[i], &f1, &f2);
        /* A clean maximum: its neighbouring minima are roots of their own. */
        if (f2 < -flat && fabs(f1) <= CD_CD_MAX_SLOPE_REL * fabs(f2)) continue;
        /* An extraneous root of the squared equation (S rho = -R T, where F' = 2 S) or the real
         * part of a complex pair far from any critical point: F' is of the order rho L there,
         * while a root of F' (even one of a cluster, resolved to ~eps^(1/3)) has |F'| ~ 1e-15 --
         * unless F'' is huge (a disk much smaller than the circle: features of width R / rho), so
         * a seed whose Newton step is short is kept. */
        if (fabs(f1) > CD_CD_ROOT_SLOPE_REL * k->g.rho * scale && !(f2 > 0.0 && fabs(f1) < CD_CD_ROOT_STEP * f2)) continue;
        ts[n] = cdk_descend(k, roots[i], CD_CD_SHELL);
        Fv[n] = cdk_rim(k, ts[n], NULL, &f2v[n]);
        Fbest = cdist__fmin(Fbest, Fv[n]);
        n++;
    }
    int n0 = n;
    for (int i = 0; i < n0 && n < cap; i++)
        if (Fv[i] <= Fbest + 0.01 * scale * scale && fabs(f2v[i]) <= flat)
            n += cdk_scan(k, ts[i], ts[i] - 0.15, ts[i] + 0.15, ts + n, cap - n);
    return n;
}

/* Parallel planes (within rounding): closed forms (docs/disk.md). Returns 1 when handled. */

static int cdk_parallel(const cdk *k, cdk_sink *o)
{
    if (!cdk_parallel_1(&k->g)) return 0;
    double ex = k->g.X[0], ey = k->g.Y[0], e = cdist__norm2(ex, ey);
    double rho = k->g.rho, R = k->g.R;
    double tol = 8.0 * DBL_EPSILON * cdist__fmax(cdist__fmax(rho, R), e);
    /* Angle on the circle of the point whose projection is nearest the disk centre: direction
     * -E in the disk plane, expressed in the circle's basis. */
    vec3 Ein = v_axpy(v_scale(ex, k->u), ey, k->v); /* circle centre's projection relative to D */
    double t0;
    if (e <= tol) {
        t0 = 0.0;
        cdk_offer(k, t0, o);
        if (rho > 0.0) o->b->equidistant = 1;
        return 1;
    }
    t0 = atan2(-v_dot(Ein, k->B), -v_dot(Ein, k->A));
    cdk_offer(k, t0, o);
    if (fabs(e - rho) < R && rho > 0.0 && R > 0.0) o->b->equidistant = 1; /* an arc lies over the face */
    return 1;
}


/* The candidates at the extremes and zeros of the height (cd_body.h). */
CD_INLINE void cdk_height(const cdk *k, cdk_sink *o)
{
    cdk_height_1(&k->g, &o->d2, o->scale, o->b ? o : NULL);
}

/* Whether the certified minimum of the rim distance, dq, can be the answer or tie with it: the
 * engine's own cut-off in minima mode (cc_scan.c), the cap and a tie. */
CD_INLINE int cdk_rim_below_cap(double dq, double dcap, double scale)
{
    return dq <= dcap * (1 + 8 * DBL_EPSILON) + CD_TIE_ULPS * DBL_EPSILON * scale;
}

/* The minima of F at ts[0 .. n) (their cos and sin into tc, tsn) and the neighbours of the flat
 * ones near the best: a neighbour of a cluster below the certification width (multiple roots) is
 * looked for by the dyadic scan. Returns the new count (the scan's minima after the n). */
static int cdk_flat_scan(const cdk *k, double *ts, double *tc, double *tsn, int n, double scale)
{
    double Fv[CDK_CAP], f2v[CDK_CAP], Fbest = INFINITY, flat = CD_CD_FLAT_REL * k->g.rho * scale;
    for (int i = 0; i < n; i++) {
        sincos(ts[i], &tsn[i], &tc[i]);
        Fv[i] = cdk_rim_cs(k, tc[i], tsn[i], NULL, &f2v[i]);
        Fbest = cdist__fmin(Fbest, Fv[i]);
    }
    int n0 = n;
    for (int i = 0; i < n0 && n < CDK_CAP; i++)
        if (Fv[i] <= Fbest + 0.01 * scale * scale && fabs(f2v[i]) <= flat)
            n += cdk_scan(k, ts[i], ts[i] - 0.15, ts[i] + 0.15, ts + n, CDK_CAP - n);
    return n;
}

/* Offer the minima of F at ts[0 .. n), the first nc at their cos and sin tc, tsn. */
CD_INLINE void cdk_offer_minima(const cdk *k, const double *ts, const double *tc, const double *tsn, int n, int nc,
                                cdk_sink *o)
{
    for (int i = 0; i < n; i++) {
        if (i < nc) cdk_offer_cs(k, ts[i], tc[i], tsn[i], o);
        else cdk_offer(k, ts[i], o);
    }
}

CD_INLINE cdist_status cdk_solve(cdist_query *q, cdist_method method, const cdk *k, cdist__best *b, double dcap0, int rim,
                                 cdist_method *used, int *rim_certified)
{
    cdk_sink o = {k, b, INFINITY, b->scale};
    *used = method;
    *rim_certified = 1; /* the parallel closed forms */
    if (cdk_parallel(k, &o)) return CDIST_OK;
    *rim_certified = 0;
    cdk_height(k, &o);
    /* Critical points of the rim distance (not asked for: the caller has them, see
     * cdist__circle_disk_core_ex). */
    if (!rim) return CDIST_OK;
    double ts[CDK_CAP], tc[CDK_CAP], tsn[CDK_CAP]; /* angles, and cos, sin of the first nc of them */
    int nc = 0;
    double scale = cdk_scale_1(&k->g);
    int n = -2;
    if (method == CDIST_METHOD_POLYNOMIAL) {
        n = cdk_poly_minima(q, k, ts, CDK_CAP, scale);
        if (n == -1) n = 0; /* F constant: the rim gives no isolated candidate; z candidates rule */
    }
    if (n < 0) {
        /* ROBUST: every critical angle of F with certified root isolation (circle-circle robust
         * method, Fourier bounds on the squared derivative, docs/circles.md), the rim being a
         * circle; its own sampling as the fallback. */
        *used = CDIST_METHOD_ROBUST;
        /* Only the minima of F matter (the lemma), and only those below the best candidate so
         * far (a z candidate, whose distance is the true one): the engine prunes the rest. */
        double dcap = o.d2 < INFINITY ? cdist__fmin(dcap0, sqrt(o.d2)) : dcap0, tq, cq, sq, sc;
        cdist__cc_frame f;
        if (cdk_rim_far_1(&k->g, dcap, scale)) {
            n = 0;
            *rim_certified = 1;
        } else if (cdist__cc_quick_frame(k->c, k->d, &f, &sc) && cdist__cc_quick(&f, &tq, &cq, &sq)) {
            /* F's global minimum, certified unique: the one minimum of F that can hold G's (a
             * minimum of G on the rim side is a global minimum of F, by the lemma, since
             * G <= F); the others lie above it by the certificate's margin */
            *rim_certified = 1;
            n = 0;
            if (cdk_rim_below_cap(cdist__cc_quick_distance(&f, sc, cq, sq), dcap, scale)) {
                ts[0] = cdist__cc_param(tq);
                n = 1;
            }
        } else {
            int sampled;
            n = cdist__circle_circle_critical(q, k->c, k->d, dcap, ts, CDK_CAP, &sampled);
            /* Certified for disk-disk's second half only where no region was merely sampled:
             * there (windows of a near-axis crossing, exhausted budgets) F' may be rounding
             * noise and the minima mode polishes nothing on F itself, while the other rim,
             * searched from the other side, may be well conditioned. */
            *rim_certified = (n >= 0 || n == -1) && !sampled;
        }
        if (n == -1) {
            n = 0; /* F constant: the rim gives no isolated candidate; z candidates rule */
            ts[n++] = 0.0;
        } else if (n == 0 && dcap < INFINITY) {
            /* no minimum of F below the cap: the z candidates rule */
        } else if (n <= 0) {
            *rim_certified = 0; /* the sampling fallback */
            n = cdk_robust_critical(k, ts, CDK_CAP, scale);
        } else {
            nc = n;
            n = cdk_flat_scan(k, ts, tc, tsn, n, scale);
        }
    }
    cdk_offer_minima(k, ts, tc, tsn, n, nc, &o);
    return CDIST_OK;
}

void cdist__cd_stage_ring(cdist__cd_stage *st)
{
    cdk *k = &st->k;
    k->c = &st->c;
    k->d = &st->d;
    cdk_ring(k);
}

CD_FMA_CLONES void cdist__cd_stage_finish(cdist__cd_stage *st, double t, double d2)
{
    if (!cdk_rim_below_cap(cdist__cc_quick_unscale(d2, st->sc), st->dcap, st->scale)) return;
    double ts[CDK_CAP], tc[CDK_CAP], tsn[CDK_CAP];
    ts[0] = cdist__cc_param(t);
    int n = cdk_flat_scan(&st->k, ts, tc, tsn, 1, st->scale);
    cdk_sink o = {&st->k, NULL, st->d2, st->bscale};
    cdk_offer_minima(&st->k, ts, tc, tsn, n, 1, &o);
    st->d2 = o.d2;
}

/* Circle c (centre at the origin) to disk d (centre relative to c's). An FMA clone: the fma()
 * of the frame, the offers and the dot products are instructions there. */
CD_FMA_CLONES static cdist_status circle_disk_solve(cdist_query *q, cdist_method method, const cdist__circle *c, const cdist__circle *d,
                                      double dcap, int rim, cdist__best *b, cdist_method *used, int *rim_certified)
{
    *used = method;
    *rim_certified = 1; /* the closed forms below */
    if (c->r == 0.0) {
        /* The circle is its centre (the origin): point to disk, points relative to d's centre. */
        cdist__best t;
        cdist__best_init(&t, b->scale);
        cdist__point_disk_core(v_neg(d->c), d, &t, 0);
        for (int i = 0; i < t.n; i++) t.c[i].param[0] = NAN;
        cdist__best_merge(b, &t, d->c, 0);
        b->equidistant = cdist__best_is_equidistant(&t);
        return CDIST_OK;
    }
    if (d->r == 0.0) {
        /* The disk is its centre: point to circle. */
        cdist__point_circle_core(d->c, c, b, 1);
        return CDIST_OK;
    }
    cdk k;
    cdk_init(&k, c, d);
    return cdk_solve(q, method, &k, b, dcap, rim, used, rim_certified);
}

/* Solved into a fresh collector, then merged into b: b may already hold other candidates (a
 * caller combining several objects), and an equidistant set here only makes b equidistant when
 * it attains b's minimum. */
cdist_status cdist__circle_disk_core_ex(cdist_query *q, cdist_method method, const cdist__circle *c, const cdist__circle *d,
                                     double dcap, int rim, cdist__best *b, cdist_method *used, int *rim_certified)
{
    int cert_dummy;
    if (!rim_certified) rim_certified = &cert_dummy;
    cdist__best t;
    cdist__best_init(&t, b->scale);
    /* b's best so far is attained too: no minimum above it can be the answer */
    if (b->n > 0) dcap = cdist__fmin(dcap, sqrt(b->c[0].d2));
    cdist_status st = circle_disk_solve(q, method, c, d, dcap, rim, &t, used, rim_certified);
    if (st) return st;
    double d2 = cdist__best_merge(b, &t, v3(0, 0, 0), 0);
    if (cdist__best_is_equidistant(&t)) cdist__best_settle_equidistant(b, d2);
    return CDIST_OK;
}

/* The scaled problem (c at the origin): the core, then r written in full (the objects' order
 * is the caller's: swap unused). */
static cdist_status circle_disk_query(cdist_query *q, cdist__circle a, cdist__circle e, int swap, cdist_result *r,
                                      cdist_method *used)
{
    (void)swap;
    vec3 offset;
    cdist__best best;
    int ex = cdist__circles_frame(&a, &e, &offset, &best);
    cdist_status st = cdist__circle_disk_core_ex(q, cdist__family_method(q, CD_FAM_CIRCLE_DISK), &a, &e, INFINITY, 1, &best, used, NULL);
    if (st) return st;
    if (best.n == 0) return cdist__fail(q, CDIST_ERR_INTERNAL, "circle-disk found no candidate");
    cdist__circles_result(&best, 0, ex, offset, r);
    return CDIST_OK;
}

cdist_status cdist_circle_disk(cdist_query *q, const cdist_circle *c, const cdist_circle *d, cdist_result *r)
{
    return cdist__circles_entry(q, c, "circle", d, "disk", CD_FAM_CIRCLE_DISK, circle_disk_query, r);
}
