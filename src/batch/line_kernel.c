/* SPDX-License-Identifier: MIT */
/* Distance kernels of line-, ray- and segment-circle for cdist_batch_distance: the scalar path's
 * validation, framing and ROBUST core (see line_kernel_body.h) in 8 lanes (AVX-512), 4 lanes
 * (AVX2) or 1 (elsewhere), chosen at run time. Every distance is bit-identical to the single
 * query's; entries failing a check or needing a branch the kernel does not take are left to the
 * scalar path, which produces their status and message (or their answer). */
#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "batch-priv.h"

#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
#define CD_X86_KERNELS 1
#include <immintrin.h>

#include "load8.h"
#endif

_Static_assert(sizeof(cdist_line) == 48 && sizeof(cdist_ray) == 48 && sizeof(cdist_segment) == 48, "line layouts");
_Static_assert(offsetof(cdist_circle, normal) == 24 && offsetof(cdist_circle, radius) == 48, "cdist_circle layout");

enum { LK_LINE = 0, LK_RAY = 1, LK_SEGMENT = 2 };

/* Newton iterations the lanes of a bracket group take together (a random line's bracket takes
 * 2 to 6, a root at a ray's start about 10); the brackets that need more go on together in a
 * second pass (stage_long, where the screen of nearly multiple roots applies). */
#define LK_LANE_ITER 12
/* Groups of W brackets iterating side by side in the vector kernels (1, 2 and 4 measured: 2
 * fastest). */
#define LK_WIDE_CHAINS 2

/* The per-entry state of a block of up to 64 entries between the kernel's stages, in columns:
 * the model of linear_circle (r, a, m0, x1, |x1|, c2, h and three invariants of fdf_scaled), the
 * core's and the outer scale factors, the brackets of robust_roots and the Newton start of a
 * single one (NaN for two), the range, the smallest candidate so far; then the brackets of each
 * entry and the list of brackets to solve. */
enum {
    LK_F_R, LK_F_A, LK_F_M0, LK_F_X1, LK_F_AX1, LK_F_C2, LK_F_H, LK_F_K, LK_F_RR2, LK_F_DFC,
    LK_F_UP, LK_F_OUTER, LK_F_BLO, LK_F_BHI, LK_F_X0, LK_F_SMIN, LK_F_SMAX, LK_F_BEST, LK_NF
};
/* The Newton state of a long bracket between stage_newton and stage_long (KN(newton)). */
enum { LK_S_X, LK_S_LO, LK_S_HI, LK_S_DX, LK_S_DXOLD, LK_S_P1, LK_S_P2, LK_S_JUMPED, LK_NS };
typedef struct lk_block {
    double f[LK_NF][64];
    double br[2][2][64]; /* [left/right branch][lo/hi][entry] */
    unsigned char ok[64], two[64], has[2][64];
    int item_entry[128];
    double item_lo[128], item_hi[128], item_x0[128], item_d2[128];
    unsigned char item_fail[128];
    int n_long, long_item[128];  /* brackets still iterating after LK_LANE_ITER iterations */
    double long_st[LK_NS][128];  /* and their Newton state */
} lk_block;

#ifdef CD_X86_KERNELS
/* 2^(k/3), k = -2..2, as the C library's cbrt has them (1.0 / SQR_CBRT2 etc.). */
static const double lk_cbrt_factor[5] = {1.0 / 1.5874010519681994748, 1.0 / 1.2599210498948731648, 1.0,
                                         1.2599210498948731648, 1.5874010519681994748};
#endif

/* CD_MADD of the scalar code: a hardware fma only when the whole build targets it. */
#ifdef FP_FAST_FMA
#define vmadd(a, b, c) vfma(a, b, c)
#else
#define vmadd(a, b, c) vadd(vmul(a, b), c)
#endif

/* ---- 1 lane ---- */

#define W 1
#define LK_CHAINS 1
#define V double
#define M int
#define KN(name) name##_1
static inline double vset(double x) { return x; }
static inline double vld(const double *p) { return *p; }
static inline void vst(double *p, double x) { *p = x; }
#define vadd(a, b) ((a) + (b))
#define vsub(a, b) ((a) - (b))
#define vmul(a, b) ((a) * (b))
#define vdiv(a, b) ((a) / (b))
#define vneg(a) (-(a))
#define vsqrt(a) sqrt(a)
#define vfma(a, b, c) fma(a, b, c)
#define vabs(a) fabs(a)
#define vmax(a, b) ((a) > (b) ? (a) : (b))
#define vmin(a, b) ((a) < (b) ? (a) : (b))
static inline double vexpbits(double x)
{
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    u &= 0x7ff0000000000000ull;
    memcpy(&x, &u, sizeof u);
    return x;
}
/* 1 / x of a power of two x in [2^-1021, 2^1022] (exact), from its exponent field */
static inline double vrecip2(double x)
{
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    u = 0x7fe0000000000000ull - u;
    memcpy(&x, &u, sizeof u);
    return x;
}
#define vlt(a, b) ((a) < (b))
#define vle(a, b) ((a) <= (b))
#define vgt(a, b) ((a) > (b))
#define vge(a, b) ((a) >= (b))
#define veq(a, b) ((a) == (b))
#define vne(a, b) ((a) != (b))
#define vsel(m, a, b) ((m) ? (a) : (b))
#define mand(a, b) ((int)(a) & (int)(b))
#define mor(a, b) ((int)(a) | (int)(b))
#define mandn(a, b) ((int)!(a) & (int)(b))
#define mnot(a) (!(a))
#define mtrue() 1
#define mfalse() 0
#define many(m) (m)
#define mbits(m) ((unsigned)(m))
#include "line_kernel_body.h"
#include "line_kernel_undef.h"

#ifdef CD_X86_KERNELS

/* Every function of an instantiation compiled for its instruction set. */
#if defined(__clang__)
#define LK_PRAGMA(x) _Pragma(#x)
#define LK_TARGET_PUSH(isa) LK_PRAGMA(clang attribute push(__attribute__((target(isa))), apply_to = function))
#define LK_TARGET_POP _Pragma("clang attribute pop")
#else
#define LK_PRAGMA(x) _Pragma(#x)
#define LK_TARGET_PUSH(isa) _Pragma("GCC push_options") LK_PRAGMA(GCC target(isa))
#define LK_TARGET_POP _Pragma("GCC pop_options")
#endif

/* ---- 8 lanes ---- */

LK_TARGET_PUSH("avx512f,fma")
#define W 8
#define LK_CHAINS LK_WIDE_CHAINS
#define V __m512d
#define M __mmask8
#define KN(name) name##_8
#define vset _mm512_set1_pd
#define vld _mm512_loadu_pd
#define vst _mm512_storeu_pd
#define vadd _mm512_add_pd
#define vsub _mm512_sub_pd
#define vmul _mm512_mul_pd
#define vdiv _mm512_div_pd
#define vneg(a) _mm512_castsi512_pd(_mm512_xor_si512(_mm512_castpd_si512(a), _mm512_set1_epi64(INT64_MIN)))
#define vsqrt _mm512_sqrt_pd
#define vfma _mm512_fmadd_pd
#define vabs _mm512_abs_pd
#define vmax _mm512_max_pd
#define vmin _mm512_min_pd
#define vexpbits(x) \
    _mm512_castsi512_pd(_mm512_and_si512(_mm512_castpd_si512(x), _mm512_set1_epi64(0x7ff0000000000000ll)))
#define vrecip2(x) \
    _mm512_castsi512_pd(_mm512_sub_epi64(_mm512_set1_epi64(0x7fe0000000000000ll), _mm512_castpd_si512(x)))
#define vlt(a, b) _mm512_cmp_pd_mask(a, b, _CMP_LT_OQ)
#define vle(a, b) _mm512_cmp_pd_mask(a, b, _CMP_LE_OQ)
#define vgt(a, b) _mm512_cmp_pd_mask(a, b, _CMP_GT_OQ)
#define vge(a, b) _mm512_cmp_pd_mask(a, b, _CMP_GE_OQ)
#define veq(a, b) _mm512_cmp_pd_mask(a, b, _CMP_EQ_OQ)
#define vne(a, b) _mm512_cmp_pd_mask(a, b, _CMP_NEQ_UQ)
#define vsel(m, a, b) _mm512_mask_blend_pd(m, b, a)
#define mand(a, b) ((__mmask8)((a) & (b)))
#define mor(a, b) ((__mmask8)((a) | (b)))
#define mandn(a, b) ((__mmask8)(~(a) & (b)))
#define mnot(a) ((__mmask8)~(a))
#define mtrue() ((__mmask8)0xff)
#define mfalse() ((__mmask8)0)
#define many(m) ((m) != 0)
#define mbits(m) ((unsigned)(m))
#define vload_objects batch_load8
#define vcmp_mask(m, a, b, p) _mm512_mask_cmp_pd_mask(m, a, b, p)
#define vfrexp_m(x) _mm512_getmant_pd(x, _MM_MANT_NORM_p5_1, _MM_MANT_SIGN_zero)
#define vfrexp_e(x) _mm512_add_pd(_mm512_getexp_pd(x), _mm512_set1_pd(1.0))
#define vtrunc(x) _mm512_roundscale_pd(x, _MM_FROUND_TO_ZERO | _MM_FROUND_NO_EXC)
#define vscale2(y, q) _mm512_scalef_pd(y, q)
#include "line_kernel_body.h"
#include "line_kernel_undef.h"
LK_TARGET_POP

/* ---- 4 lanes ---- */

LK_TARGET_PUSH("avx2,fma")
#define W 4
#define LK_CHAINS LK_WIDE_CHAINS
#define V __m256d
#define M __m256d
#define KN(name) name##_4
#define vset _mm256_set1_pd
#define vld _mm256_loadu_pd
#define vst _mm256_storeu_pd
#define vadd _mm256_add_pd
#define vsub _mm256_sub_pd
#define vmul _mm256_mul_pd
#define vdiv _mm256_div_pd
#define vneg(a) _mm256_xor_pd(a, _mm256_set1_pd(-0.0))
#define vsqrt _mm256_sqrt_pd
#define vfma _mm256_fmadd_pd
#define vabs(a) _mm256_andnot_pd(_mm256_set1_pd(-0.0), a)
#define vmax _mm256_max_pd
#define vmin _mm256_min_pd
#define vexpbits(x) _mm256_and_pd(x, _mm256_castsi256_pd(_mm256_set1_epi64x(0x7ff0000000000000ll)))
#define vrecip2(x) \
    _mm256_castsi256_pd(_mm256_sub_epi64(_mm256_set1_epi64x(0x7fe0000000000000ll), _mm256_castpd_si256(x)))
#define vlt(a, b) _mm256_cmp_pd(a, b, _CMP_LT_OQ)
#define vle(a, b) _mm256_cmp_pd(a, b, _CMP_LE_OQ)
#define vgt(a, b) _mm256_cmp_pd(a, b, _CMP_GT_OQ)
#define vge(a, b) _mm256_cmp_pd(a, b, _CMP_GE_OQ)
#define veq(a, b) _mm256_cmp_pd(a, b, _CMP_EQ_OQ)
#define vne(a, b) _mm256_cmp_pd(a, b, _CMP_NEQ_UQ)
#define vsel(m, a, b) _mm256_blendv_pd(b, a, m)
#define mand _mm256_and_pd
#define mor _mm256_or_pd
#define mandn _mm256_andnot_pd
#define mtrue() _mm256_castsi256_pd(_mm256_set1_epi64x(-1))
#define mnot(a) _mm256_xor_pd(a, mtrue())
#define mfalse() _mm256_setzero_pd()
#define many(m) (_mm256_movemask_pd(m) != 0)
#define mbits(m) ((unsigned)_mm256_movemask_pd(m))
#define vload_objects batch_load4
#define vfrexp_m(x)                                                                                          \
    _mm256_castsi256_pd(_mm256_or_si256(_mm256_and_si256(_mm256_castpd_si256(x), _mm256_set1_epi64x(0x000fffffffffffffll)), \
                                        _mm256_set1_epi64x(0x3fe0000000000000ll)))
#define vfrexp_e(x)                                                                                          \
    _mm256_sub_pd(_mm256_castsi256_pd(_mm256_or_si256(_mm256_srli_epi64(_mm256_castpd_si256(x), 52),          \
                                                      _mm256_set1_epi64x(0x4330000000000000ll))),              \
                  _mm256_set1_pd(0x1p52 + 1022.0))
#define vtrunc(x) _mm256_round_pd(x, _MM_FROUND_TO_ZERO | _MM_FROUND_NO_EXC)
#define vscale2(y, q)                                                                                        \
    _mm256_castsi256_pd(_mm256_add_epi64(                                                                     \
        _mm256_castpd_si256(y),                                                                               \
        _mm256_slli_epi64(_mm256_sub_epi64(_mm256_castpd_si256(_mm256_add_pd(q, _mm256_set1_pd(0x1.8p52))),   \
                                           _mm256_set1_epi64x(0x4338000000000000ll)),                          \
                          52)))
#include "line_kernel_body.h"
#include "line_kernel_undef.h"
LK_TARGET_POP

#endif

/* ---- dispatch ---- */

static uint64_t kernel_scalar(const cdist__job *job, int shape, double tol, size_t lo, size_t count)
{
    return block_1(job, shape, tol, lo, count, 0);
}

#ifdef CD_X86_KERNELS
/* Whether an instantiation's cube root is the C library's (its cbrt_matches), checked once:
 * 0 unknown, 1 yes, -1 no (a benign race: every thread finds the same). */
static int cbrt_verified(int *known, int (*matches)(void))
{
    int v = __atomic_load_n(known, __ATOMIC_RELAXED);
    if (!v) {
        v = matches() ? 1 : -1;
        __atomic_store_n(known, v, __ATOMIC_RELAXED);
    }
    return v > 0;
}

static int cbrt_known_8, cbrt_known_4;

static uint64_t kernel_avx512(const cdist__job *job, int shape, double tol, size_t lo, size_t count)
{
    return block_8(job, shape, tol, lo, count, cbrt_verified(&cbrt_known_8, cbrt_matches_8));
}

static uint64_t kernel_avx2(const cdist__job *job, int shape, double tol, size_t lo, size_t count)
{
    return block_4(job, shape, tol, lo, count, cbrt_verified(&cbrt_known_4, cbrt_matches_4));
}
#endif

uint64_t cdist__line_distance_kernel(const cdist__job *job, int shape, double unit_tol, size_t lo, size_t count)
{
    static cdist__kernel_fn chosen;
#ifdef CD_X86_KERNELS
    cdist__kernel_fn f = cdist__kernel_choose(&chosen, kernel_avx512, kernel_avx2, kernel_scalar);
#else
    cdist__kernel_fn f = cdist__kernel_choose(&chosen, NULL, NULL, kernel_scalar);
#endif
    return f(job, shape, unit_tol, lo, count);
}
