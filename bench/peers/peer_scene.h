/* SPDX-License-Identifier: MIT */
/* The peer benches' scenes (spheres or capsules on a jittered grid: no two overlap, so every
 * library's distance means the same) and our side of each comparison: a cdist_scene, all pairs
 * within delta and the closest pair. Times are CPU seconds of the process. */
#ifndef PEER_SCENE_H
#define PEER_SCENE_H

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "circledist.h"
#include "test_rand.h"

typedef struct peer_obj {
    int capsule;
    cdist_vec3 p0, p1; /* a sphere: p0 == p1 */
    double r;
} peer_obj;

#define PEER_SPACING 2.8

static double peer_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* n objects on a cube grid of spacing 2.8, centres jittered by up to 0.3 per axis: spheres of
 * radius 0.3..0.6, or capsules of length 0.5..1.5 and radius 0.15..0.3 in random directions
 * (extent from the centre <= 1.05, so neighbours never overlap). */
static void peer_generate(peer_obj *o, size_t n, int capsules)
{
    size_t side = (size_t)ceil(cbrt((double)n));
    for (size_t k = 0; k < n; k++) {
        size_t x = k % side, y = (k / side) % side, z = k / (side * side);
        cdist_vec3 c = {PEER_SPACING * (double)x + 0.6 * (rnd01() - 0.5), PEER_SPACING * (double)y + 0.6 * (rnd01() - 0.5),
                        PEER_SPACING * (double)z + 0.6 * (rnd01() - 0.5)};
        o[k].capsule = capsules;
        if (!capsules) {
            o[k].p0 = o[k].p1 = c;
            o[k].r = 0.3 + 0.3 * rnd01();
        } else {
            cdist_vec3 d = rnd_unit_vec();
            double h = 0.5 * (0.5 + rnd01());
            o[k].p0 = (cdist_vec3){c.x - h * d.x, c.y - h * d.y, c.z - h * d.z};
            o[k].p1 = (cdist_vec3){c.x + h * d.x, c.y + h * d.y, c.z + h * d.z};
            o[k].r = 0.15 + 0.15 * rnd01();
        }
    }
}

static int peer_count(void *user, const cdist_scene_pair *p, size_t n)
{
    (void)p;
    *(size_t *)user += n;
    return 0;
}

/* Ours: build + all pairs within delta, and build + closest pair (CPU seconds, pairs, distance). */
static void peer_ours(const peer_obj *o, size_t n, double delta, double *t_within, size_t *pairs, double *t_closest,
                      double *closest)
{
    cdist_query *q = cdist_query_new();
    void *arr = malloc(n * sizeof(cdist_capsule));
    int capsules = n > 0 && o[0].capsule;
    for (size_t k = 0; k < n; k++) {
        if (capsules) ((cdist_capsule *)arr)[k] = (cdist_capsule){{o[k].p0, o[k].p1}, o[k].r};
        else ((cdist_sphere *)arr)[k] = (cdist_sphere){o[k].p0, o[k].r};
    }
    cdist_scene_kind kind = capsules ? CDIST_SCENE_CAPSULE : CDIST_SCENE_SPHERE;
    size_t size = capsules ? sizeof(cdist_capsule) : sizeof(cdist_sphere);
    double t0 = peer_now();
    cdist_scene *s = cdist_scene_new();
    cdist_scene_add(q, s, kind, n, arr, (ptrdiff_t)size, NULL, NULL);
    *pairs = 0;
    if (cdist_scene_pairs_within_fn(q, s, delta, peer_count, pairs, NULL))
        fprintf(stderr, "ours: %s\n", cdist_query_last_error(q));
    *t_within = peer_now() - t0;
    cdist_scene_free(s);
    t0 = peer_now();
    s = cdist_scene_new();
    cdist_scene_add(q, s, kind, n, arr, (ptrdiff_t)size, NULL, NULL);
    cdist_scene_pair best;
    if (cdist_scene_closest_pair(q, s, &best)) fprintf(stderr, "ours: %s\n", cdist_query_last_error(q));
    *t_closest = peer_now() - t0;
    *closest = best.distance;
    cdist_scene_free(s);
    free(arr);
    cdist_query_free(q);
}

#endif
