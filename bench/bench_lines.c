/* SPDX-License-Identifier: MIT */
/* ns/query of line-circle for each method on a query file (default tests/data/lc_random.txt).
 * usage: bench_lines [PASSES] [FILE] [METHOD]   (reads the file with the tool's parser; METHOD
 * robust, polynomial or auto runs only that one) */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "circledist.h"
#include "query_io.h"

#define MAXQ 100000

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts); /* CPU time: robust to a loaded machine */
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

int main(int argc, char **argv)
{
    int passes = argc > 1 ? atoi(argv[1]) : 200;
    const char *file = argc > 2 ? argv[2] : "tests/data/lc_random.txt";
    if (passes < 1) passes = 1;
    FILE *f = fopen(file, "r");
    if (!f) {
        fprintf(stderr, "bench_lines: cannot open %s\n", file);
        return 1;
    }
    static cdist_line lines[MAXQ];
    static cdist_circle circles[MAXQ];
    int n = 0;
    char buf[4096], err[256];
    while (n < MAXQ && fgets(buf, sizeof buf, f)) {
        cdq_line ql;
        if (cdq_parse(buf, &ql, err, sizeof err) != 1 || strcmp(ql.kind->name, "lc")) continue;
        const double *v = ql.v;
        cdist_line l = {{v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
        cdist_circle c = {{v[6], v[7], v[8]}, {v[9], v[10], v[11]}, v[12]};
        lines[n] = l;
        circles[n] = c;
        n++;
    }
    fclose(f);
    if (n == 0) {
        fprintf(stderr, "bench_lines: no lc queries in %s\n", file);
        return 1;
    }
    const cdist_method ms[3] = {CDIST_METHOD_ROBUST, CDIST_METHOD_POLYNOMIAL, CDIST_METHOD_AUTO};
    const char *names[3] = {"robust", "polynomial", "auto"};
    cdist_query *q = cdist_query_new();
    if (!q) return 1;
    int bad = 0;
    const char *only = argc > 3 ? argv[3] : NULL;
    for (int k = 0; k < 3; k++) {
        if (only && strcmp(only, names[k])) continue;
        cdist_query_set_method(q, ms[k]);
        double sink = 0, t = now();
        for (int p = 0; p < passes; p++)
            for (int i = 0; i < n; i++) {
                cdist_result r;
                if (cdist_line_circle(q, &lines[i], &circles[i], &r) != CDIST_OK) bad++;
                sink += r.distance;
            }
        t = now() - t;
        printf("line_circle %-10s %8.1f ns/query (%d queries x %d passes, checksum %.6g)\n", names[k],
               1e9 * t / ((double)n * passes), n, passes, sink / passes);
    }
    cdist_query_free(q);
    if (bad) fprintf(stderr, "bench_lines: %d queries failed\n", bad);
    return bad ? 1 : 0;
}
