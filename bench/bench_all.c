/* SPDX-License-Identifier: MIT */
/* One benchmark for every query kind and every method the kind has, on the reference files:
 *   KIND_random.txt  mean ns/query over the whole file (the file looped, min of R repeats);
 *   KIND_hard.txt    each line timed alone (the line repeated, min of R repeats), then per family
 *                    of KIND_hard.labels the mean and the max of those per-line times.
 * Prints a table; --csv FILE also writes kind,method,file,family,lines,mean_ns,max_ns.
 * Uses only the public header and tools/query_io so that scripts/bench-compare.sh can build it
 * against an older libcircledist. Times are thread CPU time (robust to a shared machine).
 * usage: bench_all [--reps=R] [--quick] [--kinds=cc,lc,...] [--csv FILE] DATA_DIR
 *   --quick: the first 200 random lines, one pass, one repeat, 1 call per hard line (a smoke
 *   test, not a measurement). */
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
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static const char *const method_names[] = {"auto", "polynomial", "robust", "iteration"};
static const cdist_method methods[] = {CDIST_METHOD_AUTO, CDIST_METHOD_POLYNOMIAL, CDIST_METHOD_ROBUST,
                                       CDIST_METHOD_ITERATION};

typedef struct queries {
    size_t n;
    cdq_line *q;
    char (*label)[64];
} queries;

/* Parses FILE (and its .labels when labels != 0). Returns 0 when the file does not exist. */
static int load(const char *dir, const char *kind, const char *set, int labels, queries *out)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s_%s.txt", dir, kind, set);
    FILE *f = fopen(path, "r");
    if (!f) return 0;
    size_t cap = 256;
    out->n = 0;
    out->q = malloc(cap * sizeof *out->q);
    out->label = labels ? malloc(cap * sizeof *out->label) : NULL;
    FILE *fl = NULL;
    if (labels) {
        snprintf(path, sizeof path, "%s/%s_%s.labels", dir, kind, set);
        fl = fopen(path, "r");
    }
    char line[4096], err[256];
    while (fgets(line, sizeof line, f)) {
        char lab[64] = "unlabelled";
        if (fl && fgets(lab, sizeof lab, fl)) lab[strcspn(lab, "\r\n")] = '\0';
        cdq_line ql;
        if (cdq_parse(line, &ql, err, sizeof err) != 1) continue;
        if (out->n == cap) {
            cap *= 2;
            out->q = realloc(out->q, cap * sizeof *out->q);
            if (labels) out->label = realloc(out->label, cap * sizeof *out->label);
        }
        out->q[out->n] = ql;
        if (labels) memcpy(out->label[out->n], lab, sizeof lab);
        out->n++;
    }
    fclose(f);
    if (fl) fclose(fl);
    return out->n > 0;
}

static double sink;
static long failures;

/* Seconds per query of `count` calls of line i (count < 0: the whole file once per call). */
static double time_block(cdist_query *q, const queries *qs, size_t i, long count)
{
    cdist_result r;
    double t0 = now();
    if (count < 0) {
        for (size_t k = 0; k < qs->n; k++) {
            if (cdq_run(q, &qs->q[k], &r) != CDIST_OK) failures++;
            sink += r.distance;
        }
        return (now() - t0) / (double)qs->n;
    }
    for (long k = 0; k < count; k++) {
        if (cdq_run(q, &qs->q[i], &r) != CDIST_OK) failures++;
        sink += r.distance;
    }
    return (now() - t0) / (double)count;
}

/* Calls of one block: enough for about `target` seconds (at least 1, at most 1e6). */
static long calls_for(double per_call, double target)
{
    double c = target / fmax(per_call, 1e-9);
    return c < 1 ? 1 : c > 1e6 ? 1000000 : (long)c;
}

typedef struct row {
    char kind[8], method[16], set[8], family[64];
    size_t lines;
    double mean_ns, max_ns;
} row;

static row *rows;
static size_t nrows, caprows;

static void add_row(const char *kind, const char *method, const char *set, const char *family, size_t lines,
                    double mean, double max)
{
    if (nrows == caprows) rows = realloc(rows, (caprows = caprows ? 2 * caprows : 64) * sizeof *rows);
    row *w = &rows[nrows++];
    snprintf(w->kind, sizeof w->kind, "%s", kind);
    snprintf(w->method, sizeof w->method, "%s", method);
    snprintf(w->set, sizeof w->set, "%s", set);
    snprintf(w->family, sizeof w->family, "%s", family);
    w->lines = lines;
    w->mean_ns = 1e9 * mean;
    w->max_ns = 1e9 * max;
}

static int kind_selected(const char *list, const char *kind)
{
    if (!list) return 1;
    size_t n = strlen(kind);
    for (const char *p = list; (p = strstr(p, kind)); p += n)
        if ((p == list || p[-1] == ',') && (p[n] == ',' || p[n] == '\0')) return 1;
    return 0;
}

int main(int argc, char **argv)
{
    int reps = 5, quick = 0;
    const char *csv = NULL, *dir = NULL, *kinds = NULL;
    for (int i = 1; i < argc; i++) {
        if (!strncmp(argv[i], "--reps=", 7)) reps = atoi(argv[i] + 7);
        else if (!strcmp(argv[i], "--quick")) quick = 1;
        else if (!strncmp(argv[i], "--kinds=", 8)) kinds = argv[i] + 8;
        else if (!strncmp(argv[i], "--csv=", 6)) csv = argv[i] + 6;
        else if (!strcmp(argv[i], "--csv") && i + 1 < argc) csv = argv[++i];
        else if (argv[i][0] != '-' && !dir) dir = argv[i];
        else {
            fprintf(stderr, "usage: bench_all [--reps=R] [--quick] [--kinds=cc,lc,...] [--csv FILE] DATA_DIR\n");
            return 2;
        }
    }
    if (!dir) {
        fprintf(stderr, "usage: bench_all [--reps=R] [--quick] [--kinds=cc,lc,...] [--csv FILE] DATA_DIR\n");
        return 2;
    }
    if (quick) reps = 1;
    if (reps < 1) reps = 1;
    const double target = quick ? 0 : 2e-4; /* seconds per timed block of a hard line */
    cdist_query *q = cdist_query_new();
    int files = 0;
    for (const cdq_kind *kd = cdq_kinds; kd->name; kd++) {
        if (!kind_selected(kinds, kd->name)) continue;
        queries rnd = {0}, hard = {0};
        int have_r = load(dir, kd->name, "random", 0, &rnd), have_h = load(dir, kd->name, "hard", 1, &hard);
        if (!have_r && !have_h) continue;
        if (quick && rnd.n > 200) rnd.n = 200; /* a smoke test: a few of each */
        files += have_r + have_h;
        const queries *probe = have_r ? &rnd : &hard;
        for (int m = 0; m < 4; m++) {
            /* The kind has method m when a query set to m is answered by m (AUTO always). */
            cdist_query_set_method(q, methods[m]);
            cdist_result r;
            if (cdq_run(q, &probe->q[0], &r) != CDIST_OK) continue;
            if (m != 0 && r.method != (int)methods[m]) continue;
            if (have_r) {
                double per = time_block(q, &rnd, 0, -1); /* warm-up and calibration */
                long passes = quick ? 1 : calls_for(per * (double)rnd.n, 0.05);
                double best = INFINITY;
                for (int k = 0; k < reps; k++) {
                    double t = 0;
                    for (long p = 0; p < passes; p++) t += time_block(q, &rnd, 0, -1);
                    best = fmin(best, t / (double)passes);
                }
                add_row(kd->name, method_names[m], "random", "all", rnd.n, best, NAN);
            }
            if (have_h) {
                double *t = malloc(hard.n * sizeof *t);
                for (size_t i = 0; i < hard.n; i++) {
                    long count = quick ? 1 : calls_for(time_block(q, &hard, i, 1), target);
                    t[i] = INFINITY;
                    for (int k = 0; k < reps; k++) t[i] = fmin(t[i], time_block(q, &hard, i, count));
                }
                /* per family, in order of first appearance; then the whole file */
                char *done = calloc(hard.n, 1);
                double all_sum = 0, all_max = 0;
                for (size_t i = 0; i < hard.n; i++) {
                    all_sum += t[i];
                    all_max = fmax(all_max, t[i]);
                    if (done[i]) continue;
                    double sum = 0, mx = 0;
                    size_t n = 0;
                    for (size_t j = i; j < hard.n; j++)
                        if (!strcmp(hard.label[j], hard.label[i])) {
                            done[j] = 1;
                            sum += t[j];
                            mx = fmax(mx, t[j]);
                            n++;
                        }
                    add_row(kd->name, method_names[m], "hard", hard.label[i], n, sum / (double)n, mx);
                }
                add_row(kd->name, method_names[m], "hard", "all", hard.n, all_sum / (double)hard.n, all_max);
                free(done);
                free(t);
            }
        }
        free(rnd.q);
        free(hard.q);
        free(hard.label);
    }
    cdist_query_free(q);
    if (!files) {
        fprintf(stderr, "bench_all: no KIND_random.txt / KIND_hard.txt in %s\n", dir);
        return 2;
    }
    printf("%-4s %-10s %-6s %-32s %6s %12s %12s\n", "kind", "method", "file", "family", "lines", "mean ns",
           "max ns");
    for (size_t i = 0; i < nrows; i++) {
        char mx[32] = "-"; /* a random file has no per-line times */
        if (!isnan(rows[i].max_ns)) snprintf(mx, sizeof mx, "%.1f", rows[i].max_ns);
        printf("%-4s %-10s %-6s %-32s %6zu %12.1f %12s\n", rows[i].kind, rows[i].method, rows[i].set,
               rows[i].family, rows[i].lines, rows[i].mean_ns, mx);
    }
    printf("(%s; min of %d repeats; %ld failed queries)\n", quick ? "quick run, not a measurement" : "release numbers",
           reps, failures);
    if (csv) {
        FILE *f = fopen(csv, "w");
        if (!f) {
            perror(csv);
            return 2;
        }
        fprintf(f, "kind,method,file,family,lines,mean_ns,max_ns\n");
        for (size_t i = 0; i < nrows; i++)
        {
            char mx[32] = ""; /* empty: a random file has no per-line times */
            if (!isnan(rows[i].max_ns)) snprintf(mx, sizeof mx, "%.1f", rows[i].max_ns);
            fprintf(f, "%s,%s,%s,%s,%zu,%.1f,%s\n", rows[i].kind, rows[i].method, rows[i].set, rows[i].family,
                    rows[i].lines, rows[i].mean_ns, mx);
        }
        if (fclose(f) != 0) {
            perror(csv);
            return 2;
        }
    }
    free(rows);
    return failures ? 1 : 0;
}
