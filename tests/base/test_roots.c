/* SPDX-License-Identifier: MIT */
/* The root and minimum module (src/base/roots.h) and the numeric helpers (src/base/numeric.h),
 * against closed forms: built against the internal library. */
#include <float.h>
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "internal.h"

static int evals;

/* The reference for the Halley solver's step counts and answers: plain safeguarded Newton
 * (rtsafe). Root of f in [lo, hi] where f increases through zero (dir = +1) or decreases
 * (dir = -1): starts at the midpoint, and a Newton step is taken only when dir * f' > 0, it
 * stays strictly inside the bracket, and it shrinks faster than bisection would; otherwise the
 * bracket is bisected.
 * Converged when a Newton step is below rel * |x| or abs, or the bracket is below abs.
 * Every operation commutes with x -> -x for an odd f, so mirrored brackets give mirrored
 * roots. Returns lo when lo >= hi, NaN when the callback failed. */
static double rtsafe(cdist__fdf_fn fdf, const void *ctx, double lo, double hi, int dir, double rel, double abs, int max_iter)
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


/* f(x) = x^3 - 2 (root 2^(1/3)), f' = 3 x^2 */
static double cube_fdf(const void *ctx, double x, double *df)
{
    (void)ctx;
    evals++;
    *df = 3 * x * x;
    return x * x * x - 2;
}
static double cube_f(const void *ctx, double x)
{
    double d;
    return cube_fdf(ctx, x, &d);
}
/* the same with f'' = 6 x, for the Halley solver */
static double cube_fd2f(const void *ctx, double x, double *df, double *d2f)
{
    *d2f = 6 * x;
    return cube_fdf(ctx, x, df);
}
/* a triple root: f(x) = (x - 0.3)^3 + 1e-12 (x - 0.3) (root 0.3, as F' near a tangent line) */
static double triple_fdf(const void *ctx, double x, double *df)
{
    (void)ctx;
    evals++;
    double u = x - 0.3;
    *df = 3 * u * u + 1e-12;
    return u * u * u + 1e-12 * u;
}
static double triple_fd2f(const void *ctx, double x, double *df, double *d2f)
{
    *d2f = 6 * (x - 0.3);
    return triple_fdf(ctx, x, df);
}
/* a nearly double root: f = (x - 0.4) |x - 0.4| + 1e-12 (x - 0.4) (Halley's steps shrink the error
 * by only 1/3 there) */
static double double_fd2f(const void *ctx, double x, double *df, double *d2f)
{
    (void)ctx;
    evals++;
    double u = x - 0.4;
    *df = 2 * fabs(u) + 1e-12;
    *d2f = u >= 0 ? 2 : -2;
    return u * fabs(u) + 1e-12 * u;
}
/* an odd triple root (x^3), for the mirror symmetry */
static double odd_fdf(const void *ctx, double x, double *df)
{
    (void)ctx;
    *df = 3 * x * x + 1e-9;
    return x * x * x + 1e-9 * x;
}
/* a root at the end of the bracket: f(x) = 2 (x + 0.75), as F' of a line through a circle's axis */
static double lin_fdf(const void *ctx, double x, double *df)
{
    (void)ctx;
    evals++;
    *df = 2.0;
    return 2.0 * (x + 0.75);
}
static double lin_fd2f(const void *ctx, double x, double *df, double *d2f)
{
    *d2f = 0.0;
    return lin_fdf(ctx, x, df);
}
/* -cos(x - a): minimum at a */
static double cosmin(const void *ctx, double x) { return -cos(x - *(const double *)ctx); }
/* a failing callback */
static double fail_fdf(const void *ctx, double x, double *df)
{
    (void)ctx;
    *df = 1;
    return x > 0.5 ? NAN : x - 0.7;
}
static double fail_fd2f(const void *ctx, double x, double *df, double *d2f)
{
    *d2f = 0.0;
    return fail_fdf(ctx, x, df);
}
static double odd_fd2f(const void *ctx, double x, double *df, double *d2f)
{
    *d2f = 6 * x;
    return odd_fdf(ctx, x, df);
}

int main(void)
{
    const double c = cbrt(2.0), rel = CD_ROOT_REL_ULPS * DBL_EPSILON;
    evals = 0;
    double x = rtsafe(cube_fdf, NULL, 0.0, 5.0, +1, rel, CD_ROOT_ABS, CD_ROOT_MAX_ITER);
    CHECK(fabs(x - c) <= 4 * DBL_EPSILON, "rtsafe: %.17g vs %.17g", x, c);
    CHECK(evals < 40, "rtsafe took %d evaluations", evals);
    /* an empty bracket */
    x = rtsafe(cube_fdf, NULL, 5.0, 0.0, +1, rel, CD_ROOT_ABS, CD_ROOT_MAX_ITER);
    CHECK(x == 5.0, "empty bracket returns lo");
    x = cdist__root_polish(cube_fdf, NULL, 1.3, rel, CD_ROOT_ABS, CD_POLISH_MAX_ITER);
    CHECK(fabs(x - c) <= 4 * DBL_EPSILON, "polish: %.17g vs %.17g", x, c);
    double fx;
    x = cdist__root_brent(cube_f, NULL, 0.0, -2.0, 5.0, 123.0, rel, 0.0, 200, &fx);
    CHECK(fabs(x - c) <= 8 * DBL_EPSILON && fabs(fx) <= 16 * DBL_EPSILON, "brent root: %.17g vs %.17g", x, c);
    double a = 1.234, fm;
    x = cdist__min_brent(cosmin, &a, 0.0, 3.0, 0.0, 1e-9, 200, &fm);
    CHECK(fabs(x - a) <= 2e-8 && fabs(fm + 1) <= 1e-15, "brent min: %.17g vs %.17g", x, a);
    x = cdist__min_golden(cosmin, &a, 0.0, 3.0, 1e-9, 200, &fm);
    CHECK(fabs(x - a) <= 2e-8 && fabs(fm + 1) <= 1e-15, "golden min: %.17g vs %.17g", x, a);
    x = rtsafe(fail_fdf, NULL, 0.0, 1.0, +1, rel, CD_ROOT_ABS, CD_ROOT_MAX_ITER);
    CHECK(isnan(x), "failing callback gives NaN (%g)", x);
    /* the Halley variant: same answers on a simple root in fewer steps than Newton, and far
     * fewer steps on multiple roots (plain Newton shrinks the error by only 2/3 per step on a
     * triple one) */
    int plain;
    evals = 0;
    x = cdist__root_halley_accel(cube_fd2f, NULL, 0.0, 5.0, NAN, +1, rel, CD_ROOT_ABS, CD_ROOT_MAX_ITER);
    CHECK(fabs(x - c) <= 4 * DBL_EPSILON && evals < 40, "halley_accel simple: %.17g vs %.17g (%d)", x, c, evals);
    evals = 0;
    x = rtsafe(cube_fdf, NULL, 1.0, 1.5, +1, rel, CD_ROOT_ABS, CD_ROOT_MAX_ITER);
    plain = evals;
    evals = 0;
    x = cdist__root_halley_accel(cube_fd2f, NULL, 1.0, 1.5, NAN, +1, rel, CD_ROOT_ABS, CD_ROOT_MAX_ITER);
    CHECK(fabs(x - c) <= 4 * DBL_EPSILON && evals < plain, "halley_accel from the midpoint: %.17g (%d evaluations, Newton %d)",
          x, evals, plain);
    /* a start within 1e-4 of the root: two evaluations (the second step is predicted below the tolerance) */
    evals = 0;
    x = cdist__root_halley_accel(cube_fd2f, NULL, 1.0, 1.5, c + 1e-4, +1, rel, CD_ROOT_ABS, CD_ROOT_MAX_ITER);
    CHECK(fabs(x - c) <= 4 * DBL_EPSILON && evals == 2, "halley_accel from a close start: %.17g (%d evaluations)", x,
          evals);
    evals = 0;
    x = rtsafe(triple_fdf, NULL, -0.9, 1.0, +1, rel, CD_ROOT_ABS, CD_ROOT_MAX_ITER);
    plain = evals;
    CHECK(fabs(x - 0.3) <= 1e-9, "newton triple: %.17g", x);
    evals = 0;
    x = cdist__root_halley_accel(triple_fd2f, NULL, -0.9, 1.0, NAN, +1, rel, CD_ROOT_ABS, CD_ROOT_MAX_ITER);
    CHECK(fabs(x - 0.3) <= 1e-9, "halley_accel triple: %.17g", x);
    CHECK(2 * evals <= plain, "halley_accel took %d evaluations on a triple root, plain Newton %d", evals, plain);
    x = cdist__root_halley_accel(triple_fd2f, NULL, 0.2, 5.0, NAN, +1, rel, CD_ROOT_ABS, CD_ROOT_MAX_ITER);
    CHECK(fabs(x - 0.3) <= 1e-9, "halley_accel triple near the bracket end: %.17g", x);
    evals = 0;
    x = cdist__root_halley_accel(double_fd2f, NULL, -0.7, 1.0, NAN, +1, rel, CD_ROOT_ABS, CD_ROOT_MAX_ITER);
    CHECK(fabs(x - 0.4) <= 1e-9 && evals <= 30, "halley_accel double root: %.17g (%d evaluations)", x, evals);
    double xl = cdist__root_halley_accel(odd_fd2f, NULL, -0.7, 0.3, NAN, +1, rel, CD_ROOT_ABS, CD_ROOT_MAX_ITER);
    double xr = cdist__root_halley_accel(odd_fd2f, NULL, -0.3, 0.7, NAN, +1, rel, CD_ROOT_ABS, CD_ROOT_MAX_ITER);
    CHECK(xl == -xr && fabs(xl) <= 1e-12, "halley_accel mirrored brackets: %g %g", xl, xr);
    xl = cdist__root_halley_accel(odd_fd2f, NULL, -0.7, 0.3, -0.01, +1, rel, CD_ROOT_ABS, CD_ROOT_MAX_ITER);
    xr = cdist__root_halley_accel(odd_fd2f, NULL, -0.3, 0.7, 0.01, +1, rel, CD_ROOT_ABS, CD_ROOT_MAX_ITER);
    CHECK(xl == -xr && fabs(xl) <= 1e-12, "halley_accel mirrored brackets and starts: %g %g", xl, xr);
    /* a root at an end of the bracket: Newton lands on the end, which plain Newton rejects
     * and then bisects towards for ~60 steps */
    evals = 0;
    x = rtsafe(lin_fdf, NULL, -0.75, 0.5, +1, rel, CD_ROOT_ABS, CD_ROOT_MAX_ITER);
    plain = evals;
    evals = 0;
    double xe = cdist__root_halley_accel(lin_fd2f, NULL, -0.75, 0.5, NAN, +1, rel, CD_ROOT_ABS, CD_ROOT_MAX_ITER);
    CHECK(fabs(x + 0.75) <= 1e-15 && fabs(xe + 0.75) <= 1e-15, "root at the bracket end: %.17g %.17g", x, xe);
    CHECK(4 * evals <= plain, "halley_accel took %d evaluations for a root at the end, plain Newton %d", evals, plain);
    x = cdist__root_halley_accel(lin_fd2f, NULL, -2.0, -0.75, NAN, +1, rel, CD_ROOT_ABS, CD_ROOT_MAX_ITER);
    CHECK(fabs(x + 0.75) <= 1e-15, "root at the upper end: %.17g", x);
    x = cdist__root_halley_accel(fail_fd2f, NULL, 0.0, 1.0, NAN, +1, rel, CD_ROOT_ABS, CD_ROOT_MAX_ITER);
    CHECK(isnan(x), "halley_accel: failing callback gives NaN (%g)", x);

    /* error-free transforms */
    double lo, s = cdist__two_sum(1.0, 1e-30, &lo);
    CHECK(s == 1.0 && lo == 1e-30, "two_sum");
    s = cdist__two_diff(1.0, 1e-30, &lo);
    CHECK(s == 1.0 && lo == -1e-30, "two_diff");
    /* angles */
    CHECK(cdist__wrap_angle(-M_PI) == M_PI && fabs(cdist__wrap_angle(7.0) - (7.0 - 2 * M_PI)) < 1e-15, "wrap");
    CHECK(isnan(cdist__polar_angle(0, 0)) && cdist__polar_angle(-1, -0.0) == M_PI && cdist__polar_angle(-1, 0) == M_PI, "polar");
    int worst = 0;
    srand(3);
    for (int i = 0; i < 200000; i++) {
        double u = srand1() * pow(10, rand() % 9 - 4), v = srand1() * pow(10, rand() % 9 - 4);
        double want = atan2(v, u), got = cdist__polar_angle(u, v);
        if (want == -M_PI) want = M_PI;
        double ulps = fabs(got - want) / (nextafter(fabs(want), INFINITY) - fabs(want));
        if (ulps > worst) worst = (int)ceil(ulps);
    }
    CHECK(worst <= 2, "polar angle off atan2 by %d ulps", worst);
    /* the inline cube root: the C library's algorithm (glibc's bit for bit), within 1 ulp of cbrt */
    int cbrt_far = 0, cbrt_same = 0;
    for (int i = 0; i < 200000; i++) {
        double u = ldexp(0.5 + 0.5 * rand() / (double)RAND_MAX, rand() % 2040 - 1018);
        double want = cbrt(u), got = cdist__cbrt(u);
        cbrt_same += got == want;
        cbrt_far += !(fabs(got - want) <= nextafter(want, INFINITY) - want);
    }
    CHECK(cbrt_far == 0 && fabs(cdist__cbrt(27.0) - 3.0) <= 4 * DBL_EPSILON && cdist__cbrt(0.0) == 0.0 && cdist__cbrt(0x1p-1060) == cbrt(0x1p-1060),
          "cdist__cbrt: %d of 200000 more than 1 ulp from cbrt", cbrt_far);
    printf("  cdist__cbrt equal to the C library's cbrt on %d of 200000\n", cbrt_same);
    /* scaling */
    CHECK(cdist__scale_exponent(1.0) == 0 && cdist__scale_exponent(3.0) == 1 && cdist__scale_exponent(0.75) == -1, "exponent");
    CHECK(cdist__scale_exponent(1e-310) == -CD_SCALE_MAX_EXP && cdist__scale_exponent(0.0) == 0, "exponent clamp");
    CHECK(cdist__pow2(-1000) == ldexp(1.0, -1000) && cdist__pow2(1000) == ldexp(1.0, 1000), "pow2");
    return check_summary("test_roots");
}
