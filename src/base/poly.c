/* SPDX-License-Identifier: MIT */
/* Polynomial roots through gsl_poly_complex_solve, guarded so that GSL's error handler is never
 * reached, with a shift for nearly even polynomials (why and how: docs/architecture.md,
 * "Polynomial roots (GSL)"). */
#include "base/poly.h"
#include "base/roots.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>

#include <gsl/gsl_poly.h>

/* Relative size of the symmetry-breaking shift (see the top comment). */
#define CD_POLY_SHIFT 0.0377438833

struct cdist__poly_ws {
    /* ws[d] solves degree d (d + 1 coefficients), for 2 <= d <= CD_POLY_MAX_DEGREE. */
    gsl_poly_complex_workspace ws[CD_POLY_MAX_DEGREE + 1];
    double matrix[CD_POLY_MAX_DEGREE * CD_POLY_MAX_DEGREE * (CD_POLY_MAX_DEGREE + 1)];
};

cdist__poly_ws *cdist__poly_ws_new(void)
{
    cdist__poly_ws *w = calloc(1, sizeof *w);
    if (!w) return NULL;
    double *m = w->matrix;
    for (int d = 2; d <= CD_POLY_MAX_DEGREE; d++) {
        w->ws[d].nc = (size_t)d; /* GSL wants nc == n - 1 == degree */
        w->ws[d].matrix = m;
        m += d * d;
    }
    return w;
}

void cdist__poly_ws_free(cdist__poly_ws *ws) { free(ws); }

double cdist__poly_eval(const double *coef, int degree, double x, double *deriv)
{
    double p = coef[degree], dp = 0.0;
    for (int i = degree - 1; i >= 0; i--) {
        dp = fma(dp, x, p);
        p = fma(p, x, coef[i]);
    }
    if (deriv) *deriv = dp;
    return p;
}

static void sort_ascending(double *x, int n)
{
    for (int i = 1; i < n; i++) {
        double v = x[i];
        int j = i - 1;
        while (j >= 0 && x[j] > v) {
            x[j + 1] = x[j];
            j--;
        }
        x[j + 1] = v;
    }
}

typedef struct poly_ref {
    const double *a;
    int deg;
} poly_ref;

static double poly_fdf(const void *ctx, double x, double *df)
{
    const poly_ref *p = ctx;
    return cdist__poly_eval(p->a, p->deg, x, df);
}

/* A few Newton steps on the polynomial; a step is kept only while it reduces |p|. */
static double polish(const double *a, int deg, double x)
{
    poly_ref p = {a, deg};
    return cdist__root_polish(poly_fdf, &p, x, 0.0, 0.0, 4);
}

/* Fujiwara's bound on the moduli of the roots of sum a[i] x^i (a[n] != 0). */
static double root_bound(const double *a, int n)
{
    double m = 0.0;
    for (int i = 0; i < n; i++) {
        double v = pow(fabs(a[i] / a[n]), 1.0 / (n - i));
        if (i == 0) v *= 0.5; /* 2 |a0 / 2an|^(1/n) */
        if (v > m) m = v;
    }
    return 2.0 * m;
}

/* The failure mode seen: a polynomial that is nearly even (or odd), so its roots come in pairs
 * +-x of equal modulus. Only such polynomials are shifted; others are solved as they are. */
static int nearly_even_or_odd(const double *a, int n)
{
    double even = 0.0, odd = 0.0;
    for (int i = 0; i <= n; i++) {
        if (i % 2) odd = fmax(odd, fabs(a[i]));
        else even = fmax(even, fabs(a[i]));
    }
    return fmin(even, odd) <= CD_POLY_EVEN_REL * fmax(even, odd);
}

/* c(y) = a(y + s): synthetic division (Horner's scheme) n times, O(n^2). */
static void taylor_shift(const double *a, int n, double s, double *c)
{
    for (int i = 0; i <= n; i++) c[i] = a[i];
    for (int i = 0; i < n; i++)
        for (int j = n - 1; j >= i; j--) c[j] = fma(s, c[j + 1], c[j]);
}

int cdist__poly_real_roots(cdist__poly_ws *ws, const double *coef, int degree, double imag_tol, double *roots)
{
    if (!ws || degree < 0 || degree > CD_POLY_MAX_DEGREE) return CD_POLY_FAIL;
    double a[CD_POLY_MAX_DEGREE + 1];
    double maxc = 0.0;
    for (int i = 0; i <= degree; i++) {
        if (!isfinite(coef[i])) return CD_POLY_FAIL;
        if (fabs(coef[i]) > maxc) maxc = fabs(coef[i]);
    }
    if (maxc == 0.0) return CD_POLY_ZERO;
    /* Normalise (roots unchanged), then drop leading coefficients that are rounding noise
     * relative to the largest: they only contribute roots of magnitude ~1/eps. */
    for (int i = 0; i <= degree; i++) a[i] = coef[i] / maxc;
    int deg = degree;
    while (deg > 0 && fabs(a[deg]) <= CD_POLY_LEAD_ULPS * DBL_EPSILON) deg--;
    int n = 0;
    /* Exact zero constant terms: roots at 0, factored out. */
    int low = 0;
    while (low < deg && a[low] == 0.0) low++;
    if (low > 0) roots[n++] = 0.0;
    const double *b = a + low;
    int bd = deg - low;
    if (bd == 1) {
        roots[n++] = -b[0] / b[1];
    } else if (bd >= 2) {
        double z[2 * CD_POLY_MAX_DEGREE], c[CD_POLY_MAX_DEGREE + 1];
        double s = nearly_even_or_odd(b, bd) ? CD_POLY_SHIFT * root_bound(b, bd) : 0.0;
        taylor_shift(b, bd, s, c);
        if (!isfinite(c[0]) || c[bd] == 0.0) return CD_POLY_FAIL;
        if (gsl_poly_complex_solve(c, (size_t)bd + 1, &ws->ws[bd], z) != 0) return CD_POLY_FAIL;
        for (int i = 0; i < bd; i++) {
            double re = z[2 * i] + s, im = z[2 * i + 1];
            if (!isfinite(re) || !isfinite(im)) continue;
            if (fabs(im) <= imag_tol * (1.0 + hypot(re, im))) roots[n++] = polish(b, bd, re);
        }
    }
    sort_ascending(roots, n);
    return n;
}
