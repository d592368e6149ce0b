/* SPDX-License-Identifier: MIT */
/* Linking (src/topology/link.c): the double and extended-precision counts agree wherever both
 * certify (the extended one is checked against the mpmath reference only through this
 * agreement: link_check.py grades the public answers, which the double count gives almost
 * always), the extended count certifies every pair apart by more than 2^-40 L, hand-made
 * configurations with known numbers, the tori rule, errors and the batch conventions. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "topology/topology-priv.h"

static cdist_circle circ(cdist_vec3 c, cdist_vec3 n, double r)
{
    cdist_circle k = {c, n, r};
    return k;
}

static cdist_vec3 add(cdist_vec3 a, double s, cdist_vec3 b) { return tv(a.x + s * b.x, a.y + s * b.y, a.z + s * b.z); }
static cdist_vec3 cross(cdist_vec3 a, cdist_vec3 b)
{
    return tv(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static cdist_vec3 unitv(cdist_vec3 a)
{
    double n = sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
    return tv(a.x / n, a.y / n, a.z / n);
}
static cdist_vec3 perp_to(cdist_vec3 n)
{
    cdist_vec3 e = rand_unit();
    double d = e.x * n.x + e.y * n.y + e.z * n.z;
    return unitv(add(e, -d, n));
}

/* One random pair of the families (random, near the rim, nearly parallel, near-touching along
 * the closest pair, tiny next to huge), at a random power-of-two scale. */
static void random_pair(cdist_query *q, cdist_circle *a, cdist_circle *b)
{
    int fam = (int)(urand() * 5);
    cdist_vec3 ca = tv(srand1(), srand1(), srand1()), na = rand_unit();
    double ra = 0.5 + 1.5 * urand();
    cdist_vec3 rim = add(ca, ra, perp_to(na));
    *a = circ(ca, na, ra);
    switch (fam) {
    case 0: *b = circ(tv(srand1(), srand1(), srand1()), rand_unit(), 0.1 + 2 * urand()); break;
    case 1: *b = circ(add(rim, 0.3, rand_unit()), rand_unit(), 0.1 + 1.4 * urand()); break;
    case 2: {
        double ang = pow(10.0, -1 - 11 * urand());
        cdist_vec3 nb = unitv(add(tv(na.x * cos(ang), na.y * cos(ang), na.z * cos(ang)), sin(ang), perp_to(na)));
        *b = circ(add(rim, 1e-3, rand_unit()), nb, 0.5 + 1.5 * urand());
        break;
    }
    case 3: {
        *b = circ(add(rim, 0.3, rand_unit()), rand_unit(), 0.3 + 1.2 * urand());
        cdist_result r;
        if (cdist_circle_circle(q, a, b, &r) == CDIST_OK && r.distance > 0) {
            double want = pow(10.0, -3 - 9 * urand());
            cdist_vec3 dir = tv((r.pairs[0].point[1].x - r.pairs[0].point[0].x) / r.distance,
                                (r.pairs[0].point[1].y - r.pairs[0].point[0].y) / r.distance,
                                (r.pairs[0].point[1].z - r.pairs[0].point[0].z) / r.distance);
            b->center = add(b->center, want - r.distance, dir);
        }
        break;
    }
    default: {
        double rb = pow(10.0, -7 * urand());
        cdist_vec3 tang = cross(na, unitv(tv(rim.x - ca.x, rim.y - ca.y, rim.z - ca.z)));
        *b = circ(add(rim, 0.5 * rb, rand_unit()), unitv(add(tang, 0.7, rand_unit())), rb);
        break;
    }
    }
    double s = ldexp(1.0, (int)(urand() * 800) - 500);
    a->center = tv(s * a->center.x, s * a->center.y, s * a->center.z);
    b->center = tv(s * b->center.x, s * b->center.y, s * b->center.z);
    a->radius *= s;
    b->radius *= s;
}

static void check_precisions(cdist_query *q, int n)
{
    int both = 0, extended_only = 0, disagree = 0, undecided = 0, public_mismatch = 0;
    for (int i = 0; i < n; i++) {
        cdist_circle a, b;
        random_pair(q, &a, &b);
        cdist_result r;
        cdist_link lk;
        if (cdist_circle_circle(q, &a, &b, &r) != CDIST_OK || cdist_link_circles(q, &a, &b, &lk) != CDIST_OK) {
            CHECK(0, "pair %d: a query failed", i);
            continue;
        }
        if (!(r.distance > 0x1p-40 * lk.scale)) continue;
        cdist__circle va, vb;
        va.c = a.center; va.n = unitv(a.normal); va.r = a.radius;
        vb.c = b.center; vb.n = unitv(b.normal); vb.r = b.radius;
        int vd = cdist__link_count(&va, &vb, r.distance, 0);
        int vx = cdist__link_count(&va, &vb, r.distance, 1);
        if (vx == CDIST_LINK_TOUCHING) undecided++;
        if (vd != CDIST_LINK_TOUCHING && vx != CDIST_LINK_TOUCHING) {
            both++;
            if (vd != vx) disagree++;
        } else if (vx != CDIST_LINK_TOUCHING) {
            extended_only++;
        }
        int want = vd != CDIST_LINK_TOUCHING ? vd : vx;
        if (lk.linking != want || ((lk.flags & CDIST_LINK_FLAG_EXTENDED) != 0) != (vd == CDIST_LINK_TOUCHING))
            public_mismatch++;
    }
    printf("precisions: %d pairs certified by both (%d disagree), %d by extended only, %d undecided, %d public "
           "mismatches\n",
           both, disagree, extended_only, undecided, public_mismatch);
    CHECK(disagree == 0, "double and extended counts disagree on %d pairs", disagree);
    CHECK(undecided == 0, "extended precision left %d pairs apart by > 2^-40 L undecided", undecided);
    CHECK(public_mismatch == 0, "%d public answers differ from the counts", public_mismatch);
    CHECK(both > n / 2, "too few certified pairs (%d)", both);
}

static int link_of(cdist_query *q, cdist_circle a, cdist_circle b)
{
    cdist_link lk;
    cdist_status st = cdist_link_circles(q, &a, &b, &lk);
    return st == CDIST_OK ? lk.linking : -100 - (int)st;
}

static void check_known(cdist_query *q)
{
    cdist_circle a = circ(tv(0, 0, 0), tv(0, 0, 1), 1);
    /* b through a's centre going up (+1), the other way (-1), beside it (0). */
    CHECK(link_of(q, a, circ(tv(1, 0, 0), tv(0, 1, 0), 1)) == 1, "Hopf link +1");
    CHECK(link_of(q, a, circ(tv(1, 0, 0), tv(0, -1, 0), 1)) == -1, "Hopf link -1");
    CHECK(link_of(q, circ(tv(1, 0, 0), tv(0, 1, 0), 1), a) == 1, "symmetric");
    CHECK(link_of(q, a, circ(tv(3, 0, 0), tv(0, 1, 0), 1)) == 0, "apart");
    /* Coplanar nested, concentric perpendicular of different radii: 0; equal radii: touching. */
    CHECK(link_of(q, a, circ(tv(0.1, 0, 0), tv(0, 0, -1), 0.5)) == 0, "coplanar nested");
    CHECK(link_of(q, a, circ(tv(0, 0, 0), tv(1, 0, 0), 0.5)) == 0, "concentric");
    CHECK(link_of(q, a, circ(tv(0, 0, 0), tv(1, 0, 0), 1)) == CDIST_LINK_TOUCHING, "concentric equal radii");
    /* Tiny ring around a huge ring's wire, and the same 1e-15 L off the wire: linked / touching. */
    CHECK(link_of(q, circ(tv(0, 0, 0), tv(0, 0, 1), 1e9), circ(tv(1e9, 0, 0), tv(0, 1, 0), 1e-3)) == 1,
          "tiny around huge");
    CHECK(link_of(q, a, circ(tv(1, 0, 0), tv(0, 1, 0), 1e-16)) == CDIST_LINK_TOUCHING, "point-sized on the rim");
    /* A point (radius 0) is never linked. */
    CHECK(link_of(q, a, circ(tv(0.5, 0, 0), tv(0, 1, 0), 0)) == 0, "point");
    /* Gaps around the threshold: b's circle through a's rim point (1, 0, 0) moved by g. */
    for (int k = 0; k < 2; k++) {
        double g = k ? 4e-12 : 2e-13;
        int v = link_of(q, a, circ(tv(1 + 0.5 + g, 0, 0), tv(0, 1, 0), 0.5));
        CHECK(k ? v == 0 : v == CDIST_LINK_TOUCHING, "gap %g gave %d", g, v);
        v = link_of(q, a, circ(tv(1 + 0.5 - g, 0, 0), tv(0, 1, 0), 0.5));
        CHECK(k ? v == 1 : v == CDIST_LINK_TOUCHING, "gap -%g gave %d", g, v);
    }
}

static void check_tori(cdist_query *q)
{
    cdist_torus a = {circ(tv(0, 0, 0), tv(0, 0, 1), 1), 0.1};
    cdist_torus b = {circ(tv(1, 0, 0), tv(0, 1, 0), 1), 0.1};
    cdist_link lk;
    CHECK(cdist_link_tori(q, &a, &b, &lk) == CDIST_OK && lk.linking == 1 && lk.core_linking == 1, "linked tori");
    CHECK(fabs(lk.distance - (lk.core_distance - 0.2)) == 0, "signed distance");
    b.tube_radius = 0.5 * lk.core_distance + 0.5; /* overlap */
    CHECK(cdist_link_tori(q, &a, &b, &lk) == CDIST_OK && lk.linking == CDIST_LINK_OVERLAP && lk.core_linking == 1,
          "overlapping tori: %d %d", lk.linking, lk.core_linking);
    b.tube_radius = -1;
    CHECK(cdist_link_tori(q, &a, &b, &lk) == CDIST_ERR_NEGATIVE_RADIUS && lk.linking == CDIST_LINK_ERROR,
          "negative tube");
    b.tube_radius = NAN;
    CHECK(cdist_link_tori(q, &a, &b, &lk) == CDIST_ERR_NOT_FINITE, "NaN tube");
}

static void check_errors_and_batch(cdist_query *q)
{
    cdist_circle a = circ(tv(0, 0, 0), tv(0, 0, 1), 1), b = circ(tv(1, 0, 0), tv(0, 1, 0), 1);
    cdist_link lk;
    CHECK(cdist_link_circles(q, &a, NULL, &lk) == CDIST_ERR_NULL_ARGUMENT && lk.linking == CDIST_LINK_ERROR, "NULL");
    CHECK(cdist_link_circles(q, &a, &b, NULL) == CDIST_ERR_NULL_ARGUMENT, "NULL out");
    CHECK(cdist_link_circles(NULL, &a, &b, &lk) == CDIST_ERR_NULL_ARGUMENT, "NULL handle");
    cdist_circle bad = circ(tv(0, 0, 0), tv(0, 0, 0), 1);
    CHECK(cdist_link_circles(q, &a, &bad, &lk) == CDIST_ERR_ZERO_VECTOR && isnan(lk.distance), "zero normal");
    CHECK(strstr(cdist_query_last_error(q), "second circle") != NULL, "message: %s", cdist_query_last_error(q));
    CHECK(cdist_link_size() == sizeof(cdist_link), "size");
    /* The handle's method is left as it was (the distance runs with AUTO). */
    cdist_query_set_method(q, CDIST_METHOD_ITERATION);
    CHECK(cdist_link_circles(q, &a, &b, &lk) == CDIST_OK && lk.linking == 1 &&
              cdist_query_get_method(q) == CDIST_METHOD_ITERATION,
          "method kept");
    cdist_query_set_method(q, CDIST_METHOD_AUTO);

    /* Batch: a broadcast (stride 0) against four circles, one bad, negative stride on b. */
    cdist_circle bs[4] = {b, circ(tv(3, 0, 0), tv(0, 1, 0), 1), bad, circ(tv(1, 0, 0), tv(0, -1, 0), 1)};
    cdist_link out[4];
    cdist_status st[4];
    cdist_status s = cdist_link_circles_batch(q, 4, &a, 0, &bs[3], -(ptrdiff_t)sizeof(cdist_circle), out, st);
    CHECK(s == CDIST_ERR_ZERO_VECTOR, "batch status %d", (int)s);
    CHECK(st[0] == CDIST_OK && out[0].linking == -1, "batch 0");
    CHECK(st[1] == CDIST_ERR_ZERO_VECTOR && out[1].linking == CDIST_LINK_ERROR, "batch 1 (bad)");
    CHECK(st[2] == CDIST_OK && out[2].linking == 0, "batch 2");
    CHECK(st[3] == CDIST_OK && out[3].linking == 1, "batch 3");
    CHECK(strstr(cdist_query_last_error(q), "entry 1") != NULL, "batch message: %s", cdist_query_last_error(q));
    CHECK(cdist_link_circles_batch(q, 0, NULL, 0, NULL, 0, NULL, NULL) == CDIST_OK, "empty batch");
    CHECK(cdist_link_circles_batch(q, 2, &a, 0, NULL, 0, out, st) == CDIST_ERR_NULL_ARGUMENT &&
              st[1] == CDIST_ERR_NULL_ARGUMENT && out[1].linking == CDIST_LINK_ERROR,
          "NULL batch array");
    cdist_torus ta = {a, 0.1}, tb[2] = {{b, 0.1}, {b, 0.9}};
    s = cdist_link_tori_batch(q, 2, &ta, 0, tb, sizeof(cdist_torus), out, st);
    CHECK(s == CDIST_OK && out[0].linking == 1 && out[1].linking == CDIST_LINK_OVERLAP, "tori batch");
}

int main(int argc, char **argv)
{
    int n = argc > 1 ? atoi(argv[1]) : 20000;
    cdist_query *q = cdist_query_new();
    check_known(q);
    check_tori(q);
    check_errors_and_batch(q);
    check_precisions(q, n);
    cdist_query_free(q);
    return check_summary("link");
}
