/* SPDX-License-Identifier: MIT */
/* Distance kernels of line-, ray- and segment-circle for cdist_batch_distance: the single
 * query's body (src/lines/line_circle_body.h) with the kernels' framing (line_kernel_body.h) in
 * 8 lanes (AVX-512), 4 lanes (AVX2) or 1 (elsewhere), chosen at run time. Every distance is
 * bit-identical to the single query's; entries failing a check or needing a branch the kernel
 * does not take are left to the scalar path, which produces their status and message (or their
 * answer). */
#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "batch-priv.h"
#include "base/lanes/lanes.h"

_Static_assert(sizeof(cdist_line) == 48 && sizeof(cdist_ray) == 48 && sizeof(cdist_segment) == 48, "line layouts");
_Static_assert(offsetof(cdist_circle, normal) == 24 && offsetof(cdist_circle, radius) == 48, "cdist_circle layout");

enum { LK_LINE = 0, LK_RAY = 1, LK_SEGMENT = 2 };

/* Solver iterations the lanes of a bracket group take together (a random line's bracket takes
 * 2 to 5, a root at a ray's start about 10); the brackets that need more go on together in a
 * second pass (stage_long, where the screen of nearly multiple roots applies). */
#define LK_LANE_ITER 12
/* Groups of W brackets iterating side by side in the vector kernels (1, 2 and 4 measured: 2
 * fastest). */
#define LK_WIDE_CHAINS 2

/* The per-entry state of a block of up to 64 entries between the kernel's stages, in columns:
 * the model of linear_circle (r, a, m0, x1, |x1|, c2, h and three invariants of fd2f_scaled), the
 * core's and the outer scale factors, the brackets of robust_roots and the start of a single
 * one (NaN for two), the range, the smallest candidate so far; then the brackets of each entry
 * with their starts and the list of brackets to solve. */
enum {
    LK_F_R, LK_F_A, LK_F_M0, LK_F_X1, LK_F_AX1, LK_F_C2, LK_F_H, LK_F_K, LK_F_RR2, LK_F_DFC,
    LK_F_UP, LK_F_OUTER, LK_F_BLO, LK_F_BHI, LK_F_X0, LK_F_SMIN, LK_F_SMAX, LK_F_BEST, LK_NF
};
/* The solver state of a long bracket between stage_solve and stage_long (KN(solver)). */
enum { LK_S_X, LK_S_LO, LK_S_HI, LK_S_DX, LK_S_DXOLD, LK_S_P1, LK_S_P2, LK_S_JUMPED, LK_S_PH, LK_S_CP, LK_S_XP, LK_NS };
typedef struct lk_block {
    double f[LK_NF][64];
    double br[2][3][64]; /* [left/right branch][lo/hi/start][entry] */
    unsigned char ok[64], two[64], has[2][64];
    int item_entry[128];
    double item_lo[128], item_hi[128], item_x0[128], item_d2[128];
    unsigned char item_fail[128];
    int n_long, long_item[128];  /* brackets still iterating after LK_LANE_ITER iterations */
    double long_st[LK_NS][128];  /* and their solver state */
} lk_block;

#define CD_LANES 1
#define LK_CHAINS 1
#include "line_kernel_body.h"
#ifdef CD_X86_KERNELS
#define CD_LANES 8
#define LK_CHAINS LK_WIDE_CHAINS
#include "line_kernel_body.h"
#define CD_LANES 4
#define LK_CHAINS LK_WIDE_CHAINS
#include "line_kernel_body.h"
#endif

uint64_t cdist__line_distance_kernel(const cdist__job *job, int shape, double unit_tol, size_t lo, size_t count)
{
    static cdist__kernel_fn chosen;
    cdist__kernel_fn f = cdist__kernel_choose(&chosen, CD_X86_VARIANTS(kernel_8, kernel_4), kernel_1);
    return f(job, shape, unit_tol, lo, count);
}
