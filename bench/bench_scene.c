/* SPDX-License-Identifier: MIT */
/* Scene benchmarks.
 *   chain mail: a sheet of N tori in the 4-in-1 weave of examples/dask_chainmail.py (rows offset
 *     by half a spacing, tilted alternately, jitter of positions, tilts and radii); every pair
 *     with clearance <= 0.1 R. Build (add + tree) and query time, candidates answered by the
 *     exact query per reported pair, memory per object.
 *   moving: M tori of the sheet, K steps each moving every torus by a small random motion from
 *     its current pose; per step, update + query against a new scene (add + build) + query of
 *     the same poses (the first step, a plain query, alone; and steps 3..K, after the second
 *     made the scene's pair list).
 * Minimum of --reps runs; pairs are counted by a callback (the output array is the caller's
 * memory, not the scene's).
 *   bench_scene [--rings=N] [--moving=M] [--reps=R] [--steps=K] [--motion=S] [--threads=T] [--delta=D] [--wall] [--trace] */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "circledist.h"
#include "test_rand.h"

#define RADIUS 1.0
#define WIRE 0.11
#define SPACING_X 2.4
#define SPACING_Y 1.4
#define TILT (50.0 * M_PI / 180.0)
#define JITTER 0.03

static double gauss(double s)
{
    double u = rnd01(), v = rnd01();
    return s * sqrt(-2.0 * log(u + 1e-300)) * cos(2.0 * M_PI * v);
}

/* Times are CPU seconds of the process (all threads): on a machine shared with other jobs the
 * wall clock measures the load, not the code. --wall switches to the wall clock. */
static int use_wall;
static int trace; /* --trace: the scene's counters after each moving step of the first repeat */
static double now(void)
{
    struct timespec t;
    clock_gettime(use_wall ? CLOCK_MONOTONIC : CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static void sheet(cdist_torus *t, size_t n)
{
    size_t cols = (size_t)ceil(sqrt((double)n));
    for (size_t k = 0; k < n; k++) {
        size_t row = k / cols, col = k % cols;
        double s = row % 2 == 0 ? 1.0 : -1.0;
        cdist_vec3 c = {SPACING_X * ((double)col + 0.5 * (double)(row % 2)) + gauss(JITTER),
                        SPACING_Y * (double)row + gauss(JITTER), gauss(JITTER)};
        cdist_vec3 nn = {gauss(JITTER), s * sin(TILT) + gauss(JITTER), cos(TILT) + gauss(JITTER)};
        double l = sqrt(nn.x * nn.x + nn.y * nn.y + nn.z * nn.z);
        nn.x /= l, nn.y /= l, nn.z /= l;
        t[k] = (cdist_torus){{c, nn, RADIUS * (1.0 + gauss(JITTER / 3.0))}, WIRE};
    }
}

static int count_pairs(void *user, const cdist_scene_pair *p, size_t n)
{
    double *acc = user;
    for (size_t k = 0; k < n; k++) acc[0] += p[k].distance;
    acc[1] += (double)n;
    return 0;
}

static void fail(cdist_query *q, const char *what)
{
    fprintf(stderr, "%s: %s\n", what, cdist_query_last_error(q));
    exit(1);
}

int main(int argc, char **argv)
{
    size_t rings = 1000000, moving = 100000;
    int reps = 3, threads = 1, steps = 8;
    double motion = 0.01, delta = 0.1 * RADIUS;
    for (int a = 1; a < argc; a++) {
        if (!strncmp(argv[a], "--rings=", 8)) rings = strtoul(argv[a] + 8, NULL, 10);
        else if (!strncmp(argv[a], "--moving=", 9)) moving = strtoul(argv[a] + 9, NULL, 10);
        else if (!strncmp(argv[a], "--reps=", 7)) reps = atoi(argv[a] + 7);
        else if (!strncmp(argv[a], "--steps=", 8)) steps = atoi(argv[a] + 8);
        else if (!strncmp(argv[a], "--motion=", 9)) motion = atof(argv[a] + 9);
        else if (!strncmp(argv[a], "--threads=", 10)) threads = atoi(argv[a] + 10);
        else if (!strncmp(argv[a], "--delta=", 8)) delta = atof(argv[a] + 8) * RADIUS;
        else if (!strcmp(argv[a], "--wall")) use_wall = 1;
        else if (!strcmp(argv[a], "--trace")) trace = 1;
        else {
            fprintf(stderr, "usage: %s [--rings=N] [--moving=M] [--reps=R] [--steps=K] [--motion=S] [--threads=T] [--delta=D] [--wall] [--trace]\n", argv[0]);
            return 2;
        }
    }
    cdist_query *q = cdist_query_new();
    if (cdist_query_set_threads(q, threads)) fail(q, "threads");

    /* ---- chain mail ---- */
    cdist_torus *t = malloc(rings * sizeof *t);
    sheet(t, rings);
    double best_build = INFINITY, best_query = INFINITY, acc[2] = {0, 0};
    cdist_scene_stats st;
    for (int r = 0; r < reps; r++) {
        double t0 = now();
        cdist_scene *s = cdist_scene_new();
        if (cdist_scene_add(q, s, CDIST_SCENE_TORUS, rings, t, sizeof *t, NULL, NULL)) fail(q, "add");
        if (cdist_scene_rebuild(q, s)) fail(q, "build");
        double t1 = now();
        acc[0] = acc[1] = 0;
        if (cdist_scene_pairs_within_fn(q, s, delta, count_pairs, acc, NULL)) fail(q, "query");
        double t2 = now();
        best_build = fmin(best_build, t1 - t0);
        best_query = fmin(best_query, t2 - t1);
        cdist_scene_get_stats(s, &st);
        cdist_scene_free(s);
    }
    printf("chain mail: %zu tori, clearance <= %.2f R, %d thread(s), min of %d, %s seconds\n", rings, delta, threads,
           reps, use_wall ? "wall" : "CPU");
    printf("  build %.3f s + query %.3f s = %.3f s\n", best_build, best_query, best_build + best_query);
    printf("  pairs %.0f, box pairs %zu, past the bounds %zu (%.3f per pair), exact queries %zu (%.3f per pair), "
           "nodes %zu\n", acc[1], st.box_pairs, st.screened, (double)st.screened / fmax(1.0, acc[1]), st.candidates,
           (double)st.candidates / fmax(1.0, acc[1]), st.nodes);
    printf("  scene memory %.1f bytes per object (output not included)\n", (double)st.bytes / (double)rings);
    free(t);

    /* ---- moving ---- */
    if (moving > 0) {
        cdist_torus *m = malloc(moving * sizeof *m), *m2 = malloc(moving * sizeof *m2);
        double best_upd = INFINITY, best_uq = INFINITY, best_reb = INFINITY, best_rq = INFINITY;
        double best_first = INFINITY, best_first_reb = INFINITY, best_late = INFINITY, best_late_reb = INFINITY;
        size_t lists = 0;
        for (int r = 0; r < reps; r++) {
            sheet(m, moving);
            cdist_scene *s = cdist_scene_new();
            cdist_scene_add(q, s, CDIST_SCENE_TORUS, moving, m, sizeof *m, NULL, NULL);
            if (cdist_scene_pairs_within_fn(q, s, delta, count_pairs, acc, NULL)) fail(q, "moving query");
            double upd = 0, uq = 0, reb = 0, rq = 0, first = 0, first_reb = 0, late = 0, late_reb = 0;
            for (int step = 0; step < steps; step++) {
                /* a small rigid-ish motion from the current poses: S R in position (each axis, 1%
                 * by default), S in the normal */
                for (size_t k = 0; k < moving; k++) {
                    m2[k] = m[k];
                    m2[k].circle.center.x += gauss(motion), m2[k].circle.center.y += gauss(motion);
                    m2[k].circle.center.z += gauss(motion);
                    cdist_vec3 *n = &m2[k].circle.normal;
                    n->x += gauss(motion), n->y += gauss(motion), n->z += gauss(motion);
                    double l = sqrt(n->x * n->x + n->y * n->y + n->z * n->z);
                    n->x /= l, n->y /= l, n->z /= l;
                }
                double t0 = now();
                if (cdist_scene_update(q, s, moving, NULL, CDIST_SCENE_TORUS, m2, sizeof *m2, NULL)) fail(q, "update");
                double t1 = now();
                double a1[2] = {0, 0}, a2[2] = {0, 0};
                if (cdist_scene_pairs_within_fn(q, s, delta, count_pairs, a1, NULL)) fail(q, "query after update");
                double t2 = now();
                if (trace && r == 0) {
                    cdist_scene_stats ts;
                    cdist_scene_get_stats(s, &ts);
                    printf("  step %d: box pairs %zu, past the bounds %zu, exact queries %zu, reported %zu, "
                           "update + query %.4f s\n", step + 1, ts.box_pairs, ts.screened, ts.candidates, ts.reported,
                           t2 - t0);
                }
                cdist_scene *s2 = cdist_scene_new();
                cdist_scene_add(q, s2, CDIST_SCENE_TORUS, moving, m2, sizeof *m2, NULL, NULL);
                if (cdist_scene_rebuild(q, s2)) fail(q, "rebuild");
                double t3 = now();
                if (cdist_scene_pairs_within_fn(q, s2, delta, count_pairs, a2, NULL)) fail(q, "query after rebuild");
                double t4 = now();
                if (a1[1] != a2[1] || a1[0] != a2[0]) {
                    fprintf(stderr, "moving: update and rebuild disagree (%.0f vs %.0f pairs)\n", a1[1], a2[1]);
                    return 1;
                }
                cdist_scene_free(s2);
                memcpy(m, m2, moving * sizeof *m);
                upd += t1 - t0, uq += t2 - t1, reb += t3 - t2, rq += t4 - t3;
                if (step == 0) first = t2 - t0, first_reb = t4 - t2;
                if (step >= 2) late += t2 - t0, late_reb += t4 - t2;
            }
            best_upd = fmin(best_upd, upd / steps);
            best_uq = fmin(best_uq, uq / steps);
            best_reb = fmin(best_reb, reb / steps);
            best_rq = fmin(best_rq, rq / steps);
            best_first = fmin(best_first, first);
            best_first_reb = fmin(best_first_reb, first_reb);
            if (steps > 2) best_late = fmin(best_late, late / (steps - 2)), best_late_reb = fmin(best_late_reb, late_reb / (steps - 2));
            cdist_scene_get_stats(s, &st);
            lists = st.rebuilds;
            cdist_scene_free(s);
        }
        (void)lists;
        printf("moving: %zu tori, %d steps each moving every torus ~%g R, mean per step, min of %d\n", moving, steps,
               motion, reps);
        printf("  update %.4f s + query %.4f s = %.4f s (%zu refits, %zu rebuilds)\n", best_upd, best_uq,
               best_upd + best_uq, st.refits, st.rebuilds);
        printf("  rebuild %.4f s + query %.4f s = %.4f s\n", best_reb, best_rq, best_reb + best_rq);
        printf("  update + query / (rebuild + query) = %.1f%%; update / rebuild = %.1f%%\n",
               100.0 * (best_upd + best_uq) / (best_reb + best_rq), 100.0 * best_upd / best_reb);
        printf("  first step alone: update + query %.4f s, rebuild + query %.4f s (%.1f%%)\n", best_first,
               best_first_reb, 100.0 * best_first / best_first_reb);
        if (steps > 2)
            printf("  steps 3..%d (the second makes the pair list): update + query %.4f s, rebuild + query %.4f s "
                   "(%.1f%%)\n", steps, best_late, best_late_reb, 100.0 * best_late / best_late_reb);
        free(m);
        free(m2);
    }
    cdist_query_free(q);
    return 0;
}
