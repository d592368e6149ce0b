/* SPDX-License-Identifier: MIT */
/* The lane operations of the batch distance kernels (line_kernel.c, cc_kernel.c) for one
 * instruction set: the includer defines CD_LANES (1, 4 or 8) and gets W (lanes), V (W
 * doubles), M (a lane mask), KN(name) (the variant's name for `name`) and the operations
 * (vadd, vsqrt, vfma, vsel, mand, ...), each the IEEE operation of the scalar code lane by lane.
 * The 4- and 8-lane variants are compiled between CD_LANES_TARGET_PUSH and _POP (lanes.h).
 * No include guard: included once per variant, lanes_undef.h after it. */
#if CD_LANES == 1
#define W 1
#define KN(name) name##_1
#define V double
#define M int
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
/* Functions, defined once per translation unit: a unit may hold several one-lane instances (a
 * kernel's and a scalar evaluator's of src/base). */
#ifndef CD_LANES_ONE_FUNCTIONS
#define CD_LANES_ONE_FUNCTIONS
static inline double vset(double x) { return x; }
static inline double vld(const double *p) { return *p; }
static inline void vst(double *p, double x) { *p = x; }
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
#endif
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

#elif CD_LANES == 8
#define W 8
#define KN(name) name##_8
#define V __m512d
#define M __mmask8
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

#elif CD_LANES == 4
#define W 4
#define KN(name) name##_4
#define V __m256d
#define M __m256d
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
#else
#error "CD_LANES must be 1, 4 or 8"
#endif
