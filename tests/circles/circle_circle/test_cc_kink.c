/* SPDX-License-Identifier: MIT */
/* The near-crossing grid of the circle-circle engine and its re-check (src/circles/cc_kink.c),
 * through cdist__circle_circle_critical (internal; this test is linked with the library sources):
 * nearly coplanar circles, one passing near the other's centre and across its rim, where the
 * distance has narrow dips inside the near-crossing window. Every critical angle is returned once
 * (a root the grid's F' sign pair gave is not returned again by the re-check's subdivision), in
 * the critical-angle mode and in the minima mode. The truth: F' signs in long double on a dense
 * grid of A's angle (the sign changes are 0.07 rad apart here, the grid's step 2.4e-5), which
 * mpmath agrees with (the roots of H = Q sigma^2 - s^2 (w.w')^2 at 60 digits, F' signs between
 * them: the same 4 critical points). */
#include "check.h"
#include "internal.h"

static cdist_query *q;

enum { NS = 1 << 18 };

/* F'/2 at angle t of A (the library's basis of A, from cdist__check_circle), in long double. */
static long double F1_at(const cdist__circle *A, const cdist__circle *B, long double t)
{
    long double c = cosl(t), s = sinl(t), P[3], Pd[3], D[3], m[3] = {B->n.x, B->n.y, B->n.z};
    long double mn = sqrtl(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
    double u[3] = {A->u.x, A->u.y, A->u.z}, v[3] = {A->v.x, A->v.y, A->v.z};
    double ca[3] = {A->c.x, A->c.y, A->c.z}, cb[3] = {B->c.x, B->c.y, B->c.z};
    for (int i = 0; i < 3; i++) {
        m[i] /= mn;
        P[i] = ca[i] + A->r * (c * u[i] + s * v[i]);
        Pd[i] = A->r * (-s * u[i] + c * v[i]);
        D[i] = P[i] - cb[i];
    }
    long double w[3] = {m[1] * D[2] - m[2] * D[1], m[2] * D[0] - m[0] * D[2], m[0] * D[1] - m[1] * D[0]};
    long double wd[3] = {m[1] * Pd[2] - m[2] * Pd[1], m[2] * Pd[0] - m[0] * Pd[2], m[0] * Pd[1] - m[1] * Pd[0]};
    long double rho = sqrtl(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    long double h = m[0] * D[0] + m[1] * D[1] + m[2] * D[2], hd = m[0] * Pd[0] + m[1] * Pd[1] + m[2] * Pd[2];
    return (rho - B->r) * (w[0] * wd[0] + w[1] * wd[1] + w[2] * wd[2]) / rho + h * hd;
}

static double circ_dist(double a, double b)
{
    double d = fmod(fabs(a - b), 2 * M_PI);
    return fmin(d, 2 * M_PI - d);
}

/* The sign changes of F' on the dense grid: the left ends of their cells and their directions
 * (+1: a minimum, -1: a maximum). */
static int sign_changes(const cdist__circle *A, const cdist__circle *B, double *cell, int *dir, int cap)
{
    int n = 0;
    long double step = 2 * (long double)M_PI / NS, first = F1_at(A, B, -M_PI), prev = first;
    for (int j = 1; j <= NS; j++) {
        long double cur = j < NS ? F1_at(A, B, -M_PI + j * step) : first;
        if ((prev < 0) != (cur < 0) && n < cap) {
            cell[n] = (double)(-M_PI + (j - 1) * step);
            dir[n++] = prev < 0 ? 1 : -1;
        }
        prev = cur;
    }
    return n;
}

/* Returned angles t[0..n) against the true sign changes (of direction want, 0: any): pairwise
 * distinct, and each in (or next to) the cell of a different true sign change. */
static void match(const char *what, const double *t, int n, const double *cell, const int *dir, int nc, int want)
{
    double step = 2 * M_PI / NS;
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++)
            CHECK(circ_dist(t[i], t[j]) > 1e-9, "%s: angles %d and %d are one root (%.17g, %.17g)", what, i, j, t[i], t[j]);
    int used[8] = {0};
    for (int i = 0; i < n; i++) {
        int found = -1;
        for (int j = 0; j < nc && j < 8; j++)
            if (!used[j] && (!want || dir[j] == want) && circ_dist(t[i], cell[j] + 0.5 * step) <= step) found = j;
        CHECK(found >= 0, "%s: angle %.17g is no (other) true critical point", what, t[i]);
        if (found >= 0) used[found] = 1;
    }
}

int main(void)
{
    q = cdist_query_new();
    /* tests/data/cc_coplanar_dips.txt, line 8, the second circle parameterised: A (radius 14.2,
     * tilted by 4e-7 against B's plane) passes 3e-8 from the axis of B, the unit circle, and
     * crosses B's rim on either side. F: a maximum on the far side, the two dips at the rim
     * crossings (distances 6.2e-7 and 2.1e-7) and the maximum between them, near the axis. */
    cdist_circle c0 = {tv(-13.011781330284958, -5.7154526699823194, -1.684663178820854e-07),
                       tv(1.6872996420366863e-07, -3.7756970019856563e-07, 0.99999999999991451), 14.211715360001177};
    cdist_circle c1 = {tv(0, 0, 0), tv(0, 0, 1), 1};
    cdist__circle a, b;
    CHECK(cdist__check_circle(q, &c0, "c0", &a) == CDIST_OK && cdist__check_circle(q, &c1, "c1", &b) == CDIST_OK,
          "valid circles");
    b.c = v_sub(b.c, a.c);
    a.c = v3(0, 0, 0);
    double cell[8], t[64];
    int dir[8];
    int nc = sign_changes(&a, &b, cell, dir, 8);
    CHECK(nc == 4, "true critical points: %d (mpmath: 4)", nc);

    /* critical-angle mode: every critical point once */
    int n = cdist__circle_circle_critical(q, &a, &b, INFINITY, t, 64, NULL);
    CHECK(n == nc, "critical mode: %d angles for %d critical points", n, nc);
    match("critical mode", t, n, cell, dir, nc, 0);

    /* minima mode (the cap above both dips, below the maxima): minima only, each once */
    n = cdist__circle_circle_critical(q, &a, &b, 1e-3, t, 64, NULL);
    int nmin = 0;
    for (int j = 0; j < nc; j++) nmin += dir[j] > 0;
    CHECK(n >= 1 && n <= nmin, "minima mode: %d angles for %d minima", n, nmin);
    match("minima mode", t, n, cell, dir, nc, 1);

    cdist_query_free(q);
    return check_summary("cc_kink");
}
