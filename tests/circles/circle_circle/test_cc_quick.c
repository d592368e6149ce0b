/* SPDX-License-Identifier: MIT */
/* The single circle-circle query's certified search (cdist__cc_quick: the batch kernel's search
 * with the angles in lanes), each instruction set the machine has, against the root-isolation
 * scan of the same frame (cdist__cc_scan, which answers whatever the search leaves):
 *   test_cc_quick DIR   (reads DIR/cc_{random,hard}.txt)
 * on the reference files and constructed pairs: mirror-symmetric pairs (centre on the other's
 * axis, two tied minima) moved by 0 .. 1e-6, pairs that cross, touch or nearly touch, pairs
 * with one circle through the other's centre, and random pairs. Where the search certifies:
 * - the scan finds no second closest pair (no tie: the search never hides one of two pairs);
 * - the scan's distance agrees to 2 ulps of scale (the final distance of both is
 *   cdist__cc_point_d2 at their angles) and its angle to 1e-6 rad;
 * - the cosine and sine returned are those of the angle to 4e-15 (the angle's own rounding).
 * And the search certifies at least 95% of cc_random (the rest costs a failed search plus the
 * scan, so this is the speed claim's premise). */
#include "../../../src/circles/cc_search.c"

#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "test_rand.h"
#include "query_io.h"
#include "circle_pairs.h"

typedef int (*quick_fn)(const cdist__cc_frame *f, double *t, double *c, double *s);

enum { MAXN = 6000 };
static cdist_circle A[MAXN], B[MAXN];

static cdist_circle circ(cdist_vec3 c, cdist_vec3 n, double r)
{
    double l = sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
    return (cdist_circle){c, {n.x / l, n.y / l, n.z / l}, r};
}
static cdist_vec3 add3(cdist_vec3 a, cdist_vec3 b) { return (cdist_vec3){a.x + b.x, a.y + b.y, a.z + b.z}; }
static cdist_vec3 scale3(double k, cdist_vec3 a) { return (cdist_vec3){k * a.x, k * a.y, k * a.z}; }
static cdist_vec3 rpoint(void) { return (cdist_vec3){2 * rnd01() - 1, 2 * rnd01() - 1, 2 * rnd01() - 1}; }
/* a unit vector orthogonal to the unit vector n */
static cdist_vec3 ortho(cdist_vec3 n)
{
    cdist_vec3 e = fabs(n.x) < 0.9 ? (cdist_vec3){1, 0, 0} : (cdist_vec3){0, 1, 0};
    cdist_vec3 w = {n.y * e.z - n.z * e.y, n.z * e.x - n.x * e.z, n.x * e.y - n.y * e.x};
    return scale3(1.0 / sqrt(w.x * w.x + w.y * w.y + w.z * w.z), w);
}

static size_t load(const char *dir, const char *set, size_t n)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/cc_%s.txt", dir, set);
    return load_circle_pairs(path, A, B, n, MAXN);
}

/* Constructed pairs (see the header comment). */
static size_t constructed(size_t n)
{
    static const double moved[] = {0.0, 1e-15, 1e-13, 1e-11, 1e-9, 1e-7, 1e-6};
    for (int k = 0; k < 2000 && n < MAXN; k++, n++) {
        cdist_vec3 na = rnd_unit_vec(), ca = rpoint();
        double ra = 0.3 + rnd01(), rb = 0.2 + rnd01();
        A[n] = circ(ca, na, ra);
        switch (k % 4) {
        case 0: { /* B's centre on A's axis (or A's on B's), then moved */
            cdist_vec3 cb = add3(ca, scale3(2 * rnd01() - 1, na));
            cb = add3(cb, scale3(moved[k / 4 % 7], rnd_unit_vec()));
            B[n] = circ(cb, rnd_unit_vec(), rb);
            if (k / 4 % 2) {
                cdist_circle t = A[n];
                A[n] = B[n];
                B[n] = t;
            }
            break;
        }
        case 1: { /* B through a point of A, moved by 0 .. 1e-6: crossing, touching */
            cdist_vec3 u = ortho(na), P = add3(ca, scale3(ra, u)), nb = rnd_unit_vec();
            cdist_vec3 cb = add3(add3(P, scale3(rb, ortho(nb))), scale3(moved[k / 4 % 7], rnd_unit_vec()));
            B[n] = circ(cb, nb, rb);
            break;
        }
        case 2: { /* B's centre on A, moved: A crosses B's axis at or near B's centre */
            cdist_vec3 P = add3(ca, scale3(ra, ortho(na)));
            B[n] = circ(add3(P, scale3(moved[k / 4 % 7] * ra, rnd_unit_vec())), rnd_unit_vec(), rb);
            break;
        }
        default: /* random */
            B[n] = circ(add3(ca, rpoint()), rnd_unit_vec(), rb);
        }
    }
    return n;
}

typedef struct setup {
    cdist__circle a, b;
    cdist__cc_problem pb;
    cdist__cc_frame f;
    double L; /* the problem scale of the scaled frame, for ulps */
} setup;

/* The robust method's set-up of entry i (cdist_circle_circle -> cdist__cc_robust); 0 when it
 * does not reach the search (invalid, a zero radius, parallel planes: closed form). */
static int prepare(cdist_query *q, size_t i, setup *s)
{
    vec3 offset;
    cdist__best best;
    if (cdist__check_circle(q, &A[i], "a", &s->a) || cdist__check_circle(q, &B[i], "b", &s->b)) return 0;
    cdist__circles_frame(&s->a, &s->b, &offset, &best);
    if (!cdist__cc_prepare(&s->a, &s->b, &s->pb)) return 0;
    cdist__cc_frame_ring(&s->f, &s->pb.A, s->pb.CB, &s->pb.B);
    double tp[4];
    if (cdist__cc_parallel_critical(&s->f, tp) >= 0) return 0;
    s->L = s->f.L;
    return 1;
}

/* The scan's answer on the frame: its collector (settled as the robust method settles it). */
static void scan(setup *s, cdist__best *b)
{
    cdist__cc_frame f = s->f;
    cdist__cc_frame_bounds(&f);
    cdist__best_init(b, s->L);
    cdist__cc_sink k = {.f = &f, .best = b, .prune = 1, .unscale = 1.0, .swapped = 0, .A = &s->pb.A, .B = &s->pb.B,
                        .Fmin = INFINITY, .dmin = INFINITY, .rho_min = INFINITY};
    double Fmax;
    cdist__cc_scan(&f, &k, &Fmax);
    if (b->n == 0 && isfinite(k.Fmin)) cdist__cc_pair_at(&f, k.tmin, &k);
    if (b->n > 0) cdist__cc_settle_d2(&f, &k);
}

static void check_variant(const char *name, quick_fn quick, cdist_query *q, size_t n, size_t n_random)
{
    int certified = 0, certified_random = 0, tried_random = 0, tried = 0;
    double worst = 0;
    for (size_t i = 0; i < n; i++) {
        setup s;
        if (!prepare(q, i, &s)) continue;
        tried++;
        tried_random += i < n_random;
        double t, c, sn;
        if (!quick(&s.f, &t, &c, &sn)) continue;
        certified++;
        certified_random += i < n_random;
        cdist__best b;
        scan(&s, &b);
        CHECK(b.n >= 1, "%s entry %zu: the scan found nothing", name, i);
        if (b.n < 1) continue;
        double tie = CD_TIE_ULPS * DBL_EPSILON * b.scale, d0 = sqrt(b.c[0].d2);
        CHECK(b.n == 1 || sqrt(b.c[1].d2) - d0 > tie,
              "%s entry %zu: certified one closest pair where the scan finds two (%.17g, %.17g)", name, i, d0,
              sqrt(b.c[1].d2));
        double dq = sqrt(cdist__cc_point_d2(&s.f.rg, s.f.s, c, sn));
        double err = fabs(dq - d0) / (DBL_EPSILON * s.L);
        worst = err > worst ? err : worst;
        CHECK(err <= 2.0, "%s entry %zu: distance %.17g vs the scan's %.17g (%.2f ulps of scale)", name, i, dq, d0, err);
        double ts = b.c[0].param[0], dt = fabs(remainder(cdist__cc_param(t) - ts, 2 * M_PI));
        CHECK(dt <= 1e-6, "%s entry %zu: angle %.17g vs the scan's %.17g", name, i, cdist__cc_param(t), ts);
        /* t in [0, 2 pi + h) carries its own rounding, up to 9e-16 */
        CHECK(fabs(c - cos(t)) <= 4e-15 && fabs(sn - sin(t)) <= 4e-15, "%s entry %zu: (cos, sin) of %.17g off by %.3g, %.3g",
              name, i, t, c - cos(t), sn - sin(t));
    }
    CHECK(certified_random >= 0.95 * tried_random, "%s: certified %d of %d cc_random entries (< 95%%)", name,
          certified_random, tried_random);
    printf("  %s: certified %d of %d (cc_random %d of %d), worst distance difference to the scan %.2f ulps of scale\n",
           name, certified, tried, certified_random, tried_random, worst);
}

int main(int argc, char **argv)
{
    test_rng = 0x51ED2701A3C5ull;
    if (argc < 2) {
        fprintf(stderr, "usage: test_cc_quick DIR\n");
        return 2;
    }
    cdist__cc_search_tables();
    cdist_query *q = cdist_query_new();
    size_t n_random = load(argv[1], "random", 0);
    size_t n = load(argv[1], "hard", n_random);
    n = constructed(n);
    check_variant("scalar", ck_quick_1, q, n, n_random);
#ifdef CD_X86_KERNELS
    __builtin_cpu_init();
    if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) check_variant("avx2", ck_quick_4, q, n, n_random);
    if (__builtin_cpu_supports("avx512f")) check_variant("avx512", ck_quick_8, q, n, n_random);
#endif
    cdist_query_free(q);
    return check_summary("cc-quick");
}
