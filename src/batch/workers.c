/* SPDX-License-Identifier: MIT */
/* A batch on the handle's worker threads (src/api/threads.c, src/base/pool.h): chunks of
 * entries are handed out through an atomic counter; since every entry is answered on its own
 * with the same options, results do not depend on which thread took which chunk. Nothing is
 * allocated per batch. */
#include <stdatomic.h>
#include <stdint.h>

#include "batch-priv.h"

/* Below this many entries per thread the wake-up costs more than it saves. */
#define CD_MIN_ENTRIES_PER_THREAD 64

/* The hand-out state of one batch: chunks are taken in order from `next`, so the entries handed
 * out are always [0, min(next, n)) and each is answered in full (a stop only keeps threads from
 * taking more). `done` counts the entries answered, for the progress reports. */
typedef struct cdist__run {
    atomic_size_t next;
    atomic_size_t done;
    atomic_int stop;
    const cdist__job *job;
    cdist_query *q;
} cdist__run;

/* Take chunks until none is left or the batch is stopped. The calling thread (caller = q, the
 * handle with the progress option; NULL for a worker) reports progress between its chunks. */
static void drain(cdist__run *run, const cdist__job *job, cdist_query *h, cdist__slot *slot, const cdist_query *caller)
{
    size_t report_at = caller ? caller->progress_every : 0;
    for (;;) {
        if (atomic_load_explicit(&run->stop, memory_order_relaxed)) return;
        size_t lo = atomic_fetch_add_explicit(&run->next, job->chunk, memory_order_relaxed);
        if (lo >= job->n) return;
        size_t hi = job->n - lo < job->chunk ? job->n : lo + job->chunk;
        cdist__batch_range(h, job, lo, hi, slot);
        size_t done = atomic_fetch_add_explicit(&run->done, hi - lo, memory_order_relaxed) + (hi - lo);
        if (report_at && done >= report_at && done < job->n) {
            if (cdist__progress_report(caller, done, job->n)) atomic_store_explicit(&run->stop, 1, memory_order_relaxed);
            report_at = done + caller->progress_every;
        }
    }
}

/* A pool worker's part of the batch, with its own handle and failure record. */
static void worker_task(void *arg, int k)
{
    cdist__run *run = arg;
    cdist__worker *w = &run->q->workers->w[k - 1];
    w->slot.fail = SIZE_MAX;
    drain(run, run->job, w->handle, &w->slot, NULL);
}

static void take_lower(cdist__slot *first, const cdist__slot *s)
{
    if (s->fail < first->fail) *first = *s;
}

/* Entries per chunk: about 16 per thread (load balance), a multiple of the kernels' 64 entries,
 * and with progress reports at most the report interval (the calling thread reports between its
 * chunks, and a stop waits for the chunks being answered). */
static size_t chunk_size(const cdist_query *q, size_t n, int threads)
{
    size_t chunk = threads == 1 ? n : n / ((size_t)threads * 16);
    chunk = (chunk + 63) / 64 * 64;
    if (chunk == 0) chunk = 64;
    if (q->progress_fn && chunk > q->progress_every) chunk = q->progress_every;
    return chunk;
}

cdist_status cdist__workers_run(cdist_query *q, const cdist__job *job_in, cdist__slot *first, size_t *answered)
{
    cdist__job job = *job_in;
    first->fail = SIZE_MAX;
    /* The pool and q's options are read under q's flag: a setter or cdist_query_set_threads that
     * passed its batch check before this batch began has finished by then, later ones refuse. */
    if (cdist__enter_setter(q)) return CDIST_ERR_HANDLE_BUSY;
    struct cdist__workers *p = q->workers;
    int threads = p ? p->threads : 1;
    if (threads > 1 && job.n < (size_t)threads * CD_MIN_ENTRIES_PER_THREAD) threads = 1;
    if (threads > 1 && cdist__workers_sync(q)) threads = 1;
    cdist__leave_setter(q);
    job.chunk = chunk_size(q, job.n, threads);
    cdist__run run;
    atomic_init(&run.next, 0);
    atomic_init(&run.done, 0);
    atomic_init(&run.stop, 0);
    run.job = &job;
    run.q = q;
    if (threads == 1) {
        drain(&run, &job, q, first, q);
    } else {
        cdist__pool_start(p->pool, worker_task, &run);
        drain(&run, &job, q, first, q);
        cdist__pool_wait(p->pool);
        for (int i = 0; i < p->threads - 1; i++) take_lower(first, &p->w[i].slot);
    }
    size_t next = atomic_load_explicit(&run.next, memory_order_relaxed);
    *answered = next < job.n ? next : job.n;
    if (*answered == job.n && q->progress_fn) cdist__progress_report(q, job.n, job.n);
    return CDIST_OK;
}
