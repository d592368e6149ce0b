/* SPDX-License-Identifier: MIT */
/* The handle's in-use flag (issue 10 item 9) and non-finite hardening (issue 10 item 1).
 * Built against the internal library: the flag is set by hand for the deterministic checks.
 *  - a call entering a handle another call holds gets CDIST_ERR_HANDLE_BUSY and leaves the
 *    handle (status, message) untouched; setters too;
 *  - two threads hammering one handle see BUSY or the single-threaded answer, never another;
 *  - the entry path never returns CDIST_OK with a non-finite distance;
 *  - subnormal normals and directions: no NaN vectors, no "nan" in messages. */
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <string.h>

#include "check.h"
#include "internal.h"

#define NQ 64

static cdist_vec3 pts[NQ];
static cdist_line lines[NQ];
static cdist_circle circs[NQ];
static cdist_circle circs2[NQ];
static double want_pc[NQ], want_lc[NQ], want_cc[NQ], want_cd[NQ], want_dd[NQ];
static cdist_query *shared;
static atomic_int wrong, busy_seen, ok_seen, ready, point_busy;

static void *hammer(void *arg)
{
    int id = (int)(size_t)arg;
    cdist_result r;
    atomic_fetch_add(&ready, 1);
    while (atomic_load(&ready) < 2) {
    } /* start together */
    for (int it = 0; it < 100000; it++) {
        int i = (it * 7 + id) % NQ;
        cdist_status st;
        double want;
        int kind = (it + id) % 6;
        if (kind == 0) {
            st = cdist_point_circle(shared, &pts[i], &circs[i], &r);
            want = want_pc[i];
        } else if (kind == 1) {
            st = cdist_line_circle(shared, &lines[i], &circs[i], &r);
            want = want_lc[i];
        } else if (kind == 3) {
            /* the circles family: a long call, so the other thread often finds the flag taken */
            st = cdist_circle_circle(shared, &circs[i], &circs2[i], &r);
            want = want_cc[i];
        } else if (kind == 4) {
            st = cdist_circle_disk(shared, &circs[i], &circs2[i], &r);
            want = want_cd[i];
        } else if (kind == 5) {
            st = cdist_disk_disk(shared, &circs[i], &circs2[i], &r);
            want = want_dd[i];
        } else {
            st = cdist_query_set_method(shared, CDIST_METHOD_AUTO);
            if (st != CDIST_OK && st != CDIST_ERR_HANDLE_BUSY) atomic_fetch_add(&wrong, 1);
            continue;
        }
        if (st == CDIST_ERR_HANDLE_BUSY) {
            atomic_fetch_add(&busy_seen, 1);
            if (kind == 0) atomic_fetch_add(&point_busy, 1);
            if (!isnan(r.distance) || r.num_pairs != 0) atomic_fetch_add(&wrong, 1);
        } else if (st == CDIST_OK && r.distance == want) {
            atomic_fetch_add(&ok_seen, 1);
        } else {
            atomic_fetch_add(&wrong, 1);
        }
    }
    return NULL;
}

/* Split mode: thread 0 runs the circles family until 20000 of its calls answered, thread 1 runs
 * point-circle as long as thread 0 runs (so the two overlap whatever the scheduling). */
static atomic_int circles_done;
static void *hammer_split(void *arg)
{
    int id = (int)(size_t)arg, answered = 0;
    cdist_result r;
    atomic_fetch_add(&ready, 1);
    while (atomic_load(&ready) < 2) {
    }
    for (int it = 0; id == 0 ? answered < 20000 : !atomic_load(&circles_done); it++) {
        int i = (it * 7 + id) % NQ, kind = id == 0 ? it % 3 : 3;
        cdist_status st;
        double want;
        if (kind == 0) {
            st = cdist_circle_circle(shared, &circs[i], &circs2[i], &r);
            want = want_cc[i];
        } else if (kind == 1) {
            st = cdist_circle_disk(shared, &circs[i], &circs2[i], &r);
            want = want_cd[i];
        } else if (kind == 2) {
            st = cdist_disk_disk(shared, &circs[i], &circs2[i], &r);
            want = want_dd[i];
        } else {
            st = cdist_point_circle(shared, &pts[i], &circs[i], &r);
            want = want_pc[i];
        }
        if (st == CDIST_ERR_HANDLE_BUSY) {
            if (kind == 3) atomic_fetch_add(&point_busy, 1);
            if (!isnan(r.distance) || r.num_pairs != 0) atomic_fetch_add(&wrong, 1);
        } else if (st == CDIST_OK && r.distance == want) {
            answered++;
        } else {
            atomic_fetch_add(&wrong, 1);
        }
    }
    if (id == 0) atomic_store(&circles_done, 1);
    return NULL;
}

static void check_threads(void)
{
    cdist_query *q = cdist_query_new();
    srand(7);
    for (int i = 0; i < NQ; i++) {
        pts[i] = tv(srand1() * 3, srand1() * 3, srand1() * 3);
        lines[i].origin = tv(srand1() * 3, srand1() * 3, srand1() * 3);
        lines[i].direction = rand_unit();
        circs[i].center = tv(srand1(), srand1(), srand1());
        circs[i].normal = rand_unit();
        circs[i].radius = 0.5 + urand();
        cdist_result r;
        CHECK(cdist_point_circle(q, &pts[i], &circs[i], &r) == CDIST_OK, "pc %d", i);
        want_pc[i] = r.distance;
        CHECK(cdist_line_circle(q, &lines[i], &circs[i], &r) == CDIST_OK, "lc %d", i);
        want_lc[i] = r.distance;
        circs2[i].center = tv(srand1(), srand1(), srand1());
        circs2[i].normal = rand_unit();
        circs2[i].radius = 0.5 + urand();
        CHECK(cdist_circle_circle(q, &circs[i], &circs2[i], &r) == CDIST_OK, "cc %d", i);
        want_cc[i] = r.distance;
        /* independent of the code under test: the circle-circle distance by dense sampling of
         * the first circle against the closed-form point-circle distance */
        double brute = INFINITY;
        for (int k = 0; k < 20000; k++) {
            cdist_vec3 x;
            cdist_circle_point(&circs[i], 2 * M_PI * k / 20000, &x);
            cdist_result rp;
            cdist_point_circle(q, &x, &circs2[i], &rp);
            brute = fmin(brute, rp.distance);
        }
        CHECK(want_cc[i] <= brute + 1e-14 && want_cc[i] >= brute - 1e-5, "cc %d: %.17g vs sampled %.17g", i, want_cc[i],
              brute);
        cdist_status sc = cdist_circle_disk(q, &circs[i], &circs2[i], &r);
        CHECK(sc == CDIST_OK && r.distance <= want_cc[i] + 1e-14, "cd %d: %d %.17g %.17g", i, (int)sc, r.distance, want_cc[i]);
        want_cd[i] = r.distance;
        CHECK(cdist_disk_disk(q, &circs[i], &circs2[i], &r) == CDIST_OK && r.distance <= want_cd[i] + 1e-14, "dd %d", i);
        want_dd[i] = r.distance;
    }
    cdist_query_free(q);
    shared = cdist_query_new();
    pthread_t th[2];
    int started = 0;
    for (int t = 0; t < 2; t++)
        if (pthread_create(&th[t], NULL, hammer, (void *)(size_t)t) == 0) started++;
    CHECK(started == 2, "could not start the threads");
    for (int t = 0; t < started; t++) pthread_join(th[t], NULL);
    CHECK(atomic_load(&wrong) == 0, "%d wrong answers from two threads on one handle", atomic_load(&wrong));
    CHECK(atomic_load(&ok_seen) > 0, "no answer at all");
    printf("threads: %d answers, %d busy, %d wrong\n", atomic_load(&ok_seen), atomic_load(&busy_seen),
           atomic_load(&wrong));
    /* the flag is free again */
    cdist_result r;
    CHECK(cdist_point_circle(shared, &pts[0], &circs[0], &r) == CDIST_OK && r.distance == want_pc[0], "after threads");
    /* The circle queries hold the flag too: point queries running beside nothing but circle
     * queries are turned away (they would not be if the circles bypassed the flag). */
    atomic_store(&ready, 0);
    atomic_store(&point_busy, 0);
    started = 0;
    for (int t = 0; t < 2; t++)
        if (pthread_create(&th[t], NULL, hammer_split, (void *)(size_t)t) == 0) started++;
    CHECK(started == 2, "could not start the threads");
    for (int t = 0; t < started; t++) pthread_join(th[t], NULL);
    CHECK(atomic_load(&wrong) == 0, "%d wrong answers beside the circle queries", atomic_load(&wrong));
    CHECK(atomic_load(&point_busy) > 0, "no point query was turned away by a running circle query");
    printf("circles beside points: %d point queries turned away, %d wrong\n", atomic_load(&point_busy),
           atomic_load(&wrong));
    cdist_query_free(shared);
}

static void check_busy_flag(void)
{
    cdist_query *q = cdist_query_new();
    cdist_result r;
    cdist_vec3 p = {1, 2, 3};
    cdist_circle c = {{0, 0, 0}, {0, 0, 1}, 1};
    CHECK(cdist_query_set_method(q, (cdist_method)9) == CDIST_ERR_BAD_OPTION, "bad method");
    char before[CD_MESSAGE_LEN];
    strcpy(before, cdist_query_last_error(q));
    atomic_store(&q->busy, 1); /* as if another thread were inside */
    CHECK(cdist_point_circle(q, &p, &c, &r) == CDIST_ERR_HANDLE_BUSY, "busy point query");
    CHECK(isnan(r.distance) && r.num_pairs == 0, "busy result is the error state");
    cdist_line l = {{0, 0, 5}, {1, 0, 0}};
    CHECK(cdist_segment_disk(q, &(cdist_segment){{0, 0, 1}, {1, 0, 1}}, &c, &r) == CDIST_ERR_HANDLE_BUSY, "busy sd");
    CHECK(cdist_line_circle(q, &l, &c, &r) == CDIST_ERR_HANDLE_BUSY, "busy lc");
    cdist_circle c2 = {{0, 0, 2}, {1, 0, 0}, 1};
    r.distance = 1.0;
    CHECK(cdist_circle_circle(q, &c, &c2, &r) == CDIST_ERR_HANDLE_BUSY && isnan(r.distance) && r.num_pairs == 0,
          "busy cc");
    CHECK(cdist_circle_disk(q, &c, &c2, &r) == CDIST_ERR_HANDLE_BUSY, "busy cd");
    CHECK(cdist_disk_disk(q, &c, &c2, &r) == CDIST_ERR_HANDLE_BUSY, "busy dd");
    CHECK(cdist_query_set_unit_tolerance(q, 1e-3) == CDIST_ERR_HANDLE_BUSY, "busy setter");
    CHECK(cdist_query_last_status(q) == CDIST_ERR_BAD_OPTION && !strcmp(cdist_query_last_error(q), before),
          "the busy calls touched the handle: %d '%s'", (int)cdist_query_last_status(q), cdist_query_last_error(q));
    CHECK(cdist_query_get_unit_tolerance(q) == CD_DEFAULT_UNIT_TOL, "busy setter changed the option");
    atomic_store(&q->busy, 0);
    CHECK(cdist_point_circle(q, &p, &c, &r) == CDIST_OK && fabs(r.distance - sqrt(5.0 - 2 * sqrt(5.0) + 1 + 9)) < 1e-15,
          "free again: %.17g", r.distance);
    CHECK(cdist_query_last_status(q) == CDIST_OK, "status after the free call");
    cdist_query_free(q);
}

static void check_final_guard(void)
{
    cdist_query *q = cdist_query_new();
    cdist_result r;
    CHECK(cdist__enter(q, &r) == CDIST_OK, "enter");
    r.distance = NAN; /* a core that went wrong */
    r.num_pairs = 1;
    cdist_status st = cdist__leave(q, &r, CDIST_OK, CDIST_METHOD_AUTO);
    CHECK(st == CDIST_ERR_INTERNAL && r.num_pairs == 0 && cdist_query_last_status(q) == CDIST_ERR_INTERNAL &&
              strlen(cdist_query_last_error(q)) > 0,
          "non-finite distance let through: status %d", (int)st);
    CHECK(atomic_load(&q->busy) == 0, "flag released after a failure");
    CHECK(cdist__enter(q, &r) == CDIST_OK, "enter");
    r.distance = INFINITY;
    CHECK(cdist__leave(q, &r, CDIST_OK, CDIST_METHOD_AUTO) == CDIST_ERR_INTERNAL, "infinite distance let through");
    cdist_query_free(q);
}

static int finite_unit(cdist_vec3 v) { return isfinite(v.x) && isfinite(v.y) && isfinite(v.z) && fabs(tdist(v, tv(0, 0, 0)) - 1) < 1e-15; }

static void check_subnormal(void)
{
    cdist_circle c = {{1, 2, 3}, {0, 0, 1e-310}, 2};
    cdist_vec3 u, v, p;
    cdist_status st = cdist_circle_basis(&c, &u, &v);
    CHECK(st == CDIST_OK && finite_unit(u) && finite_unit(v) && fabs(u.z) < 1e-15 && fabs(v.z) < 1e-15,
          "basis of normal (0, 0, 1e-310): status %d u (%g %g %g)", (int)st, u.x, u.y, u.z);
    st = cdist_circle_point(&c, 0.5, &p);
    CHECK(st == CDIST_OK && fabs(tdist(p, c.center) - 2) < 1e-15 && p.z == 3, "circle point: status %d (%g %g %g)",
          (int)st, p.x, p.y, p.z);
    cdist_query *q = cdist_query_new();
    cdist_result r;
    cdist_vec3 pt = {0, 0, 0};
    st = cdist_point_circle(q, &pt, &c, &r);
    CHECK(st == CDIST_ERR_NOT_UNIT && isnan(r.distance) && !strstr(cdist_query_last_error(q), "nan"),
          "pc with normal 1e-310: status %d '%s'", (int)st, cdist_query_last_error(q));
    cdist_line l = {{0, 0, 5}, {1e-310, 0, 0}};
    cdist_circle c1 = {{0, 0, 0}, {0, 0, 1}, 1};
    st = cdist_line_circle(q, &l, &c1, &r);
    CHECK(st == CDIST_ERR_NOT_UNIT && !strstr(cdist_query_last_error(q), "nan"), "line direction 1e-310: %d '%s'",
          (int)st, cdist_query_last_error(q));
    /* any length accepted: the direction is still used correctly */
    cdist_query_set_unit_tolerance(q, 2.0);
    st = cdist_line_circle(q, &l, &c1, &r);
    CHECK(st == CDIST_OK && r.distance == 5.0, "line direction 1e-310 accepted: %d %.17g", (int)st,
          r.distance);
    st = cdist_line_disk(q, &l, &c1, &r);
    CHECK(st == CDIST_OK && r.distance == 5.0, "line-disk direction 1e-310: %d %.17g", (int)st, r.distance);
    st = cdist_point_circle(q, &pt, &c, &r);
    CHECK(st == CDIST_OK && fabs(r.distance - sqrt(9 + (sqrt(5.0) - 2) * (sqrt(5.0) - 2))) < 1e-14,
          "normal 1e-310 accepted: %d %.17g", (int)st, r.distance);
    /* a segment with subnormal extent */
    cdist_segment s = {{0, 0, 5}, {4e-320, 0, 5}};
    st = cdist_segment_circle(q, &s, &c1, &r);
    CHECK(st == CDIST_OK && fabs(r.distance - sqrt(26.0)) < 1e-14, "tiny segment: %d %.17g", (int)st, r.distance);
    cdist_query_free(q);
}

int main(void)
{
    check_busy_flag();
    check_final_guard();
    check_subnormal();
    check_threads();
    return check_summary("test_handle");
}
