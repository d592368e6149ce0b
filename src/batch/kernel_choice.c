/* SPDX-License-Identifier: MIT */
/* The variant of a batch distance kernel this CPU runs, chosen once per kernel from the lane
 * instruction set (src/base/lanes/lanes_isa.c). */
#include "batch-priv.h"
#include "base/lanes/lanes.h"

cdist__kernel_fn cdist__kernel_choose(cdist__kernel_fn *chosen, cdist__kernel_fn avx512, cdist__kernel_fn avx2,
                                      cdist__kernel_fn scalar)
{
    cdist__kernel_fn f = __atomic_load_n(chosen, __ATOMIC_RELAXED);
    if (f) return f;
    int isa = cdist__lanes_isa();
    f = scalar;
    if (avx512 && isa == CD_ISA_AVX512) f = avx512;
    else if (avx2 && isa >= CD_ISA_AVX2) f = avx2;
    __atomic_store_n(chosen, f, __ATOMIC_RELAXED);
    return f;
}
