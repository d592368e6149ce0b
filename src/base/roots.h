/* SPDX-License-Identifier: MIT */
/* The one root and minimum module of the library (every family's solvers go through it).
 *
 * A family describes its function by a callback and a context pointer:
 *     cdist__fdf_fn: f(x) returned, f'(x) written to *df   (for the Newton-based solvers)
 *     cdist__f_fn:   f(x) returned                         (derivative-free Brent solvers)
 * A callback that fails (e.g. a user curve returning an error) returns NaN and records the
 * reason in its context; every solver then stops and returns NaN.
 *
 * Tolerances: a solver stops when its step is below rel * |x| + ... or abs (see each); the
 * library's defaults are CD_ROOT_REL_ULPS * eps and CD_ROOT_ABS (src/base/tolerances.h), for
 * problems scaled to L in [1, 2) (src/base/numeric.h).
 *
 * cdist__root_newton, cdist__root_newton_accel and cdist__root_polish are always inlined so that a
 * hot family (line-circle) gets them specialised for its callback (the call through the pointer
 * is inlined away); the Brent solvers are out of line (roots.c). */
#ifndef CDIST_BASE_ROOTS_H
#define CDIST_BASE_ROOTS_H

#include <math.h>

#include "base/numeric.h"
#include "base/tolerances.h"

typedef double (*cdist__fdf_fn)(const void *ctx, double x, double *df);
typedef double (*cdist__f_fn)(const void *ctx, double x);

/* Root of f in [lo, hi] where f increases through zero (dir = +1: f(lo) <= 0 <= f(hi)) or
 * decreases (dir = -1), the ends' values not needed. Safeguarded Newton (rtsafe): starts at the
 * midpoint, and a Newton step is taken only when dir * f' > 0, it stays strictly inside the
 * bracket, and it shrinks faster than bisection would; otherwise the bracket is bisected.
 * Converged when a Newton step is below rel * |x| or abs, or the bracket is below abs.
 * Every operation commutes with x -> -x for an odd f, so mirrored brackets give mirrored
 * roots. Returns lo when lo >= hi, NaN when the callback failed. */
CD_INLINE double cdist__root_newton(cdist__fdf_fn fdf, const void *ctx, double lo, double hi, int dir, double rel,
                                 double abs, int max_iter)
{
    if (!(lo < hi)) return lo;
    double x = 0.5 * (lo + hi), dxold = hi - lo, dx = dxold;
    for (int it = 0; it < max_iter; it++) {
        double df, f = fdf(ctx, x, &df);
        if (f != f) return NAN;
        if (dir < 0) {
            f = -f;
            df = -df;
        }
        if (f == 0.0) return x;
        if (f < 0.0) lo = x;
        else hi = x;
        double step = f / df, xn = x - step;
        if (df > 0.0 && (fabs(step) <= rel * fabs(x) || fabs(step) <= abs)) return xn; /* converged */
        if (!(df > 0.0) || !(xn > lo && xn < hi) || fabs(2.0 * f) > fabs(dxold * df)) {
            dxold = dx;
            xn = 0.5 * (lo + hi);
            dx = fabs(xn - x);
        } else {
            dxold = dx;
            dx = fabs(xn - x);
        }
        x = xn;
        if (dx <= rel * fabs(x) || !(hi - lo > abs)) break;
    }
    return x;
}

/* cdist__root_newton with accelerations, for a hot family (line-circle); same bracket
 * safeguards, and it differs from cdist__root_newton's answer by less than the tolerance:
 * - it starts at x0 (a caller's estimate; the midpoint when x0 is not inside (lo, hi), e.g. NaN);
 * - the last step of a quadratic convergence: with e' = C e^2, C estimated from the last two
 *   Newton steps (C = |step| / |prev|^2), when the step after this one would be below the
 *   tolerance with a margin of 4, the point after this step is returned without evaluating
 *   there;
 * - a root that may be multiple (a tangency, where f ~ (x - x*)^m and a Newton step only shrinks
 *   the error by (m - 1)/m): when two successive Newton steps shrank by a steady ratio q in
 *   [1/2, 1), the step is taken 1/(1 - q) = m times (exact for an m-fold root), or, past the
 *   bracket's end, 63/64 of the way there;
 * - a root at an end of the bracket (a Newton step lands on or past it): 1023/1024 of the way
 *   there instead of a bisection, every other time.
 * At a simple root inside the bracket the steps are cdist__root_newton's. Commutes with
 * x -> -x for an odd f (and mirrored x0) as cdist__root_newton does. */
CD_INLINE double cdist__root_newton_accel(cdist__fdf_fn fdf, const void *ctx, double lo, double hi, double x0,
                                          int dir, double rel, double abs, int max_iter)
{
    if (!(lo < hi)) return lo;
    double x = (x0 > lo && x0 < hi) ? x0 : 0.5 * (lo + hi), dxold = hi - lo, dx = dxold;
    /* the last two Newton steps' lengths (0: none since a bisection or an extrapolation); the
     * ratios q = |step| / p1 and p1 / p2 are compared multiplied out, without a division in
     * the loop's chain */
    double p1 = 0.0, p2 = 0.0;
    int jumped = 0; /* the last step went to near an end of the bracket */
    for (int it = 0; it < max_iter; it++) {
        double df, f = fdf(ctx, x, &df);
        if (f != f) return NAN;
        if (dir < 0) {
            f = -f;
            df = -df;
        }
        if (f == 0.0) return x;
        if (f < 0.0) lo = x;
        else hi = x;
        double step = f / df, xn = x - step, as = fabs(step);
        if (df > 0.0 && (as <= rel * fabs(x) || as <= abs)) return xn; /* converged */
        int past = df > 0.0 && !(xn > lo && xn < hi);
        if (past && !jumped) {
            /* Newton lands on or past an end: the root is at that end within rounding (F' of a
             * line through the axis is linear up to it; near a tangency it flattens there), and
             * bisection would take ~60 steps to reach it. A point 1023/1024 of the way to that
             * end shrinks the bracket 1024 times when so, and costs one step otherwise (every
             * other such step bisects, so the bracket at least halves every two steps). */
            dxold = dx;
            xn = (xn >= hi) ? hi - 0x1p-10 * (hi - x) : lo + 0x1p-10 * (x - lo);
            dx = fabs(xn - x);
            p1 = p2 = 0.0;
            jumped = 1;
        } else if (!(df > 0.0) || past || fabs(2.0 * f) > fabs(dxold * df)) {
            dxold = dx;
            xn = 0.5 * (lo + hi);
            dx = fabs(xn - x);
            p1 = p2 = 0.0;
            jumped = 0;
        } else {
            jumped = 0;
            /* quadratic: q <= 1/4 and the next step, 4 q^2 |step|, below the tolerance */
            if (4.0 * as <= p1 && 4.0 * (as * as) * as <= cdist__fmax(rel * fabs(xn), abs) * (p1 * p1)) return xn;
            /* linear with a steady q in [1/2, 1): |q - p1/p2| <= q/8 */
            if (2.0 * as >= p1 && as < p1 && fabs(as * p2 - p1 * p1) <= 0.125 * (as * p2)) {
                double xm = x - step * (p1 / (p1 - as)); /* the step times m = 1 / (1 - q) */
                /* beyond the bracket: the m-fold point lies past its end (at a tangency F' has
                 * its inflection there) */
                if (!(xm < hi)) xm = hi - 0x1p-6 * (hi - x);
                if (!(xm > lo)) xm = lo + 0x1p-6 * (x - lo);
                xn = xm;
                p1 = p2 = 0.0; /* measure the ratio afresh after an extrapolated step */
            } else {
                p2 = p1;
                p1 = as;
            }
            dxold = dx;
            dx = fabs(xn - x);
        }
        x = xn;
        if (dx <= rel * fabs(x) || !(hi - lo > abs)) break;
    }
    return x;
}

/* Newton on f from x (a root estimate, e.g. from a polynomial), a step kept only while |f|
 * decreases; stops when a step is below rel * |x| or abs (abs = 0, rel = 0: only the |f| test).
 * Returns the polished x (x itself when no step helped), NaN when the callback failed. */
CD_INLINE double cdist__root_polish(cdist__fdf_fn fdf, const void *ctx, double x, double rel, double abs,
                                    int max_iter)
{
    double df, f = fdf(ctx, x, &df);
    if (f != f) return NAN;
    for (int it = 0; it < max_iter && f != 0.0; it++) {
        if (!(df != 0.0) || !isfinite(df)) break;
        double xn = x - f / df, dfn;
        double fn = fdf(ctx, xn, &dfn);
        if (fn != fn) return NAN;
        if (!(fabs(fn) < fabs(f))) break;
        double dx = fabs(xn - x);
        x = xn;
        f = fn;
        df = dfn;
        if (dx <= rel * fabs(x) || dx <= abs) break;
    }
    return x;
}

/* Root of f in [a, b] with f(a) = fa, f(b) = fb of opposite signs (or one zero), without
 * derivatives: Brent's zeroin (inverse quadratic / secant steps, bisection whenever they do not
 * shrink the bracket fast enough). Stops when the bracket half-width is below
 * rel * |x| + abs. Writes f at the returned root to *fx (may be NULL; that is the last value
 * evaluated there, or fa/fb). Returns NaN when the callback failed. */
double cdist__root_brent(cdist__f_fn f, const void *ctx, double a, double fa, double b, double fb, double rel, double abs,
                     int max_iter, double *fx);

/* Local minimum of f on [a, b]: Brent's method (parabolic steps through the three best
 * points, golden-section steps when a parabola is not trustworthy). Stops when the bracket
 * around the best point is within 2 (rel * |x| + abs). Writes f at the minimum to *fmin (may be
 * NULL). Returns NaN when the callback failed. abs should exceed the noise of f's argmin,
 * about sqrt(eps) * |b - a| for a smooth f (a parabola cannot resolve below it). */
double cdist__min_brent(cdist__f_fn f, const void *ctx, double a, double b, double rel, double abs, int max_iter,
                    double *fmin);

/* Golden-section search for a minimum of f on [lo, hi] (no parabolic steps: for functions
 * whose values are accurate but whose shape is not smooth at the scale of the bracket). Stops
 * when the bracket is below abs or after max_iter steps. Same conventions. */
double cdist__min_golden(cdist__f_fn f, const void *ctx, double lo, double hi, double abs, int max_iter, double *fmin);

#endif
