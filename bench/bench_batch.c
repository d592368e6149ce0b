/* SPDX-License-Identifier: MIT */
/* Batch throughput: ns/query per kind for the single-query loop, cdist_batch, cdist_batch_distance,
 * cdist_batch_grad and the first two with 2 threads, on N queries made by repeating the random
 * reference file of the kind (minimum over repeats; the machine is shared, so the minimum is the
 * honest number). Then the contact kinds whose cores have a reference file (TT from cc, TS from pc,
 * Tl from lc, Sd from pd; tube and sphere radii 0.1), their batch column cdist_batch_contact.
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

/* The output buffers of a benchmark (n entries each). */
typedef struct buffers {
    cdist_result *res;
    cdist_contact *contacts;
    double *dist;
    cdist_grad *grads;
    cdist_status *st;
} buffers;

/* One kind on n entries: minimum over reps of the single-query loop, the full batch (results, or
 * contacts for a contact kind), the distance batch, both on `threads` threads and the gradient
 * batch (0 without one), in ns/entry, printed as one row (and a CSV line). Returns non-zero when
 * a call failed. */
static int measure(cdist_query *q, cdist_kind kind, size_t n, int reps, int threads, const unsigned char *A,
                   const unsigned char *B, const buffers *o, FILE *out)
{
    size_t sa = cdist_kind_size_a(kind), sb = cdist_kind_size_b(kind);
    int contact = cdist_kind_result_size(kind) == sizeof(cdist_contact), has_grad = cdist_kind_has_grad(kind), rc = 0;
    void *full = contact ? (void *)o->contacts : (void *)o->res;
    double t[6] = {1e300, 1e300, 1e300, 1e300, 1e300, 1e300}, check = 0.0;
    for (int r = 0; r < reps; r++) {
        double d[6] = {0};
        for (int pass = 0; pass < 2; pass++) { /* pass 0: 1 thread, pass 1: T threads */
            cdist_query_set_threads(q, pass ? threads : 1);
            double t0 = now();
            if (!pass) {
                for (size_t i = 0; i < n; i++) {
                    if (contact) single_contact(q, kind, A + i * sa, B + i * sb, &o->contacts[i]);
                    else single(q, kind, A + i * sa, B + i * sb, &o->res[i]);
                }
            }
            double t1 = now();
            if (contact ? cdist_batch_contact(q, kind, n, A, (ptrdiff_t)sa, B, (ptrdiff_t)sb, full, o->st)
                        : cdist_batch(q, kind, n, A, (ptrdiff_t)sa, B, (ptrdiff_t)sb, full, o->st))
                rc = 1;
            double t2 = now();
            if (cdist_batch_distance(q, kind, n, A, (ptrdiff_t)sa, B, (ptrdiff_t)sb, o->dist, o->st)) rc = 1;
            double t3 = now();
            if (!pass && has_grad && cdist_batch_grad(q, kind, n, A, (ptrdiff_t)sa, B, (ptrdiff_t)sb, full, o->grads, o->st))
                rc = 1;
            double t4 = now();
            if (pass) {
                d[3] = t2 - t1;
                d[4] = t3 - t2;
            } else {
                d[0] = t1 - t0;
                d[1] = t2 - t1;
                d[2] = t3 - t2;
                d[5] = t4 - t3;
            }
        }
        for (int j = 0; j < 6; j++)
            if (d[j] < t[j]) t[j] = d[j];
        check += o->dist[n - 1] + (contact ? o->contacts[n / 2].distance : o->res[n / 2].distance);
    }
    cdist_query_set_threads(q, 1);
    for (int j = 0; j < 6; j++) t[j] *= 1e9 / (double)n;
    printf("%-15s %9.1f %9.1f %9.1f %9.1f %9.1f %7.2fx %9.1f\n", cdist_kind_name(kind), t[0], t[1], t[2], t[3], t[4],
           t[1] / t[3], t[5]);
    if (out)
        fprintf(out, "%s,%zu,%.2f,%.2f,%.2f,%.2f,%.2f,%.2f\n", cdist_kind_name(kind), n, t[0], t[1], t[2], t[3], t[4], t[5]);
    return rc || !(check == check);
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
    buffers o = {malloc(n * sizeof *o.res), malloc(n * sizeof *o.contacts), malloc(n * sizeof *o.dist),
                 malloc(n * sizeof *o.grads), malloc(n * sizeof *o.st)};
    int rc = 0;
    for (const cdq_kind *kd = cdq_kinds; kd->name; kd++) { /* every kind with a batch kind */
        if (kd->batch_kind < 0 || (only && !strstr(only, kd->name))) continue;
        cdist_kind kind = (cdist_kind)kd->batch_kind;
        size_t sa = cdist_kind_size_a(kind), sb = cdist_kind_size_b(kind);
        unsigned char *A = malloc(n * sa), *B = malloc(n * sb);
        if (load(argc - first, argv + first, kd->name, kind, n, A, B)) rc |= measure(q, kind, n, reps, threads, A, B, &o, out);
        free(A);
        free(B);
    }
    /* the contact kinds, their objects built from their cores' reference files */
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
        if (load(argc - first, argv + first, core->name, ck, n, XA, XB)) {
            for (size_t i = 0; i < n; i++) make_contact_objects(kind, XA + i * ca, XB + i * cb, A + i * sa, B + i * sb);
            rc |= measure(q, kind, n, reps, threads, A, B, &o, out);
        }
        free(XA);
        free(XB);
        free(A);
        free(B);
    }
    printf("(speedup: batch 1 thread / batch %d threads; batch: cdist_batch, or cdist_batch_contact for a contact "
           "kind; grad: cdist_batch_grad, 1 thread)\n", threads);
    cdist_query_free(q);
    free(o.res);
    free(o.contacts);
    free(o.dist);
    free(o.grads);
    free(o.st);
    if (out) fclose(out);
    return rc;
}
