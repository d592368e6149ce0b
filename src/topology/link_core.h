/* SPDX-License-Identifier: MIT */
/* The linking number of two circles in one floating-point type, with a running error bound:
 * included by link.c once per type, with
 *   LK_REAL  the type, LK_SQRT its square root, LK_U its unit roundoff (as a double),
 *   LK_FN    the function's name;
 * undefined again at the end of this file.
 *
 * The caller scales so that L = max(ra, rb, |w|) is in [1, 2) (a's centre at the origin, b's at
 * w). Returns -1, 0, +1 when certified, LK_UNDECIDED otherwise. The count and why d_low (a lower
 * bound of the circles' distance) settles every decision: docs/linking.md, "How it is
 * computed". The error terms are first-order bounds with every constant at least doubled (unit
 * normals renormalised here: |n| = 1 +- 3u).
 */

static int LK_FN(const double na_in[3], const double nb_in[3], const double w_in[3], double ra_in, double rb_in,
                 double d_low)
{
    const double u = LK_U;
    LK_REAL na[3], nb[3], w[3];
    LK_REAL la = 0, lb = 0;
    for (int i = 0; i < 3; i++) {
        na[i] = na_in[i];
        nb[i] = nb_in[i];
        w[i] = w_in[i];
        la += na[i] * na[i];
        lb += nb[i] * nb[i];
    }
    la = LK_SQRT(la);
    lb = LK_SQRT(lb);
    for (int i = 0; i < 3; i++) {
        na[i] /= la;
        nb[i] /= lb;
    }
    const LK_REAL ra = ra_in, rb = rb_in;

    LK_REAL n[3] = {na[1] * nb[2] - na[2] * nb[1], na[2] * nb[0] - na[0] * nb[2], na[0] * nb[1] - na[1] * nb[0]};
    LK_REAL s = LK_SQRT(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    const double sd = (double)s;
    /* |n - n_exact| and |s - s_exact|: 3u per component from the products, 6u from the normals'
     * lengths, doubled. */
    const double e_s = 32.0 * u;
    if (2.0 * fmin(ra_in, rb_in) * (sd + e_s) < d_low) return 0;
    if (!(sd > 4.0 * e_s)) return LK_UNDECIDED;

    LK_REAL D[3] = {n[0] / s, n[1] / s, n[2] / s};
    const double wn = sqrt(w_in[0] * w_in[0] + w_in[1] * w_in[1] + w_in[2] * w_in[2]) * (1.0 + 4.0 * u);
    /* |D - D_exact| <= (e_n + e_s) / (s - e_s) + rounding, with s - e_s >= 3s/4. */
    const double e_D = 2.0 * (2.0 * e_s) / (0.75 * sd) + 4.0 * u;
    const LK_REAL ca = w[0] * na[0] + w[1] * na[1] + w[2] * na[2];
    const LK_REAL cb = w[0] * nb[0] + w[1] * nb[1] + w[2] * nb[2];
    const LK_REAL tb = w[0] * D[0] + w[1] * D[1] + w[2] * D[2];
    /* w.na: 3u of rounding, 3u of the normal's length and direction, doubled. */
    const double e_c = 16.0 * u * wn;
    const double e_tb = wn * (e_D + 8.0 * u);

    /* Half-chords squared, (r - delta)(r + delta): delta_a = |w.nb| / s is the distance from a's
     * centre to the line (in a's plane), delta_b = |w.na| / s that from b's centre. */
    const LK_REAL del_a = (cb < 0 ? -cb : cb) / s, del_b = (ca < 0 ? -ca : ca) / s;
    const double dad = (double)del_a, dbd = (double)del_b;
    const double e_da = 2.0 * (e_c + dad * e_s) / (0.75 * sd) + 4.0 * u * dad;
    const double e_db = 2.0 * (e_c + dbd * e_s) / (0.75 * sd) + 4.0 * u * dbd;
    const LK_REAL Ha = (ra - del_a) * (ra + del_a), Hb = (rb - del_b) * (rb + del_b);
    const double e_Ha = e_da * (fabs(ra_in - dad) + ra_in + dad + e_da) + 8.0 * u * fabs(ra_in - dad) * (ra_in + dad);
    const double e_Hb = e_db * (fabs(rb_in - dbd) + rb_in + dbd + e_db) + 8.0 * u * fabs(rb_in - dbd) * (rb_in + dbd);
    const double Had = (double)Ha, Hbd = (double)Hb;

    /* A chord that does not exist: b does not cross a's disk (or a does not cross b's). */
    if (Had < -e_Ha || Hbd < -e_Hb) return 0;
    if (Had <= e_Ha || Hbd <= e_Hb) {
        double eta = INFINITY;
        if (Had <= e_Ha) eta = sqrt(2.0 * e_Ha);
        if (Hbd <= e_Hb) eta = fmin(eta, sqrt(2.0 * e_Hb));
        return eta < d_low ? 0 : LK_UNDECIDED;
    }
    const LK_REAL ha = LK_SQRT(Ha), hb = LK_SQRT(Hb);
    const double had = (double)ha, hbd = (double)hb;
    /* |sqrt(H) - sqrt(H^)| <= |H - H^| / sqrt(H^) since the true H >= H^ - e >= 0. */
    const double e_ha = e_Ha / had + 4.0 * u * had, e_hb = e_Hb / hbd + 4.0 * u * hbd;

    const LK_REAL up = tb + hb, dn = tb - hb;
    const LK_REAL f_up = (up < 0 ? -up : up) - ha, f_dn = (dn < 0 ? -dn : dn) - ha;
    const double e_f = e_tb + e_hb + e_ha + 8.0 * u * (fabs((double)tb) + hbd + had);
    const double fu = (double)f_up, fd = (double)f_dn;
    if (!(e_f < d_low) && !(fabs(fu) > e_f && fabs(fd) > e_f)) return LK_UNDECIDED;
    return (fu < 0.0) - (fd < 0.0);
}

#undef LK_REAL
#undef LK_SQRT
#undef LK_U
#undef LK_FN
