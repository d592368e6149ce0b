/* SPDX-License-Identifier: MIT */
/* The one run-time choice of the lane instruction set (AVX-512, AVX2 + FMA, scalar), shared by
 * the batch distance kernels and the single circle-circle query's search in lanes. */
#include "base/lanes/lanes.h"

int cdist__lanes_isa(void)
{
    /* a benign race: every thread computes the same value */
    static int isa = -1;
    int v = __atomic_load_n(&isa, __ATOMIC_RELAXED);
    if (v >= 0) return v;
    v = CD_ISA_SCALAR;
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
    __builtin_cpu_init();
    if (__builtin_cpu_supports("avx512f")) v = CD_ISA_AVX512;
    else if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) v = CD_ISA_AVX2;
#endif
    __atomic_store_n(&isa, v, __ATOMIC_RELAXED);
    return v;
}

int cdist__lanes_width(int lanes)
{
    if (lanes) return lanes;
    int isa = cdist__lanes_isa();
    return isa == CD_ISA_AVX512 ? 8 : isa == CD_ISA_AVX2 ? 4 : 1;
}
