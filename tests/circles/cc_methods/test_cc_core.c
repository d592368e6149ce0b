/* SPDX-License-Identifier: MIT */
/* The polynomial and iteration cores called directly (the library's sources are compiled into
 * this test), so that a method failure cannot hide behind the dispatcher's fallback to the
 * robust method: every line of the reference files must be answered by the method itself with
 * CDIST_OK. The two methods, which share only the Newton finish, must agree to a few ulps of
 * scale, and the iteration count must lie in [0, cap].
 * usage: test_cc_core FILE... */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "internal.h"

static int run_file(cdist_query *q, const char *path)
{
    FILE *f = fopen(path, "r");
    CHECK(f != NULL, "cannot open %s", path);
    if (!f) return 0;
    char line[2048];
    int n = 0, lineno = 0;
    double worst = 0;
    while (fgets(line, sizeof line, f)) {
        lineno++;
        cdist_circle A, B;
        char kind[8];
        if (sscanf(line, "%7s %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf", kind, &A.center.x,
                   &A.center.y, &A.center.z, &A.normal.x, &A.normal.y, &A.normal.z, &A.radius, &B.center.x,
                   &B.center.y, &B.center.z, &B.normal.x, &B.normal.y, &B.normal.z, &B.radius) != 15 ||
            strcmp(kind, "cc"))
            continue;
        cdist__circle a, b;
        CHECK(cdist__check_circle(q, &A, "a", &a) == CDIST_OK && cdist__check_circle(q, &B, "b", &b) == CDIST_OK,
              "%s:%d: invalid circles", path, lineno);
        b.c = v_sub(b.c, a.c);
        a.c = v3(0, 0, 0);
        double L = fmax(fmax(a.r, b.r), v_norm(b.c));
        cdist__best bp, bi;
        cdist__best_init(&bp, L);
        cdist__best_init(&bi, L);
        int iters = -1;
        cdist_status sp = cdist__cc_polynomial(q, &a, &b, &bp);
        cdist_status si = cdist__cc_iteration(q, &a, &b, &bi, &iters);
        CHECK(sp == CDIST_OK && bp.n >= 1, "%s:%d: polynomial failed (%s)", path, lineno, cdist_query_last_error(q));
        CHECK(si == CDIST_OK && bi.n >= 1, "%s:%d: iteration failed (%s)", path, lineno, cdist_query_last_error(q));
        CHECK(iters >= 0 && iters <= q->max_iterations, "%s:%d: iterations %d", path, lineno, iters);
        if (sp == CDIST_OK && si == CDIST_OK && bp.n && bi.n) {
            double e = fabs(sqrt(bp.c[0].d2) - sqrt(bi.c[0].d2)) / (L > 0 ? L : 1);
            worst = fmax(worst, e);
            CHECK(e <= 16 * DBL_EPSILON, "%s:%d: polynomial %.17g vs iteration %.17g", path, lineno,
                  sqrt(bp.c[0].d2), sqrt(bi.c[0].d2));
            CHECK(bp.equidistant == bi.equidistant, "%s:%d: equidistant flags differ", path, lineno);
        }
        n++;
    }
    fclose(f);
    printf("%s: %d queries answered by both methods, max disagreement %.3g of scale\n", path, n, worst);
    return n;
}

int main(int argc, char **argv)
{
    cdist_query *q = cdist_query_new();
    for (int i = 1; i < argc; i++) CHECK(run_file(q, argv[i]) > 0, "%s: no queries", argv[i]);
    cdist_query_free(q);
    return check_summary("cc_core");
}
