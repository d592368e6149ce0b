/* SPDX-License-Identifier: MIT */
/* Callback curves, helices and cubic Bezier curves to circles and disks.
 *  - A segment passed as a callback curve reproduces the shared line-circle and line-disk
 *    reference distances (a window of the line that contains every critical point, see below)
 *    and the long double brute force of brute.h on random segments.
 *  - Helix and Bezier queries against the brute force.
 *  - Callback failures, non-finite callback values and bad input give the documented status
 *    and an error result; nothing crashes. */
#include <float.h>
#include <string.h>

#include "brute.h"
#include "ref_lines.h"
#include "query_io.h"

static cdist_query *q;
static double worst[6];
static const char *names[6] = {"segment-curve/circle", "segment-curve/disk", "helix/circle", "helix/disk",
                               "bezier/circle", "bezier/disk"};

/* ---- the segment as a callback curve ---- */

typedef struct seg_curve {
    cdist_vec3 p0, m;
    int calls;
} seg_curve;

static int seg_fn(void *user, double t, cdist_vec3 *p, cdist_vec3 *d)
{
    seg_curve *s = user;
    s->calls++;
    *p = tv(s->p0.x + t * s->m.x, s->p0.y + t * s->m.y, s->p0.z + t * s->m.z);
    *d = s->m;
    return 0;
}

typedef struct bf_seg_ctx {
    lv p0, m;
    bf_circle c;
    int disk;
} bf_seg_ctx;

static ld f_seg(const void *p, ld s)
{
    const bf_seg_ctx *x = p;
    lv pt = lv_add(x->p0, lv_scale(s, x->m));
    return x->disk ? bf_point_disk(pt, &x->c) : bf_point_circle(pt, &x->c);
}

static void check_pairs(const cdist_result *r, const cdist_circle *c, int disk, double tol, const char *what, long id)
{
    for (int i = 0; i < r->num_pairs; i++) {
        CHECK(fabs(tdist(r->pairs[i].point[0], r->pairs[i].point[1]) - r->distance) <= tol,
              "%s %ld: pair %d does not realise the distance", what, id, i);
        double on = (double)(disk ? ref_point_disk(r->pairs[i].point[1], *c) : ref_point_circle(r->pairs[i].point[1], *c));
        CHECK(on <= tol, "%s %ld: pair %d second point %.3g off", what, id, i, on);
    }
}

/* Lines of the shared lc/ld files as segments: every critical point of the line's distance lies
 * within r of the foot of the perpendicular from the centre (|Delta.M| <= r at a critical point;
 * for the disk also the plane crossing inside the disk, |P - C| <= r), so the segment
 * [foot - r - 1, foot + r + 1] has the line's distance. */
static void shared_lines(const char *qpath, const char *epath, int disk)
{
    FILE *fq = fopen(qpath, "r"), *fe = fopen(epath, "r");
    CHECK(fq && fe, "open %s", qpath);
    if (!fq || !fe) return;
    long lineno = 0;
    cdq_line ql;
    long double e;
    while (ref_next(fq, fe, &ql, &e, &lineno)) {
        double L = cdq_scale(&ql, (double)e);
        const double *v = ql.v;
        cdist_vec3 B = tv(v[0], v[1], v[2]), M = tv(v[3], v[4], v[5]);
        cdist_circle c = {tv(v[6], v[7], v[8]), tv(v[9], v[10], v[11]), v[12]};
        double mm = M.x * M.x + M.y * M.y + M.z * M.z;
        double foot = ((c.center.x - B.x) * M.x + (c.center.y - B.y) * M.y + (c.center.z - B.z) * M.z) / mm;
        double half = (c.radius + L) / sqrt(mm);
        seg_curve s = {B, M, 0};
        cdist_result r;
        cdist_status st = (disk ? cdist_curve_disk : cdist_curve_circle)(q, seg_fn, &s, foot - half, foot + half, &c, &r);
        CHECK(st == CDIST_OK, "line %ld: %s", lineno, cdist_query_last_error(q));
        if (st) continue;
        double mag = 0;
        for (int i = 0; i < ql.nvalues; i++) mag = fmax(mag, fabs(v[i]));
        /* The callback's positions are doubles: about one ulp of the coordinates (and of the
         * parameter times |M|) of rounding that no method can remove. */
        double floor_ = 2.0 * DBL_EPSILON * (mag + fabs(foot) * sqrt(mm) + half * sqrt(mm)) / L;
        double er = (double)(fabsl((long double)r.distance - e) / L);
        if (er > worst[disk]) worst[disk] = er;
        CHECK(er <= 1e-12 + floor_, "%s line %ld: %.17g vs %.21Lg error %.3g of scale (floor %.3g)", qpath, lineno,
              r.distance, e, er, floor_);
        check_pairs(&r, &c, disk, 1e-12 * L + 16 * DBL_EPSILON * (mag + half * sqrt(mm)), qpath, lineno);
    }
    fclose(fq);
    fclose(fe);
}

static void random_segments(void)
{
    for (int i = 0; i < 400; i++) {
        int disk = i & 1;
        cdist_circle c = {tv(srand1(), srand1(), srand1()), rand_unit(), 0.1 + 1.4 * urand()};
        cdist_vec3 a = tv(2 * srand1(), 2 * srand1(), 2 * srand1()), b = tv(2 * srand1(), 2 * srand1(), 2 * srand1());
        if (i % 17 == 5) c.radius = 0;
        if (i % 19 == 8) b = a;
        if (i % 10 == 3) { /* in the circle's plane, crossing it */
            double h = (a.x - c.center.x) * c.normal.x + (a.y - c.center.y) * c.normal.y + (a.z - c.center.z) * c.normal.z;
            a = tv(a.x - h * c.normal.x, a.y - h * c.normal.y, a.z - h * c.normal.z);
            h = (b.x - c.center.x) * c.normal.x + (b.y - c.center.y) * c.normal.y + (b.z - c.center.z) * c.normal.z;
            b = tv(b.x - h * c.normal.x, b.y - h * c.normal.y, b.z - h * c.normal.z);
        }
        seg_curve s = {a, tv(b.x - a.x, b.y - a.y, b.z - a.z), 0};
        bf_seg_ctx x = {lv_of(a), lv_of(s.m), bf_circ(c), disk};
        ld ref = bf_min1d(f_seg, &x, 0, 1, 8192);
        cdist_result r;
        cdist_status st = (disk ? cdist_curve_disk : cdist_curve_circle)(q, seg_fn, &s, 0.0, 1.0, &c, &r);
        CHECK(st == CDIST_OK, "random segment %d: %s", i, cdist_query_last_error(q));
        double L = fmax(c.radius, fmax(tdist(a, c.center), tdist(b, c.center)));
        double er = (double)(fabsl((ld)r.distance - ref) / L);
        if (er > worst[disk]) worst[disk] = er;
        CHECK(er <= 1e-12, "random segment %d (%s): %.17g vs %.20Lg error %.3g", i, disk ? "disk" : "circle",
              r.distance, ref, er);
        check_pairs(&r, &c, disk, 1e-12 * L, "random segment", i);
        for (int k = 0; k < r.num_pairs; k++)
            CHECK(r.pairs[k].param[0] >= 0 && r.pairs[k].param[0] <= 1 &&
                      tdist(r.pairs[k].point[0], tv(a.x + r.pairs[k].param[0] * s.m.x, a.y + r.pairs[k].param[0] * s.m.y,
                                                    a.z + r.pairs[k].param[0] * s.m.z)) <= 1e-15 * L,
                  "random segment %d: param[0] is the curve parameter", i);
    }
}

static void degenerate_segments(void)
{
    cdist_result r;
    cdist_circle c = {tv(1, 2, 3), tv(0, 0, 1), 2};
    /* Along the axis through the centre: distance r, every circle point closest. */
    seg_curve s = {tv(1, 2, -1), tv(0, 0, 6), 0};
    CHECK(cdist_curve_circle(q, seg_fn, &s, 0, 1, &c, &r) == CDIST_OK && r.distance == 2 && r.equidistant,
          "axis segment: %.17g eq %d", r.distance, r.equidistant);
    /* Parallel to a disk, above its face: distance 3, a continuum. */
    seg_curve over = {tv(0, 2, 6), tv(2, 0.5, 0), 0};
    CHECK(cdist_curve_disk(q, seg_fn, &over, 0, 1, &c, &r) == CDIST_OK && fabs(r.distance - 3) < 1e-15 && r.equidistant,
          "segment over the disk face: %.17g eq %d", r.distance, r.equidistant);
    /* Through the circle's plane, symmetric chord crossing the circle twice: two pairs at 0. */
    seg_curve chord = {tv(-3, 2, 3), tv(8, 0, 0), 0};
    CHECK(cdist_curve_circle(q, seg_fn, &chord, 0, 1, &c, &r) == CDIST_OK && r.distance < 1e-15 && r.num_pairs == 2,
          "chord: %.17g pairs %d", r.distance, r.num_pairs);
    /* Tangent to the circle: distance 0 at one point. */
    seg_curve tang = {tv(-3, 4, 3), tv(8, 0, 0), 0};
    CHECK(cdist_curve_circle(q, seg_fn, &tang, 0, 1, &c, &r) == CDIST_OK && r.distance < 1e-15 && r.num_pairs == 1 &&
              fabs(r.pairs[0].param[0] - 0.5) < 1e-7,
          "tangent: %.17g pairs %d s %.17g", r.distance, r.num_pairs, r.pairs[0].param[0]);
    /* t0 == t1: a single point. */
    CHECK(cdist_curve_circle(q, seg_fn, &tang, 0.5, 0.5, &c, &r) == CDIST_OK && r.distance == 0 &&
              r.pairs[0].param[0] == 0.5,
          "point curve: %.17g", r.distance);
    /* Few and many samples. */
    CHECK(cdist_query_set_curve_samples(q, 7) == CDIST_ERR_BAD_OPTION, "7 samples refused");
    CHECK(cdist_query_set_curve_samples(q, 8) == CDIST_OK, "8 samples");
    CHECK(cdist_curve_circle(q, seg_fn, &chord, 0, 1, &c, &r) == CDIST_OK && r.distance < 1e-15, "8 samples answer");
    CHECK(cdist_query_set_curve_samples(q, 100000) == CDIST_OK && cdist_query_get_curve_samples(q) == 100000,
          "100000 samples");
    CHECK(cdist_curve_circle(q, seg_fn, &chord, 0, 1, &c, &r) == CDIST_OK && r.distance < 1e-15, "many samples answer");
    CHECK(cdist_query_set_curve_samples(q, 512) == CDIST_OK, "back to 512");
}

/* ---- callback failures and bad input ---- */

typedef struct bad_curve {
    int mode; /* 0 fail, 1 NaN position, 2 Inf derivative, 3 fail only beyond t = 0.7, 4 huge, 5 writes nothing */
} bad_curve;

static int bad_fn(void *user, double t, cdist_vec3 *p, cdist_vec3 *d)
{
    const bad_curve *b = user;
    *p = tv(t, 1, 0);
    *d = tv(1, 0, 0);
    switch (b->mode) {
    case 0: return 7;
    case 1: p->y = NAN; return 0;
    case 2: d->z = INFINITY; return 0;
    case 3: return t > 0.7 ? -1 : 0;
    case 4: p->x = 1e200; return 0;
    default: return 0;
    }
}

static int silent_fn(void *user, double t, cdist_vec3 *p, cdist_vec3 *d)
{
    (void)user; (void)t; (void)p; (void)d;
    return 0;
}

static void callbacks_and_bad_input(void)
{
    cdist_result r;
    cdist_circle c = {tv(0, 0, 0), tv(0, 0, 1), 1};
    const cdist_status want[5] = {CDIST_ERR_CALLBACK_FAILED, CDIST_ERR_CALLBACK_NOT_FINITE,
                                  CDIST_ERR_CALLBACK_NOT_FINITE, CDIST_ERR_CALLBACK_FAILED, CDIST_ERR_OUT_OF_RANGE};
    for (int m = 0; m < 5; m++) {
        bad_curve b = {m};
        for (int disk = 0; disk < 2; disk++) {
            cdist_status st = (disk ? cdist_curve_disk : cdist_curve_circle)(q, bad_fn, &b, 0, 1, &c, &r);
            CHECK(st == want[m], "mode %d disk %d: %s", m, disk, cdist_status_name(st));
            CHECK(isnan(r.distance) && r.num_pairs == 0, "mode %d: error result", m);
            CHECK(cdist_query_last_status(q) == want[m] && strlen(cdist_query_last_error(q)) > 0, "mode %d message", m);
        }
    }
    CHECK(cdist_curve_circle(q, silent_fn, NULL, 0, 1, &c, &r) == CDIST_ERR_CALLBACK_NOT_FINITE,
          "callback that writes nothing");
    seg_curve s = {tv(0, 0, 0), tv(1, 0, 0), 0};
    CHECK(cdist_curve_circle(NULL, seg_fn, &s, 0, 1, &c, &r) == CDIST_ERR_NULL_ARGUMENT, "NULL handle");
    CHECK(cdist_curve_circle(q, NULL, &s, 0, 1, &c, &r) == CDIST_ERR_NULL_ARGUMENT && isnan(r.distance), "NULL fn");
    CHECK(cdist_curve_circle(q, seg_fn, &s, 0, 1, NULL, &r) == CDIST_ERR_NULL_ARGUMENT, "NULL circle");
    CHECK(cdist_curve_disk(q, seg_fn, &s, 0, 1, &c, NULL) == CDIST_ERR_NULL_ARGUMENT, "NULL result");
    CHECK(cdist_curve_circle(q, seg_fn, &s, NAN, 1, &c, &r) == CDIST_ERR_NOT_FINITE, "NaN t0");
    CHECK(cdist_curve_disk(q, seg_fn, &s, 0, INFINITY, &c, &r) == CDIST_ERR_NOT_FINITE, "Inf t1");
    CHECK(cdist_curve_circle(q, seg_fn, &s, 1, 0, &c, &r) == CDIST_ERR_BAD_INTERVAL && r.num_pairs == 0, "reversed");
    CHECK(cdist_curve_circle(q, seg_fn, &s, -1e308, 1e308, &c, &r) == CDIST_ERR_BAD_INTERVAL, "overlong interval");
    cdist_circle bad = c;
    bad.normal = tv(0, 0, 0);
    CHECK(cdist_curve_circle(q, seg_fn, &s, 0, 1, &bad, &r) == CDIST_ERR_ZERO_VECTOR, "zero normal");
    /* The callback is not called when the input is rejected. */
    s.calls = 0;
    cdist_curve_circle(q, seg_fn, &s, 1, 0, &c, &r);
    CHECK(s.calls == 0, "no calls on bad input");

    cdist_helix h = {tv(0, 0, 0), tv(0, 0, 1), tv(1, 0, 0), 1, 0.5, 0, 10};
    cdist_helix hb = h;
    hb.axis = tv(0, 0, 2);
    CHECK(cdist_helix_circle(q, &hb, &c, &r) == CDIST_ERR_NOT_UNIT, "helix non-unit axis");
    hb.axis = tv(0, 0, 0);
    CHECK(cdist_helix_circle(q, &hb, &c, &r) == CDIST_ERR_ZERO_VECTOR, "helix zero axis");
    hb = h;
    hb.zero_direction = tv(0, 0, -3);
    CHECK(cdist_helix_disk(q, &hb, &c, &r) == CDIST_ERR_ZERO_VECTOR, "helix zero_direction along the axis");
    hb = h;
    hb.t0 = 11;
    CHECK(cdist_helix_circle(q, &hb, &c, &r) == CDIST_ERR_BAD_INTERVAL, "helix reversed");
    hb = h;
    hb.t1 = 1e300;
    CHECK(cdist_helix_circle(q, &hb, &c, &r) == CDIST_ERR_BAD_INTERVAL, "helix too many turns");
    hb = h;
    hb.pitch = NAN;
    CHECK(cdist_helix_circle(q, &hb, &c, &r) == CDIST_ERR_NOT_FINITE, "helix NaN pitch");
    hb = h;
    hb.radius = -1;
    CHECK(cdist_helix_circle(q, &hb, &c, &r) == CDIST_ERR_NEGATIVE_RADIUS, "helix negative radius");
    CHECK(cdist_helix_circle(q, NULL, &c, &r) == CDIST_ERR_NULL_ARGUMENT, "NULL helix");
    cdist_bezier3 bz = {{tv(0, 0, 0), tv(1, 1, 0), tv(2, 1, 0), tv(3, 0, 0)}};
    CHECK(cdist_bezier3_circle(q, NULL, &c, &r) == CDIST_ERR_NULL_ARGUMENT, "NULL Bezier");
    bz.p[2].z = NAN;
    CHECK(cdist_bezier3_disk(q, &bz, &c, &r) == CDIST_ERR_NOT_FINITE && isnan(r.distance), "NaN Bezier");
    bz.p[2].z = 1e200;
    CHECK(cdist_bezier3_circle(q, &bz, &c, &r) == CDIST_ERR_OUT_OF_RANGE, "huge Bezier");
}

/* ---- helix and Bezier against brute force ---- */


static void helix_case(long id, const cdist_helix *h, const cdist_circle *c, int disk)
{
    bf_helix x = bf_helix_of(h, c, disk);
    int ns = (int)fmin(4e5, 4096 * (1 + (h->t1 - h->t0) / (2 * M_PI)));
    ld ref = bf_min1d(bf_f_helix, &x, h->t0, h->t1, ns);
    cdist_result r;
    cdist_status st = (disk ? cdist_helix_disk : cdist_helix_circle)(q, h, c, &r);
    CHECK(st == CDIST_OK, "helix %ld: %s", id, cdist_query_last_error(q));
    if (st) return;
    double ext = fabs(h->pitch) * fmax(fabs(h->t0), fabs(h->t1)) / (2 * M_PI);
    double L = fmax(fmax(h->radius, c->radius), tdist(h->center, c->center) + ext);
    L = fmax(L, (double)ref);
    double er = (double)(fabsl((ld)r.distance - ref) / L);
    if (er > worst[2 + disk]) worst[2 + disk] = er;
    CHECK(er <= 1e-12, "helix %ld (%s): %.17g vs %.20Lg error %.3g", id, disk ? "disk" : "circle", r.distance, ref, er);
    check_pairs(&r, c, disk, 1e-12 * L, "helix", id);
    for (int k = 0; k < r.num_pairs; k++) {
        double t = r.pairs[k].param[0];
        CHECK(t >= h->t0 && t <= h->t1, "helix %ld: param %.17g outside", id, t);
        ld d = lv_norm(lv_sub(lv_of(r.pairs[k].point[0]),
                              lv_add(x.c, lv_add(lv_scale(x.r * cosl(t), x.u),
                                                 lv_add(lv_scale(x.r * sinl(t), x.v), lv_scale(x.rise * t, x.n))))));
        CHECK((double)d <= 1e-13 * L, "helix %ld: point is not the helix point at its param (%.3g)", id, (double)d);
    }
}

static void bezier_case(long id, const cdist_bezier3 *bz, const cdist_circle *c, int disk)
{
    bf_bez x;
    for (int i = 0; i < 4; i++) x.p[i] = lv_of(bz->p[i]);
    x.k = bf_circ(*c);
    x.disk = disk;
    ld ref = bf_min1d(bf_f_bez, &x, 0, 1, 16384);
    cdist_result r;
    cdist_status st = (disk ? cdist_bezier3_disk : cdist_bezier3_circle)(q, bz, c, &r);
    CHECK(st == CDIST_OK, "bezier %ld: %s", id, cdist_query_last_error(q));
    if (st) return;
    double L = fmax(c->radius, (double)ref);
    for (int i = 0; i < 4; i++) L = fmax(L, tdist(bz->p[i], c->center));
    double er = (double)(fabsl((ld)r.distance - ref) / L);
    if (er > worst[4 + disk]) worst[4 + disk] = er;
    CHECK(er <= 1e-12, "bezier %ld (%s): %.17g vs %.20Lg error %.3g", id, disk ? "disk" : "circle", r.distance, ref, er);
    check_pairs(&r, c, disk, 1e-12 * L, "bezier", id);
    for (int k = 0; k < r.num_pairs; k++)
        CHECK(r.pairs[k].param[0] >= 0 && r.pairs[k].param[0] <= 1 &&
                  (double)fabsl(bf_f_bez(&(bf_bez){{x.p[0], x.p[1], x.p[2], x.p[3]}, bf_circ(*c), disk}, r.pairs[k].param[0]) -
                                (ld)r.distance) <= 1e-12 * L,
              "bezier %ld: param does not give the distance", id);
}

static void helix_bezier_cases(void)
{
    for (int i = 0; i < 120; i++) {
        cdist_circle c = {tv(srand1(), srand1(), srand1()), rand_unit(), 0.1 + 1.4 * urand()};
        cdist_helix h = {tv(srand1(), srand1(), srand1()), rand_unit(), rand_unit(), 0.1 + urand(),
                         (i % 7 == 0) ? 0.0 : 2 * srand1(), -10 * urand(), 0};
        h.t1 = h.t0 + (i % 5 == 0 ? 60.0 : 15 * urand());
        if (i % 11 == 0) h.radius = 0;
        if (i % 9 == 4) c.radius = 0; /* the target is a point */
        if (i % 13 == 6) { /* the target coaxial with the helix */
            c.normal = h.axis;
            c.center = tv(h.center.x + 0.3 * h.axis.x, h.center.y + 0.3 * h.axis.y, h.center.z + 0.3 * h.axis.z);
        }
        helix_case(i, &h, &c, i & 1);
        cdist_bezier3 bz;
        for (int k = 0; k < 4; k++) bz.p[k] = tv(2 * srand1(), 2 * srand1(), 2 * srand1());
        bezier_case(i, &bz, &c, (i >> 1) & 1);
    }
    /* Coaxial helix through a circle of its own radius: crosses it once per turn. */
    cdist_circle c = {tv(0, 0, 1), tv(0, 0, 1), 1};
    cdist_helix h = {tv(0, 0, 0), tv(0, 0, 1), tv(1, 0, 0), 1, 0.5, -20, 20};
    cdist_result r;
    CHECK(cdist_helix_circle(q, &h, &c, &r) == CDIST_OK && r.distance < 1e-15 &&
              fabs(r.pairs[0].param[0] - 4 * M_PI) < 1e-6,
          "helix through its circle: %.17g t %.17g", r.distance, r.pairs[0].param[0]);
    helix_case(900, &h, &c, 0);
    /* Coaxial helix inside a bigger disk: distance 0 where it crosses the plane. */
    cdist_circle d = {tv(0, 0, 2), tv(0, 0, 1), 3};
    helix_case(901, &h, &d, 1);
    /* Many turns, far from the circle except one turn. */
    cdist_helix longh = {tv(0, 0, 0), tv(0, 0, 1), tv(1, 0, 0), 1, 0.1, 0, 2 * M_PI * 2000};
    cdist_circle side = {tv(3, 0, 100), tv(1, 0, 0), 1.5};
    CHECK(cdist_helix_circle(q, &longh, &side, &r) == CDIST_OK, "long helix");
    helix_case(902, &longh, &side, 0);
    /* Pitch 0 helix over three turns is its circle. */
    cdist_helix flat = {tv(0, 0, 0), tv(0, 0, 1), tv(1, 0, 0), 1, 0, 0, 6 * M_PI};
    cdist_circle coax = {tv(0, 0, 1), tv(0, 0, 1), 2};
    CHECK(cdist_helix_circle(q, &flat, &coax, &r) == CDIST_OK && fabs(r.distance - sqrt(2.0)) < 1e-15 && r.equidistant,
          "flat helix coaxial: %.17g eq %d", r.distance, r.equidistant);
    /* A straight Bezier (collinear control points) along the disk's axis. */
    cdist_bezier3 line = {{tv(0, 0, 3), tv(0, 0, 2), tv(0, 0, 1), tv(0, 0, 0.5)}};
    cdist_circle dd = {tv(0, 0, 0), tv(0, 0, 1), 1};
    CHECK(cdist_bezier3_disk(q, &line, &dd, &r) == CDIST_OK && r.distance == 0.5, "axial Bezier to disk %.17g",
          r.distance);
    CHECK(cdist_bezier3_circle(q, &line, &dd, &r) == CDIST_OK && fabs(r.distance - sqrt(1.25)) < 1e-15 && r.equidistant,
          "axial Bezier to circle %.17g", r.distance);
    bezier_case(903, &line, &dd, 0);
    /* A looping Bezier in the unit circle's plane crossing it at four isolated points (near
     * (-0.806, -0.592), (0.986, 0.166), (0.972, 0.236), (-0.78, -0.626)): distance 0, finitely
     * many pairs, so not equidistant; two of them are reported. */
    cdist_bezier3 ess = {{tv(-1.2, -0.7, 0), tv(1.9, 0.1, 0), tv(1.7, 1.1, 0), tv(-1.5, -1.1, 0)}};
    cdist_circle unit = {tv(0, 0, 0), tv(0, 0, 1), 1};
    CHECK(cdist_bezier3_circle(q, &ess, &unit, &r) == CDIST_OK && r.distance < 1e-15 && !r.equidistant &&
              r.num_pairs == 2,
          "S-curve crossing four times: %.17g eq %d pairs %d", r.distance, r.equidistant, r.num_pairs);
    bezier_case(904, &ess, &unit, 0);
    /* Degenerate Bezier: all control points equal (a point). */
    cdist_bezier3 pt = {{tv(2, 0, 0), tv(2, 0, 0), tv(2, 0, 0), tv(2, 0, 0)}};
    CHECK(cdist_bezier3_circle(q, &pt, &dd, &r) == CDIST_OK && r.distance == 1, "point Bezier %.17g", r.distance);
}

/* Scaling every length by 2^k (exact in binary) scales the distance by 2^k. */
static cdist_vec3 sv(cdist_vec3 v, double f) { return tv(v.x * f, v.y * f, v.z * f); }

static void scale_invariance(void)
{
    const double fs[3] = {ldexp(1, -300), ldexp(1, 300), ldexp(1, 480)};
    for (int i = 0; i < 30; i++) {
        cdist_circle c = {tv(srand1(), srand1(), srand1()), rand_unit(), 0.1 + 1.4 * urand()};
        cdist_helix h = {tv(srand1(), srand1(), srand1()), rand_unit(), rand_unit(), 0.1 + urand(), 2 * srand1(), 0, 10};
        cdist_bezier3 bz;
        for (int k = 0; k < 4; k++) bz.p[k] = tv(2 * srand1(), 2 * srand1(), 2 * srand1());
        seg_curve sg = {tv(2 * srand1(), 2 * srand1(), 2 * srand1()), tv(srand1(), srand1(), srand1()), 0};
        for (int disk = 0; disk < 2; disk++) {
            cdist_result r0[3], r;
            CHECK((disk ? cdist_helix_disk : cdist_helix_circle)(q, &h, &c, &r0[0]) == CDIST_OK &&
                      (disk ? cdist_bezier3_disk : cdist_bezier3_circle)(q, &bz, &c, &r0[1]) == CDIST_OK &&
                      (disk ? cdist_curve_disk : cdist_curve_circle)(q, seg_fn, &sg, 0, 1, &c, &r0[2]) == CDIST_OK,
                  "scale case %d", i);
            for (int k = 0; k < 3; k++) {
                double f = fs[k];
                cdist_circle cs = {sv(c.center, f), c.normal, c.radius * f};
                cdist_helix hs = h;
                hs.center = sv(h.center, f);
                hs.radius *= f;
                hs.pitch *= f;
                cdist_bezier3 bs;
                for (int j = 0; j < 4; j++) bs.p[j] = sv(bz.p[j], f);
                seg_curve ss = {sv(sg.p0, f), sv(sg.m, f), 0};
                double L = 4.0;
                CHECK((disk ? cdist_helix_disk : cdist_helix_circle)(q, &hs, &cs, &r) == CDIST_OK &&
                          fabs(r.distance / f - r0[0].distance) <= 1e-14 * (L + 2),
                      "helix scale 2^%d: %.17g vs %.17g", ilogb(f), r.distance / f, r0[0].distance);
                CHECK((disk ? cdist_bezier3_disk : cdist_bezier3_circle)(q, &bs, &cs, &r) == CDIST_OK &&
                          fabs(r.distance / f - r0[1].distance) <= 1e-14 * L,
                      "bezier scale 2^%d: %.17g vs %.17g", ilogb(f), r.distance / f, r0[1].distance);
                CHECK((disk ? cdist_curve_disk : cdist_curve_circle)(q, seg_fn, &ss, 0, 1, &cs, &r) == CDIST_OK &&
                          fabs(r.distance / f - r0[2].distance) <= 1e-14 * L,
                      "callback scale 2^%d: %.17g vs %.17g", ilogb(f), r.distance / f, r0[2].distance);
            }
        }
    }
    /* a subnormal pitch at a huge angle (found by the fuzzer): pitch / (2 pi) lost the pitch's
     * few bits before the scaling; the helix point (radius 0, one angle) at pitch t / (2 pi) */
    cdist_helix h = {tv(0, 0, 0), tv(0, 0, 1), tv(1, 0, 0), 0.0, 7.3269935278256863e-320, 1e151, 1e151};
    cdist_circle c = {tv(1e-167, 0, 0), tv(0, 0, 1), 1e-170};
    cdist_result r;
    long double z = (long double)h.pitch * 1e151L / (2 * 3.14159265358979323846264338327950288L);
    CHECK(cdist_helix_circle(q, &h, &c, &r) == CDIST_OK && fabsl(r.pairs[0].point[0].z - z) <= 1e-14L * z,
          "subnormal pitch: helix point z %.17g, want %.17Lg", r.pairs[0].point[0].z, z);
}

int main(int argc, char **argv)
{
    q = cdist_query_new();
    if (argc >= 2) {
        static const char *const set[] = {"random", "hard"};
        for (int disk = 0; disk < 2; disk++)
            for (int k = 0; k < 2; k++) {
                char a[4096], b[4096];
                snprintf(a, sizeof a, "%s/l%c_%s.txt", argv[1], disk ? 'd' : 'c', set[k]);
                snprintf(b, sizeof b, "%s/l%c_%s.expected", argv[1], disk ? 'd' : 'c', set[k]);
                shared_lines(a, b, disk);
            }
    }
    random_segments();
    degenerate_segments();
    callbacks_and_bad_input();
    helix_bezier_cases();
    scale_invariance();
    for (int k = 0; k < 6; k++) printf("%s: max error %.3g of scale\n", names[k], worst[k]);
    cdist_query_free(q);
    return check_summary("curves");
}
