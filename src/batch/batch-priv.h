/* SPDX-License-Identifier: MIT */
/* Batch subsystem (src/batch): the kind table, the per-range loop, the hand-out of entries to
 * the handle's worker threads and the distance kernels. Nothing here is exported. */
#ifndef CDIST_BATCH_PRIV_H
#define CDIST_BATCH_PRIV_H

#include <stddef.h>
#include <stdint.h>

#include "internal.h"

/* What a batch writes per entry. */
typedef enum cdist__out { CD_OUT_RESULT, CD_OUT_DISTANCE, CD_OUT_CONTACT, CD_OUT_GRAD } cdist__out;

/* One batch call: n entries of one kind; a full result, a contact, a gradient (with its result
 * or contact) or a distance per entry. */
typedef struct cdist__job {
    cdist_kind kind;
    size_t n;
    const char *a, *b;
    ptrdiff_t a_stride, b_stride;
    void *results;          /* cdist_result or cdist_contact array (result_size bytes each), else NULL */
    double *distances;      /* distance-only batch, else NULL */
    cdist_status *statuses; /* may be NULL */
    size_t chunk;           /* entries taken at a time by a thread (a multiple of 64, the kernels' block; at most the progress interval) */
    cdist__out out;
    size_t result_size;
    cdist_grad *grads; /* gradient batch, else NULL */
    /* A screen (cdist__batch_screen), else NULL: entry i needs its exact distance only near
     * cutoffs[i]. */
    const double *cutoffs;
} cdist__job;

static inline const void *cdist__job_a(const cdist__job *j, size_t i) { return j->a + (ptrdiff_t)i * j->a_stride; }
static inline const void *cdist__job_b(const cdist__job *j, size_t i) { return j->b + (ptrdiff_t)i * j->b_stride; }

/* Answer entries [lo, hi) of the job with handle h (any thread's own handle); failures are
 * recorded in slot. Entries are independent: the answer of an entry does not depend on which
 * thread or range computes it. */
void cdist__batch_range(cdist_query *h, const cdist__job *job, size_t lo, size_t hi, cdist__slot *slot);

/* Run the whole job with q's worker threads (cdist__workers) (or on the calling thread alone); *first gets the
 * lowest failing entry of all threads. The caller holds q's batch flag. Returns
 * CDIST_ERR_HANDLE_BUSY (and runs nothing) when another call held q while its options were to be
 * copied to the workers. With a progress callback on q (cdist_query_set_progress), the calling
 * thread reports between chunks and a non-zero return stops the job: *answered is the number of
 * entries answered, always the first ones, [0, *answered) (n when it ran to the end). */
cdist_status cdist__workers_run(cdist_query *q, const cdist__job *job, cdist__slot *first, size_t *answered);

/* A distance kernel variant: entries [lo, lo + count) of job, an int selecting the kind's shape,
 * the unit tolerance; returns the mask of the entries left for the scalar path. */
typedef uint64_t (*cdist__kernel_fn)(const cdist__job *job, int shape, double unit_tol, size_t lo, size_t count);
/* The variant this CPU runs (AVX-512, else AVX2 + FMA, else scalar; a NULL variant is skipped:
 * an AVX-512 CPU without an AVX-512 variant runs the AVX2 one), cached in *chosen. */
cdist__kernel_fn cdist__kernel_choose(cdist__kernel_fn *chosen, cdist__kernel_fn avx512, cdist__kernel_fn avx2,
                                      cdist__kernel_fn scalar);

/* Distance kernels of point-circle (disk = 0) and point-disk (disk = 1) for entries
 * [lo, lo + count), count <= 64: writes distances[i] of every entry whose inputs pass the fast
 * validation and returns a mask (bit k: entry lo + k) of the entries left for the scalar path
 * (which then produces their status and message). The checks and arithmetic are the single
 * query's fast path (src/point/point_body.h, in lanes), so the distances are bit-identical to
 * the single query's. */
uint64_t cdist__point_distance_kernel(const cdist__job *job, int disk, double unit_tol, size_t lo, size_t count);

/* Distance kernel of line-circle (shape 0), ray-circle (1) and segment-circle (2) for entries
 * [lo, lo + count), count <= 64, with the same contract: distances bit-identical to the single
 * query's (ROBUST method of the line-circle family only: the caller checks), a mask of the
 * entries left for the scalar path (src/batch/line_kernel.c). */
uint64_t cdist__line_distance_kernel(const cdist__job *job, int shape, double unit_tol, size_t lo, size_t count);

/* Distance kernel of circle-circle (ROBUST method) for entries [lo, lo + count), count <= 64:
 * writes distances[i] of every entry it certifies and returns the mask of those left for the
 * scalar path. Not bit-identical to the single query: the same certified minimum of the same F,
 * found by another search; the distances agree to an ulp or two of the scale
 * (src/batch/cc_kernel.c). */
uint64_t cdist__cc_distance_kernel(const cdist__job *job, double unit_tol, size_t lo, size_t count);

/* A circle-circle screen for scenes: distances[i] is the exact distance of cdist_batch_distance,
 * or, when the distance is certainly above cutoffs[i], a certified lower bound above
 * cutoffs[i] (rounding included), or -INFINITY when a point of the circles is within
 * cutoffs[i] (to the rounding of F there: the caller answers such a pair in full). The kernel
 * decides the last two from F at the search's hull points (ck_screen) and searches only the
 * entries they leave. */
cdist_status cdist__batch_screen(cdist_query *q, size_t n, const cdist_circle *a, const cdist_circle *b,
                                 const double *cutoffs, double *distances);

/* The single circle-circle query's certified search (cdist__cc_quick) of the frames f[k] that
 * are not NULL, k < count <= 64, in lanes (one frame per lane; lanes: 1, 4 or 8, the
 * instruction set's, the caller's check; 0: this CPU's widest): the mask of those it
 * certifies, with the angle found, its cosine and sine in t[k], c[k], s[k], each bit-identical
 * to cdist__cc_quick's of the same width, and the squared distance there in d2[k]
 * (cdist__cc_point_d2's, in the frame's units) (src/batch/cc_kernel.c). */
struct cdist__cc_frame;
uint64_t cdist__cc_quick_lanes(const struct cdist__cc_frame *const *f, int count, int lanes, double *t, double *c,
                               double *s, double *d2);
/* The single query's fast validation and basis (cdist__circle_fast_basis) of both circles of
 * the entries [lo, lo + count), count <= 64, in lanes (lanes as above): a[k], b[k] where
 * accepted, exchanged where bit k of swap is set, framed as cdist__circles_frame frames them (a
 * at the origin, both scaled by 1 / up[k], the collector's scale bscale[k]); returns the mask of
 * the entries it does not accept. */
uint64_t cdist__circle_pairs_lanes(const cdist__job *job, double unit_tol, size_t lo, int count, int lanes,
                                   uint64_t swap, cdist__circle *a, cdist__circle *b, double *up, double *bscale);

/* cdist_circle_circle(q, a[k], b[k], r[k]) for k < n, every answer the same to the bit, each
 * followed by done(ctx, k, its status) (q's message is the entry's then); the certified searches
 * of the entries that reach them run in lanes together (cdist__cc_staged_start,
 * cdist__cc_quick_lanes, cdist__cc_staged_finish). */
void cdist__circle_circle_many(cdist_query *q, size_t n, const cdist_circle *const *a, const cdist_circle *const *b,
                               cdist_result *const *r, void (*done)(void *ctx, size_t i, cdist_status st), void *ctx);

/* Distance kernels of circle-disk (disk = 0) and disk-disk (1), ROBUST method, for entries
 * [lo, lo + count), count <= 64: the single query's own stages (cdist__cd_stage_ring, _finish) with the
 * rim searches of the block in lanes (cdist__cc_quick_lanes), so the distances are
 * bit-identical to the single query's; the mask of the entries left for the scalar path
 * (src/batch/cd_kernel.c). */
uint64_t cdist__cd_distance_kernel(const cdist__job *job, int disk, double unit_tol, size_t lo, size_t count);

#endif
