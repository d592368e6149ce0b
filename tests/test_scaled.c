/* SPDX-License-Identifier: MIT */
/* Tiny and huge inputs (issue 10 item 2) for the point and lines families: every reference line
 * of pc pd lc ld rc rd sc sd (tests/data, revision 2) scaled by 2^k, k from -1000 to 500.
 *
 * Positions and radii are scaled (line and ray directions stay unit, normals stay as they are).
 * Expected, for every k:
 *  - a scaled coordinate above 1e150: CDIST_ERR_OUT_OF_RANGE;
 *  - every scaled input and the distance normal doubles (or zero): the unscaled answer times 2^k
 *    exactly (distance bit for bit, the points within 1e-12 L 2^k), and the unscaled answer
 *    within 1e-12 L of the reference (tests/data/KIND_SET.expected);
 *  - otherwise (a scaled input is subnormal, so it is rounded to a few bits): the reference
 *    times 2^k within 1e-12 L 2^k plus the effect of that rounding, at most sqrt(2^-1074 L 2^k)
 *    per input for a tangent-like minimum; and never a non-finite distance with CDIST_OK.
 * usage: test_scaled DATA_DIR */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "circledist.h"

#define TOL 1e-12
#define MAXV 16

/* indices of the numbers scaled by 2^k, per kind */
static const int point_idx[] = {0, 1, 2, 3, 4, 5, 9};          /* P, C, r */
static const int line_idx[] = {0, 1, 2, 6, 7, 8, 12};          /* B, C, r (M unit, unscaled) */
static const int seg_idx[] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 12};  /* P0, P1, C, r */

static cdist_status run(cdist_query *q, const char *kind, const double *v, cdist_result *r)
{
    cdist_vec3 a = {v[0], v[1], v[2]};
    if (kind[0] == 'p') {
        cdist_circle c = {{v[3], v[4], v[5]}, {v[6], v[7], v[8]}, v[9]};
        return kind[1] == 'c' ? cdist_point_circle(q, &a, &c, r) : cdist_point_disk(q, &a, &c, r);
    }
    cdist_vec3 b = {v[3], v[4], v[5]};
    cdist_circle c = {{v[6], v[7], v[8]}, {v[9], v[10], v[11]}, v[12]};
    int disk = kind[1] == 'd';
    if (kind[0] == 'l') {
        cdist_line l = {a, b};
        return disk ? cdist_line_disk(q, &l, &c, r) : cdist_line_circle(q, &l, &c, r);
    }
    if (kind[0] == 'r') {
        cdist_ray l = {a, b};
        return disk ? cdist_ray_disk(q, &l, &c, r) : cdist_ray_circle(q, &l, &c, r);
    }
    cdist_segment s = {a, b};
    return disk ? cdist_segment_disk(q, &s, &c, r) : cdist_segment_circle(q, &s, &c, r);
}

/* The scale L of the shared README (long double, unscaled input). */
static long double scale_of(const char *kind, const double *v, long double expected)
{
    long double L = fabsl(expected);
    if (kind[0] == 'p') {
        long double d2 = 0;
        for (int i = 0; i < 3; i++) d2 += ((long double)v[i] - v[3 + i]) * ((long double)v[i] - v[3 + i]);
        L = fmaxl(L, fmaxl(sqrtl(d2), v[9]));
        return L;
    }
    long double A[3], D[3], dd = 0, t, num = 0;
    for (int i = 0; i < 3; i++) {
        A[i] = (long double)v[i] - v[6 + i];
        D[i] = kind[0] == 's' ? (long double)v[3 + i] - v[i] : (long double)v[3 + i];
        dd += D[i] * D[i];
        num += A[i] * D[i];
    }
    t = dd > 0 ? -num / dd : 0;
    if (kind[0] != 'l' && t < 0) t = 0;
    if (kind[0] == 's' && t > 1) t = 1;
    long double n2 = 0;
    for (int i = 0; i < 3; i++) n2 += (A[i] + t * D[i]) * (A[i] + t * D[i]);
    return fmaxl(L, fmaxl(sqrtl(n2), v[12]));
}

static int ks[64], nks;

static void make_ks(void)
{
    for (int k = -1000; k <= 500; k += 37) ks[nks++] = k;
    const int extra[] = {-1022 + 60, -999, -53, -1, 1, 52, 450, 496, 497, 500};
    for (size_t i = 0; i < sizeof extra / sizeof extra[0]; i++) ks[nks++] = extra[i];
}

static int normal_or_zero(double x) { return x == 0.0 || fabs(x) >= DBL_MIN; }

static void check_file(cdist_query *q, const char *dir, const char *kind, const char *set)
{
    char qf[1024], ef[1024];
    snprintf(qf, sizeof qf, "%s/%s_%s.txt", dir, kind, set);
    snprintf(ef, sizeof ef, "%s/%s_%s.expected", dir, kind, set);
    FILE *fq = fopen(qf, "r"), *fe = fopen(ef, "r");
    CHECK(fq && fe, "cannot open %s or %s", qf, ef);
    if (!fq || !fe) {
        if (fq) fclose(fq);
        if (fe) fclose(fe);
        return;
    }
    const int *idx = kind[0] == 'p' ? point_idx : kind[0] == 's' ? seg_idx : line_idx;
    int nidx = kind[0] == 'p' ? 7 : kind[0] == 's' ? 10 : 7;
    int nval = kind[0] == 'p' ? 10 : 13;
    char line[4096], eline[256];
    long lineno = 0;
    int exact = 0, rounded = 0, range = 0;
    while (fgets(line, sizeof line, fq)) {
        lineno++;
        if (line[0] == '#' || line[0] == '\n') continue;
        if (!fgets(eline, sizeof eline, fe)) break;
        long double expected = strtold(eline, NULL);
        double v[MAXV];
        char *s = line + strlen(kind), *e;
        for (int i = 0; i < nval; i++) {
            v[i] = strtod(s, &e);
            s = e;
        }
        long double L = scale_of(kind, v, expected);
        cdist_result r0, r;
        cdist_status st0 = run(q, kind, v, &r0);
        CHECK(st0 == CDIST_OK, "%s line %ld: unscaled status %d", qf, lineno, (int)st0);
        if (st0) continue;
        CHECK(fabsl(r0.distance - expected) <= TOL * L, "%s line %ld: unscaled %.17g vs reference %.21Lg (L %Lg)", qf,
              lineno, r0.distance, expected, L);
        for (int j = 0; j < nks; j++) {
            int k = ks[j];
            double w[MAXV];
            memcpy(w, v, sizeof w);
            int big = 0, normal = normal_or_zero(ldexp(r0.distance, k));
            for (int i = 0; i < nidx; i++) {
                w[idx[i]] = ldexp(v[idx[i]], k);
                if (fabs(w[idx[i]]) > 1e150) big = 1;
                if (!normal_or_zero(w[idx[i]]) || (v[idx[i]] != 0.0 && w[idx[i]] == 0.0)) normal = 0;
            }
            cdist_status st = run(q, kind, w, &r);
            if (big) {
                CHECK(st == CDIST_ERR_OUT_OF_RANGE, "%s line %ld k %d: status %d, expected out of range", qf, lineno,
                      k, (int)st);
                range++;
                continue;
            }
            CHECK(st == CDIST_OK && isfinite(r.distance), "%s line %ld k %d: status %d distance %g", qf, lineno, k,
                  (int)st, r.distance);
            if (st) continue;
            long double Lk = ldexpl(L, k);
            if (normal) {
                exact++;
                CHECK(r.distance == ldexp(r0.distance, k), "%s line %ld k %d: %.17g is not 2^k times %.17g", qf,
                      lineno, k, r.distance, r0.distance);
                CHECK(r.num_pairs == r0.num_pairs && r.equidistant == r0.equidistant,
                      "%s line %ld k %d: pairs %d/%d equidistant %d/%d", qf, lineno, k, r.num_pairs, r0.num_pairs,
                      r.equidistant, r0.equidistant);
                for (int p = 0; p < 2; p++) {
                    const double *a = &r.pairs[0].point[p].x, *b = &r0.pairs[0].point[p].x;
                    for (int c = 0; c < 3; c++)
                        CHECK(fabsl(a[c] - ldexpl(b[c], k)) <= TOL * Lk, "%s line %ld k %d: point %d coordinate %d", qf,
                              lineno, k, p, c);
                }
            } else {
                rounded++;
                long double allow = TOL * Lk + 10 * sqrtl(0x1p-1074L * Lk) + 0x1p-1070L;
                CHECK(fabsl(r.distance - ldexpl(expected, k)) <= allow,
                      "%s line %ld k %d: %.17g vs reference %.17Lg (allowance %Lg)", qf, lineno, k, r.distance,
                      ldexpl(expected, k), allow);
            }
        }
    }
    printf("%s: %ld lines; %d scaled queries exact, %d with subnormal inputs, %d out of range\n", qf, lineno, exact,
           rounded, range);
    fclose(fq);
    fclose(fe);
}

/* The example of the issue: point and circle at 1e-300. */
static void check_examples(cdist_query *q)
{
    cdist_vec3 p = {3e-300, 4e-300, 12e-300};
    cdist_circle c = {{0, 0, 0}, {0, 0, 1}, 2e-300};
    cdist_result r;
    cdist_status st = cdist_point_circle(q, &p, &c, &r);
    /* rho = 5e-300, h = 12e-300: d = sqrt(3^2 + 12^2) 1e-300 */
    CHECK(st == CDIST_OK && fabs(r.distance - sqrt(153.0) * 1e-300) <= 1e-14 * 1.3e-299 && !r.equidistant,
          "pc at 1e-300: status %d distance %.17g equidistant %d", (int)st, r.distance, r.equidistant);
    /* The same with a subnormal radius and point. */
    cdist_vec3 ps = {3e-310, 4e-310, 0};
    cdist_circle cs = {{0, 0, 0}, {0, 0, 1}, 1e-310};
    st = cdist_point_disk(q, &ps, &cs, &r);
    CHECK(st == CDIST_OK && fabs(r.distance - 4e-310) <= 1e-312, "pd at 1e-310: status %d distance %g", (int)st,
          r.distance);
    /* A segment 1e-300 long next to a circle of radius 1e-300. */
    cdist_segment sg = {{2e-300, 0, -1e-300}, {2e-300, 0, 1e-300}};
    st = cdist_segment_circle(q, &sg, &(cdist_circle){{0, 0, 0}, {0, 0, 1}, 1e-300}, &r);
    CHECK(st == CDIST_OK && fabs(r.distance - 1e-300) <= 1e-314, "sc at 1e-300: status %d distance %.17g", (int)st,
          r.distance);
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: test_scaled DATA_DIR\n");
        return 2;
    }
    make_ks();
    cdist_query *q = cdist_query_new();
    if (!q) return 1;
    check_examples(q);
    const char *kinds[] = {"pc", "pd", "lc", "ld", "rc", "rd", "sc", "sd"};
    const char *sets[] = {"random", "hard"};
    for (int i = 0; i < 8; i++)
        for (int j = 0; j < 2; j++) check_file(q, argv[1], kinds[i], sets[j]);
    cdist_query_free(q);
    return check_summary("test_scaled");
}
