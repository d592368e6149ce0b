/* SPDX-License-Identifier: MIT */
/* Lines, rays and segments to circles: the special cases of Eberly §4.1 constructed exactly (and
 * again after a random rotation, translation and scale), agreement of the two methods, rays and
 * segments against an independent long double brute force, properties, bad input. */
#include <float.h>
#include <string.h>

#include "check.h"

static cdist_query *q;
static const cdist_method methods[2] = {CDIST_METHOD_ROBUST, CDIST_METHOD_POLYNOMIAL};
static const char *mname[2] = {"robust", "polynomial"};

static cdist_circle circ(cdist_vec3 c, cdist_vec3 n, double r)
{
    cdist_circle o = {c, n, r};
    return o;
}
static cdist_vec3 add(cdist_vec3 a, cdist_vec3 b) { return tv(a.x + b.x, a.y + b.y, a.z + b.z); }
static cdist_vec3 sub(cdist_vec3 a, cdist_vec3 b) { return tv(a.x - b.x, a.y - b.y, a.z - b.z); }
static cdist_vec3 scl(double s, cdist_vec3 a) { return tv(s * a.x, s * a.y, s * a.z); }
static double dot(cdist_vec3 a, cdist_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static double norm(cdist_vec3 a) { return sqrt(dot(a, a)); }
static cdist_vec3 unitv(cdist_vec3 a) { return scl(1.0 / norm(a), a); }

/* ---- an independent long double reference ---- */
/* Tolerance against the brute force, relative to the scale: 1e-13 where long double carries
 * more bits than double; where it does not (valgrind computes x87 long double in double) the
 * reference itself is off by up to ~1.2e-12 in the degenerate families, so 1e-11 there. */
static double ref_tol = 1e-13;
static int long_double_extended(void)
{
    volatile long double one = 1.0L, tiny = 0x1p-60L;
    return one + tiny != one;
}

typedef struct {
    long double b[3], m[3], c[3], n[3], r;
} ldprob;

static ldprob mkprob(cdist_vec3 B, cdist_vec3 M, cdist_circle c)
{
    ldprob p;
    long double nn = sqrtl((long double)c.normal.x * c.normal.x + (long double)c.normal.y * c.normal.y +
                           (long double)c.normal.z * c.normal.z);
    p.b[0] = B.x; p.b[1] = B.y; p.b[2] = B.z;
    p.m[0] = M.x; p.m[1] = M.y; p.m[2] = M.z;
    p.c[0] = c.center.x; p.c[1] = c.center.y; p.c[2] = c.center.z;
    p.n[0] = c.normal.x / nn; p.n[1] = c.normal.y / nn; p.n[2] = c.normal.z / nn;
    p.r = c.radius;
    return p;
}

/* distance from B + t M to the circle, closed form with |N x D| for the axis distance */
static long double ld_dist(const ldprob *p, long double t)
{
    long double d[3];
    for (int i = 0; i < 3; i++) d[i] = (p->b[i] - p->c[i]) + t * p->m[i];
    long double h = p->n[0] * d[0] + p->n[1] * d[1] + p->n[2] * d[2];
    long double x = p->n[1] * d[2] - p->n[2] * d[1], y = p->n[2] * d[0] - p->n[0] * d[2],
                z = p->n[0] * d[1] - p->n[1] * d[0];
    long double rho = sqrtl(x * x + y * y + z * z);
    return sqrtl((rho - p->r) * (rho - p->r) + h * h);
}

/* min over t in [lo, hi] (finite): dense sampling, then golden section on every sampled local
 * minimum (on the distance itself, which is V-shaped, not flat, where it reaches 0). */
static long double brute(const ldprob *p, long double lo, long double hi, long double *targ)
{
    enum { NS = 4000 };
    static long double f[NS + 1];
    long double best = INFINITY, bt = lo;
    for (int k = 0; k <= NS; k++) f[k] = ld_dist(p, lo + (hi - lo) * k / NS);
    for (int k = 0; k <= NS; k++) {
        int left = k == 0 || f[k] <= f[k - 1], right = k == NS || f[k] <= f[k + 1];
        if (!left || !right) continue;
        long double a = lo + (hi - lo) * (k > 0 ? k - 1 : 0) / NS, b = lo + (hi - lo) * (k < NS ? k + 1 : NS) / NS;
        const long double g = 0.6180339887498948482045868L;
        long double x1 = b - g * (b - a), x2 = a + g * (b - a), f1 = ld_dist(p, x1), f2 = ld_dist(p, x2);
        for (int it = 0; it < 200 && b - a > 0; it++) {
            if (f1 < f2) {
                b = x2; x2 = x1; f2 = f1; x1 = b - g * (b - a); f1 = ld_dist(p, x1);
            } else {
                a = x1; x1 = x2; f1 = f2; x2 = a + g * (b - a); f2 = ld_dist(p, x2);
            }
        }
        long double cand[3] = {a, b, 0.5L * (a + b)};
        for (int i = 0; i < 3; i++) {
            long double v = ld_dist(p, cand[i]);
            if (v < best) { best = v; bt = cand[i]; }
        }
        if (f[k] < best) { best = f[k]; bt = lo + (hi - lo) * k / NS; }
    }
    if (targ) *targ = bt;
    return best;
}

/* ---- helpers ---- */

static cdist_status line_q(int mi, cdist_vec3 B, cdist_vec3 M, cdist_circle c, cdist_result *r)
{
    cdist_query_set_method(q, methods[mi]);
    cdist_line l = {B, M};
    return cdist_line_circle(q, &l, &c, r);
}
static cdist_status ray_q(int mi, cdist_vec3 B, cdist_vec3 M, cdist_circle c, cdist_result *r)
{
    cdist_query_set_method(q, methods[mi]);
    cdist_ray l = {B, M};
    return cdist_ray_circle(q, &l, &c, r);
}
static cdist_status seg_q(int mi, cdist_vec3 p0, cdist_vec3 p1, cdist_circle c, cdist_result *r)
{
    cdist_query_set_method(q, methods[mi]);
    cdist_segment s = {p0, p1};
    return cdist_segment_circle(q, &s, &c, r);
}

/* Every pair: point[0] = B + param[0] M (M as passed), point[1] on the circle at angle param[1],
 * |point[0] - point[1]| = distance. tol absolute. */
static void check_pairs(const char *what, const cdist_result *r, cdist_vec3 B, cdist_vec3 M, cdist_circle c,
                        double tol)
{
    CHECK(r->num_pairs >= 1 && r->num_pairs <= 2, "%s: num_pairs %d", what, r->num_pairs);
    for (int i = 0; i < r->num_pairs && i < 2; i++) {
        const cdist_pair *p = &r->pairs[i];
        cdist_vec3 on = add(B, scl(p->param[0], M));
        CHECK(tdist(on, p->point[0]) <= tol, "%s pair %d: point[0] is %.3g from B + t M", what, i,
              tdist(on, p->point[0]));
        CHECK((double)ref_point_circle(p->point[1], c) <= tol, "%s pair %d: point[1] off the circle by %.3g", what,
              i, (double)ref_point_circle(p->point[1], c));
        if (c.radius > 0) {
            cdist_vec3 k;
            CHECK(cdist_circle_point(&c, p->param[1], &k) == CDIST_OK && tdist(k, p->point[1]) <= tol,
                  "%s pair %d: angle %.17g does not give point[1]", what, i, p->param[1]);
        }
        CHECK(fabs(tdist(p->point[0], p->point[1]) - r->distance) <= tol, "%s pair %d: |p0-p1| %.17g vs %.17g",
              what, i, tdist(p->point[0], p->point[1]), r->distance);
    }
}

/* ---- special cases ---- */

typedef struct {
    const char *name;
    int kind; /* 0 line, 1 ray, 2 segment (B = p0, M = p1) */
    cdist_vec3 B, M;
    double r;
    double dist;
    int pairs, eq;
    double tparam[2]; /* expected line parameters (NaN: not checked) */
} special;

static void run_special(const special *s, int mi, const trot *R, double sc, cdist_vec3 T)
{
    cdist_circle c0 = circ(tv(0, 0, 0), tv(0, 0, 1), s->r);
    cdist_circle c = R ? xform_circle(R, sc, T, c0) : c0;
    cdist_vec3 B = R ? xform_point(R, sc, T, s->B) : s->B;
    cdist_vec3 M = s->kind == 2 ? (R ? xform_point(R, sc, T, s->M) : s->M) : (R ? rot_apply(R, s->M) : s->M);
    double L = sc * fmax(s->r, 1.0) * 4;
    double tol = R ? 1e-14 * L + 8 * DBL_EPSILON * norm(T) : 4 * DBL_EPSILON * L;
    cdist_result r;
    cdist_status st = s->kind == 0 ? line_q(mi, B, M, c, &r) : s->kind == 1 ? ray_q(mi, B, M, c, &r)
                                                                            : seg_q(mi, B, M, c, &r);
    char what[128];
    snprintf(what, sizeof what, "%s [%s%s]", s->name, mname[mi], R ? ", moved" : "");
    CHECK(st == CDIST_OK, "%s: status %s", what, cdist_status_name(st));
    CHECK_NEAR(r.distance, sc * s->dist, tol, what);
    CHECK(r.num_pairs == s->pairs, "%s: %d pairs, expected %d", what, r.num_pairs, s->pairs);
    CHECK(r.equidistant == s->eq, "%s: equidistant %d, expected %d", what, r.equidistant, s->eq);
    CHECK(r.method == (int)methods[mi], "%s: method %d", what, r.method);
    cdist_vec3 dir = s->kind == 2 ? sub(M, B) : M;
    check_pairs(what, &r, B, dir, c, tol);
    if (!R) {
        for (int i = 0; i < s->pairs && i < r.num_pairs; i++) {
            if (isnan(s->tparam[0])) continue;
            double t = r.pairs[i].param[0];
            double e = fmin(fabs(t - s->tparam[0]), fabs(t - s->tparam[1]));
            CHECK(e <= 1e-7, "%s: pair %d param %.17g, expected %g or %g", what, i, t, s->tparam[0], s->tparam[1]);
        }
        if (s->pairs == 2) CHECK(fabs(r.pairs[0].param[0] - r.pairs[1].param[0]) > 1e-3, "%s: distinct pairs", what);
    }
}

static void special_cases(void)
{
    const double rt3 = sqrt(3.0), rt2 = sqrt(2.0);
    const special cases[] = {
        /* the axis: every circle point equally close */
        {"axis", 0, {0, 0, 5}, {0, 0, 1}, 2, 2, 1, 1, {-5, -5}},
        {"axis, downward", 0, {0, 0, 5}, {0, 0, -1}, 2, 2, 1, 1, {5, 5}},
        {"ray on the axis away from the plane", 1, {0, 0, 3}, {0, 0, 1}, 2, sqrt(13.0), 1, 1, {0, 0}},
        {"ray on the axis towards the plane", 1, {0, 0, 3}, {0, 0, -1}, 2, 2, 1, 1, {3, 3}},
        {"segment on the axis", 2, {0, 0, 3}, {0, 0, -1}, 2, 2, 1, 1, {NAN, NAN}},
        {"segment on the axis above the plane", 2, {0, 0, 3}, {0, 0, 1}, 2, sqrt(5.0), 1, 1, {NAN, NAN}},
        /* perpendicular to the plane, not the axis: the plane crossing */
        {"perpendicular inside", 0, {0.5, 0, 7}, {0, 0, -1}, 2, 1.5, 1, 0, {7, 7}},
        {"perpendicular outside", 0, {3, 4, 1}, {0, 0, 1}, 2, 3, 1, 0, {-1, -1}},
        {"ray perpendicular, away", 1, {3, 4, 1}, {0, 0, 1}, 2, sqrt(10.0), 1, 0, {0, 0}},
        /* through the centre: two symmetric pairs at t = +-r m0, distance r |a| */
        {"through centre", 0, {0, 0, 0}, {0.6, 0, 0.8}, 2, 1.6, 2, 0, {-1.2, 1.2}},
        {"through centre, other origin", 0, {-1.5, 0, -2}, {0.6, 0, 0.8}, 2, 1.6, 2, 0, {1.3, 3.7}},
        {"through centre, steep", 0, {0, 0, 0}, {0.28, 0.96, 0}, 1, 0, 2, 0, {-1, 1}},
        /* parallel to the plane */
        {"parallel outside", 0, {0, 3, 1}, {1, 0, 0}, 2, rt2, 1, 0, {0, 0}},
        {"parallel tangent", 0, {0, 2, 1.5}, {1, 0, 0}, 2, 1.5, 1, 0, {NAN, NAN}},
        {"in-plane tangent", 0, {5, 2, 0}, {-1, 0, 0}, 2, 0, 1, 0, {5, 5}},
        {"in-plane secant", 0, {0, 1, 0}, {1, 0, 0}, 2, 0, 2, 0, {-rt3, rt3}},
        {"parallel secant above", 0, {0, 1, 0.5}, {1, 0, 0}, 2, 0.5, 2, 0, {-rt3, rt3}},
        {"parallel through the axis", 0, {0, 0, 1}, {1, 0, 0}, 2, 1, 2, 0, {-2, 2}},
        {"parallel secant, ray sees one", 1, {0, 1, 0.5}, {1, 0, 0}, 2, 0.5, 1, 0, {rt3, rt3}},
        /* through the axis off the centre: not symmetric, one pair (d0^2 - d1^2 = 4 r m0 m2 b2):
         * F = (1 + 0.8 t)^2 + (0.6 |t| - 2)^2 has minima t = -2 (F = 1) and t = 0.4 (F = 4.84) */
        {"through the axis above", 0, {0, 0, 1}, {0.6, 0, 0.8}, 2, 1, 1, 0, {-2, -2}},
        /* radius 0: the circle is its centre */
        {"radius 0", 0, {1, 2, 3}, {0, 0, 1}, 0, sqrt(5.0), 1, 0, {-3, -3}},
        /* segment with an end on the axis that is not the closest point: no flag */
        {"segment from the axis", 2, {0, 0, 0.1}, {3, 0, 0.1}, 2, 0.1, 1, 0, {NAN, NAN}},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        const special s = cases[k];
        for (int mi = 0; mi < 2; mi++) {
            run_special(&s, mi, NULL, 1, tv(0, 0, 0));
            for (int rep = 0; rep < 20; rep++) {
                trot R = rand_rotation();
                double sc = pow(10.0, 4 * srand1());
                cdist_vec3 T = scl(sc * 5, tv(srand1(), srand1(), srand1()));
                run_special(&s, mi, &R, sc, T);
            }
        }
    }
}

/* ---- both methods agree on random lines; both agree with the brute force ---- */

static void random_problem(cdist_vec3 *B, cdist_vec3 *M, cdist_circle *c)
{
    *c = circ(tv(srand1(), srand1(), srand1()), rand_unit(), 0.1 + 2 * urand());
    *B = add(c->center, scl(3, tv(srand1(), srand1(), srand1())));
    *M = rand_unit();
    /* sometimes nearly degenerate: parallel to the plane, through the centre, near the axis */
    int k = (int)(urand() * 8);
    cdist_vec3 n = c->normal;
    if (k == 0) *M = unitv(sub(*M, scl(dot(*M, n), n)));
    if (k == 1) *B = c->center;
    if (k == 2) *M = unitv(add(n, scl(1e-7, rand_unit())));
    if (k == 3) *B = add(c->center, scl(c->radius * (1 + 1e-9 * srand1()), unitv(sub(*M, scl(dot(*M, n), n)))));
}

static void methods_agree(void)
{
    double worst = 0, worstb = 0;
    for (int it = 0; it < 20000; it++) {
        cdist_vec3 B, M;
        cdist_circle c;
        random_problem(&B, &M, &c);
        cdist_result r0, r1;
        CHECK(line_q(0, B, M, c, &r0) == CDIST_OK && line_q(1, B, M, c, &r1) == CDIST_OK, "random status");
        cdist_vec3 rel = sub(B, c.center);
        cdist_vec3 B0 = sub(rel, scl(dot(rel, M), M));
        double L = fmax(c.radius, norm(B0));
        double e = fabs(r0.distance - r1.distance) / L;
        worst = fmax(worst, e);
        CHECK(e <= 1e-14, "random %d: robust %.17g polynomial %.17g", it, r0.distance, r1.distance);
        if (it < 2000) {
            /* a few against the long double brute force on [-R, R] around B0 */
            ldprob p = mkprob(B, M, c);
            double t0 = -dot(rel, M), R = 2 * (c.radius + norm(B0)) + 1;
            long double ref = brute(&p, t0 - R, t0 + R, NULL);
            double eb = (double)fabsl(r0.distance - ref) / L;
            worstb = fmax(worstb, eb);
            CHECK(eb <= ref_tol, "random line %d vs brute force: %.17g vs %.17Lg", it, r0.distance, ref);
        }
        check_pairs("random robust", &r0, B, M, c, 1e-13 * fmax(L, norm(rel)));
        check_pairs("random polynomial", &r1, B, M, c, 1e-13 * fmax(L, norm(rel)));
    }
    printf("methods agree on random lines: max difference %.3g of scale; vs brute force %.3g\n", worst, worstb);
}

/* ---- degenerate families against the long double brute force ---- */

static void degenerate_families(void)
{
    double worst = 0;
    for (int it = 0; it < 4200; it++) {
        cdist_circle c = circ(tv(srand1(), srand1(), srand1()), rand_unit(), 0.1 + 2 * urand());
        cdist_vec3 n = c.normal, e = unitv(sub(rand_unit(), scl(dot(rand_unit(), n), n)));
        e = unitv(sub(e, scl(dot(e, n), n)));
        cdist_vec3 f = tv(n.y * e.z - n.z * e.y, n.z * e.x - n.x * e.z, n.x * e.y - n.y * e.x);
        double k = pow(10.0, -3 - 12 * urand()), r = c.radius;
        cdist_vec3 B, M;
        switch (it % 7) {
        case 0: /* nearly perpendicular to the plane, anywhere near the circle */
            M = unitv(add(n, scl(k, e)));
            B = add(c.center, scl(r, tv(1.5 * srand1(), 1.5 * srand1(), 1.5 * srand1())));
            break;
        case 1: /* nearly parallel, nearly tangent (inside or outside), at some height */
            M = unitv(add(e, scl(k * srand1(), n)));
            B = add(add(c.center, scl(r * (1 + k * srand1()), f)), scl(r * srand1() * (it % 12 < 6), n));
            break;
        case 2: /* nearly through the centre */
            M = rand_unit();
            B = add(c.center, scl(k * r, rand_unit()));
            break;
        case 3: /* nearly the axis */
            M = unitv(add(n, scl(k, rand_unit())));
            B = add(c.center, add(scl(k * r, e), scl(3 * srand1(), n)));
            break;
        case 4: /* far from the circle, or a tiny circle */
            M = rand_unit();
            B = add(c.center, scl(1e3 * r, rand_unit()));
            if (it % 12 < 6) c.radius = r * k;
            break;
        case 5: /* far from the coordinate origin, line origin near the circle */
            c.center = scl(1e5, tv(srand1(), srand1(), srand1()));
            M = rand_unit();
            B = add(add(c.center, scl(r, tv(srand1(), srand1(), srand1()))), scl(10 * srand1(), M));
            break;
        default: /* origin far along the line */
            M = rand_unit();
            B = add(add(c.center, scl(r, tv(srand1(), srand1(), srand1()))), scl(1e4 * srand1(), M));
            break;
        }
        cdist_vec3 rel = sub(B, c.center);
        double t0 = -dot(rel, M);
        cdist_vec3 B0 = add(rel, scl(t0, M));
        double L = fmax(c.radius, norm(B0)), R = 2 * L + 1;
        ldprob p = mkprob(B, M, c);
        long double ref = brute(&p, t0 - R, t0 + R, NULL);
        for (int mi = 0; mi < 2; mi++) {
            cdist_result res;
            CHECK(line_q(mi, B, M, c, &res) == CDIST_OK, "degenerate status");
            double err = (double)fabsl(res.distance - ref) / L;
            worst = fmax(worst, err);
            CHECK(err <= ref_tol, "degenerate family %d, k %.3g (%s): %.17g vs brute force %.17Lg (%.3g of scale)",
                  it % 7, k, mname[mi], res.distance, ref, err);
            /* point coordinates carry rounding of their own magnitude */
            check_pairs("degenerate", &res, B, M, c,
                        1e-13 * fmax(L, norm(rel)) + 16 * DBL_EPSILON * (norm(c.center) + norm(B)));
        }
    }
    printf("degenerate families vs brute force: max error %.3g of scale\n", worst);
}

/* ---- rays and segments against the long double brute force ---- */

static void rays_segments(void)
{
    double worst[2] = {0, 0};
    for (int it = 0; it < 3000; it++) {
        cdist_circle c = circ(tv(srand1(), srand1(), srand1()), rand_unit(), 0.1 + 2 * urand());
        cdist_vec3 M = rand_unit();
        cdist_vec3 n = c.normal;
        int k = it % 6;
        if (k == 0) M = unitv(sub(M, scl(dot(M, n), n)));
        if (k == 1) M = unitv(add(n, scl(1e-3, rand_unit())));
        /* a line through a point near the circle */
        cdist_vec3 X = add(c.center, scl(1.5 * c.radius, tv(srand1(), srand1(), srand1())));
        if (k == 2) X = c.center;
        double ta = 3 * srand1(), tb = 3 * srand1();
        cdist_vec3 B = add(X, scl(ta, M));
        int mi = it & 1;
        cdist_result r;
        /* ray */
        CHECK(ray_q(mi, B, M, c, &r) == CDIST_OK, "ray status");
        ldprob p = mkprob(B, M, c);
        cdist_vec3 rel = sub(B, c.center);
        double L = fmax(c.radius, norm(rel));
        long double ref = brute(&p, 0, 2 * (norm(rel) + c.radius) + 1, NULL);
        double e = (double)fabsl(r.distance - ref) / L;
        worst[0] = fmax(worst[0], e);
        CHECK(e <= ref_tol, "ray %d (%s): %.17g vs brute force %.17Lg", it, mname[mi], r.distance, ref);
        check_pairs("ray", &r, B, M, c, 1e-13 * L);
        for (int i = 0; i < r.num_pairs; i++) CHECK(r.pairs[i].param[0] >= 0, "ray param >= 0");
        /* segment */
        cdist_vec3 P1 = add(X, scl(tb, M));
        CHECK(seg_q(mi, B, P1, c, &r) == CDIST_OK, "segment status");
        cdist_vec3 D = sub(P1, B);
        p = mkprob(B, D, c);
        L = fmax(L, norm(sub(P1, c.center)));
        ref = brute(&p, 0, 1, NULL);
        e = (double)fabsl(r.distance - ref) / L;
        worst[1] = fmax(worst[1], e);
        CHECK(e <= ref_tol, "segment %d (%s): %.17g vs brute force %.17Lg", it, mname[mi], r.distance, ref);
        check_pairs("segment", &r, B, D, c, 1e-13 * L);
        for (int i = 0; i < r.num_pairs; i++)
            CHECK(r.pairs[i].param[0] >= 0 && r.pairs[i].param[0] <= 1, "segment param in [0,1]");
    }
    printf("rays vs brute force: max error %.3g of scale; segments %.3g\n", worst[0], worst[1]);
}

/* ---- properties ---- */

static void properties(void)
{
    for (int it = 0; it < 2000; it++) {
        cdist_vec3 B, M;
        cdist_circle c;
        random_problem(&B, &M, &c);
        int mi = it & 1;
        cdist_result r, rt;
        CHECK(line_q(mi, B, M, c, &r) == CDIST_OK, "status");
        cdist_vec3 rel = sub(B, c.center);
        double L = fmax(c.radius, norm(sub(rel, scl(dot(rel, M), M))));
        /* invariance under rotation, translation and scale */
        trot R = rand_rotation();
        double sc = pow(2.0, (int)(20 * srand1())) * (1 + 0.1 * urand());
        cdist_vec3 T = scl(sc * 3, tv(srand1(), srand1(), srand1()));
        cdist_circle c2 = xform_circle(&R, sc, T, c);
        CHECK(line_q(mi, xform_point(&R, sc, T, B), rot_apply(&R, M), c2, &rt) == CDIST_OK, "moved status");
        CHECK(fabs(rt.distance - sc * r.distance) <= 2e-14 * sc * (L + norm(rel)), "invariance %d: %.17g vs %.17g",
              it, rt.distance, sc * r.distance);
        /* no sampled pair is closer than the distance */
        for (int k = 0; k < 50; k++) {
            double t = dot(scl(-1, rel), M) + 3 * (L + 1) * srand1(), a = M_PI * srand1();
            cdist_vec3 P = add(B, scl(t, M)), K;
            cdist_circle_point(&c, a, &K);
            CHECK(tdist(P, K) >= r.distance - 1e-14 * (L + norm(rel)), "sampled pair closer: %.17g < %.17g",
                  tdist(P, K), r.distance);
        }
        /* a direction of another length (any length accepted): same points, t for that direction */
        cdist_query_set_unit_tolerance(q, INFINITY);
        cdist_vec3 M3 = scl(3.0, M);
        CHECK(line_q(mi, B, M3, c, &rt) == CDIST_OK, "scaled direction status");
        CHECK(fabs(rt.distance - r.distance) <= 1e-14 * (L + norm(rel)), "scaled direction distance");
        check_pairs("scaled direction", &rt, B, M3, c, 1e-13 * (L + norm(rel)));
        cdist_query_set_unit_tolerance(q, 1e-6);
        /* the ray from the line's point of the best pair sees the same distance; the ray
         * beyond it the other way never sees less */
        cdist_vec3 P0 = r.pairs[0].point[0];
        CHECK(ray_q(mi, P0, M, c, &rt) == CDIST_OK && fabs(rt.distance - r.distance) <= 1e-13 * (L + norm(rel)),
              "ray from the closest point: %.17g vs %.17g", rt.distance, r.distance);
        CHECK(ray_q(mi, add(P0, M), M, c, &rt) == CDIST_OK && rt.distance >= r.distance - 1e-14 * (L + norm(rel)),
              "ray beyond");
    }
    /* far from the origin: the same configuration moved by 1e6 keeps ~1e-10 absolute */
    cdist_circle c = circ(tv(1e6, -2e6, 3e6), unitv(tv(1, 2, 2)), 1.5);
    cdist_vec3 B = add(c.center, tv(0.3, 2, -1)), M = unitv(tv(2, -1, 0.5));
    cdist_circle c0 = circ(tv(0, 0, 0), c.normal, 1.5);
    cdist_result r, r0;
    for (int mi = 0; mi < 2; mi++) {
        CHECK(line_q(mi, B, M, c, &r) == CDIST_OK && line_q(mi, tv(0.3, 2, -1), M, c0, &r0) == CDIST_OK, "far");
        CHECK_NEAR(r.distance, r0.distance, 4e-10, "far from the origin");
    }
    /* AUTO answers with ROBUST; ITERATION (not a method of this query) too */
    cdist_query_set_method(q, CDIST_METHOD_AUTO);
    cdist_line l = {B, M};
    CHECK(cdist_line_circle(q, &l, &c, &r) == CDIST_OK && r.method == CDIST_METHOD_ROBUST, "auto is robust");
    cdist_query_set_method(q, CDIST_METHOD_ITERATION);
    CHECK(cdist_line_circle(q, &l, &c, &r) == CDIST_OK && r.method == CDIST_METHOD_ROBUST, "iteration -> robust");
    /* segment p0 == p1 is a point */
    cdist_segment s = {B, B};
    CHECK(cdist_segment_circle(q, &s, &c, &r) == CDIST_OK, "point segment");
    CHECK(cdist_point_circle(q, &B, &c, &r0) == CDIST_OK && r.distance == r0.distance && r.pairs[0].param[0] == 0,
          "point segment = point-circle");
    cdist_query_set_method(q, CDIST_METHOD_AUTO);
}

/* A problem far smaller than its coordinates (a circle of radius 1e-300 at x = 1e10; a segment
 * of length 1e-320 at x = 2^49): scaled to its own size the coordinates overflowed, and every
 * query ended in CDIST_ERR_INTERNAL. Expected values: the obvious geometry, and for the tilted
 * lines mpmath (tests/lines/far_tiny_ref.py, dense angle sampling + golden refinement
 * in coordinates relative to the centre, 60 digits). */
static void far_tiny(void)
{
    const double X = 1e10, r = 1e-300;
    cdist_circle c = circ(tv(X, 0, 0), tv(1, 0, 0), r);
    cdist_result res;
    for (int mi = 0; mi < 2; mi++) {
        cdist_query_set_method(q, methods[mi]);
        cdist_line axis = {tv(X, 0, 0), tv(1, 0, 0)}, inplane = {tv(X, 0, 0), tv(0, 1, 0)};
        cdist_ray raxis = {tv(X, 0, 0), tv(1, 0, 0)};
        /* the axis: every circle point at distance r; the disk is crossed */
        CHECK(cdist_line_circle(q, &axis, &c, &res) == CDIST_OK && res.distance == r && res.equidistant,
              "far tiny: line on the axis (%s): %.17g", mname[mi], res.distance);
        CHECK(cdist_ray_circle(q, &raxis, &c, &res) == CDIST_OK && res.distance == r && res.equidistant,
              "far tiny: ray on the axis (%s): %.17g", mname[mi], res.distance);
        CHECK(cdist_line_disk(q, &axis, &c, &res) == CDIST_OK && res.distance == 0.0, "far tiny: line-disk (%s)",
              mname[mi]);
        CHECK(cdist_ray_disk(q, &raxis, &c, &res) == CDIST_OK && res.distance == 0.0, "far tiny: ray-disk (%s)",
              mname[mi]);
        /* in the plane through the centre: crosses the circle twice */
        CHECK(cdist_line_circle(q, &inplane, &c, &res) == CDIST_OK && res.distance == 0.0 && res.num_pairs == 2,
              "far tiny: line in the plane (%s): %.17g, %d pairs", mname[mi], res.distance, res.num_pairs);
        /* the smallest radius */
        cdist_circle sub = circ(tv(X, 0, 0), tv(1, 0, 0), 5e-324);
        CHECK(cdist_line_circle(q, &axis, &sub, &res) == CDIST_OK && res.distance == 5e-324,
              "far tiny: radius 5e-324 (%s): %.17g", mname[mi], res.distance);
        /* a segment of subnormal length at 2^49 (p1 - p0 = (0, 1e-320, 0), exact) */
        const double Y = 0x1p49;
        cdist_segment sg = {tv(Y, 0, 0), tv(Y, 1e-320, 0)};
        cdist_circle cs = circ(tv(Y, 0, 0), tv(1, 0, 0), r);
        CHECK(cdist_segment_circle(q, &sg, &cs, &res) == CDIST_OK && fabs(res.distance - (r - 1e-320)) <= 4e-16 * r,
              "far tiny: segment in the plane (%s): %.17g", mname[mi], res.distance);
        CHECK(cdist_segment_disk(q, &sg, &cs, &res) == CDIST_OK && res.distance == 0.0,
              "far tiny: segment-disk (%s): %.17g", mname[mi], res.distance);
        cdist_circle pt = circ(tv(Y, 3e-320, 0), tv(0, 0, 1), 0.0);
        CHECK(cdist_segment_circle(q, &sg, &pt, &res) == CDIST_OK && res.distance == 3e-320 - 1e-320,
              "far tiny: segment to a point (%s): %.17g", mname[mi], res.distance);
        /* tilted lines and rays (mpmath) */
        static const struct {
            int ray;
            double o[3], d[3], c[3], n[3], r, expect;
        } T[] = {
            {0, {1e10, 1.6388162525724092e-300, -1.1412072766573532e-300},
             {-0.41610325208200699, 0.83167139159654491, -0.36766938954262174},
             {1e10, -1.6562110652433133e-300, -3.2731139451696211e-301},
             {-0.31355142005619185, -0.92554030675682242, -0.21227493386933971}, 5.5725970024134755e-301,
             1.1685214789257201251e-300},
            {0, {1e10, -5.1040982909707508e-301, 1.9097786283823126e-301},
             {-0.16273172480573278, 0.64032002629907314, 0.75067213193384608},
             {1e10, -1.7488441001067075e-300, -1.7615953201350695e-300},
             {0.67600068438250549, 0.29743752434729109, -0.67420619533236181}, 4.9132155435672043e-301,
             3.9719956800895304218e-303},
            {1, {1e10, -1.9097482877776457e-300, -1.5321885480093656e-301},
             {-0.18422307351495118, -0.58560384851458247, 0.78938583201728096},
             {1e10, -1.3278064843738217e-300, -1.5316168220730725e-300},
             {-0.081324055447123275, -0.21494806101977632, 0.97323364567274984}, 2.1201339672948977e-301,
             1.4690062807617788277e-300},
            {1, {1e10, -3.934229746627835e-301, -8.886434768621974e-301},
             {0.11426489540623476, -0.99304590971694096, 0.02834351552393069},
             {1e10, -1.4522954279398968e-300, -2.7791339564369722e-301},
             {0.92470972976695431, 0.2630574704154528, -0.27515937733057472}, 1.1454171503260734e-300,
             1.0901748157376875645e-301},
        };
        for (size_t i = 0; i < sizeof T / sizeof T[0]; i++) {
            cdist_vec3 o = tv(T[i].o[0], T[i].o[1], T[i].o[2]), d = tv(T[i].d[0], T[i].d[1], T[i].d[2]);
            cdist_circle ct = circ(tv(T[i].c[0], T[i].c[1], T[i].c[2]), tv(T[i].n[0], T[i].n[1], T[i].n[2]), T[i].r);
            double L = fmax(T[i].r, fmax(fabs(T[i].o[1] - T[i].c[1]), fabs(T[i].o[2] - T[i].c[2])));
            cdist_status st = T[i].ray ? ray_q(mi, o, d, ct, &res) : line_q(mi, o, d, ct, &res);
            CHECK(st == CDIST_OK && fabs(res.distance - T[i].expect) <= 1e-14 * L,
                  "far tiny: tilted %zu (%s): %.17g vs %.17g", i, mname[mi], res.distance, T[i].expect);
        }
    }
    cdist_query_set_method(q, CDIST_METHOD_AUTO);
}

/* ---- extreme magnitudes ---- */

static void extremes(void)
{
    /* power-of-two scalings are exact: the distance must scale exactly (to rounding) */
    for (int it = 0; it < 400; it++) {
        cdist_vec3 B, M;
        cdist_circle c;
        random_problem(&B, &M, &c);
        int mi = it & 1;
        cdist_result r, rs;
        CHECK(line_q(mi, B, M, c, &r) == CDIST_OK, "extremes status");
        double L = fmax(c.radius, r.distance);
        for (int e = -480; e <= 480; e += 240) {
            double f = ldexp(1.0, e);
            cdist_circle cs = circ(scl(f, c.center), c.normal, f * c.radius);
            CHECK(line_q(mi, scl(f, B), M, cs, &rs) == CDIST_OK, "scaled status");
            CHECK(fabs(rs.distance / f - r.distance) <= 1e-14 * (L + norm(sub(B, c.center))),
                  "scaled by 2^%d: %.17g vs %.17g", e, rs.distance / f, r.distance);
            CHECK(rs.num_pairs == r.num_pairs && rs.equidistant == r.equidistant, "scaled by 2^%d: pairs", e);
        }
    }
    cdist_circle c = circ(tv(0, 0, 0), tv(0, 0, 1), 2);
    cdist_result r;
    for (int mi = 0; mi < 2; mi++) {
        /* a segment of length 1e-200 is (nearly) a point */
        cdist_vec3 p0 = tv(3, 0, 0.5);
        CHECK(seg_q(mi, p0, add(p0, tv(1e-200, 0, 0)), c, &r) == CDIST_OK, "tiny segment status");
        CHECK_NEAR(r.distance, sqrt(1.25), 4e-16, "tiny segment");
        CHECK(r.pairs[0].param[0] >= 0 && r.pairs[0].param[0] <= 1, "tiny segment param");
        /* a direction of length 1e-300 (any length accepted) */
        cdist_query_set_unit_tolerance(q, INFINITY);
        CHECK(line_q(mi, tv(0, 1, 0.5), tv(1e-300, 0, 0), c, &r) == CDIST_OK, "tiny direction status");
        CHECK_NEAR(r.distance, 0.5, 4e-16, "tiny direction");
        CHECK(r.num_pairs == 2 && isfinite(r.pairs[0].param[0]) && isfinite(r.pairs[1].param[0]),
              "tiny direction: two pairs with finite parameters (%d)", r.num_pairs);
        CHECK(line_q(mi, tv(0, 1, 0.5), tv(1e100, 0, 0), c, &r) == CDIST_OK && fabs(r.distance - 0.5) <= 4e-16,
              "huge direction");
        cdist_query_set_unit_tolerance(q, 1e-6);
        /* coordinates near the 1e150 limit */
        cdist_circle big = circ(tv(5e149, -5e149, 5e149), tv(0, 0, 1), 5e149);
        CHECK(line_q(mi, tv(5e149, -2.5e149, 7.5e149), tv(1, 0, 0), big, &r) == CDIST_OK, "huge status");
        CHECK(fabs(r.distance - 2.5e149) <= 1e-15 * 2.5e149 && r.num_pairs == 2,
              "huge coordinates: %.17g, %d pairs", r.distance, r.num_pairs);
        /* a ray far from a tiny circle */
        cdist_circle tiny = circ(tv(0, 0, 0), tv(0, 0, 1), 1e-300);
        CHECK(ray_q(mi, tv(1, 1, 1), tv(0, 0, 1), tiny, &r) == CDIST_OK, "tiny circle status");
        CHECK_NEAR(r.distance, sqrt(3.0), 4e-16, "tiny circle");
        /* a ray of direction 1e-319 (subnormal, any length accepted) against a circle of radius
         * 8e-171 (found by the fuzzer): its length's few bits made the range conversion 1e-5 off,
         * so the distance was 7e-6 too small; the same ray with its direction scaled by 2^600 is
         * the reference */
        cdist_query_set_unit_tolerance(q, INFINITY);
        cdist_circle sub = circ(tv(-4.7484649221802205e-320, 1.3343230897234545e-319, 0),
                                tv(3.8764390572704204e-320, 1.2918828507456915e-319, -5.933728406553371e-320),
                                8.0947715414629838e-171);
        cdist_vec3 o = tv(8.0947715414629838e-171, -7.0611862103630956e-320, 0),
                   dsub = tv(-8.3279705263000517e-320, 0, -1.4995386416927674e-319);
        cdist_result rr;
        CHECK(ray_q(mi, o, dsub, sub, &r) == CDIST_OK && ray_q(mi, o, scl(0x1p600, dsub), sub, &rr) == CDIST_OK &&
                  fabs(r.distance - rr.distance) <= 4e-16 * 8.1e-171,
              "subnormal ray direction: %.17g vs %.17g with the direction scaled", r.distance, rr.distance);
        cdist_ray ray = {o, dsub}, rays = {o, scl(0x1p600, dsub)};
        CHECK(cdist_ray_disk(q, &ray, &sub, &r) == CDIST_OK && cdist_ray_disk(q, &rays, &sub, &rr) == CDIST_OK &&
                  fabs(r.distance - rr.distance) <= 4e-16 * 8.1e-171,
              "subnormal ray direction, disk: %.17g vs %.17g with the direction scaled", r.distance, rr.distance);
        cdist_query_set_unit_tolerance(q, 1e-6);
        /* a tiny segment along the axis, 1e-302 off it (found by the fuzzer): the circle point of
         * a direction with subnormal squares was NaN (r / |(X, Y)| overflowed) */
        cdist_circle off = circ(tv(-4.1858709320789469e-302, 0, 0), tv(1, -2.8393226951346075e-22, 0), 3.1396500615433622e-07);
        CHECK(seg_q(mi, tv(9.332636185032189e-151, 0, 0), tv(6.3931240613300022e-213, 0, 0), off, &r) == CDIST_OK,
              "segment on the axis status");
        CHECK_NEAR(r.distance, 3.1396500615433622e-07, 4e-16 * 3.14e-7, "segment on the axis");
        CHECK(r.num_pairs >= 1 && isfinite(r.pairs[0].point[1].x) && isfinite(r.pairs[0].point[1].y) &&
                  isfinite(r.pairs[0].point[1].z) &&
                  fabs(hypot(r.pairs[0].point[1].y, r.pairs[0].point[1].z) - 3.1396500615433622e-07) <= 1e-21,
              "segment on the axis: the circle point (%g %g %g) is on the circle", r.pairs[0].point[1].x,
              r.pairs[0].point[1].y, r.pairs[0].point[1].z);
    }
    far_tiny();
}

/* ---- bad input ---- */

static void bad_input(void)
{
    cdist_result r;
    cdist_circle c = circ(tv(0, 0, 0), tv(0, 0, 1), 1);
    cdist_line l = {tv(1, 2, 3), tv(1, 0, 0)};
    cdist_ray ray = {tv(1, 2, 3), tv(1, 0, 0)};
    cdist_segment s = {tv(1, 2, 3), tv(2, 2, 3)};
    CHECK(cdist_line_circle(NULL, &l, &c, &r) == CDIST_ERR_NULL_ARGUMENT, "NULL handle");
    CHECK(isnan(r.distance) && r.num_pairs == 0, "error result");
    CHECK(cdist_line_circle(q, NULL, &c, &r) == CDIST_ERR_NULL_ARGUMENT, "NULL line");
    CHECK(cdist_ray_circle(q, NULL, &c, &r) == CDIST_ERR_NULL_ARGUMENT, "NULL ray");
    CHECK(cdist_segment_circle(q, NULL, &c, &r) == CDIST_ERR_NULL_ARGUMENT, "NULL segment");
    CHECK(cdist_line_circle(q, &l, NULL, &r) == CDIST_ERR_NULL_ARGUMENT, "NULL circle");
    CHECK(cdist_line_circle(q, &l, &c, NULL) == CDIST_ERR_NULL_ARGUMENT, "NULL result");
    cdist_line bad = l;
    bad.origin.y = NAN;
    CHECK(cdist_line_circle(q, &bad, &c, &r) == CDIST_ERR_NOT_FINITE, "NaN origin");
    CHECK(isnan(r.distance) && r.num_pairs == 0, "NaN origin result");
    CHECK(strstr(cdist_query_last_error(q), "origin") != NULL, "message: %s", cdist_query_last_error(q));
    bad = l;
    bad.direction = tv(0, 0, 0);
    CHECK(cdist_line_circle(q, &bad, &c, &r) == CDIST_ERR_ZERO_VECTOR, "zero direction");
    bad.direction = tv(2, 0, 0);
    CHECK(cdist_line_circle(q, &bad, &c, &r) == CDIST_ERR_NOT_UNIT, "non-unit direction");
    bad.direction = tv(INFINITY, 0, 0);
    CHECK(cdist_line_circle(q, &bad, &c, &r) == CDIST_ERR_NOT_FINITE, "infinite direction");
    bad = l;
    bad.origin.x = 1e151;
    CHECK(cdist_line_circle(q, &bad, &c, &r) == CDIST_ERR_OUT_OF_RANGE, "huge origin");
    cdist_ray bray = ray;
    bray.direction = tv(0, 0.5, 0);
    CHECK(cdist_ray_circle(q, &bray, &c, &r) == CDIST_ERR_NOT_UNIT, "ray non-unit");
    bray.direction = tv(0, 0, 0);
    CHECK(cdist_ray_circle(q, &bray, &c, &r) == CDIST_ERR_ZERO_VECTOR, "ray zero");
    cdist_segment bs = s;
    bs.p1.z = NAN;
    CHECK(cdist_segment_circle(q, &bs, &c, &r) == CDIST_ERR_NOT_FINITE, "segment NaN");
    bs = s;
    bs.p1 = tv(5, 7, 100); /* any length: fine */
    CHECK(cdist_segment_circle(q, &bs, &c, &r) == CDIST_OK, "segment of any length");
    cdist_circle bc = c;
    bc.radius = -1;
    CHECK(cdist_line_circle(q, &l, &bc, &r) == CDIST_ERR_NEGATIVE_RADIUS, "negative radius");
    bc = c;
    bc.normal = tv(0, 0, 0);
    CHECK(cdist_segment_circle(q, &s, &bc, &r) == CDIST_ERR_ZERO_VECTOR, "zero normal");
    bc.normal = tv(0, 0, 3);
    CHECK(cdist_ray_circle(q, &ray, &bc, &r) == CDIST_ERR_NOT_UNIT, "non-unit normal");
    CHECK(cdist_line_circle(q, &l, &c, &r) == CDIST_OK && cdist_query_last_error(q)[0] == '\0', "recovers");
}

int main(void)
{
    q = cdist_query_new();
    if (!long_double_extended()) {
        ref_tol = 1e-11;
        printf("long double has double precision here (valgrind?): brute-force tolerance %g\n", ref_tol);
    }
    special_cases();
    methods_agree();
    degenerate_families();
    rays_segments();
    properties();
    extremes();
    bad_input();
    cdist_query_free(q);
    return check_summary("lines");
}
