/* SPDX-License-Identifier: MIT */
/* Disk queries: exact constructions (pairs and flags asserted), a long double brute force for
 * ld/rd/sd/cd/dd on random and near-degenerate inputs, and properties (dd symmetry, invariance
 * under rotation, translation and scale, disk distance <= rim distance, pairs on the objects). */
#include <string.h>

#include "check.h"
#include "test_ld.h"

static cdist_query *q;
static const double EPS = 2.220446049250313e-16;

static cdist_circle circ(double cx, double cy, double cz, double nx, double ny, double nz, double r)
{
    cdist_circle c = {tv(cx, cy, cz), tv(nx, ny, nz), r};
    return c;
}

static int near_pt(cdist_vec3 a, cdist_vec3 b, double tol) { return tdist(a, b) <= tol; }

/* ---- long double reference (independent of the library) ---- */


typedef struct { lv c, n, u, v; ld r; } ldisk;
/* Objects are taken relative to an origin O (a double point near them): the difference of two
 * doubles is exact in long double, so far-from-origin inputs keep their precision. */
static cdist_vec3 O;
static ldisk lmake(cdist_circle c)
{
    ldisk d;
    lv_frame(c, O, &d.c, &d.n, &d.u, &d.v);
    d.r = c.radius;
    return d;
}
static ld ldisk_dist(const ldisk *d, lv p)
{
    lv D = lv_sub(p, d->c);
    ld h = lv_dot(d->n, D), rho = lv_norm(lv_cross(d->n, D));
    if (rho <= d->r) return fabsl(h);
    return sqrtl((rho - d->r) * (rho - d->r) + h * h);
}
static lv lcircle_pt(const ldisk *d, ld t, ld s) { return lv_add(d->c, lv_add(lv_scale(s * cosl(t), d->u), lv_scale(s * sinl(t), d->v))); }

typedef ld (*lfun)(const void *ctx, ld t);
static ld golden(lfun f, const void *ctx, ld a, ld b, ld tol)
{
    const ld g = 0.6180339887498948482045868L;
    ld c = b - g * (b - a), d = a + g * (b - a), fc = f(ctx, c), fd = f(ctx, d);
    ld best = fminl(fminl(f(ctx, a), f(ctx, b)), fminl(fc, fd));
    for (int it = 0; it < 400 && b - a > tol; it++) {
        if (fc <= fd) {
            b = d; d = c; fd = fc; c = b - g * (b - a); fc = f(ctx, c);
        } else {
            a = c; c = d; fc = fd; d = a + g * (b - a); fd = f(ctx, d);
        }
        best = fminl(best, fminl(fc, fd));
    }
    return best;
}

typedef struct { lv B, M; const ldisk *d; } lin_ctx;
static ld lin_f(const void *ctx, ld t)
{
    const lin_ctx *c = ctx;
    return ldisk_dist(c->d, lv_add(c->B, lv_scale(t, c->M)));
}
/* Convex in t: golden section over a window that contains the minimum. */
static ld ref_linear(cdist_vec3 B, cdist_vec3 M, ld tmin, ld tmax, cdist_circle dk)
{
    O = dk.center;
    ldisk d = lmake(dk);
    lin_ctx c = {lv_sub(lv_of(B), lv_of(O)), lv_of(M), &d};
    ld mm = lv_dot(c.M, c.M), tc = lv_dot(lv_sub(d.c, c.B), c.M) / mm;
    ld d0 = lv_norm(lv_sub(lv_add(c.B, lv_scale(tc, c.M)), d.c));
    ld w = (d0 + 2 * d.r) / sqrtl(mm) + 1;
    ld lo = fmaxl(tmin, tc - w), hi = fminl(tmax, tc + w);
    if (lo > hi) return lin_f(&c, tc < tmin ? tmin : tmax);
    return golden(lin_f, &c, lo, hi, (hi - lo) * 1e-19L);
}

typedef struct { const ldisk *c, *d; } cd_ctx;
static ld cd_f(const void *ctx, ld t)
{
    const cd_ctx *c = ctx;
    return ldisk_dist(c->d, lcircle_pt(c->c, t, c->c->r));
}
/* Circle-disk: 2048 samples, every sampled local minimum refined by golden section. */
static ld ref_circle_disk(cdist_circle cc, cdist_circle dk)
{
    O = dk.center;
    ldisk c = lmake(cc), d = lmake(dk);
    cd_ctx x = {&c, &d};
    enum { NS = 2048 };
    static ld v[NS];
    const ld h = 2 * 3.14159265358979323846264L / NS;
    ld best = INFINITY;
    ld vmin = INFINITY, vmax = 0;
    for (int i = 0; i < NS; i++) {
        v[i] = cd_f(&x, i * h);
        vmin = fminl(vmin, v[i]);
        vmax = fmaxl(vmax, v[i]);
    }
    for (int i = 0; i < NS; i++) {
        ld a = v[(i + NS - 1) % NS], b = v[(i + 1) % NS];
        best = fminl(best, v[i]);
        if (v[i] <= a && v[i] <= b && v[i] > vmin + 0.1L * (vmax - vmin)) {
            best = fminl(best, golden(cd_f, &x, (i - 1) * h, (i + 1) * h, 1e-19L));
        } else if (v[i] <= a && v[i] <= b) {
            /* Resample the bracket: a minimum-maximum-minimum cluster narrower than the grid
             * would otherwise give golden section the higher minimum. */
            enum { NF = 256 };
            ld w[NF + 1], t0 = (i - 1) * h, hf = 2 * h / NF;
            for (int j = 0; j <= NF; j++) w[j] = cd_f(&x, t0 + j * hf);
            for (int j = 1; j < NF; j++)
                if (w[j] <= w[j - 1] && w[j] <= w[j + 1])
                    best = fminl(best, golden(cd_f, &x, t0 + (j - 1) * hf, t0 + (j + 1) * hf, 1e-19L));
        }
    }
    return best;
}

/* Disk-disk: the distance from a point to disk 1 is convex in the point, disk 0 is convex: nested
 * golden section (outer x, inner y over the chord of disk 0). */
typedef struct { const ldisk *a, *b; ld x, w; } dd_ctx;
static ld dd_in(const void *ctx, ld y)
{
    const dd_ctx *c = ctx;
    return ldisk_dist(c->b, lv_add(c->a->c, lv_add(lv_scale(c->x, c->a->u), lv_scale(y, c->a->v))));
}
static ld dd_out(const void *ctx, ld x)
{
    dd_ctx c = *(const dd_ctx *)ctx;
    c.x = x;
    ld w = sqrtl(fmaxl(c.a->r * c.a->r - x * x, 0));
    if (w == 0) return dd_in(&c, 0);
    return golden(dd_in, &c, -w, w, w * 1e-17L);
}
static ld ref_disk_disk(cdist_circle d0, cdist_circle d1)
{
    O = d1.center;
    ldisk a = lmake(d0), b = lmake(d1);
    if (a.r == 0) return ldisk_dist(&b, a.c);
    dd_ctx c = {&a, &b, 0, 0};
    return golden(dd_out, &c, -a.r, a.r, a.r * 1e-17L);
}

/* ---- helpers ---- */

static double cscale(cdist_circle a, cdist_circle b, double d)
{
    return fmax(fmax(fabs(d), tdist(a.center, b.center)), fmax(a.radius, b.radius));
}

/* Pairs lie on their objects and realise the distance. kind0: 'c' circle, 'd' disk, 'l' line... */
static void check_pairs_disk(const char *what, const cdist_result *r, cdist_circle second, double L)
{
    double tol = 64 * EPS * L;
    for (int i = 0; i < r->num_pairs; i++) {
        double dp = tdist(r->pairs[i].point[0], r->pairs[i].point[1]);
        CHECK(fabs(dp - r->distance) <= tol, "%s pair %d: |p0-p1| %.17g vs distance %.17g", what, i, dp, r->distance);
        CHECK((double)ref_point_disk(r->pairs[i].point[1], second) <= tol, "%s pair %d: second point off the disk",
              what, i);
    }
}

/* ---- exact constructions ---- */

static void exact_circle_disk(void)
{
    cdist_result r;
    cdist_circle d = circ(0, 0, 0, 0, 0, 1, 2);
    for (int m = 0; m <= 2; m++) {
        cdist_query_set_method(q, (cdist_method)m);
        /* Piercing twice: circle in the xz-plane, centre (1,0,0), radius 0.5. */
        cdist_circle c = circ(1, 0, 0, 0, 1, 0, 0.5);
        CHECK(cdist_circle_disk(q, &c, &d, &r) == CDIST_OK, "pierce2 status");
        CHECK(r.distance <= 4 * EPS && r.num_pairs == 2 && !r.equidistant, "pierce2: d %g pairs %d eq %d", r.distance,
              r.num_pairs, r.equidistant);
        for (int i = 0; i < r.num_pairs; i++) {
            cdist_vec3 p = r.pairs[i].point[0];
            CHECK(near_pt(p, tv(0.5, 0, 0), 1e-15) || near_pt(p, tv(1.5, 0, 0), 1e-15), "pierce2 point %g %g %g", p.x,
                  p.y, p.z);
            CHECK(near_pt(p, r.pairs[i].point[1], 1e-15), "pierce2 pair coincides");
        }
        if (r.num_pairs == 2)
            CHECK(tdist(r.pairs[0].point[0], r.pairs[1].point[0]) > 0.9, "pierce2: two distinct pairs");
        /* Piercing once (the other crossing is outside the disk). */
        c = circ(2, 0, 0, 0, 1, 0, 1);
        CHECK(cdist_circle_disk(q, &c, &d, &r) == CDIST_OK && r.distance <= 4 * EPS && r.num_pairs == 1 &&
                  !r.equidistant && near_pt(r.pairs[0].point[1], tv(1, 0, 0), 1e-15),
              "pierce1: d %g pairs %d", r.distance, r.num_pairs);
        CHECK(fabs(r.pairs[0].param[1] - 0.0) <= 1e-15, "pierce1 disk angle %g", r.pairs[0].param[1]);
        /* Linked with the rim: centred on the rim point (2,0,0), radius 0.5, in the xz-plane. */
        c = circ(2, 0, 0, 0, 1, 0, 0.5);
        CHECK(cdist_circle_disk(q, &c, &d, &r) == CDIST_OK && r.distance <= 4 * EPS && r.num_pairs == 1 &&
                  near_pt(r.pairs[0].point[0], tv(1.5, 0, 0), 1e-15),
              "linked: d %g pairs %d", r.distance, r.num_pairs);
        /* Coplanar concentric, inside: 0 everywhere. */
        c = circ(0, 0, 0, 0, 0, 1, 1);
        CHECK(cdist_circle_disk(q, &c, &d, &r) == CDIST_OK && r.distance == 0 && r.equidistant && r.num_pairs == 1,
              "coplanar concentric inside: %g eq %d", r.distance, r.equidistant);
        /* Coplanar concentric, outside: r_c - r_d everywhere. */
        c = circ(0, 0, 0, 0, 0, -1, 3);
        CHECK(cdist_circle_disk(q, &c, &d, &r) == CDIST_OK && r.distance == 1 && r.equidistant,
              "coplanar concentric outside: %g eq %d", r.distance, r.equidistant);
        CHECK(fabs(tdist(r.pairs[0].point[0], tv(0, 0, 0)) - 3) <= 4 * EPS &&
                  fabs(tdist(r.pairs[0].point[1], tv(0, 0, 0)) - 2) <= 4 * EPS,
              "concentric representative pair");
        /* Coplanar overlapping. */
        c = circ(2, 0, 0, 0, 0, 1, 1);
        CHECK(cdist_circle_disk(q, &c, &d, &r) == CDIST_OK && r.distance == 0 && r.equidistant,
              "coplanar overlap: %g eq %d", r.distance, r.equidistant);
        /* Coplanar disjoint: one pair (4,0,0)-(2,0,0). */
        c = circ(5, 0, 0, 0, 0, 1, 1);
        CHECK(cdist_circle_disk(q, &c, &d, &r) == CDIST_OK && r.distance == 2 && !r.equidistant && r.num_pairs == 1 &&
                  near_pt(r.pairs[0].point[0], tv(4, 0, 0), 4 * EPS) &&
                  near_pt(r.pairs[0].point[1], tv(2, 0, 0), 4 * EPS),
              "coplanar disjoint: %g", r.distance);
        /* Coplanar, externally tangent: a single contact point. */
        c = circ(3, 0, 0, 0, 0, 1, 1);
        CHECK(cdist_circle_disk(q, &c, &d, &r) == CDIST_OK && r.distance == 0 && !r.equidistant &&
                  r.num_pairs == 1 && near_pt(r.pairs[0].point[0], tv(2, 0, 0), 4 * EPS),
              "coplanar tangent: %g eq %d", r.distance, r.equidistant);
        /* Parallel above the face, overlapping projection: equidistant at the height. */
        c = circ(1, 0, 3, 0, 0, 1, 0.5);
        CHECK(cdist_circle_disk(q, &c, &d, &r) == CDIST_OK && r.distance == 3 && r.equidistant,
              "parallel over face: %g eq %d", r.distance, r.equidistant);
        CHECK(fabs(r.pairs[0].point[1].z) == 0 && fabs(r.pairs[0].point[0].z - 3) == 0, "parallel pair heights");
        /* Parallel, projection outside: one pair. */
        c = circ(4, 0, 3, 0, 0, 1, 1);
        CHECK(cdist_circle_disk(q, &c, &d, &r) == CDIST_OK && fabs(r.distance - sqrt(10.0)) <= 4 * EPS &&
                  !r.equidistant && near_pt(r.pairs[0].point[0], tv(3, 0, 3), 4 * EPS) &&
                  near_pt(r.pairs[0].point[1], tv(2, 0, 0), 4 * EPS),
              "parallel outside: %.17g", r.distance);
        /* Coaxial above, larger: equidistant at sqrt(1 + 1). */
        c = circ(0, 0, 1, 0, 0, 1, 3);
        CHECK(cdist_circle_disk(q, &c, &d, &r) == CDIST_OK && fabs(r.distance - sqrt(2.0)) <= 4 * EPS && r.equidistant,
              "coaxial: %.17g eq %d", r.distance, r.equidistant);
        /* Tangent to the rim: circle in the plane x = 2 touching (2,0,0) from above. */
        c = circ(2, 0, 1, 1, 0, 0, 1);
        CHECK(cdist_circle_disk(q, &c, &d, &r) == CDIST_OK && r.distance <= 4 * EPS && r.num_pairs == 1 &&
                  near_pt(r.pairs[0].point[0], tv(2, 0, 0), 1e-15),
              "rim tangent: %g pairs %d", r.distance, r.num_pairs);
        /* Around the disk in a vertical plane: two symmetric pairs at distance 1. */
        c = circ(0, 0, 0, 0, 1, 0, 3);
        CHECK(cdist_circle_disk(q, &c, &d, &r) == CDIST_OK && fabs(r.distance - 1) <= 4 * EPS && r.num_pairs == 2 &&
                  !r.equidistant,
              "around: %.17g pairs %d", r.distance, r.num_pairs);
        if (r.num_pairs == 2) {
            CHECK(fabs(fabs(r.pairs[0].point[0].x) - 3) <= 4 * EPS && fabs(fabs(r.pairs[1].point[0].x) - 3) <= 4 * EPS &&
                      r.pairs[0].point[0].x * r.pairs[1].point[0].x < 0,
                  "around: the pairs are (+-3, 0, 0)");
        }
        /* Circle of radius 0 (a point) over the face, and a disk of radius 0. */
        c = circ(1, 1, 2, 0, 0, 1, 0);
        CHECK(cdist_circle_disk(q, &c, &d, &r) == CDIST_OK && r.distance == 2 && near_pt(r.pairs[0].point[1], tv(1, 1, 0), 0),
              "point circle: %g", r.distance);
        cdist_circle p0 = circ(5, 0, 0, 0, 0, 1, 0);
        c = circ(0, 0, 0, 0, 0, 1, 3);
        CHECK(cdist_circle_disk(q, &c, &p0, &r) == CDIST_OK && r.distance == 2 && near_pt(r.pairs[0].point[0], tv(3, 0, 0), 4 * EPS),
              "point disk: %g", r.distance);
        /* The disk's polar angle reproduces the disk point. */
        c = circ(3, 4, 7, 0.6, 0, 0.8, 1);
        CHECK(cdist_circle_disk(q, &c, &d, &r) == CDIST_OK, "generic status");
        double a = r.pairs[0].param[1];
        double rr = hypot(r.pairs[0].point[1].x, r.pairs[0].point[1].y);
        CHECK(fabs(rr * cos(a) - r.pairs[0].point[1].x) <= 1e-14 && fabs(rr * sin(a) - r.pairs[0].point[1].y) <= 1e-14,
              "disk polar angle");
        cdist_vec3 k;
        cdist_circle_point(&c, r.pairs[0].param[0], &k);
        CHECK(near_pt(k, r.pairs[0].point[0], 1e-14), "circle angle reproduces the circle point");
        CHECK(r.method == (m == 1 ? CDIST_METHOD_POLYNOMIAL : CDIST_METHOD_ROBUST), "method reported %d", r.method);
    }
    cdist_query_set_method(q, CDIST_METHOD_AUTO);
}

static void exact_disk_disk(void)
{
    cdist_result r, s;
    cdist_circle a = circ(0, 0, 0, 0, 0, 1, 1);
    struct { cdist_circle b; double d; int eq; cdist_vec3 p0, p1; const char *what; } cases[] = {
        {circ(1.5, 0, 0, 0, 0, 1, 1), 0, 1, {NAN, 0, 0}, {0, 0, 0}, "coplanar overlap"},
        {circ(0.5, 0, 2, 0, 0, -1, 1), 2, 1, {NAN, 0, 0}, {0, 0, 0}, "parallel stacked"},
        {circ(0, 0, 2, 0, 0, 1, 3), 2, 1, {NAN, 0, 0}, {0, 0, 0}, "parallel, a under b's face"},
        {circ(3, 0, 2, 0, 0, 1, 1), sqrt(5.0), 0, {1, 0, 0}, {2, 0, 2}, "parallel disjoint"},
        {circ(0, 0, 0, 1, 0, 0, 1), 0, 1, {NAN, 0, 0}, {0, 0, 0}, "crossing along a segment"},
        {circ(0, 0, 1, 1, 0, 0, 1), 0, 0, {0, 0, 0}, {0, 0, 0}, "touching at a point"},
        {circ(0, 0, 2, 1, 0, 0, 1), 1, 0, {0, 0, 0}, {0, 0, 1}, "T above the centre"},
        {circ(3, 0, 0, 1, 0, 0, 1), 2, 0, {1, 0, 0}, {3, 0, 0}, "rim to face"},
        {circ(2, 0, 0, 0, 0, 1, 1), 0, 0, {1, 0, 0}, {1, 0, 0}, "coplanar tangent"},
        {circ(0, 0, 0, 0, 0, 1, 1), 0, 1, {NAN, 0, 0}, {0, 0, 0}, "identical"},
        {circ(0.3, 0.2, 5, 0, 0, 1, 0), 5, 0, {0.3, 0.2, 0}, {0.3, 0.2, 5}, "point over the face"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        CHECK(cdist_disk_disk(q, &a, &cases[i].b, &r) == CDIST_OK, "%s: status", cases[i].what);
        CHECK(fabs(r.distance - cases[i].d) <= 8 * EPS, "%s: distance %.17g expected %.17g", cases[i].what, r.distance,
              cases[i].d);
        CHECK(r.equidistant == cases[i].eq, "%s: equidistant %d", cases[i].what, r.equidistant);
        if (!cases[i].eq) {
            CHECK(r.num_pairs == 1, "%s: pairs %d", cases[i].what, r.num_pairs);
            CHECK(near_pt(r.pairs[0].point[0], cases[i].p0, 1e-15) && near_pt(r.pairs[0].point[1], cases[i].p1, 1e-15),
                  "%s: pair (%g %g %g)-(%g %g %g)", cases[i].what, r.pairs[0].point[0].x, r.pairs[0].point[0].y,
                  r.pairs[0].point[0].z, r.pairs[0].point[1].x, r.pairs[0].point[1].y, r.pairs[0].point[1].z);
        }
        CHECK((double)ref_point_disk(r.pairs[0].point[0], a) <= 8 * EPS, "%s: first point in disk a", cases[i].what);
        CHECK((double)ref_point_disk(r.pairs[0].point[1], cases[i].b) <= 8 * EPS, "%s: second point in disk b",
              cases[i].what);
        CHECK(cdist_disk_disk(q, &cases[i].b, &a, &s) == CDIST_OK && s.distance == r.distance &&
                  s.equidistant == r.equidistant && s.num_pairs == r.num_pairs &&
                  near_pt(s.pairs[0].point[0], r.pairs[0].point[1], 0) && near_pt(s.pairs[0].point[1], r.pairs[0].point[0], 0),
              "%s: swapped arguments disagree", cases[i].what);
    }
}

static void exact_linear_disk(void)
{
    cdist_result r;
    cdist_circle d = circ(0, 0, 0, 0, 0, 1, 2);
    for (int m = 0; m <= 2; m++) {
        cdist_query_set_method(q, (cdist_method)m);
        /* Piercing: the crossing point is the pair; t for the direction as passed. */
        cdist_line l = {tv(0.5, 0.3, 4), tv(0, 0, -1)};
        CHECK(cdist_line_disk(q, &l, &d, &r) == CDIST_OK && r.distance == 0 && !r.equidistant && r.num_pairs == 1 &&
                  near_pt(r.pairs[0].point[0], tv(0.5, 0.3, 0), 0) && r.pairs[0].param[0] == 4,
              "pierce: %g t %g", r.distance, r.pairs[0].param[0]);
        CHECK(fabs(r.pairs[0].param[1] - atan2(0.3, 0.5)) <= 4 * EPS, "pierce disk angle");
        /* The axis: the centre, disk angle NaN. */
        l = (cdist_line){tv(0, 0, 1), tv(0, 0, 1)};
        CHECK(cdist_line_disk(q, &l, &d, &r) == CDIST_OK && r.distance == 0 && !r.equidistant &&
                  near_pt(r.pairs[0].point[1], tv(0, 0, 0), 0) && isnan(r.pairs[0].param[1]) && r.pairs[0].param[0] == -1,
              "axis: %g", r.distance);
        /* Through the rim point perpendicular to the plane. */
        l = (cdist_line){tv(2, 0, 5), tv(0, 0, 1)};
        CHECK(cdist_line_disk(q, &l, &d, &r) == CDIST_OK && r.distance == 0 && near_pt(r.pairs[0].point[1], tv(2, 0, 0), 4 * EPS),
              "through rim: %g", r.distance);
        /* In the plane across the disk: equidistant at 0. */
        l = (cdist_line){tv(-5, 1, 0), tv(1, 0, 0)};
        CHECK(cdist_line_disk(q, &l, &d, &r) == CDIST_OK && r.distance == 0 && r.equidistant && r.num_pairs == 1,
              "in plane: %g eq %d", r.distance, r.equidistant);
        /* Parallel over the face: equidistant at the height. */
        l = (cdist_line){tv(-5, 1, 2), tv(2, 0, 0)};
        cdist_query_set_unit_tolerance(q, INFINITY);
        CHECK(cdist_line_disk(q, &l, &d, &r) == CDIST_OK && r.distance == 2 && r.equidistant &&
                  fabs(r.pairs[0].point[0].y - 1) <= 4 * EPS && r.pairs[0].point[1].z == 0,
              "parallel over: %g eq %d", r.distance, r.equidistant);
        /* t for the direction as passed (length 2). */
        cdist_vec3 lp = tv(-5 + 2 * r.pairs[0].param[0], 1, 2);
        CHECK(near_pt(lp, r.pairs[0].point[0], 1e-14), "param for the direction as passed");
        cdist_query_set_unit_tolerance(q, 1e-6);
        /* In the plane, outside: one pair (0,3,0)-(0,2,0). */
        l = (cdist_line){tv(-5, 3, 0), tv(1, 0, 0)};
        CHECK(cdist_line_disk(q, &l, &d, &r) == CDIST_OK && r.distance == 1 && !r.equidistant &&
                  near_pt(r.pairs[0].point[0], tv(0, 3, 0), 4 * EPS) && near_pt(r.pairs[0].point[1], tv(0, 2, 0), 4 * EPS),
              "plane outside: %g", r.distance);
        /* In the plane, tangent to the rim: a single contact point. */
        l = (cdist_line){tv(-5, 2, 0), tv(1, 0, 0)};
        CHECK(cdist_line_disk(q, &l, &d, &r) == CDIST_OK && r.distance == 0 && !r.equidistant && r.num_pairs == 1 &&
                  near_pt(r.pairs[0].point[1], tv(0, 2, 0), 4 * EPS),
              "tangent: %g eq %d", r.distance, r.equidistant);
        /* Skew, outside: (3,0,1) to the rim point (2,0,0). */
        l = (cdist_line){tv(3, -4, 1), tv(0, 1, 0)};
        CHECK(cdist_line_disk(q, &l, &d, &r) == CDIST_OK && fabs(r.distance - sqrt(2.0)) <= 4 * EPS && r.num_pairs == 1 &&
                  near_pt(r.pairs[0].point[1], tv(2, 0, 0), 4 * EPS) && fabs(r.pairs[0].param[0] - 4) <= 1e-14,
              "skew: %.17g", r.distance);
        /* Rays: stopping short of the disk, and reaching it. */
        cdist_ray ry = {tv(0.5, 0, 5), tv(0, 0, 1)};
        CHECK(cdist_ray_disk(q, &ry, &d, &r) == CDIST_OK && r.distance == 5 && r.pairs[0].param[0] == 0 &&
                  near_pt(r.pairs[0].point[1], tv(0.5, 0, 0), 0),
              "ray away: %g", r.distance);
        ry.direction = tv(0, 0, -1);
        CHECK(cdist_ray_disk(q, &ry, &d, &r) == CDIST_OK && r.distance == 0 && r.pairs[0].param[0] == 5, "ray towards: %g",
              r.distance);
        /* A ray in the plane starting inside: equidistant 0. */
        ry = (cdist_ray){tv(0, 0, 0), tv(1, 0, 0)};
        CHECK(cdist_ray_disk(q, &ry, &d, &r) == CDIST_OK && r.distance == 0 && r.equidistant, "ray in plane");
        /* Segments: over the face (equidistant), beyond the rim, through the face. */
        cdist_segment sg = {tv(0, 0, 1), tv(1, 0, 1)};
        CHECK(cdist_segment_disk(q, &sg, &d, &r) == CDIST_OK && r.distance == 1 && r.equidistant, "segment over face");
        CHECK(r.pairs[0].param[0] >= 0 && r.pairs[0].param[0] <= 1, "segment s in [0,1]");
        sg = (cdist_segment){tv(3, 0, 1), tv(5, 0, 1)};
        CHECK(cdist_segment_disk(q, &sg, &d, &r) == CDIST_OK && fabs(r.distance - sqrt(2.0)) <= 4 * EPS &&
                  r.pairs[0].param[0] == 0 && !r.equidistant,
              "segment beyond: %.17g s %g", r.distance, r.pairs[0].param[0]);
        sg = (cdist_segment){tv(1, 1, -1), tv(1, 1, 3)};
        CHECK(cdist_segment_disk(q, &sg, &d, &r) == CDIST_OK && r.distance == 0 && r.pairs[0].param[0] == 0.25 &&
                  near_pt(r.pairs[0].point[1], tv(1, 1, 0), 0),
              "segment through: %g s %g", r.distance, r.pairs[0].param[0]);
        sg = (cdist_segment){tv(1, 1, 1), tv(1, 1, 1)};
        CHECK(cdist_segment_disk(q, &sg, &d, &r) == CDIST_OK && r.distance == 1 && r.pairs[0].param[0] == 0,
              "degenerate segment");
        /* A segment ending exactly on the face. */
        sg = (cdist_segment){tv(1, 0, 2), tv(1, 0, 0)};
        CHECK(cdist_segment_disk(q, &sg, &d, &r) == CDIST_OK && r.distance == 0 && r.pairs[0].param[0] == 1,
              "segment ending on the face: s %g", r.pairs[0].param[0]);
    }
    cdist_query_set_method(q, CDIST_METHOD_AUTO);
}

/* ---- brute force on random and near-degenerate inputs ---- */

static cdist_circle rand_circle(double spread)
{
    cdist_circle c = {tv(spread * srand1(), spread * srand1(), spread * srand1()), rand_unit(), 0.05 + 1.5 * urand()};
    return c;
}

/* A near-degenerate circle/disk pair, family k, in a random frame. */
static void degenerate_pair(int k, cdist_circle *a, cdist_circle *b, int far)
{
    double tiny = pow(10.0, -4 - 12 * urand());
    double R = 0.5 + urand();
    *b = circ(0, 0, 0, 0, 0, 1, R);
    double rho = 0.2 + urand();
    switch (k % 10) {
    case 0: /* nearly parallel, over the face */
        *a = circ(srand1() * R, 0, 0.5 * srand1(), tiny, 0, 1, rho);
        break;
    case 1: /* nearly coaxial */
        *a = circ(tiny, tiny * srand1(), srand1(), tiny * srand1(), 0, 1, rho);
        break;
    case 2: /* nearly touching the face from above at one point (tilted) */
    {
        double th = 0.3 + urand();
        *a = circ(0.3 * srand1(), 0.2 * srand1(), rho * sin(th) + tiny * srand1(), 0, cos(th), sin(th), rho);
        a->normal = tv(0, cos(th), sin(th));
        /* lowest point at height ~tiny: centre height rho * cos(th) */
        a->center.z = rho * cos(th) + tiny * srand1();
        break;
    }
    case 3: /* nearly through the rim */
        *a = circ(R + rho * 0.0, 0, rho + tiny * srand1(), 1, 0, 0, rho);
        break;
    case 4: /* linked with the rim, perpendicular */
        *a = circ(R + tiny * srand1(), 0, tiny * srand1(), 0, 1, 0, rho);
        break;
    case 5: /* coplanar within rounding, overlapping or near-tangent */
        *a = circ(R + rho + tiny * srand1(), 0, tiny * srand1(), 0, 0, 1, rho);
        break;
    case 6: /* parallel, projection near-tangent to the rim */
        *a = circ(R + rho + tiny * srand1(), 0, 0.7, 0, 0, 1, rho);
        break;
    case 7: /* centre on the axis, tilted */
        *a = circ(0, 0, srand1(), srand1(), srand1(), 1, rho);
        break;
    case 8: /* a disk 1e-1..1e-4 of the circle's size, within a few of its radii of the circle */
    {
        double r = pow(10.0, -1 - 3 * urand()) * R;
        cdist_vec3 n = rand_unit(), m = rand_unit();
        cdist_vec3 w = tv(n.y * m.z - n.z * m.y, n.z * m.x - n.x * m.z, n.x * m.y - n.y * m.x);
        double wn = sqrt(w.x * w.x + w.y * w.y + w.z * w.z);
        *a = circ(-R * w.x / wn + 3 * r * srand1(), -R * w.y / wn + 3 * r * srand1(), -R * w.z / wn + 3 * r * srand1(),
                  n.x, n.y, n.z, R);
        *b = circ(0, 0, 0, 0, 0, 1, r);
        break;
    }
    default: /* a circle 1e-3 of the disk's size near its rim, random orientation */
    {
        double r = pow(10.0, -1 - 3 * urand()) * R;
        cdist_vec3 n = rand_unit();
        *a = circ(R + 2 * r * srand1(), 2 * r * srand1(), 2 * r * srand1(), n.x, n.y, n.z, r);
        break;
    }
    }
    double n = sqrt(a->normal.x * a->normal.x + a->normal.y * a->normal.y + a->normal.z * a->normal.z);
    a->normal = tv(a->normal.x / n, a->normal.y / n, a->normal.z / n);
    trot rot = rand_rotation();
    double s = pow(10.0, 3 * srand1());
    cdist_vec3 t = far && urand() < 0.3 ? tv(1e5 * srand1(), 1e5 * srand1(), 1e5 * srand1()) : tv(srand1(), srand1(), srand1());
    *a = xform_circle(&rot, s, t, *a);
    *b = xform_circle(&rot, s, t, *b);
}

static double worst_cd[3], worst_dd, worst_lin[3];

static void brute_one_cd(cdist_circle c, cdist_circle d, const char *what)
{
    ld ref = ref_circle_disk(c, d);
    for (int m = 0; m <= 2; m++) {
        cdist_result r;
        cdist_query_set_method(q, (cdist_method)m);
        CHECK(cdist_circle_disk(q, &c, &d, &r) == CDIST_OK, "%s cd status", what);
        double L = cscale(c, d, (double)ref);
        double e = (double)(fabsl(r.distance - ref) / L);
        if (e > worst_cd[m]) worst_cd[m] = e;
        CHECK(e <= 1e-12, "%s cd method %d: %.17g vs brute force %.20Lg (error %.3g of scale %.3g)\n  cd %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g", what, m, r.distance,
              ref, e, L, c.center.x, c.center.y, c.center.z, c.normal.x, c.normal.y, c.normal.z, c.radius,
              d.center.x, d.center.y, d.center.z, d.normal.x, d.normal.y, d.normal.z, d.radius);
        if (getenv("DISK_VERBOSE") && e > 1e-14)
            printf("%s m%d e %.3g\n  cd %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", what, m, e,
                   c.center.x, c.center.y, c.center.z, c.normal.x, c.normal.y, c.normal.z, c.radius,
                   d.center.x, d.center.y, d.center.z, d.normal.x, d.normal.y, d.normal.z, d.radius);
        double ctol = 64 * EPS * L + 32 * EPS * fmax(fabs(c.center.x), fmax(fabs(c.center.y), fabs(c.center.z)));
        for (int i = 0; i < r.num_pairs; i++) {
            CHECK((double)ref_point_circle(r.pairs[i].point[0], c) <= ctol, "%s cd: first point off the circle", what);
            CHECK((double)ref_point_disk(r.pairs[i].point[1], d) <= ctol, "%s cd: second point off the disk", what);
            CHECK(fabs(tdist(r.pairs[i].point[0], r.pairs[i].point[1]) - r.distance) <= ctol, "%s cd: pair distance",
                  what);
        }
        /* Disk distance <= rim (circle-circle) distance: the rim is part of the disk. */
        ld rim = INFINITY;
        O = d.center;
        ldisk lc = lmake(c), ldk = lmake(d);
        for (int i = 0; i < 256; i++) {
            lv p = lv_sub(lcircle_pt(&lc, i * 3.14159265358979323846L / 128, lc.r), ldk.c);
            ld h = lv_dot(ldk.n, p), rho = lv_norm(lv_cross(ldk.n, p));
            rim = fminl(rim, sqrtl((rho - ldk.r) * (rho - ldk.r) + h * h));
        }
        CHECK(r.distance <= rim + 1e-13 * L, "%s: disk distance %.17g > sampled rim distance %.17Lg", what, r.distance, rim);
    }
    cdist_query_set_method(q, CDIST_METHOD_AUTO);
}

static void brute_one_dd(cdist_circle a, cdist_circle b, const char *what)
{
    ld ref = ref_disk_disk(a, b);
    cdist_result r, s;
    CHECK(cdist_disk_disk(q, &a, &b, &r) == CDIST_OK, "%s dd status", what);
    double L = cscale(a, b, (double)ref);
    double e = (double)(fabsl(r.distance - ref) / L);
    if (e > worst_dd) worst_dd = e;
    CHECK(e <= 1e-12, "%s dd: %.17g vs brute force %.20Lg (error %.3g of scale %.3g)", what, r.distance, ref, e, L);
    double ctol = 64 * EPS * L + 32 * EPS * fmax(fabs(a.center.x), fmax(fabs(a.center.y), fabs(a.center.z)));
    for (int i = 0; i < r.num_pairs; i++) {
        CHECK((double)ref_point_disk(r.pairs[i].point[0], a) <= ctol, "%s dd: first point off its disk", what);
        CHECK((double)ref_point_disk(r.pairs[i].point[1], b) <= ctol, "%s dd: second point off its disk", what);
    }
    /* Symmetry: f(b, a) is f(a, b) with the points swapped, exactly. */
    CHECK(cdist_disk_disk(q, &b, &a, &s) == CDIST_OK && s.distance == r.distance && s.equidistant == r.equidistant &&
              s.num_pairs == r.num_pairs && near_pt(s.pairs[0].point[0], r.pairs[0].point[1], 0),
          "%s dd: f(a,b) %.17g and f(b,a) %.17g disagree", what, r.distance, s.distance);
    /* Disk-disk <= circle-disk either way. */
    cdist_result c0, c1;
    cdist_circle_disk(q, &a, &b, &c0);
    cdist_circle_disk(q, &b, &a, &c1);
    CHECK(r.distance <= c0.distance + 4 * EPS * L && r.distance <= c1.distance + 4 * EPS * L, "%s dd > cd", what);
}

/* Regression (review of the certified rim search): a disk 4.7e-9 across beside a unit rim that
 * passes 1.3e-11 from it. The first half's rim minimum came from the engine, off by 5e-12 rad,
 * and the second half had skipped its (well conditioned) rim search: 1.39e-11 instead of
 * 1.33e-11. Disk-disk can never exceed the distance between the rims (the same two circles'
 * cdist_circle_circle), nor circle-disk either way. The 5e-12 rad were the engine's Newton
 * stopping after a step of 1.7e-10 rad as if F's features were a radian wide (they are the
 * tiny rim's 4.7e-9): circle-disk of the big circle and the tiny disk, whose rim minimum comes
 * from that engine alone, gave 1.39e-11 too (6.4e-13 of scale). */
static void tiny_disk_by_rim(void)
{
    cdist_circle a = {{0, 0, 0}, {0x1.c3dd683edeffep-2, -0x1.49e4076bc3d2ep-1, 0x1.3fcc3cdbea7a2p-1}, 0x1.45a879d797bdep-28};
    cdist_circle b = {{-0x1.58fc3a203e73cp-1, 0x1.cad582c230317p-2, -0x1.2cd3c33a393c9p-1},
                      {0x1.7a18c95161117p-1, 0x1.be5f3f4945666p-2, -0x1.076414e9ad486p-1}, 1};
    cdist_result r, s, c;
    CHECK(cdist_circle_circle(q, &a, &b, &c) == CDIST_OK, "tiny disk by rim: cc status");
    CHECK(cdist_disk_disk(q, &a, &b, &r) == CDIST_OK && cdist_disk_disk(q, &b, &a, &s) == CDIST_OK,
          "tiny disk by rim: dd status");
    CHECK(r.distance <= c.distance + 4 * EPS && s.distance == r.distance,
          "tiny disk by rim: dd %.17g, swapped %.17g, above the rims' distance %.17g", r.distance, s.distance, c.distance);
    brute_one_dd(a, b, "tiny disk by rim");
    /* Circle-disk both ways, every method: the rims' distance and the brute force to a few ulps
     * (brute_one_cd's 1e-12 of scale would let the 6.4e-13 through). */
    ld ref_big = ref_circle_disk(b, a), ref_tiny = ref_circle_disk(a, b);
    for (int m = 0; m <= 2; m++) {
        cdist_query_set_method(q, (cdist_method)m);
        CHECK(cdist_circle_disk(q, &b, &a, &r) == CDIST_OK && cdist_circle_disk(q, &a, &b, &s) == CDIST_OK,
              "tiny disk by rim: cd status");
        CHECK(r.distance <= c.distance + 4 * EPS && s.distance <= c.distance + 4 * EPS,
              "tiny disk by rim, method %d: cd %.17g (tiny circle: %.17g) above the rims' distance %.17g", m, r.distance,
              s.distance, c.distance);
        CHECK(fabsl(r.distance - ref_big) <= 8 * EPS && fabsl(s.distance - ref_tiny) <= 8 * EPS,
              "tiny disk by rim, method %d: cd %.17g vs brute force %.17Lg, tiny circle %.17g vs %.17Lg", m, r.distance,
              ref_big, s.distance, ref_tiny);
    }
    cdist_query_set_method(q, CDIST_METHOD_AUTO);
    brute_one_cd(b, a, "tiny disk by rim");
    brute_one_cd(a, b, "tiny circle by a big disk's rim");
}

static void brute_one_lin(int kind, cdist_vec3 B, cdist_vec3 M, cdist_circle d, const char *what)
{
    /* kind 0 line, 1 ray, 2 segment (M = p1). */
    ld ref;
    cdist_result r;
    cdist_status st;
    if (kind == 2) {
        cdist_vec3 D = tv(M.x - B.x, M.y - B.y, M.z - B.z);
        ref = ref_linear(B, D, 0, 1, d);
        cdist_segment s = {B, M};
        st = cdist_segment_disk(q, &s, &d, &r);
    } else {
        ref = ref_linear(B, M, kind == 0 ? -INFINITY : 0, INFINITY, d);
        cdist_line l = {B, M};
        cdist_ray ry = {B, M};
        st = kind == 0 ? cdist_line_disk(q, &l, &d, &r) : cdist_ray_disk(q, &ry, &d, &r);
    }
    CHECK(st == CDIST_OK, "%s status %d", what, st);
    double L = fmax(fmax(d.radius, (double)ref), tdist(B, d.center));
    if (kind == 2) L = fmax(L, tdist(M, d.center));
    double e = (double)(fabsl(r.distance - ref) / L);
    if (e > worst_lin[kind]) worst_lin[kind] = e;
    CHECK(e <= 1e-12, "%s: %.17g vs brute force %.20Lg (error %.3g of scale %.3g)", what, r.distance, ref, e, L);
    check_pairs_disk(what, &r, d, L + fmax(fabs(B.x), fmax(fabs(B.y), fabs(B.z))));
    for (int i = 0; i < r.num_pairs; i++) {
        if (kind == 2) {
            double s = r.pairs[i].param[0];
            CHECK(s >= 0 && s <= 1, "%s: s %g", what, s);
            cdist_vec3 p = tv(B.x + s * (M.x - B.x), B.y + s * (M.y - B.y), B.z + s * (M.z - B.z));
            CHECK(near_pt(p, r.pairs[i].point[0], 1e-13 * L), "%s: s reproduces the point", what);
        } else {
            double t = r.pairs[i].param[0];
            if (kind == 1) CHECK(t >= 0, "%s: ray t %g", what, t);
            cdist_vec3 p = tv(B.x + t * M.x, B.y + t * M.y, B.z + t * M.z);
            CHECK(near_pt(p, r.pairs[i].point[0], 1e-12 * (L + fabs(t))), "%s: t reproduces the point", what);
        }
    }
}

static void brute_force(void)
{
    char what[64];
    /* DISK_STRESS=k multiplies the case counts (exploration; the default runs in seconds). */
    int mult = getenv("DISK_STRESS") ? atoi(getenv("DISK_STRESS")) : 1;
    if (mult < 1) mult = 1;
    for (int i = 0; i < 300 * mult; i++) {
        cdist_circle c = rand_circle(1.5), d = rand_circle(1.5);
        snprintf(what, sizeof what, "random %d", i);
        brute_one_cd(c, d, what);
        if (i < 150 * mult) brute_one_dd(c, d, what);
    }
    for (int i = 0; i < 400 * mult; i++) {
        cdist_circle c, d;
        degenerate_pair(i, &c, &d, 1);
        snprintf(what, sizeof what, "degenerate %d (family %d)", i, i % 10);
        brute_one_cd(c, d, what);
        brute_one_cd(d, c, what);
        if (i < 200 * mult) brute_one_dd(c, d, what);
    }
    for (int i = 0; i < 600 * mult; i++) {
        cdist_circle d = rand_circle(1.0);
        cdist_vec3 B = tv(2 * srand1(), 2 * srand1(), 2 * srand1()), M = rand_unit();
        int fam = i % 6;
        if (fam >= 3) {
            /* near-degenerate: nearly parallel to the plane over the face, through the rim,
             * along the axis, from a random frame. */
            double tiny = pow(10.0, -4 - 12 * urand());
            double R = 0.5 + urand();
            d = circ(0, 0, 0, 0, 0, 1, R);
            if (fam == 3) { B = tv(-3, R * srand1(), 0.3 * srand1()); M = tv(1, 0, tiny * srand1()); }
            else if (fam == 4) { B = tv(R, 0, 1); M = tv(tiny * srand1(), tiny * srand1(), -1); }
            else { B = tv(R * srand1(), R * srand1(), tiny * srand1()); M = tv(srand1(), srand1(), tiny * srand1()); }
            double n = sqrt(M.x * M.x + M.y * M.y + M.z * M.z);
            M = tv(M.x / n, M.y / n, M.z / n);
            trot rot = rand_rotation();
            double s = pow(10.0, 2 * srand1());
            cdist_vec3 t = tv(10 * srand1(), 10 * srand1(), 10 * srand1());
            cdist_vec3 B2 = xform_point(&rot, s, t, B), P1 = xform_point(&rot, s, t, tv(B.x + 4 * M.x, B.y + 4 * M.y, B.z + 4 * M.z));
            d = xform_circle(&rot, s, t, d);
            M = rot_apply(&rot, M);
            snprintf(what, sizeof what, "degenerate linear %d", i);
            brute_one_lin(0, B2, M, d, what);
            brute_one_lin(1, B2, M, d, what);
            brute_one_lin(2, B2, P1, d, what);
            continue;
        }
        snprintf(what, sizeof what, "random linear %d", i);
        brute_one_lin(0, B, M, d, what);
        brute_one_lin(1, B, M, d, what);
        cdist_vec3 P1 = tv(B.x + 3 * srand1(), B.y + 3 * srand1(), B.z + 3 * srand1());
        brute_one_lin(2, B, P1, d, what);
    }
    printf("brute force max error of scale: cd auto %.3g polynomial %.3g robust %.3g, dd %.3g, ld %.3g rd %.3g sd %.3g\n",
           worst_cd[0], worst_cd[1], worst_cd[2], worst_dd, worst_lin[0], worst_lin[1], worst_lin[2]);
}

/* ---- invariance ---- */

static void invariance(void)
{
    for (int i = 0; i < 200; i++) {
        cdist_circle a = rand_circle(1.5), b = rand_circle(1.5);
        if (i % 4 == 1) degenerate_pair(i, &a, &b, 0);
        trot rot = rand_rotation();
        double s = pow(2.0, (int)(20 * srand1())); /* power of two: scaling is exact */
        cdist_vec3 t = tv(100 * srand1(), 100 * srand1(), 100 * srand1());
        cdist_circle a2 = xform_circle(&rot, s, t, a), b2 = xform_circle(&rot, s, t, b);
        cdist_result r1, r2;
        cdist_circle_disk(q, &a, &b, &r1);
        cdist_circle_disk(q, &a2, &b2, &r2);
        double L = cscale(a, b, r1.distance);
        /* The moved inputs are rounded, which moves the objects by a few ulps of their
         * coordinates and radii; the distance is 1-Lipschitz in such moves. */
        double mag = 100 + s * (4 + cscale(a, b, 0));
        double tol = 1e-13 * L + 16 * EPS * mag / s;
        CHECK(fabs(r2.distance / s - r1.distance) <= tol, "cd invariance %d: %.17g vs %.17g", i, r1.distance,
              r2.distance / s);
        cdist_disk_disk(q, &a, &b, &r1);
        cdist_disk_disk(q, &a2, &b2, &r2);
        CHECK(fabs(r2.distance / s - r1.distance) <= tol, "dd invariance %d: %.17g vs %.17g", i, r1.distance,
              r2.distance / s);
        cdist_line l = {a.center, a.normal}, l2 = {a2.center, a2.normal};
        cdist_line_disk(q, &l, &b, &r1);
        cdist_line_disk(q, &l2, &b2, &r2);
        CHECK(fabs(r2.distance / s - r1.distance) <= tol, "ld invariance %d: %.17g vs %.17g", i, r1.distance,
              r2.distance / s);
    }
}

static void errors(void)
{
    cdist_result r;
    cdist_circle d = circ(0, 0, 0, 0, 0, 1, 1), bad = circ(0, 0, 0, 0, 0, 0, 1);
    CHECK(cdist_circle_disk(q, &d, &bad, &r) == CDIST_ERR_ZERO_VECTOR && isnan(r.distance), "zero normal");
    CHECK(cdist_disk_disk(q, NULL, &d, &r) == CDIST_ERR_NULL_ARGUMENT, "null disk");
    CHECK(cdist_line_disk(q, NULL, &d, &r) == CDIST_ERR_NULL_ARGUMENT, "null line");
    cdist_ray ry = {tv(0, 0, 0), tv(0, 0, 2)};
    CHECK(cdist_ray_disk(q, &ry, &d, &r) == CDIST_ERR_NOT_UNIT, "ray not unit");
    cdist_segment sg = {tv(NAN, 0, 0), tv(0, 0, 0)};
    CHECK(cdist_segment_disk(q, &sg, &d, &r) == CDIST_ERR_NOT_FINITE, "segment NaN");
    CHECK(cdist_circle_disk(q, &d, &d, NULL) == CDIST_ERR_NULL_ARGUMENT, "null result");
}

int main(void)
{
    q = cdist_query_new();
    exact_circle_disk();
    exact_disk_disk();
    tiny_disk_by_rim();
    exact_linear_disk();
    errors();
    invariance();
    brute_force();
    cdist_query_free(q);
    return check_summary("test_disk");
}
