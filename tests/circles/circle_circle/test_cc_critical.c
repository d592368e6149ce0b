/* SPDX-License-Identifier: MIT */
/* cdist__circle_circle_critical (internal; this test is linked with the library sources): every
 * critical angle of theta -> dist^2(c0(theta), c1) is found (checked against a long double
 * sampling of the function), every returned angle is critical or an axis crossing, -1 for the
 * constant cases, and the minimum over the returned angles is the circle-circle distance. */
#include "check.h"
#include "internal.h"

static cdist_query *q;

static long double F_at(const cdist_circle *c0, const cdist_circle *c1, double t)
{
    cdist_vec3 p;
    cdist_circle_point(c0, t, &p);
    long double d = ref_point_circle(p, *c1);
    return d * d;
}

static double circ_dist(double a, double b)
{
    double d = fmod(fabs(a - b), 2 * M_PI);
    return fmin(d, 2 * M_PI - d);
}

static int critical(const cdist_circle *c0, const cdist_circle *c1, double *t, int cap)
{
    cdist__circle a, b;
    if (cdist__check_circle(q, c0, "c0", &a) || cdist__check_circle(q, c1, "c1", &b)) return -2;
    return cdist__circle_circle_critical(q, &a, &b, INFINITY, t, cap, NULL);
}

/* Minima mode (the minima up to the cap and up to the global minimum, to the tie tolerance): when
 * the sampled global minimum lies below dcap (a little under, for the sampling), it is returned,
 * and every returned angle is critical or an axis crossing. */
static void minima_case(int i, const cdist_circle *c0, const cdist_circle *c1, const long double *Fs, int NS, double dcap)
{
    cdist__circle a, b;
    if (cdist__check_circle(q, c0, "c0", &a) || cdist__check_circle(q, c1, "c1", &b)) return;
    double t[64];
    int n = cdist__circle_circle_critical(q, &a, &b, dcap, t, 64, NULL);
    CHECK(n >= 0, "case %d: minima mode returned %d", i, n);
    if (n < 0) return;
    double L = fmax(fmax(c0->radius, c1->radius), tdist(c0->center, c1->center));
    int jm = 0;
    for (int j = 1; j < NS; j++)
        if (Fs[j] < Fs[jm]) jm = j;
    if (sqrtl(Fs[jm]) <= dcap - 1e-9 * L) {
        double tj = -M_PI + jm * (2 * M_PI / NS), best = INFINITY;
        for (int k = 0; k < n; k++) best = fmin(best, circ_dist(tj, t[k]));
        CHECK(best <= 2.5 * (2 * M_PI / NS), "case %d: sampled minimum at %.6f (d %.6Lg, cap %.6g) not returned", i, tj,
              sqrtl(Fs[jm]), dcap);
    }
    for (int k = 0; k < n; k++) {
        double h = 1e-5;
        long double d1 = (F_at(c0, c1, t[k] + h) - F_at(c0, c1, t[k] - h)) / (2 * h);
        cdist_vec3 p;
        cdist_circle_point(c0, t[k], &p);
        cdist_vec3 D = tv(p.x - c1->center.x, p.y - c1->center.y, p.z - c1->center.z), m = c1->normal;
        double rho = tdist(tv(m.y * D.z - m.z * D.y, m.z * D.x - m.x * D.z, m.x * D.y - m.y * D.x), tv(0, 0, 0));
        CHECK(fabsl(d1) <= 1e-6 * L * L || rho <= 1e-6 * L, "case %d: minima-mode angle %.17g is not critical", i, t[k]);
    }
}

static void random_case(int i, cdist_circle c0, cdist_circle c1)
{
    double t[64];
    int n = critical(&c0, &c1, t, 64);
    CHECK(n >= 2, "case %d: %d critical angles", i, n);
    if (n < 2) return;
    double L = fmax(fmax(c0.radius, c1.radius), tdist(c0.center, c1.center));
    /* sampled extrema must be near a returned angle */
    enum { NS = 20000 };
    static long double Fs[NS];
    for (int j = 0; j < NS; j++) Fs[j] = F_at(&c0, &c1, -M_PI + j * (2 * M_PI / NS));
    for (int j = 0; j < NS; j++) {
        long double a = Fs[(j + NS - 1) % NS], m = Fs[j], b = Fs[(j + 1) % NS];
        int ext = (m < a && m <= b) || (m > a && m >= b);
        if (!ext) continue;
        double tj = -M_PI + j * (2 * M_PI / NS), best = INFINITY;
        for (int k = 0; k < n; k++) best = fmin(best, circ_dist(tj, t[k]));
        CHECK(best <= 2.5 * (2 * M_PI / NS), "case %d: sampled extremum at %.6f (F %.6Lg) not returned (nearest %.3g)",
              i, tj, m, best);
    }
    /* minima mode with caps at, between and above the sampled minima */
    {
        long double lo = Fs[0], hi = Fs[0];
        for (int j = 1; j < NS; j++) lo = fminl(lo, Fs[j]), hi = fmaxl(hi, Fs[j]);
        for (int c = 0; c < 3; c++) minima_case(i, &c0, &c1, Fs, NS, (double)sqrtl(lo + (hi - lo) * (0.05 + 0.45 * c)));
    }
    /* each returned angle is critical: central difference small, or an axis crossing */
    double dmin = INFINITY;
    for (int k = 0; k < n; k++) {
        double h = 1e-5;
        long double d1 = (F_at(&c0, &c1, t[k] + h) - F_at(&c0, &c1, t[k] - h)) / (2 * h);
        cdist_vec3 p;
        cdist_circle_point(&c0, t[k], &p);
        cdist_vec3 D = tv(p.x - c1.center.x, p.y - c1.center.y, p.z - c1.center.z);
        cdist_vec3 n1 = c1.normal;
        double rho = tdist(tv(n1.y * D.z - n1.z * D.y, n1.z * D.x - n1.x * D.z, n1.x * D.y - n1.y * D.x), tv(0, 0, 0));
        CHECK(fabsl(d1) <= 1e-6 * L * L || rho <= 1e-6 * L, "case %d: angle %.17g is not critical (F' %.3Lg)", i, t[k],
              d1);
        dmin = fmin(dmin, (double)sqrtl(F_at(&c0, &c1, t[k])));
    }
    /* the minimum over the critical angles is the distance from c0 to c1 */
    cdist_result r;
    CHECK(cdist_circle_circle(q, &c0, &c1, &r) == CDIST_OK, "case %d status", i);
    CHECK(fabs(dmin - r.distance) <= 1e-14 * L, "case %d: min over critical angles %.17g vs distance %.17g", i, dmin,
          r.distance);
}

int main(void)
{
    q = cdist_query_new();
    for (int i = 0; i < 150; i++) {
        cdist_circle c0 = {tv(srand1(), srand1(), srand1()), rand_unit(), 0.1 + 1.5 * urand()};
        cdist_circle c1 = {tv(srand1(), srand1(), srand1()), rand_unit(), 0.1 + 1.5 * urand()};
        if (i % 3 == 1) c1.center = c0.center, c1.center.x += 0.3 * c0.radius; /* linked-ish */
        if (i % 3 == 2) c1.normal = c0.normal;                                    /* parallel planes */
        random_case(i, c0, c1);
    }
    /* c0 crossing c1's axis: c0 has radius 2 in the plane x = 0, centred on c1's axis
     * (the line through (0, 0.3, 0) along z): it crosses that axis at z = +-2. */
    {
        double t[64];
        cdist_circle c0 = {tv(0, 0.3, 0), tv(1, 0, 0), 2}, c1 = {tv(0, 0.3, 0), tv(0, 0, 1), 1};
        int n, found;
        n = critical(&c0, &c1, t, 64);
        found = 0;
        for (int k = 0; k < n; k++) {
            cdist_vec3 p;
            cdist_circle_point(&c0, t[k], &p);
            if (fabs(p.x) < 1e-12 && fabs(p.y - 0.3) < 1e-12 && fabs(fabs(p.z) - 2) < 1e-12) found++;
        }
        CHECK(found >= 2, "axis crossings returned: %d (of %d angles)", found, n);
    }
    /* constant cases: -1 */
    cdist_circle z0 = {tv(0, 0, 0), tv(0, 0, 1), 2};
    cdist_circle coax = {tv(0, 0, 3), tv(0, 0, -1), 1};
    cdist_circle meridian = {tv(2, 0, 0), tv(0, 1, 0), 1};
    cdist_circle villarceau = {tv(0, 1, 0), tv(-0.5, 0, sqrt(3.0) / 2), 2};
    cdist_circle point = {tv(0, 0, 5), tv(0, 0, 1), 0};
    double t[64];
    CHECK(critical(&coax, &z0, t, 64) == -1, "coaxial: -1");
    CHECK(critical(&z0, &coax, t, 64) == -1, "coaxial swapped: -1");
    CHECK(critical(&meridian, &z0, t, 64) == -1, "meridian: -1");
    CHECK(critical(&villarceau, &z0, t, 64) == -1, "villarceau: -1");
    CHECK(critical(&z0, &point, t, 64) == -1, "point on the axis: -1");
    CHECK(critical(&point, &z0, t, 64) == -1, "radius 0 circle: -1");
    /* the meridian seen from the larger circle is not constant */
    CHECK(critical(&z0, &meridian, t, 64) >= 2, "meridian from the larger circle: critical angles");
    cdist_query_free(q);
    return check_summary("cc_critical");
}
