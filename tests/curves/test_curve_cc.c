/* SPDX-License-Identifier: MIT */
/* A circle passed as a callback curve over [0, 2 pi], and the same circle as a full arc
 * (its own zero_direction, range [a, a + 2 pi]), reproduce the shared circle-circle and
 * circle-disk reference distances (tests/data/cc_*, cd_*: computed independently) within
 * 1e-12 of scale (the callback: plus the rounding of its absolute positions), the circle in
 * both roles for cc. The pairs must realise the distance and lie on the objects.
 * usage: test_curve_cc [--samples=N] QUERIES EXPECTED */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "circle_curve.h"
#include "query_io.h"
#include "ref_lines.h"

static double worst_arc = 0;
static long worst_arc_line = 0;

/* The full circle c0 as an arc (zero_direction some vector off the normal, range [a, a + 2 pi])
 * against circle or disk c1: the arc machinery must reproduce the full-circle reference. */
static void full_arc(cdist_query *q, long lineno, const cdist_circle *c0, const cdist_circle *c1, int disk,
                     long double e, double L, double ptol)
{
    cdist_vec3 zd = {c0->normal.y - 0.3, 0.7 - c0->normal.z, c0->normal.x + 0.1};
    double a0 = -1.0 - 3.0 * (double)(lineno % 5);
    cdist_arc a = {*c0, zd, a0, a0 + 2 * M_PI};
    cdist_result r;
    cdist_status st = disk ? cdist_arc_disk(q, &a, c1, &r) : cdist_arc_circle(q, &a, c1, &r);
    if (st == CDIST_ERR_ZERO_VECTOR) return; /* zd happened to be along the normal */
    CHECK(st == CDIST_OK, "line %ld full arc: %s", lineno, cdist_query_last_error(q));
    if (st) return;
    double er = (double)(fabsl((long double)r.distance - e) / L);
    if (er > worst_arc) {
        worst_arc = er;
        worst_arc_line = lineno;
    }
    CHECK(er <= 1e-12, "line %ld full arc (%s): distance %.17g expected %.21Lg error %.3g of scale", lineno,
          disk ? "disk" : "circle", r.distance, e, er);
    for (int i = 0; i < r.num_pairs; i++) {
        CHECK(fabs(tdist(r.pairs[i].point[0], r.pairs[i].point[1]) - r.distance) <= ptol,
              "line %ld full arc: pair %d does not realise the distance", lineno, i);
        double on0 = (double)ref_point_circle(r.pairs[i].point[0], *c0);
        double on1 = (double)(disk ? ref_point_disk(r.pairs[i].point[1], *c1) : ref_point_circle(r.pairs[i].point[1], *c1));
        CHECK(on0 <= ptol && on1 <= ptol, "line %ld full arc: pair %d off the objects (%g, %g)", lineno, i, on0, on1);
        CHECK(c0->radius == 0 || (r.pairs[i].param[0] >= a.start && r.pairs[i].param[0] <= a.end),
              "line %ld full arc: param %.17g outside", lineno, r.pairs[i].param[0]);
    }
}

int main(int argc, char **argv)
{
    int samples = 512;
    int ai = 1;
    if (ai < argc && !strncmp(argv[ai], "--samples=", 10)) samples = atoi(argv[ai++] + 10);
    if (argc - ai < 2) {
        fprintf(stderr, "usage: test_curve_cc [--samples=N] QUERIES EXPECTED\n");
        return 2;
    }
    FILE *fq = fopen(argv[ai], "r"), *fe = fopen(argv[ai + 1], "r");
    if (!fq || !fe) return 2;
    cdist_query *q = cdist_query_new();
    CHECK(cdist_query_set_curve_samples(q, samples) == CDIST_OK, "samples");
    long lineno = 0;
    double worst = 0, worst_ratio = 0;
    long worst_line = 0;
    cdq_line ql;
    long double e;
    while (ref_next(fq, fe, &ql, &e, &lineno)) {
        double L = cdq_scale(&ql, (double)e);
        int disk = !strcmp(ql.kind->name, "cd");
        cdist_circle c0 = {{ql.v[0], ql.v[1], ql.v[2]}, {ql.v[3], ql.v[4], ql.v[5]}, ql.v[6]};
        cdist_circle c1 = {{ql.v[7], ql.v[8], ql.v[9]}, {ql.v[10], ql.v[11], ql.v[12]}, ql.v[13]};
        {
            double mag = 0;
            for (int i = 0; i < ql.nvalues; i++) mag = fmax(mag, fabs(ql.v[i]));
            full_arc(q, lineno, &c0, &c1, disk, e, L, 1e-13 * L + 16 * 2.2e-16 * mag);
        }
        for (int role = 0; role < 2; role++) {
            if (disk && role) break; /* the disk is not a curve */
            circ_curve k = circ_curve_of(role ? &c1 : &c0);
            const cdist_circle *other = role ? &c0 : &c1;
            cdist_result r;
            cdist_status st = (disk ? cdist_curve_disk : cdist_curve_circle)(q, circ_fn, &k, 0.0, 2 * M_PI, other, &r);
            CHECK(st == CDIST_OK, "line %ld role %d: %s", lineno, role, cdist_query_last_error(q));
            if (st) continue;
            double er = (double)(fabsl((long double)r.distance - e) / L);
            if (!(er <= worst)) {
                worst = isnan(er) ? INFINITY : er;
                worst_line = lineno;
            }
            /* The callback's positions are doubles: far from the origin they carry rounding of
             * about one ulp of the coordinates, which bounds what any method can reach from
             * them (the built-in arc queries work relative to the centre and do not have it). */
            double mag = 0;
            for (int i = 0; i < ql.nvalues; i++) mag = fmax(mag, fabs(ql.v[i]));
            double floor_ = 2.0 * 2.2e-16 * mag / L;
            if (er / (1e-12 + floor_) > worst_ratio) worst_ratio = er / (1e-12 + floor_);
            CHECK(er <= 1e-12 + floor_, "line %ld role %d: distance %.17g expected %.21Lg error %.3g of scale (floor %.3g)",
                  lineno, role, r.distance, e, er, floor_);
            double ptol = 1e-13 * L + 16 * 2.2e-16 * mag;
            for (int i = 0; i < r.num_pairs; i++) {
                double dp = tdist(r.pairs[i].point[0], r.pairs[i].point[1]);
                CHECK(fabs(dp - r.distance) <= ptol, "line %ld: pair %d does not realise the distance", lineno, i);
                double on0 = (double)ref_point_circle(r.pairs[i].point[0], role ? c1 : c0);
                double on1 = (double)(disk ? ref_point_disk(r.pairs[i].point[1], *other)
                                           : ref_point_circle(r.pairs[i].point[1], *other));
                CHECK(on0 <= ptol && on1 <= ptol, "line %ld: pair %d off the circles (%g, %g)", lineno, i,
                      on0, on1);
            }
        }
    }
    printf("%s: callback curve: max error %.3g of scale (line %ld); max error / (1e-12 + position rounding floor) "
           "%.3g; full arc: max error %.3g of scale (line %ld)\n",
           argv[ai], worst, worst_line, worst_ratio, worst_arc, worst_arc_line);
    cdist_query_free(q);
    fclose(fq);
    fclose(fe);
    return check_summary("curve-cc");
}
