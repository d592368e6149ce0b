/* SPDX-License-Identifier: MIT */
/* The lane instruction sets of the distance kernels in lanes (the batch kernels and the
 * circle-circle query's search):
 * whether the x86 variants (AVX-512, AVX2 + FMA) are built, and the pragmas compiling a variant
 * for its instruction set. The lane operations of a variant are in lanes_def.h. */
#ifndef CDIST_BASE_LANES_H
#define CDIST_BASE_LANES_H

#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
#define CD_X86_KERNELS 1
#include <immintrin.h>

#include "base/lanes/load8.h"

/* Every function between PUSH and POP compiled for the instruction set isa. */
#define CD_LANES_PRAGMA(x) _Pragma(#x)
#if defined(__clang__)
#define CD_LANES_TARGET_PUSH(isa) \
    CD_LANES_PRAGMA(clang attribute push(__attribute__((target(isa))), apply_to = function))
#define CD_LANES_TARGET_POP _Pragma("clang attribute pop")
#else
#define CD_LANES_TARGET_PUSH(isa) _Pragma("GCC push_options") CD_LANES_PRAGMA(GCC target(isa))
#define CD_LANES_TARGET_POP _Pragma("GCC pop_options")
#endif
#endif

/* The lane instruction set this CPU runs, found once (src/base/lanes/lanes_isa.c). */
enum { CD_ISA_SCALAR, CD_ISA_AVX2, CD_ISA_AVX512 };
int cdist__lanes_isa(void);
/* The lane width a variant of the given width runs: lanes (1, 4 or 8, the caller's check), or
 * for 0 this CPU's widest (8 with AVX-512, 4 with AVX2 + FMA, else 1). */
int cdist__lanes_width(int lanes);

/* The AVX-512 and AVX2 variants of a kernel for cdist__kernel_choose(), NULL where they are not
 * built. */
#ifdef CD_X86_KERNELS
#define CD_X86_VARIANTS(avx512, avx2) avx512, avx2
#else
#define CD_X86_VARIANTS(avx512, avx2) NULL, NULL
#endif

#endif
