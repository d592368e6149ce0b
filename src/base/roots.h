/* SPDX-License-Identifier: MIT */
/* The one root and minimum module of the library (every family's solvers go through it).
 *
 * A family describes its function by a callback and a context pointer:
 *     cdist__fdf_fn: f(x) returned, f'(x) written to *df   (Newton's polishing)
 *     cdist__fd2f_fn: the same, and f''(x) written to *d2f   (Halley's steps)
 *     cdist__f_fn:   f(x) returned                         (derivative-free Brent solvers)
 * A callback that fails (e.g. a user curve returning an error) returns NaN and records the
 * reason in its context; every solver then stops and returns NaN.
 *
 * Tolerances: a solver stops when its step is below rel * |x| + ... or abs (see each); the
 * library's defaults are CD_ROOT_REL_ULPS * eps and CD_ROOT_ABS (src/base/tolerances.h), for
 * problems scaled to L in [1, 2) (src/base/numeric.h).
 *
 * cdist__root_halley_accel is written once over lanes (roots_halley.h): roots.c holds its
 * 1-lane instance behind the callback, and a hot family (line-circle, its batch kernels)
 * instantiates the same step with its evaluator inlined. cdist__root_polish is always inlined
 * (specialised for its callback); the Brent solvers are out of line (roots.c). */
#ifndef CDIST_BASE_ROOTS_H
#define CDIST_BASE_ROOTS_H

#include <math.h>

#include "base/numeric.h"
#include "base/tolerances.h"

typedef double (*cdist__fdf_fn)(const void *ctx, double x, double *df);
typedef double (*cdist__f_fn)(const void *ctx, double x);
typedef double (*cdist__fd2f_fn)(const void *ctx, double x, double *df, double *d2f);

/* Root of f in [lo, hi] where f increases through zero (dir = +1: f(lo) <= 0 <= f(hi)) or
 * decreases (dir = -1), the ends' values not needed, for a hot family (line-circle): rtsafe's
 * bracket and safeguards with Halley's steps, started at x0 (the midpoint when x0 is not inside
 * (lo, hi), e.g. NaN), and its accelerations (the last step of a fast convergence not evaluated,
 * multiple roots extrapolated, a root at a bracket end approached 1023/1024 of the way):
 * docs/lines.md, "The solver". Converged when a step is below rel * |x| or abs, or the bracket is
 * below abs; differs from rtsafe's answer by less than that. Returns lo when lo >= hi, NaN when
 * the callback failed. The callback also writes f''; f, f', f'' may all be multiplied by one
 * positive factor, which can vary with x (only signs and the ratios f / f', f f'' / f'^2 are
 * used). Commutes with x -> -x for an odd f and a mirrored x0. */
double cdist__root_halley_accel(cdist__fd2f_fn fd2f, const void *ctx, double lo, double hi, double x0, int dir, double rel,
                              double abs, int max_iter);

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
