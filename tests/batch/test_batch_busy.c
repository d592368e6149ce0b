/* SPDX-License-Identifier: MIT */
/* Two threads running batches on one handle at once (and a third calling its setters): a batch
 * call either fails every entry with CDIST_ERR_HANDLE_BUSY (distance NaN) and returns it, or
 * gives exactly the single queries' answers. Reference: the single queries on a separate handle.
 * Before the batch flag, the shared worker pool mixed the two calls' entries (wrong distances
 * with statuses other than BUSY). */
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"

enum { N = 20000, CALLS = 100 };
static cdist_vec3 P[N];
static cdist_circle C[N];
static double ref_d[N];
static cdist_status ref_s[N], ref_first;
static cdist_query *shared;

typedef struct {
    int full; /* cdist_batch (full results), else cdist_batch_distance */
    int setters; /* a third thread calls the option setters meanwhile */
    int ok_calls, busy_calls, wrong_calls, first_wrong;
    cdist_status wrong_status;
    double *d;
    cdist_result *r;
    cdist_status *s;
} caller;

static int same(double a, double b) { return (isnan(a) && isnan(b)) || !memcmp(&a, &b, sizeof a); }

static void *call_batches(void *arg)
{
    caller *c = arg;
    for (int k = 0; k < CALLS; k++) {
        cdist_status st =
            c->full ? cdist_batch(shared, CDIST_KIND_POINT_DISK, N, P, sizeof P[0], C, sizeof C[0], c->r, c->s)
                    : cdist_batch_distance(shared, CDIST_KIND_POINT_DISK, N, P, sizeof P[0], C, sizeof C[0], c->d, c->s);
        /* Every entry: the single query's answer, or BUSY with NaN. */
        int nbusy = 0, wrong = 0;
        for (int i = 0; i < N; i++) {
            double d = c->full ? c->r[i].distance : c->d[i];
            if (c->s[i] == CDIST_ERR_HANDLE_BUSY && isnan(d)) {
                nbusy++;
            } else if (!(same(d, ref_d[i]) && c->s[i] == ref_s[i]) && !wrong) {
                wrong = 1;
                c->first_wrong = i;
                c->wrong_status = c->s[i];
            }
        }
        int busy = nbusy == N;
        if (busy && st != CDIST_ERR_HANDLE_BUSY) wrong = 1;
        if (nbusy == 0 && st != ref_first) wrong = 1; /* the lowest failing entry's status */
        /* Some entries BUSY, others answered: only an option setter taking the handle's flag
         * between two entries of this thread's range can do that (another batch never does). */
        if (nbusy > 0 && !busy && !c->setters) wrong = 1;
        c->wrong_calls += wrong;
        c->busy_calls += busy;
        c->ok_calls += !busy;
    }
    return NULL;
}

static atomic_int stop;
static int threads_now;
static void *call_setters(void *arg)
{
    (void)arg;
    int setter_ok = 0;
    while (!stop) {
        /* Same options and thread counts that change nothing in the answers. */
        setter_ok += cdist_query_set_unit_tolerance(shared, 1e-9) == CDIST_OK;
        setter_ok += cdist_query_set_threads(shared, (setter_ok & 1) ? threads_now : 2) == CDIST_OK;
    }
    return NULL;
}

int main(void)
{
    uint64_t x = 0x243F6A8885A308D3ull;
    for (int i = 0; i < N; i++) {
        double v[7];
        for (int k = 0; k < 7; k++) {
            x ^= x << 13, x ^= x >> 7, x ^= x << 17;
            v[k] = (double)(x >> 11) * 0x1p-53 - 0.5;
        }
        double ln = sqrt(v[3] * v[3] + v[4] * v[4] + v[5] * v[5]);
        C[i] = (cdist_circle){{v[0], v[1], v[2]}, {v[3] / ln, v[4] / ln, v[5] / ln}, v[6] + 0.5};
        P[i] = (cdist_vec3){4 * v[2], 4 * v[0], 4 * v[1]};
        if (i % 97 == 5) C[i].radius = -1.0; /* failing entries: their statuses must match too */
    }
    cdist_query *ref = cdist_query_new();
    cdist_query_set_unit_tolerance(ref, 1e-9);
    for (int i = 0; i < N; i++) {
        cdist_result r;
        ref_s[i] = cdist_point_disk(ref, &P[i], &C[i], &r);
        ref_d[i] = r.distance;
    }
    cdist_query_free(ref);
    for (int i = N - 1; i >= 0; i--)
        if (ref_s[i]) ref_first = ref_s[i];

    int counts[] = {1, 2, 4};
    for (int t = 0; t < 3; t++) {
        for (int with_setters = 0; with_setters < 2; with_setters++) {
            shared = cdist_query_new();
            cdist_query_set_unit_tolerance(shared, 1e-9);
            CHECK(cdist_query_set_threads(shared, counts[t]) == CDIST_OK, "set_threads(%d)", counts[t]);
            threads_now = counts[t];
            caller c[2];
            pthread_t th[3];
            for (int k = 0; k < 2; k++) {
                c[k] = (caller){.full = k, .setters = with_setters};
                c[k].d = malloc(N * sizeof *c[k].d);
                c[k].r = malloc(N * sizeof *c[k].r);
                c[k].s = malloc(N * sizeof *c[k].s);
            }
            stop = 0;
            if (with_setters) pthread_create(&th[2], NULL, call_setters, NULL);
            for (int k = 0; k < 2; k++) pthread_create(&th[k], NULL, call_batches, &c[k]);
            for (int k = 0; k < 2; k++) pthread_join(th[k], NULL);
            stop = 1;
            if (with_setters) pthread_join(th[2], NULL);
            for (int k = 0; k < 2; k++) {
                CHECK(c[k].wrong_calls == 0,
                      "threads %d%s, caller %d: %d of %d calls wrong (first entry %d, status %s)", counts[t],
                      with_setters ? " + setters" : "", k, c[k].wrong_calls, CALLS, c[k].first_wrong,
                      cdist_status_name(c[k].wrong_status));
                printf("threads %d%s, caller %d: %d answered, %d busy\n", counts[t], with_setters ? " + setters" : "",
                       k, c[k].ok_calls, c[k].busy_calls);
                free(c[k].d), free(c[k].r), free(c[k].s);
            }
            cdist_query_free(shared);
        }
    }
    return check_summary("batch-busy");
}
