/* SPDX-License-Identifier: MIT */
/* The bare GSL solve of a degree-8 polynomial (companion matrix QR), for comparison with the
 * circle-circle polynomial method in bench_all (min of 5 rounds).
 * usage: bench_gsl_poly [REPEATS] */
#define _POSIX_C_SOURCE 200809L
#include <gsl/gsl_errno.h>
#include <gsl/gsl_poly.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts); /* CPU time: robust to a loaded machine */
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

int main(int argc, char **argv)
{
    int reps = argc > 1 ? atoi(argv[1]) : 100;
    if (reps < 1) reps = 1;
    int rounds = reps >= 5 ? 5 : 1, per = reps >= 5 ? reps / 5 : reps;
    double sink = 0;
    /* Bare GSL degree-8 solve (companion matrix QR) on polynomials with random coefficients. */
    gsl_error_handler_t *old = gsl_set_error_handler_off();
    gsl_poly_complex_workspace *ws = gsl_poly_complex_workspace_alloc(9);
    enum { NP = 256 };
    static double coef[NP][9], z[16];
    unsigned long long s = 88172645463325252ull;
    for (int i = 0; i < NP; i++)
        for (int j = 0; j < 9; j++) {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            coef[i][j] = (double)(s >> 11) / 9007199254740992.0 * 2 - 1;
        }
    int gfail = 0;
    double tg = INFINITY;
    long m = 0;
    for (int round = 0; round < rounds; round++) {
        double t0 = now();
        long mm = 0;
        for (int rep = 0; rep < per * 8; rep++)
            for (int i = 0; i < NP; i++, mm++) {
                if (gsl_poly_complex_solve(coef[i], 9, ws, z) != GSL_SUCCESS) gfail++;
                sink += z[0];
            }
        double t = (now() - t0) / mm;
        if (t < tg) tg = t;
        m += mm;
    }
    printf("gsl_poly_complex_solve degree 8: %8.1f ns/solve (%ld solves, %d failures)\n", 1e9 * tg, m, gfail);
    gsl_poly_complex_workspace_free(ws);
    gsl_set_error_handler(old);
    return (gfail || !isfinite(sink)) ? 1 : 0;
}
