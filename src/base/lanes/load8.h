/* SPDX-License-Identifier: MIT */
/* Loading objects into columns for the AVX-512 and AVX2 batch kernels (point_kernel.c,
 * line_kernel.c). */
#ifndef CDIST_BASE_LANES_LOAD8_H
#define CDIST_BASE_LANES_LOAD8_H

#include <immintrin.h>
#include <stddef.h>

/* The first `fields` (<= 7) doubles of 8 objects (at p + k * stride) as vectors col[0..7], e.g.
 * a circle's centre, normal and radius: one masked load per object (never touching a byte after
 * it) and an 8x8 transpose, cheaper than a gather per field or copies one by one. col[7] and
 * the columns beyond `fields` are zero. */
__attribute__((target("avx512f"))) static inline void batch_load8(const char *p, ptrdiff_t stride, int fields,
                                                                   __m512d col[8])
{
    __m512d r[8];
    __mmask8 m = (__mmask8)((1u << fields) - 1u);
    for (int k = 0; k < 8; k++) r[k] = _mm512_maskz_loadu_pd(m, p + k * stride);
    __m512d t[8];
    for (int k = 0; k < 8; k += 2) {
        t[k] = _mm512_unpacklo_pd(r[k], r[k + 1]);     /* r_k[0] r_k+1[0] r_k[2] r_k+1[2] ... */
        t[k + 1] = _mm512_unpackhi_pd(r[k], r[k + 1]); /* r_k[1] r_k+1[1] r_k[3] r_k+1[3] ... */
    }
    const __m512i lo2 = _mm512_set_epi64(13, 12, 5, 4, 9, 8, 1, 0), hi2 = _mm512_set_epi64(15, 14, 7, 6, 11, 10, 3, 2);
    __m512d u[8];
    for (int h = 0; h < 8; h += 4) {
        u[h + 0] = _mm512_permutex2var_pd(t[h], lo2, t[h + 2]);     /* fields 0 and 4, rows h..h+3 */
        u[h + 1] = _mm512_permutex2var_pd(t[h], hi2, t[h + 2]);     /* fields 2 and 6 */
        u[h + 2] = _mm512_permutex2var_pd(t[h + 1], lo2, t[h + 3]); /* fields 1 and 5 */
        u[h + 3] = _mm512_permutex2var_pd(t[h + 1], hi2, t[h + 3]); /* fields 3 and 7 */
    }
    const __m512i lo4 = _mm512_set_epi64(11, 10, 9, 8, 3, 2, 1, 0), hi4 = _mm512_set_epi64(15, 14, 13, 12, 7, 6, 5, 4);
    col[0] = _mm512_permutex2var_pd(u[0], lo4, u[4]);
    col[4] = _mm512_permutex2var_pd(u[0], hi4, u[4]);
    col[2] = _mm512_permutex2var_pd(u[1], lo4, u[5]);
    col[6] = _mm512_permutex2var_pd(u[1], hi4, u[5]);
    col[1] = _mm512_permutex2var_pd(u[2], lo4, u[6]);
    col[5] = _mm512_permutex2var_pd(u[2], hi4, u[6]);
    col[3] = _mm512_permutex2var_pd(u[3], lo4, u[7]);
    col[7] = _mm512_setzero_pd();
}

/* The same for 4 objects in AVX2 vectors: fields 0..3 in one load per object (masked for fewer
 * fields: a point's three), fields 4.. (fields - 1) in a masked load, two 4x4 transposes. */
__attribute__((target("avx2"))) static inline void batch_load4(const char *p, ptrdiff_t stride, int fields,
                                                                __m256d col[8])
{
    const __m256i lane = _mm256_setr_epi64x(0, 1, 2, 3);
    const __m256i head = _mm256_cmpgt_epi64(_mm256_set1_epi64x(fields), lane);
    const __m256i tail = _mm256_cmpgt_epi64(_mm256_set1_epi64x(fields - 4), lane);
    for (int h = 0; h < 2; h++) {
        __m256d r[4];
        for (int k = 0; k < 4; k++) {
            const double *o = (const double *)(p + k * stride) + 4 * h;
            r[k] = h ? _mm256_maskload_pd(o, tail) : fields < 4 ? _mm256_maskload_pd(o, head) : _mm256_loadu_pd(o);
        }
        __m256d t0 = _mm256_unpacklo_pd(r[0], r[1]), t1 = _mm256_unpackhi_pd(r[0], r[1]);
        __m256d t2 = _mm256_unpacklo_pd(r[2], r[3]), t3 = _mm256_unpackhi_pd(r[2], r[3]);
        col[4 * h + 0] = _mm256_permute2f128_pd(t0, t2, 0x20);
        col[4 * h + 1] = _mm256_permute2f128_pd(t1, t3, 0x20);
        col[4 * h + 2] = _mm256_permute2f128_pd(t0, t2, 0x31);
        col[4 * h + 3] = _mm256_permute2f128_pd(t1, t3, 0x31);
    }
}

#endif
