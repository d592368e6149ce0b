/* SPDX-License-Identifier: MIT */
/* The batch entry points: one generic entry per result type over a table of query kinds. A new
 * kind adds one enum value and one row here. */
#include <math.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "batch-priv.h"

typedef cdist_status (*kind_fn)(cdist_query *q, const void *a, const void *b, cdist_result *r);

#define WRAP(fn, TA, TB)                                                                                      \
    static cdist_status k_##fn(cdist_query *q, const void *a, const void *b, cdist_result *r)                \
    {                                                                                                         \
        return cdist_##fn(q, (const TA *)a, (const TB *)b, r);                                               \
    }
WRAP(point_circle, cdist_vec3, cdist_circle)
WRAP(point_disk, cdist_vec3, cdist_circle)
WRAP(line_circle, cdist_line, cdist_circle)
WRAP(ray_circle, cdist_ray, cdist_circle)
WRAP(segment_circle, cdist_segment, cdist_circle)
WRAP(circle_circle, cdist_circle, cdist_circle)
WRAP(line_disk, cdist_line, cdist_circle)
WRAP(ray_disk, cdist_ray, cdist_circle)
WRAP(segment_disk, cdist_segment, cdist_circle)
WRAP(circle_disk, cdist_circle, cdist_circle)
WRAP(disk_disk, cdist_circle, cdist_circle)
WRAP(arc_circle, cdist_arc, cdist_circle)
WRAP(arc_arc, cdist_arc, cdist_arc)
WRAP(segment_arc, cdist_segment, cdist_arc)
WRAP(arc_disk, cdist_arc, cdist_circle)
WRAP(helix_circle, cdist_helix, cdist_circle)
WRAP(helix_disk, cdist_helix, cdist_circle)
WRAP(bezier3_circle, cdist_bezier3, cdist_circle)
WRAP(bezier3_disk, cdist_bezier3, cdist_circle)
#undef WRAP

static cdist_status k_curve_circle(cdist_query *q, const void *a, const void *b, cdist_result *r)
{
    const cdist_curve *c = a;
    return cdist_curve_circle(q, c->fn, c->user, c->t0, c->t1, b, r);
}

static cdist_status k_curve_disk(cdist_query *q, const void *a, const void *b, cdist_result *r)
{
    const cdist_curve *c = a;
    return cdist_curve_disk(q, c->fn, c->user, c->t0, c->t1, b, r);
}

/* The distance kernel of a kind, if any (zero, the default of a row: none). */
enum {
    NO_KERNEL = 0,
    POINT_CIRCLE_KERNEL,
    POINT_DISK_KERNEL,
    LINE_CIRCLE_KERNEL, /* the line kernels in the order of their shapes: line, ray, segment */
    RAY_CIRCLE_KERNEL,
    SEGMENT_CIRCLE_KERNEL,
    CIRCLE_CIRCLE_KERNEL
};

/* A kind's name is its family's (cdist__family_table): the kind and family numbers agree. */
static const struct {
    size_t size_a, size_b;
    kind_fn full;
    int kernel;
} kinds[] = {
    [CDIST_KIND_POINT_CIRCLE] = {sizeof(cdist_vec3), sizeof(cdist_circle), k_point_circle,
                                 .kernel = POINT_CIRCLE_KERNEL},
    [CDIST_KIND_POINT_DISK] = {sizeof(cdist_vec3), sizeof(cdist_circle), k_point_disk,
                               .kernel = POINT_DISK_KERNEL},
    [CDIST_KIND_LINE_CIRCLE] = {sizeof(cdist_line), sizeof(cdist_circle), k_line_circle, .kernel = LINE_CIRCLE_KERNEL},
    [CDIST_KIND_RAY_CIRCLE] = {sizeof(cdist_ray), sizeof(cdist_circle), k_ray_circle, .kernel = RAY_CIRCLE_KERNEL},
    [CDIST_KIND_SEGMENT_CIRCLE] = {sizeof(cdist_segment), sizeof(cdist_circle), k_segment_circle,
                                   .kernel = SEGMENT_CIRCLE_KERNEL},
    [CDIST_KIND_CIRCLE_CIRCLE] = {sizeof(cdist_circle), sizeof(cdist_circle), k_circle_circle,
                                  .kernel = CIRCLE_CIRCLE_KERNEL},
    [CDIST_KIND_LINE_DISK] = {sizeof(cdist_line), sizeof(cdist_circle), k_line_disk},
    [CDIST_KIND_RAY_DISK] = {sizeof(cdist_ray), sizeof(cdist_circle), k_ray_disk},
    [CDIST_KIND_SEGMENT_DISK] = {sizeof(cdist_segment), sizeof(cdist_circle), k_segment_disk},
    [CDIST_KIND_CIRCLE_DISK] = {sizeof(cdist_circle), sizeof(cdist_circle), k_circle_disk},
    [CDIST_KIND_DISK_DISK] = {sizeof(cdist_circle), sizeof(cdist_circle), k_disk_disk},
    [CDIST_KIND_CURVE_CIRCLE] = {sizeof(cdist_curve), sizeof(cdist_circle), k_curve_circle},
    [CDIST_KIND_CURVE_DISK] = {sizeof(cdist_curve), sizeof(cdist_circle), k_curve_disk},
    [CDIST_KIND_ARC_CIRCLE] = {sizeof(cdist_arc), sizeof(cdist_circle), k_arc_circle},
    [CDIST_KIND_ARC_ARC] = {sizeof(cdist_arc), sizeof(cdist_arc), k_arc_arc},
    [CDIST_KIND_SEGMENT_ARC] = {sizeof(cdist_segment), sizeof(cdist_arc), k_segment_arc},
    [CDIST_KIND_ARC_DISK] = {sizeof(cdist_arc), sizeof(cdist_circle), k_arc_disk},
    [CDIST_KIND_HELIX_CIRCLE] = {sizeof(cdist_helix), sizeof(cdist_circle), k_helix_circle},
    [CDIST_KIND_HELIX_DISK] = {sizeof(cdist_helix), sizeof(cdist_circle), k_helix_disk},
    [CDIST_KIND_BEZIER3_CIRCLE] = {sizeof(cdist_bezier3), sizeof(cdist_circle), k_bezier3_circle},
    [CDIST_KIND_BEZIER3_DISK] = {sizeof(cdist_bezier3), sizeof(cdist_circle), k_bezier3_disk},
};
#define KIND_COUNT ((int)(sizeof kinds / sizeof kinds[0]))
#define SAME_NUMBER(K) _Static_assert((int)CDIST_KIND_##K == (int)CD_FAM_##K, "cdist_kind and family of " #K)
SAME_NUMBER(POINT_CIRCLE);
SAME_NUMBER(POINT_DISK);
SAME_NUMBER(LINE_CIRCLE);
SAME_NUMBER(RAY_CIRCLE);
SAME_NUMBER(SEGMENT_CIRCLE);
SAME_NUMBER(CIRCLE_CIRCLE);
SAME_NUMBER(LINE_DISK);
SAME_NUMBER(RAY_DISK);
SAME_NUMBER(SEGMENT_DISK);
SAME_NUMBER(CIRCLE_DISK);
SAME_NUMBER(DISK_DISK);
SAME_NUMBER(CURVE_CIRCLE);
SAME_NUMBER(CURVE_DISK);
SAME_NUMBER(ARC_CIRCLE);
SAME_NUMBER(ARC_ARC);
SAME_NUMBER(SEGMENT_ARC);
SAME_NUMBER(ARC_DISK);
SAME_NUMBER(HELIX_CIRCLE);
SAME_NUMBER(HELIX_DISK);
SAME_NUMBER(BEZIER3_CIRCLE);
SAME_NUMBER(BEZIER3_DISK);
#undef SAME_NUMBER
_Static_assert(KIND_COUNT == CD_FAM_COUNT, "one family per cdist_kind");

static int kind_ok(cdist_kind k) { return (unsigned)k < (unsigned)KIND_COUNT && kinds[k].full; }

int cdist_kind_count(void) { return KIND_COUNT; }
const char *cdist_kind_name(cdist_kind k) { return kind_ok(k) ? cdist__family_table[k].name : NULL; }
size_t cdist_kind_size_a(cdist_kind k) { return kind_ok(k) ? kinds[k].size_a : 0; }
size_t cdist_kind_size_b(cdist_kind k) { return kind_ok(k) ? kinds[k].size_b : 0; }

/* ---- one range of entries ---- */

static void record(cdist__slot *slot, cdist_query *h, size_t i, cdist_status st)
{
    if (st == CDIST_OK || slot->fail != SIZE_MAX) return; /* a thread meets its entries in order */
    slot->fail = i;
    slot->status = st;
    memcpy(slot->message, h->message, sizeof slot->message);
}

/* The scalar path of one entry: the single query itself. */
static void entry(cdist_query *h, const cdist__job *job, size_t i, cdist__slot *slot)
{
    kind_fn f = kinds[job->kind].full;
    cdist_status st;
    if (job->results) {
        st = f(h, cdist__job_a(job, i), cdist__job_b(job, i), &job->results[i]);
    } else {
        cdist_result r;
        st = f(h, cdist__job_a(job, i), cdist__job_b(job, i), &r);
        job->distances[i] = r.distance;
    }
    if (job->statuses) job->statuses[i] = st;
    record(slot, h, i, st);
}

static inline size_t lowest_bit(uint64_t x)
{
#if defined(__GNUC__)
    return (size_t)__builtin_ctzll(x);
#else
    size_t k = 0;
    while (!(x >> k & 1)) k++;
    return k;
#endif
}

/* The kernel of a job, if it is to run: distance-only, and the line and circle kernels only for
 * the method they implement (the ROBUST core; the three line kinds run the line-circle family's
 * method). */
static int job_kernel(const cdist_query *h, const cdist__job *job)
{
    int kernel = job->distances ? kinds[job->kind].kernel : NO_KERNEL;
    if (kernel >= LINE_CIRCLE_KERNEL && kernel <= SEGMENT_CIRCLE_KERNEL &&
        cdist__family_method(h, CD_FAM_LINE_CIRCLE) == CDIST_METHOD_POLYNOMIAL)
        return NO_KERNEL;
    if (kernel == CIRCLE_CIRCLE_KERNEL && cdist__family_method(h, CD_FAM_CIRCLE_CIRCLE) != CDIST_METHOD_ROBUST)
        return NO_KERNEL;
    return kernel;
}

/* Entries [lo, lo + count) of the job through its kernel; the mask of those left. */
static uint64_t run_kernel(int kernel, const cdist_query *h, const cdist__job *job, size_t lo, size_t count)
{
    if (kernel == CIRCLE_CIRCLE_KERNEL) return cdist__cc_distance_kernel(job, h->unit_tol, lo, count);
    if (kernel >= LINE_CIRCLE_KERNEL)
        return cdist__line_distance_kernel(job, kernel - LINE_CIRCLE_KERNEL, h->unit_tol, lo, count);
    return cdist__point_distance_kernel(job, kernel == POINT_DISK_KERNEL, h->unit_tol, lo, count);
}

void cdist__batch_range(cdist_query *h, const cdist__job *job, size_t lo, size_t hi, cdist__slot *slot)
{
    int kernel = job_kernel(h, job);
    if (kernel != NO_KERNEL) {
        for (size_t i = lo; i < hi; i += 64) {
            size_t cnt = hi - i < 64 ? hi - i : 64;
            uint64_t left = run_kernel(kernel, h, job, i, cnt);
            if (job->statuses)
                for (size_t k = 0; k < cnt; k++) job->statuses[i + k] = CDIST_OK;
            for (; left; left &= left - 1) entry(h, job, i + lowest_bit(left), slot);
        }
        return;
    }
    for (size_t i = lo; i < hi; i++) entry(h, job, i, slot);
}

/* ---- the entry points ---- */

/* NULL handle or arrays, bad kind: every writable output says so. */
static cdist_status fail_all(cdist_query *q, cdist_status st, size_t n, cdist_result *results, double *distances,
                             cdist_status *statuses, const char *why)
{
    for (size_t i = 0; i < n; i++) {
        if (results) cdist__begin(NULL, &results[i]);
        if (distances) distances[i] = NAN;
        if (statuses) statuses[i] = st;
    }
    if (!q) return st;
    cdist__begin(q, NULL);
    return cdist__fail(q, st, "batch: %s", why);
}

static cdist_status run_locked(cdist_query *q, cdist_kind kind, size_t n, const void *a, ptrdiff_t a_stride,
                               const void *b, ptrdiff_t b_stride, cdist_result *results, double *distances,
                               cdist_status *statuses)
{
    if (!kind_ok(kind)) {
        fail_all(q, CDIST_ERR_BAD_KIND, n, results, distances, statuses, "");
        return cdist__fail(q, CDIST_ERR_BAD_KIND, "batch: %d is not a cdist_kind (0..%d)", (int)kind, KIND_COUNT - 1);
    }
    if (!a || !b || !(results || distances))
        return fail_all(q, CDIST_ERR_NULL_ARGUMENT, n, results, distances, statuses,
                        !a ? "first object array is NULL" : !b ? "second object array is NULL" : "output array is NULL");
    cdist__job job = {kind, n, a, b, a_stride, b_stride, results, distances, statuses, 0};
    cdist__slot first;
    if (cdist__workers_run(q, &job, &first)) /* another call held the handle while the options were read */
        return fail_all(NULL, CDIST_ERR_HANDLE_BUSY, n, results, distances, statuses, "");
    cdist__begin(q, NULL);
    if (first.fail == SIZE_MAX) return CDIST_OK;
    return cdist__fail(q, first.status, "batch entry %zu: %.200s", first.fail, first.message);
}

static cdist_status run(cdist_query *q, cdist_kind kind, size_t n, const void *a, ptrdiff_t a_stride, const void *b,
                        ptrdiff_t b_stride, cdist_result *results, double *distances, cdist_status *statuses)
{
    if (!q) return n ? fail_all(q, CDIST_ERR_NULL_ARGUMENT, n, results, distances, statuses, "") : CDIST_ERR_NULL_ARGUMENT;
    /* One batch at a time per handle (it owns the worker pool and the worker handles); a second
     * one fails every entry without touching the handle. */
    if (atomic_exchange_explicit(&q->batch_busy, 1, memory_order_acquire))
        return fail_all(NULL, CDIST_ERR_HANDLE_BUSY, n, results, distances, statuses, "");
    cdist_status st = CDIST_OK;
    if (n == 0)
        cdist__begin(q, NULL);
    else
        st = run_locked(q, kind, n, a, a_stride, b, b_stride, results, distances, statuses);
    atomic_store_explicit(&q->batch_busy, 0, memory_order_release);
    return st;
}

cdist_status cdist_batch(cdist_query *q, cdist_kind kind, size_t n, const void *a, ptrdiff_t a_stride, const void *b,
                         ptrdiff_t b_stride, cdist_result *results, cdist_status *statuses)
{
    return run(q, kind, n, a, a_stride, b, b_stride, results, NULL, statuses);
}

cdist_status cdist_batch_distance(cdist_query *q, cdist_kind kind, size_t n, const void *a, ptrdiff_t a_stride,
                                  const void *b, ptrdiff_t b_stride, double *distances, cdist_status *statuses)
{
    return run(q, kind, n, a, a_stride, b, b_stride, NULL, distances, statuses);
}

cdist_status cdist_circle_circle_batch(cdist_query *q, size_t n, const cdist_circle *c0, const cdist_circle *c1,
                                       cdist_result *results, cdist_status *statuses)
{
    return cdist_batch(q, CDIST_KIND_CIRCLE_CIRCLE, n, c0, sizeof *c0, c1, sizeof *c1, results, statuses);
}
