/* SPDX-License-Identifier: MIT */
/* Small exact-arithmetic and scaling helpers shared by every family. Header-only. */
#ifndef CDIST_BASE_NUMERIC_H
#define CDIST_BASE_NUMERIC_H

#include <float.h>
#include <math.h>

/* ---- FMA policy ----
 * fma() is used wherever one rounding matters (dot products in vec.h, error-free transforms);
 * it is correctly rounded everywhere, so its results do not depend on the hardware.
 * CD_MADD(a, b, c) = a * b + c is for hot loops that need no single rounding: a hardware fma
 * only when the whole build targets it (-mfma defines FP_FAST_FMA), else a multiply and an add
 * (a software fma() would be a slow library call). The build uses ISO C (-std=c17), so the
 * compiler never contracts a * b + c on its own. Hence the baseline and FMA clones below give
 * bit-identical results (checked on every point and lines reference file). */
#ifdef FP_FAST_FMA
#define CD_MADD(a, b, c) fma(a, b, c)
#else
#define CD_MADD(a, b, c) ((a) * (b) + (c))
#endif

/* Hot functions may carry CD_FMA_CLONES: gcc builds a baseline and an FMA clone and picks one
 * at load time (ifunc), so the x86-64 baseline build still runs everywhere; in the FMA clone
 * fma() is one instruction instead of a library call. Helpers they call must be inlined into
 * them (CD_INLINE) to run in the clone. Empty for other compilers and targets, and under
 * AddressSanitizer and ThreadSanitizer (an instrumented ifunc resolver runs before the
 * sanitizer's runtime is initialised). */
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__ELF__) && \
    !defined(CD_NO_FMA_CLONES) && !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
#define CD_FMA_CLONES __attribute__((target_clones("fma", "default")))
#else
#define CD_FMA_CLONES
#endif

/* gcc's basic-block (SLP) vectoriser packs the scalar x, y, z arithmetic of a short fused path
 * into 2-lane vectors whose shuffles and spills cost more than they save; such a path opts
 * out. */
#if defined(__GNUC__) && !defined(__clang__)
#define CD_NO_SLP __attribute__((optimize("no-tree-slp-vectorize")))
#else
#define CD_NO_SLP
#endif

/* A helper that must be inlined into its (possibly FMA-cloned) caller: an out-of-line copy
 * would be compiled for the baseline ISA, where every fma() is a library call. */
#if defined(__GNUC__)
#define CD_INLINE static inline __attribute__((always_inline))
#else
#define CD_INLINE static inline
#endif

/* ---- error-free transforms ---- */

/* a + b = s + *lo exactly (Knuth's TwoSum; no condition on |a|, |b|). */
static inline double cdist__two_sum(double a, double b, double *lo)
{
    double s = a + b, bb = s - a;
    *lo = (a - (s - bb)) + (b - bb);
    return s;
}

/* a - b = s + *lo exactly. */
static inline double cdist__two_diff(double a, double b, double *lo) { return cdist__two_sum(a, -b, lo); }

/* ---- angles ---- */

#define CD_TWO_PI 6.283185307179586476925286766559

/* Angle t wrapped to (-pi, pi]. For |t| <= pi (M_PI is half the double CD_TWO_PI exactly)
 * remainder returns t itself, so the libm call is only made for the others (the same results). */
static inline double cdist__wrap_angle(double t)
{
    double a = fabs(t) <= M_PI ? t : remainder(t, CD_TWO_PI);
    return (a <= -M_PI) ? a + CD_TWO_PI : a;
}

/* fmax and fmin without a libm call (gcc calls libm for them, since maxsd/minsd treat NaN
 * differently): the same results, NaN operands included (the order of +0 and -0 aside).
 * The point and lines hot paths used a dozen libm calls per query. */
CD_INLINE double cdist__fmax(double a, double b) { return a > b ? a : (b == b ? b : a); }
CD_INLINE double cdist__fmin(double a, double b) { return a < b ? a : (b == b ? b : a); }

/* sqrt(a^2 + b^2) without hypot's guards against overflow and underflow (hypot is a slow libm
 * call): for the values of a problem scaled to L ~ 1, where a component below ~1e-154 (which
 * squares to 0) is negligible against the tolerances it is compared with. */
CD_INLINE double cdist__norm2(double a, double b) { return sqrt(a * a + b * b); }

/* The angle a in [0, pi] at the centre of a circle of radius R between the direction to a point
 * at distance e > 0 in its plane and the circle's crossings with the circle of radius s around
 * that point (|R - e| <= s <= R + e): cos a = (R^2 + e^2 - s^2) / (2 R e), taken by the half
 * angle, tan^2(a/2) = (s^2 - (R - e)^2) / ((R + e)^2 - s^2), from factors free of cancellation
 * (R - e is exact where e is near R). Not acos of the cosine, nor a chord from it: a tiny circle
 * (s = 1e-9 R) across the big one puts the cosine within eps of 1, where both lost the crossing. */
CD_INLINE double cdist__crossing_angle(double R, double e, double s)
{
    double dm = R - e, dp = R + e;
    return 2.0 * atan2(sqrt(cdist__fmax(0.0, (s - dm) * (s + dm))), sqrt(cdist__fmax(0.0, (dp - s) * (dp + s))));
}

/* atan(y / x) for 0 <= y <= x, x > 0: fdlibm's s_atan.c (Sun Microsystems, 1993; "permission
 * to use, copy, modify, and distribute this software is freely granted, provided that this
 * notice is preserved") restricted to that range: reduction to |t| < 7/16 and an odd
 * polynomial of degree 23. The reduced argument is formed from y and x directly, with one
 * division ((2y - x) and (y - x) are exact by Sterbenz's lemma in their ranges).
 * Without branches: the three reduction intervals are rows of a table (row 0, t = (1 y - 0 x) /
 * (1 x + 0 y) = y / x and the sum hi - ((t s - lo) - t) = t - t s with hi = lo = 0, give
 * fdlibm's roundings exactly), since the interval of a random argument is not predictable. */
CD_INLINE double cdist__atan_ratio(double y, double x)
{
    static const double aT[] = {
        3.33333333333329318027e-01,  -1.99999999998764832476e-01, 1.42857142725034663711e-01,
        -1.11111104054623557880e-01, 9.09088713343650656196e-02,  -7.69187620504482999495e-02,
        6.66107313738753120669e-02,  -5.83357013379057348645e-02, 4.97687799461593236017e-02,
        -3.65315727442169155270e-02, 1.62858201153657823623e-02,
    };
    /* per row: y and x weights of the numerator, x and y weights of the denominator, hi, lo */
    static const double row[3][6] = {
        {1.0, 0.0, 1.0, 0.0, 0.0, 0.0},
        {2.0, 1.0, 2.0, 1.0, 4.63647609000806093515e-01, 2.26987774529616870924e-17},
        {1.0, 1.0, 1.0, 1.0, 7.85398163397448278999e-01, 3.06161699786838301793e-17},
    };
    const double *k = row[(y >= 0.4375 * x) + (y >= 0.6875 * x)];
    double t = (k[0] * y - k[1] * x) / (k[2] * x + k[3] * y);
    double z = t * t, w = z * z;
    double s1 = z * (aT[0] + w * (aT[2] + w * (aT[4] + w * (aT[6] + w * (aT[8] + w * aT[10])))));
    double s2 = w * (aT[1] + w * (aT[3] + w * (aT[5] + w * (aT[7] + w * aT[9]))));
    return k[4] - ((t * (s1 + s2) - k[5]) - t);
}

/* Polar angle of finite (x, y) in (-pi, pi]; NaN for (0, 0) or NaN arguments. Within 2 ulps of
 * atan2 (measured on 2e7 random and near-axis arguments: 1.5 ulp) and about twice as fast, with
 * one division: the point queries spent a third of their time in atan2. The octant is a table
 * row, not a branch (row j: a = base + sign (a0 + off), the roundings of pi - (a0 - pi_lo),
 * pi/2 - (a0 - pio2_lo) and pi/2 + (a0 + pio2_lo)): random directions made every branch a coin
 * toss. */
CD_INLINE double cdist__polar_angle(double x, double y)
{
    const double pio2_hi = 1.57079632679489655800e+00, pio2_lo = 6.12323399573676603587e-17;
    const double pi_hi = 3.1415926535897931160e+00, pi_lo = 1.2246467991473531772e-16;
    static const double octant[4][3] = {
        {0.0, 1.0, 0.0}, {pi_hi, -1.0, -pi_lo}, {pio2_hi, -1.0, -pio2_lo}, {pio2_hi, 1.0, pio2_lo}};
    static const double flip[2] = {1.0, -1.0};
    double ax = fabs(x), ay = fabs(y);
    if (!(ax + ay > 0.0)) return NAN; /* (0, 0) or a NaN: one predictable branch */
    int steep = ay > ax;
    const double *o = octant[2 * steep + (x < 0.0)];
    double a = o[0] + o[1] * (cdist__atan_ratio(steep ? ax : ay, steep ? ay : ax) + o[2]);
    return flip[(y < 0.0) & (a != pi_hi)] * a; /* -pi is reported as pi */
}

/* ---- power-of-two scaling (exact) ----
 * A family works on a copy scaled by 2^-e where e = cdist__scale_exponent(L), so that the problem
 * scale L * 2^-e is in [1, 2): squares neither overflow nor underflow, and the answer scales
 * back exactly (lengths times 2^e, squared lengths times 2^e twice; exact unless a value is
 * subnormal). L must be finite; L = 0 (or NaN) gives 0. The exponent is clamped to
 * [-CD_SCALE_MAX_EXP, CD_SCALE_MAX_EXP] so that 2^e and 2^-e are normal doubles and a unit
 * vector scaled by either stays far from overflow; a subnormal L (below 2^-1022) is then
 * scaled to about 2^-22 or more, still free of underflow in squares. */
#define CD_SCALE_MAX_EXP 1000

static inline int cdist__scale_exponent(double L)
{
    int e;
    if (!(L > 0.0) || !isfinite(L)) return 0;
    if (L >= 0x1p-1022) {
        /* exponent field of a normal double, without a libm call */
        union { double d; unsigned long long u; } b = {L};
        e = (int)((b.u >> 52) & 0x7ff) - 1023;
    } else {
        e = ilogb(L);
    }
    if (e < -CD_SCALE_MAX_EXP) e = -CD_SCALE_MAX_EXP;
    if (e > CD_SCALE_MAX_EXP) e = CD_SCALE_MAX_EXP;
    return e;
}

/* 2^e for |e| <= 1022, exactly, without a libm call. */
static inline double cdist__pow2(int e)
{
    union { unsigned long long u; double d; } b = {(unsigned long long)(e + 1023) << 52};
    return b.d;
}

/* ---- cube root ---- */

/* 2^(k/3), k = -2..2 (the factors of cdist__cbrt; 1.0 / SQR_CBRT2 etc. of the C library's). */
static const double cdist__cbrt_factor[5] = {1.0 / 1.5874010519681994748, 1.0 / 1.2599210498948731648, 1.0,
                                              1.2599210498948731648, 1.5874010519681994748};

/* Cube root of a positive normal x, inline: the algorithm of glibc's cbrt
 * (sysdeps/ieee754/dbl-64/s_cbrt.c: x = xm 2^xe with xm in [0.5, 1), a polynomial guess of
 * xm^(1/3), one Halley step, the exponent split by 3), operation by operation, with the exponent
 * taken and put back by bit operations instead of frexp and ldexp calls; within ~1 ulp. The line
 * kernel repeats it in lanes (src/batch/line_kernel_body.h), so both give the same bits on every
 * C library. Other x (0, subnormal, infinite, NaN, negative): the C library's cbrt. */
CD_INLINE double cdist__cbrt(double x)
{
    if (!(x >= 0x1p-1022 && x <= DBL_MAX)) return cbrt(x);
    union { double d; unsigned long long u; } b = {x};
    int xe = (int)(b.u >> 52) - 1022;
    b.u = (b.u & 0x000fffffffffffffull) | 0x3fe0000000000000ull;
    double xm = b.d;
    double u = 0.784932344976639262 - 0.145263899385486377 * xm;
    u = -1.83469277483613086 + u * xm;
    u = 2.44693122563534430 + u * xm;
    u = -2.11499494167371287 + u * xm;
    u = 1.50819193781584896 + u * xm;
    u = 0.354895765043919860 + u * xm;
    double t2 = u * u * u;
    double ym = u * (t2 + 2.0 * xm) / (2.0 * t2 + xm) * cdist__cbrt_factor[2 + xe % 3];
    return ym * cdist__pow2(xe / 3); /* exact: |xe / 3| <= 341 */
}

#endif
