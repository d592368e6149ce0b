/* SPDX-License-Identifier: MIT */
/* Batch entry points against the single queries, on every reference file found:
 *   test_batch DIR...   (reference files KIND_{random,hard}.txt/.expected looked up in each DIR)
 * - cdist_batch() is bit-identical to the single query of every entry, with bad entries (NaN,
 *   zero normal, negative radius, NULL callback) mixed in at random positions; its distances also
 *   match the shared expected values (1e-12 of scale, or the erratum);
 * - cdist_batch_distance() is within 2 ulps of scale of the single query's distance, NaN and the
 *   same status for a bad entry;
 * - 1, 2 and 7 threads give bit-identical results;
 * - strides: user structs, broadcast (0), negative; NULL handle/arrays, bad kind, messages. */
#include <float.h>
#include <pthread.h>
#include <time.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "test_rand.h"
#include "circle_curve.h"
#include "circledist.h"
#include "query_io.h"
#include "single.h"

/* Beyond the tool's kinds (tools/query_io.c, each read from its own files): callback curves, the
 * first circle of the cc/cd lines as a curve. */
static const struct {
    const char *file;
    cdist_kind kind;
} curve_files[] = {{"cc", CDIST_KIND_CURVE_CIRCLE}, {"cd", CDIST_KIND_CURVE_DISK}};


static FILE *open_in(int ndirs, char **dirs, const char *name, char *path, size_t len)
{
    for (int i = 0; i < ndirs; i++) {
        snprintf(path, len, "%s/%s", dirs[i], name);
        FILE *f = fopen(path, "r");
        if (f) return f;
    }
    return NULL;
}

#define MAX_LINES 2100
#define CURVE_LINES 120

static cdq_line lines[MAX_LINES];
static double expected[MAX_LINES];
static circ_curve curves[MAX_LINES];

/* Corrupt entry i's objects in one of the documented ways; returns the status expected. */
static cdist_status corrupt(cdist_kind k, unsigned char *a, size_t sa, unsigned char *b, size_t sb)
{
    (void)sa;
    (void)sb;
    double *bd = (double *)b; /* every second object starts with a circle (arcs too) */
    switch (next_rand() % 4) {
    case 0:
        if (k == CDIST_KIND_CURVE_CIRCLE || k == CDIST_KIND_CURVE_DISK) {
            ((cdist_curve *)a)->fn = NULL;
            return CDIST_ERR_NULL_ARGUMENT;
        }
        ((double *)a)[0] = NAN;
        return CDIST_ERR_NOT_FINITE;
    case 1: bd[1] = INFINITY; return CDIST_ERR_NOT_FINITE;
    case 2: bd[3] = bd[4] = bd[5] = 0.0; return CDIST_ERR_ZERO_VECTOR;
    default: bd[6] = -1.0; return CDIST_ERR_NEGATIVE_RADIUS;
    }
}

static int same_result(const cdist_result *x, const cdist_result *y) { return !memcmp(x, y, sizeof *x); }

static void run_file(cdist_query *q, int ndirs, char **dirs, const char *kname, cdist_kind kind, const char *set)
{
    char name[64], path[1024], epath[1024];
    int curve = kind == CDIST_KIND_CURVE_CIRCLE || kind == CDIST_KIND_CURVE_DISK;
    snprintf(name, sizeof name, "%s_%s.txt", kname, set);
    FILE *f = open_in(ndirs, dirs, name, path, sizeof path);
    if (!f) {
        printf("  %-14s %-6s not found, skipped\n", cdist_kind_name(kind), set);
        return;
    }
    snprintf(epath, sizeof epath, "%.*s.expected", (int)(strlen(path) - 4), path);
    FILE *fe = fopen(epath, "r");
    CHECK(fe != NULL, "no %s", epath);
    if (!fe) {
        fclose(f);
        return;
    }
    size_t n = 0;
    long lineno[MAX_LINES];
    char buf[2048], err[256];
    long ln = 0;
    while (n < MAX_LINES && fgets(buf, sizeof buf, f)) {
        ln++;
        int s = cdq_parse(buf, &lines[n], err, sizeof err);
        if (s <= 0) continue;
        char eb[128];
        if (!fgets(eb, sizeof eb, fe)) break;
        expected[n] = strtod(eb, NULL);
        lineno[n] = ln;
        n++;
        if (curve && n >= CURVE_LINES) break;
    }
    fclose(f);
    fclose(fe);
    size_t sa = cdist_kind_size_a(kind), sb = cdist_kind_size_b(kind);
    unsigned char *A = malloc(n * sa), *B = malloc(n * sb);
    cdist_status *want_bad = calloc(n, sizeof *want_bad);
    for (size_t i = 0; i < n; i++) {
        const double *v = lines[i].v;
        if (curve) {
            cdist_circle c;
            memcpy(&c, v, sizeof c);
            curves[i] = circ_curve_of(&c);
            cdist_curve cv = {circ_fn, &curves[i], -M_PI, M_PI};
            memcpy(A + i * sa, &cv, sa);
            memcpy(B + i * sb, v + 7, sb);
        } else {
            CHECK((size_t)lines[i].nvalues * sizeof(double) == sa + sb, "%s: %d numbers for sizes %zu + %zu", name,
                  lines[i].nvalues, sa, sb);
            memcpy(A + i * sa, v, sa);
            memcpy(B + i * sb, v + sa / sizeof(double), sb);
        }
        if (next_rand() % 100 < 4) want_bad[i] = corrupt(kind, A + i * sa, sa, B + i * sb, sb);
    }
    /* the single queries */
    cdist_result *rs = malloc(n * sizeof *rs), *rb = malloc(n * sizeof *rb), *r1 = malloc(n * sizeof *r1);
    cdist_status *ss = malloc(n * sizeof *ss), *sbt = malloc(n * sizeof *sbt), *s1 = malloc(n * sizeof *s1);
    double *db = malloc(n * sizeof *db), *d1 = malloc(n * sizeof *d1);
    size_t first_bad = SIZE_MAX;
    int nbad = 0, far = 0, same_dist = 0;
    double worst = 0.0;
    for (size_t i = 0; i < n; i++) {
        ss[i] = single(q, kind, A + i * sa, B + i * sb, &rs[i]);
        if (want_bad[i]) {
            nbad++;
            CHECK(ss[i] == want_bad[i], "%s:%ld corrupted: %s, expected %s", name, lineno[i], cdist_status_name(ss[i]),
                  cdist_status_name(want_bad[i]));
        }
        if (ss[i] && first_bad == SIZE_MAX) first_bad = i;
    }
    for (int threads = 1; threads <= 7; threads += (threads == 1 ? 1 : 5)) {
        CHECK(cdist_query_set_threads(q, threads) == CDIST_OK, "set threads %d", threads);
        cdist_status ret = cdist_batch(q, kind, n, A, (ptrdiff_t)sa, B, (ptrdiff_t)sb, rb, sbt);
        cdist_status want = first_bad == SIZE_MAX ? CDIST_OK : ss[first_bad];
        CHECK(ret == want, "%s threads %d: batch returned %s, want %s", name, threads, cdist_status_name(ret),
              cdist_status_name(want));
        if (first_bad != SIZE_MAX) {
            char tag[64];
            snprintf(tag, sizeof tag, "entry %zu:", first_bad);
            CHECK(strstr(cdist_query_last_error(q), tag) != NULL, "%s: message '%s' lacks '%s'", name,
                  cdist_query_last_error(q), tag);
        }
        int mism = 0, dmis = 0, tdiff = 0;
        same_dist = 0;
        for (size_t i = 0; i < n; i++) {
            if (!same_result(&rb[i], &rs[i]) || sbt[i] != ss[i]) {
                if (mism++ < 3)
                    CHECK(0, "%s:%ld threads %d: batch %.17g (%s) vs single %.17g (%s)", name, lineno[i], threads,
                          rb[i].distance, cdist_status_name(sbt[i]), rs[i].distance, cdist_status_name(ss[i]));
            }
        }
        CHECK(mism == 0, "%s threads %d: %d batch results differ from the single queries", name, threads, mism);
        ret = cdist_batch_distance(q, kind, n, A, (ptrdiff_t)sa, B, (ptrdiff_t)sb, db, sbt);
        CHECK(ret == want, "%s threads %d: distance batch returned %s", name, threads, cdist_status_name(ret));
        for (size_t i = 0; i < n; i++) {
            int ok;
            if (ss[i]) {
                ok = isnan(db[i]) && sbt[i] == ss[i];
            } else {
                double L = cdq_scale(&lines[i], expected[i]);
                ok = sbt[i] == CDIST_OK && fabs(db[i] - rs[i].distance) <= 2.0 * ulp(L);
                same_dist += !memcmp(&db[i], &rs[i].distance, sizeof(double));
            }
            if (!ok && dmis++ < 3)
                CHECK(0, "%s:%ld threads %d: distance %.17g (%s) vs single %.17g (%s)", name, lineno[i], threads, db[i],
                      cdist_status_name(sbt[i]), rs[i].distance, cdist_status_name(ss[i]));
        }
        CHECK(dmis == 0, "%s threads %d: %d distances off", name, threads, dmis);
        if (threads == 1) {
            memcpy(r1, rb, n * sizeof *r1);
            memcpy(d1, db, n * sizeof *d1);
            memcpy(s1, sbt, n * sizeof *s1);
        } else {
            for (size_t i = 0; i < n; i++)
                tdiff += !same_result(&rb[i], &r1[i]) || memcmp(&db[i], &d1[i], sizeof(double)) || sbt[i] != s1[i];
            CHECK(tdiff == 0, "%s: %d entries differ between 1 and %d threads", name, tdiff, threads);
        }
    }
    CHECK(cdist_query_set_threads(q, 1) == CDIST_OK, "back to 1 thread");
    /* the answers are right, not just consistent: the shared reference, 1e-12 of scale (the
     * project's bar) for the exact families; the sampled ones (callback curves, helices, Bezier
     * curves) only to 1e-9 here, their accuracy is the curve tests' business */
    int sampled = curve || kind == CDIST_KIND_HELIX_CIRCLE || kind == CDIST_KIND_HELIX_DISK ||
                  kind == CDIST_KIND_BEZIER3_CIRCLE || kind == CDIST_KIND_BEZIER3_DISK;
    double tol = sampled ? 1e-9 : 1e-12;
    for (size_t i = 0; i < n; i++) {
        if (ss[i]) continue;
        double L = cdq_scale(&lines[i], expected[i]);
        double e = fabs(r1[i].distance - expected[i]) / L;
        if (e > worst) worst = e;
        if (e > tol) far++;
    }
    CHECK(far == 0, "%s: %d distances off the reference by more than %g of scale (worst %.3g)", name, far, tol, worst);
    /* distance-only answers from a distance kernel (point, line, ray and segment against a
     * circle) repeat the single query's arithmetic: all bit-identical here */
    printf("  %-14s %-6s %4zu entries (%2d bad), worst error %.2g of scale, distance-only bit-identical %d of %zu\n",
           cdist_kind_name(kind), set, n, nbad, worst, same_dist, n - (size_t)nbad);
    free(A);
    free(B);
    free(want_bad);
    free(rs);
    free(rb);
    free(r1);
    free(ss);
    free(sbt);
    free(s1);
    free(db);
    free(d1);
}

/* ---- strides, broadcast, NULLs ---- */

typedef struct user_item {
    int tag;
    cdist_circle circle;
    char note[13];
    cdist_vec3 point;
} user_item;

static void strides(cdist_query *q)
{
    enum { N = 300 };
    user_item *items = malloc(N * sizeof *items);
    for (int i = 0; i < N; i++) {
        double t = 0.37 * i;
        items[i].tag = i;
        items[i].circle = (cdist_circle){{cos(t), sin(2 * t), 0.1 * i}, {0, sin(t), cos(t)}, 0.5 + 0.01 * i};
        items[i].point = tv(sin(3 * t), 1.0 + cos(t), 2.0 - 0.02 * i);
    }
    cdist_result *r = malloc(N * sizeof *r), s;
    double *d = malloc(N * sizeof *d);
    for (int threads = 1; threads <= 2; threads++) {
        cdist_query_set_threads(q, threads);
        /* user structs */
        CHECK(cdist_batch(q, CDIST_KIND_POINT_DISK, N, &items[0].point, sizeof(user_item), &items[0].circle,
                          sizeof(user_item), r, NULL) == CDIST_OK,
              "user structs");
        CHECK(cdist_batch_distance(q, CDIST_KIND_POINT_DISK, N, &items[0].point, sizeof(user_item), &items[0].circle,
                                   sizeof(user_item), d, NULL) == CDIST_OK,
              "user structs, distance");
        int bad = 0;
        for (int i = 0; i < N; i++) {
            cdist_point_disk(q, &items[i].point, &items[i].circle, &s);
            bad += !same_result(&r[i], &s) || d[i] != s.distance;
        }
        CHECK(bad == 0, "user structs: %d entries differ", bad);
        /* broadcast: one circle against every point, one point against every circle */
        CHECK(cdist_batch(q, CDIST_KIND_CIRCLE_CIRCLE, N, &items[0].circle, sizeof(user_item), &items[7].circle, 0, r,
                          NULL) == CDIST_OK,
              "broadcast b");
        bad = 0;
        for (int i = 0; i < N; i++) {
            cdist_circle_circle(q, &items[i].circle, &items[7].circle, &s);
            bad += !same_result(&r[i], &s);
        }
        CHECK(bad == 0, "broadcast b: %d entries differ", bad);
        CHECK(cdist_batch_distance(q, CDIST_KIND_POINT_CIRCLE, N, &items[3].point, 0, &items[0].circle,
                                   sizeof(user_item), d, NULL) == CDIST_OK,
              "broadcast a");
        bad = 0;
        for (int i = 0; i < N; i++) {
            cdist_point_circle(q, &items[3].point, &items[i].circle, &s);
            bad += d[i] != s.distance;
        }
        CHECK(bad == 0, "broadcast a: %d entries differ", bad);
        /* negative strides: the arrays walked backwards */
        CHECK(cdist_batch_distance(q, CDIST_KIND_POINT_CIRCLE, N, &items[N - 1].point, -(ptrdiff_t)sizeof(user_item),
                                   &items[N - 1].circle, -(ptrdiff_t)sizeof(user_item), d, NULL) == CDIST_OK,
              "negative strides");
        CHECK(cdist_batch(q, CDIST_KIND_POINT_CIRCLE, N, &items[N - 1].point, -(ptrdiff_t)sizeof(user_item),
                          &items[N - 1].circle, -(ptrdiff_t)sizeof(user_item), r, NULL) == CDIST_OK,
              "negative strides, full");
        bad = 0;
        for (int i = 0; i < N; i++) {
            cdist_point_circle(q, &items[N - 1 - i].point, &items[N - 1 - i].circle, &s);
            bad += d[i] != s.distance || !same_result(&r[i], &s);
        }
        CHECK(bad == 0, "negative strides: %d entries differ", bad);
    }
    cdist_query_set_threads(q, 1);
    free(r);
    free(d);
    free(items);
}

/* Threads really run concurrently: a callback curve whose evaluations wait (up to 10 s) until a
 * second thread has evaluated too, recording the threads seen. */
static pthread_mutex_t seen_mutex = PTHREAD_MUTEX_INITIALIZER;
static pthread_t seen[64];
static int nseen;

static int seen_count(void)
{
    pthread_mutex_lock(&seen_mutex);
    pthread_t me = pthread_self();
    int found = 0;
    for (int i = 0; i < nseen; i++) found |= pthread_equal(seen[i], me);
    if (!found && nseen < 64) seen[nseen++] = me;
    int n = nseen;
    pthread_mutex_unlock(&seen_mutex);
    return n;
}

static int waiting_fn(void *user, double t, cdist_vec3 *p, cdist_vec3 *d)
{
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    do {
        if (seen_count() >= 2) break;
        clock_gettime(CLOCK_MONOTONIC, &t1);
    } while (t1.tv_sec - t0.tv_sec < 10);
    return circ_fn(user, t, p, d);
}

static void concurrency(cdist_query *q)
{
    enum { N = 400 };
    cdist_circle c = {{0, 0, 0}, {0, 0, 1}, 1.0}, other = {{0.5, 0.2, 0.3}, {0.6, 0, 0.8}, 0.7};
    circ_curve k = circ_curve_of(&c);
    cdist_curve cv = {waiting_fn, &k, -M_PI, M_PI};
    cdist_result *r = malloc(N * sizeof *r);
    cdist_query_set_curve_samples(q, 8);
    CHECK(cdist_query_set_threads(q, 2) == CDIST_OK, "2 threads");
    nseen = 0;
    CHECK(cdist_batch(q, CDIST_KIND_CURVE_CIRCLE, N, &cv, 0, &other, 0, r, NULL) == CDIST_OK, "waiting batch");
    CHECK(nseen >= 2, "only %d thread(s) evaluated the curves of a 2-thread batch", nseen);
    CHECK(r[0].distance == r[N - 1].distance, "broadcast entries agree");
    cdist_query_set_threads(q, 1);
    cdist_query_set_curve_samples(q, 512);
    free(r);
}

static void conventions(cdist_query *q)
{
    CHECK(cdist_kind_count() == 38, "kind count %d", cdist_kind_count());
    CHECK(!strcmp(cdist_kind_name(CDIST_KIND_CIRCLE_CIRCLE), "circle_circle"), "kind name");
    CHECK(!strcmp(cdist_kind_name(CDIST_KIND_BEZIER3_DISK), "bezier3_disk"), "kind name");
    CHECK(cdist_kind_name((cdist_kind)38) == NULL && cdist_kind_name((cdist_kind)-1) == NULL, "bad kind name");
    CHECK(cdist_kind_size_a(CDIST_KIND_CURVE_CIRCLE) == sizeof(cdist_curve), "size a");
    CHECK(cdist_kind_size_b(CDIST_KIND_SEGMENT_ARC) == sizeof(cdist_arc), "size b");
    CHECK(cdist_kind_size_a((cdist_kind)99) == 0 && cdist_kind_size_b((cdist_kind)99) == 0, "bad kind sizes");
    for (int k = 0; k < cdist_kind_count(); k++)
        CHECK(cdist_kind_name((cdist_kind)k) && cdist_kind_size_a((cdist_kind)k) && cdist_kind_size_b((cdist_kind)k),
              "kind %d", k);

    CHECK(cdist_query_get_threads(q) == 1 && cdist_query_get_threads(NULL) == 1, "default threads");
    CHECK(cdist_query_set_threads(q, 0) == CDIST_ERR_BAD_OPTION, "0 threads");
    CHECK(cdist_query_set_threads(q, 257) == CDIST_ERR_BAD_OPTION, "257 threads");
    CHECK(cdist_query_set_threads(NULL, 2) == CDIST_ERR_NULL_ARGUMENT, "NULL handle threads");
    CHECK(cdist_query_set_threads(q, 3) == CDIST_OK && cdist_query_get_threads(q) == 3, "3 threads");

    cdist_vec3 p[3] = {{1, 2, 3}, {0, 0, 0}, {4, 0, 0}};
    cdist_circle c = {{0, 0, 0}, {0, 0, 1}, 1.0};
    cdist_result r[3];
    cdist_status st[3];
    double d[3];
    /* NULL handle: outputs still filled */
    st[0] = st[1] = st[2] = CDIST_OK;
    CHECK(cdist_batch(NULL, CDIST_KIND_POINT_CIRCLE, 3, p, sizeof p[0], &c, 0, r, st) == CDIST_ERR_NULL_ARGUMENT,
          "NULL handle");
    CHECK(isnan(r[2].distance) && r[2].num_pairs == 0 && st[2] == CDIST_ERR_NULL_ARGUMENT, "NULL handle fills");
    d[1] = 0.0;
    CHECK(cdist_batch_distance(NULL, CDIST_KIND_POINT_CIRCLE, 3, p, sizeof p[0], &c, 0, d, st) ==
              CDIST_ERR_NULL_ARGUMENT && isnan(d[1]),
          "NULL handle, distance");
    /* NULL arrays */
    CHECK(cdist_batch(q, CDIST_KIND_POINT_CIRCLE, 3, NULL, sizeof p[0], &c, 0, r, st) == CDIST_ERR_NULL_ARGUMENT &&
              isnan(r[0].distance) && st[0] == CDIST_ERR_NULL_ARGUMENT,
          "NULL a");
    CHECK(cdist_batch(q, CDIST_KIND_POINT_CIRCLE, 3, p, sizeof p[0], NULL, 0, NULL, st) == CDIST_ERR_NULL_ARGUMENT &&
              st[1] == CDIST_ERR_NULL_ARGUMENT,
          "NULL b and results");
    CHECK(cdist_query_last_status(q) == CDIST_ERR_NULL_ARGUMENT && strlen(cdist_query_last_error(q)) > 0, "message");
    /* bad kind */
    CHECK(cdist_batch(q, (cdist_kind)77, 3, p, sizeof p[0], &c, 0, r, st) == CDIST_ERR_BAD_KIND &&
              st[0] == CDIST_ERR_BAD_KIND && isnan(r[1].distance),
          "bad kind");
    CHECK(cdist_batch_distance(q, (cdist_kind)-3, 3, p, sizeof p[0], &c, 0, d, st) == CDIST_ERR_BAD_KIND &&
              isnan(d[0]),
          "bad kind, distance");
    /* empty */
    CHECK(cdist_batch(q, CDIST_KIND_POINT_CIRCLE, 0, NULL, 0, NULL, 0, NULL, NULL) == CDIST_OK, "empty batch");
    CHECK(cdist_batch(NULL, CDIST_KIND_POINT_CIRCLE, 0, NULL, 0, NULL, 0, NULL, NULL) == CDIST_ERR_NULL_ARGUMENT,
          "empty batch, NULL handle");
    /* a good batch after a bad one: status and message cleared */
    CHECK(cdist_batch(q, CDIST_KIND_POINT_CIRCLE, 3, p, sizeof p[0], &c, 0, r, NULL) == CDIST_OK &&
              cdist_query_last_status(q) == CDIST_OK && cdist_query_last_error(q)[0] == '\0',
          "good batch clears the error");
    CHECK(fabs(r[2].distance - 3.0) <= 4 * DBL_EPSILON && r[1].equidistant, "values %g", r[2].distance);
    /* the circle-circle wrapper */
    cdist_circle cs[2] = {c, {{3, 0, 0}, {0, 0, 1}, 1.0}}, ct[2] = {cs[1], {{-5, 0, 0}, {0, 0, 1}, 1.0}};
    CHECK(cdist_circle_circle_batch(NULL, 2, cs, cs, r, st) == CDIST_ERR_NULL_ARGUMENT && isnan(r[0].distance) &&
              st[1] == CDIST_ERR_NULL_ARGUMENT,
          "wrapper, NULL handle fills");
    CHECK(cdist_circle_circle_batch(q, 2, cs, ct, r, st) == CDIST_OK && fabs(r[0].distance - 1.0) < 1e-15 &&
              fabs(r[1].distance - 6.0) < 1e-14,
          "wrapper %g %g", r[0].distance, r[1].distance);
    cdist_query_set_threads(q, 1);
}

int main(int argc, char **argv)
{
    test_rng = 88172645463325252ull;
    if (argc < 2) {
        fprintf(stderr, "usage: test_batch DIR...\n");
        return 2;
    }
    int first = 1;
    cdist_query *q = cdist_query_new();
    conventions(q);
    strides(q);
    concurrency(q);
    const char *sets[] = {"random", "hard"};
    for (int s = 0; s < 2; s++) {
        for (const cdq_kind *kd = cdq_kinds; kd->name; kd++)
            if (kd->batch_kind >= 0) run_file(q, argc - first, argv + first, kd->name, (cdist_kind)kd->batch_kind, sets[s]);
        for (size_t k = 0; k < sizeof curve_files / sizeof curve_files[0]; k++)
            run_file(q, argc - first, argv + first, curve_files[k].file, curve_files[k].kind, sets[s]);
    }
    cdist_query_free(q);
    return check_summary("batch");
}
