/* SPDX-License-Identifier: MIT */
/* Circle-circle benchmark: ns per query of each method on a query file (default
 * tests/data/cc_random.txt), plus the bare GSL solve of a degree-8 polynomial for comparison
 * with the polynomial method.
 * usage: bench_cc QUERIES [REPEATS] */
#define _POSIX_C_SOURCE 200809L
#include <gsl/gsl_errno.h>
#include <gsl/gsl_poly.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "circledist.h"

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts); /* CPU time: robust to a loaded machine */
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: bench_cc QUERIES [REPEATS]\n");
        return 2;
    }
    int reps = argc > 2 ? atoi(argv[2]) : 100;
    if (reps < 1) reps = 1;
    FILE *f = fopen(argv[1], "r");
    if (!f) {
        fprintf(stderr, "bench_cc: cannot open %s\n", argv[1]);
        return 2;
    }
    size_t cap = 4096, n = 0;
    cdist_circle *a = malloc(cap * sizeof *a), *b = malloc(cap * sizeof *b);
    char line[1024];
    while (n < cap && fgets(line, sizeof line, f)) {
        double v[14];
        char kind[8];
        if (sscanf(line, "%7s %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf", kind, &v[0], &v[1], &v[2],
                   &v[3], &v[4], &v[5], &v[6], &v[7], &v[8], &v[9], &v[10], &v[11], &v[12], &v[13]) != 15 ||
            strcmp(kind, "cc"))
            continue;
        a[n] = (cdist_circle){{v[0], v[1], v[2]}, {v[3], v[4], v[5]}, v[6]};
        b[n] = (cdist_circle){{v[7], v[8], v[9]}, {v[10], v[11], v[12]}, v[13]};
        n++;
    }
    fclose(f);
    if (n == 0) {
        fprintf(stderr, "bench_cc: no cc queries in %s\n", argv[1]);
        return 2;
    }
    cdist_query *q = cdist_query_new();
    const char *names[] = {"auto", "polynomial", "robust", "iteration"};
    const cdist_method ms[] = {CDIST_METHOD_AUTO, CDIST_METHOD_POLYNOMIAL, CDIST_METHOD_ROBUST,
                               CDIST_METHOD_ITERATION};
    double sink = 0;
    int fails = 0;
    /* Rounds interleave the methods; the fastest round of each is reported (the machine may be
     * shared, and the minimum is the least disturbed measurement). */
    double best[4] = {INFINITY, INFINITY, INFINITY, INFINITY};
    int answered[4] = {-1, -1, -1, -1};
    int rounds = reps >= 5 ? 5 : 1, per = reps >= 5 ? reps / 5 : reps;
    for (int round = 0; round < rounds; round++)
        for (int k = 0; k < 4; k++) {
            cdist_query_set_method(q, ms[k]);
            cdist_result r;
            double t0 = now();
            for (int rep = 0; rep < per; rep++)
                for (size_t i = 0; i < n; i++) {
                    if (cdist_circle_circle(q, &a[i], &b[i], &r) != CDIST_OK) fails++;
                    sink += r.distance;
                    answered[k] = r.method;
                }
            double t = (now() - t0) / ((double)per * n);
            if (t < best[k]) best[k] = t;
        }
    for (int k = 0; k < 4; k++)
        printf("cc %-10s %8.1f ns/query  (%zu queries x %d, best of %d rounds, answered by method %d)\n", names[k],
               1e9 * best[k], n, per, rounds, answered[k]);
    /* Bare GSL degree-8 solve (companion matrix QR) on polynomials with random coefficients. */
    gsl_error_handler_t *old = gsl_set_error_handler_off();
    gsl_poly_complex_workspace *ws = gsl_poly_complex_workspace_alloc(9);
    enum { NP = 256 };
    static double coef[NP][9], z[16];
    unsigned long long s = 88172645463325252ull;
    for (int i = 0; i < NP; i++)
        for (int j = 0; j < 9; j++) {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            coef[i][j] = (double)(s >> 11) / 9007199254740992.0 * 2 - 1;
        }
    int gfail = 0;
    double tg = INFINITY;
    long m = 0;
    for (int round = 0; round < rounds; round++) {
        double t0 = now();
        long mm = 0;
        for (int rep = 0; rep < per * 8; rep++)
            for (int i = 0; i < NP; i++, mm++) {
                if (gsl_poly_complex_solve(coef[i], 9, ws, z) != GSL_SUCCESS) gfail++;
                sink += z[0];
            }
        double t = (now() - t0) / mm;
        if (t < tg) tg = t;
        m += mm;
    }
    printf("gsl_poly_complex_solve degree 8: %8.1f ns/solve (%ld solves, %d failures)\n", 1e9 * tg, m, gfail);
    gsl_poly_complex_workspace_free(ws);
    gsl_set_error_handler(old);
    cdist_query_free(q);
    free(a);
    free(b);
    if (fails) printf("%d queries failed\n", fails);
    return (fails || !isfinite(sink)) ? 1 : 0;
}
