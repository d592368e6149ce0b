/* SPDX-License-Identifier: MIT */
/* Batch throughput: ns/query per kind for the single-query loop, cdist_batch, cdist_batch_distance
 * and both with 2 threads, on N queries made by repeating the random reference file of the kind
 * (minimum over repeats; the machine is shared, so the minimum is the honest number).
 *   bench_batch [--n=N] [--reps=R] [--threads=T] [--csv=FILE] [--kinds=pc,lc,...] DIR...  */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "circledist.h"
#include "query_io.h"
#include "single.h"

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

/* Reads DIR/KIND_random.txt into the object arrays; returns the number of distinct lines. */
static size_t load(int ndirs, char **dirs, const char *k, cdist_kind kind, size_t n, unsigned char *A,
                   unsigned char *B)
{
    char path[1024], buf[2048], err[256];
    FILE *f = NULL;
    for (int i = 0; i < ndirs && !f; i++) {
        snprintf(path, sizeof path, "%s/%s_random.txt", dirs[i], k);
        f = fopen(path, "r");
    }
    if (!f) return 0;
    size_t sa = cdist_kind_size_a(kind), sb = cdist_kind_size_b(kind), m = 0;
    while (m < n && fgets(buf, sizeof buf, f)) {
        cdq_line ql;
        if (cdq_parse(buf, &ql, err, sizeof err) <= 0) continue;
        memcpy(A + m * sa, ql.v, sa);
        memcpy(B + m * sb, ql.v + sa / sizeof(double), sb);
        m++;
    }
    fclose(f);
    for (size_t i = m; m > 0 && i < n; i++) {
        memcpy(A + i * sa, A + (i % m) * sa, sa);
        memcpy(B + i * sb, B + (i % m) * sb, sb);
    }
    return m;
}

int main(int argc, char **argv)
{
    size_t n = 100000;
    int reps = 5, threads = 2;
    const char *csv = NULL, *only = NULL;
    int first = 1;
    for (; first < argc && !strncmp(argv[first], "--", 2); first++) {
        const char *a = argv[first];
        if (!strncmp(a, "--n=", 4)) n = strtoul(a + 4, NULL, 10);
        else if (!strncmp(a, "--reps=", 7)) reps = atoi(a + 7);
        else if (!strncmp(a, "--threads=", 10)) threads = atoi(a + 10);
        else if (!strncmp(a, "--csv=", 6)) csv = a + 6;
        else if (!strcmp(a, "--csv") && first + 1 < argc) csv = argv[++first];
        else if (!strncmp(a, "--kinds=", 8)) only = a + 8;
        else {
            fprintf(stderr, "unknown option %s\n", a);
            return 2;
        }
    }
    if (first >= argc || n == 0 || reps < 1) {
        fprintf(stderr, "usage: bench_batch [--n=N] [--reps=R] [--threads=T] [--csv=FILE] [--kinds=pc,lc] DIR...\n");
        return 2;
    }
    FILE *out = NULL;
    if (csv && !(out = fopen(csv, "w"))) {
        fprintf(stderr, "cannot write %s\n", csv);
        return 1;
    }
    if (out) fprintf(out, "kind,n,single_ns,batch_ns,distance_ns,batch_%dt_ns,distance_%dt_ns\n", threads, threads);
    printf("ns/query, %zu queries, min of %d repeats; %d-thread columns use cdist_query_set_threads(%d)\n", n, reps,
           threads, threads);
    printf("%-15s %9s %9s %9s %9s %9s %8s\n", "kind", "single", "batch", "distance", "batch-T", "dist-T", "speedup");
    cdist_query *q = cdist_query_new();
    cdist_result *res = malloc(n * sizeof *res);
    double *dist = malloc(n * sizeof *dist);
    cdist_status *st = malloc(n * sizeof *st);
    int rc = 0;
    for (const cdq_kind *kd = cdq_kinds; kd->name; kd++) { /* every kind with a batch kind */
        if (kd->batch_kind < 0 || (only && !strstr(only, kd->name))) continue;
        cdist_kind kind = (cdist_kind)kd->batch_kind;
        size_t sa = cdist_kind_size_a(kind), sb = cdist_kind_size_b(kind);
        unsigned char *A = malloc(n * sa), *B = malloc(n * sb);
        if (!load(argc - first, argv + first, kd->name, kind, n, A, B)) {
            free(A);
            free(B);
            continue;
        }
        double t[5] = {1e300, 1e300, 1e300, 1e300, 1e300}, check = 0.0;
        for (int r = 0; r < reps; r++) {
            cdist_query_set_threads(q, 1);
            double t0 = now();
            for (size_t i = 0; i < n; i++) single(q, kind, A + i * sa, B + i * sb, &res[i]);
            double t1 = now();
            if (cdist_batch(q, kind, n, A, (ptrdiff_t)sa, B, (ptrdiff_t)sb, res, st)) rc = 1;
            double t2 = now();
            if (cdist_batch_distance(q, kind, n, A, (ptrdiff_t)sa, B, (ptrdiff_t)sb, dist, st)) rc = 1;
            double t3 = now();
            cdist_query_set_threads(q, threads);
            double t4 = now();
            if (cdist_batch(q, kind, n, A, (ptrdiff_t)sa, B, (ptrdiff_t)sb, res, st)) rc = 1;
            double t5 = now();
            if (cdist_batch_distance(q, kind, n, A, (ptrdiff_t)sa, B, (ptrdiff_t)sb, dist, st)) rc = 1;
            double t6 = now();
            double d[5] = {t1 - t0, t2 - t1, t3 - t2, t5 - t4, t6 - t5};
            for (int j = 0; j < 5; j++)
                if (d[j] < t[j]) t[j] = d[j];
            check += dist[n - 1] + res[n / 2].distance;
        }
        for (int j = 0; j < 5; j++) t[j] *= 1e9 / (double)n;
        printf("%-15s %9.1f %9.1f %9.1f %9.1f %9.1f %7.2fx\n", cdist_kind_name(kind), t[0], t[1], t[2], t[3], t[4],
               t[1] / t[3]);
        if (out)
            fprintf(out, "%s,%zu,%.2f,%.2f,%.2f,%.2f,%.2f\n", cdist_kind_name(kind), n, t[0], t[1], t[2], t[3], t[4]);
        if (!(check == check)) rc = 1;
        free(A);
        free(B);
    }
    printf("(speedup: batch 1 thread / batch %d threads)\n", threads);
    cdist_query_free(q);
    free(res);
    free(dist);
    free(st);
    if (out) fclose(out);
    return rc;
}
