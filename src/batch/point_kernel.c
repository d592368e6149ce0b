/* SPDX-License-Identifier: MIT */
/* Distance kernels of point-circle and point-disk for cdist_batch_distance: the single queries'
 * fast path (src/point/point_body.h: their checks and their distance, unscaled) in 8 lanes
 * (AVX-512), 4 lanes (AVX2) or 1 (the tails and other machines), chosen at run time. Every
 * distance is bit-identical to the single query's; entries the fast path would doubt (a failed
 * check, a scale below CD_POINT_MIN_SCALE) are left to the scalar path, which produces their
 * status and message (or their answer). */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "batch-priv.h"
#include "base/lanes/lanes.h"

/* The kernels read the objects as arrays of doubles. */
_Static_assert(offsetof(cdist_vec3, y) == 8 && offsetof(cdist_vec3, z) == 16, "cdist_vec3 layout");
_Static_assert(offsetof(cdist_circle, normal) == 24 && offsetof(cdist_circle, radius) == 48, "cdist_circle layout");

#define CD_LANES 1
#include "point_kernel_body.h"
#ifdef CD_X86_KERNELS
#define CD_LANES 8
#include "point_kernel_body.h"
#define CD_LANES 4
#include "point_kernel_body.h"
#endif

uint64_t cdist__point_distance_kernel(const cdist__job *job, int disk, double unit_tol, size_t lo, size_t count)
{
    static cdist__kernel_fn chosen;
    cdist__kernel_fn f = cdist__kernel_choose(&chosen, CD_X86_VARIANTS(kernel_8, kernel_4), kernel_1);
    return f(job, disk, unit_tol, lo, count);
}
