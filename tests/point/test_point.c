/* SPDX-License-Identifier: MIT */
/* Point-circle and point-disk: exact constructions, far-from-origin, near-axis, properties. */
#include <float.h>

#include "check.h"
#include "base/point_circle.h"

static cdist_query *q;

static cdist_circle circ(double cx, double cy, double cz, double nx, double ny, double nz, double r)
{
    cdist_circle c = {tv(cx, cy, cz), tv(nx, ny, nz), r};
    return c;
}

static void exact_cases(void)
{
    cdist_result r;
    cdist_circle c = circ(0, 0, 0, 0, 0, 1, 2);
    cdist_vec3 p = tv(3, 4, 12); /* rho 5, h 12: distance sqrt(9 + 144) */
    CHECK(cdist_point_circle(q, &p, &c, &r) == CDIST_OK, "status");
    CHECK_NEAR(r.distance, sqrt(153.0), 1e-15 * 13, "pc distance");
    CHECK(r.num_pairs == 1 && !r.equidistant, "one pair");
    CHECK_NEAR(r.pairs[0].point[1].x, 1.2, 4e-16, "closest x");
    CHECK_NEAR(r.pairs[0].point[1].y, 1.6, 4e-16, "closest y");
    CHECK_NEAR(r.pairs[0].point[1].z, 0.0, 0, "closest z");
    CHECK(r.pairs[0].point[0].x == 3 && r.pairs[0].point[0].z == 12, "first point is p");
    CHECK(isnan(r.pairs[0].param[0]), "point param NaN");
    /* The angle reproduces the point through cdist_circle_point. */
    cdist_vec3 k;
    CHECK(cdist_circle_point(&c, r.pairs[0].param[1], &k) == CDIST_OK, "circle_point");
    CHECK(tdist(k, r.pairs[0].point[1]) < 1e-15 * 4, "angle reproduces the point");

    /* On the axis: equidistant, distance sqrt(r^2 + h^2). */
    p = tv(0, 0, -3);
    CHECK(cdist_point_circle(q, &p, &c, &r) == CDIST_OK, "axis status");
    CHECK(r.equidistant == 1 && r.num_pairs == 1, "axis equidistant");
    CHECK_NEAR(r.distance, sqrt(13.0), 8e-16, "axis distance");
    CHECK_NEAR(tdist(r.pairs[0].point[1], tv(0, 0, 0)), 2.0, 4e-16, "representative on circle");
    /* The centre itself. */
    p = tv(0, 0, 0);
    CHECK(cdist_point_circle(q, &p, &c, &r) == CDIST_OK && r.equidistant && r.distance == 2.0, "centre");
    /* Point on the circle. */
    p = tv(0, -2, 0);
    CHECK(cdist_point_circle(q, &p, &c, &r) == CDIST_OK && r.distance == 0.0, "on circle: %g", r.distance);
    /* Radius 0: the circle is its centre. */
    cdist_circle z = circ(1, 2, 3, 0, 1, 0, 0);
    p = tv(4, 6, 3);
    CHECK(cdist_point_circle(q, &p, &z, &r) == CDIST_OK && r.distance == 5.0 && !r.equidistant,
          "radius 0: %g", r.distance);
    CHECK(cdist_point_disk(q, &p, &z, &r) == CDIST_OK && r.distance == 5.0, "radius 0 disk");

    /* Near the axis: 1e-12 off the axis of a unit circle at height 1 (sqrt(|D|^2 - h^2) would
     * give 0 or 1.5e-8 here). */
    cdist_circle u = circ(0, 0, 0, 0, 0, 1, 1);
    p = tv(1e-12, 0, 1);
    CHECK(cdist_point_circle(q, &p, &u, &r) == CDIST_OK && !r.equidistant, "near axis");
    CHECK_NEAR(r.distance, sqrt((1 - 1e-12) * (1 - 1e-12) + 1.0), 4e-16, "near axis distance");
    CHECK_NEAR(r.pairs[0].point[1].x, 1.0, 0, "near axis closest point");

    /* Disk: inside projection -> plane distance; outside -> rim. */
    cdist_circle d = circ(0, 0, 0, 0, 0, 1, 2);
    p = tv(1, 1, 5);
    CHECK(cdist_point_disk(q, &p, &d, &r) == CDIST_OK && r.distance == 5.0, "disk face: %g", r.distance);
    CHECK(r.pairs[0].point[1].x == 1 && r.pairs[0].point[1].y == 1 && r.pairs[0].point[1].z == 0, "disk foot");
    CHECK(!r.equidistant && r.num_pairs == 1, "disk unique");
    p = tv(0, 0, 5);
    CHECK(cdist_point_disk(q, &p, &d, &r) == CDIST_OK && r.distance == 5.0 && !r.equidistant, "disk centre");
    CHECK(isnan(r.pairs[0].param[1]), "disk centre param NaN");
    p = tv(6, 0, 3);
    CHECK(cdist_point_disk(q, &p, &d, &r) == CDIST_OK && r.distance == 5.0, "disk rim: %g", r.distance);
    p = tv(1, 0, 0);
    CHECK(cdist_point_disk(q, &p, &d, &r) == CDIST_OK && r.distance == 0.0, "in disk");

    /* Far from the origin: a 1e8 offset must not cost digits relative to the unit scale. */
    cdist_circle f = circ(1e8 + 0.5, -3e8, 7e7, 0, 0, 1, 1);
    p = tv(1e8 + 0.5 + 3, -3e8, 7e7 + 4);
    CHECK(cdist_point_circle(q, &p, &f, &r) == CDIST_OK, "far");
    CHECK_NEAR(r.distance, sqrt(20.0), 1e-15 * 5, "far distance");

    /* Non-unit normal within tolerance is normalised; outside is rejected. */
    cdist_circle nu = circ(0, 0, 0, 0, 0, 1 + 1e-9, 2);
    p = tv(3, 4, 12);
    CHECK(cdist_point_circle(q, &p, &nu, &r) == CDIST_OK, "near-unit normal accepted");
    CHECK_NEAR(r.distance, sqrt(153.0), 1e-14, "near-unit normal distance");
    nu.normal.z = 2;
    CHECK(cdist_point_circle(q, &p, &nu, &r) == CDIST_ERR_NOT_UNIT, "length 2 normal rejected");
    cdist_query_set_unit_tolerance(q, INFINITY);
    CHECK(cdist_point_circle(q, &p, &nu, &r) == CDIST_OK, "any length with infinite tolerance");
    CHECK_NEAR(r.distance, sqrt(153.0), 1e-14, "normalised distance");
    cdist_query_set_unit_tolerance(q, 1e-6);
}

/* Properties on random inputs: invariance, the pair lies on the circle and realises the distance,
 * and no sampled circle point is closer. */
static void properties(void)
{
    cdist_result r, r2;
    for (int it = 0; it < 2000; it++) {
        cdist_circle c = {tv(srand1(), srand1(), srand1()), rand_unit(), 0.1 + 2 * urand()};
        cdist_vec3 p = tv(2 * srand1(), 2 * srand1(), 2 * srand1());
        if (it % 5 == 0) { /* near the axis */
            double h = srand1();
            double e = pow(10.0, -15 * urand());
            cdist_vec3 side = rand_unit();
            p = tv(c.center.x + h * c.normal.x + e * side.x, c.center.y + h * c.normal.y + e * side.y,
                   c.center.z + h * c.normal.z + e * side.z);
        }
        for (int disk = 0; disk < 2; disk++) {
            cdist_status st = disk ? cdist_point_disk(q, &p, &c, &r) : cdist_point_circle(q, &p, &c, &r);
            CHECK(st == CDIST_OK, "status");
            long double ref = disk ? ref_point_disk(p, c) : ref_point_circle(p, c);
            double L = fmax(c.radius, tdist(p, c.center));
            CHECK_NEAR(r.distance, (double)ref, 1e-15 * L, "vs long double"); /* valgrind runs long double as double */
            cdist_vec3 k = r.pairs[0].point[1];
            double on = (double)(disk ? ref_point_disk(k, c) : ref_point_circle(k, c));
            CHECK(on <= 1e-15 * L, "closest point off the object by %g", on);
            CHECK_NEAR(tdist(p, k), r.distance, 1e-15 * L, "pair realises distance");
            /* Sampled points are never closer. */
            cdist_vec3 u, v;
            cdist_circle_basis(&c, &u, &v);
            for (int s = 0; s < 64; s++) {
                double a = 2 * M_PI * s / 64, rad = disk ? c.radius * urand() : c.radius;
                cdist_vec3 x = tv(c.center.x + rad * (cos(a) * u.x + sin(a) * v.x),
                                  c.center.y + rad * (cos(a) * u.y + sin(a) * v.y),
                                  c.center.z + rad * (cos(a) * u.z + sin(a) * v.z));
                CHECK(tdist(p, x) >= r.distance - 1e-15 * L, "sample closer");
            }
            /* Invariance under rotation, translation and scale. */
            trot R = rand_rotation();
            double s = pow(10.0, 3 * srand1());
            cdist_vec3 t = tv(100 * srand1(), 100 * srand1(), 100 * srand1());
            cdist_circle c2 = xform_circle(&R, s, t, c);
            cdist_vec3 p2 = xform_point(&R, s, t, p);
            st = disk ? cdist_point_disk(q, &p2, &c2, &r2) : cdist_point_circle(q, &p2, &c2, &r2);
            CHECK(st == CDIST_OK, "status");
            double L2 = s * L + 1e-16 * 300 * s; /* translation rounding */
            CHECK_NEAR(r2.distance, s * r.distance, 1e-13 * (L2 + 100), "invariance");
        }
    }
}

/* A point 1e-160 of the scale from the axis (but not on it, at the axis tolerance): the in-plane
 * direction has subnormal squares; the reported circle point must still lie on the circle. Found
 * by libFuzzer (radius 5.6e112, offset from the axis 1.3e-47). */
static void near_axis_tiny_offset(void)
{
    cdist_result r;
    double R = 5.6133372798172279e+112;
    for (int k = 0; k < 40; k++) {
        double off = ldexp(1.3e-47, -8 * k), hgt = ldexp(2.9e-33, -8 * k);
        cdist_vec3 p = tv(-off, 0, hgt);
        cdist_circle c = circ(0, 0, 0, 0, 0, 1, R);
        CHECK(cdist_point_circle(q, &p, &c, &r) == CDIST_OK, "near axis %d", k);
        cdist_vec3 k1 = r.pairs[0].point[1];
        double rho = hypot(k1.x, k1.y);
        /* (equidistant may be set: every circle point is equally close to far below an ulp) */
        CHECK(fabs(rho - R) <= 4 * DBL_EPSILON * R && k1.z == 0, "near axis %d: circle point at radius %.17g (R %.17g), z %g",
              k, rho, R, k1.z);
        CHECK(fabs(r.distance - hypot(R, hgt)) <= 2 * DBL_EPSILON * R, "near axis %d: distance", k);
    }
}

/* The one point-to-circle evaluation (src/base/point_circle.h) against the same formulas in long
 * double (64-bit significand: products of doubles within 2^-64 of exact) on random unit normals
 * and points, many of them near the axis (1e-3 .. 1e-15 of the scale; down to 1e-300 for
 * coordinate-axis normals, where the offset is exact): rho and h within a
 * few eps |D| (where sqrt(|D|^2 - h^2) errs by about sqrt(eps) |D|), the squared distance within
 * a few eps (|D| + r)^2, and the circle point along the in-plane direction at radius r to a few
 * ulps, perpendicular to n, and (away from the axis) in the direction of D's in-plane part. */
static uint64_t ev_rng = 0x2545F4914F6CDD1Dull;
static double ev_u(void)
{
    ev_rng ^= ev_rng << 13;
    ev_rng ^= ev_rng >> 7;
    ev_rng ^= ev_rng << 17;
    return (double)(ev_rng >> 11) * 0x1p-53 * 2.0 - 1.0;
}

static void evaluator_vs_long_double(void)
{
    const double eps = DBL_EPSILON;
    int bad = 0;
    for (int i = 0; i < 20000; i++) {
        vec3 n = v3(ev_u(), ev_u(), ev_u());
        n = v_scale(1.0 / v_norm(n), n);
        double L = ldexp(1.0, (int)(ev_u() * 60)), r = L * (0.5 + 0.5 * ev_u());
        vec3 D = v3(L * ev_u(), L * ev_u(), L * ev_u());
        if (i % 4 == 1) { /* near the axis: h n plus an offset of 1e-3 .. 1e-15 of the scale */
            double off = L * pow(10.0, -3.0 - 12.0 * (0.5 + 0.5 * ev_u()));
            D = v_axpy(v_scale(L * ev_u(), n), off, v3(ev_u(), ev_u(), ev_u()));
        } else if (i % 4 == 3) { /* n a coordinate axis: offsets down to 1e-300 of the scale, exact */
            double off = L * pow(10.0, -3.0 - 297.0 * (0.5 + 0.5 * ev_u())), c[3];
            int a = i / 4 % 3;
            for (int k = 0; k < 3; k++) c[k] = k == a ? L * ev_u() : off * ev_u();
            double nk[3] = {0, 0, 0};
            nk[a] = ev_u() < 0 ? -1.0 : 1.0;
            n = v3(nk[0], nk[1], nk[2]);
            D = v3(c[0], c[1], c[2]);
        }
        cdist__pc_parts e = cdist__point_circle(n, D, r);
        long double nx = n.x, ny = n.y, nz = n.z, dx = D.x, dy = D.y, dz = D.z;
        long double px = ny * dz - nz * dy, py = nz * dx - nx * dz, pz = nx * dy - ny * dx;
        long double rho = sqrtl(px * px + py * py + pz * pz), h = nx * dx + ny * dy + nz * dz;
        long double d2 = (rho - r) * (rho - r) + h * h, mD = v_norm(D);
        int ok = fabsl(e.rho - rho) <= 4 * eps * mD && fabsl(e.h - h) <= 4 * eps * mD &&
                 fabsl(e.d2 - d2) <= 8 * eps * (mD + r) * (mD + r) && e.dr == e.rho - r && e.hh == e.h * e.h;
        vec3 w = cdist__pc_inplane(e.np, n);
        if (ok && v_maxabs(w) > 0.0) {
            vec3 k = cdist__pc_along(w, r);
            long double kx = k.x, ky = k.y, kz = k.z, kn = sqrtl(kx * kx + ky * ky + kz * kz);
            ok = fabsl(kn - r) <= 4 * eps * r && fabsl(kx * nx + ky * ny + kz * nz) <= 4 * eps * r;
            if (ok && rho > 1e-6L * mD) { /* D's in-plane part D - h n, its direction against k's */
                long double ix = dx - h * nx, iy = dy - h * ny, iz = dz - h * nz;
                long double c = (ix * kx + iy * ky + iz * kz) / (sqrtl(ix * ix + iy * iy + iz * iz) * kn);
                ok = 1.0L - c <= 1e-18L + 64 * eps * mD / rho;
            }
        }
        if (!ok && bad++ < 3)
            CHECK(0, "evaluator case %d: rho %.17g (ref %.17Lg), h %.17g (ref %.17Lg), d2 %.17g (ref %.17Lg)", i, e.rho,
                  rho, e.h, h, e.d2, d2);
    }
    CHECK(bad == 0, "evaluator: %d of 20000 cases off", bad);
}

int main(void)
{
    evaluator_vs_long_double();
    q = cdist_query_new();
    near_axis_tiny_offset();
    CHECK(q != NULL, "handle");
    exact_cases();
    properties();
    cdist_query_free(q);
    return check_summary("test_point");
}
