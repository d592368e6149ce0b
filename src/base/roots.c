/* SPDX-License-Identifier: MIT */
/* The out-of-line solvers of the root and minimum module (declarations and conventions in
 * roots.h): the Halley solver's 1-lane instance behind its callback, and the derivative-free
 * ones. Brent's zeroin and fmin follow R. P. Brent, "Algorithms for Minimization without
 * Derivatives" (1973), ch. 4 and 5. */
#include "base/roots.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#define CD_LANES 1
#include "base/lanes/lanes_def.h"
#include "base/roots_halley.h"
#include "base/lanes/lanes_undef.h"

double cdist__root_halley_accel(cdist__fd2f_fn fd2f, const void *ctx, double lo, double hi, double x0, int dir, double rel,
                              double abs, int max_iter)
{
    halley_1 s = halley_start_1(lo, hi, x0, 1);
    for (int it = 0; it < max_iter && s.act; it++) {
        double df, d2f, f = fd2f(ctx, s.x, &df, &d2f);
        if (dir < 0) f = -f, df = -df, d2f = -d2f;
        halley_step_1(&s, f, df, d2f, rel, abs);
    }
    return s.act ? s.x : s.res;
}

double cdist__root_brent(cdist__f_fn f, const void *ctx, double a, double fa, double b, double fb, double rel, double abs,
                     int max_iter, double *fx)
{
    if (fa != fa || fb != fb) return NAN;
    double c = a, fc = fa, d = b - a, e = d;
    for (int it = 0; it < max_iter; it++) {
        if ((fb > 0) == (fc > 0)) {
            c = a;
            fc = fa;
            d = e = b - a;
        }
        if (fabs(fc) < fabs(fb)) {
            a = b; b = c; c = a;
            fa = fb; fb = fc; fc = fa;
        }
        double tol = rel * fabs(b) + abs;
        double m = 0.5 * (c - b);
        if (fabs(m) <= tol || fb == 0.0) break;
        if (fabs(e) >= tol && fabs(fa) > fabs(fb)) {
            double p, q, r, s = fb / fa;
            if (a == c) {
                p = 2.0 * m * s;
                q = 1.0 - s;
            } else {
                q = fa / fc;
                r = fb / fc;
                p = s * (2.0 * m * q * (q - r) - (b - a) * (r - 1.0));
                q = (q - 1.0) * (r - 1.0) * (s - 1.0);
            }
            if (p > 0) q = -q;
            else p = -p;
            if (2.0 * p < fmin(3.0 * m * q - fabs(tol * q), fabs(e * q))) {
                e = d;
                d = p / q;
            } else {
                d = m;
                e = m;
            }
        } else {
            d = m;
            e = m;
        }
        a = b;
        fa = fb;
        b += (fabs(d) > tol) ? d : (m > 0 ? tol : -tol);
        fb = f(ctx, b);
        if (fb != fb) return NAN;
    }
    if (fx) *fx = fb;
    return b;
}

double cdist__min_brent(cdist__f_fn f, const void *ctx, double a, double b, double rel, double abs, int max_iter,
                    double *fmin)
{
    const double cgold = 0.3819660112501051; /* (3 - sqrt 5) / 2 */
    if (a > b) {
        double t = a;
        a = b;
        b = t;
    }
    double x = a + cgold * (b - a), w = x, v = x;
    double fxv = f(ctx, x);
    if (fxv != fxv) return NAN;
    double fw = fxv, fv = fxv, d = 0.0, e = 0.0;
    for (int it = 0; it < max_iter; it++) {
        double xm = 0.5 * (a + b), tol1 = rel * fabs(x) + abs, tol2 = 2.0 * tol1;
        if (fabs(x - xm) <= tol2 - 0.5 * (b - a)) break;
        int golden = 1;
        if (fabs(e) > tol1) {
            /* parabola through x, w, v */
            double r = (x - w) * (fxv - fv), q = (x - v) * (fxv - fw), p = (x - v) * q - (x - w) * r;
            q = 2.0 * (q - r);
            if (q > 0.0) p = -p;
            else q = -q;
            double etemp = e;
            e = d;
            if (!(fabs(p) >= fabs(0.5 * q * etemp) || p <= q * (a - x) || p >= q * (b - x))) {
                d = p / q;
                double u = x + d;
                if (u - a < tol2 || b - u < tol2) d = (xm - x >= 0.0) ? tol1 : -tol1;
                golden = 0;
            }
        }
        if (golden) {
            e = (x >= xm) ? a - x : b - x;
            d = cgold * e;
        }
        double u = (fabs(d) >= tol1) ? x + d : x + (d >= 0.0 ? tol1 : -tol1);
        double fu = f(ctx, u);
        if (fu != fu) return NAN;
        if (fu <= fxv) {
            if (u >= x) a = x;
            else b = x;
            v = w; fv = fw;
            w = x; fw = fxv;
            x = u; fxv = fu;
        } else {
            if (u < x) a = u;
            else b = u;
            if (fu <= fw || w == x) {
                v = w; fv = fw;
                w = u; fw = fu;
            } else if (fu <= fv || v == x || v == w) {
                v = u; fv = fu;
            }
        }
    }
    if (fmin) *fmin = fxv;
    return x;
}

double cdist__min_golden(cdist__f_fn f, const void *ctx, double lo, double hi, double abs, int max_iter, double *fmin)
{
    const double g = 0.6180339887498949;
    double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
    double f1 = f(ctx, x1), f2 = f(ctx, x2);
    for (int it = 0; it < max_iter && hi - lo > abs; it++) {
        if (f1 != f1 || f2 != f2) return NAN;
        if (f1 < f2) {
            hi = x2, x2 = x1, f2 = f1, x1 = hi - g * (hi - lo);
            f1 = f(ctx, x1);
        } else {
            lo = x1, x1 = x2, f1 = f2, x2 = lo + g * (hi - lo);
            f2 = f(ctx, x2);
        }
    }
    if (f1 != f1 || f2 != f2) return NAN;
    if (fmin) *fmin = (f1 < f2) ? f1 : f2;
    return (f1 < f2) ? x1 : x2;
}
