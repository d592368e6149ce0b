/* SPDX-License-Identifier: MIT */
/* No allocation inside a batch once the handle is set up (threads included).
 * Method: this executable defines malloc, calloc, realloc, free and the aligned allocators; by ELF
 * symbol interposition they also serve the shared library's (and GSL's) calls. They count and
 * forward to glibc's __libc_* entry points. Built only without sanitizers (which interpose the
 * allocator themselves). */
#include <math.h>
#include <stdatomic.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "circle_curve.h"
#include "circledist.h"

extern void *__libc_malloc(size_t);
extern void *__libc_calloc(size_t, size_t);
extern void *__libc_realloc(void *, size_t);
extern void *__libc_memalign(size_t, size_t);
extern void __libc_free(void *);

static atomic_long allocations;

void *malloc(size_t n)
{
    atomic_fetch_add(&allocations, 1);
    return __libc_malloc(n);
}
void *calloc(size_t n, size_t m)
{
    atomic_fetch_add(&allocations, 1);
    return __libc_calloc(n, m);
}
void *realloc(void *p, size_t n)
{
    atomic_fetch_add(&allocations, 1);
    return __libc_realloc(p, n);
}
void free(void *p)
{
    if (p) atomic_fetch_add(&allocations, 1);
    __libc_free(p);
}
void *memalign(size_t a, size_t n)
{
    atomic_fetch_add(&allocations, 1);
    return __libc_memalign(a, n);
}
void *aligned_alloc(size_t a, size_t n) { return memalign(a, n); }
int posix_memalign(void **p, size_t a, size_t n)
{
    *p = memalign(a, n);
    return *p ? 0 : 12;
}

enum { N = 500 };
static cdist_vec3 pts[N];
static cdist_circle circ[N];
static cdist_line lin[N];
static cdist_arc arcs[N];
static cdist_helix hel[N];
static cdist_curve curv[N];
static circ_curve cc[N];
static cdist_result res[N];
static double dist[N];
static cdist_status st[N];
static cdist_torus tori[N];
static cdist_contact contacts[N];
static cdist_grad grads[N];

static int on_progress(void *user, size_t done, size_t total)
{
    (void)total;
    *(size_t *)user = done;
    return 0;
}

static void batches(cdist_query *q, const char *what)
{
    static const struct {
        cdist_kind k;
        const void *a;
        size_t sa;
    } runs[] = {
        {CDIST_KIND_POINT_CIRCLE, pts, sizeof pts[0]}, {CDIST_KIND_POINT_DISK, pts, sizeof pts[0]},
        {CDIST_KIND_LINE_CIRCLE, lin, sizeof lin[0]},  {CDIST_KIND_LINE_DISK, lin, sizeof lin[0]},
        {CDIST_KIND_CIRCLE_CIRCLE, circ, sizeof circ[0]}, {CDIST_KIND_CIRCLE_DISK, circ, sizeof circ[0]},
        {CDIST_KIND_ARC_CIRCLE, arcs, sizeof arcs[0]}, {CDIST_KIND_HELIX_DISK, hel, sizeof hel[0]},
        {CDIST_KIND_CURVE_CIRCLE, curv, sizeof curv[0]},
    };
    for (size_t i = 0; i < sizeof runs / sizeof runs[0]; i++) {
        /* circles shifted by one against each other */
        long before = atomic_load(&allocations);
        cdist_status s1 = cdist_batch(q, runs[i].k, N, runs[i].a, (ptrdiff_t)runs[i].sa, circ + 1, 0,
                                      res, st);
        cdist_status s2 = cdist_batch_distance(q, runs[i].k, N - 1, runs[i].a, (ptrdiff_t)runs[i].sa, circ + 1,
                                               sizeof circ[0], dist, st);
        long after = atomic_load(&allocations);
        CHECK(after == before, "%s, %s: %ld allocations inside the batch", what, cdist_kind_name(runs[i].k),
              after - before);
        CHECK(s1 == CDIST_OK && s2 == CDIST_OK && isfinite(res[N - 1].distance) && isfinite(dist[N - 2]),
              "%s, %s: %s %s", what, cdist_kind_name(runs[i].k), cdist_status_name(s1), cdist_status_name(s2));
    }
    /* contacts, gradients, signed distances, with progress reports */
    size_t reported = 0;
    cdist_query_set_progress(q, on_progress, &reported, 100);
    long before_c = atomic_load(&allocations);
    cdist_status c1 = cdist_batch_contact(q, CDIST_KIND_TORUS_TORUS, N, tori, sizeof tori[0], tori + 1, 0, contacts, st);
    cdist_status c2 = cdist_batch_grad(q, CDIST_KIND_TORUS_TORUS, N, tori, sizeof tori[0], tori + 1, 0, contacts, grads, st);
    cdist_status c3 = cdist_batch_grad(q, CDIST_KIND_CIRCLE_DISK, N, circ, sizeof circ[0], circ + 1, 0, res, grads, st);
    cdist_status c4 = cdist_batch_distance(q, CDIST_KIND_TORUS_TORUS, N, tori, sizeof tori[0], tori + 1, 0, dist, st);
    CHECK(atomic_load(&allocations) == before_c, "%s, contact and gradient batches: %ld allocations", what,
          atomic_load(&allocations) - before_c);
    CHECK(!c1 && !c2 && !c3 && !c4 && reported == N && isfinite(contacts[N - 1].distance), "%s: %s %s %s %s, %zu reported",
          what, cdist_status_name(c1), cdist_status_name(c2), cdist_status_name(c3), cdist_status_name(c4), reported);
    cdist_query_set_progress(q, NULL, NULL, 0);
    /* a batch with bad entries formats messages: still no allocation */
    circ[5].radius = -1.0;
    long before = atomic_load(&allocations);
    cdist_status s = cdist_batch(q, CDIST_KIND_CIRCLE_CIRCLE, N - 1, circ, sizeof circ[0], circ + 1, sizeof circ[0],
                                 res, st);
    CHECK(atomic_load(&allocations) == before && s == CDIST_ERR_NEGATIVE_RADIUS, "%s, bad entries: %ld allocations",
          what, atomic_load(&allocations) - before);
    circ[5].radius = 1.0;
}

int main(void)
{
    for (int i = 0; i < N; i++) {
        double t = 0.731 * i;
        pts[i] = tv(cos(t), sin(1.3 * t), 0.2 * sin(t));
        circ[i] = (cdist_circle){{0.3 * cos(t), 0.2 * sin(t), 0.1 * cos(2 * t)}, {sin(t) * 0.6, 0.8, cos(t) * 0.6}, 1.0};
        lin[i] = (cdist_line){{sin(t), 0.5, cos(t)}, {0.6, 0.0, 0.8}};
        arcs[i] = (cdist_arc){circ[i], {1, 0, 0}, -1.0, 0.5 + 0.001 * i};
        hel[i] = (cdist_helix){{0, 0, 0}, {0, 0, 1}, {1, 0, 0}, 0.5, 0.3, 0.0, 6.0};
        tori[i] = (cdist_torus){circ[i], 0.05};
    }
    for (int i = 0; i < N; i++) { /* after every circle is set (circ[i + 3] is read) */
        cc[i] = circ_curve_of(&circ[(i + 3) % N]);
        curv[i] = (cdist_curve){circ_fn, &cc[i], -M_PI, M_PI};
    }
    long before = atomic_load(&allocations);
    cdist_query *q = cdist_query_new();
    /* the counter sees the library's allocations (else this test could not fail); under valgrind,
     * whose own allocator replaces every malloc, the test cannot count and is skipped */
    if (atomic_load(&allocations) == before) {
        const char *pre = getenv("LD_PRELOAD");
        if (pre && strstr(pre, "vgpreload")) {
            printf("SKIP: valgrind replaces the allocator; nothing to count\n");
            cdist_query_free(q);
            return 77;
        }
    }
    CHECK(atomic_load(&allocations) > before, "the interposed malloc did not see cdist_query_new");
    cdist_query_set_curve_samples(q, 64);
    batches(q, "1 thread");
    CHECK(cdist_query_set_threads(q, 2) == CDIST_OK, "2 threads");
    batches(q, "2 threads");
    /* options changed after the workers exist: the setters size the workers' workspaces */
    CHECK(cdist_query_set_curve_samples(q, 2000) == CDIST_OK && cdist_query_set_method(q, CDIST_METHOD_POLYNOMIAL) == 0,
          "options");
    batches(q, "2 threads, more samples");
    CHECK(cdist_query_set_threads(q, 5) == CDIST_OK, "5 threads");
    batches(q, "5 threads");
    cdist_query_free(q);
    return check_summary("batch-alloc");
}
