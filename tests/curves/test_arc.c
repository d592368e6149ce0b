/* SPDX-License-Identifier: MIT */
/* Arc queries (arc-circle, arc-arc, segment-arc, arc-disk) against the long double brute force
 * of brute.h: random configurations, constructed degenerate ones (closest point at an endpoint,
 * the other circle's closest pair cut out of the arc, coplanar, concentric, coaxial, full and
 * zero-length arcs), symmetry, params and pairs, and bad input. */
#include <fenv.h>
#include <float.h>
#include <stdlib.h>
#include <string.h>

#include "brute.h"

#define PI_L 3.14159265358979323846264338327950288L

static cdist_query *q;
/* --short: a fifth of the random and constructed cases (the default suite); full in `slow`. */
static int full = 1;
static double worst_err[4];
static int worst_id[4];
static const char *kind_name[4] = {"arc-circle", "arc-arc", "segment-arc", "arc-disk"};

/* ---- brute-force objective functions ---- */

typedef struct bf_ctx {
    bf_arc a, b;
    bf_circle c;
    lv s0, s1;
} bf_ctx;

static ld f_arc_circle(const void *p, ld t) { const bf_ctx *x = p; return bf_point_circle(bf_arc_point(&x->a, t), &x->c); }
static ld f_arc_disk(const void *p, ld t) { const bf_ctx *x = p; return bf_point_disk(bf_arc_point(&x->a, t), &x->c); }
static ld f_arc_arc(const void *p, ld t) { const bf_ctx *x = p; return bf_point_arc(bf_arc_point(&x->a, t), &x->b); }
static ld f_arc_arc_rev(const void *p, ld t) { const bf_ctx *x = p; return bf_point_arc(bf_arc_point(&x->b, t), &x->a); }
static ld f_seg_arc(const void *p, ld s)
{
    const bf_ctx *x = p;
    return bf_point_arc(lv_add(x->s0, lv_scale(s, lv_sub(x->s1, x->s0))), &x->a);
}
static ld f_arc_seg(const void *p, ld t) { const bf_ctx *x = p; return bf_point_segment(bf_arc_point(&x->a, t), x->s0, x->s1); }

/* Samples of the brute force: constructed cases have flat distance functions with narrow dips
 * (an arc passing the other circle's centre: a dip of 3e-14 of scale a few 1e-4 wide), so they
 * get many more. */
static int NS = 8192;

/* distances to the other object's axis, for the narrow dips (brute.h bf_axis_dips) */
static ld r_arc_c(const void *p, ld t) { const bf_ctx *x = p; return bf_axis_dist(bf_arc_point(&x->a, t), &x->c); }
static ld r_arc_b(const void *p, ld t) { const bf_ctx *x = p; return bf_axis_dist(bf_arc_point(&x->a, t), &x->b.c); }
static ld r_b_arc(const void *p, ld t) { const bf_ctx *x = p; return bf_axis_dist(bf_arc_point(&x->b, t), &x->a.c); }
static ld r_seg_a(const void *p, ld s)
{
    const bf_ctx *x = p;
    return bf_axis_dist(lv_add(x->s0, lv_scale(s, lv_sub(x->s1, x->s0))), &x->a.c);
}

static ld bf_arc_circle(const cdist_arc *a, const cdist_circle *c, int disk)
{
    bf_ctx x;
    x.a = bf_arc_of(a);
    x.c = bf_circ(*c);
    ld d = bf_min1d(disk ? f_arc_disk : f_arc_circle, &x, x.a.a0, x.a.a1, NS);
    if (!disk) d = fminl(d, bf_axis_dips(f_arc_circle, r_arc_c, &x, x.a.a0, x.a.a1, 2048, x.a.c.r));
    return d;
}

static ld bf_arc_arc(const cdist_arc *a, const cdist_arc *b)
{
    bf_ctx x;
    x.a = bf_arc_of(a);
    x.b = bf_arc_of(b);
    ld d = fminl(bf_min1d(f_arc_arc, &x, x.a.a0, x.a.a1, NS), bf_min1d(f_arc_arc_rev, &x, x.b.a0, x.b.a1, NS));
    d = fminl(d, bf_axis_dips(f_arc_arc, r_arc_b, &x, x.a.a0, x.a.a1, 2048, x.a.c.r));
    return fminl(d, bf_axis_dips(f_arc_arc_rev, r_b_arc, &x, x.b.a0, x.b.a1, 2048, x.b.c.r));
}

static ld bf_seg_arc(const cdist_segment *s, const cdist_arc *a)
{
    bf_ctx x;
    x.a = bf_arc_of(a);
    x.s0 = lv_of(s->p0);
    x.s1 = lv_of(s->p1);
    ld d = fminl(bf_min1d(f_seg_arc, &x, 0, 1, NS), bf_min1d(f_arc_seg, &x, x.a.a0, x.a.a1, NS));
    return fminl(d, bf_axis_dips(f_seg_arc, r_seg_a, &x, 0, 1, 2048, lv_norm(lv_sub(x.s1, x.s0))));
}

/* ---- result checks ---- */

static double maxabs3(cdist_vec3 v) { return fmax(fabs(v.x), fmax(fabs(v.y), fabs(v.z))); }

/* The pair point p with arc param t lies on the arc: on its circle, t in [start, end], and the
 * arc's point at t is p. */
static void check_on_arc(cdist_vec3 p, double t, const cdist_arc *a, double tol, const char *what, int id)
{
    bf_arc b = bf_arc_of(a);
    CHECK((double)bf_point_circle(lv_of(p), &b.c) <= tol, "%s case %d: point %.3g off the arc's circle", what, id,
          (double)bf_point_circle(lv_of(p), &b.c));
    if (a->circle.radius == 0) return;
    CHECK(t >= a->start && t <= a->end, "%s case %d: arc param %.17g outside [%.17g, %.17g]", what, id, t, a->start,
          a->end);
    lv e = bf_arc_point(&b, t);
    CHECK((double)lv_norm(lv_sub(e, lv_of(p))) <= tol + 4e-16 * a->circle.radius * fabs(t),
          "%s case %d: arc point at param %.17g is %.3g from the pair point", what, id, t,
          (double)lv_norm(lv_sub(e, lv_of(p))));
}

static void check_result(int kind, int id, cdist_status st, const cdist_result *r, ld ref, double L, double mag,
                         const cdist_arc *a0, const cdist_arc *a1, const cdist_circle *c, const cdist_segment *s)
{
    const char *what = kind_name[kind];
    CHECK(st == CDIST_OK, "%s case %d: status %s: %s", what, id, cdist_status_name(st), cdist_query_last_error(q));
    if (st) return;
    double err = (double)(fabsl((ld)r->distance - ref) / L);
    if (err > worst_err[kind]) {
        worst_err[kind] = err;
        worst_id[kind] = id;
    }
    if (getenv("ARC_DEBUG") && atoi(getenv("ARC_DEBUG")) == id && kind == 0)
        printf("ac %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g  %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n",
               a0->circle.center.x, a0->circle.center.y, a0->circle.center.z, a0->circle.normal.x, a0->circle.normal.y,
               a0->circle.normal.z, a0->circle.radius, a0->zero_direction.x, a0->zero_direction.y, a0->zero_direction.z,
               a0->start, a0->end, c->center.x, c->center.y, c->center.z, c->normal.x, c->normal.y, c->normal.z, c->radius);
    CHECK(err <= 1e-12, "%s case %d: distance %.17g brute force %.20Lg error %.3g of scale %.3g", what, id, r->distance,
          ref, err, L);
    CHECK(r->num_pairs >= 1 && r->num_pairs <= 2, "%s case %d: num_pairs %d", what, id, r->num_pairs);
    double tol = 1e-12 * L + 16 * DBL_EPSILON * mag;
    for (int i = 0; i < r->num_pairs && i < 2; i++) {
        const cdist_pair *p = &r->pairs[i];
        CHECK(fabs(tdist(p->point[0], p->point[1]) - r->distance) <= tol, "%s case %d pair %d does not realise it",
              what, id, i);
        if (kind == 2) {
            lv s0 = lv_of(s->p0), s1 = lv_of(s->p1);
            CHECK((double)bf_point_segment(lv_of(p->point[0]), s0, s1) <= tol && p->param[0] >= 0 && p->param[0] <= 1,
                  "%s case %d: first point off the segment", what, id);
            check_on_arc(p->point[1], p->param[1], a0, tol, what, id);
        } else {
            check_on_arc(p->point[0], p->param[0], a0, tol, what, id);
            if (kind == 1) check_on_arc(p->point[1], p->param[1], a1, tol, what, id);
            if (kind == 0) CHECK((double)ref_point_circle(p->point[1], *c) <= tol, "%s case %d: off circle", what, id);
            if (kind == 3) CHECK((double)ref_point_disk(p->point[1], *c) <= tol, "%s case %d: off disk", what, id);
        }
    }
}

static double scale_of(double ref, double r0, double r1, cdist_vec3 c0, cdist_vec3 c1)
{
    return fmax(fmax(ref, fmax(r0, r1)), tdist(c0, c1));
}

static void run_arc_circle(int id, const cdist_arc *a, const cdist_circle *c)
{
    cdist_result r;
    ld ref = bf_arc_circle(a, c, 0);
    double L = scale_of((double)ref, a->circle.radius, c->radius, a->circle.center, c->center);
    double mag = fmax(maxabs3(a->circle.center), maxabs3(c->center));
    check_result(0, id, cdist_arc_circle(q, a, c, &r), &r, ref, L, mag, a, NULL, c, NULL);
    ref = bf_arc_circle(a, c, 1);
    L = scale_of((double)ref, a->circle.radius, c->radius, a->circle.center, c->center);
    check_result(3, id, cdist_arc_disk(q, a, c, &r), &r, ref, L, mag, a, NULL, c, NULL);
}

static void run_arc_arc(int id, const cdist_arc *a, const cdist_arc *b)
{
    cdist_result r, r2;
    ld ref = bf_arc_arc(a, b);
    double L = scale_of((double)ref, a->circle.radius, b->circle.radius, a->circle.center, b->circle.center);
    double mag = fmax(maxabs3(a->circle.center), maxabs3(b->circle.center));
    check_result(1, id, cdist_arc_arc(q, a, b, &r), &r, ref, L, mag, a, b, NULL, NULL);
    /* f(a, b) and f(b, a) agree. */
    check_result(1, id, cdist_arc_arc(q, b, a, &r2), &r2, ref, L, mag, b, a, NULL, NULL);
    CHECK(fabs(r.distance - r2.distance) <= 4 * DBL_EPSILON * L, "arc-arc case %d: asymmetric %.17g vs %.17g", id,
          r.distance, r2.distance);
}

static void run_seg_arc(int id, const cdist_segment *s, const cdist_arc *a)
{
    cdist_result r;
    ld ref = bf_seg_arc(s, a);
    double L = fmax(fmax((double)ref, a->circle.radius),
                    fmax(tdist(s->p0, a->circle.center), tdist(s->p1, a->circle.center)));
    double mag = fmax(maxabs3(s->p0), fmax(maxabs3(s->p1), maxabs3(a->circle.center)));
    check_result(2, id, cdist_segment_arc(q, s, a, &r), &r, ref, L, mag, a, NULL, NULL, s);
}

static cdist_arc rand_arc(double scale)
{
    cdist_arc a;
    a.circle.center = tv(scale * srand1(), scale * srand1(), scale * srand1());
    a.circle.normal = rand_unit();
    a.circle.radius = scale * (0.1 + 1.4 * urand());
    a.zero_direction = rand_unit();
    a.start = M_PI * srand1();
    double u = urand();
    a.end = a.start + (u < 0.1 ? 2 * M_PI : 2 * M_PI * u);
    return a;
}

static cdist_circle rand_circle(double scale)
{
    cdist_circle c = {tv(scale * srand1(), scale * srand1(), scale * srand1()), rand_unit(), scale * (0.1 + 1.4 * urand())};
    return c;
}

/* p moved into the plane of circle c (long double projection, rounded). */
static cdist_vec3 into_plane(cdist_vec3 p, const cdist_circle *c)
{
    lv n = lv_unit(lv_of(c->normal));
    lv d = lv_sub(lv_of(p), lv_of(c->center));
    lv o = lv_sub(lv_of(p), lv_scale(lv_dot(n, d), n));
    return tv((double)o.x, (double)o.y, (double)o.z);
}

static void random_cases(void)
{
    for (int i = 0; i < (full ? 200 : 40); i++) {
        cdist_arc a = rand_arc(1.0), b = rand_arc(1.0);
        cdist_circle c = rand_circle(1.0);
        cdist_segment s = {tv(2 * srand1(), 2 * srand1(), 2 * srand1()), tv(2 * srand1(), 2 * srand1(), 2 * srand1())};
        if (i % 4 == 1) { /* coplanar objects: crossings, tangencies, two symmetric minima */
            c.normal = a.circle.normal;
            c.center = into_plane(c.center, &a.circle);
            b.circle.normal = a.circle.normal;
            b.circle.center = into_plane(b.circle.center, &a.circle);
            s.p0 = into_plane(s.p0, &a.circle);
            s.p1 = into_plane(s.p1, &a.circle);
        }
        if (i % 4 == 2) { /* parallel planes */
            c.normal = a.circle.normal;
            b.circle.normal = a.circle.normal;
        }
        if (i % 10 == 3) { /* points: zero radii, zero-length arcs and segments */
            c.radius = 0;
            b.circle.radius = 0;
            s.p1 = s.p0;
            a.end = a.start;
        }
        if (i % 10 == 7) { /* a zero-radius arc against everything */
            a.circle.radius = 0;
        }
        run_arc_circle(i, &a, &c);
        run_arc_arc(i, &a, &b);
        run_seg_arc(i, &s, &a);
    }
}

/* Arcs of circles from a configuration with known full-circle structure, transformed by a
 * random rotation, scale and translation. */
static cdist_arc xarc(const trot *R, double sc, cdist_vec3 t, cdist_circle c, cdist_vec3 zd, double a0, double a1)
{
    cdist_arc a = {xform_circle(R, sc, t, c), rot_apply(R, zd), a0, a1};
    return a;
}

static void constructed_cases(void)
{
    int id = 1000;
    NS = 16384;
    cdist_result r;
    for (int rep = 0; rep < (full ? 12 : 3); rep++) {
        trot R = rand_rotation();
        double sc = rep < 4 ? 1.0 : (rep < 8 ? 1e-3 + urand() * 10 : 100.0 * urand());
        cdist_vec3 t = rep % 3 == 2 ? tv(1e4 * srand1(), 1e4 * srand1(), 1e4 * srand1()) : tv(srand1(), srand1(), srand1());
        cdist_circle unit = {tv(0, 0, 0), tv(0, 0, 1), 1.0};
        cdist_vec3 ex = tv(1, 0, 0);
        /* Coplanar circle to the +x side: an arc on the far side has its closest points at the
         * two symmetric endpoints (two pairs). */
        cdist_circle side = xform_circle(&R, sc, t, (cdist_circle){tv(3, 0, 0), tv(0, 0, 1), 1.0});
        cdist_arc far = xarc(&R, sc, t, unit, ex, M_PI / 2, 3 * M_PI / 2);
        run_arc_circle(id++, &far, &side);
        /* (Far from the origin the rounding of the moved inputs breaks the symmetry itself.) */
        int symmetric = rep % 3 != 2;
        CHECK(cdist_arc_circle(q, &far, &side, &r) == CDIST_OK && (r.num_pairs == 2 || !symmetric),
              "rep %d: symmetric endpoints: %d pairs", rep, r.num_pairs);
        if (r.num_pairs == 2) {
            double p0 = r.pairs[0].param[0], p1 = r.pairs[1].param[0];
            CHECK((fabs(p0 - M_PI / 2) < 1e-9 && fabs(p1 - 3 * M_PI / 2) < 1e-9) ||
                      (fabs(p1 - M_PI / 2) < 1e-9 && fabs(p0 - 3 * M_PI / 2) < 1e-9),
                  "endpoint params %.17g %.17g", p0, p1);
        }
        /* Same side circle above the plane, tilted: the full-circle closest pair at angle 0 is cut
         * out of the arc [0.4, 2 pi - 0.3]: the answer is an endpoint. */
        cdist_circle tilted = xform_circle(&R, sc, t, (cdist_circle){tv(2.2, 0.3, 0.7), tv(0.6, 0, 0.8), 0.9});
        cdist_arc cut = xarc(&R, sc, t, unit, ex, 0.4, 2 * M_PI - 0.3);
        run_arc_circle(id++, &cut, &tilted);
        CHECK(cdist_arc_circle(q, &cut, &tilted, &r) == CDIST_OK &&
                  (r.pairs[0].param[0] == 0.4 || r.pairs[0].param[0] == 2 * M_PI - 0.3),
              "cut arc: endpoint expected, param %.17g", r.pairs[0].param[0]);
        /* Linked circles (distance 0 on the full circles) with the crossing cut out. */
        cdist_circle linked = xform_circle(&R, sc, t, (cdist_circle){tv(1, 0, 0), tv(0, 1, 0), 1.0});
        cdist_arc nolink = xarc(&R, sc, t, unit, ex, 0.5, 2 * M_PI - 0.5);
        run_arc_circle(id++, &nolink, &linked);
        cdist_arc link_arc = xarc(&R, sc, t, (cdist_circle){tv(1, 0, 0), tv(0, 1, 0), 1.0}, tv(0, 0, 1), -1.0, 1.0);
        run_arc_arc(id++, &nolink, &link_arc);
        run_arc_arc(id++, &cut, &link_arc);
        /* Concentric coplanar arcs: equidistant where the ranges overlap, else endpoints. */
        cdist_arc big = xarc(&R, sc, t, (cdist_circle){tv(0, 0, 0), tv(0, 0, 1), 2.0}, ex, 0.0, 1.0);
        cdist_arc small1 = xarc(&R, sc, t, unit, ex, 0.5, 2.0);
        cdist_arc small2 = xarc(&R, sc, t, unit, ex, 2.0, 3.0);
        run_arc_arc(id++, &big, &small1);
        CHECK(cdist_arc_arc(q, &big, &small1, &r) == CDIST_OK && r.equidistant, "concentric overlap equidistant");
        run_arc_arc(id++, &big, &small2);
        CHECK(cdist_arc_arc(q, &big, &small2, &r) == CDIST_OK && !r.equidistant && r.num_pairs == 1,
              "concentric disjoint ranges: one endpoint pair (eq %d, pairs %d)", r.equidistant, r.num_pairs);
        /* Coaxial circle: every arc point equidistant. */
        cdist_circle coax = xform_circle(&R, sc, t, (cdist_circle){tv(0, 0, 0.5), tv(0, 0, 1), 1.5});
        run_arc_circle(id++, &small1, &coax);
        CHECK(cdist_arc_circle(q, &small1, &coax, &r) == CDIST_OK && (r.equidistant || !symmetric),
              "rep %d: coaxial equidistant", rep);
        /* Full and zero-length arcs. */
        cdist_arc full = xarc(&R, sc, t, unit, tv(0.3, 0.4, 0.2), -M_PI, M_PI);
        run_arc_circle(id++, &full, &tilted);
        run_arc_circle(id++, &full, &linked);
        cdist_arc dot = xarc(&R, sc, t, unit, ex, 1.0, 1.0);
        run_arc_circle(id++, &dot, &tilted);
        run_arc_arc(id++, &dot, &cut);
        /* Disk: the arc dips through the disk; arc over the disk face; arc beside the rim. */
        cdist_circle disk = xform_circle(&R, sc, t, (cdist_circle){tv(0, 0, 0), tv(0, 0, 1), 1.5});
        cdist_arc dip = xarc(&R, sc, t, (cdist_circle){tv(0.3, 0, 0.5), tv(0, 1, 0), 0.8}, ex, -1.0, 5.0);
        cdist_arc above = xarc(&R, sc, t, (cdist_circle){tv(0.3, 0, 0.5), tv(0, 1, 0), 0.8}, ex, -2.5, -0.7);
        cdist_arc rim = xarc(&R, sc, t, (cdist_circle){tv(2.5, 0, 0.2), tv(0, 1, 0), 0.6}, ex, 0.0, 6.0);
        run_arc_circle(id++, &dip, &disk);
        run_arc_circle(id++, &above, &disk);
        run_arc_circle(id++, &rim, &disk);
        /* Segments: along the axis (equidistant), through the arc's gap, crossing the arc,
         * long and nearly tangent. */
        cdist_segment axis = {xform_point(&R, sc, t, tv(0, 0, -1)), xform_point(&R, sc, t, tv(0, 0, 2))};
        run_seg_arc(id++, &axis, &small1);
        CHECK(cdist_segment_arc(q, &axis, &small1, &r) == CDIST_OK && (r.equidistant || !symmetric),
              "rep %d: axis segment equidistant", rep);
        cdist_segment gap = {xform_point(&R, sc, t, tv(2, -0.2, 0)), xform_point(&R, sc, t, tv(-2, 0.1, 0.05))};
        run_seg_arc(id++, &gap, &cut);
        run_seg_arc(id++, &gap, &small2);
        cdist_segment across = {xform_point(&R, sc, t, tv(-2, 1.2, 0)), xform_point(&R, sc, t, tv(2, 0.5, 0))};
        run_seg_arc(id++, &across, &small1);
        cdist_segment tang = {xform_point(&R, sc, t, tv(-100, 1.0 + 1e-9, 1e-7)), xform_point(&R, sc, t, tv(100, 1.0 + 1e-9, 1e-7))};
        run_seg_arc(id++, &tang, &full);
        run_seg_arc(id++, &tang, &small1);
    }
}

/* Exactly representable degenerate configurations with known answers. */
static void exact_cases(void)
{
    cdist_result r;
    cdist_arc full = {{tv(0, 0, 0), tv(0, 0, 1), 1}, tv(1, 0, 0), -M_PI, M_PI};
    /* A circle through the arc circle's centre, linked: every arc point is at distance 1. */
    cdist_circle linked = {tv(1, 0, 0), tv(0, 1, 0), 1};
    CHECK(cdist_arc_circle(q, &full, &linked, &r) == CDIST_OK && fabs(r.distance - 1) <= 4e-16 && r.equidistant,
          "linked constant distance: %.17g eq %d", r.distance, r.equidistant);
    cdist_arc part = full;
    part.start = 0.5;
    part.end = 2.0;
    CHECK(cdist_arc_circle(q, &part, &linked, &r) == CDIST_OK && fabs(r.distance - 1) <= 4e-16 && r.equidistant,
          "linked constant distance, part: %.17g eq %d", r.distance, r.equidistant);
    /* Arc parallel to a disk above its face: distance 2, a continuum. */
    cdist_arc high = {{tv(0.2, 0, 2), tv(0, 0, 1), 0.5}, tv(0, 1, 0), 0, 1};
    cdist_circle disk = {tv(0, 0, 0), tv(0, 0, -1), 1};
    CHECK(cdist_arc_disk(q, &high, &disk, &r) == CDIST_OK && r.distance == 2 && r.equidistant,
          "arc over the disk face: %.17g eq %d", r.distance, r.equidistant);
    /* Arc in the disk's plane, inside: distance 0, a continuum. */
    cdist_arc in = {{tv(0.2, 0, 0), tv(0, 0, 1), 0.5}, tv(0, 1, 0), 0, 1};
    CHECK(cdist_arc_disk(q, &in, &disk, &r) == CDIST_OK && r.distance == 0 && r.equidistant,
          "arc in the disk: %.17g eq %d", r.distance, r.equidistant);
    /* Arc crossing the disk's plane once inside the disk: distance 0 at one point. */
    /* (V = N x U = -z here: z = 0.5 - 0.8 sin a, crossing at sin a = 0.625, x = 0.925.) */
    cdist_arc cross = {{tv(0.3, 0, 0.5), tv(0, 1, 0), 0.8}, tv(1, 0, 0), 0, 1.5};
    CHECK(cdist_arc_disk(q, &cross, &disk, &r) == CDIST_OK && r.distance <= 2e-16 && !r.equidistant &&
              r.num_pairs == 1 && fabs(r.pairs[0].param[0] - asin(0.625)) < 1e-15,
          "arc crossing the disk: %.17g eq %d pairs %d", r.distance, r.equidistant, r.num_pairs);
    cross.end = 2.5; /* both crossings: two pairs */
    CHECK(cdist_arc_disk(q, &cross, &disk, &r) == CDIST_OK && r.distance <= 2e-16 && r.num_pairs == 2,
          "arc crossing the disk twice: %.17g pairs %d", r.distance, r.num_pairs);
    /* Arc beside the disk, coplanar: the rim distance 1 at angle pi. */
    cdist_arc beside = {{tv(3, 0, 0), tv(0, 0, 1), 1}, tv(1, 0, 0), 1, 5};
    CHECK(cdist_arc_disk(q, &beside, &disk, &r) == CDIST_OK && fabs(r.distance - 1) <= 4e-16 &&
              fabs(r.pairs[0].param[0] - M_PI) < 1e-8,
          "arc beside the disk: %.17g at %.17g", r.distance, r.pairs[0].param[0]);
    /* Two arcs of one circle with disjoint ranges: the gap's endpoints, two pairs when the gaps
     * are equal (angles 1..2 and 3..5 of the unit circle: gaps 1 and 2 - pi + ... ). */
    cdist_arc a1 = {{tv(0, 0, 0), tv(0, 0, 1), 1}, tv(1, 0, 0), 0, 1};
    cdist_arc a2 = {{tv(0, 0, 0), tv(0, 0, 1), 1}, tv(1, 0, 0), 2, 2 * M_PI - 1};
    CHECK(cdist_arc_arc(q, &a1, &a2, &r) == CDIST_OK && fabs(r.distance - 2 * sin(0.5)) <= 1e-15 &&
              r.num_pairs == 2 && !r.equidistant,
          "gaps of one circle: %.17g pairs %d", r.distance, r.num_pairs);
    /* The same arcs overlapping: distance 0, a continuum. */
    cdist_arc a3 = a2;
    a3.start = 0.5;
    CHECK(cdist_arc_arc(q, &a1, &a3, &r) == CDIST_OK && r.distance == 0 && r.equidistant, "overlap: %.17g eq %d",
          r.distance, r.equidistant);
    /* Segment along a chord of the arc's circle, arc covering one crossing only. */
    cdist_segment chord = {tv(-2, 0.5, 0), tv(2, 0.5, 0)};
    cdist_arc left = {{tv(0, 0, 0), tv(0, 0, 1), 1}, tv(-1, 0, 0), -1, 1};
    CHECK(cdist_segment_arc(q, &chord, &left, &r) == CDIST_OK && r.distance <= 4e-16 && r.num_pairs == 1 &&
              fabs(r.pairs[0].point[0].x + sqrt(0.75)) < 1e-15,
          "chord, one crossing: %.17g pairs %d", r.distance, r.num_pairs);
}

/* Scaling every length by 2^k (exact in binary) scales the distance by 2^k: extreme scales
 * (2^-300, 2^300, near the 1e150 limit) keep the accuracy (nothing overflows or underflows). */
static cdist_vec3 sv(cdist_vec3 v, double f) { return tv(v.x * f, v.y * f, v.z * f); }
static cdist_arc sarc(cdist_arc a, double f)
{
    a.circle.center = sv(a.circle.center, f);
    a.circle.radius *= f;
    return a;
}

static void scale_invariance(void)
{
    const double fs[3] = {ldexp(1, -300), ldexp(1, 300), ldexp(1, 480)};
    for (int i = 0; i < (full ? 40 : 8); i++) {
        cdist_arc a = rand_arc(1.0), b = rand_arc(1.0);
        cdist_circle c = rand_circle(1.0);
        cdist_segment s = {tv(2 * srand1(), 2 * srand1(), 2 * srand1()), tv(2 * srand1(), 2 * srand1(), 2 * srand1())};
        cdist_result r0[4], r;
        CHECK(cdist_arc_circle(q, &a, &c, &r0[0]) == CDIST_OK && cdist_arc_arc(q, &a, &b, &r0[1]) == CDIST_OK &&
                  cdist_segment_arc(q, &s, &a, &r0[2]) == CDIST_OK && cdist_arc_disk(q, &a, &c, &r0[3]) == CDIST_OK,
              "scale case %d", i);
        for (int k = 0; k < 3; k++) {
            double f = fs[k];
            cdist_arc as = sarc(a, f), bs = sarc(b, f);
            cdist_circle cs = {sv(c.center, f), c.normal, c.radius * f};
            cdist_segment ss = {sv(s.p0, f), sv(s.p1, f)};
            double L = 3.0;
            for (int kind = 0; kind < 4; kind++) {
                cdist_status st = kind == 0   ? cdist_arc_circle(q, &as, &cs, &r)
                                  : kind == 1 ? cdist_arc_arc(q, &as, &bs, &r)
                                  : kind == 2 ? cdist_segment_arc(q, &ss, &as, &r)
                                              : cdist_arc_disk(q, &as, &cs, &r);
                CHECK(st == CDIST_OK && fabs(r.distance / f - r0[kind].distance) <= 1e-14 * L,
                      "%s scale 2^%d case %d: %.17g vs %.17g (%s)", kind_name[kind], ilogb(f), i, r.distance / f,
                      r0[kind].distance, cdist_query_last_error(q));
            }
        }
    }
}

/* Arcs on coaxial circles: the distance between the circles is constant, so where the ranges
 * share an azimuth the answer is that constant (closed form: 0 on the same circle, |r1 - r0|
 * for concentric coplanar circles, hypot(h, r1 - r0) at axial offset h), flagged as a
 * continuum when they share an interval; else the nearest ends (long double reference). The
 * sampled scan answered these with rounding noise (3e-20 to 3e-16 on the same circle). */
static void coaxial_arcs(void)
{
    for (int i = 0; i < 400; i++) {
        cdist_vec3 n = rand_unit(), z = rand_unit(), c = tv(10 * srand1(), 10 * srand1(), 10 * srand1());
        double r0 = 0.1 + 2 * urand(), h = 0.0, r1 = r0;
        if (i % 3 == 1) r1 = 0.1 + 2 * urand();
        if (i % 3 == 2) h = srand1(), r1 = 0.1 + 2 * urand();
        cdist_vec3 c1 = tv(c.x + h * n.x, c.y + h * n.y, c.z + h * n.z);
        double sg = i % 2 ? -1.0 : 1.0;
        cdist_vec3 z1 = i % 4 < 2 ? z : rand_unit();
        double s0 = 4 * srand1(), s1 = 4 * srand1();
        cdist_arc a = {{c, n, r0}, z, s0, s0 + 2 * M_PI * urand()};
        cdist_arc b = {{c1, tv(sg * n.x, sg * n.y, sg * n.z), r1}, z1, s1, s1 + 2 * M_PI * urand()};
        if (i % 5 == 0) b.end = b.start;
        bf_arc A = bf_arc_of(&a), B = bf_arc_of(&b);
        /* shared azimuth: B's point at angle phi is at A's angle of the same direction */
        int shared = 0, interval = 0;
        ld best = INFINITY;
        for (int k = 0; k <= 4000; k++) {
            ld phi = B.a0 + (B.a1 - B.a0) * k / 4000;
            lv d = lv_sub(bf_arc_point(&B, phi), B.c.c);
            lv in = lv_sub(d, lv_scale(lv_dot(d, A.c.n), A.c.n));
            ld ang = atan2l(lv_dot(A.v, in), lv_dot(A.u, in));
            ld kk = fmodl(ang - A.a0, 2 * 3.14159265358979323846264338327950288L);
            if (kk < 0) kk += 2 * 3.14159265358979323846264338327950288L;
            if (A.a0 + kk <= A.a1 + 1e-12L) shared++;
        }
        interval = shared > 2 && b.end > b.start;
        ld cst = sqrtl((ld)h * h + ((ld)r1 - r0) * ((ld)r1 - r0));
        for (int e = 0; e < 2; e++) {
            best = fminl(best, bf_point_arc(bf_arc_point(&A, e ? A.a1 : A.a0), &B));
            best = fminl(best, bf_point_arc(bf_arc_point(&B, e ? B.a1 : B.a0), &A));
        }
        if (shared) best = fminl(best, cst);
        cdist_result r;
        CHECK(cdist_arc_arc(q, &a, &b, &r) == CDIST_OK, "coaxial %d: %s", i, cdist_query_last_error(q));
        double L = fmax(fmax(r0, r1), fmax(fabs(h), 1.0));
        CHECK(fabsl((ld)r.distance - best) <= 1e-13 * L, "coaxial %d: %.17g vs %.20Lg", i, r.distance, best);
        if (shared && i % 3 == 0 && sg > 0 && i % 4 < 2)
            CHECK(r.distance == 0.0, "same circle %d: distance %.3g, not exactly 0", i, r.distance);
        if (interval && r.distance <= (double)cst + 1e-13 * L)
            CHECK(r.equidistant, "coaxial %d: shared interval not flagged as a continuum", i);
    }
}

/* The span rule end <= RU(start + RU(2 pi)), with the upper bound computed here under the
 * upward rounding mode: every end up to it is accepted (in particular start + 2 * M_PI in
 * double), the next double is refused, at any |start|. */
static void span_rule(void)
{
    cdist_result r;
    cdist_circle c = {tv(3, 0, 0), tv(0, 0, 1), 1};
    const double two_pi_up = nextafter(2 * M_PI, INFINITY);
    double starts[] = {0.0, -M_PI, 1.0, 100.5, -3e3, 1e6 + 0.3, -7.7e12, 1e17, -1e17, 0x1p60};
    /* The bound is found by rounding upward; where rounding modes are ignored (valgrind) only
     * the plain 2 pi span is checked. */
    volatile double one = 1.0, tiny = 0x1p-60, probe;
    fesetround(FE_UPWARD);
    probe = one + tiny;
    fesetround(FE_TONEAREST);
    int rounding = probe > 1.0;
    if (!rounding) printf("rounding modes are ignored here (valgrind?): the span's rounded-up bound is not checked\n");
    srand(77);
    for (int i = 0; i < 2000; i++) {
        double st = i < (int)(sizeof starts / sizeof starts[0])
                        ? starts[i]
                        : ldexp((double)rand() / RAND_MAX - 0.5, rand() % 130 - 20);
        volatile double sum = 0;
        fesetround(FE_UPWARD);
        sum = st + two_pi_up;
        fesetround(FE_TONEAREST);
        double up = sum;
        cdist_arc a = {{tv(0, 0, 0), tv(0, 0, 1), 1}, tv(1, 0, 0), st, st + 2 * M_PI};
        CHECK(cdist_arc_circle(q, &a, &c, &r) == CDIST_OK, "start %.17g, end = start + 2 pi in double accepted", st);
        if (!rounding) continue;
        a.end = up;
        CHECK(cdist_arc_circle(q, &a, &c, &r) == CDIST_OK, "start %.17g, end at the rounded-up bound accepted", st);
        a.end = nextafter(up, INFINITY);
        CHECK(cdist_arc_circle(q, &a, &c, &r) == CDIST_ERR_BAD_INTERVAL && r.num_pairs == 0,
              "start %.17g, end one double past the bound refused", st);
    }
    /* The reported case: 64 past a start of 1e17 was answered as a full circle. */
    cdist_arc big = {{tv(0, 0, 0), tv(0, 0, 1), 1}, tv(1, 0, 0), 1e17, 1e17 + 64};
    CHECK(cdist_arc_circle(q, &big, &c, &r) == CDIST_ERR_BAD_INTERVAL, "start 1e17, end 1e17 + 64 refused");
    CHECK(cdist_arc_arc(q, &big, &big, &r) == CDIST_ERR_BAD_INTERVAL, "arc-arc: start 1e17, end 1e17 + 64 refused");
}

static void bad_input(void)
{
    cdist_result r;
    cdist_arc a = {{tv(0, 0, 0), tv(0, 0, 1), 1}, tv(1, 0, 0), 0, 1};
    cdist_circle c = {tv(3, 0, 0), tv(0, 0, 1), 1};
    cdist_segment s = {tv(0, 0, 0), tv(1, 1, 1)};
    CHECK(cdist_arc_circle(NULL, &a, &c, &r) == CDIST_ERR_NULL_ARGUMENT, "NULL handle");
    CHECK(cdist_arc_circle(q, NULL, &c, &r) == CDIST_ERR_NULL_ARGUMENT && isnan(r.distance), "NULL arc");
    CHECK(cdist_arc_circle(q, &a, NULL, &r) == CDIST_ERR_NULL_ARGUMENT, "NULL circle");
    CHECK(cdist_arc_circle(q, &a, &c, NULL) == CDIST_ERR_NULL_ARGUMENT, "NULL result");
    CHECK(cdist_arc_arc(q, &a, NULL, &r) == CDIST_ERR_NULL_ARGUMENT, "NULL arc 2");
    CHECK(cdist_segment_arc(q, NULL, &a, &r) == CDIST_ERR_NULL_ARGUMENT, "NULL segment");
    CHECK(cdist_arc_disk(q, NULL, &c, &r) == CDIST_ERR_NULL_ARGUMENT, "NULL arc disk");
    cdist_arc b = a;
    b.start = 2;
    CHECK(cdist_arc_circle(q, &b, &c, &r) == CDIST_ERR_BAD_INTERVAL && r.num_pairs == 0, "reversed arc");
    b = a;
    b.end = 7;
    CHECK(cdist_arc_arc(q, &a, &b, &r) == CDIST_ERR_BAD_INTERVAL, "arc longer than 2 pi");
    b = a;
    b.start = NAN;
    CHECK(cdist_segment_arc(q, &s, &b, &r) == CDIST_ERR_NOT_FINITE && isnan(r.distance), "NaN angle");
    b = a;
    b.end = INFINITY;
    CHECK(cdist_arc_disk(q, &b, &c, &r) == CDIST_ERR_NOT_FINITE, "infinite angle");
    b = a;
    b.zero_direction = tv(0, 0, 2);
    CHECK(cdist_arc_circle(q, &b, &c, &r) == CDIST_ERR_ZERO_VECTOR, "zero_direction along the normal");
    b.zero_direction = tv(0, 0, 0);
    CHECK(cdist_arc_circle(q, &b, &c, &r) == CDIST_ERR_ZERO_VECTOR, "zero zero_direction");
    b.zero_direction = tv(NAN, 0, 0);
    CHECK(cdist_arc_circle(q, &b, &c, &r) == CDIST_ERR_NOT_FINITE, "NaN zero_direction");
    b = a;
    b.circle.radius = -1;
    CHECK(cdist_arc_circle(q, &b, &c, &r) == CDIST_ERR_NEGATIVE_RADIUS, "negative radius");
    b = a;
    b.circle.normal = tv(0, 0, 2);
    CHECK(cdist_arc_circle(q, &b, &c, &r) == CDIST_ERR_NOT_UNIT, "non-unit normal");
    s.p1.y = NAN;
    CHECK(cdist_segment_arc(q, &s, &a, &r) == CDIST_ERR_NOT_FINITE, "NaN segment");
    /* zero_direction need not be unit nor in the plane. */
    b = a;
    b.zero_direction = tv(5, 0, 3);
    CHECK(cdist_arc_circle(q, &b, &c, &r) == CDIST_OK && fabs(r.distance - 1) < 1e-15 && r.pairs[0].param[0] == 0,
          "zero_direction projected: %.17g %.17g", r.distance, r.pairs[0].param[0]);
    /* Angles beyond (-pi, pi]: the arc's own range is kept. */
    b = a;
    b.zero_direction = tv(0, 1, 0);
    b.start = 3.0;
    b.end = 3.0 + 2 * M_PI;
    CHECK(cdist_arc_circle(q, &b, &c, &r) == CDIST_OK && fabs(r.distance - 1) < 1e-15, "shifted range");
    CHECK(r.pairs[0].param[0] >= b.start && r.pairs[0].param[0] <= b.end &&
              fabs(r.pairs[0].param[0] - (3 * M_PI / 2)) < 1e-12,
          "param in the arc's own range: %.17g", r.pairs[0].param[0]);
}

int main(int argc, char **argv)
{
    full = !(argc > 1 && !strcmp(argv[1], "--short"));
    q = cdist_query_new();
    random_cases();
    constructed_cases();
    exact_cases();
    scale_invariance();
    bad_input();
    span_rule();
    coaxial_arcs();
    for (int k = 0; k < 4; k++) printf("%s: max error %.3g of scale (case %d)\n", kind_name[k], worst_err[k], worst_id[k]);
    cdist_query_free(q);
    return check_summary("arc");
}
