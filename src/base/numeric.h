/* Small exact-arithmetic and scaling helpers shared by every family. Header-only. */
#ifndef CDIST_BASE_NUMERIC_H
#define CDIST_BASE_NUMERIC_H

#include <math.h>

/* ---- FMA policy ----
 * fma() is used wherever one rounding matters (dot products in vec.h, error-free transforms).
 * CD_MADD(a, b, c) = a * b + c is for hot loops that need no single rounding: a hardware fma
 * when the compiler knows it has one (FP_FAST_FMA, e.g. -mfma or a target_clones("fma")
 * clone), else a multiply and an add (a software fma() would be a slow library call). */
#ifdef FP_FAST_FMA
#define CD_MADD(a, b, c) fma(a, b, c)
#else
#define CD_MADD(a, b, c) ((a) * (b) + (c))
#endif

/* Hot functions may carry CD_FMA_CLONES: gcc builds a baseline and an FMA clone and picks one
 * at load time (ifunc), so the x86-64 baseline build still runs everywhere. Empty elsewhere. */
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__ELF__) && \
    !defined(CD_NO_FMA_CLONES) && !defined(__SANITIZE_ADDRESS__)
#define CD_FMA_CLONES __attribute__((target_clones("fma", "default")))
#else
#define CD_FMA_CLONES
#endif

/* ---- error-free transforms ---- */

/* a + b = s + *lo exactly (Knuth's TwoSum; no condition on |a|, |b|). */
static inline double cd_two_sum(double a, double b, double *lo)
{
    double s = a + b, bb = s - a;
    *lo = (a - (s - bb)) + (b - bb);
    return s;
}

/* a - b = s + *lo exactly. */
static inline double cd_two_diff(double a, double b, double *lo) { return cd_two_sum(a, -b, lo); }

/* a * b = p + *lo exactly (needs a correctly rounded fma). */
static inline double cd_two_prod(double a, double b, double *lo)
{
    double p = a * b;
    *lo = fma(a, b, -p);
    return p;
}

/* ---- angles ---- */

#define CD_TWO_PI 6.283185307179586476925286766559

/* Angle t wrapped to (-pi, pi]. */
static inline double cd_wrap_angle(double t)
{
    double a = remainder(t, CD_TWO_PI);
    return (a <= -M_PI) ? a + CD_TWO_PI : a;
}

/* Polar angle of (x, y) in (-pi, pi]; NaN for (0, 0). */
static inline double cd_polar_angle(double x, double y)
{
    if (x == 0.0 && y == 0.0) return NAN;
    double a = atan2(y, x);
    return (a == -M_PI) ? M_PI : a;
}

/* ---- power-of-two scaling (exact) ----
 * A family works on a copy scaled by 2^-e where e = cd_scale_exponent(L), so that the problem
 * scale L * 2^-e is in [1, 2): squares neither overflow nor underflow, and the answer scales
 * back exactly (cd_pow2(e) times a length, cd_pow2(2 e) times a squared length, with
 * ldexp() where the factor itself would overflow or underflow). L must be finite; L = 0 gives 0. */
static inline int cd_scale_exponent(double L) { return (L > 0.0 && isfinite(L)) ? ilogb(L) : 0; }

/* 2^e for |e| <= 1022 (exact; the range every scale exponent of accepted input lies in). */
static inline double cd_pow2(int e) { return ldexp(1.0, e); }

#endif
