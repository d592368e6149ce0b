/* A circle passed as a callback curve over [0, 2 pi] reproduces the shared circle-circle
 * reference distances (tests/data/cc_*.expected, computed independently) within 1e-12 of scale,
 * in both roles (first circle as the curve, then the second). The pairs must realise the
 * distance and lie on the circles.
 * usage: test_curve_cc [--samples=N] QUERIES EXPECTED [ERRATA] */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "query_io.h"

typedef struct circ_curve {
    cdist_vec3 c, u, v;
    double r;
} circ_curve;

static int circ_fn(void *user, double t, cdist_vec3 *p, cdist_vec3 *d)
{
    const circ_curve *k = user;
    double s = sin(t), c = cos(t);
    p->x = k->c.x + k->r * (c * k->u.x + s * k->v.x);
    p->y = k->c.y + k->r * (c * k->u.y + s * k->v.y);
    p->z = k->c.z + k->r * (c * k->u.z + s * k->v.z);
    d->x = k->r * (-s * k->u.x + c * k->v.x);
    d->y = k->r * (-s * k->u.y + c * k->v.y);
    d->z = k->r * (-s * k->u.z + c * k->v.z);
    return 0;
}

static circ_curve make(const cdist_circle *c)
{
    circ_curve k;
    k.c = c->center;
    k.r = c->radius;
    cdist_circle_basis(c, &k.u, &k.v);
    return k;
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
    char line[4096], eline[256];
    long lineno = 0;
    double worst = 0, worst_ratio = 0;
    long worst_line = 0;
    while (fgets(line, sizeof line, fq)) {
        lineno++;
        cdq_line ql;
        char err[256];
        if (cdq_parse(line, &ql, err, sizeof err) != 1) continue;
        if (!fgets(eline, sizeof eline, fe)) break;
        long double e = strtold(eline, NULL);
        double L = cdq_scale(&ql, (double)e);
        cdist_circle c0 = {{ql.v[0], ql.v[1], ql.v[2]}, {ql.v[3], ql.v[4], ql.v[5]}, ql.v[6]};
        cdist_circle c1 = {{ql.v[7], ql.v[8], ql.v[9]}, {ql.v[10], ql.v[11], ql.v[12]}, ql.v[13]};
        for (int role = 0; role < 2; role++) {
            circ_curve k = make(role ? &c1 : &c0);
            const cdist_circle *other = role ? &c0 : &c1;
            cdist_result r;
            cdist_status st = cdist_curve_circle(q, circ_fn, &k, 0.0, 2 * M_PI, other, &r);
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
                double on1 = (double)ref_point_circle(r.pairs[i].point[1], *other);
                CHECK(on0 <= ptol && on1 <= ptol, "line %ld: pair %d off the circles (%g, %g)", lineno, i,
                      on0, on1);
            }
        }
    }
    printf("%s: max error %.3g of scale (line %ld); max error / (1e-12 + position rounding floor) %.3g\n", argv[ai],
           worst, worst_line, worst_ratio);
    cdist_query_free(q);
    fclose(fq);
    fclose(fe);
    return check_summary("curve-cc");
}
