/* SPDX-License-Identifier: MIT */
/* Distance kernel of circle-circle for cdist_batch_distance: the certified search of the single
 * query (src/circles/cc_search_body.h) in 8 lanes (AVX-512), 4 lanes (AVX2) or 1, one entry per
 * lane, after the single query's validation, framing and problem set up in lanes operation by
 * operation and its ring (ring_lanes.h, so that F is the single query's F to the last bit), and
 * the distance at the angle found by the single query's formula (cdist__cc_point_d2). Whatever
 * the search does not certify goes to the scalar path. The method and why the two agree:
 * docs/circles.md. */
#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "batch-priv.h"
#include "circles/cc_search.h"
#include "base/lanes/lanes.h"

/* The columns of a block: the ring (al, be, ga, ha, hb, hc), B's radius s, R^2, the bounds
 * W1 = |al| + |be| >= |w'|, Hh = |ha| + |hb|, Hc0 = |hc|, Lw = 2 R + |C| of convex(), and the
 * two factors scaling the distance back (cdist__cc_prepare's unscale, 2^e of the frame). */
enum { CK_C_ALX, CK_C_ALY, CK_C_ALZ, CK_C_BEX, CK_C_BEY, CK_C_BEZ, CK_C_GAX, CK_C_GAY, CK_C_GAZ, CK_C_HA, CK_C_HB,
       CK_C_HC, CK_C_S, CK_C_R2, CK_C_W1, CK_C_HH, CK_C_HC0, CK_C_LW, CK_C_UNSC, CK_C_UP, CK_C_CUT, CK_NC };
typedef struct ck_block {
    double col[CK_NC][64];
    double t[64]; /* the angle found */
    double ct[64], st[64]; /* its cosine and sine, by rotation from the basin's centre */
    double d[64]; /* the distance there */
    /* a screen's verdicts (cdist__batch_screen): -inf at most the cutoff, else a certified lower
     * bound above it */
    double screen[64];
} ck_block;

#define CC_LANES_BODY "batch/cc_kernel_body.h"
#include "circles/cc_search_lanes.h"

typedef unsigned (*ck_setup_fn)(const cdist__job *job, double unit_tol, size_t lo, int base, int n, ck_block *b);
typedef unsigned (*ck_search_fn)(ck_block *b, int g);
typedef void (*ck_final_fn)(ck_block *b, int g);
/* The kernel's parts in one instruction set's lanes. */
typedef struct ck_variant {
    int lanes;
    ck_setup_fn setup;
    ck_search_fn search, screen, search_quick;
    ck_final_fn final, point_d2;
    /* the circle-disk kernel's validation and framing (cdist__circle_pairs_lanes) */
    unsigned (*circles)(const cdist__job *job, double unit_tol, size_t lo, int base, int n, unsigned swap,
                        cdist__circle *a, cdist__circle *b, double *up, double *bscale);
} ck_variant;

static const ck_variant ck_v1 = {1, ck_setup_1, ck_search_1, ck_screen_1, ck_search_quick_1, ck_final_1,
                                 ck_point_d2_1, ck_circles_1};
#ifdef CD_X86_KERNELS
static const ck_variant ck_v4 = {4, ck_setup_4, ck_search_4, ck_screen_4, ck_search_quick_4, ck_final_4,
                                 ck_point_d2_4, ck_circles_4};
static const ck_variant ck_v8 = {8, ck_setup_8, ck_search_8, ck_screen_8, ck_search_quick_8, ck_final_8,
                                 ck_point_d2_8, ck_circles_8};
#endif

static uint64_t ck_run(const ck_variant *v, const cdist__job *job, double unit_tol, size_t lo, size_t count);

/* A screen's block: the verdicts of ck_screen where it decides; the entries it leaves are
 * packed into lanes of their own for the whole search (so that a group's lanes stop together). */
static uint64_t ck_run_screen(const ck_variant *v, const cdist__job *job, double unit_tol, size_t lo, int n,
                              uint64_t left, ck_block *b)
{
    int lanes = v->lanes, groups = (n + lanes - 1) / lanes * lanes;
    uint64_t open = 0, all = n < 64 ? ((uint64_t)1 << n) - 1 : ~(uint64_t)0;
    for (int g = 0; g < groups; g += lanes) {
        uint64_t lane_mask = ((uint64_t)1 << lanes) - 1;
        if (((left >> g) & lane_mask) != lane_mask) open |= (uint64_t)v->screen(b, g) << g;
    }
    open &= all & ~left;
    cdist_circle pa[64], pb[64];
    double pd[64];
    int idx[64], m = 0;
    for (int k = 0; k < n; k++) {
        if (left >> k & 1) continue;
        if (!(open >> k & 1)) {
            job->distances[lo + (size_t)k] = b->screen[k];
            continue;
        }
        memcpy(&pa[m], cdist__job_a(job, lo + (size_t)k), sizeof pa[m]);
        memcpy(&pb[m], cdist__job_b(job, lo + (size_t)k), sizeof pb[m]);
        idx[m++] = k;
    }
    left &= all; /* the lanes past the block's last entry are no entries */
    if (m == 0) return left;
    cdist__job packed = *job;
    packed.n = (size_t)m;
    packed.a = (const char *)pa;
    packed.b = (const char *)pb;
    packed.a_stride = packed.b_stride = sizeof pa[0];
    packed.distances = pd;
    packed.cutoffs = NULL;
    uint64_t pl = ck_run(v, &packed, unit_tol, 0, (size_t)m);
    for (int j = 0; j < m; j++) {
        if (pl >> j & 1) left |= (uint64_t)1 << idx[j];
        else job->distances[lo + (size_t)idx[j]] = pd[j];
    }
    return left;
}

static uint64_t ck_run(const ck_variant *v, const cdist__job *job, double unit_tol, size_t lo, size_t count)
{
    cdist__cc_search_tables();
    ck_block b;
    uint64_t left = 0;
    int lanes = v->lanes, n = (int)count, groups = (n + lanes - 1) / lanes * lanes;
    ck_search_fn search = v->search;
    ck_final_fn final = v->final;
    for (int g = 0; g < groups; g += lanes)
        left |= (uint64_t)v->setup(job, unit_tol, lo, g, n - g < lanes ? n - g : lanes, &b) << g;
    if (job->cutoffs) return ck_run_screen(v, job, unit_tol, lo, n, left, &b);
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
    return ck_run(&ck_v1, job, tol, lo, count);
}

#ifdef CD_X86_KERNELS
static uint64_t kernel_avx512(const cdist__job *job, int shape, double tol, size_t lo, size_t count)
{
    (void)shape;
    return ck_run(&ck_v8, job, tol, lo, count);
}

static uint64_t kernel_avx2(const cdist__job *job, int shape, double tol, size_t lo, size_t count)
{
    (void)shape;
    return ck_run(&ck_v4, job, tol, lo, count);
}
#endif

/* The variant of a lane width (cdist__lanes_width). */
static const ck_variant *ck_variant_of(int lanes)
{
#ifdef CD_X86_KERNELS
    lanes = cdist__lanes_width(lanes);
    if (lanes == 8) return &ck_v8;
    if (lanes == 4) return &ck_v4;
#else
    (void)lanes;
#endif
    return &ck_v1;
}

uint64_t cdist__cc_quick_lanes(const cdist__cc_frame *const *f, int count, int lanes, double *t, double *c, double *s,
                               double *d2)
{
    const ck_variant *v = ck_variant_of(lanes);
    cdist__cc_search_tables();
    ck_block b;
    uint64_t todo = 0;
    int W = v->lanes, groups = (count + W - 1) / W * W;
    for (int k = 0; k < groups; k++) {
        const cdist__cc_frame *e = k < count ? f[k] : NULL;
        if (e) todo |= (uint64_t)1 << k;
        const double col[CK_NC] = {e ? e->rg.al.x : 0.0, e ? e->rg.al.y : 0.0, e ? e->rg.al.z : 0.0,
                                   e ? e->rg.be.x : 0.0, e ? e->rg.be.y : 0.0, e ? e->rg.be.z : 0.0,
                                   e ? e->rg.ga.x : 0.0, e ? e->rg.ga.y : 0.0, e ? e->rg.ga.z : 0.0,
                                   e ? e->rg.ha : 0.0,   e ? e->rg.hb : 0.0,   e ? e->rg.hc : 0.0,
                                   e ? e->s : 0.0,       e ? e->R * e->R : 0.0, e ? e->W1 : 0.0,
                                   e ? e->Hh : 0.0,      e ? e->Hc0 : 0.0,    e ? e->Lw : 0.0, 0.0, 0.0, NAN};
        for (int j = 0; j < CK_NC; j++) b.col[j][k] = col[j];
    }
    uint64_t found = 0, lane_mask = ((uint64_t)1 << W) - 1;
    for (int g = 0; g < groups; g += W) {
        if (!((todo >> g) & lane_mask)) continue;
        uint64_t ok = ~(uint64_t)v->search_quick(&b, g) & lane_mask & (todo >> g);
        if (ok) v->point_d2(&b, g);
        found |= ok << g;
    }
    for (int k = 0; k < count; k++)
        if (found >> k & 1) {
            t[k] = b.t[k];
            c[k] = b.ct[k];
            s[k] = b.st[k];
            d2[k] = b.d[k];
        }
    return found;
}

void cdist__circle_circle_many(cdist_query *q, size_t n, const cdist_circle *const *a, const cdist_circle *const *b,
                               cdist_result *const *r, void (*done)(void *ctx, size_t i, cdist_status st), void *ctx)
{
    enum { SUB = 16 }; /* the entries whose stages are kept at once (in the first-level cache) */
    cdist__cc_staged x[SUB];
    const cdist__cc_frame *f[SUB];
    double t[SUB], c[SUB], s[SUB], d2[SUB];
    int staged[SUB];
    for (size_t lo = 0; lo < n; lo += SUB) {
        int cnt = n - lo < SUB ? (int)(n - lo) : SUB, m = 0;
        for (int k = 0; k < cnt; k++)
            if ((staged[k] = cdist__cc_staged_start(q, a[lo + (size_t)k], b[lo + (size_t)k], &x[k]))) f[m++] = &x[k].rs.f;
        uint64_t found = m ? cdist__cc_quick_lanes(f, m, 0, t, c, s, d2) : 0;
        for (int k = 0, j = 0; k < cnt; k++) {
            size_t i = lo + (size_t)k;
            cdist_status st;
            if (!staged[k]) {
                st = cdist_circle_circle(q, a[i], b[i], r[i]);
            } else {
                st = cdist__cc_staged_finish(q, &x[k], (int)(found >> j & 1), t[j], c[j], s[j], r[i]);
                j++;
            }
            done(ctx, i, st);
        }
    }
}

uint64_t cdist__circle_pairs_lanes(const cdist__job *job, double unit_tol, size_t lo, int count, int lanes,
                                   uint64_t swap, cdist__circle *a, cdist__circle *b, double *up, double *bscale)
{
    const ck_variant *v = ck_variant_of(lanes);
    uint64_t bad = 0;
    for (int g = 0; g < count; g += v->lanes) {
        int n = count - g < v->lanes ? count - g : v->lanes;
        unsigned sw = (unsigned)(swap >> g) & ((1u << v->lanes) - 1u);
        bad |= (uint64_t)v->circles(job, unit_tol, lo, g, n, sw, a + g, b + g, up + g, bscale + g) << g;
    }
    return bad;
}

uint64_t cdist__cc_distance_kernel(const cdist__job *job, double unit_tol, size_t lo, size_t count)
{
    static cdist__kernel_fn chosen;
    cdist__kernel_fn f = cdist__kernel_choose(&chosen, CD_X86_VARIANTS(kernel_avx512, kernel_avx2), kernel_scalar);
    return f(job, 0, unit_tol, lo, count);
}
