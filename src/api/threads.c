/* SPDX-License-Identifier: MIT */
/* A handle's worker threads (api-priv.h): a handle with T > 1 threads owns a pool of T - 1
 * threads (src/base/pool.h), each with its own query handle (workspaces included), created by
 * cdist_query_set_threads and joined by cdist_query_free; the calling thread is the T-th worker
 * and uses the main handle. */
#include <stdlib.h>

#include "api/api-priv.h"

#define CD_MAX_THREADS 256

void cdist__workers_free(struct cdist__workers *w)
{
    if (!w) return;
    cdist__pool_free(w->pool);
    for (int i = 0; i < w->threads - 1; i++) cdist_query_free(w->w[i].handle);
    free(w);
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
    for (int i = 0; i < threads - 1; i++) {
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
    int error, failed;
    p->pool = cdist__pool_new(threads - 1, &error, &failed);
    if (!p->pool) {
        cdist__workers_free(p);
        if (!error) return cdist__fail(q, CDIST_ERR_NO_MEMORY, "out of memory for %d threads", threads);
        return cdist__fail(q, CDIST_ERR_THREAD, "could not start worker thread %d of %d (error %d)", failed + 1,
                           threads, error);
    }
    q->workers = p;
    return CDIST_OK;
}

CD_OPTION_SETTER(cdist_query_set_threads, int, set_threads_locked)

int cdist_query_get_threads(const cdist_query *q) { return (q && q->workers) ? q->workers->threads : 1; }
