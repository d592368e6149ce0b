/* SPDX-License-Identifier: MIT */
/* The worker pool (pool.h): each task is announced by a generation number under a mutex; a
 * worker spins briefly for the next one before it sleeps on a condition variable. */
#include "base/pool.h"

#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>

/* A worker polls this many times (about 50 us) for the next task before it sleeps: back-to-back
 * tasks then skip the wake-up latency, without burning a core when tasks are rare. */
#define CD_POOL_SPIN 1000

static inline void cpu_relax(void)
{
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
    __builtin_ia32_pause();
#endif
}

typedef struct pool_thread {
    cdist__pool *pool;
    int index;
    pthread_t thread;
} pool_thread;

struct cdist__pool {
    int workers;
    int started; /* threads running */
    pthread_mutex_t mutex;
    pthread_cond_t start, done;
    atomic_ulong generation; /* incremented (under the mutex) per task and to quit */
    int pending;              /* workers still busy with the current task */
    int quit;
    cdist__pool_task task;
    void *arg;
    pool_thread t[];
};

static void *thread_main(void *arg)
{
    pool_thread *t = arg;
    cdist__pool *p = t->pool;
    unsigned long seen = 0;
    for (;;) {
        for (int i = 0; i < CD_POOL_SPIN && atomic_load_explicit(&p->generation, memory_order_relaxed) == seen; i++)
            cpu_relax();
        pthread_mutex_lock(&p->mutex);
        while (atomic_load_explicit(&p->generation, memory_order_relaxed) == seen && !p->quit)
            pthread_cond_wait(&p->start, &p->mutex);
        if (p->quit) {
            pthread_mutex_unlock(&p->mutex);
            return NULL;
        }
        seen = atomic_load_explicit(&p->generation, memory_order_relaxed);
        cdist__pool_task task = p->task;
        void *task_arg = p->arg;
        pthread_mutex_unlock(&p->mutex);
        task(task_arg, t->index);
        pthread_mutex_lock(&p->mutex);
        if (--p->pending == 0) pthread_cond_signal(&p->done);
        pthread_mutex_unlock(&p->mutex);
    }
}

void cdist__pool_free(cdist__pool *p)
{
    if (!p) return;
    if (p->started > 0) {
        pthread_mutex_lock(&p->mutex);
        p->quit = 1;
        atomic_fetch_add(&p->generation, 1);
        pthread_cond_broadcast(&p->start);
        pthread_mutex_unlock(&p->mutex);
        for (int i = 0; i < p->started; i++) pthread_join(p->t[i].thread, NULL);
    }
    pthread_cond_destroy(&p->done);
    pthread_cond_destroy(&p->start);
    pthread_mutex_destroy(&p->mutex);
    free(p);
}

cdist__pool *cdist__pool_new(int workers, int *error, int *failed)
{
    *error = 0;
    *failed = 0;
    cdist__pool *p = calloc(1, sizeof *p + (size_t)workers * sizeof(pool_thread));
    if (!p) return NULL;
    p->workers = workers;
    pthread_mutex_init(&p->mutex, NULL);
    pthread_cond_init(&p->start, NULL);
    pthread_cond_init(&p->done, NULL);
    atomic_init(&p->generation, 0);
    for (int i = 0; i < workers; i++) {
        p->t[i].pool = p;
        p->t[i].index = i + 1;
        int e = pthread_create(&p->t[i].thread, NULL, thread_main, &p->t[i]);
        if (e) {
            cdist__pool_free(p);
            *error = e;
            *failed = i;
            return NULL;
        }
        p->started++;
    }
    return p;
}

void cdist__pool_start(cdist__pool *p, cdist__pool_task task, void *arg)
{
    pthread_mutex_lock(&p->mutex);
    p->task = task;
    p->arg = arg;
    p->pending = p->workers;
    atomic_fetch_add(&p->generation, 1);
    pthread_cond_broadcast(&p->start);
    pthread_mutex_unlock(&p->mutex);
}

void cdist__pool_wait(cdist__pool *p)
{
    pthread_mutex_lock(&p->mutex);
    while (p->pending > 0) pthread_cond_wait(&p->done, &p->mutex);
    pthread_mutex_unlock(&p->mutex);
}
