/* SPDX-License-Identifier: MIT */
/* Per-family timing of a reference query file: each line timed alone (minimum over repeats),
 * then mean and max per family of the .labels file (or "all" without labels), plus max error
 * against .expected when given.
 * usage: bench_cases QUERIES [LABELS|-] [EXPECTED|-] [REPEATS] */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "circledist.h"
#include "query_io.h"

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

#define MAXL 20000
static cdq_line q[MAXL];
static char lab[MAXL][64];
static double expv[MAXL], tmin[MAXL];

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: bench_cases QUERIES [LABELS|-] [EXPECTED|-] [REPEATS]\n");
        return 2;
    }
    int reps = argc > 4 ? atoi(argv[4]) : 20;
    FILE *f = fopen(argv[1], "r");
    if (!f) return 2;
    char line[4096], err[256];
    int n = 0;
    while (n < MAXL && fgets(line, sizeof line, f))
        if (cdq_parse(line, &q[n], err, sizeof err) == 1) n++;
    fclose(f);
    for (int i = 0; i < n; i++) strcpy(lab[i], "all"), expv[i] = NAN;
    if (argc > 2 && strcmp(argv[2], "-")) {
        FILE *g = fopen(argv[2], "r");
        for (int i = 0; g && i < n && fscanf(g, "%63s", lab[i]) == 1; i++) {}
        if (g) fclose(g);
    }
    if (argc > 3 && strcmp(argv[3], "-")) {
        FILE *g = fopen(argv[3], "r");
        for (int i = 0; g && i < n && fscanf(g, "%lf", &expv[i]) == 1; i++) {}
        if (g) fclose(g);
    }
    cdist_query *h = cdist_query_new();
    cdist_result r;
    double maxerr = 0;
    int worst = -1;
    for (int i = 0; i < n; i++) {
        tmin[i] = 1e30;
        for (int k = 0; k < reps; k++) {
            int inner = 5;
            double t0 = now();
            for (int j = 0; j < inner; j++) cdq_run(h, &q[i], &r);
            double t = (now() - t0) / inner;
            if (t < tmin[i]) tmin[i] = t;
        }
        if (!isnan(expv[i])) {
            double e = fabs(r.distance - expv[i]) / cdq_scale(&q[i], expv[i]);
            if (!(e <= maxerr)) maxerr = e, worst = i;
        }
    }
    /* families in order of first appearance */
    double all = 0, allmax = 0;
    for (int i = 0; i < n; i++) {
        all += tmin[i];
        if (tmin[i] > allmax) allmax = tmin[i];
        int first = 1;
        for (int j = 0; j < i; j++)
            if (!strcmp(lab[j], lab[i])) first = 0;
        if (!first) continue;
        double s = 0, mx = 0;
        int c = 0;
        for (int j = i; j < n; j++)
            if (!strcmp(lab[j], lab[i])) {
                s += tmin[j], c++;
                if (tmin[j] > mx) mx = tmin[j];
            }
        printf("%-32s n=%4d mean %9.3f us  max %9.3f us\n", lab[i], c, 1e6 * s / c, 1e6 * mx);
    }
    double *sorted = malloc(n * sizeof *sorted);
    memcpy(sorted, tmin, n * sizeof *sorted);
    for (int i = 1; i < n; i++)
        for (int j = i; j > 0 && sorted[j - 1] > sorted[j]; j--) {
            double t = sorted[j]; sorted[j] = sorted[j - 1]; sorted[j - 1] = t;
        }
    printf("%-32s n=%4d mean %9.3f us  max %9.3f us  median %.3f us  max/median %.1f  maxerr %.3g (line %d)\n",
           "ALL", n, 1e6 * all / n, 1e6 * allmax, 1e6 * sorted[n / 2], allmax / sorted[n / 2], maxerr, worst + 1);
    free(sorted);
    cdist_query_free(h);
    return 0;
}
