/* SPDX-License-Identifier: MIT */
/* The near-crossing grid of the circle-circle engine and its re-check (src/circles/cc_kink.c),
 * through cdist__circle_circle_critical (internal; this test is linked with the library sources),
 * on the cases of cc_kink.txt against their critical points from mpmath (cc_kink.critical, by
 * cc_kink_exact.py), each circle parameterised in turn:
 *   - critical-angle mode: as many angles as critical points, each critical point returned once
 *     (a root the grid's F' sign pair gave is not returned again by the re-check's subdivision)
 *     and found, also two that one grid interval holds with no F' sign change across it;
 *   - minima mode (a cap above every minimum): the angles are distinct minima, the global one
 *     among them.
 * usage: test_cc_kink CASES CRITICAL */
#include <string.h>

#include "check.h"
#include "internal.h"

enum { MAXC = 8 };

static double circ_dist(double a, double b)
{
    double d = fmod(fabs(a - b), 2 * M_PI);
    return fmin(d, 2 * M_PI - d);
}

/* Returned angles t[0..n) against the reference critical points (angle, kind +1 minimum / -1
 * maximum) of kind want (0: any): pairwise distinct, each within tol of a different reference. */
static void match(const char *what, int line, int order, const double *t, int n, const double *ref, const int *kind,
                  int nr, int want)
{
    const double tol = 1e-9; /* rad: the refined angles are far closer; the nearest pair is 7e-7 apart */
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++)
            CHECK(circ_dist(t[i], t[j]) > tol, "line %d, order %d, %s: angles %d and %d are one root (%.17g, %.17g)",
                  line, order, what, i, j, t[i], t[j]);
    int used[MAXC] = {0};
    for (int i = 0; i < n; i++) {
        int found = -1;
        for (int j = 0; j < nr; j++)
            if (!used[j] && (!want || kind[j] == want) && circ_dist(t[i], ref[j]) <= tol) found = j;
        CHECK(found >= 0, "line %d, order %d, %s: angle %.17g is no (other) critical point", line, order, what,
              t[i]);
        if (found >= 0) used[found] = 1;
    }
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: test_cc_kink CASES CRITICAL\n");
        return 2;
    }
    FILE *fc = fopen(argv[1], "r"), *fr = fopen(argv[2], "r");
    if (!fc || !fr) {
        fprintf(stderr, "cannot open %s or %s\n", argv[1], argv[2]);
        return 2;
    }
    cdist_query *q = cdist_query_new();
    char buf[2048];
    int line = 0, cases = 0;
    while (fgets(buf, sizeof buf, fc)) {
        line++;
        double v[14];
        if (buf[0] == '#' ||
            sscanf(buf, "cc %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf", v, v + 1, v + 2, v + 3, v + 4,
                   v + 5, v + 6, v + 7, v + 8, v + 9, v + 10, v + 11, v + 12, v + 13) != 14)
            continue;
        cdist_circle c[2] = {{tv(v[0], v[1], v[2]), tv(v[3], v[4], v[5]), v[6]},
                             {tv(v[7], v[8], v[9]), tv(v[10], v[11], v[12]), v[13]}};
        for (int order = 0; order < 2; order++) {
            int rl, ro, nr;
            if (fscanf(fr, "%d %d %d", &rl, &ro, &nr) != 3 || rl != line || ro != order || nr > MAXC) {
                fprintf(stderr, "%s: no reference for line %d, order %d\n", argv[2], line, order);
                return 2;
            }
            double ref[MAXC], dref[MAXC], dmax = 0;
            int kind[MAXC], nmin = 0, gmin = -1;
            for (int j = 0; j < nr; j++) {
                char k[8];
                if (fscanf(fr, "%lf %7s %lf", &ref[j], k, &dref[j]) != 3) return 2;
                kind[j] = strcmp(k, "min") ? -1 : 1;
                dmax = fmax(dmax, dref[j]);
                if (kind[j] > 0 && (gmin < 0 || dref[j] < dref[gmin])) gmin = j;
                nmin += kind[j] > 0;
            }
            cases++;
            cdist__circle a, b;
            CHECK(cdist__check_circle(q, &c[order], "c0", &a) == CDIST_OK &&
                      cdist__check_circle(q, &c[1 - order], "c1", &b) == CDIST_OK,
                  "line %d: valid circles", line);
            b.c = v_sub(b.c, a.c);
            a.c = v3(0, 0, 0);
            double t[64];
            int n = cdist__circle_circle_critical(q, &a, &b, INFINITY, t, 64, NULL);
            CHECK(n == nr, "line %d, order %d, critical mode: %d angles for %d critical points", line, order, n, nr);
            match("critical mode", line, order, t, n, ref, kind, nr, 0);

            n = cdist__circle_circle_critical(q, &a, &b, 2 * dmax, t, 64, NULL);
            CHECK(n >= 1 && n <= nmin, "line %d, order %d, minima mode: %d angles for %d minima", line, order, n, nmin);
            match("minima mode", line, order, t, n, ref, kind, nr, 1);
            int global = 0;
            for (int i = 0; i < n && gmin >= 0; i++) global |= circ_dist(t[i], ref[gmin]) <= 1e-9;
            CHECK(global, "line %d, order %d, minima mode: the global minimum at %.17g is missing", line, order,
                  gmin >= 0 ? ref[gmin] : NAN);
        }
    }
    fclose(fc);
    fclose(fr);
    CHECK(cases == 4, "%d cases read", cases);
    cdist_query_free(q);
    return check_summary("cc_kink");
}
