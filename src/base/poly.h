/* SPDX-License-Identifier: MIT */
/* Real polynomial roots (companion matrix and the library's own QR, src/base/poly.c). */
#ifndef CDIST_POLY_H
#define CDIST_POLY_H

#include <math.h>

#define CD_POLY_MAX_DEGREE 8

typedef struct cdist__poly_ws cdist__poly_ws;

/* Workspaces for every degree up to CD_POLY_MAX_DEGREE. NULL when memory runs out. */
cdist__poly_ws *cdist__poly_ws_new(void);
void cdist__poly_ws_free(cdist__poly_ws *ws);

/* Real roots of sum_{i=0}^{degree} coef[i] x^i (ascending order), sorted ascending, written to
 * roots (room for `degree` values). Leading coefficients below a relative threshold are
 * dropped; roots whose imaginary part is at most imag_tol * (1 + |z|) count as real (callers
 * polish every root on their true function, so extra candidates are harmless). Each root is
 * polished by Newton on the polynomial.
 * Returns the number of roots, CD_POLY_ZERO when every coefficient is zero, or
 * CD_POLY_FAIL when a coefficient is not finite, degree is out of range, or the QR iteration did
 * not converge (a status, never an abort). */
#define CD_POLY_ZERO (-1)
#define CD_POLY_FAIL (-2)
int cdist__poly_real_roots(cdist__poly_ws *ws, const double *coef, int degree, double imag_tol, double *roots);

/* out = a b for ascending coefficients of degrees da and db (out, of degree da + db, must not
 * alias them); each product added with one rounding (fma) when fused, else two. The two methods
 * that call it keep their own rounding (results bit for bit). */
static inline void cdist__poly_mul(const double *a, int da, const double *b, int db, int fused, double *out)
{
    for (int i = 0; i <= da + db; i++) out[i] = 0.0;
    for (int i = 0; i <= da; i++)
        for (int j = 0; j <= db; j++) out[i + j] = fused ? fma(a[i], b[j], out[i + j]) : out[i + j] + a[i] * b[j];
}


#endif
