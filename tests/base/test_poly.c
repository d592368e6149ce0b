/* SPDX-License-Identifier: MIT */
/* The polynomial module (src/base/poly.c, from the internal library): real roots, guards, and the
 * GSL error handler is never reached nor changed. The test is the host here, so it installs a
 * counting handler of its own: any call to it is a failure. */
#include <gsl/gsl_errno.h>

#include <string.h>

#include "check.h"
#include "base/poly.h"
#include "circledist.h"

static int handler_calls;
static void counting_handler(const char *reason, const char *file, int line, int err)
{
    (void)file; (void)line; (void)err;
    fprintf(stderr, "GSL error handler called: %s\n", reason);
    handler_calls++;
}

/* max |p(root)| / (sum |a_i| |root|^i): relative residual */
static double rel_residual(const double *a, int n, double x)
{
    double p = 0, s = 0;
    for (int i = n; i >= 0; i--) {
        p = p * x + a[i];
        s = s * fabs(x) + fabs(a[i]);
    }
    return fabs(p) / s;
}

/* Inputs on which gsl_poly_complex_solve failed to converge (its error handler aborted the
 * process): the octic of a circle-circle query, and the query itself under POLYNOMIAL. */
static void qr_regressions(cdist__poly_ws *ws)
{
    double octic[9] = {-0.00055781227743234379, -8.7986697896803222e-06, 0.0051513604888113766,
                       6.9469415138111138e-05,  -0.014592585164581878,   -0.00013712299003684793,
                       0.01164450275251055,     5.748746786380097e-24,   8.7742798601605494e-46};
    double roots[8];
    int n = cdist__poly_real_roots(ws, octic, 8, 1e-6, roots);
    CHECK(n >= 1, "octic of the circle-circle query solved (%d)", n);
    for (int i = 0; i < n; i++) CHECK(rel_residual(octic, 8, roots[i]) < 1e-12, "octic root residual");
    cdist_circle c0 = {{0, 0, 0}, {0, 0, 1}, 1};
    cdist_circle c1 = {{1.1169167390820272, -1.9176268644667807, -7.9374918668142605e-11},
                       {-2.5585250546652929e-11, 2.3743154905492666e-11, 1},
                       2.4234011543210277};
    cdist_query *q = cdist_query_new();
    cdist_result rp, rr;
    CHECK(q && cdist_query_set_method(q, CDIST_METHOD_POLYNOMIAL) == CDIST_OK, "polynomial method");
    cdist_status sp = cdist_circle_circle(q, &c0, &c1, &rp);
    CHECK(q && cdist_query_set_method(q, CDIST_METHOD_ROBUST) == CDIST_OK, "robust method");
    cdist_status sr = cdist_circle_circle(q, &c0, &c1, &rr);
    CHECK(sp == CDIST_OK && rp.method == CDIST_METHOD_POLYNOMIAL, "answered by POLYNOMIAL (%d, %d)", (int)sp, rp.method);
    CHECK(sr == CDIST_OK && fabs(rp.distance - rr.distance) <= 1e-15, "distance %.17g vs robust %.17g", rp.distance, rr.distance);
    cdist_query_free(q);
}

int main(int argc, char **argv)
{
    /* With "default-handler" GSL's handler stays the default (abort): a call to it crashes the
     * test, whatever the checks. */
    if (argc > 1 && strcmp(argv[1], "default-handler") == 0) {
        cdist__poly_ws *ws = cdist__poly_ws_new();
        qr_regressions(ws);
        cdist__poly_ws_free(ws);
        return check_summary("test_poly default-handler");
    }
    gsl_set_error_handler(counting_handler);
    cdist__poly_ws *ws = cdist__poly_ws_new();
    qr_regressions(ws);
    double roots[8];
    /* (x-1)(x-2)(x-3)(x+4) = x^4 - 2x^3 - 13x^2 + 38x - 24 */
    double q4[5] = {-24, 38, -13, -2, 1};
    int n = cdist__poly_real_roots(ws, q4, 4, 1e-8, roots);
    CHECK(n == 4, "quartic roots %d", n);
    if (n == 4) {
        CHECK_NEAR(roots[0], -4, 1e-14, "root -4");
        CHECK_NEAR(roots[1], 1, 1e-14, "root 1");
        CHECK_NEAR(roots[2], 2, 1e-14, "root 2");
        CHECK_NEAR(roots[3], 3, 1e-14, "root 3");
    }
    /* Vanishing leading coefficients are dropped; zero constant terms give root 0. */
    double lead0[5] = {0, -2, 1, 0, 0}; /* x^2 - 2x */
    n = cdist__poly_real_roots(ws, lead0, 4, 1e-8, roots);
    CHECK(n == 2 && roots[0] == 0.0 && fabs(roots[1] - 2) < 1e-15, "dropped leading zeros: %d", n);
    double zero[3] = {0, 0, 0};
    CHECK(cdist__poly_real_roots(ws, zero, 2, 1e-8, roots) == CD_POLY_ZERO, "zero polynomial");
    double bad[3] = {1, NAN, 1};
    CHECK(cdist__poly_real_roots(ws, bad, 2, 1e-8, roots) == CD_POLY_FAIL, "NaN coefficient");
    double inf[3] = {1, 0, INFINITY};
    CHECK(cdist__poly_real_roots(ws, inf, 2, 1e-8, roots) == CD_POLY_FAIL, "Inf coefficient");
    CHECK(cdist__poly_real_roots(ws, q4, 9, 1e-8, roots) == CD_POLY_FAIL, "degree too high");
    CHECK(cdist__poly_real_roots(NULL, q4, 4, 1e-8, roots) == CD_POLY_FAIL, "no workspace");
    double constant[1] = {3};
    CHECK(cdist__poly_real_roots(ws, constant, 0, 1e-8, roots) == 0, "constant");
    /* The nearly even degree-8 polynomial on which GSL's QR failed to converge unshifted (equal
     * circles concentric to 1e-12 in different planes). */
    double even8[9] = {0.012685339533715968, 1.1173386777584377e-10, -0.15928175999602698, -8.9386063812693968e-10,
                       0.65928175999602701,  1.9092510231177577e-09, -1, -1.2077653804513858e-09, 0.5};
    n = cdist__poly_real_roots(ws, even8, 8, 1e-6, roots);
    CHECK(n >= 0, "nearly even octic solved (%d)", n);
    for (int i = 0; i < n; i++) CHECK(rel_residual(even8, 8, roots[i]) < 1e-12, "octic root residual");
    /* Random nearly even / odd / exactly even / dense polynomials of every degree. */
    for (int it = 0; it < 20000; it++) {
        int deg = 2 + it % 7;
        double a[9];
        for (int i = 0; i <= deg; i++) {
            double r = srand1();
            int mode = (it / 7) % 4;
            a[i] = mode == 0 ? r : mode == 1 ? ((i % 2) ? 0 : r) : mode == 2 ? ((i % 2) ? r * 1e-11 : r) : ((i % 2) ? r : r * 1e-11);
        }
        a[deg] = 0.5 + urand();
        n = cdist__poly_real_roots(ws, a, deg, 1e-8, roots);
        CHECK(n >= 0 && n <= deg, "random polynomial %d: %d roots", it, n);
        for (int i = 0; i < n; i++) CHECK(rel_residual(a, deg, roots[i]) < 1e-9, "random root residual");
    }
    cdist__poly_ws_free(ws);
    CHECK(handler_calls == 0, "GSL's error handler was called %d times", handler_calls);
    /* The module never changes the handler: ours is still installed. */
    CHECK(gsl_set_error_handler(NULL) == counting_handler, "handler unchanged");
    return check_summary("test_poly");
}
