/* SPDX-License-Identifier: MIT */
/* Disk queries: nanoseconds per query on the shared random cases, per method.
 * usage: bench_disk [--reps=N] DATA_DIR
 * ld_random.txt drives ld, rd and sd (the same numbers read as line, ray, segment); cd_random.txt
 * drives cd and dd. Calls the public functions directly (no per-query parsing or dispatch). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "circledist.h"
#include "query_io.h"

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts); /* CPU time: less sensitive to a loaded machine */
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static int load(const char *dir, const char *name, cdq_line **out)
{
    char path[4096], line[4096], err[256];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "r");
    if (!f) return -1;
    int n = 0, cap = 0;
    cdq_line *v = NULL;
    while (fgets(line, sizeof line, f)) {
        cdq_line ql;
        if (cdq_parse(line, &ql, err, sizeof err) != 1) continue;
        if (n == cap) {
            cap = cap ? 2 * cap : 1024;
            v = realloc(v, cap * sizeof *v);
        }
        v[n++] = ql;
    }
    fclose(f);
    *out = v;
    return n;
}

static cdist_vec3 V(const double *v) { cdist_vec3 r = {v[0], v[1], v[2]}; return r; }
static cdist_circle C(const double *v) { cdist_circle c = {V(v), V(v + 3), v[6]}; return c; }

static double sink;

static double run(cdist_query *q, const char *kind, const cdq_line *ql, int n, int reps)
{
    cdist_result r;
    double t0 = now();
    for (int k = 0; k < reps; k++) {
        for (int i = 0; i < n; i++) {
            const double *v = ql[i].v;
            if (!strcmp(kind, "ld")) {
                cdist_line l = {V(v), V(v + 3)};
                cdist_circle d = C(v + 6);
                cdist_line_disk(q, &l, &d, &r);
            } else if (!strcmp(kind, "rd")) {
                cdist_ray l = {V(v), V(v + 3)};
                cdist_circle d = C(v + 6);
                cdist_ray_disk(q, &l, &d, &r);
            } else if (!strcmp(kind, "sd")) {
                cdist_segment s = {V(v), V(v + 3)};
                s.p1.x += s.p0.x; s.p1.y += s.p0.y; s.p1.z += s.p0.z;
                cdist_circle d = C(v + 6);
                cdist_segment_disk(q, &s, &d, &r);
            } else {
                cdist_circle a = C(v), b = C(v + 7);
                if (!strcmp(kind, "cd")) cdist_circle_disk(q, &a, &b, &r);
                else cdist_disk_disk(q, &a, &b, &r);
            }
            sink += r.distance;
        }
    }
    return (now() - t0) / ((double)reps * n) * 1e9;
}

int main(int argc, char **argv)
{
    int reps = 20;
    const char *dir = NULL;
    for (int i = 1; i < argc; i++) {
        if (!strncmp(argv[i], "--reps=", 7)) reps = atoi(argv[i] + 7);
        else dir = argv[i];
    }
    if (!dir || reps < 1) {
        fprintf(stderr, "usage: bench_disk [--reps=N] DATA_DIR\n");
        return 2;
    }
    cdq_line *ld = NULL, *cd = NULL;
    int nl = load(dir, "ld_random.txt", &ld), nc = load(dir, "cd_random.txt", &cd);
    if (nl <= 0 || nc <= 0) {
        fprintf(stderr, "bench_disk: cannot read %s/ld_random.txt or cd_random.txt\n", dir);
        return 2;
    }
    cdist_query *q = cdist_query_new();
    const char *kinds[] = {"ld", "rd", "sd", "cd", "dd"};
    const cdist_method methods[] = {CDIST_METHOD_AUTO, CDIST_METHOD_POLYNOMIAL, CDIST_METHOD_ROBUST};
    const char *mnames[] = {"auto", "polynomial", "robust"};
    printf("%-4s %12s %12s %12s   (ns/query, %d reps of %d/%d queries)\n", "kind", mnames[0], mnames[1], mnames[2],
           reps, nl, nc);
    for (int k = 0; k < 5; k++) {
        printf("%-4s", kinds[k]);
        for (int m = 0; m < 3; m++) {
            cdist_query_set_method(q, methods[m]);
            int isl = kinds[k][0] != 'c' && kinds[k][0] != 'd';
            printf(" %12.0f", run(q, kinds[k], isl ? ld : cd, isl ? nl : nc, reps));
        }
        printf("\n");
    }
    cdist_query_free(q);
    free(ld);
    free(cd);
    return sink == sink ? 0 : 1;
}
