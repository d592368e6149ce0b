/* SPDX-License-Identifier: MIT */
/* Reference test: runs every query of a query file and compares each distance with an
 * independently computed expected distance (../shared/cases/README.md: error = |d - e| / L).
 * Also checks that every reported pair lies on its objects and realises the distance.
 * usage: refcheck [--method=NAME] [--tol=X] QUERIES EXPECTED */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "query_io.h"

static cdist_circle circle_at(const double *v)
{
    cdist_circle c = {tv(v[0], v[1], v[2]), tv(v[3], v[4], v[5]), v[6]};
    return c;
}

static double coord_mag(const cdq_line *ql)
{
    double m = 0;
    for (int i = 0; i < ql->nvalues; i++) m = fmax(m, fabs(ql->v[i]));
    return m;
}

int main(int argc, char **argv)
{
    const char *method = "auto";
    double tol = 1e-13;
    const char *files[2] = {NULL, NULL};
    int nf = 0;
    for (int i = 1; i < argc; i++) {
        if (!strncmp(argv[i], "--method=", 9)) method = argv[i] + 9;
        else if (!strncmp(argv[i], "--tol=", 6)) tol = atof(argv[i] + 6);
        else if (nf < 2) files[nf++] = argv[i];
    }
    if (nf != 2) {
        fprintf(stderr, "usage: refcheck [--method=NAME] [--tol=X] QUERIES EXPECTED\n");
        return 2;
    }
    cdist_method m = !strcmp(method, "polynomial") ? CDIST_METHOD_POLYNOMIAL
                     : !strcmp(method, "robust")   ? CDIST_METHOD_ROBUST
                     : !strcmp(method, "iteration") ? CDIST_METHOD_ITERATION
                                                    : CDIST_METHOD_AUTO;
    FILE *fq = fopen(files[0], "r"), *fe = fopen(files[1], "r");
    if (!fq || !fe) {
        fprintf(stderr, "refcheck: cannot open %s or %s\n", files[0], files[1]);
        return 2;
    }
    cdist_query *q = cdist_query_new();
    cdist_query_set_method(q, m);
    char line[4096];
    long lineno = 0, nq = 0, worst_line = 0;
    double worst = 0.0, worst_pair = 0.0;
    while (fgets(line, sizeof line, fq)) {
        lineno++;
        cdq_line ql;
        char err[256];
        int k = cdq_parse(line, &ql, err, sizeof err);
        if (k == 0) continue;
        CHECK(k == 1, "line %ld: parse error: %s", lineno, err);
        if (k != 1) continue;
        char eline[256];
        if (!fgets(eline, sizeof eline, fe)) {
            CHECK(0, "line %ld: no expected value", lineno);
            break;
        }
        long double expected = strtold(eline, NULL);
        nq++;
        cdist_result r;
        cdist_status st = cdq_run(q, &ql, &r);
        CHECK(st == CDIST_OK, "line %ld: status %s: %s", lineno, cdist_status_name(st), cdist_query_last_error(q));
        if (st != CDIST_OK) continue;
        double L = cdq_scale(&ql, (double)expected);
        double e = (double)(fabsl((long double)r.distance - expected) / L);
        if (!(e <= worst) || isnan(e)) {
            if (!(e <= worst)) worst = isnan(e) ? INFINITY : e;
            worst_line = lineno;
        }
        CHECK(e <= tol, "line %ld (%s): distance %.17g expected %.21Lg error %.3g of scale %.3g", lineno,
              ql.kind->name, r.distance, expected, e, L);
        CHECK(r.num_pairs >= 1 && r.num_pairs <= 2, "line %ld: num_pairs %d", lineno, r.num_pairs);
        CHECK(fabs(r.sqr_distance - r.distance * r.distance) <= 4e-16 * fmax(r.sqr_distance, 1e-300),
              "line %ld: sqr_distance inconsistent", lineno);
        /* Pairs: realise the distance and lie on the objects (circle/disk checked in long
         * double). Point coordinates carry rounding of their own magnitude. */
        double ptol = tol * L + 16 * 2.2e-16 * coord_mag(&ql);
        const char *kn = ql.kind->name;
        int last_is_disk = kn[1] == 'd';
        int n = ql.kind->nvalues;
        cdist_circle last = circle_at(ql.v + n - 7);
        for (int i = 0; i < r.num_pairs; i++) {
            double dp = tdist(r.pairs[i].point[0], r.pairs[i].point[1]);
            double ep = fabs(dp - r.distance);
            worst_pair = fmax(worst_pair, ep / L);
            CHECK(ep <= ptol, "line %ld pair %d: |p0-p1| = %.17g but distance %.17g", lineno, i, dp, r.distance);
            if (strcmp(kn, "aa") && strcmp(kn, "sa")) {
                double on = (double)(last_is_disk ? ref_point_disk(r.pairs[i].point[1], last)
                                                  : ref_point_circle(r.pairs[i].point[1], last));
                CHECK(on <= ptol, "line %ld pair %d: second point is %.3g off its %s", lineno, i, on,
                      last_is_disk ? "disk" : "circle");
            }
            if (!strcmp(kn, "cc") || !strcmp(kn, "cd") || !strcmp(kn, "dd")) {
                cdist_circle first = circle_at(ql.v);
                double on = (double)(kn[0] == 'd' ? ref_point_disk(r.pairs[i].point[0], first)
                                                  : ref_point_circle(r.pairs[i].point[0], first));
                CHECK(on <= ptol, "line %ld pair %d: first point is %.3g off its %s", lineno, i, on,
                      kn[0] == 'd' ? "disk" : "circle");
            }
            if (kn[0] == 'p') CHECK(tdist(r.pairs[i].point[0], tv(ql.v[0], ql.v[1], ql.v[2])) == 0.0,
                                    "line %ld: first point is not the query point", lineno);
        }
    }
    cdist_query_free(q);
    fclose(fq);
    fclose(fe);
    printf("refcheck %s method=%s: %ld queries, max error %.3g of scale (line %ld), max pair error %.3g, tol %.3g\n",
           files[0], method, nq, worst, worst_line, worst_pair, tol);
    CHECK(nq > 0, "no queries read");
    return check_summary("refcheck");
}
