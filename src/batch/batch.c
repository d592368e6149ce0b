/* SPDX-License-Identifier: MIT */
/* The batch entry points: one generic entry per result type over the table of query kinds made
 * from the registry (src/api/kinds.def). */
#include <math.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "batch-priv.h"
#include "swept/swept-priv.h"

/* The single query of a kind (r: cdist_result, or cdist_contact for a contact kind) and its
 * _grad query. */
typedef cdist_status (*kind_fn)(cdist_query *q, const void *a, const void *b, void *r);
typedef cdist_status (*grad_fn)(cdist_query *q, const void *a, const void *b, void *r, cdist_grad *g);

#define WRAP(fn, TA, TB, TR)                                                                                  \
    static cdist_status k_##fn(cdist_query *q, const void *a, const void *b, void *r)                        \
    {                                                                                                         \
        return cdist_##fn(q, (const TA *)a, (const TB *)b, (TR *)r);                                         \
    }
#define WRAP_GRAD(fn, TA, TB, TR)                                                                             \
    WRAP(fn, TA, TB, TR)                                                                                      \
    static cdist_status g_##fn(cdist_query *q, const void *a, const void *b, void *r, cdist_grad *g)         \
    {                                                                                                         \
        return cdist_##fn##_grad(q, (const TA *)a, (const TB *)b, (TR *)r, g);                               \
    }
#define WRAP_NO_GRAD WRAP
#define CD_KIND(KIND, number, name, letters, TA, TB, grad, ...) WRAP_##grad(name, TA, TB, cdist_result)
#define CD_CONTACT_KIND(KIND, number, name, letters, TA, TB, ...) WRAP_GRAD(name, TA, TB, cdist_contact)
#define CD_CURVE_KIND(KIND, number, name, TB, ...)                                                            \
    static cdist_status k_##name(cdist_query *q, const void *a, const void *b, void *r)                      \
    {                                                                                                         \
        const cdist_curve *c = a;                                                                             \
        return cdist_##name(q, c->fn, c->user, c->t0, c->t1, (const TB *)b, (cdist_result *)r);              \
    }
#include "api/kinds.def"
#undef WRAP_NO_GRAD
#undef WRAP_GRAD
#undef WRAP

/* The distance kernel of a kind, if any (the registry's kernel column). */
enum {
    NO_KERNEL = 0,
    POINT_CIRCLE_KERNEL,
    POINT_DISK_KERNEL,
    LINE_CIRCLE_KERNEL, /* the line kernels in the order of their shapes: line, ray, segment */
    RAY_CIRCLE_KERNEL,
    SEGMENT_CIRCLE_KERNEL,
    CIRCLE_CIRCLE_KERNEL,
    CIRCLE_DISK_KERNEL,
    DISK_DISK_KERNEL,
    /* the core kinds of contact kinds without a kernel: they take the scalar path */
    SEGMENT_DISK_KERNEL = NO_KERNEL,
    NONE_KERNEL = NO_KERNEL /* closed forms: point-point, point-segment, segment-segment */
};

/* Byte offset of a swept object's radius, by type; a plain object (radius 0) has none. Each swept
 * struct starts with its core object, so a kernel of the core kind reads the swept array as it
 * is. */
enum { PLAIN = -1 };
#define RADIUS_cdist_torus ((int)offsetof(cdist_torus, tube_radius))
#define RADIUS_cdist_capsule ((int)offsetof(cdist_capsule, radius))
#define RADIUS_cdist_sphere ((int)offsetof(cdist_sphere, radius))
#define RADIUS_cdist_rounded_disk ((int)offsetof(cdist_rounded_disk, radius))
#define RADIUS_cdist_circle PLAIN
#define RADIUS_cdist_line PLAIN
#define RADIUS_cdist_ray PLAIN
#define RADIUS_cdist_segment PLAIN
_Static_assert(offsetof(cdist_torus, circle) == 0 && offsetof(cdist_capsule, segment) == 0 &&
                   offsetof(cdist_sphere, center) == 0 && offsetof(cdist_rounded_disk, disk) == 0,
               "a swept object starts with its core");

/* A contact kind's kernel is its core kind's, `swap` when the core kernel takes the objects in
 * the other order (the torus is the circle, the second object). */
typedef struct kind_row {
    const char *name;
    size_t size_a, size_b;
    kind_fn full;
    grad_fn grad;
    int kernel;
    int contact;
    int swap;
    int radius_a, radius_b;
} kind_row;

#define GRAD_FN_GRAD(name) g_##name
#define GRAD_FN_NO_GRAD(name) NULL
static const kind_row kinds[] = {
#define CD_KIND(KIND, number, name, letters, TA, TB, grad, methods, auto_method, kernel, help)          \
    [CDIST_KIND_##KIND] = {#name, sizeof(TA), sizeof(TB), k_##name, GRAD_FN_##grad(name), kernel, 0, 0, PLAIN, PLAIN},
#define CD_CURVE_KIND(KIND, number, name, TB, ...)                                                                   \
    [CDIST_KIND_##KIND] = {#name, sizeof(cdist_curve), sizeof(TB), k_##name, NULL, NO_KERNEL, 0, 0, PLAIN, PLAIN},
#define CD_CONTACT_KIND(KIND, number, name, letters, TA, TB, A, B, core, swap, help)                               \
    [CDIST_KIND_##KIND] = {#name, sizeof(TA), sizeof(TB), k_##name, g_##name, core##_KERNEL, 1, swap, RADIUS_##TA, \
                           RADIUS_##TB},
#include "api/kinds.def"
};
#undef GRAD_FN_GRAD
#undef GRAD_FN_NO_GRAD
#define KIND_COUNT ((int)(sizeof kinds / sizeof kinds[0]))

static int kind_ok(cdist_kind k) { return (unsigned)k < (unsigned)KIND_COUNT && kinds[k].full; }

int cdist_kind_count(void) { return KIND_COUNT; }
const char *cdist_kind_name(cdist_kind k)
{
    return kind_ok(k) ? kinds[k].name : NULL;
}
size_t cdist_kind_size_a(cdist_kind k) { return kind_ok(k) ? kinds[k].size_a : 0; }
size_t cdist_kind_size_b(cdist_kind k) { return kind_ok(k) ? kinds[k].size_b : 0; }
size_t cdist_kind_result_size(cdist_kind k)
{
    return kind_ok(k) ? (kinds[k].contact ? sizeof(cdist_contact) : sizeof(cdist_result)) : 0;
}
int cdist_kind_has_grad(cdist_kind k) { return kind_ok(k) && kinds[k].grad != NULL; }

/* ---- one range of entries ---- */

static void record(cdist__slot *slot, cdist_query *h, size_t i, cdist_status st)
{
    if (st == CDIST_OK || slot->fail != SIZE_MAX) return; /* a thread meets its entries in order */
    slot->fail = i;
    slot->status = st;
    memcpy(slot->message, h->message, sizeof slot->message);
}

/* Room for the result of any kind, for the entries whose result the caller does not keep. */
typedef union any_result {
    cdist_result result;
    cdist_contact contact;
} any_result;

static double any_distance(const kind_row *row, const any_result *r)
{
    return row->contact ? r->contact.distance : r->result.distance;
}

/* The scalar path of one entry: the single query itself. */
static void entry(cdist_query *h, const cdist__job *job, size_t i, cdist__slot *slot)
{
    const kind_row *row = &kinds[job->kind];
    const void *a = cdist__job_a(job, i), *b = cdist__job_b(job, i);
    void *kept = job->results ? (char *)job->results + i * job->result_size : NULL;
    any_result local;
    cdist_status st;
    switch (job->out) {
    case CD_OUT_GRAD: st = row->grad(h, a, b, kept ? kept : &local, &job->grads[i]); break;
    case CD_OUT_DISTANCE:
        st = row->full(h, a, b, &local);
        job->distances[i] = any_distance(row, &local);
        break;
    default: st = row->full(h, a, b, kept); break;
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
 * method; circle-disk and disk-disk the ROBUST method of their own families). */
static int job_kernel(const cdist_query *h, const cdist__job *job)
{
    int kernel = job->out == CD_OUT_DISTANCE ? kinds[job->kind].kernel : NO_KERNEL;
    if (kernel >= LINE_CIRCLE_KERNEL && kernel <= SEGMENT_CIRCLE_KERNEL &&
        cdist__family_method(h, CD_FAM_LINE_CIRCLE) == CDIST_METHOD_POLYNOMIAL)
        return NO_KERNEL;
    int circles = kernel == CIRCLE_CIRCLE_KERNEL || kernel == CIRCLE_DISK_KERNEL || kernel == DISK_DISK_KERNEL;
    cdist__fam fam = kernel == CIRCLE_CIRCLE_KERNEL ? CD_FAM_CIRCLE_CIRCLE
                     : kernel == CIRCLE_DISK_KERNEL ? CD_FAM_CIRCLE_DISK : CD_FAM_DISK_DISK;
    if (circles && cdist__family_method(h, fam) != CDIST_METHOD_ROBUST) return NO_KERNEL;
    return kernel;
}

/* Entries [lo, lo + count) of the job through its kernel; the mask of those left. */
static uint64_t run_kernel(int kernel, const cdist_query *h, const cdist__job *job, size_t lo, size_t count)
{
    if (kernel == CIRCLE_CIRCLE_KERNEL) return cdist__cc_distance_kernel(job, h->unit_tol, lo, count);
    if (kernel == CIRCLE_DISK_KERNEL || kernel == DISK_DISK_KERNEL)
        return cdist__cd_distance_kernel(job, kernel == DISK_DISK_KERNEL, h->unit_tol, lo, count);
    if (kernel >= LINE_CIRCLE_KERNEL)
        return cdist__line_distance_kernel(job, kernel - LINE_CIRCLE_KERNEL, h->unit_tol, lo, count);
    return cdist__point_distance_kernel(job, kernel == POINT_DISK_KERNEL, h->unit_tol, lo, count);
}

static double radius_at(const char *obj, int offset)
{
    double r = 0.0;
    if (offset != PLAIN) memcpy(&r, obj + offset, sizeof r);
    return r;
}

/* A contact kind through its core's kernel: the core distances of the block, then the radii
 * subtracted as the single query does (core_distance - (r0 + r1)). An entry whose radius the
 * single query would reject is left to the scalar path, which reports it. */
static uint64_t run_contact_kernel(int kernel, const cdist_query *h, const cdist__job *job, size_t lo, size_t count)
{
    const kind_row *row = &kinds[job->kind];
    cdist__job core = *job;
    if (row->swap) {
        core.a = job->b;
        core.b = job->a;
        core.a_stride = job->b_stride;
        core.b_stride = job->a_stride;
    }
    uint64_t left = run_kernel(kernel, h, &core, lo, count);
    for (size_t k = 0; k < count; k++) {
        if (left >> k & 1) continue;
        size_t i = lo + k;
        double ra = radius_at(cdist__job_a(job, i), row->radius_a), rb = radius_at(cdist__job_b(job, i), row->radius_b);
        if (ra >= 0.0 && ra <= CD_MAX_ABS && rb >= 0.0 && rb <= CD_MAX_ABS)
            job->distances[i] -= ra + rb;
        else
            left |= (uint64_t)1 << k;
    }
    return left;
}

/* Circle-circle and torus-torus entries with full results, contacts or gradients: the single
 * queries, their cores' certified searches in lanes (cdist__circle_circle_many), each core
 * answer then made the entry's as its query makes it (cdist__swept_query's contact,
 * cdist__grad_fill's gradient). */
enum { MANY_BLOCK = 16 }; /* about 10 KB of block on the stack */
typedef struct many_block {
    cdist_query *h;
    const cdist__job *job;
    size_t lo;
    cdist__slot *slot;
    cdist__core_obj a[MANY_BLOCK], b[MANY_BLOCK];
    cdist_result core[MANY_BLOCK], *r[MANY_BLOCK]; /* where each core answer goes */
    cdist_contact contact[MANY_BLOCK], *c[MANY_BLOCK];
    uint32_t later; /* the entries whose contact many_later makes */
} many_block;

static int many_job(const cdist__job *job)
{
    return job->out != CD_OUT_DISTANCE &&
           (job->kind == CDIST_KIND_CIRCLE_CIRCLE || job->kind == CDIST_KIND_TORUS_TORUS);
}

/* Entry i's place in the output array, fetched for writing ahead of its answer: a contact spans
 * six cache lines, which the hardware's prefetch does not bring in time. */
enum { OUTPUT_AHEAD = 2 };
static void output_prefetch(const cdist__job *job, size_t i)
{
    if (!job->results || i >= job->n) return;
    const char *p = (const char *)job->results + i * job->result_size;
    for (size_t o = 0; o < job->result_size; o += 64) __builtin_prefetch(p + o, 1, 3);
}

/* Entry k's gradient, status and failure record, once its result (and contact) is made. */
static void many_finish(const many_block *x, size_t k, cdist_status st)
{
    const cdist__job *job = x->job;
    size_t i = x->lo + k;
    if (job->out == CD_OUT_GRAD && st == CDIST_OK) cdist__grad_fill(&x->a[k], &x->b[k], x->r[k], &job->grads[i]);
    if (job->statuses) job->statuses[i] = st;
    record(x->slot, x->h, i, st);
}

static void many_done(void *ctx, size_t k, cdist_status st)
{
    many_block *x = ctx;
    output_prefetch(x->job, x->lo + k + OUTPUT_AHEAD);
    if (x->job->kind == CDIST_KIND_TORUS_TORUS) {
        if (st == CDIST_OK && cdist__contact_ready(&x->a[k], &x->b[k])) {
            x->later |= (uint32_t)1 << k;
            return;
        }
        st = cdist__contact_of_core_query(x->h, &x->a[k], &x->b[k], st, x->r[k], x->c[k]);
    }
    many_finish(x, k, st);
}

/* The contacts of the block's entries whose core query succeeded, made after its searches: one
 * after another, their dependency chains (a division, a square root, a division) overlap. */
static void many_later(const many_block *x, size_t cnt)
{
    for (size_t k = 0; k < cnt; k++)
        if (x->later >> k & 1) {
            cdist__contact_of_core(&x->a[k], &x->b[k], x->r[k], x->c[k]);
            many_finish(x, k, CDIST_OK);
        }
}

static void many_range(cdist_query *h, const cdist__job *job, size_t lo, size_t hi, cdist__slot *slot)
{
    many_block x;
    int torus = job->kind == CDIST_KIND_TORUS_TORUS;
    const cdist_circle *pa[MANY_BLOCK], *pb[MANY_BLOCK];
    for (size_t i = lo; i < hi; i += MANY_BLOCK) {
        size_t cnt = hi - i < MANY_BLOCK ? hi - i : MANY_BLOCK;
        x.h = h, x.job = job, x.lo = i, x.slot = slot, x.later = 0;
        for (size_t k = 0; k < cnt; k++) {
            const void *ea = cdist__job_a(job, i + k), *eb = cdist__job_b(job, i + k);
            char *kept = job->results ? (char *)job->results + (i + k) * job->result_size : NULL;
            if (torus) {
                x.a[k] = CD_SWEPT_TORUS((const cdist_torus *)ea);
                x.b[k] = CD_SWEPT_TORUS((const cdist_torus *)eb);
                x.r[k] = &x.core[k];
                x.c[k] = kept ? (cdist_contact *)kept : &x.contact[k];
            } else {
                x.a[k] = cdist__plain_core(CD_CORE_CIRCLE, ea);
                x.b[k] = cdist__plain_core(CD_CORE_CIRCLE, eb);
                x.r[k] = kept ? (cdist_result *)kept : &x.core[k];
            }
            pa[k] = x.a[k].obj;
            pb[k] = x.b[k].obj;
            if (job->out == CD_OUT_GRAD) cdist__grad_set_error(&job->grads[i + k]);
        }
        cdist__circle_circle_many(h, cnt, pa, pb, x.r, many_done, &x);
        many_later(&x, cnt);
    }
}

void cdist__batch_range(cdist_query *h, const cdist__job *job, size_t lo, size_t hi, cdist__slot *slot)
{
    if (many_job(job)) { /* (another method: cdist__cc_staged_start leaves every entry to its query) */
        many_range(h, job, lo, hi, slot);
        return;
    }
    int kernel = job_kernel(h, job);
    if (kernel != NO_KERNEL) {
        int contact = kinds[job->kind].contact;
        for (size_t i = lo; i < hi; i += 64) {
            size_t cnt = hi - i < 64 ? hi - i : 64;
            uint64_t left = contact ? run_contact_kernel(kernel, h, job, i, cnt) : run_kernel(kernel, h, job, i, cnt);
            if (job->statuses)
                for (size_t k = 0; k < cnt; k++) job->statuses[i + k] = CDIST_OK;
            for (; left; left &= left - 1) entry(h, job, i + lowest_bit(left), slot);
        }
        return;
    }
    for (size_t i = lo; i < hi; i++) entry(h, job, i, slot);
}

/* ---- the entry points ---- */

/* Entry i's outputs in the error state with status st. */
static void fail_entry(const cdist__job *job, size_t i, cdist_status st)
{
    if (job->results && job->result_size) {
        char *r = (char *)job->results + i * job->result_size;
        if (job->result_size == sizeof(cdist_contact))
            cdist__contact_set_error((cdist_contact *)r);
        else
            cdist__result_set_error((cdist_result *)r);
    }
    if (job->distances) job->distances[i] = NAN;
    if (job->grads) cdist__grad_set_error(&job->grads[i]);
    if (job->statuses) job->statuses[i] = st;
}

/* Entries [lo, n) in the error state with status st: each output array in one pass (a
 * cancelled batch may leave millions of entries, and Ctrl-C waits for this). */
static void fail_range(const cdist__job *job, size_t lo, cdist_status st)
{
    size_t n = job->n;
    if (lo >= n) return;
    if (job->distances)
        for (size_t i = lo; i < n; i++) job->distances[i] = NAN;
    if (job->statuses)
        for (size_t i = lo; i < n; i++) job->statuses[i] = st;
    if (job->grads) {
        cdist__grad_set_error(&job->grads[lo]);
        for (size_t i = lo + 1; i < n; i++) job->grads[i] = job->grads[lo];
    }
    if (job->results && job->result_size) {
        char *first = (char *)job->results + lo * job->result_size;
        fail_entry(job, lo, st);
        for (size_t i = lo + 1; i < n; i++) memcpy((char *)job->results + i * job->result_size, first, job->result_size);
    }
}

/* NULL handle or arrays, bad kind: every writable output says so. */
static cdist_status fail_all(cdist_query *q, cdist_status st, const cdist__job *job, const char *why)
{
    fail_range(job, 0, st);
    if (!q) return st;
    cdist__begin(q, NULL);
    return cdist__fail(q, st, "batch: %s", why);
}

static cdist_status check_overlap(cdist_query *q, const cdist__job *job)
{
    size_t n = job->n;
    cdist__span s[6] = {
        cdist__span_of(job->a, n, job->a_stride, kinds[job->kind].size_a, "first object array"),
        cdist__span_of(job->b, n, job->b_stride, kinds[job->kind].size_b, "second object array"),
    };
    int k = 2;
    if (job->results) s[k++] = cdist__span_of(job->results, n, (ptrdiff_t)job->result_size, job->result_size, "results");
    if (job->distances) s[k++] = cdist__span_of(job->distances, n, sizeof(double), sizeof(double), "distances");
    if (job->grads) s[k++] = cdist__span_of(job->grads, n, sizeof(cdist_grad), sizeof(cdist_grad), "gradients");
    if (job->statuses) s[k++] = cdist__span_of(job->statuses, n, sizeof(cdist_status), sizeof(cdist_status), "statuses");
    const char *x, *y;
    if (!cdist__spans_overlap(s, k, 2, &x, &y)) return CDIST_OK;
    cdist__begin(q, NULL);
    return cdist__fail(q, CDIST_ERR_OVERLAP, CDIST__OVERLAP_MESSAGE, x, y);
}

/* The kinds an output answers: full results the plain kinds, contacts the contact kinds,
 * gradients the kinds with a _grad query, distances every kind. */
static const char *kind_refused(cdist_kind kind, cdist__out out)
{
    switch (out) {
    case CD_OUT_RESULT: return kinds[kind].contact ? "has contact results: use cdist_batch_contact()" : NULL;
    case CD_OUT_CONTACT: return kinds[kind].contact ? NULL : "is not a contact kind: use cdist_batch()";
    case CD_OUT_GRAD: return kinds[kind].grad ? NULL : "has no gradient query";
    default: return NULL;
    }
}

static cdist_status run_locked(cdist_query *q, cdist__job *job)
{
    if (!kind_ok(job->kind) || kind_refused(job->kind, job->out)) {
        fail_all(q, CDIST_ERR_BAD_KIND, job, "");
        if (!kind_ok(job->kind))
            return cdist__fail(q, CDIST_ERR_BAD_KIND, "batch: %d is not a cdist_kind (0..%d)", (int)job->kind,
                               KIND_COUNT - 1);
        return cdist__fail(q, CDIST_ERR_BAD_KIND, "batch: kind %s %s", cdist_kind_name(job->kind),
                           kind_refused(job->kind, job->out));
    }
    const char *missing = !job->a ? "first object array is NULL"
                          : !job->b ? "second object array is NULL"
                          : (job->out == CD_OUT_GRAD ? !job->grads
                             : job->out == CD_OUT_DISTANCE ? !job->distances
                                                           : !job->results)
                              ? "output array is NULL"
                              : NULL;
    if (missing) return fail_all(q, CDIST_ERR_NULL_ARGUMENT, job, missing);
    cdist_status st = check_overlap(q, job);
    if (st) return st;
    cdist__slot first;
    size_t answered;
    if (cdist__workers_run(q, job, &first, &answered)) /* another call held the handle while the options were read */
        return fail_all(NULL, CDIST_ERR_HANDLE_BUSY, job, "");
    fail_range(job, answered, CDIST_ERR_CANCELLED);
    cdist__begin(q, NULL);
    if (answered < job->n) {
        if (first.fail != SIZE_MAX)
            return cdist__fail(q, CDIST_ERR_CANCELLED,
                               "batch cancelled by the progress callback: %zu of %zu entries answered (entry %zu: %.160s)",
                               answered, job->n, first.fail, first.message);
        return cdist__fail(q, CDIST_ERR_CANCELLED, "batch cancelled by the progress callback: %zu of %zu entries answered",
                           answered, job->n);
    }
    if (first.fail == SIZE_MAX) return CDIST_OK;
    return cdist__fail(q, first.status, "batch entry %zu: %.200s", first.fail, first.message);
}

static cdist_status run(cdist_query *q, cdist__job *job)
{
    if (!q) return job->n ? fail_all(q, CDIST_ERR_NULL_ARGUMENT, job, "") : CDIST_ERR_NULL_ARGUMENT;
    /* One batch at a time per handle (it owns the worker pool and the worker handles); a second
     * one fails every entry without touching the handle. */
    if (atomic_exchange_explicit(&q->batch_busy, 1, memory_order_acquire))
        return fail_all(NULL, CDIST_ERR_HANDLE_BUSY, job, "");
    cdist_status st = CDIST_OK;
    if (job->n == 0)
        cdist__begin(q, NULL);
    else
        st = run_locked(q, job);
    atomic_store_explicit(&q->batch_busy, 0, memory_order_release);
    return st;
}

/* One batch call: a job of the given output (its results' type fixed by the entry point, or
 * for gradients the kind's: none for a number that is not a kind, result_size 0, those results
 * are never written). */
static cdist_status batch_call(cdist_query *q, cdist_kind kind, size_t n, const void *a, ptrdiff_t a_stride,
                               const void *b, ptrdiff_t b_stride, cdist__out out, void *results, double *distances,
                               cdist_grad *grads, cdist_status *statuses)
{
    size_t result_size = out == CD_OUT_CONTACT  ? sizeof(cdist_contact)
                         : out == CD_OUT_RESULT ? sizeof(cdist_result)
                                                : cdist_kind_result_size(kind);
    cdist__job job = {kind, n, a, b, a_stride, b_stride, results, distances, statuses, 0, out, result_size, grads, NULL};
    return run(q, &job);
}

cdist_status cdist__batch_screen(cdist_query *q, size_t n, const cdist_circle *a, const cdist_circle *b,
                                 const double *cutoffs, double *distances)
{
    cdist__job job = {CDIST_KIND_CIRCLE_CIRCLE, n, (const char *)a, (const char *)b, sizeof *a, sizeof *b, NULL,
                      distances, NULL, 0, CD_OUT_DISTANCE, 0, NULL, cutoffs};
    return run(q, &job);
}

cdist_status cdist_batch(cdist_query *q, cdist_kind kind, size_t n, const void *a, ptrdiff_t a_stride, const void *b,
                         ptrdiff_t b_stride, cdist_result *results, cdist_status *statuses)
{
    return batch_call(q, kind, n, a, a_stride, b, b_stride, CD_OUT_RESULT, results, NULL, NULL, statuses);
}

cdist_status cdist_batch_distance(cdist_query *q, cdist_kind kind, size_t n, const void *a, ptrdiff_t a_stride,
                                  const void *b, ptrdiff_t b_stride, double *distances, cdist_status *statuses)
{
    return batch_call(q, kind, n, a, a_stride, b, b_stride, CD_OUT_DISTANCE, NULL, distances, NULL, statuses);
}

cdist_status cdist_batch_contact(cdist_query *q, cdist_kind kind, size_t n, const void *a, ptrdiff_t a_stride,
                                 const void *b, ptrdiff_t b_stride, cdist_contact *contacts, cdist_status *statuses)
{
    return batch_call(q, kind, n, a, a_stride, b, b_stride, CD_OUT_CONTACT, contacts, NULL, NULL, statuses);
}

cdist_status cdist_batch_grad(cdist_query *q, cdist_kind kind, size_t n, const void *a, ptrdiff_t a_stride,
                              const void *b, ptrdiff_t b_stride, void *results, cdist_grad *grads,
                              cdist_status *statuses)
{
    return batch_call(q, kind, n, a, a_stride, b, b_stride, CD_OUT_GRAD, results, NULL, grads, statuses);
}

cdist_status cdist_circle_circle_batch(cdist_query *q, size_t n, const cdist_circle *c0, const cdist_circle *c1,
                                       cdist_result *results, cdist_status *statuses)
{
    return cdist_batch(q, CDIST_KIND_CIRCLE_CIRCLE, n, c0, sizeof *c0, c1, sizeof *c1, results, statuses);
}
