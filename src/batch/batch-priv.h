/* SPDX-License-Identifier: MIT */
/* Batch subsystem (src/batch): the kind table, the per-range loop, worker threads and the
 * distance kernels. Nothing here is exported. */
#ifndef CDIST_BATCH_PRIV_H
#define CDIST_BATCH_PRIV_H

#include <stddef.h>
#include <stdint.h>

#include "internal.h"

/* One batch call: n entries of one kind; a full result or a distance per entry. */
typedef struct cd_job {
    cdist_kind kind;
    size_t n;
    const char *a, *b;
    ptrdiff_t a_stride, b_stride;
    cdist_result *results; /* full batch, else NULL */
    double *distances;     /* distance-only batch, else NULL */
    cdist_status *statuses; /* may be NULL */
    size_t chunk;           /* entries taken at a time by a thread (a multiple of 8) */
} cd_job;

static inline const void *cd_job_a(const cd_job *j, size_t i) { return j->a + (ptrdiff_t)i * j->a_stride; }
static inline const void *cd_job_b(const cd_job *j, size_t i) { return j->b + (ptrdiff_t)i * j->b_stride; }

/* The lowest failing entry one thread met (fail == SIZE_MAX: none) and its message. */
typedef struct cd_slot {
    size_t fail;
    cdist_status status;
    char message[CD_MESSAGE_LEN];
} cd_slot;

/* Answer entries [lo, hi) of the job with handle h (any thread's own handle); failures are
 * recorded in slot. Entries are independent: the answer of an entry does not depend on which
 * thread or range computes it. */
void cd_batch_range(cdist_query *h, const cd_job *job, size_t lo, size_t hi, cd_slot *slot);

/* Run the whole job with q's worker threads (or on the calling thread alone); *first gets the
 * lowest failing entry of all threads. */
void cd_workers_run(cdist_query *q, const cd_job *job, cd_slot *first);

/* Distance kernels of point-circle (disk = 0) and point-disk (disk = 1) for entries
 * [lo, lo + count), count <= 64: writes distances[i] of every entry whose inputs pass the fast
 * validation and returns a mask (bit k: entry lo + k) of the entries left for the scalar path
 * (which then produces their status and message). The arithmetic is that of
 * cd_point_circle_core/cd_point_disk_core and cd_check_circle operation by operation, so the
 * distances are bit-identical to the single query's. */
uint64_t cd_point_distance_kernel(const cd_job *job, int disk, double unit_tol, size_t lo, size_t count);

#endif
