/* SPDX-License-Identifier: MIT */
/* The polynomial module (src/base/poly.c, from the internal library): real roots and guards,
 * checked against GSL's gsl_poly_complex_solve as the independent reference (the library does
 * not link GSL; this test does, with GSL's error handler off: it is the host here). */
#include <gsl/gsl_errno.h>
#include <gsl/gsl_poly.h>

#include "check.h"
#include "base/poly.h"
#include "circledist.h"

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

/* GSL's roots of the same polynomial against ours (`n` roots, imaginary parts up to imag_tol
 * counted as real): every root GSL finds clearly real is among ours, and each of ours is near
 * one of GSL's with a small imaginary part. Near-multiple roots move by about sqrt(eps), hence
 * the tolerances. Inputs GSL does not converge on are counted, not compared. */
static long gsl_compared, gsl_failed;
static void against_gsl(const double *a, int deg, const double *roots, int n, const char *what, int id)
{
    double z[2 * CD_POLY_MAX_DEGREE];
    gsl_poly_complex_workspace *w = gsl_poly_complex_workspace_alloc((size_t)deg + 1);
    int st = w ? gsl_poly_complex_solve(a, (size_t)deg + 1, w, z) : GSL_ENOMEM;
    gsl_poly_complex_workspace_free(w);
    if (st != GSL_SUCCESS) {
        gsl_failed++;
        return;
    }
    gsl_compared++;
    for (int k = 0; k < deg; k++) {
        double re = z[2 * k], im = z[2 * k + 1], s = 1.0 + hypot(re, im), near = INFINITY;
        if (fabs(im) > 1e-12 * s) continue;
        for (int i = 0; i < n; i++) near = fmin(near, fabs(roots[i] - re));
        CHECK(near <= 1e-6 * s, "%s %d: GSL's real root %.17g not found (nearest %.3g away)", what, id, re, near);
    }
    for (int i = 0; i < n; i++) {
        double near = INFINITY;
        for (int k = 0; k < deg; k++) near = fmin(near, hypot(z[2 * k] - roots[i], z[2 * k + 1]));
        CHECK(near <= 1e-6 * (1.0 + fabs(roots[i])), "%s %d: root %.17g is no root of GSL's (nearest %.3g away)", what,
              id, roots[i], near);
    }
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
    /* GSL on the degree the module solves: the two leading coefficients (1e-24, 1e-46 against
     * 1e-2) are negligible and dropped, as the module does; kept, GSL's roots of the near-fourfold
     * cluster at +-0.5033 scatter by 1e-3. */
    if (n >= 0) against_gsl(octic, 6, roots, n, "octic", 0);
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

int main(void)
{
    gsl_set_error_handler_off();
    cdist__poly_ws *ws = cdist__poly_ws_new();
    qr_regressions(ws);
    double roots[8];
    /* (x-1)(x-2)(x-3)(x+4) = x^4 - 2x^3 - 13x^2 + 38x - 24 */
    double q4[5] = {-24, 38, -13, -2, 1};
    int n = cdist__poly_real_roots(ws, q4, 4, 1e-8, roots);
    CHECK(n == 4, "quartic roots %d", n);
    if (n >= 0) against_gsl(q4, 4, roots, n, "quartic", 0);
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
    if (n >= 0) against_gsl(even8, 8, roots, n, "nearly even octic", 0);
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
        if (n >= 0) against_gsl(a, deg, roots, n, "random polynomial", it);
    }
    cdist__poly_ws_free(ws);
    printf("test_poly: %ld polynomials compared with GSL's roots, %ld on which GSL did not converge\n", gsl_compared,
           gsl_failed);
    CHECK(gsl_compared >= 19000, "compared with GSL %ld times", gsl_compared);
    return check_summary("test_poly");
}
