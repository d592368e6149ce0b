/* SPDX-License-Identifier: MIT */
/* Distance kernels of point-circle and point-disk for cdist_batch_distance: the single query's
 * fast path (point_fast in src/point/point.c, its checks and its distance) operation by
 * operation (same roundings, fma where the scalar code calls fma), unscaled like it: every
 * distance is bit-identical to the single query's, and the entries the fast path would doubt
 * (scale below CD_POINT_MIN_SCALE included) are left to the scalar path.
 * AVX-512 (8 lanes) and AVX2 (4 lanes) versions are chosen at run time; the scalar version
 * serves the tails and other machines. Entries failing any check are left
 * to the scalar path, which produces their status and message. */
#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include "batch-priv.h"
#include "base/lanes/lanes.h"

/* The kernels load the fields by byte offset. */
_Static_assert(offsetof(cdist_vec3, y) == 8 && offsetof(cdist_vec3, z) == 16, "cdist_vec3 layout");
_Static_assert(offsetof(cdist_circle, normal) == 24 && offsetof(cdist_circle, radius) == 48, "cdist_circle layout");

/* One entry: returns 0 (and writes *d) when every fast check passes (the single query's own:
 * cdist__in_range and cdist__circle_fast_body). */
static int point_one(const cdist_vec3 *P, const cdist_circle *C, int disk, double tol, double *d)
{
    vec3 p = *P;
    cdist__circle cc;
    if (!cdist__in_range(p) || !cdist__circle_fast_body(tol, C, &cc)) return 1;
    vec3 n = cc.n;
    double r = cc.r;
    vec3 rel = v_sub(p, cc.c);
    vec3 np = v_cross(n, rel);
    double h = v_dot(n, rel), q2 = v_sqr(np), rho = sqrt(q2);
    /* the scale guard: |rel|^2 = |n x rel|^2 + h^2, or r^2, at least CD_POINT_MIN_SCALE^2 */
    if (!(cdist__fmax(q2 + h * h, r * r) >= CD_POINT_MIN_SCALE * CD_POINT_MIN_SCALE)) return 1;
    if (disk && !(rho > r)) {
        *d = sqrt(h * h);
    } else {
        double dr = rho - r;
        *d = sqrt(fma(dr, dr, h * h));
    }
    return 0;
}

static uint64_t kernel_scalar(const cdist__job *job, int disk, double tol, size_t lo, size_t count)
{
    uint64_t left = 0;
    for (size_t k = 0; k < count; k++) {
        size_t i = lo + k;
        if (point_one(cdist__job_a(job, i), cdist__job_b(job, i), disk, tol, &job->distances[i])) left |= (uint64_t)1 << k;
    }
    return left;
}

#ifdef CD_X86_KERNELS

#define AVX512 __attribute__((target("avx512f,fma")))
#define AVX2 __attribute__((target("avx2,fma")))

/* ---- 8 lanes ---- */

AVX512 static inline __m512d abs8(__m512d x) { return _mm512_abs_pd(x); }
AVX512 static inline __m512d max3_8(__m512d x, __m512d y, __m512d z)
{
    return _mm512_max_pd(_mm512_max_pd(abs8(x), abs8(y)), abs8(z));
}
/* fma(a.x, b.x, fma(a.y, b.y, a.z * b.z)) as v_dot */
/* every component finite and within the limit (a max would drop NaNs) */
AVX512 static inline __mmask8 in8(__m512d x, __m512d y, __m512d z, __m512d lim)
{
    return _mm512_cmp_pd_mask(abs8(x), lim, _CMP_LE_OQ) & _mm512_cmp_pd_mask(abs8(y), lim, _CMP_LE_OQ) &
           _mm512_cmp_pd_mask(abs8(z), lim, _CMP_LE_OQ);
}
AVX512 static inline __m512d dot8(__m512d ax, __m512d ay, __m512d az, __m512d bx, __m512d by, __m512d bz)
{
    return _mm512_fmadd_pd(ax, bx, _mm512_fmadd_pd(ay, by, _mm512_mul_pd(az, bz)));
}

AVX512 static uint64_t kernel_avx512(const cdist__job *job, int disk, double tol, size_t lo, size_t count)
{
    uint64_t left = 0;
    size_t k = 0;
    const __m512d lim = _mm512_set1_pd(CD_MAX_ABS), zero = _mm512_setzero_pd(), one = _mm512_set1_pd(1.0);
    const __m512d vtol = _mm512_set1_pd(tol);
    for (; k + 8 <= count; k += 8) {
        size_t i = lo + k;
        const char *pa = cdist__job_a(job, i), *pb = cdist__job_b(job, i);
        __m512d col[8], pt[8];
        batch_load8(pb, job->b_stride, 7, col);
        batch_load8(pa, job->a_stride, 3, pt);
        __m512d px = pt[0], py = pt[1], pz = pt[2];
        __m512d cx = col[0], cy = col[1], cz = col[2], dx = col[3], dy = col[4], dz = col[5], r = col[6];
        __m512d m = max3_8(dx, dy, dz);
        __mmask8 ok = in8(px, py, pz, lim) & in8(cx, cy, cz, lim) & in8(dx, dy, dz, lim) &
                      _mm512_cmp_pd_mask(r, zero, _CMP_GE_OQ) &
                      _mm512_cmp_pd_mask(r, lim, _CMP_LE_OQ) &
                      _mm512_cmp_pd_mask(m, _mm512_set1_pd(CD_MIN_NORMAL_FAST), _CMP_GE_OQ);
        __m512d len = _mm512_sqrt_pd(dot8(dx, dy, dz, dx, dy, dz));
        ok &= _mm512_cmp_pd_mask(abs8(_mm512_sub_pd(len, one)), vtol, _CMP_LE_OQ);
        __m512d il = _mm512_div_pd(one, len);
        __m512d nx = _mm512_mul_pd(il, dx), ny = _mm512_mul_pd(il, dy), nz = _mm512_mul_pd(il, dz);
        __m512d rx = _mm512_sub_pd(px, cx), ry = _mm512_sub_pd(py, cy), rz = _mm512_sub_pd(pz, cz);
        /* n x rel, each component a product difference without fma (as v_cross) */
        __m512d qx = _mm512_sub_pd(_mm512_mul_pd(ny, rz), _mm512_mul_pd(nz, ry));
        __m512d qy = _mm512_sub_pd(_mm512_mul_pd(nz, rx), _mm512_mul_pd(nx, rz));
        __m512d qz = _mm512_sub_pd(_mm512_mul_pd(nx, ry), _mm512_mul_pd(ny, rx));
        __m512d h = dot8(nx, ny, nz, rx, ry, rz);
        __m512d q2 = dot8(qx, qy, qz, qx, qy, qz), rho = _mm512_sqrt_pd(q2);
        __m512d dr = _mm512_sub_pd(rho, r);
        __m512d hh = _mm512_mul_pd(h, h);
        /* the scale guard (see point_one) */
        ok &= _mm512_cmp_pd_mask(_mm512_max_pd(_mm512_add_pd(q2, hh), _mm512_mul_pd(r, r)),
                                 _mm512_set1_pd(CD_POINT_MIN_SCALE * CD_POINT_MIN_SCALE), _CMP_GE_OQ);
        __m512d d2 = _mm512_fmadd_pd(dr, dr, hh);
        if (disk) d2 = _mm512_mask_blend_pd(_mm512_cmp_pd_mask(rho, r, _CMP_GT_OQ), hh, d2);
        __m512d d = _mm512_sqrt_pd(d2);
        _mm512_mask_storeu_pd(&job->distances[i], ok, d);
        left |= (uint64_t)(uint8_t)~ok << k;
    }
    if (k < count) left |= kernel_scalar(job, disk, tol, lo + k, count - k) << k;
    return left;
}

/* ---- 4 lanes ---- */

AVX2 static inline __m256d abs4(__m256d x) { return _mm256_andnot_pd(_mm256_set1_pd(-0.0), x); }
AVX2 static inline __m256d max3_4(__m256d x, __m256d y, __m256d z)
{
    return _mm256_max_pd(_mm256_max_pd(abs4(x), abs4(y)), abs4(z));
}
AVX2 static inline __m256d dot4(__m256d ax, __m256d ay, __m256d az, __m256d bx, __m256d by, __m256d bz)
{
    return _mm256_fmadd_pd(ax, bx, _mm256_fmadd_pd(ay, by, _mm256_mul_pd(az, bz)));
}
AVX2 static inline int le4(__m256d a, __m256d b) { return _mm256_movemask_pd(_mm256_cmp_pd(a, b, _CMP_LE_OQ)); }
AVX2 static inline int in4(__m256d x, __m256d y, __m256d z, __m256d lim)
{
    return le4(abs4(x), lim) & le4(abs4(y), lim) & le4(abs4(z), lim);
}

AVX2 static uint64_t kernel_avx2(const cdist__job *job, int disk, double tol, size_t lo, size_t count)
{
    uint64_t left = 0;
    size_t k = 0;
    const __m256d lim = _mm256_set1_pd(CD_MAX_ABS), zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1.0);
    const __m256d vtol = _mm256_set1_pd(tol);
    const long long as = (long long)job->a_stride, bs = (long long)job->b_stride;
    const __m256i ia = _mm256_set_epi64x(3 * as, 2 * as, as, 0), ib = _mm256_set_epi64x(3 * bs, 2 * bs, bs, 0);
    for (; k + 4 <= count; k += 4) {
        size_t i = lo + k;
        const char *pa = cdist__job_a(job, i), *pb = cdist__job_b(job, i);
        __m256d px = _mm256_i64gather_pd((const double *)pa, ia, 1),
                py = _mm256_i64gather_pd((const double *)(pa + 8), ia, 1),
                pz = _mm256_i64gather_pd((const double *)(pa + 16), ia, 1);
        __m256d cx = _mm256_i64gather_pd((const double *)pb, ib, 1),
                cy = _mm256_i64gather_pd((const double *)(pb + 8), ib, 1),
                cz = _mm256_i64gather_pd((const double *)(pb + 16), ib, 1);
        __m256d dx = _mm256_i64gather_pd((const double *)(pb + 24), ib, 1),
                dy = _mm256_i64gather_pd((const double *)(pb + 32), ib, 1),
                dz = _mm256_i64gather_pd((const double *)(pb + 40), ib, 1);
        __m256d r = _mm256_i64gather_pd((const double *)(pb + 48), ib, 1);
        __m256d m = max3_4(dx, dy, dz);
        int ok = in4(px, py, pz, lim) & in4(cx, cy, cz, lim) & in4(dx, dy, dz, lim) & le4(zero, r) &
                 le4(r, lim) & le4(_mm256_set1_pd(CD_MIN_NORMAL_FAST), m);
        __m256d len = _mm256_sqrt_pd(dot4(dx, dy, dz, dx, dy, dz));
        ok &= le4(abs4(_mm256_sub_pd(len, one)), vtol);
        __m256d il = _mm256_div_pd(one, len);
        __m256d nx = _mm256_mul_pd(il, dx), ny = _mm256_mul_pd(il, dy), nz = _mm256_mul_pd(il, dz);
        __m256d rx = _mm256_sub_pd(px, cx), ry = _mm256_sub_pd(py, cy), rz = _mm256_sub_pd(pz, cz);
        __m256d qx = _mm256_sub_pd(_mm256_mul_pd(ny, rz), _mm256_mul_pd(nz, ry));
        __m256d qy = _mm256_sub_pd(_mm256_mul_pd(nz, rx), _mm256_mul_pd(nx, rz));
        __m256d qz = _mm256_sub_pd(_mm256_mul_pd(nx, ry), _mm256_mul_pd(ny, rx));
        __m256d h = dot4(nx, ny, nz, rx, ry, rz);
        __m256d q2 = dot4(qx, qy, qz, qx, qy, qz), rho = _mm256_sqrt_pd(q2);
        __m256d dr = _mm256_sub_pd(rho, r);
        __m256d hh = _mm256_mul_pd(h, h);
        ok &= le4(_mm256_set1_pd(CD_POINT_MIN_SCALE * CD_POINT_MIN_SCALE),
                  _mm256_max_pd(_mm256_add_pd(q2, hh), _mm256_mul_pd(r, r))); /* the scale guard (see point_one) */
        __m256d d2 = _mm256_fmadd_pd(dr, dr, hh);
        if (disk) d2 = _mm256_blendv_pd(hh, d2, _mm256_cmp_pd(rho, r, _CMP_GT_OQ));
        __m256d d = _mm256_sqrt_pd(d2);
        double out[4];
        _mm256_storeu_pd(out, d);
        for (int l = 0; l < 4; l++)
            if (ok >> l & 1) job->distances[i + (size_t)l] = out[l];
        left |= (uint64_t)(~ok & 15) << k;
    }
    if (k < count) left |= kernel_scalar(job, disk, tol, lo + k, count - k) << k;
    return left;
}

#endif

uint64_t cdist__point_distance_kernel(const cdist__job *job, int disk, double unit_tol, size_t lo, size_t count)
{
    static cdist__kernel_fn chosen;
    cdist__kernel_fn f = cdist__kernel_choose(&chosen, CD_X86_VARIANTS(kernel_avx512, kernel_avx2), kernel_scalar);
    return f(job, disk, unit_tol, lo, count);
}
