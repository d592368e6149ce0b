/* SPDX-License-Identifier: MIT */
/* The one run-time choice of a distance kernel's variant (AVX-512, AVX2 + FMA, scalar), shared
 * by the point and line kernels. */
#include "batch-priv.h"

cdist__kernel_fn cdist__kernel_choose(cdist__kernel_fn *chosen, cdist__kernel_fn avx512, cdist__kernel_fn avx2,
                                      cdist__kernel_fn scalar)
{
    /* a benign race: every thread computes the same value */
    cdist__kernel_fn f = __atomic_load_n(chosen, __ATOMIC_RELAXED);
    if (f) return f;
    f = scalar;
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
    __builtin_cpu_init();
    if (avx512 && __builtin_cpu_supports("avx512f")) f = avx512;
    else if (avx2 && __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) f = avx2;
#else
    (void)avx512;
    (void)avx2;
#endif
    __atomic_store_n(chosen, f, __ATOMIC_RELAXED);
    return f;
}
