/* SPDX-License-Identifier: MIT */
/* The point-circle/point-disk distance kernels, each instruction set the machine has (scalar,
 * AVX2, AVX-512), against the single queries: a kernel leaves an entry to the scalar path exactly
 * when the single query rejects it, and its distances are bit-identical to the single query's.
 * The kernel source is compiled into this test so that every variant can be called directly. */
#include "../../src/batch/point_kernel.c"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"

enum { N = 4099 };
static cdist_vec3 P[N];
static cdist_circle C[N];
static double D[N];

static uint64_t rng = 0x9E3779B97F4A7C15ull;
static double rnd01(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (double)(rng >> 11) * 0x1p-53;
}

static void make(void)
{
    for (int i = 0; i < N; i++) {
        double s = pow(10.0, 6.0 * rnd01() - 3.0);
        cdist_vec3 n = {rnd01() - 0.5, rnd01() - 0.5, rnd01() - 0.5};
        double ln = sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
        n.x /= ln, n.y /= ln, n.z /= ln;
        C[i] = (cdist_circle){{s * (rnd01() - 0.5), s * (rnd01() - 0.5), s * (rnd01() - 0.5)}, n, s * rnd01()};
        P[i] = (cdist_vec3){s * (2 * rnd01() - 1), s * (2 * rnd01() - 1), s * (2 * rnd01() - 1)};
        switch (i % 23) { /* special and bad entries */
        case 1: P[i] = (cdist_vec3){C[i].center.x + 3 * n.x, C[i].center.y + 3 * n.y, C[i].center.z + 3 * n.z}; break;
        case 2: C[i].radius = 0.0; break;
        case 3: C[i].radius = -0.5; break;
        case 4: P[i].y = NAN; break;
        case 5: C[i].center.z = INFINITY; break;
        case 6: C[i].normal = (cdist_vec3){0, 0, 0}; break;
        case 7: C[i].normal.x *= 1.01; break; /* not unit */
        case 8: C[i].normal.y = NAN; break;
        case 9: P[i].x = 2e150; break;
        case 10: C[i].radius = INFINITY; break;
        case 11: C[i].radius = -0.0; break;
        case 12: C[i].normal = (cdist_vec3){0, 0, 1.0 + 1e-7}; break;
        case 13: C[i].normal = (cdist_vec3){0, 0, -1}; P[i].x = C[i].center.x + 0.5 * C[i].radius; break; /* over the disk */
        case 14: P[i].z = -INFINITY; C[i].normal.x = NAN; break;
        default: break;
        }
    }
}

typedef uint64_t (*kfn)(const cdist__job *, int, double, size_t, size_t);

static void check_kernel(const char *name, kfn k, cdist_query *q, double tol)
{
    cdist_query_set_unit_tolerance(q, tol);
    for (int disk = 0; disk < 2; disk++) {
        cdist__job job = {disk ? CDIST_KIND_POINT_DISK : CDIST_KIND_POINT_CIRCLE, N, (const char *)P, (const char *)C,
                      sizeof P[0], sizeof C[0], NULL, D, NULL, 64, CD_OUT_DISTANCE, 0, NULL, NULL};
        int bad = 0, wrong_left = 0, checked = 0;
        for (size_t lo = 0; lo < N; lo += 64) {
            size_t cnt = N - lo < 64 ? N - lo : 64;
            for (size_t i = lo; i < lo + cnt; i++) D[i] = -1.0;
            uint64_t left = k(&job, disk, tol, lo, cnt);
            for (size_t j = 0; j < cnt; j++) {
                size_t i = lo + j;
                cdist_result r;
                cdist_status st = disk ? cdist_point_disk(q, &P[i], &C[i], &r) : cdist_point_circle(q, &P[i], &C[i], &r);
                int l = (int)(left >> j & 1);
                if (l != (st != CDIST_OK)) {
                    if (wrong_left++ < 3)
                        CHECK(0, "%s disk=%d entry %zu: kernel %s, single query %s", name, disk, i,
                              l ? "left it" : "answered", cdist_status_name(st));
                    continue;
                }
                if (!l) {
                    checked++;
                    if (memcmp(&D[i], &r.distance, sizeof(double)) && bad++ < 3)
                        CHECK(0, "%s disk=%d entry %zu: %.17g vs single %.17g", name, disk, i, D[i], r.distance);
                }
            }
        }
        CHECK(bad == 0 && wrong_left == 0, "%s disk=%d tol=%g: %d distances differ, %d entries misrouted", name, disk,
              tol, bad, wrong_left);
        CHECK(checked > (tol > 0 ? N / 2 : N / 20), "%s: only %d entries answered by the kernel", name, checked);
    }
}

/* Normals whose largest component is below 0x1p-500 (down to subnormal), with any length
 * accepted (tolerance INFINITY): the single query rescales them by a power of two and answers;
 * a kernel must leave them to the scalar path (1 / m overflows there and gave NaN with CDIST_OK).
 * Reference: the single query, entry by entry, and the brute fact that a distance is a number. */
enum { NT = 64 };
static void check_tiny_normals(const char *name, kfn k, cdist_query *q)
{
    static const double comp[] = {1e-310, 0x1p-501, 0x1.fffffffffffffp-501, 0x1p-500, 1e-200, 0.25};
    cdist_vec3 tp[NT];
    cdist_circle tc[NT];
    double td[NT];
    for (int i = 0; i < NT; i++) {
        double c = comp[i % 6];
        tc[i] = (cdist_circle){{0.5 * i, -1.0, 2.0}, {c, (i & 8) ? 0.0 : c, c}, 1.0 + i};
        tp[i] = (cdist_vec3){3.0, 0.25 * i, -1.5};
    }
    cdist_query_set_unit_tolerance(q, INFINITY);
    for (int disk = 0; disk < 2; disk++) {
        cdist__job job = {disk ? CDIST_KIND_POINT_DISK : CDIST_KIND_POINT_CIRCLE, NT, (const char *)tp, (const char *)tc,
                          sizeof tp[0], sizeof tc[0], NULL, td, NULL, 64, CD_OUT_DISTANCE, 0, NULL, NULL};
        for (int i = 0; i < NT; i++) td[i] = -1.0;
        uint64_t left = k(&job, disk, INFINITY, 0, NT);
        for (int i = 0; i < NT; i++) {
            int tiny = comp[i % 6] < 0x1p-500;
            CHECK((int)(left >> i & 1) == tiny, "%s disk=%d normal component %g: kernel %s", name, disk, comp[i % 6],
                  (left >> i & 1) ? "left it" : "answered it");
            if (left >> i & 1) continue;
            cdist_result r;
            cdist_status st = disk ? cdist_point_disk(q, &tp[i], &tc[i], &r) : cdist_point_circle(q, &tp[i], &tc[i], &r);
            CHECK(st == CDIST_OK && !memcmp(&td[i], &r.distance, sizeof(double)),
                  "%s disk=%d entry %d: %.17g vs single %.17g", name, disk, i, td[i], r.distance);
        }
    }
}

/* The same normals through the public batch: status and distance of every entry as the single
 * query's (before the fix: NaN with CDIST_OK). */
static void check_tiny_normals_batch(cdist_query *q)
{
    cdist_vec3 p = {1.0, 2.0, 3.0};
    cdist_circle c = {{0.0, 0.0, 0.0}, {1e-310, 1e-310, 1e-310}, 2.0};
    cdist_vec3 tp[NT];
    cdist_circle tc[NT];
    double td[NT];
    cdist_status ts[NT];
    for (int i = 0; i < NT; i++) tp[i] = p, tc[i] = c, tc[i].radius = 0.5 * i;
    cdist_query_set_unit_tolerance(q, INFINITY);
    for (int disk = 0; disk < 2; disk++) {
        cdist_status st = cdist_batch_distance(q, disk ? CDIST_KIND_POINT_DISK : CDIST_KIND_POINT_CIRCLE, NT, tp,
                                               sizeof tp[0], tc, sizeof tc[0], td, ts);
        CHECK(st == CDIST_OK, "batch of tiny normals: %s", cdist_status_name(st));
        int bad = 0;
        for (int i = 0; i < NT; i++) {
            cdist_result r;
            cdist_status s1 = disk ? cdist_point_disk(q, &tp[i], &tc[i], &r) : cdist_point_circle(q, &tp[i], &tc[i], &r);
            if ((ts[i] != s1 || !(td[i] == r.distance) || isnan(td[i])) && bad++ < 3)
                CHECK(0, "batch disk=%d entry %d: %.17g (%s) vs single %.17g (%s)", disk, i, td[i],
                      cdist_status_name(ts[i]), r.distance, cdist_status_name(s1));
        }
        CHECK(bad == 0, "batch disk=%d: %d tiny-normal entries differ from the single query", disk, bad);
    }
}

int main(void)
{
    make();
    cdist_query *q = cdist_query_new();
    double tols[] = {1e-6, 0.0, INFINITY};
    for (int t = 0; t < 3; t++) {
        check_kernel("scalar", kernel_1, q, tols[t]);
#ifdef CD_X86_KERNELS
        __builtin_cpu_init();
        if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) check_kernel("avx2", kernel_4, q, tols[t]);
        else printf("no AVX2 here: skipped\n");
        if (__builtin_cpu_supports("avx512f"))
            check_kernel("avx512", kernel_8, q, tols[t]);
        else printf("no AVX-512 here: skipped\n");
#endif
    }
    check_tiny_normals("scalar", kernel_1, q);
#ifdef CD_X86_KERNELS
    if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) check_tiny_normals("avx2", kernel_4, q);
    if (__builtin_cpu_supports("avx512f")) check_tiny_normals("avx512", kernel_8, q);
#endif
    check_tiny_normals_batch(q);
    cdist_query_free(q);
    return check_summary("point-kernel");
}
