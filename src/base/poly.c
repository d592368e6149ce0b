/* SPDX-License-Identifier: MIT */
/* Polynomial roots as the eigenvalues of the balanced companion matrix, by the library's own
 * Francis double-shift QR (EISPACK hqr), which returns a status when it does not converge: no
 * GSL call, so GSL's error handler cannot be reached (why not gsl_poly_complex_solve nor
 * gsl_eigen_nonsymm: docs/architecture.md, "Polynomial roots"). Nearly even polynomials are
 * shifted first. */
#include "base/poly.h"
#include "base/roots.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>


struct cdist__poly_ws {
    double h[CD_POLY_MAX_DEGREE * CD_POLY_MAX_DEGREE]; /* the companion matrix, row-major */
};

cdist__poly_ws *cdist__poly_ws_new(void) { return calloc(1, sizeof(cdist__poly_ws)); }

void cdist__poly_ws_free(cdist__poly_ws *ws) { free(ws); }

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

/* Horner evaluation of the polynomial and its derivative (*df): the polishing's callback. */
static double poly_fdf(const void *ctx, double x, double *df)
{
    const poly_ref *p = ctx;
    double v = p->a[p->deg], dv = 0.0;
    for (int i = p->deg - 1; i >= 0; i--) {
        dv = fma(dv, x, v);
        v = fma(v, x, p->a[i]);
    }
    *df = dv;
    return v;
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

/* The hard case for shifted QR: a polynomial that is nearly even (or odd), so its roots come in
 * pairs +-x of equal modulus. Only such polynomials are shifted; others are solved as they are. */
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

/* Parlett-Reinsch balancing of the n x n h by powers of 2 (exact: eigenvalues unchanged).
 * Each accepted scaling shrinks the row + column norm by 5%, so sweeps end; capped anyway. */
static void balance(double *h, int n)
{
    for (int sweep = 0, done = 0; !done && sweep < 64; sweep++) {
        done = 1;
        for (int i = 0; i < n; i++) {
            double c = 0.0, r = 0.0;
            for (int j = 0; j < n; j++)
                if (j != i) {
                    c += fabs(h[j * n + i]);
                    r += fabs(h[i * n + j]);
                }
            if (c == 0.0 || r == 0.0 || !isfinite(c + r)) continue;
            double g = r * 0.5, f = 1.0, s = c + r;
            while (c < g) {
                f *= 2.0;
                c *= 4.0;
            }
            g = r * 2.0;
            while (c >= g) {
                f *= 0.5;
                c *= 0.25;
            }
            if ((c + r) / f < 0.95 * s) {
                done = 0;
                g = 1.0 / f;
                for (int j = 0; j < n; j++) h[i * n + j] *= g;
                for (int j = 0; j < n; j++) h[j * n + i] *= f;
            }
        }
    }
}

#define H(i, j) h[(i) * n + (j)]
/* Eigenvalues (wr + i wi) of the upper Hessenberg h (n x n, row-major, overwritten): Francis
 * double-shift QR (EISPACK hqr), exceptional shifts every 10 sweeps. A subdiagonal element is
 * negligible below eps times its two diagonal neighbours (LAPACK's test) or, after 10 sweeps,
 * eps times the matrix's norm (still backward stable: clustered roots stall above the local
 * test). Every loop is bounded (CD_POLY_QR_ITS sweeps a root); returns -1 when they did not
 * suffice (NaNs end there too). */
static int hessenberg_qr(double *h, int n, double *wr, double *wi)
{
    double norm = 0.0, t = 0.0;
    for (int i = 0; i < n; i++)
        for (int j = i > 0 ? i - 1 : 0; j < n; j++) norm += fabs(H(i, j));
    int en = n - 1;
    while (en >= 0) {
        int its = 0, na = en - 1, enm2 = na - 1;
        for (;;) {
            /* l: the top of the unreduced block ending at en. */
            int l;
            for (l = en; l > 0; l--) {
                double s = fabs(H(l - 1, l - 1)) + fabs(H(l, l));
                if (s == 0.0) s = norm;
                double sub = fabs(H(l, l - 1));
                if (sub <= DBL_EPSILON * s || (its >= 10 && sub <= DBL_EPSILON * norm)) break;
            }
            double x = H(en, en);
            if (l == en) { /* one real root */
                wr[en] = x + t;
                wi[en] = 0.0;
                en = na;
                break;
            }
            double y = H(na, na), w = H(en, na) * H(na, en);
            if (l == na) { /* two roots */
                double p = (y - x) * 0.5, q = p * p + w, zz = sqrt(fabs(q));
                x += t;
                if (q >= 0.0) {
                    zz = p + copysign(zz, p);
                    wr[na] = x + zz;
                    wr[en] = zz != 0.0 ? x - w / zz : wr[na];
                    wi[na] = wi[en] = 0.0;
                } else {
                    wr[na] = wr[en] = x + p;
                    wi[na] = zz;
                    wi[en] = -zz;
                }
                en = enm2;
                break;
            }
            if (its == CD_POLY_QR_ITS) return -1;
            if (its > 0 && its % 10 == 0) { /* exceptional shift */
                t += x;
                for (int i = 0; i <= en; i++) H(i, i) -= x;
                double s = fabs(H(en, na)) + fabs(H(na, enm2));
                x = y = 0.75 * s;
                w = -0.4375 * s * s;
            }
            its++;
            /* m: where two consecutive small subdiagonal elements let the sweep start. */
            int m;
            double p = 0.0, q = 0.0, r = 0.0;
            for (m = enm2; m >= l; m--) {
                double zz = H(m, m), rr = x - zz, ss = y - zz;
                p = (rr * ss - w) / H(m + 1, m) + H(m, m + 1);
                q = H(m + 1, m + 1) - zz - rr - ss;
                r = H(m + 2, m + 1);
                double s = fabs(p) + fabs(q) + fabs(r);
                p /= s;
                q /= s;
                r /= s;
                if (m == l) break;
                double tst1 = fabs(p) * (fabs(H(m - 1, m - 1)) + fabs(zz) + fabs(H(m + 1, m + 1)));
                if (tst1 + fabs(H(m, m - 1)) * (fabs(q) + fabs(r)) == tst1) break;
            }
            for (int i = m + 2; i <= en; i++) {
                H(i, i - 2) = 0.0;
                if (i != m + 2) H(i, i - 3) = 0.0;
            }
            /* The double QR step on rows and columns l..en, chasing the bulge from m. */
            for (int k = m; k <= na; k++) {
                int notlast = k != na;
                if (k != m) {
                    p = H(k, k - 1);
                    q = H(k + 1, k - 1);
                    r = notlast ? H(k + 2, k - 1) : 0.0;
                    x = fabs(p) + fabs(q) + fabs(r);
                    if (x == 0.0) continue;
                    p /= x;
                    q /= x;
                    r /= x;
                }
                double s = copysign(sqrt(p * p + q * q + r * r), p);
                if (k != m) H(k, k - 1) = -s * x;
                else if (l != m) H(k, k - 1) = -H(k, k - 1);
                p += s;
                x = p / s;
                y = q / s;
                double zz = r / s;
                q /= p;
                r /= p;
                int imax = en < k + 3 ? en : k + 3;
                if (notlast) {
                    for (int j = k; j <= en; j++) {
                        p = H(k, j) + q * H(k + 1, j) + r * H(k + 2, j);
                        H(k, j) -= p * x;
                        H(k + 1, j) -= p * y;
                        H(k + 2, j) -= p * zz;
                    }
                    for (int i = l; i <= imax; i++) {
                        p = x * H(i, k) + y * H(i, k + 1) + zz * H(i, k + 2);
                        H(i, k) -= p;
                        H(i, k + 1) -= p * q;
                        H(i, k + 2) -= p * r;
                    }
                } else {
                    for (int j = k; j <= en; j++) {
                        p = H(k, j) + q * H(k + 1, j);
                        H(k, j) -= p * x;
                        H(k + 1, j) -= p * y;
                    }
                    for (int i = l; i <= imax; i++) {
                        p = x * H(i, k) + y * H(i, k + 1);
                        H(i, k) -= p;
                        H(i, k + 1) -= p * q;
                    }
                }
            }
        }
    }
    return 0;
}
#undef H

/* Roots of sum c[i] x^i (c[n] != 0, n >= 2) as the eigenvalues of its companion matrix (first
 * row -c[n-1..0] / c[n], ones below the diagonal: upper Hessenberg). */
static int companion_roots(double *h, const double *c, int n, double *wr, double *wi)
{
    for (int i = 0; i < n * n; i++) h[i] = 0.0;
    for (int j = 0; j < n; j++) h[j] = -c[n - 1 - j] / c[n];
    for (int i = 1; i < n; i++) h[i * n + i - 1] = 1.0;
    balance(h, n);
    return hessenberg_qr(h, n, wr, wi);
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
        double wr[CD_POLY_MAX_DEGREE], wi[CD_POLY_MAX_DEGREE], c[CD_POLY_MAX_DEGREE + 1];
        double s = nearly_even_or_odd(b, bd) ? CD_POLY_SHIFT * root_bound(b, bd) : 0.0;
        taylor_shift(b, bd, s, c);
        if (!isfinite(c[0]) || c[bd] == 0.0) return CD_POLY_FAIL;
        if (companion_roots(ws->h, c, bd, wr, wi) != 0) return CD_POLY_FAIL;
        for (int i = 0; i < bd; i++) {
            double re = wr[i] + s, im = wi[i];
            if (!isfinite(re) || !isfinite(im)) continue;
            if (fabs(im) <= imag_tol * (1.0 + hypot(re, im))) roots[n++] = polish(b, bd, re);
        }
    }
    sort_ascending(roots, n);
    return n;
}
