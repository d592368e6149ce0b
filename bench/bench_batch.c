/* SPDX-License-Identifier: MIT */
/* Batch throughput: ns/query per kind for the single-query loop, cdist_batch, cdist_batch_distance,
 * cdist_batch_grad and the first two with 2 threads, on N queries made by repeating the random
 * reference file of the kind (minimum over repeats; the machine is shared, so the minimum is the
 * honest number). Then the contact kinds whose cores have a reference file (TT from cc, TS from pc,
 * Tl from lc, Sd from pd; tube and sphere radii 0.1): the contact loop, cdist_batch_contact,
 * cdist_batch_distance, cdist_batch_grad, and the first two with T threads.
 *   bench_batch [--n=N] [--reps=R] [--threads=T] [--csv=FILE] [--kinds=pc,lc,TT,...] [--cpu] DIR...  */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "circledist.h"
#include "query_io.h"
#include "single.h"

/* Wall clock, or with --cpu the calling thread's CPU time (steadier on a loaded machine; then
 * the T-thread columns count the calling thread's share only). */
static clockid_t bench_clock = CLOCK_MONOTONIC;

static double now(void)
{
    struct timespec t;
    clock_gettime(bench_clock, &t);
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

/* The contact kinds benchmarked: the kind, its short name, the core file, the swept objects' layout. */
static const struct {
    const char *name, *file;
    cdist_kind kind;
} contact_kinds[] = {
    {"TT", "cc", CDIST_KIND_TORUS_TORUS},
    {"TS", "pc", CDIST_KIND_TORUS_SPHERE},
    {"Tl", "lc", CDIST_KIND_TORUS_LINE},
    {"Sd", "pd", CDIST_KIND_SPHERE_DISK},
};

/* Swept objects of a contact kind from the core objects xa, xb of a reference line (radius 0.1). */
static void make_contact_objects(cdist_kind kind, const unsigned char *xa, const unsigned char *xb, unsigned char *a,
                                 unsigned char *b)
{
    switch (kind) {
    case CDIST_KIND_TORUS_TORUS: {
        cdist_torus t = {*(const cdist_circle *)xa, 0.1}, u = {*(const cdist_circle *)xb, 0.1};
        memcpy(a, &t, sizeof t);
        memcpy(b, &u, sizeof u);
        break;
    }
    case CDIST_KIND_TORUS_SPHERE: {
        cdist_torus t = {*(const cdist_circle *)xb, 0.1};
        cdist_sphere s = {*(const cdist_vec3 *)xa, 0.1};
        memcpy(a, &t, sizeof t);
        memcpy(b, &s, sizeof s);
        break;
    }
    case CDIST_KIND_TORUS_LINE: {
        cdist_torus t = {*(const cdist_circle *)xb, 0.1};
        memcpy(a, &t, sizeof t);
        memcpy(b, xa, sizeof(cdist_line));
        break;
    }
    default: { /* sphere-disk */
        cdist_sphere s = {*(const cdist_vec3 *)xa, 0.1};
        memcpy(a, &s, sizeof s);
        memcpy(b, xb, sizeof(cdist_circle));
        break;
    }
    }
}

static int bench_contacts(int ndirs, char **dirs, cdist_query *q, size_t n, int reps, int threads, const char *only,
                          cdist_contact *contacts, double *dist, cdist_grad *grads, cdist_status *st, FILE *out)
{
    int rc = 0;
    printf("\n%-15s %9s %9s %9s %9s %9s %9s\n", "contact kind", "single", "contact", "distance", "grad", "contact-T",
           "dist-T");
    for (size_t k = 0; k < sizeof contact_kinds / sizeof contact_kinds[0]; k++) {
        if (only && !strstr(only, contact_kinds[k].name)) continue;
        cdist_kind kind = contact_kinds[k].kind;
        const cdq_kind *core = NULL;
        for (const cdq_kind *kd = cdq_kinds; kd->name; kd++)
            if (!strcmp(kd->name, contact_kinds[k].file)) core = kd;
        cdist_kind ck = (cdist_kind)core->batch_kind;
        size_t ca = cdist_kind_size_a(ck), cb = cdist_kind_size_b(ck);
        size_t sa = cdist_kind_size_a(kind), sb = cdist_kind_size_b(kind);
        unsigned char *XA = malloc(n * ca), *XB = malloc(n * cb), *A = malloc(n * sa), *B = malloc(n * sb);
        if (!load(ndirs, dirs, core->name, ck, n, XA, XB)) {
            free(XA);
            free(XB);
            free(A);
            free(B);
            continue;
        }
        for (size_t i = 0; i < n; i++) make_contact_objects(kind, XA + i * ca, XB + i * cb, A + i * sa, B + i * sb);
        double t[6] = {1e300, 1e300, 1e300, 1e300, 1e300, 1e300}, check = 0.0;
        for (int r = 0; r < reps; r++) {
            cdist_query_set_threads(q, 1);
            double t0 = now();
            for (size_t i = 0; i < n; i++) single_contact(q, kind, A + i * sa, B + i * sb, &contacts[i]);
            double t1 = now();
            if (cdist_batch_contact(q, kind, n, A, (ptrdiff_t)sa, B, (ptrdiff_t)sb, contacts, st)) rc = 1;
            double t2 = now();
            if (cdist_batch_distance(q, kind, n, A, (ptrdiff_t)sa, B, (ptrdiff_t)sb, dist, st)) rc = 1;
            double t3 = now();
            if (cdist_batch_grad(q, kind, n, A, (ptrdiff_t)sa, B, (ptrdiff_t)sb, contacts, grads, st)) rc = 1;
            double t4 = now();
            cdist_query_set_threads(q, threads);
            double t5 = now();
            if (cdist_batch_contact(q, kind, n, A, (ptrdiff_t)sa, B, (ptrdiff_t)sb, contacts, st)) rc = 1;
            double t6 = now();
            if (cdist_batch_distance(q, kind, n, A, (ptrdiff_t)sa, B, (ptrdiff_t)sb, dist, st)) rc = 1;
            double t7 = now();
            double d[6] = {t1 - t0, t2 - t1, t3 - t2, t4 - t3, t6 - t5, t7 - t6};
            for (int j = 0; j < 6; j++)
                if (d[j] < t[j]) t[j] = d[j];
            check += dist[n - 1] + contacts[n / 2].distance;
        }
        cdist_query_set_threads(q, 1);
        for (int j = 0; j < 6; j++) t[j] *= 1e9 / (double)n;
        printf("%-15s %9.1f %9.1f %9.1f %9.1f %9.1f %9.1f\n", cdist_kind_name(kind), t[0], t[1], t[2], t[3], t[4], t[5]);
        if (out)
            fprintf(out, "%s,%zu,%.2f,%.2f,%.2f,%.2f,%.2f,%.2f\n", cdist_kind_name(kind), n, t[0], t[1], t[2], t[4], t[5],
                    t[3]);
        if (!(check == check)) rc = 1;
        free(XA);
        free(XB);
        free(A);
        free(B);
    }
    return rc;
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
        else if (!strcmp(a, "--cpu")) bench_clock = CLOCK_THREAD_CPUTIME_ID;
        else {
            fprintf(stderr, "unknown option %s\n", a);
            return 2;
        }
    }
    if (first >= argc || n == 0 || reps < 1) {
        fprintf(stderr, "usage: bench_batch [--n=N] [--reps=R] [--threads=T] [--csv=FILE] [--kinds=pc,lc] [--cpu] DIR...\n");
        return 2;
    }
    FILE *out = NULL;
    if (csv && !(out = fopen(csv, "w"))) {
        fprintf(stderr, "cannot write %s\n", csv);
        return 1;
    }
    if (out)
        fprintf(out, "kind,n,single_ns,batch_ns,distance_ns,batch_%dt_ns,distance_%dt_ns,grad_ns\n", threads, threads);
    printf("ns/query, %zu queries, min of %d repeats; %d-thread columns use cdist_query_set_threads(%d)\n", n, reps,
           threads, threads);
    printf("%-15s %9s %9s %9s %9s %9s %8s %9s\n", "kind", "single", "batch", "distance", "batch-T", "dist-T", "speedup",
           "grad");
    cdist_query *q = cdist_query_new();
    cdist_result *res = malloc(n * sizeof *res);
    double *dist = malloc(n * sizeof *dist);
    cdist_status *st = malloc(n * sizeof *st);
    cdist_grad *grads = malloc(n * sizeof *grads);
    cdist_contact *contacts = malloc(n * sizeof *contacts);
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
        double t[6] = {1e300, 1e300, 1e300, 1e300, 1e300, 1e300}, check = 0.0;
        int has_grad = cdist_kind_has_grad(kind);
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
            cdist_query_set_threads(q, 1);
            double t7 = now();
            if (has_grad && cdist_batch_grad(q, kind, n, A, (ptrdiff_t)sa, B, (ptrdiff_t)sb, res, grads, st)) rc = 1;
            double t8 = now();
            double d[6] = {t1 - t0, t2 - t1, t3 - t2, t5 - t4, t6 - t5, has_grad ? t8 - t7 : 0.0};
            for (int j = 0; j < 6; j++)
                if (d[j] < t[j]) t[j] = d[j];
            check += dist[n - 1] + res[n / 2].distance;
        }
        for (int j = 0; j < 6; j++) t[j] *= 1e9 / (double)n;
        printf("%-15s %9.1f %9.1f %9.1f %9.1f %9.1f %7.2fx %9.1f\n", cdist_kind_name(kind), t[0], t[1], t[2], t[3], t[4],
               t[1] / t[3], t[5]);
        if (out)
            fprintf(out, "%s,%zu,%.2f,%.2f,%.2f,%.2f,%.2f,%.2f\n", cdist_kind_name(kind), n, t[0], t[1], t[2], t[3], t[4],
                    t[5]);
        if (!(check == check)) rc = 1;
        free(A);
        free(B);
    }
    printf("(speedup: batch 1 thread / batch %d threads; grad: cdist_batch_grad, 1 thread)\n", threads);
    rc |= bench_contacts(argc - first, argv + first, q, n, reps, threads, only, contacts, dist, grads, st, out);
    cdist_query_free(q);
    free(res);
    free(dist);
    free(st);
    free(grads);
    free(contacts);
    if (out) fclose(out);
    return rc;
}
