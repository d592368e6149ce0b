/* SPDX-License-Identifier: MIT */
/* Distance kernel of circle-circle for cdist_batch_distance: a certified search of the robust
 * method's F (src/circles/cc_engine.c) in 8 lanes (AVX-512), 4 lanes (AVX2) or 1, one entry per
 * lane, and the distance recomputed at the angle found by the robust method's own formula.
 * The same search answers the single query first (cdist__cc_quick, ck_quick in
 * cc_kernel_body.h): one entry, its grid, zoom points and hull points spread over the lanes,
 * with the same steps and certificate (and so, on the AVX-512 variant, the same angle and
 * distance as the kernel, bit for bit, on cc_random).
 *
 * Per lane group, the set-up: the single query's validation (the fast path of
 * cdist__check_circle), framing (cdist__circles_frame), problem (cdist__cc_prepare: A the
 * parameterised circle, B the other, scaled to L in [0.5, 1)) and ring coefficients of F(t), the
 * squared distance from A's point at angle t to B (cdist__ring_init), operation by operation, so
 * that F is the single query's F to the last bit.
 * Then the search (cc_kernel_body.h):
 *   1. Grid: F at CK_GRID equally spaced angles. F extends to a concave function G of
 *      (cos t, sin t) (cc_engine.c), so on an arc of width w, F >= min(F(a), F(b), G(T)) with T
 *      the tangents' intersection, and G(T) = F_ext(T) - R^2 tan^2(w / 2) where F_ext is the
 *      same formula at the point (cos, sin) / cos(w / 2). The bound of every interval outside
 *      the basin (the two intervals around the best grid angle) is kept: the smallest, minlb.
 *   2. Zoom: the basin [t - h, t + h] is certified convex (F''/2 at its ends against a bound of
 *      F'''/2, as the engine's convex()); else it is split in 8, the hull bounds of the six
 *      subintervals away from the best point join minlb and the basin shrinks to the two
 *      around it (h / 4), up to CK_LEVELS times.
 *   3. Newton on F' in the convex basin (one minimum there), cos and sin by rotation from the
 *      basin's centre with a Taylor series of the offset.
 *   4. The certificate: minlb exceeds F at the angle found by CD_CCK_CERT_MARGIN, so no point
 *      outside the final basin is closer, and F there is at least CD_CCK_MIN_F.
 *   5. The distance at the angle found: cdist__cc_point_d2, the robust method's formula
 *      (double-double), in lanes operation by operation, scaled back as the single query scales
 *      its answer.
 * Whatever fails (a check of the fast validation, a zero radius, equal radii, a near-tie of two
 * minima, a basin on B's axis or not certified in CK_LEVELS levels, Newton not settled, circles
 * that touch or cross) goes to the scalar path. The angle differs from the single query's by
 * rounding only (both are the certified unique minimum of the same F, settled by Newton); at a
 * minimum d* >= 1e-12 of the scale the distance depends on it to second order (tolerances.h),
 * and the two agree to an ulp of the scale. */
#include <float.h>
#include <math.h>
#include <pthread.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "batch-priv.h"
#include "circles/circles-priv.h"
#include "base/lanes/lanes.h"

#define CK_GRID 32     /* grid angles (97% of random pairs prune every interval outside the basin) */
#define CK_LEVELS 7    /* basin half-widths 2 pi / CK_GRID * 4^-l, l < 7: down to 5e-5 rad */
#define CK_NEWTON_MAX 8 /* from a certified basin Newton settles in 3 to 5 steps */
#define CK_FIRST_CONVEX 2 /* the level of the first convexity check (measured: below it < 7% pass) */
/* The single query's search gives up after this many levels (the scan then answers): 99.3% of
 * cc_random certify by level 3, the rest by 4; basins that are not convex by then are mostly
 * near-touching circles, which the scan handles. */
#define CK_QUICK_LEVELS 5

/* The columns of a block: the ring (al, be, ga, ha, hb, hc), B's radius s, R^2, the bounds
 * W1 = |al| + |be| >= |w'|, Hh = |ha| + |hb|, Hc0 = |hc|, Lw = 2 R + |C| of convex(), and the
 * two factors scaling the distance back (cdist__cc_prepare's unscale, 2^e of the frame). */
enum { CK_C_ALX, CK_C_ALY, CK_C_ALZ, CK_C_BEX, CK_C_BEY, CK_C_BEZ, CK_C_GAX, CK_C_GAY, CK_C_GAZ, CK_C_HA, CK_C_HB,
       CK_C_HC, CK_C_S, CK_C_R2, CK_C_W1, CK_C_HH, CK_C_HC0, CK_C_LW, CK_C_UNSC, CK_C_UP, CK_NC };
typedef struct ck_block {
    double col[CK_NC][64];
    double t[64]; /* the angle found */
    double ct[64], st[64]; /* its cosine and sine, by rotation from the basin's centre */
    double d[64]; /* the distance there */
} ck_block;

/* Angles of the search, computed once (ck_tables_init). */
static struct {
    double grid_c[CK_GRID], grid_s[CK_GRID]; /* cos, sin of 2 pi j / CK_GRID */
    double hull_c[CK_GRID], hull_s[CK_GRID]; /* the hull point of [t_j, t_j+1]: cos, sin of its middle / cos(pi / CK_GRID) */
    double grid_tan2;                        /* tan^2(pi / CK_GRID) */
    double half[CK_LEVELS];                  /* basin half-width h_l */
    double end_c[CK_LEVELS], end_s[CK_LEVELS]; /* cos, sin of h_l */
    double sub_c[CK_LEVELS][4], sub_s[CK_LEVELS][4]; /* cos, sin of k h_l / 4, k = 1..3 */
    double hull_sub_c[CK_LEVELS][4], hull_sub_s[CK_LEVELS][4]; /* of (2m + 1) h_l / 8, / cos(h_l / 8) */
    double sub_tan2[CK_LEVELS];              /* tan^2(h_l / 8) */
    /* the single query's zoom (cdist__cc_quick), lane k: cos, sin of (k - 4) h_l / 4 and of the
     * hull point of [(k - 4) h_l / 4, (k - 3) h_l / 4], (2 k - 7) h_l / 8, / cos(h_l / 8) */
    double zoom_c[CK_LEVELS][8], zoom_s[CK_LEVELS][8];
    double zoom_hull_c[CK_LEVELS][8], zoom_hull_s[CK_LEVELS][8];
    double lane_index[CK_GRID]; /* j at index j */
} ck_tab;
static pthread_once_t ck_tab_once = PTHREAD_ONCE_INIT;

static void ck_tables_init(void)
{
    double step = 2.0 * M_PI / CK_GRID, sec = 1.0 / cos(0.5 * step);
    for (int j = 0; j < CK_GRID; j++) {
        ck_tab.grid_c[j] = cos(j * step);
        ck_tab.grid_s[j] = sin(j * step);
        ck_tab.hull_c[j] = cos((j + 0.5) * step) * sec;
        ck_tab.hull_s[j] = sin((j + 0.5) * step) * sec;
        ck_tab.lane_index[j] = j;
    }
    ck_tab.grid_tan2 = tan(0.5 * step) * tan(0.5 * step);
    double h = step;
    for (int l = 0; l < CK_LEVELS; l++, h *= 0.25) {
        ck_tab.half[l] = h;
        ck_tab.end_c[l] = cos(h);
        ck_tab.end_s[l] = sin(h);
        double q = 0.125 * h, qsec = 1.0 / cos(q);
        for (int k = 0; k < 4; k++) {
            ck_tab.sub_c[l][k] = cos(k * 0.25 * h);
            ck_tab.sub_s[l][k] = sin(k * 0.25 * h);
            ck_tab.hull_sub_c[l][k] = cos((2 * k + 1) * q) * qsec;
            ck_tab.hull_sub_s[l][k] = sin((2 * k + 1) * q) * qsec;
        }
        ck_tab.sub_tan2[l] = tan(q) * tan(q);
        for (int k = 0; k < 8; k++) {
            ck_tab.zoom_c[l][k] = cos((k - 4) * 0.25 * h);
            ck_tab.zoom_s[l][k] = sin((k - 4) * 0.25 * h);
            ck_tab.zoom_hull_c[l][k] = cos((2 * k - 7) * q) * qsec;
            ck_tab.zoom_hull_s[l][k] = sin((2 * k - 7) * q) * qsec;
        }
    }
}

#define CD_LANES 1
#include "base/lanes/lanes_def.h"
#include "base/lanes/lanes_vec.h"
#include "cc_kernel_body.h"
#include "base/lanes/lanes_undef.h"

#ifdef CD_X86_KERNELS
CD_LANES_TARGET_PUSH("avx512f,fma")
#define CD_LANES 8
#include "base/lanes/lanes_def.h"
#include "base/lanes/lanes_vec.h"
#include "cc_kernel_body.h"
#include "base/lanes/lanes_undef.h"
CD_LANES_TARGET_POP

CD_LANES_TARGET_PUSH("avx2,fma")
#define CD_LANES 4
#include "base/lanes/lanes_def.h"
#include "base/lanes/lanes_vec.h"
#include "cc_kernel_body.h"
#include "base/lanes/lanes_undef.h"
CD_LANES_TARGET_POP
#endif

typedef unsigned (*ck_setup_fn)(const cdist__job *job, double unit_tol, size_t lo, int base, int n, ck_block *b);
typedef unsigned (*ck_search_fn)(ck_block *b, int g);
typedef void (*ck_final_fn)(ck_block *b, int g);

static uint64_t ck_run(ck_setup_fn setup, ck_search_fn search, ck_final_fn final, int lanes, const cdist__job *job,
                       double unit_tol, size_t lo, size_t count)
{
    pthread_once(&ck_tab_once, ck_tables_init);
    ck_block b;
    uint64_t left = 0;
    int n = (int)count, groups = (n + lanes - 1) / lanes * lanes;
    for (int g = 0; g < groups; g += lanes)
        left |= (uint64_t)setup(job, unit_tol, lo, g, n - g < lanes ? n - g : lanes, &b) << g;
    for (int g = 0; g < groups; g += lanes) {
        uint64_t lane_mask = ((uint64_t)1 << lanes) - 1;
        if (((left >> g) & lane_mask) == lane_mask) continue;
        left |= (uint64_t)search(&b, g) << g;
        if (((left >> g) & lane_mask) != lane_mask) final(&b, g);
    }
    if (n < 64) left &= ((uint64_t)1 << n) - 1;
    for (int k = 0; k < n; k++) {
        if (left >> k & 1) continue;
        if (isfinite(b.d[k])) job->distances[lo + (size_t)k] = b.d[k];
        else left |= (uint64_t)1 << k;
    }
    return left;
}

static uint64_t kernel_scalar(const cdist__job *job, int shape, double tol, size_t lo, size_t count)
{
    (void)shape;
    return ck_run(ck_setup_1, ck_search_1, ck_final_1, 1, job, tol, lo, count);
}

#ifdef CD_X86_KERNELS
static uint64_t kernel_avx512(const cdist__job *job, int shape, double tol, size_t lo, size_t count)
{
    (void)shape;
    return ck_run(ck_setup_8, ck_search_8, ck_final_8, 8, job, tol, lo, count);
}

static uint64_t kernel_avx2(const cdist__job *job, int shape, double tol, size_t lo, size_t count)
{
    (void)shape;
    return ck_run(ck_setup_4, ck_search_4, ck_final_4, 4, job, tol, lo, count);
}
#endif

int cdist__cc_quick(const cdist__cc_frame *f, double *t, double *c, double *s)
{
    pthread_once(&ck_tab_once, ck_tables_init);
#ifdef CD_X86_KERNELS
    int isa = cdist__lanes_isa();
    if (isa == CD_ISA_AVX512) return ck_quick_8(f, t, c, s);
    if (isa == CD_ISA_AVX2) return ck_quick_4(f, t, c, s);
#endif
    return ck_quick_1(f, t, c, s);
}

uint64_t cdist__cc_distance_kernel(const cdist__job *job, double unit_tol, size_t lo, size_t count)
{
    static cdist__kernel_fn chosen;
    cdist__kernel_fn f = cdist__kernel_choose(&chosen, CD_X86_VARIANTS(kernel_avx512, kernel_avx2), kernel_scalar);
    return f(job, 0, unit_tol, lo, count);
}
