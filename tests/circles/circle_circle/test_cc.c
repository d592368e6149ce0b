/* SPDX-License-Identifier: MIT */
/* Circle-circle: the paper's worked examples, exact constructions of every special family with
 * pair counts and flags, symmetry, rotation/translation/scale invariance, an independent long
 * double brute force on random linked and near-degenerate configurations, and the batch entry.
 * usage: test_cc [--method=auto|robust|polynomial|iteration] */
#include <float.h>
#include <string.h>

#include "check.h"

static cdist_query *q;
/* Tolerance of the extreme-scale checks: a few ulps for the robust method (AUTO uses it), the
 * project's 1e-13 of scale for the others. */
static double scale_tol = 4 * 2.220446049250313e-16;
static const double EPS = 2.220446049250313e-16;
/* |f(a, b) - f(b, a)| allowed on the random configurations, in units of the scale: 4 ulps for the
 * methods that treat both circles alike; the iteration method runs from the first circle, so
 * its two answers err independently, each by up to ~3.2 ulps measured (linked circles touching
 * a centre), and may differ by twice that. */
static double sym_tol = 4 * 2.220446049250313e-16;

static cdist_circle circ(double cx, double cy, double cz, double nx, double ny, double nz, double r)
{
    double n = sqrt(nx * nx + ny * ny + nz * nz);
    cdist_circle c = {tv(cx, cy, cz), tv(nx / n, ny / n, nz / n), r};
    return c;
}

static double v_maxabs_t(cdist_vec3 a) { return fmax(fabs(a.x), fmax(fabs(a.y), fabs(a.z))); }

static double scale_of(const cdist_circle *a, const cdist_circle *b, double d)
{
    return fmax(fmax(a->radius, b->radius), fmax(d, tdist(a->center, b->center)));
}

/* ---- independent brute force (long double): sample one circle's angle with the closed-form
 * point-circle distance, polish every sampled local minimum by golden section; both ways. ---- */
static void ld_basis(cdist_vec3 n, long double u[3], long double v[3])
{
    /* any orthonormal basis of the plane (independent of the library's rule) */
    long double N[3] = {n.x, n.y, n.z}, nn = sqrtl(N[0] * N[0] + N[1] * N[1] + N[2] * N[2]);
    for (int i = 0; i < 3; i++) N[i] /= nn;
    long double e[3] = {0, 0, 0};
    int k = (fabsl(N[0]) < 0.6L) ? 0 : (fabsl(N[1]) < 0.6L ? 1 : 2);
    e[k] = 1;
    long double d = N[k];
    long double w[3] = {e[0] - d * N[0], e[1] - d * N[1], e[2] - d * N[2]};
    long double wn = sqrtl(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    for (int i = 0; i < 3; i++) u[i] = w[i] / wn;
    v[0] = N[1] * u[2] - N[2] * u[1];
    v[1] = N[2] * u[0] - N[0] * u[2];
    v[2] = N[0] * u[1] - N[1] * u[0];
}

static long double ld_pc(const long double p[3], const cdist_circle *c)
{
    long double N[3] = {c->normal.x, c->normal.y, c->normal.z};
    long double nn = sqrtl(N[0] * N[0] + N[1] * N[1] + N[2] * N[2]);
    for (int i = 0; i < 3; i++) N[i] /= nn;
    long double D[3] = {p[0] - c->center.x, p[1] - c->center.y, p[2] - c->center.z};
    long double h = N[0] * D[0] + N[1] * D[1] + N[2] * D[2];
    long double x = N[1] * D[2] - N[2] * D[1], y = N[2] * D[0] - N[0] * D[2], z = N[0] * D[1] - N[1] * D[0];
    long double rho = sqrtl(x * x + y * y + z * z) - (long double)c->radius;
    return sqrtl(rho * rho + h * h);
}

static long double ld_one(const cdist_circle *a, const cdist_circle *b, int ns)
{
    long double u[3], v[3];
    ld_basis(a->normal, u, v);
    long double C[3] = {a->center.x, a->center.y, a->center.z}, r = a->radius;
#define PT(t, P)                                                                                               \
    do {                                                                                                       \
        long double cs = cosl(t), sn = sinl(t);                                                                \
        for (int i_ = 0; i_ < 3; i_++) P[i_] = C[i_] + r * (cs * u[i_] + sn * v[i_]);                          \
    } while (0)
    long double best = INFINITY, h = 2 * 3.14159265358979323846264L / ns, P[3];
    long double prev2, prev1, first, second;
    PT(0.0L, P);
    first = prev2 = ld_pc(P, b);
    PT(h, P);
    second = prev1 = ld_pc(P, b);
    for (int i = 2; i <= ns + 1; i++) {
        long double cur;
        if (i == ns) cur = first;
        else if (i == ns + 1) cur = second;
        else {
            PT(i * h, P);
            cur = ld_pc(P, b);
        }
        if (prev1 <= prev2 && prev1 <= cur) {
            long double lo = (i - 2) * h, hi = i * h, g = 0.6180339887498948482L;
            long double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo), f1, f2;
            PT(x1, P);
            f1 = ld_pc(P, b);
            PT(x2, P);
            f2 = ld_pc(P, b);
            for (int it = 0; it < 90; it++) {
                if (f1 < f2) {
                    hi = x2, x2 = x1, f2 = f1, x1 = hi - g * (hi - lo);
                    PT(x1, P);
                    f1 = ld_pc(P, b);
                } else {
                    lo = x1, x1 = x2, f1 = f2, x2 = lo + g * (hi - lo);
                    PT(x2, P);
                    f2 = ld_pc(P, b);
                }
            }
            long double m = fminl(fminl(f1, f2), prev1);
            if (m < best) best = m;
        }
        prev2 = prev1;
        prev1 = cur;
    }
#undef PT
    return best;
}

static long double brute(const cdist_circle *a, const cdist_circle *b, int ns)
{
    if (a->radius == 0) {
        long double p[3] = {a->center.x, a->center.y, a->center.z};
        return ld_pc(p, b);
    }
    if (b->radius == 0) {
        long double p[3] = {b->center.x, b->center.y, b->center.z};
        return ld_pc(p, a);
    }
    return fminl(ld_one(a, b, ns), ld_one(b, a, ns));
}

/* ---- result checks ---- */
static void check_pairs(const char *what, const cdist_circle *a, const cdist_circle *b, const cdist_result *r,
                        double tol)
{
    for (int i = 0; i < r->num_pairs; i++) {
        double on0 = (double)ref_point_circle(r->pairs[i].point[0], *a);
        double on1 = (double)ref_point_circle(r->pairs[i].point[1], *b);
        double dp = tdist(r->pairs[i].point[0], r->pairs[i].point[1]);
        CHECK(on0 <= tol && on1 <= tol, "%s pair %d off the circles: %.3g %.3g", what, i, on0, on1);
        CHECK(fabs(dp - r->distance) <= tol, "%s pair %d: |p0-p1| %.17g vs %.17g", what, i, dp, r->distance);
        /* param reproduces the point */
        if (a->radius > 0) {
            cdist_vec3 p;
            cdist_circle_point(a, r->pairs[i].param[0], &p);
            CHECK(tdist(p, r->pairs[i].point[0]) <= tol, "%s pair %d: param[0] does not give point[0]", what, i);
        }
        if (b->radius > 0) {
            cdist_vec3 p;
            cdist_circle_point(b, r->pairs[i].param[1], &p);
            CHECK(tdist(p, r->pairs[i].point[1]) <= tol, "%s pair %d: param[1] does not give point[1]", what, i);
        }
    }
}

/* Distance, pair count and flag of one configuration, then the same for the swapped arguments
 * and for a random rigid motion + scale of it. */
static void expect(const char *what, cdist_circle a, cdist_circle b, double d, int pairs, int equi)
{
    for (int variant = 0; variant < 3; variant++) {
        cdist_circle x = a, y = b;
        double s = 1, dd = d;
        if (variant == 2) {
            trot R = rand_rotation();
            s = exp(3 * srand1());
            /* translation of the problem's size: the equidistant tests are relative to the scale */
            cdist_vec3 t = tv(3 * s * srand1(), 3 * s * srand1(), 3 * s * srand1());
            x = xform_circle(&R, s, t, a);
            y = xform_circle(&R, s, t, b);
            dd = d * s;
        }
        if (variant == 1) {
            cdist_circle tmp = x;
            x = y;
            y = tmp;
        }
        cdist_result r;
        cdist_status st = cdist_circle_circle(q, &x, &y, &r);
        CHECK(st == CDIST_OK, "%s: status %s", what, cdist_status_name(st));
        if (st) continue;
        double L = scale_of(&x, &y, dd);
        double coord = fmax(v_maxabs_t(x.center), v_maxabs_t(y.center)) + L;
        /* exact inputs: a few ulps; moved inputs carry the rounding of the motion */
        double tol = variant == 2 ? 64 * EPS * coord : 8 * EPS * L;
        CHECK(fabs(r.distance - dd) <= tol, "%s (variant %d): distance %.17g expected %.17g (err %.3g of scale)", what,
              variant, r.distance, dd, fabs(r.distance - dd) / L);
        CHECK(r.num_pairs == pairs, "%s (variant %d): %d pairs, expected %d", what, variant, r.num_pairs, pairs);
        CHECK(r.equidistant == equi, "%s (variant %d): equidistant %d, expected %d", what, variant, r.equidistant,
              equi);
        check_pairs(what, &x, &y, &r, 64 * EPS * coord);
    }
}

static void exact_families(void)
{
    const double r3 = sqrt(3.0);
    /* coplanar */
    expect("coplanar concentric", circ(0, 0, 0, 0, 0, 1, 2), circ(0, 0, 0, 0, 0, -1, 5), 3, 1, 1);
    expect("coplanar identical", circ(1, 2, 3, 0, 1, 0, 2), circ(1, 2, 3, 0, 1, 0, 2), 0, 1, 1);
    expect("coplanar separated", circ(0, 0, 0, 0, 0, 1, 1), circ(5, 0, 0, 0, 0, 1, 2), 2, 1, 0);
    expect("coplanar external tangent", circ(0, 0, 0, 0, 0, 1, 1), circ(3, 0, 0, 0, 0, 1, 2), 0, 1, 0);
    expect("coplanar internal tangent", circ(0, 0, 0, 0, 0, 1, 3), circ(2, 0, 0, 0, 0, 1, 1), 0, 1, 0);
    expect("coplanar overlapping", circ(0, 0, 0, 0, 0, 1, 2), circ(2, 0, 0, 0, 0, 1, 2), 0, 2, 0);
    expect("coplanar contained", circ(0, 0, 0, 0, 0, 1, 5), circ(1, 0, 0, 0, 0, 1, 1), 3, 1, 0);
    /* a tiny circle across the rim of a unit one, coplanar: the crossings (rho = s, 2^-30 from
     * the closest angle) came out of the parallel closed form as acos of a cosine within eps of
     * 1, i.e. no crossing at all (7.9e-10 reported for 0) */
    expect("coplanar tiny across the rim", circ(0, 0, 0, 0, 0, 1, 1), circ(1 + 0x1p-33, 0, 0, 0, 0, 1, 0x1p-30), 0, 1, 0);
    expect("parallel tiny over the rim", circ(0, 0, 0, 0, 0, 1, 1), circ(1 - 0x1p-33, 0, 0x1p-40, 0, 0, -1, 0x1p-30), 0x1p-40,
           1, 0);
    /* parallel planes */
    expect("parallel coaxial", circ(0, 0, 0, 0, 0, 1, 1), circ(0, 0, 4, 0, 0, 1, 3), sqrt(20.0), 1, 1);
    expect("parallel offset overlapping", circ(0, 0, 0, 0, 0, 1, 2), circ(2, 0, 1, 0, 0, -1, 2), 1, 2, 0);
    expect("parallel separated", circ(0, 0, 0, 0, 0, 1, 1), circ(5, 0, 2, 0, 0, 1, 1), sqrt(13.0), 1, 0);
    expect("parallel contained", circ(0, 0, 0, 0, 0, 1, 4), circ(1, 0, 3, 0, 0, 1, 1), sqrt(4.0 + 9.0), 1, 0);
    /* centres on the normal line, axes meeting at right angles (paper remark 1): two pairs */
    expect("centre on normal line, perpendicular", circ(0, 0, 0, 0, 0, 1, 2), circ(0, 0, 3, 1, 0, 0, 1),
           sqrt(13.0) - 1, 2, 0);
    expect("concentric perpendicular", circ(0, 0, 0, 0, 0, 1, 2), circ(0, 0, 0, 1, 0, 0, 1), 1, 2, 0);
    /* axes meeting (not perpendicular): c1's axis (-4,-5,4) + t (4,5,2) meets the z axis at
     * (0,0,6); the plane through the z axis and (4,5,0) is a mirror of both: two pairs. */
    {
        cdist_circle a = circ(0, 0, 0, 0, 0, 1, 10), b = circ(-4, -5, 4, 4, 5, 2, 6);
        double d = (double)brute(&a, &b, 4096);
        expect("axes meeting", a, b, d, 2, 0);
    }
    /* linked rings: Hopf link of unit circles, each through the other's centre. c1 is a
     * meridian of c0's distance tori: every point of it is at distance 1 from c0. */
    expect("hopf link", circ(0, 0, 0, 0, 0, 1, 1), circ(1, 0, 0, 0, 1, 0, 1), 1, 1, 1);
    expect("meridian circle", circ(0, 0, 0, 0, 0, 1, 2), circ(2, 0, 0, 0, 1, 0, 1), 1, 1, 1);
    expect("meridian circle, larger first", circ(2, 0, 0, 0, 1, 0, 1), circ(0, 0, 0, 0, 0, 1, 2), 1, 1, 1);
    /* Villarceau circle of the torus (major 2, minor 1) around c0: constant distance 1. */
    expect("villarceau", circ(0, 0, 0, 0, 0, 1, 2), circ(0, 1, 0, -0.5, 0, r3 / 2, 2), 1, 1, 1);
    /* linked generic (no symmetry): brute force */
    {
        cdist_circle a = circ(0, 0, 0, 0, 0, 1, 2), b = circ(1.7, 0.2, 0.1, 0.3, 1, 0.2, 1.3);
        double d = (double)brute(&a, &b, 4096);
        expect("linked generic", a, b, d, 1, 0);
    }
    /* a circle through the other's axis (non-smooth point of F): c0 crosses c1's axis at
     * (0,0,2) and (0,0,-2) */
    {
        cdist_circle a = circ(0, 0, 0, 1, 0, 0, 2), b = circ(0.5, 0.3, 0, 0, 0, 1, 1);
        double d = (double)brute(&a, &b, 4096);
        expect("through the axis", a, b, d, 1, 0);
    }
    /* radius 0 */
    expect("point on axis", circ(0, 0, 3, 0, 0, 1, 0), circ(0, 0, 0, 0, 0, 1, 4), 5, 1, 1);
    expect("point off axis", circ(3, 0, 4, 1, 0, 0, 0), circ(0, 0, 0, 0, 0, 1, 1), sqrt(4.0 + 16.0), 1, 0);
    expect("two points", circ(1, 2, 3, 0, 0, 1, 0), circ(4, 6, 3, 1, 0, 0, 0), 5, 1, 0);
}

static void paper_examples(void)
{
    /* Geometric iteration paper, example 1 (true value, not the printed 10.24875800). */
    cdist_circle a = circ(0, 0, 0, 0, 0, 1, 6), b = circ(10, 8, 9, 4, 7, 6, 8);
    cdist_result r;
    CHECK(cdist_circle_circle(q, &a, &b, &r) == CDIST_OK, "example 1 status");
    CHECK_NEAR(r.distance, 10.2487575517830, 2e-13, "example 1");
    CHECK_NEAR(r.distance, (double)brute(&a, &b, 8192), 8 * EPS * 16, "example 1 vs brute force");
    CHECK(r.num_pairs == 1 && !r.equidistant, "example 1: one pair");
    check_pairs("example 1", &a, &b, &r, 1e-13);
    /* Example 2: two pairs. */
    a = circ(0, 0, 0, 0, 0, 1, 10);
    b = circ(-4, -5, 4, 4, 5, 0, 6);
    CHECK(cdist_circle_circle(q, &a, &b, &r) == CDIST_OK, "example 2 status");
    CHECK_NEAR(r.distance, 1.9953652268769, 2e-13, "example 2");
    CHECK_NEAR(r.distance, (double)brute(&a, &b, 8192), 8 * EPS * 10, "example 2 vs brute force");
    CHECK(r.num_pairs == 2 && !r.equidistant, "example 2: %d pairs", r.num_pairs);
    check_pairs("example 2", &a, &b, &r, 1e-13);
    if (r.num_pairs == 2)
        CHECK(tdist(r.pairs[0].point[0], r.pairs[1].point[0]) > 1e-3, "example 2: the pairs are distinct");
}

/* Random configurations of a few kinds; distance vs the brute force, symmetry. */
static cdist_circle rand_circle(double rmax)
{
    cdist_vec3 n = rand_unit();
    return (cdist_circle){tv(srand1(), srand1(), srand1()), n, rmax * (0.05 + urand())};
}

static int skip_perturbed; /* --skip-perturbed: no kind 7 (see meson.build) */

static void random_checks(int count)
{
    double worst = 0, worst_sym = 0, worst7 = 0;
    for (int i = 0; i < count; i++) {
        cdist_circle a = rand_circle(1.5), b = rand_circle(1.5);
        int kind = i % 8;
        if (kind == 7 && skip_perturbed) continue;
        if (kind == 1) { /* linked: b's centre on a, b's plane containing a's tangent-ish */
            double t = 6.283 * urand();
            cdist_vec3 u, v;
            cdist_circle_basis(&a, &u, &v);
            b.center = tv(a.center.x + a.radius * (cos(t) * u.x + sin(t) * v.x),
                          a.center.y + a.radius * (cos(t) * u.y + sin(t) * v.y),
                          a.center.z + a.radius * (cos(t) * u.z + sin(t) * v.z));
            b.radius = a.radius * (0.3 + 1.4 * urand());
        } else if (kind == 2) { /* nearly coaxial */
            cdist_vec3 n = a.normal;
            b.normal = tv(n.x + 1e-7 * srand1(), n.y + 1e-7 * srand1(), n.z + 1e-7 * srand1());
            double nn = sqrt(b.normal.x * b.normal.x + b.normal.y * b.normal.y + b.normal.z * b.normal.z);
            b.normal = tv(b.normal.x / nn, b.normal.y / nn, b.normal.z / nn);
            double h = srand1();
            b.center = tv(a.center.x + h * n.x + 1e-6 * srand1(), a.center.y + h * n.y + 1e-6 * srand1(),
                          a.center.z + h * n.z + 1e-6 * srand1());
        } else if (kind == 3) { /* nearly parallel, offset */
            cdist_vec3 n = a.normal;
            b.normal = tv(n.x + 1e-9 * srand1(), n.y + 1e-9 * srand1(), n.z + 1e-9 * srand1());
            double nn = sqrt(b.normal.x * b.normal.x + b.normal.y * b.normal.y + b.normal.z * b.normal.z);
            b.normal = tv(b.normal.x / nn, b.normal.y / nn, b.normal.z / nn);
        } else if (kind == 4) { /* near-touching: move b so the distance is tiny (about 1e-9) */
            cdist_result r;
            cdist_circle_circle(q, &a, &b, &r);
            cdist_vec3 d = tv(r.pairs[0].point[0].x - r.pairs[0].point[1].x,
                              r.pairs[0].point[0].y - r.pairs[0].point[1].y,
                              r.pairs[0].point[0].z - r.pairs[0].point[1].z);
            double k = 1 - 1e-9;
            b.center = tv(b.center.x + k * d.x, b.center.y + k * d.y, b.center.z + k * d.z);
        } else if (kind == 5) { /* very different radii */
            b.radius = a.radius * 1e-4 * (1 + urand());
        } else if (kind == 7) { /* an exact family perturbed by 1e-6 .. 1e-14 */
            static const cdist_circle fam[][2] = {
                {{{0, 0, 0}, {0, 0, 1}, 2}, {{2, 0, 0}, {0, 1, 0}, 1}},                   /* meridian */
                {{{0, 0, 0}, {0, 0, 1}, 2}, {{0, 1, 0}, {-0.5, 0, 0.86602540378443865}, 2}}, /* villarceau */
                {{{0, 0, 0}, {0, 0, 1}, 1}, {{0, 0, 0.5}, {0, 0, 1}, 1.5}},                /* coaxial */
                {{{0, 0, 0}, {0, 0, 1}, 1}, {{1, 0, 0}, {0, 1, 0}, 1}},                    /* hopf */
                {{{0, 0, 0}, {0, 0, 1}, 1}, {{2, 0, 0}, {0, 0, 1}, 1}},                    /* external tangent */
                {{{0, 0, 0}, {0, 0, 1}, 2}, {{0, 0, 0.3}, {1, 0, 0}, 1}},                  /* axes perpendicular */
            };
            int fi = (i / 8) % 6;
            double eps = pow(10.0, -6 - 8 * urand());
            a = fam[fi][0];
            b = fam[fi][1];
            b.center = tv(b.center.x + eps * srand1(), b.center.y + eps * srand1(), b.center.z + eps * srand1());
            cdist_vec3 n = tv(b.normal.x + eps * srand1(), b.normal.y + eps * srand1(), b.normal.z + eps * srand1());
            double nn = sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
            b.normal = tv(n.x / nn, n.y / nn, n.z / nn);
            b.radius *= 1 + eps * srand1();
        } else if (kind == 6) { /* centre near the other's axis */
            double h = 2 * srand1();
            b.center = tv(a.center.x + h * a.normal.x + 1e-8 * srand1(), a.center.y + h * a.normal.y,
                          a.center.z + h * a.normal.z);
        }
        cdist_result r, rs;
        CHECK(cdist_circle_circle(q, &a, &b, &r) == CDIST_OK, "random %d status", i);
        CHECK(cdist_circle_circle(q, &b, &a, &rs) == CDIST_OK, "random %d swapped status", i);
        long double e = brute(&a, &b, 2048);
        double L = scale_of(&a, &b, r.distance);
        double err = (double)fabsl((long double)r.distance - e) / L;
        double sym = fabs(r.distance - rs.distance) / L;
        if (err > worst && kind != 7) worst = err;
        if (sym > worst_sym) worst_sym = sym;
        /* Exact families perturbed by 1e-6 .. 1e-14 (kind 7) sit at the resolution limit of
         * double arithmetic (F' near a near-crossing of an axis carries a relative rounding
         * eps L / rho): held to the project's bar of 1e-12 of scale, the rest to 1e-13. */
        double tol = kind == 7 ? 1e-12 : 1e-13;
        if (kind == 7 && err > worst7) worst7 = err;
        CHECK(err <= tol,
              "random %d (kind %d): distance %.17g brute force %.20Lg (err %.3g of scale)\n  cc %.17g %.17g %.17g "
              "%.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g",
              i, kind, r.distance, e, err, a.center.x, a.center.y, a.center.z, a.normal.x, a.normal.y, a.normal.z,
              a.radius, b.center.x, b.center.y, b.center.z, b.normal.x, b.normal.y, b.normal.z, b.radius);
        CHECK(sym <= sym_tol,
              "random %d (kind %d): f(a,b) %.17g f(b,a) %.17g (brute force %.20Lg)\n  cc %.17g %.17g %.17g %.17g %.17g "
              "%.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g",
              i, kind, r.distance, rs.distance, e, a.center.x, a.center.y, a.center.z, a.normal.x, a.normal.y,
              a.normal.z, a.radius, b.center.x, b.center.y, b.center.z, b.normal.x, b.normal.y, b.normal.z, b.radius);
        CHECK(kind == 7 || (r.num_pairs == rs.num_pairs && r.equidistant == rs.equidistant),
              "random %d: swapped flags differ", i);
        if (r.num_pairs == rs.num_pairs && r.num_pairs >= 1) {
            /* swapped pairs: the same points in the other order (pairs may come in either order) */
            double best = INFINITY;
            for (int j = 0; j < rs.num_pairs; j++)
                best = fmin(best, tdist(r.pairs[0].point[0], rs.pairs[j].point[1]) +
                                      tdist(r.pairs[0].point[1], rs.pairs[j].point[0]));
            /* (not for kind 7: near-constant distances leave the pair ill-conditioned) */
            CHECK(kind == 7 || r.equidistant || best <= 1e-6 * L, "random %d (kind %d): swapped pair differs by %.3g",
                  i, kind, best);
        }
        check_pairs("random", &a, &b, &r, 64 * EPS * (L + 2));
        /* invariance under a rigid motion and a scale */
        trot R = rand_rotation();
        double s = exp(2 * srand1());
        cdist_vec3 t = tv(50 * srand1(), 50 * srand1(), 50 * srand1());
        cdist_circle ta = xform_circle(&R, s, t, a), tb = xform_circle(&R, s, t, b);
        cdist_result rt;
        CHECK(cdist_circle_circle(q, &ta, &tb, &rt) == CDIST_OK, "moved %d status", i);
        long double et = brute(&ta, &tb, 2048);
        double Lt = scale_of(&ta, &tb, rt.distance);
        CHECK(fabsl((long double)rt.distance - et) <= tol * Lt,
              "moved %d (kind %d): %.17g vs brute force %.20Lg\n  cc %.17g %.17g %.17g %.17g %.17g %.17g %.17g "
              "%.17g %.17g %.17g %.17g %.17g %.17g %.17g",
              i, kind, rt.distance, et, ta.center.x, ta.center.y, ta.center.z, ta.normal.x, ta.normal.y, ta.normal.z,
              ta.radius, tb.center.x, tb.center.y, tb.center.z, tb.normal.x, tb.normal.y, tb.normal.z, tb.radius);
        /* (for kind 7 the rounding of the motion itself moves the near-degenerate distance) */
        CHECK(kind == 7 || fabs(rt.distance - s * r.distance) <= 1e-12 * Lt + 64 * EPS * 60 * s,
              "moved %d: %.17g vs s d %.17g", i, rt.distance, s * r.distance);
    }
    printf("random: max error vs brute force %.3g of scale (perturbed exact families: %.3g), max asymmetry %.3g "
           "of scale\n",
           worst, worst7, worst_sym);
}

/* Extreme magnitudes: the same configurations scaled by 2^-480 .. 2^480 (about 1e-145 ..
 * 1e145) give the scaled distance (scaling by a power of two is exact). */
static void extreme_scales(void)
{
    for (int i = 0; i < 40; i++) {
        cdist_circle a = rand_circle(1.5), b = rand_circle(1.5);
        if (i % 4 == 1) b = a, b.center.x += 0.25, b.normal = rand_unit(); /* linked-ish */
        if (i % 4 == 2) b.normal = a.normal;                                /* parallel */
        cdist_result r0, r;
        CHECK(cdist_circle_circle(q, &a, &b, &r0) == CDIST_OK, "scale base %d", i);
        for (int e = -480; e <= 480; e += 160) {
            double f = ldexp(1.0, e);
            cdist_circle x = a, y = b;
            x.center = tv(f * a.center.x, f * a.center.y, f * a.center.z);
            y.center = tv(f * b.center.x, f * b.center.y, f * b.center.z);
            x.radius *= f;
            y.radius *= f;
            CHECK(cdist_circle_circle(q, &x, &y, &r) == CDIST_OK, "scale 2^%d status %s", e,
                  cdist_query_last_error(q));
            double L = scale_of(&x, &y, r.distance);
            CHECK(fabs(r.distance - f * r0.distance) <= scale_tol * L, "scale 2^%d case %d: %.17g vs %.17g", e, i,
                  r.distance, f * r0.distance);
            CHECK(r.num_pairs == r0.num_pairs && r.equidistant == r0.equidistant, "scale 2^%d case %d: flags", e,
                  i);
        }
    }
    /* a circle of subnormal radius on the axis of one of radius 1.5e-159, normals of subnormal
     * components (found by the fuzzer): the polynomial and iteration methods reported a closest
     * point 0.12% off the second circle (its direction normalised through a subnormal square) */
    cdist_circle a = {tv(2.2613384610153854e-320, 2.9594532185890668e-320, 7.1871729500526135e-320),
                      tv(-1.0807686002777268e-319, 0, -5.0508330974350634e-320), 3.041962181444555e-320};
    cdist_circle b = {tv(-0.0, 1.4772562810653272e-321, 8.0932893445254596e-320),
                      tv(-1.4582841602650233e-319, 1.3784431518970779e-320, 5.9045785334487374e-320),
                      1.5478445530020227e-159};
    cdist_query_set_unit_tolerance(q, INFINITY);
    for (int m = 0; m < 4; m++) {
        cdist_result r;
        cdist_query_set_method(q, (cdist_method)m);
        CHECK(cdist_circle_circle(q, &a, &b, &r) == CDIST_OK, "subnormal radius on the axis, method %d", m);
        /* checked scaled by 2^520 (exact): the squares of 1e-159 are subnormal doubles (and long
         * double is double under valgrind) */
        const double k = 0x1p520;
        const double kn = 0x1p1000; /* the normals too: the same directions, normal components */
        cdist_circle as = {tv(k * a.center.x, k * a.center.y, k * a.center.z),
                           tv(kn * a.normal.x, kn * a.normal.y, kn * a.normal.z), k * a.radius};
        cdist_circle bs = {tv(k * b.center.x, k * b.center.y, k * b.center.z),
                           tv(kn * b.normal.x, kn * b.normal.y, kn * b.normal.z), k * b.radius};
        cdist_vec3 p0 = tv(k * r.pairs[0].point[0].x, k * r.pairs[0].point[0].y, k * r.pairs[0].point[0].z);
        cdist_vec3 p1 = tv(k * r.pairs[0].point[1].x, k * r.pairs[0].point[1].y, k * r.pairs[0].point[1].z);
        double dp = tdist(p0, p1), tol = 1e-14 * bs.radius;
        CHECK(r.num_pairs == 1 && ref_point_circle(p0, as) <= tol && ref_point_circle(p1, bs) <= tol &&
                  fabs(dp - k * r.distance) <= tol,
              "subnormal radius on the axis, method %d: the pair is off the circles or %.17g from the distance %.17g",
              m, dp / k, r.distance);
    }
    cdist_query_set_method(q, CDIST_METHOD_AUTO);
    cdist_query_set_unit_tolerance(q, 1e-6);
}

static void batch(void)
{
    cdist_circle a[3] = {circ(0, 0, 0, 0, 0, 1, 1), circ(0, 0, 0, 0, 0, 1, 1), circ(0, 0, 0, 0, 0, 1, 2)};
    cdist_circle b[3] = {circ(5, 0, 0, 0, 0, 1, 2), circ(1, 1, 1, 0, 0, 1, -1), circ(2, 0, 0, 0, 0, 1, 2)};
    cdist_result r[3];
    cdist_status st[3];
    cdist_status s = cdist_circle_circle_batch(q, 3, a, b, r, st);
    CHECK(s == CDIST_ERR_NEGATIVE_RADIUS, "batch status %s", cdist_status_name(s));
    CHECK(st[0] == CDIST_OK && st[1] == CDIST_ERR_NEGATIVE_RADIUS && st[2] == CDIST_OK, "batch statuses %d %d %d",
          st[0], st[1], st[2]);
    CHECK(r[0].distance == 2.0 && r[0].num_pairs == 1, "batch entry 0: %g", r[0].distance);
    CHECK(isnan(r[1].distance) && r[1].num_pairs == 0, "batch entry 1 is NaN");
    CHECK(r[2].distance <= 8 * EPS && r[2].num_pairs == 2, "batch entry 2: %g, %d pairs", r[2].distance, r[2].num_pairs);
    CHECK(strstr(cdist_query_last_error(q), "entry 1") != NULL, "batch message: %s", cdist_query_last_error(q));
    /* statuses may be NULL; all good -> OK */
    CHECK(cdist_circle_circle_batch(q, 1, a, b, r, NULL) == CDIST_OK, "batch of one");
    CHECK(cdist_circle_circle_batch(q, 0, NULL, NULL, NULL, NULL) == CDIST_OK, "empty batch");
    CHECK(cdist_circle_circle_batch(q, 2, a, NULL, r, st) == CDIST_ERR_NULL_ARGUMENT, "NULL circles");
}

int main(int argc, char **argv)
{
    const char *method = "auto";
    int count = 400;
    for (int i = 1; i < argc; i++) {
        if (!strncmp(argv[i], "--method=", 9)) method = argv[i] + 9;
        if (!strncmp(argv[i], "--count=", 8)) count = atoi(argv[i] + 8);
        if (!strcmp(argv[i], "--skip-perturbed")) skip_perturbed = 1;
        if (!strncmp(argv[i], "--seed=", 7)) check_rng_state = strtoull(argv[i] + 7, NULL, 10) | 1;
    }
    cdist_method m = !strcmp(method, "polynomial") ? CDIST_METHOD_POLYNOMIAL
                     : !strcmp(method, "robust")   ? CDIST_METHOD_ROBUST
                     : !strcmp(method, "iteration") ? CDIST_METHOD_ITERATION
                                                    : CDIST_METHOD_AUTO;
    q = cdist_query_new();
    cdist_query_set_method(q, m);
    if (m == CDIST_METHOD_POLYNOMIAL || m == CDIST_METHOD_ITERATION) scale_tol = 1e-13;
    if (m == CDIST_METHOD_ITERATION) sym_tol = 8 * EPS;
    paper_examples();
    exact_families();
    random_checks(count);
    extreme_scales();
    batch();
    cdist_query_free(q);
    return check_summary("circle_circle");
}
