/* SPDX-License-Identifier: MIT */
/* Circle-circle POLYNOMIAL and ITERATION methods through the public API: the paper's worked
 * examples, exact constructions of every special family (pair counts and flags asserted),
 * symmetry, rigid-motion and scale invariance, the iteration count, and an independent long
 * double brute force (dense sampling + golden section on the closed-form point-circle
 * distance) on random linked and near-degenerate configurations.
 *
 * The dispatcher falls back to the robust method when a method fails and then reports
 * method ROBUST: every answer here must come from the method asked for (test_cc_core also calls
 * the methods directly). */
#include <string.h>

#include "check.h"

static cdist_query *q;
static cdist_method method;
static const char *mname;

static cdist_vec3 unitv(double x, double y, double z)
{
    double n = sqrt(x * x + y * y + z * z);
    return tv(x / n, y / n, z / n);
}

static cdist_circle circ(double cx, double cy, double cz, cdist_vec3 n, double r)
{
    cdist_circle c = {tv(cx, cy, cz), n, r};
    return c;
}

static const cdist_vec3 Z = {0, 0, 1};

/* ---- long double brute force ---- */

typedef struct {
    long double c[3], n[3], u[3], v[3], r;
} lcirc;

static void lcross(const long double *a, const long double *b, long double *o)
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

static lcirc lmake(const cdist_circle *c)
{
    lcirc o;
    o.c[0] = c->center.x, o.c[1] = c->center.y, o.c[2] = c->center.z;
    long double n[3] = {c->normal.x, c->normal.y, c->normal.z};
    long double nn = sqrtl(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int i = 0; i < 3; i++) o.n[i] = n[i] / nn;
    /* any in-plane unit vector: cross with the axis of the largest |n| component's successor */
    int k = fabsl(o.n[0]) < 0.5L ? 0 : (fabsl(o.n[1]) < 0.5L ? 1 : 2);
    long double e[3] = {0, 0, 0};
    e[k] = 1;
    lcross(o.n, e, o.u);
    long double un = sqrtl(o.u[0] * o.u[0] + o.u[1] * o.u[1] + o.u[2] * o.u[2]);
    for (int i = 0; i < 3; i++) o.u[i] /= un;
    lcross(o.n, o.u, o.v);
    o.r = c->radius;
    return o;
}

/* distance from m(t) to circle f */
static long double ldist(const lcirc *m, const lcirc *f, long double t)
{
    long double ct = cosl(t), st = sinl(t), d[3], nd[3];
    for (int i = 0; i < 3; i++) d[i] = m->c[i] + m->r * (ct * m->u[i] + st * m->v[i]) - f->c[i];
    long double h = f->n[0] * d[0] + f->n[1] * d[1] + f->n[2] * d[2];
    lcross(f->n, d, nd);
    long double rho = sqrtl(nd[0] * nd[0] + nd[1] * nd[1] + nd[2] * nd[2]);
    return sqrtl(h * h + (rho - f->r) * (rho - f->r));
}

#define BF_N 4096
/* Minimum over m of the distance to f; *count = distinct local minima within `tie` of it. */
static long double bf_side(const lcirc *m, const lcirc *f, long double tie, int *count)
{
    static long double val[BF_N];
    const long double step = 2.0L * 3.14159265358979323846264338327950288L / BF_N;
    for (int i = 0; i < BF_N; i++) val[i] = ldist(m, f, i * step);
    long double mins[BF_N / 2];
    int nm = 0;
    for (int i = 0; i < BF_N && nm < BF_N / 2; i++) {
        long double a = val[(i + BF_N - 1) % BF_N], b = val[i], c = val[(i + 1) % BF_N];
        if (!(b <= a && b < c)) continue;
        long double lo = (i - 1) * step, hi = (i + 1) * step;
        const long double gr = 0.61803398874989484820458683436563812L;
        long double x1 = hi - gr * (hi - lo), x2 = lo + gr * (hi - lo);
        long double f1 = ldist(m, f, x1), f2 = ldist(m, f, x2);
        for (int it = 0; it < 110; it++) {
            if (f1 <= f2) {
                hi = x2, x2 = x1, f2 = f1;
                x1 = hi - gr * (hi - lo);
                f1 = ldist(m, f, x1);
            } else {
                lo = x1, x1 = x2, f1 = f2;
                x2 = lo + gr * (hi - lo);
                f2 = ldist(m, f, x2);
            }
        }
        long double v = fminl(fminl(f1, f2), b);
        mins[nm++] = v;
    }
    long double best = INFINITY;
    for (int i = 0; i < nm; i++) best = fminl(best, mins[i]);
    int cnt = 0;
    for (int i = 0; i < nm; i++)
        if (mins[i] - best <= tie) cnt++;
    if (count) *count = cnt;
    return best;
}

static double scale_of(const cdist_circle *a, const cdist_circle *b, double d)
{
    double L = fmax(fmax(a->radius, b->radius), fmax(d, tdist(a->center, b->center)));
    return L > 0 ? L : 1.0;
}

/* Brute-force distance, and the count of tied distinct minima along a (tie 1e-15 of scale). */
static long double brute(const cdist_circle *a, const cdist_circle *b, int *count)
{
    lcirc la = lmake(a), lb = lmake(b);
    long double L = scale_of(a, b, 0.0);
    long double d0 = bf_side(&la, &lb, 1e-15L * L, count);
    long double d1 = bf_side(&lb, &la, 1e-15L * L, NULL);
    return fminl(d0, d1);
}

/* ---- checks ---- */

static int run(const cdist_circle *a, const cdist_circle *b, cdist_result *r)
{
    cdist_status st = cdist_circle_circle(q, a, b, r);
    CHECK(st == CDIST_OK, "%s: status %s: %s", mname, cdist_status_name(st), cdist_query_last_error(q));
    /* the method itself answered (the dispatcher reports a fallback to the robust method) */
    CHECK(st != CDIST_OK || r->method == (int)method, "%s: answered by method %d", mname, r->method);
    return st == CDIST_OK;
}

/* Every pair lies on its circles and realises the distance; params reproduce the points. */
static void check_pairs(const char *what, const cdist_circle *a, const cdist_circle *b, const cdist_result *r)
{
    double L = scale_of(a, b, r->distance);
    double cm = fmax(fmax(fabs(a->center.x), fabs(a->center.y)), fabs(a->center.z));
    cm = fmax(cm, fmax(fmax(fabs(b->center.x), fabs(b->center.y)), fabs(b->center.z)));
    double tol = 1e-14 * L + 16 * 2.2e-16 * cm;
    for (int i = 0; i < r->num_pairs; i++) {
        CHECK((double)ref_point_circle(r->pairs[i].point[0], *a) <= tol, "%s %s: pair %d point 0 off circle", mname,
              what, i);
        CHECK((double)ref_point_circle(r->pairs[i].point[1], *b) <= tol, "%s %s: pair %d point 1 off circle", mname,
              what, i);
        CHECK(fabs(tdist(r->pairs[i].point[0], r->pairs[i].point[1]) - r->distance) <= tol,
              "%s %s: pair %d does not realise the distance", mname, what, i);
        cdist_vec3 p;
        if (a->radius > 0 && cdist_circle_point(a, r->pairs[i].param[0], &p) == CDIST_OK)
            CHECK(tdist(p, r->pairs[i].point[0]) <= tol, "%s %s: param 0 does not reproduce the point", mname, what);
        if (b->radius > 0 && cdist_circle_point(b, r->pairs[i].param[1], &p) == CDIST_OK)
            CHECK(tdist(p, r->pairs[i].point[1]) <= tol, "%s %s: param 1 does not reproduce the point", mname, what);
    }
    if (r->num_pairs == 2)
        CHECK(tdist(r->pairs[0].point[0], r->pairs[1].point[0]) + tdist(r->pairs[0].point[1], r->pairs[1].point[1]) >
                  1e-6 * L,
              "%s %s: the two pairs are the same", mname, what);
}

/* Distance vs an expected value, pair count and flag; also the swapped query. */
static void expect(const char *what, cdist_circle a, cdist_circle b, double d, double rel, int pairs, int equi)
{
    cdist_result r, s;
    if (!run(&a, &b, &r)) return;
    double L = scale_of(&a, &b, d);
    CHECK(fabs(r.distance - d) <= rel * L, "%s %s: distance %.17g expected %.17g (err %.3g of scale)", mname, what,
          r.distance, d, fabs(r.distance - d) / L);
    if (pairs) CHECK(r.num_pairs == pairs, "%s %s: %d pairs, expected %d", mname, what, r.num_pairs, pairs);
    CHECK(r.equidistant == equi, "%s %s: equidistant %d, expected %d", mname, what, r.equidistant, equi);
    check_pairs(what, &a, &b, &r);
    if (!run(&b, &a, &s)) return;
    CHECK(fabs(s.distance - r.distance) <= 8 * 2.2e-16 * L, "%s %s: swapped distance %.17g vs %.17g", mname, what,
          s.distance, r.distance);
    CHECK(s.num_pairs == r.num_pairs && s.equidistant == r.equidistant, "%s %s: swapped pairs %d/%d flag %d/%d",
          mname, what, s.num_pairs, r.num_pairs, s.equidistant, r.equidistant);
    check_pairs(what, &b, &a, &s);
    if (method == CDIST_METHOD_ITERATION)
        CHECK(r.iterations >= 0 && r.iterations <= cdist_query_get_max_iterations(q), "%s %s: iterations %d", mname,
              what, r.iterations);
    else
        CHECK(r.iterations == 0, "%s %s: iterations %d for a non-iterative method", mname, what, r.iterations);
}

/* The same, moved by a rotation, translation and scale (expected distance scaled). */
static void expect_moved(const char *what, cdist_circle a, cdist_circle b, double d, double rel, int pairs, int equi)
{
    expect(what, a, b, d, rel, pairs, equi);
    for (int k = 0; k < 3; k++) {
        trot R = rand_rotation();
        double s = k == 0 ? 1.0 : (k == 1 ? 1e-3 : 1e3);
        cdist_vec3 t = tv(srand1() * 10 * s, srand1() * 10 * s, srand1() * 10 * s);
        cdist_circle A = xform_circle(&R, s, t, a), B = xform_circle(&R, s, t, b);
        char buf[128];
        snprintf(buf, sizeof buf, "%s (moved, scale %g)", what, s);
        expect(buf, A, B, d * s, rel * 4, pairs, equi);
    }
}

/* Distance and pair count from the brute force. */
static void expect_brute(const char *what, cdist_circle a, cdist_circle b, double rel, int assert_count)
{
    int cnt;
    long double d = brute(&a, &b, &cnt);
    int pairs = assert_count ? (cnt >= 2 ? 2 : 1) : 0;
    expect(what, a, b, (double)d, rel, pairs, 0);
}

static void paper_examples(void)
{
    /* Example 1: R = 6; R1 = 8, axis <4,7,6>, centre (10,8,9). The paper prints 10.24875800 (its
     * stopping tolerance); 10.248757551783033702 is the mpmath value for these doubles. */
    cdist_circle c0 = circ(0, 0, 0, Z, 6), c1 = circ(10, 8, 9, unitv(4, 7, 6), 8);
    expect("paper example 1", c0, c1, 10.248757551783033702, 1e-15, 1, 0);
    /* Example 2: R = 10; R1 = 6, axis <4,5,0>, centre (-4,-5,4): 1.995365226877, two pairs. */
    c0 = circ(0, 0, 0, Z, 10);
    c1 = circ(-4, -5, 4, unitv(4, 5, 0), 6);
    expect("paper example 2", c0, c1, 1.9953652268768859384, 1e-15, 2, 0);
    cdist_result r;
    if (run(&c0, &c1, &r) && r.num_pairs == 2) {
        /* the pairs are mirror images in the plane through both axes (normal (5,-4,0)/sqrt 41) */
        cdist_vec3 p = r.pairs[0].point[0], m = unitv(5, -4, 0);
        double pm = p.x * m.x + p.y * m.y + p.z * m.z;
        cdist_vec3 refl = tv(p.x - 2 * pm * m.x, p.y - 2 * pm * m.y, p.z - 2 * pm * m.z);
        CHECK(tdist(refl, r.pairs[1].point[0]) <= 1e-12, "%s example 2: pairs are not mirror images", mname);
    }
}

/* Regressions found by stress testing against the robust method. (1-3) a larger circle whose
 * centre is within ~1e-6 of the smaller one's axis: the squared polynomial has near-double roots
 * that the eigenvalue solver returned as complex pairs with imaginary parts ~1e-4, so the global
 * minimum's root was dropped (error 1e-7). (4) nearly coplanar overlapping circles of radius
 * 123, normals 1.4e-4 apart: -p6/p7 gave the wrong sign of sin t at a near-double root.
 * (5) equal circles concentric to 1e-12 in different planes: the nearly even phi made GSL's QR
 * fail to converge, and GSL's default error handler aborted the process. */
static void near_axis_regressions(void)
{
    static const double cases[][14] = {
        {-0.6767925028284858, -0.72991175437528488, -0.02447527240523395, -0.43698077029309257, 0.89448571097331886,
         0.094568066801705916, 0.43865023552353088, -0.24290945637718478, -1.618056523363524, -0.11837051431510687,
         -0.13040742873502192, -0.32854399180594412, -0.93544254124929338, 2.8481373494283444},
        {0.044213901007447376, -0.33130656072870623, 0.66799619287580891, -0.16230292079392325, 0.98275180755107461,
         -0.088637727051505619, 0.7407999949688846, 0.32772059472221043, -2.0479529053423882, 0.82282637858152152,
         -0.40381133001865255, 0.30971737078732475, 0.86082028320733339, 3.0599076678879173},
        {0.9804649721761256, -0.64153638064841667, -0.38736735765739549, -0.10786863504954793, 0.69221699299367745,
         0.71358250551939573, 0.9335707786835542, 0.84260046380387432, 0.24321622872759355, 0.52469344141796492,
         0.86279591192411909, -0.47167212418379639, -0.18195774683968038, 3.2670542110104854},
        {8356.2686475893006, -381.66957929993509, 2844.1919778138217, 0.76909818137855435, -0.18398715163472648,
         -0.61207574321609926, 123.01567705614073, 8281.0860370908395, -442.04863093311542, 2767.8060915990841,
         0.76906770035413852, -0.1838698528825943, -0.6121492869169497, 123.0319943181189},
        {2.9368356841831482, 4.7479266927957102, -2.083669375650802, -0.40753672600826185, -0.55819017183296182,
         0.72272923631437225, 0.078836229095138349, 2.9368356841841097, 4.7479266927995507, -2.0836693756472937,
         0.51384541626788582, 0.27605729705515591, -0.81225319754562042, 0.078836229100625668},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const double *v = cases[i];
        cdist_circle a = circ(v[0], v[1], v[2], tv(v[3], v[4], v[5]), v[6]);
        cdist_circle b = circ(v[7], v[8], v[9], tv(v[10], v[11], v[12]), v[13]);
        expect_brute("centre near the smaller circle's axis", a, b, 1e-14, 0);
    }
}

static void families(void)
{
    cdist_vec3 mZ = tv(0, 0, -1);
    /* Same plane (Eberly §5.1): concentric, equal, separated, tangent (outside, inside),
     * overlapping, containing either way. */
    expect_moved("coplanar concentric", circ(0, 0, 0, Z, 2), circ(0, 0, 0, mZ, 1), 1.0, 1e-15, 1, 1);
    expect_moved("coplanar equal", circ(0, 0, 0, Z, 1), circ(0, 0, 0, Z, 1), 0.0, 1e-15, 1, 1);
    expect_moved("coplanar separated", circ(0, 0, 0, Z, 2), circ(5, 0, 0, Z, 1), 2.0, 1e-15, 1, 0);
    expect_moved("coplanar tangent outside", circ(0, 0, 0, Z, 2), circ(3, 0, 0, mZ, 1), 0.0, 1e-15, 1, 0);
    expect_moved("coplanar tangent inside", circ(0, 0, 0, Z, 2), circ(1, 0, 0, Z, 1), 0.0, 1e-15, 1, 0);
    expect_moved("coplanar overlapping", circ(0, 0, 0, Z, 2), circ(2, 0, 0, Z, 1.5), 0.0, 1e-15, 2, 0);
    expect_moved("coplanar c1 inside c0", circ(0, 0, 0, Z, 2), circ(0.5, 0, 0, Z, 1), 0.5, 1e-15, 1, 0);
    expect_moved("coplanar c0 inside c1", circ(0, 0, 0, Z, 1), circ(0.5, 0, 0, mZ, 2), 0.5, 1e-15, 1, 0);
    /* Parallel planes (§5.2, Li et al. §2.3). */
    expect_moved("parallel separated", circ(0, 0, 0, Z, 2), circ(5, 0, 1, Z, 1), sqrt(5.0), 1e-15, 1, 0);
    expect_moved("parallel overlapping", circ(0, 0, 0, Z, 2), circ(2, 0, -1, mZ, 1.5), 1.0, 1e-15, 2, 0);
    expect_moved("parallel contained", circ(0, 0, 0, Z, 2), circ(0.5, 0, 1, Z, 1), sqrt(1.25), 1e-15, 1, 0);
    expect_moved("parallel tangent", circ(0, 0, 0, Z, 2), circ(3, 0, 1, Z, 1), 1.0, 1e-15, 1, 0);
    /* Coaxial (Li et al. §2.4): equidistant, sqrt((r1 - r0)^2 + h^2). */
    expect_moved("coaxial", circ(0, 0, 0, Z, 2), circ(0, 0, 3, Z, 1), sqrt(10.0), 1e-15, 1, 1);
    expect_moved("coaxial equal radii", circ(0, 0, 0, Z, 1), circ(0, 0, -2, mZ, 1), 2.0, 1e-15, 1, 1);
    /* Axes meeting, perpendicular, centre of c1 on c0's axis (Li et al. remark 1):
     * |sqrt(R^2 + pz^2) - R1| with two mirror pairs. */
    expect_moved("remark 1", circ(0, 0, 0, Z, 4), circ(0, 0, 3, tv(1, 0, 0), 2), 3.0, 1e-15, 2, 0);
    expect_moved("remark 1, concentric", circ(0, 0, 0, Z, 4), circ(0, 0, 0, tv(0, 1, 0), 2), 2.0, 1e-15, 2, 0);
    /* Zero radii: point-circle. */
    expect("c1 a point", circ(0, 0, 0, Z, 2), circ(3, 4, 12, Z, 0), sqrt(153.0), 1e-15, 1, 0);
    expect("c1 a point on the axis", circ(0, 0, 0, Z, 2), circ(0, 0, 1, Z, 0), sqrt(5.0), 1e-15, 1, 1);
    expect("both points", circ(0, 0, 0, Z, 0), circ(3, 4, 0, Z, 0), 5.0, 1e-15, 1, 0);
    /* Linked and touching rings. */
    expect_moved("linked touching", circ(0, 0, 0, Z, 1), circ(0.5, 0, 0, tv(0, 1, 0), 0.5), 0.0, 1e-15, 1, 0);
    expect_moved("crossing at one point", circ(0, 0, 0, Z, 1), circ(1, 0, 0.75, tv(0, 1, 0), 0.75), 0.0, 1e-15, 1, 0);
    /* Brute-force references (distance and pair count) for the rest. */
    expect_brute("centres on the normal line", circ(0, 0, 0, Z, 2), circ(0, 0, 1.5, unitv(0.3, 0, 1), 1), 1e-14, 1);
    expect_brute("centres on the normal line, big tilt", circ(0, 0, 0, Z, 1), circ(0, 0, 0.5, unitv(2, 0, 1), 3),
                 1e-14, 1);
    /* Equal perpendicular rings, each through the other's centre: every point of either is at
     * distance r from the other (equidistant without being coaxial). */
    expect_moved("rings through each other's centre", circ(0, 0, 0, Z, 1), circ(1, 0, 0, tv(0, 1, 0), 1), 1.0,
                 1e-15, 1, 1);
    expect_brute("linked rings", circ(0, 0, 0, Z, 1), circ(0.8, 0, 0, tv(0, 1, 0), 0.9), 1e-14, 1);
    expect_brute("linked, offset", circ(0, 0, 0, Z, 1), circ(0.9, 0.1, 0.05, unitv(0.1, 1, 0.2), 0.8), 1e-14, 1);
    expect_brute("axes meeting", circ(0, 0, 0, Z, 3), circ(1, 0, 2, unitv(1, 0, 1), 1.5), 1e-14, 1);
    expect_brute("axes meeting, c1 large", circ(0, 0, 0, Z, 1), circ(1, 0, 2, unitv(1, 0, 0.3), 4), 1e-14, 1);
    expect_brute("nearly parallel", circ(0, 0, 0, Z, 1), circ(1.2, 0.3, 0.1, unitv(1e-9, 0, 1), 0.7), 1e-14, 1);
    expect_brute("nearly coaxial", circ(0, 0, 0, Z, 1), circ(1e-9, 0, 0.5, Z, 0.7), 1e-14, 1);
}

/* Random linked and near-degenerate configurations against the brute force. */
static void random_brute(int n)
{
    double worst = 0;
    for (int i = 0; i < n; i++) {
        int kind = i % 6;
        cdist_circle a = circ(srand1(), srand1(), srand1(), rand_unit(), 0.2 + urand()), b;
        cdist_vec3 u, v;
        cdist_circle_basis(&a, &u, &v);
        double t = 6.283 * urand(), e = pow(10.0, -3.0 - 10.0 * urand());
        cdist_vec3 on = tv(a.center.x + a.radius * (cos(t) * u.x + sin(t) * v.x),
                           a.center.y + a.radius * (cos(t) * u.y + sin(t) * v.y),
                           a.center.z + a.radius * (cos(t) * u.z + sin(t) * v.z));
        cdist_vec3 n1 = rand_unit();
        switch (kind) {
        case 0: /* linked: c1 passes through c0's disk near c0 */
            b = circ(on.x + 0.3 * srand1(), on.y + 0.3 * srand1(), on.z + 0.3 * srand1(), n1, 0.2 + urand());
            break;
        case 1: /* nearly coplanar */
            b = circ(a.center.x + u.x * srand1() + e * a.normal.x, a.center.y + u.y * srand1() + e * a.normal.y,
                     a.center.z + u.z * srand1() + e * a.normal.z,
                     unitv(a.normal.x + e * n1.x, a.normal.y + e * n1.y, a.normal.z + e * n1.z), 0.2 + urand());
            break;
        case 2: /* nearly coaxial */
        {
            double s = 2 * srand1();
            b = circ(a.center.x + s * a.normal.x + e * u.x, a.center.y + s * a.normal.y + e * u.y,
                     a.center.z + s * a.normal.z + e * u.z,
                     unitv(a.normal.x + e * n1.x, a.normal.y + e * n1.y, a.normal.z + e * n1.z), 0.2 + urand());
            break;
        }
        case 3: /* nearly touching: c1 through a point of c0, then nudged by e */
        {
            cdist_vec3 x = rand_unit();
            cdist_vec3 w = unitv(n1.y * x.z - n1.z * x.y, n1.z * x.x - n1.x * x.z, n1.x * x.y - n1.y * x.x);
            double rb = 0.2 + urand();
            b = circ(on.x + rb * w.x + e * v.x, on.y + rb * w.y + e * v.y, on.z + rb * w.z + e * v.z, n1, rb);
            break;
        }
        case 4: /* centre near c0's axis, tilted */
        {
            double s = 2 * srand1();
            b = circ(a.center.x + s * a.normal.x + e * u.x, a.center.y + s * a.normal.y + e * u.y,
                     a.center.z + s * a.normal.z + e * u.z, n1, 0.2 + 2 * urand());
            break;
        }
        default: /* axes nearly meeting: c1's axis through a point of c0's axis, nudged by e */
        {
            double s = srand1(), k = srand1();
            b = circ(a.center.x + s * a.normal.x + k * n1.x + e * v.x, a.center.y + s * a.normal.y + k * n1.y + e * v.y,
                     a.center.z + s * a.normal.z + k * n1.z + e * v.z, n1, 0.2 + urand());
        }
        }
        cdist_result r;
        if (!run(&a, &b, &r)) continue;
        int cnt;
        long double d = brute(&a, &b, &cnt);
        double L = scale_of(&a, &b, (double)d);
        double err = (double)(fabsl(r.distance - d) / L);
        worst = fmax(worst, err);
        CHECK(err <= 1e-13, "%s random kind %d #%d: %.17g vs brute %.20Lg (err %.3g)", mname, kind, i, r.distance, d,
              err);
        check_pairs("random", &a, &b, &r);
    }
    printf("%s: random linked/near-degenerate vs long double brute force: max error %.3g of scale\n", mname, worst);
}

static void iteration_cap(void)
{
    /* A generic configuration: the iteration runs (count > 0) and respects the cap; with a cap
     * of 1 the Newton finish still gives the exact answer. */
    cdist_circle a = circ(0, 0, 0, Z, 6), b = circ(10, 8, 9, unitv(4, 7, 6), 8);
    cdist_result r;
    if (run(&a, &b, &r))
        CHECK(r.iterations > 0 && r.iterations <= cdist_query_get_max_iterations(q), "iterations %d", r.iterations);
    int caps[] = {1, 2, 5};
    for (int i = 0; i < 3; i++) {
        cdist_query_set_max_iterations(q, caps[i]);
        if (run(&a, &b, &r)) {
            CHECK(r.iterations > 0 && r.iterations <= caps[i], "cap %d: iterations %d", caps[i], r.iterations);
            CHECK(fabs(r.distance - 10.248757551783033702) <= 1e-14 * 20, "cap %d: distance %.17g", caps[i],
                  r.distance);
        }
    }
    cdist_query_set_max_iterations(q, 200);
}

int main(int argc, char **argv)
{
    int nrand = argc > 1 ? atoi(argv[1]) : 300;
    q = cdist_query_new();
    cdist_method ms[2] = {CDIST_METHOD_POLYNOMIAL, CDIST_METHOD_ITERATION};
    for (int i = 0; i < 2; i++) {
        method = ms[i];
        mname = i ? "iteration" : "polynomial";
        cdist_query_set_method(q, method);
        check_rng_state = 0x9E3779B97F4A7C15ull;
        paper_examples();
        families();
        near_axis_regressions();
        random_brute(nrand);
        if (method == CDIST_METHOD_ITERATION) iteration_cap();
    }
    cdist_query_free(q);
    return check_summary("cc_methods");
}
