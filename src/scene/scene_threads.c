/* SPDX-License-Identifier: MIT */
/* The threads of one scene call: the handle's worker handles and a pool started for the call. */
#include <stdlib.h>

#include "scene-priv.h"

void cdist__scene_pool_start(cdist__scene_pool *p, int threads)
{
    int error, failed;
    p->workers = threads > 1 ? cdist__pool_new(threads - 1, &error, &failed) : NULL;
    p->threads = p->workers ? threads : 1;
}

void cdist__scene_pool_run(cdist__scene_pool *p, void (*fn)(void *ctx, int t), void *ctx)
{
    if (p->workers) cdist__pool_start(p->workers, fn, ctx);
    fn(ctx, 0);
    if (p->workers) cdist__pool_wait(p->workers);
}

void cdist__scene_pool_stop(cdist__scene_pool *p) { cdist__pool_free(p->workers); }

/* Handles with the options of q, created once per scene and kept: *list grows to n. */
static cdist_status sync_handles(cdist_query *q, cdist_query ***list, int *have, int n)
{
    if (*have < n) {
        cdist_query **h = realloc(*list, (size_t)n * sizeof *h);
        if (!h) return cdist__fail(q, CDIST_ERR_NO_MEMORY, "scene: out of memory for %d thread handles", n);
        *list = h;
        while (*have < n) {
            if (!(h[*have] = cdist_query_new()))
                return cdist__fail(q, CDIST_ERR_NO_MEMORY, "scene: out of memory for %d thread handles", n);
            (*have)++;
        }
    }
    for (int t = 0; t < n; t++) {
        cdist_query *w = (*list)[t];
        cdist_status st;
        if ((st = cdist_query_set_method(w, cdist_query_get_method(q))) ||
            (st = cdist_query_set_unit_tolerance(w, cdist_query_get_unit_tolerance(q))) ||
            (st = cdist_query_set_curve_samples(w, cdist_query_get_curve_samples(q))) ||
            (st = cdist_query_set_max_iterations(w, cdist_query_get_max_iterations(q))))
            return cdist__fail(q, st, "scene: thread handle: %s", cdist_query_last_error(w));
    }
    return CDIST_OK;
}

int cdist__scene_call_threads(cdist_query *q, cdist_scene *s, cdist_query **handles, cdist_query ***screen)
{
    int threads = cdist_query_get_threads(q);
    if (threads > 1 && sync_handles(q, &s->worker, &s->worker_n, threads - 1)) threads = 1;
    handles[0] = q;
    for (int t = 1; t < threads; t++) handles[t] = s->worker[t - 1];
    *screen = sync_handles(q, &s->screen, &s->screen_n, threads) ? NULL : s->screen;
    return threads;
}
