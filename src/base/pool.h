/* SPDX-License-Identifier: MIT */
/* A pool of worker threads that run one task at a time. It knows nothing of what the task does:
 * the API layer owns a pool per query handle (with a handle per worker) and the batch and scene
 * layers hand it their work. Nothing is allocated per task. */
#ifndef CDIST_BASE_POOL_H
#define CDIST_BASE_POOL_H

/* What every worker runs: worker is its number, 1 .. workers (0 is left to the calling thread,
 * which usually runs the same task alongside). */
typedef void (*cdist__pool_task)(void *arg, int worker);

typedef struct cdist__pool cdist__pool;

/* Start `workers` (>= 1) threads that wait for tasks. NULL on failure, with *error 0 when memory
 * ran out, else pthread_create's error code and *failed the index of the thread it failed to
 * start (the threads already started are stopped again). */
cdist__pool *cdist__pool_new(int workers, int *error, int *failed);
/* Stop and join the threads (NULL allowed). Not while a task runs. */
void cdist__pool_free(cdist__pool *p);
/* Every worker starts task(arg, worker); the caller may work meanwhile, then waits for them with
 * cdist__pool_wait before it starts the next task. */
void cdist__pool_start(cdist__pool *p, cdist__pool_task task, void *arg);
void cdist__pool_wait(cdist__pool *p);

#endif
