/* SPDX-License-Identifier: MIT */
/* Batch worker threads. A handle with T > 1 threads owns T - 1 pthreads, each with its own query
 * handle (workspaces included), created by cdist_query_set_threads and joined by
 * cdist_query_free; the calling thread is the T-th worker and uses the main handle. A batch hands
 * out chunks of entries through an atomic counter; since every entry is answered on its own with
 * the same options, results do not depend on which thread took which chunk. Nothing is allocated
 * per batch. */
#include <pthread.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdlib.h>

#include "batch-priv.h"

#define CD_MAX_THREADS 256
/* Below this many entries per thread the wake-up costs more than it saves. */
#define CD_MIN_ENTRIES_PER_THREAD 64
/* A worker polls this many times (about 50 us) for the next batch before it sleeps: back-to-back
 * batches then skip the wake-up latency, without burning a core when batches are rare. */
#define CD_SPIN 1000

static inline void cpu_relax(void)
{
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
    __builtin_ia32_pause();
#endif
}

typedef struct cdist__worker {
    struct cdist__workers *pool;
    cdist_query *handle;
    pthread_t thread;
    cdist__slot slot;
} cdist__worker;

/* The hand-out state of one batch: chunks are taken in order from `next`, so the entries handed
 * out are always [0, min(next, n)) and each is answered in full (a stop only keeps threads from
 * taking more). `done` counts the entries answered, for the progress reports. */
typedef struct cdist__run {
    atomic_size_t next;
    atomic_size_t done;
    atomic_int stop;
} cdist__run;

struct cdist__workers {
    int threads; /* including the calling thread */
    int started; /* pthreads running */
    pthread_mutex_t mutex;
    pthread_cond_t start, done;
    atomic_ulong generation; /* incremented (under the mutex) per batch and to quit */
    int pending;              /* workers still busy with the current batch */
    int quit;
    const cdist__job *job;
    cdist__run *run;
    cdist__worker w[]; /* threads - 1 */
};

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

static void *worker_main(void *arg)
{
    cdist__worker *w = arg;
    struct cdist__workers *p = w->pool;
    unsigned long seen = 0;
    for (;;) {
        for (int i = 0; i < CD_SPIN && atomic_load_explicit(&p->generation, memory_order_relaxed) == seen; i++)
            cpu_relax();
        pthread_mutex_lock(&p->mutex);
        while (atomic_load_explicit(&p->generation, memory_order_relaxed) == seen && !p->quit)
            pthread_cond_wait(&p->start, &p->mutex);
        if (p->quit) {
            pthread_mutex_unlock(&p->mutex);
            return NULL;
        }
        seen = atomic_load_explicit(&p->generation, memory_order_relaxed);
        const cdist__job *job = p->job;
        cdist__run *run = p->run;
        pthread_mutex_unlock(&p->mutex);
        w->slot.fail = SIZE_MAX;
        drain(run, job, w->handle, &w->slot, NULL);
        pthread_mutex_lock(&p->mutex);
        if (--p->pending == 0) pthread_cond_signal(&p->done);
        pthread_mutex_unlock(&p->mutex);
    }
}

void cdist__workers_free(struct cdist__workers *p)
{
    if (!p) return;
    if (p->started > 0) {
        pthread_mutex_lock(&p->mutex);
        p->quit = 1;
        atomic_fetch_add(&p->generation, 1);
        pthread_cond_broadcast(&p->start);
        pthread_mutex_unlock(&p->mutex);
        for (int i = 0; i < p->started; i++) pthread_join(p->w[i].thread, NULL);
    }
    for (int i = 0; i < p->threads - 1; i++) cdist_query_free(p->w[i].handle);
    pthread_cond_destroy(&p->done);
    pthread_cond_destroy(&p->start);
    pthread_mutex_destroy(&p->mutex);
    free(p);
}

/* Every option through the public setters: they size the worker's workspaces (and never
 * allocate when the size is unchanged, as at the start of a batch). A new handle option must be
 * copied here too, or results would depend on the thread count (test_batch would show it). */
static cdist_status sync_one(cdist_query *q, cdist_query *w)
{
    cdist_status st;
    if ((st = cdist_query_set_method(w, q->method)) || (st = cdist_query_set_unit_tolerance(w, q->unit_tol)) ||
        (st = cdist_query_set_curve_samples(w, q->curve_samples)) ||
        (st = cdist_query_set_max_iterations(w, q->max_iterations)))
        return cdist__fail(q, st, "worker handle: %s", cdist_query_last_error(w));
    return CDIST_OK;
}

cdist_status cdist__workers_sync(cdist_query *q)
{
    struct cdist__workers *p = q->workers;
    if (!p) return CDIST_OK;
    for (int i = 0; i < p->threads - 1; i++) {
        cdist_status st = sync_one(q, p->w[i].handle);
        if (st) return st;
    }
    return CDIST_OK;
}

static cdist_status set_threads_locked(cdist_query *q, int threads)
{
    if (threads < 1 || threads > CD_MAX_THREADS)
        return cdist__fail(q, CDIST_ERR_BAD_OPTION, "threads must be in [1, %d] (got %d)", CD_MAX_THREADS, threads);
    cdist__begin(q, NULL);
    if (threads == cdist_query_get_threads(q)) return CDIST_OK;
    cdist__workers_free(q->workers);
    q->workers = NULL;
    if (threads == 1) return CDIST_OK;
    struct cdist__workers *p = calloc(1, sizeof *p + (size_t)(threads - 1) * sizeof(cdist__worker));
    if (!p) return cdist__fail(q, CDIST_ERR_NO_MEMORY, "out of memory for %d threads", threads);
    p->threads = threads;
    pthread_mutex_init(&p->mutex, NULL);
    pthread_cond_init(&p->start, NULL);
    pthread_cond_init(&p->done, NULL);
    atomic_init(&p->generation, 0);
    for (int i = 0; i < threads - 1; i++) {
        p->w[i].pool = p;
        p->w[i].handle = cdist_query_new();
        if (!p->w[i].handle) {
            cdist__workers_free(p);
            return cdist__fail(q, CDIST_ERR_NO_MEMORY, "out of memory for the handles of %d threads", threads);
        }
        cdist_status st = sync_one(q, p->w[i].handle); /* its own status and message (e.g. a bad option) */
        if (st) {
            cdist__workers_free(p);
            return st;
        }
    }
    for (int i = 0; i < threads - 1; i++) {
        int e = pthread_create(&p->w[i].thread, NULL, worker_main, &p->w[i]);
        if (e) {
            cdist__workers_free(p);
            return cdist__fail(q, CDIST_ERR_THREAD, "could not start worker thread %d of %d (error %d)", i + 1,
                           threads, e);
        }
        p->started++;
    }
    q->workers = p;
    return CDIST_OK;
}

/* Under the handle's flag, and refused while a batch runs: the pool it would free is in use. */
cdist_status cdist_query_set_threads(cdist_query *q, int threads)
{
    cdist_status st = cdist__enter_setter(q);
    if (st) return st;
    if (atomic_load_explicit(&q->batch_busy, memory_order_acquire)) {
        cdist__leave_setter(q);
        return CDIST_ERR_HANDLE_BUSY;
    }
    st = set_threads_locked(q, threads);
    cdist__leave_setter(q);
    return st;
}

int cdist_query_get_threads(const cdist_query *q) { return (q && q->workers) ? q->workers->threads : 1; }

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
    if (threads == 1) {
        drain(&run, &job, q, first, q);
    } else {
        pthread_mutex_lock(&p->mutex);
        p->job = &job;
        p->run = &run;
        p->pending = p->threads - 1;
        atomic_fetch_add(&p->generation, 1);
        pthread_cond_broadcast(&p->start);
        pthread_mutex_unlock(&p->mutex);
        drain(&run, &job, q, first, q);
        pthread_mutex_lock(&p->mutex);
        while (p->pending > 0) pthread_cond_wait(&p->done, &p->mutex);
        pthread_mutex_unlock(&p->mutex);
        for (int i = 0; i < p->threads - 1; i++) take_lower(first, &p->w[i].slot);
    }
    size_t next = atomic_load_explicit(&run.next, memory_order_relaxed);
    *answered = next < job.n ? next : job.n;
    if (*answered == job.n && q->progress_fn) cdist__progress_report(q, job.n, job.n);
    return CDIST_OK;
}
