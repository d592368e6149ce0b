/* SPDX-License-Identifier: MIT */
/* Speed of the curve and arc queries on random unit-scale inputs.
 * usage: bench_curve [COUNT]   (prints nanoseconds per query for each query kind) */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "circledist.h"
#include "circle_curve.h" /* tests/common */

static unsigned long long st = 0x2545F4914F6CDD1Dull;
static double ur(void)
{
    st ^= st << 13;
    st ^= st >> 7;
    st ^= st << 17;
    return (double)(st >> 11) * (1.0 / 9007199254740992.0) * 2.0 - 1.0;
}
static cdist_vec3 rv(void) { cdist_vec3 v = {ur(), ur(), ur()}; return v; }
static cdist_vec3 ru(void)
{
    for (;;) {
        cdist_vec3 v = rv();
        double n = sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
        if (n > 0.1 && n <= 1) { v.x /= n; v.y /= n; v.z /= n; return v; }
    }
}
static cdist_circle rc(void) { cdist_circle c = {rv(), ru(), 0.8 + 0.7 * ur()}; return c; }
static cdist_arc ra(void)
{
    cdist_arc a = {rc(), ru(), M_PI * ur(), 0};
    a.end = a.start + M_PI * (1.0 + ur());
    return a;
}

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

int main(int argc, char **argv)
{
    int n = argc > 1 ? atoi(argv[1]) : 2000;
    if (n < 1) n = 1;
    cdist_query *q = cdist_query_new();
    cdist_result r;
    double sink = 0;
    const char *names[] = {"arc_circle", "arc_arc", "segment_arc", "arc_disk", "helix_circle (3 turns)",
                           "helix_disk (3 turns)", "bezier3_circle", "bezier3_disk", "curve_circle (callback circle)"};
    for (int kind = 0; kind < 9; kind++) {
        st = 0x2545F4914F6CDD1Dull;
        int fails = 0;
        double t0 = now();
        for (int i = 0; i < n; i++) {
            cdist_arc a = ra(), b = ra();
            cdist_circle c = rc();
            cdist_segment s = {rv(), rv()};
            cdist_helix h = {rv(), ru(), ru(), 0.5 + 0.5 * ur(), ur(), 0, 6 * M_PI};
            cdist_bezier3 bz = {{rv(), rv(), rv(), rv()}};
            circ_curve cc = {c.center, {0, 0, 0}, {0, 0, 0}, c.radius};
            cdist_circle_basis(&c, &cc.u, &cc.v);
            cdist_status stt = CDIST_OK;
            switch (kind) {
            case 0: stt = cdist_arc_circle(q, &a, &c, &r); break;
            case 1: stt = cdist_arc_arc(q, &a, &b, &r); break;
            case 2: stt = cdist_segment_arc(q, &s, &a, &r); break;
            case 3: stt = cdist_arc_disk(q, &a, &c, &r); break;
            case 4: stt = cdist_helix_circle(q, &h, &c, &r); break;
            case 5: stt = cdist_helix_disk(q, &h, &c, &r); break;
            case 6: stt = cdist_bezier3_circle(q, &bz, &c, &r); break;
            case 7: stt = cdist_bezier3_disk(q, &bz, &c, &r); break;
            default: stt = cdist_curve_circle(q, circ_fn, &cc, 0, 2 * M_PI, &a.circle, &r); break;
            }
            fails += stt != CDIST_OK;
            sink += r.distance;
        }
        double dt = now() - t0;
        printf("%-32s %10.0f ns/query  (%d queries, %d failed, default %d curve samples)\n", names[kind], 1e9 * dt / n,
               n, fails, cdist_query_get_curve_samples(q));
        if (fails) return 1;
    }
    cdist_query_free(q);
    return sink == 12345.0 ? 2 : 0;
}
