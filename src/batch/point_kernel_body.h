/* SPDX-License-Identifier: MIT */
/* One instance of the point distance kernel (src/batch/point_kernel.c) for the lanes the
 * includer chose (CD_LANES), compiled for their instruction set: entries [lo, lo + count),
 * count <= 64, W at a time through the point queries' fast path (src/point/point_body.h);
 * returns the mask of the entries left for the scalar path. A wider instance hands its tail to
 * kernel_1. No include guard. */
#if CD_LANES == 8
CD_LANES_TARGET_PUSH("avx512f,fma")
#elif CD_LANES == 4
CD_LANES_TARGET_PUSH("avx2,fma")
#endif
#include "base/lanes/lanes_def.h"
#include "base/lanes/lanes_vec.h"
#include "base/point_circle_lanes.h"
#include "api/circle_fast_lanes.h"
#include "point/point_body.h"

static uint64_t KN(kernel)(const cdist__job *job, int disk, double tol, size_t lo, size_t count)
{
    const unsigned all = (1u << W) - 1u;
    uint64_t left = 0;
    size_t k = 0;
    for (; k + W <= count; k += W) {
        size_t i = lo + k;
        const double *pa = cdist__job_a(job, i), *pb = cdist__job_b(job, i);
        V pt[8], col[8];
#ifdef vload_objects
        vload_objects((const char *)pb, job->b_stride, 7, col);
        vload_objects((const char *)pa, job->a_stride, 3, pt);
#else
        for (int f = 0; f < 7; f++) col[f] = vld(pb + f);
        for (int f = 0; f < 3; f++) pt[f] = vld(pa + f);
#endif
        KN(point_lane) e = KN(point_fast)(pt, col, col + 3, col[6], tol, disk);
        unsigned ok = mbits(e.ok);
        V d = vsqrt(e.d2);
        if (ok == all) {
            vst(&job->distances[i], d);
        } else {
            double dl[W];
            vst(dl, d);
            for (unsigned b = ok; b; b &= b - 1) job->distances[i + (size_t)__builtin_ctz(b)] = dl[__builtin_ctz(b)];
        }
        left |= (uint64_t)(~ok & all) << k;
    }
#if W > 1
    if (k < count) left |= kernel_1(job, disk, tol, lo + k, count - k) << k;
#endif
    return left;
}

#if W > 1
CD_LANES_TARGET_POP
#endif
#include "base/lanes/lanes_undef.h"
