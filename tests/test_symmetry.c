/* SPDX-License-Identifier: MIT */
/* f(a, b) = f(b, a) on every reference file: each query of a kind whose two objects have the
 * same layout (cc, dd, aa; cdq_swapped) is run in both argument orders under every method, and
 * both answers must have the same status, pair count and equidistant flag, and distances within
 * 4 eps L of each other (L the problem scale of ../shared/cases/README.md, cdq_scale; arc pairs to
 * the bit). Every
 * cc line also runs as torus-torus and every dd line as rounded disk - rounded disk (tube and
 * rounding radii 1/8 and 1/16 of the radii: swept objects keep the core's decisions). Files of
 * other kinds have no swapped counterpart in the API and are counted as skipped.
 * Constructed regressions: parallel capsules overlapping over a short part of a very long one,
 * near-identical circles, a circle pair whose tie the polynomial method decided per order, and
 * arcs whose near tie was decided per order.
 * usage: test_symmetry DATA_DIR */
#include <dirent.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "query_io.h"

static cdist_query *q;
static long n_pairs_checked;

/* One query in both orders; where: for the messages. Returns 1 when both agree. */
static int both_orders(const cdq_line *ql, const char *where)
{
    cdq_line sw;
    if (!cdq_swapped(ql, &sw)) return 0;
    cdist_result r0, r1;
    cdist_status s0 = cdq_run(q, ql, &r0), s1 = cdq_run(q, &sw, &r1);
    n_pairs_checked++;
    if (s0 != s1) {
        CHECK(0, "%s: status %s, swapped %s", where, cdist_status_name(s0), cdist_status_name(s1));
        return 0;
    }
    if (s0 != CDIST_OK) return 1;
    double L = cdq_scale(ql, fabs(r0.distance));
    int ok = fabs(r0.distance - r1.distance) <= 4.0 * DBL_EPSILON * L && r0.num_pairs == r1.num_pairs &&
             r0.equidistant == r1.equidistant;
    /* Arcs are put in lexicographic order before anything is computed: the same bits. */
    if (!strcmp(ql->kind->name, "aa")) ok = ok && r0.distance == r1.distance;
    CHECK(ok, "%s (method %d): distance %.17g / %.17g (scale %g), %d / %d pairs, equidistant %d / %d", where,
          (int)cdist_query_get_method(q), r0.distance, r1.distance, L, r0.num_pairs, r1.num_pairs, r0.equidistant,
          r1.equidistant);
    return ok;
}

/* A swept kind built from a line of circles: kind "TT" from cc (centre, normal, radius, tube),
 * "RR" from dd (the same layout). */
static int as_swept(const cdq_line *ql, cdq_line *out)
{
    const char *k = ql->kind->name, *to = !strcmp(k, "cc") ? "TT" : (!strcmp(k, "dd") ? "RR" : NULL);
    if (!to) return 0;
    char err[64], text[64];
    snprintf(text, sizeof text, "%s", to);
    if (cdq_parse(strcat(text, " 0 0 0 0 0 1 1 0 0 0 0 0 0 1 1 0"), out, err, sizeof err) != 1) return 0;
    for (int h = 0; h < 2; h++) {
        memcpy(out->v + 8 * h, ql->v + 7 * h, 7 * sizeof(double));
        out->v[8 * h + 7] = ql->v[7 * h + 6] / (h ? 16 : 8);
    }
    return 1;
}

static void run_file(const char *dir, const char *name)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "r");
    CHECK(f != NULL, "cannot open %s", path);
    if (!f) return;
    char line[4096];
    int lineno = 0, checked = 0, skipped = 0, bad = 0;
    while (fgets(line, sizeof line, f)) {
        lineno++;
        cdq_line ql, sw;
        char err[256];
        if (cdq_parse(line, &ql, err, sizeof err) != 1) continue;
        if (!cdq_swapped(&ql, &sw)) {
            skipped++;
            continue;
        }
        char where[1200];
        for (int m = 0; m < 4; m++) {
            cdist_query_set_method(q, (cdist_method)m);
            snprintf(where, sizeof where, "%s:%d", name, lineno);
            bad += !both_orders(&ql, where);
            cdq_line swept;
            if (as_swept(&ql, &swept)) {
                snprintf(where, sizeof where, "%s:%d as %s", name, lineno, swept.kind->name);
                bad += !both_orders(&swept, where);
            }
        }
        cdist_query_set_method(q, CDIST_METHOD_AUTO);
        checked++;
    }
    fclose(f);
    printf("%-26s %5d queries in both orders (x 4 methods), %d disagree; %d without a swapped kind\n", name, checked,
           bad, skipped);
}

static int by_name(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

/* Constructed lines: the answer in both orders, and the expected equidistant flag and pair count
 * (-1: not asserted). */
static void constructed(const char *text, int equidistant, int pairs, int method)
{
    cdq_line ql;
    char err[256];
    CHECK(cdq_parse(text, &ql, err, sizeof err) == 1, "parse %s: %s", text, err);
    cdist_query_set_method(q, (cdist_method)method);
    cdist_query_set_unit_tolerance(q, INFINITY);
    both_orders(&ql, text);
    cdist_result r;
    CHECK(cdq_run(q, &ql, &r) == CDIST_OK, "%s: status", text);
    if (equidistant >= 0) CHECK(r.equidistant == equidistant, "%s: equidistant %d, expected %d", text, r.equidistant, equidistant);
    if (pairs >= 0) CHECK(r.num_pairs == pairs, "%s: %d pairs, expected %d", text, r.num_pairs, pairs);
    cdist_query_set_method(q, CDIST_METHOD_AUTO);
    cdist_query_set_unit_tolerance(q, 1e-6);
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : "tests/data";
    q = cdist_query_new();
    DIR *d = opendir(dir);
    CHECK(d != NULL, "cannot open %s", dir);
    char *names[256];
    int n = 0;
    for (struct dirent *e; d && (e = readdir(d)) && n < 256;) {
        size_t len = strlen(e->d_name);
        if (len > 4 && !strcmp(e->d_name + len - 4, ".txt")) names[n++] = strdup(e->d_name);
    }
    if (d) closedir(d);
    qsort(names, n, sizeof names[0], by_name);
    CHECK(n >= 30, "only %d reference files in %s", n, dir);
    for (int i = 0; i < n; i++) {
        run_file(dir, names[i]);
        free(names[i]);
    }
    /* Parallel capsule axes overlapping over z in [-2, 9.9e-8]: a segment of closest pairs, so
     * equidistant in both orders (the overlap was measured in units of the longer segment). */
    constructed("KK 5 0 -1e+100 5 0 9.9e-08 0 1 0 5 1 0 -2 0", 1, 1, 0);
    /* A segment of length 2e-47 against one of length 2e115 at a large angle: not parallel in
     * either order (scaled together, the short one's direction underflowed in one order only;
     * fuzzing) */
    constructed("KK 1.3808057678557591e-47 1.4273774922216749e-71 6.99532952516786e-77 2.5270009609557079e-52 "
                "1.2468982170859502e-47 1.3808047238042771e-47 1.4273774922216749e-71 6.99532952516786e-77 "
                "2.5270012596604412e-52 -1.416009635817783e+115 -1.4679178779048922e+115 0.00047375244252740922 "
                "1.5204758982242148e-52 1.6561016059396399e-47",
                0, 1, 0);
    /* ... and collinear ones that only touch end to end: one closest pair */
    constructed("KK 0 0 0 0 0 1 0 0 0 1 0 0 3 0", 0, 1, 0);
    /* Equal coplanar circles whose centres are 1.1e-14 apart (radius 100): within the stated
     * equidistance tolerance (32 eps L), one equidistant pair under every method and order. */
    for (int m = 0; m < 4; m++) constructed("cc 10 0 0 0 0 1 100 10.000000000000011 0 0 0 0 1 100", 1, 1, m);
    /* Two nearly tied minima at 1e64 with non-unit normals: the polynomial and iteration methods
     * counted one pair in one order and two in the other (fuzzing). */
    for (int m = 0; m < 4; m++)
        constructed("cc 6.0270637511294368e+63 2.4516417267759531e+64 2.4108255004517747e+64 2.4108255004517747e+64 "
                    "2.4108255004517797e+64 2.4108255004517747e+64 2.4108255004517747e+64 2.41082550077743e+64 "
                    "2.4108255004517747e+64 2.4108255004513258e+64 2.4108255004517747e+64 2.4108255004517747e+64 "
                    "2.4108255004517797e+64 2.4108255016394588e+64",
                    0, -1, m);
    /* An arc of radius 0.47 near the centre of an arc of radius 3.8e13: the distance varies by 3e-14
     * of itself along the small arc, a near tie that was framed from the first arc and decided
     * per order (two pairs in one order, one in the other; fuzzing). */
    for (int m = 0; m < 4; m++)
        constructed(
                "aa 0.39895676931027224 0.5224792785671786 0.6261565000760978 0.2622876215278672 0.8646153324565261 "
                "0.4285388319328195 0.466008185766032 0.4842590053606674 -0.8640874185750406 -0.1372812761720248 "
                "-2.6666587390468575 1.5745029410586993 -0.6194335836742999 -1.8404952278911693 -1.881610527444844 "
                "0.20871860779753282 -0.33069319078066123 0.9203687067313647 38489143690508.0 0.9999999990958548 "
                "-3.855556141833852e-05 -1.793764429389198e-05 2.992264633846098 5.331391286495808",
            -1, -1, m);
    printf("%ld queries compared in both orders\n", n_pairs_checked);
    cdist_query_free(q);
    return check_summary("symmetry");
}
