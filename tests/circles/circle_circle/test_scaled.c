/* SPDX-License-Identifier: MIT */
/* Scale invariance of the circles family (cc, cd, dd): every line of a reference file, scaled
 * by 2^k (exact) for k from -1000 to 500 in a stride, must give 2^k times the reference
 * distance within the reference tolerance of the scaled problem. Lines whose scaled numbers
 * would leave the accepted range (|x| > 1e150) or the normal doubles are skipped (counted).
 * Also the issue-10 regressions with hand-derived answers: tiny inputs, mixed scales.
 * usage: test_scaled [--tol=X] QUERIES EXPECTED */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "circledist.h"
#include "query_io.h"

static int failures;

static void check(const char *what, double got, double want, double tol)
{
    if (!(fabs(got - want) <= tol)) {
        printf("FAIL %s: got %.17g want %.17g (tol %.3g)\n", what, got, want, tol);
        failures++;
    }
}

/* One query line given as text, with its expected distance (derived by hand) and flags. */
static void line_case(cdist_query *q, const char *text, double want, double reltol, int want_equi)
{
    cdq_line ql;
    char err[256];
    cdist_result r;
    if (cdq_parse(text, &ql, err, sizeof err) != 1 || cdq_run(q, &ql, &r) != CDIST_OK) {
        printf("FAIL %s: %s\n", text, err);
        failures++;
        return;
    }
    check(text, r.distance, want, reltol * want);
    if (want_equi >= 0 && r.equidistant != want_equi) {
        printf("FAIL %s: equidistant %d, want %d\n", text, r.equidistant, want_equi);
        failures++;
    }
}

static void regressions(cdist_query *q)
{
    /* Tiny inputs: the squared distance underflows, the distance must not. c0 passes through
     * c1's centre; c1 (radius 1e-200) is then at 1e-200 from that point, and no closer. */
    line_case(q, "cc 0 0 0 0 0 1 1e-200 1e-200 0 0 0 1 0 1e-200", 1e-200, 1e-15, -1);
    /* Two points (radius 0) 8e-189 apart: the scale must come from the coordinates, not from a
     * norm whose square underflows (it gave 0; found by the fuzz smoke test). */
    line_case(q, "cc 0 8e-189 0 0 0 1 0 0 0 0 1 0 0 0", 8e-189, 1e-15, -1);
    /* Stacked coaxial disks 3e-170 apart (every pair of the overlap is closest). */
    line_case(q, "dd 0 0 0 0 0 1 1e-170 0 0 3e-170 0 0 1 1e-170", 3e-170, 1e-15, 1);
    line_case(q, "cd 0 0 0 0 0 1 1e-170 0 0 3e-170 0 0 1 1e-170", 3e-170, 1e-15, 1);
    /* Mixed scales, coplanar: the big disk's rim passes through the origin exactly (centre
     * -1e8, R = 1e8), the small one (r = 1e-8) has its centre at 1.49e-8: a gap of
     * 1.49e-8 - 1e-8 = 4.9e-9, not a contact; one closest pair (not equidistant). The
     * reference is the exact gap; the tolerance is that of the problem scale 1e8. */
    double gap = 1.49e-8 - 1e-8;
    const char *mixed[] = {
        "dd -1e8 0 0 0 0 1 1e8 1.49e-8 0 0 0 0 1 1e-8", "dd 1.49e-8 0 0 0 0 1 1e-8 -1e8 0 0 0 0 1 1e8",
        "cd 1.49e-8 0 0 0 0 1 1e-8 -1e8 0 0 0 0 1 1e8", "cd -1e8 0 0 0 0 1 1e8 1.49e-8 0 0 0 0 1 1e-8",
        "cc -1e8 0 0 0 0 1 1e8 1.49e-8 0 0 0 0 1 1e-8", "cc 1.49e-8 0 0 0 0 1 1e-8 -1e8 0 0 0 0 1 1e8",
    };
    for (int i = 0; i < 6; i++) {
        cdq_line ql;
        char err[256];
        cdist_result r;
        if (cdq_parse(mixed[i], &ql, err, sizeof err) != 1 || cdq_run(q, &ql, &r) != CDIST_OK) {
            printf("FAIL %s\n", mixed[i]);
            failures++;
            continue;
        }
        /* Contact must be exact: a positive gap is never reported as 0. Within the scale
         * tolerance (1e8 * 4e-15) of the gap, and one pair, not equidistant. */
        if (!(r.distance > 0) || !(fabs(r.distance - gap) <= 4e-15 * 1e8) || r.equidistant) {
            printf("FAIL %s: distance %.17g (gap %.17g) equidistant %d\n", mixed[i], r.distance, gap, r.equidistant);
            failures++;
        }
    }
}

int main(int argc, char **argv)
{
    double tol = 1e-12;
    int ai = 1;
    for (; ai < argc && !strncmp(argv[ai], "--", 2); ai++) {
        if (!strncmp(argv[ai], "--tol=", 6)) tol = atof(argv[ai] + 6);
    }
    cdist_query *q = cdist_query_new();
    regressions(q);
    if (argc - ai >= 2) {
        FILE *f = fopen(argv[ai], "r"), *g = fopen(argv[ai + 1], "r");
        if (!f || !g) {
            printf("cannot open inputs\n");
            return 1;
        }
        char line[4096], err[256];
        int n = 0, skipped = 0, run = 0;
        double worst = 0;
        long lineno = 0;
        while (fgets(line, sizeof line, f)) {
            cdq_line ql;
            lineno++;
            if (cdq_parse(line, &ql, err, sizeof err) != 1) continue;
            double want;
            if (fscanf(g, "%lf", &want) != 1) break;
            double L = cdq_scale(&ql, want);
            int k = -1000 + (n * 37) % 1501; /* stride through -1000 .. 500 */
            n++;
            cdq_line s = ql;
            int ok = 1;
            for (int i = 0; i < s.nvalues; i++) {
                /* normals (unit vectors) are not scaled: columns 3-5 and 10-12 of cc/cd/dd */
                int normal = (i >= 3 && i <= 5) || (i >= 10 && i <= 12);
                if (normal) continue;
                double x = ldexp(ql.v[i], k);
                if (fabs(x) > 1e150 || (x != 0 && fabs(x) < DBL_MIN)) ok = 0;
                s.v[i] = x;
            }
            if (!ok) {
                skipped++;
                continue;
            }
            cdist_result r;
            if (cdq_run(q, &s, &r) != CDIST_OK) {
                printf("FAIL line %d (k = %d): status %s\n", n, k, cdist_query_last_error(q));
                failures++;
                continue;
            }
            run++;
            double e = fabs(ldexp(r.distance, -k) - want) / L;
            if (e > worst) worst = e;
            if (getenv("SCALED_VERBOSE") && e > 1e-14) printf("line %d k %d error %.3g\n", n, k, e);
            if (!(e <= tol)) {
                printf("FAIL line %d (k = %d): distance %.17g, want %.17g * 2^k (error %.3g of scale)\n", n, k,
                       r.distance, want, e);
                failures++;
            }
        }
        printf("%d lines scaled and checked, %d skipped (out of range), worst error %.3g of scale\n", run, skipped,
               worst);
        if (run < n / 2) {
            printf("FAIL: too few lines checked\n");
            failures++;
        }
    }
    cdist_query_free(q);
    if (failures) printf("%d failures\n", failures);
    return failures ? 1 : 0;
}
