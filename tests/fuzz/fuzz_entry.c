/* SPDX-License-Identifier: MIT */
/* Fuzz target for the parser and every public entry point.
 * - libFuzzer: clang -fsanitize=fuzzer,address (meson -Dfuzz=true... see README) uses
 *   LLVMFuzzerTestOneInput directly.
 * - Otherwise a main() drives it with deterministic pseudo-random inputs (a smoke test).
 * The input is read two ways: as query text for the tool's parser, and as raw doubles (any bit
 * pattern: NaN, Inf, subnormal, huge) for every query function (under libFuzzer for the one
 * kind the input's last byte selects). The first byte also sets the
 * handle's options (method, unit tolerance INFINITY, curve samples) and a power-of-two scale of
 * the coordinates (tiny, subnormal, huge). The contract checked (abort() on violation, so the
 * fuzzer reports it): no crash; status != OK, or the distance is finite and >= 0, there are
 * 1-2 pairs, each pair lies on its objects and realises the distance (long double geometry,
 * tolerance relative to the input's magnitude; swept kinds: the witness pair realises the signed
 * distance's magnitude); the distance-only batch agrees; kinds whose objects have the same
 * layout (cc, dd, aa, TT, KK, SS, RR) succeed or fail together and give the same distance, pair count and
 * equidistant flag in both argument orders; a scene of tori from the same doubles reports
 * exactly the pairs within delta that the single queries report, to the bit, before and after
 * updates (check_scene); errors leave NaN, no pairs and a message. */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "circledist.h"
#include "query_io.h"

static cdist_query *q;
static const double *cur_v; /* the values of the query being checked, for the report */
static int cur_n;
/* Smoke driver only: kinds whose violations are reported but not fatal (open bugs of other
 * families, listed in main); NULL under libFuzzer (everything aborts). */
static const char *known_open;
static long open_violations;

static int is_known_open(const char *kind)
{
    if (!known_open) return 0;
    size_t n = strlen(kind);
    for (const char *p = known_open; (p = strstr(p, kind)); p += n)
        if ((p == known_open || p[-1] == ',') && (p[n] == ',' || p[n] == '\0')) return 1;
    return 0;
}

static void violation(const char *kind, const char *what, const cdist_result *r)
{
    if (is_known_open(kind) && ++open_violations > 3) return; /* report the first few only */
    fprintf(stderr, "fuzz: contract violated (%s): %s; distance %.17g, %d pairs, method %d, unit tol %g, samples %d\n",
            kind, what, r->distance, r->num_pairs, (int)cdist_query_get_method(q), cdist_query_get_unit_tolerance(q),
            cdist_query_get_curve_samples(q));
    fprintf(stderr, "%s", kind);
    for (int i = 0; i < cur_n; i++) fprintf(stderr, " %.17g", cur_v[i]);
    fprintf(stderr, "\n");
    for (int i = 0; i < r->num_pairs; i++)
        fprintf(stderr, "pair %d: (%.17g %.17g %.17g) (%.17g %.17g %.17g) params %.17g %.17g\n", i,
                r->pairs[i].point[0].x, r->pairs[i].point[0].y, r->pairs[i].point[0].z, r->pairs[i].point[1].x,
                r->pairs[i].point[1].y, r->pairs[i].point[1].z, r->pairs[i].param[0], r->pairs[i].param[1]);
    if (!is_known_open(kind)) abort();
}

/* Swept kinds (upper-case tool names, src/swept) give signed distances (negative = overlap). */
static int signed_kind(const char *kind) { return kind[0] >= 'A' && kind[0] <= 'Z'; }

static void check_result(const char *kind, cdist_status st, const cdist_result *r)
{
    if (st == CDIST_OK) {
        if (!(signed_kind(kind) || r->distance >= 0.0) || !isfinite(r->distance) || r->num_pairs < 1 || r->num_pairs > 2)
            violation(kind, "OK without a finite distance >= 0 and 1-2 pairs", r);
    } else {
        if (!isnan(r->distance) || r->num_pairs != 0) violation(kind, "error without the error result", r);
        if (cdist_query_last_error(q)[0] == '\0') violation(kind, "error without a message", r);
    }
}

/* ---- the objects, in long double, to check that pairs lie on them ---- */

typedef long double ld;
typedef struct lv {
    ld x, y, z;
} lv;
static lv L3(const double *v) { lv r = {v[0], v[1], v[2]}; return r; }
static lv lvp(cdist_vec3 a) { lv r = {a.x, a.y, a.z}; return r; }
static lv lsub(lv a, lv b) { lv r = {a.x - b.x, a.y - b.y, a.z - b.z}; return r; }
static lv ladd(lv a, lv b) { lv r = {a.x + b.x, a.y + b.y, a.z + b.z}; return r; }
static lv lsc(ld s, lv a) { lv r = {s * a.x, s * a.y, s * a.z}; return r; }
static ld ldot(lv a, lv b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static lv lcross(lv a, lv b) { lv r = {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; return r; }
/* Scaled by the largest component: in double (valgrind runs long double as double) the squares
 * of tiny or huge components would underflow or overflow. */
static ld lnorm(lv a)
{
    ld m = fabsl(a.x) > fabsl(a.y) ? fabsl(a.x) : fabsl(a.y);
    if (fabsl(a.z) > m) m = fabsl(a.z);
    if (!(m > 0) || isinf(m)) return m;
    lv s = {a.x / m, a.y / m, a.z / m};
    return m * sqrtl(ldot(s, s));
}
/* Scaled first: subnormal components must not underflow the norm (valgrind runs long double as
 * double, where the squares of 1e-320 vanish). */
static lv lunit(lv a)
{
    ld m = fabsl(a.x) > fabsl(a.y) ? fabsl(a.x) : fabsl(a.y);
    if (fabsl(a.z) > m) m = fabsl(a.z);
    lv s = {a.x / m, a.y / m, a.z / m}; /* divided: 1 / m overflows for subnormal m */
    return lsc(1.0L / lnorm(s), s);
}

enum { O_POINT, O_CIRCLE, O_DISK, O_LINE, O_ARC, O_HELIX, O_BEZIER, O_CURVE };
typedef struct obj {
    int type;
    const double *v; /* its values (layout of tools/query_io.c) */
    ld tmin, tmax;   /* O_LINE: parameter range; O_CURVE: t range */
} obj;

static ld d_circle(lv x, const double *v, int disk)
{
    lv n = lunit(L3(v + 3)), d = lsub(x, L3(v));
    ld h = ldot(n, d), rho = lnorm(lcross(n, d)), e = rho - v[6];
    if (disk && e < 0) e = 0;
    return sqrtl(h * h + e * e);
}

/* Distance from x to the object; param: the pair's parameter on it (curves are checked there). */
static ld d_obj(const obj *o, lv x, double param)
{
    const double *v = o->v;
    switch (o->type) {
    case O_POINT: return lnorm(lsub(x, L3(v)));
    case O_CIRCLE: return d_circle(x, v, 0);
    case O_DISK: return d_circle(x, v, 1);
    case O_LINE: {
        lv p0 = L3(v), m = L3(v + 3);
        if (o->tmax == 1.0L) m = lsub(m, p0); /* segment: p0 p1 */
        /* in units of the direction's largest component (no underflow of m.m in double) */
        ld sc = fabsl(m.x) > fabsl(m.y) ? fabsl(m.x) : fabsl(m.y);
        if (fabsl(m.z) > sc) sc = fabsl(m.z);
        if (!(sc > 0)) return lnorm(lsub(x, p0));
        lv mu = {m.x / sc, m.y / sc, m.z / sc};
        ld t = ldot(lsub(x, p0), mu) / ldot(mu, mu), lo = o->tmin * sc, hi = o->tmax * sc;
        t = t < lo ? lo : (t > hi ? hi : t);
        return lnorm(lsub(x, ladd(p0, lsc(t, mu))));
    }
    case O_ARC: {
        /* NaN: the angle is meaningless (a radius negligible at the problem's scale). */
        if (param == param && !(param >= v[10] - 1e-9 * (1 + fabs(v[10])) && param <= v[11] + 1e-9 * (1 + fabs(v[11]))))
            return INFINITY;
        return d_circle(x, v, 0);
    }
    case O_HELIX: {
        if (!(param >= v[11] && param <= v[12])) return INFINITY;
        lv n = lunit(L3(v + 3)), z = L3(v + 6);
        lv u = lunit(lsub(z, lsc(ldot(z, n), n))), w = lcross(n, u);
        ld t = param, rise = (ld)v[10] / (2 * 3.14159265358979323846264338327950288L);
        lv p = ladd(L3(v), ladd(lsc(v[9] * cosl(t), u), ladd(lsc(v[9] * sinl(t), w), lsc(rise * t, n))));
        return lnorm(lsub(x, p));
    }
    case O_BEZIER: {
        if (!(param >= 0.0 && param <= 1.0)) return INFINITY;
        ld t = param, mt = 1 - t;
        lv p = ladd(ladd(lsc(mt * mt * mt, L3(v)), lsc(3 * mt * mt * t, L3(v + 3))),
                    ladd(lsc(3 * mt * t * t, L3(v + 6)), lsc(t * t * t, L3(v + 9))));
        return lnorm(lsub(x, p));
    }
    default: { /* O_CURVE: fuzz_curve, v[0..2] + t v[3..5] */
        if (!(param >= o->tmin && param <= o->tmax)) return INFINITY;
        return lnorm(lsub(x, ladd(L3(v), lsc(param, L3(v + 3)))));
    }
    }
}

/* OK results: every pair on its objects and realising the distance, within a tolerance
 * relative to the magnitude of the input values (mag, excluding angles). */
/* A helix's point at a parameter depends on its frame U = unit(z - (z.N) N): with z at angle
 * theta from the axis, the doubles of z and N fix U only to about eps / sin(theta), which moves
 * the point by that times the radius (the frame's conditioning, not the query's error). */
static ld frame_slack(const obj *o)
{
    if (o->type != O_HELIX) return 0;
    lv n = lunit(L3(o->v + 3)), z = L3(o->v + 6);
    ld s = lnorm(lcross(n, z)) / lnorm(z);
    return 8 * DBL_EPSILON * fabsl((ld)o->v[9]) / s;
}

static void check_pairs(const char *kind, const obj *o0, const obj *o1, double mag, const cdist_result *r)
{
    ld tol = 1e-7L * ((ld)mag + r->distance) + 1e-300L;
    for (int i = 0; i < r->num_pairs; i++) {
        const cdist_pair *pr = &r->pairs[i];
        lv a = lvp(pr->point[0]), b = lvp(pr->point[1]);
        if (!(fabsl(lnorm(lsub(a, b)) - r->distance) <= tol)) violation(kind, "a pair does not realise the distance", r);
        if (!(d_obj(o0, a, pr->param[0]) <= tol + frame_slack(o0))) violation(kind, "a pair's first point is off its object", r);
        if (!(d_obj(o1, b, pr->param[1]) <= tol)) violation(kind, "a pair's second point is off its object", r);
    }
}

/* The objects of a query line (tools/query_io.c layouts). */
static void objects_of(const cdq_line *ql, obj *o0, obj *o1)
{
    const char *k = ql->kind->name;
    const double *v = ql->v;
    *o0 = (obj){O_POINT, v, 0, 0};
    *o1 = (obj){O_CIRCLE, v + 6, 0, 0};
    int second_disk = k[1] == 'd';
    switch (k[0]) {
    case 'p': o1->v = v + 3; break;
    case 'l': o0->type = O_LINE; o0->tmin = -INFINITY; o0->tmax = INFINITY; break;
    case 'r': o0->type = O_LINE; o0->tmin = 0; o0->tmax = INFINITY; break;
    case 's': o0->type = O_LINE; o0->tmin = 0; o0->tmax = 1; break;
    case 'c': o0->type = O_CIRCLE; o1->v = v + 7; break;
    case 'd': o0->type = O_DISK; o1->v = v + 7; break;
    case 'a': o0->type = O_ARC; o1->v = v + 12; break;
    case 'h': o0->type = O_HELIX; o1->v = v + 13; break;
    case 'b': o0->type = O_BEZIER; o1->v = v + 12; break;
    }
    if (second_disk) o1->type = O_DISK;
    if (k[1] == 'a') o1->type = O_ARC;
}

/* Angles and curve parameters (not scaled with the coordinates, not part of the magnitude). */
static int is_angle(const char *k, int i)
{
    if (k[0] == 'a' && (i == 10 || i == 11)) return 1;
    if (!strcmp(k, "aa") && (i == 22 || i == 23)) return 1;
    if (!strcmp(k, "sa") && (i == 16 || i == 17)) return 1;
    if (k[0] == 'h' && (i == 11 || i == 12)) return 1;
    return 0;
}

static double magnitude(const cdq_line *ql)
{
    double m = 0;
    for (int i = 0; i < ql->nvalues; i++)
        if (!is_angle(ql->kind->name, i) && isfinite(ql->v[i])) m = fmax(m, fabs(ql->v[i]));
    if (ql->kind->name[0] == 'h') /* the helix's axial reach */
        m = fmax(m, fabs(ql->v[10]) * fmax(fabs(ql->v[11]), fabs(ql->v[12])));
    return m;
}

/* The distance-only batch of the same query as one entry (its SIMD kernels for points, lines,
 * rays and segments against circles, and circle-circle): the single query's status, and its
 * distance to 2 ulps of the problem scale (NaN for a bad entry). */
static void check_batch_distance(const cdq_line *ql, cdist_status st, const cdist_result *r)
{
    if (!ql->kind->objects || ql->kind->batch_kind < 0) return;
    double a[32], b[32], d; /* room for the largest object (a helix, a Bezier curve) */
    cdist_status bs;
    ql->kind->objects(ql->v, a, b);
    cdist_batch_distance(q, (cdist_kind)ql->kind->batch_kind, 1, a, 0, b, 0, &d, &bs);
    /* (the scale can overflow for a tiny non-unit direction: equal distances need no scale) */
    double L = st == CDIST_OK ? cdq_scale(ql, r->distance) : 0.0;
    int same = bs == st && (st != CDIST_OK ? isnan(d)
                                           : d == r->distance || fabs(d - r->distance) <= 2.0 * (nextafter(L, INFINITY) - L));
    if (!same) {
        fprintf(stderr, "fuzz: distance-only batch: %s %.17g\n", cdist_status_name(bs), d);
        violation(ql->kind->name, "the distance-only batch differs from the single query", r);
    }
}

/* The full batch of the same query as one entry (circle-circle runs the single query in stages,
 * its search in lanes; the other plain kinds the single query): the single query's status and
 * result, to the bit. */
static void check_batch_full(const cdq_line *ql, cdist_status st, const cdist_result *r)
{
    if (!ql->kind->objects || ql->kind->batch_kind < 0 || signed_kind(ql->kind->name)) return;
    double a[32], b[32];
    cdist_result rb;
    cdist_status bs;
    ql->kind->objects(ql->v, a, b);
    cdist_batch(q, (cdist_kind)ql->kind->batch_kind, 1, a, 0, b, 0, &rb, &bs);
    if (bs != st || (st == CDIST_OK && memcmp(&rb, r, sizeof rb))) {
        fprintf(stderr, "fuzz: full batch: %s %.17g\n", cdist_status_name(bs), rb.distance);
        violation(ql->kind->name, "the full batch differs from the single query", r);
    }
}

/* f(a, b) = f(b, a) for kinds whose two objects have the same layout: both OK or both errors
 * (which error may differ: each object can be bad its own way, and the first is reported), the
 * same pair count and equidistant flag, and the distance to 16 ulps of the input's magnitude. */
static void check_swapped(const cdq_line *ql, cdist_status st, const cdist_result *r)
{
    cdq_line sw;
    if (!cdq_swapped(ql, &sw)) return;
    cdist_result rs;
    cdist_status ss = cdq_run(q, &sw, &rs);
    if ((ss == CDIST_OK) != (st == CDIST_OK)) {
        fprintf(stderr, "fuzz: swapped order: status %s, this order %s\n", cdist_status_name(ss), cdist_status_name(st));
        violation(ql->kind->name, "success depends on the argument order", r);
        return;
    }
    if (st != CDIST_OK) return;
    /* (plus the absolute floor of check_pairs: subnormal inputs carry a few bits only) */
    double tol = 16.0 * DBL_EPSILON * fmax(magnitude(ql), fabs(r->distance)) + 1e-300;
    if (!(fabs(rs.distance - r->distance) <= tol) || rs.num_pairs != r->num_pairs || rs.equidistant != r->equidistant) {
        fprintf(stderr, "fuzz: swapped order: distance %.17g, %d pairs, equidistant %d; this order equidistant %d\n",
                rs.distance, rs.num_pairs, rs.equidistant, r->equidistant);
        violation(ql->kind->name, "the answer depends on the argument order", r);
    }
}

static void run_checked(const cdq_line *ql)
{
    cdist_result r;
    cur_v = ql->v;
    cur_n = ql->nvalues;
    cdist_status st = cdq_run(q, ql, &r);
    check_result(ql->kind->name, st, &r);
    check_batch_distance(ql, st, &r);
    check_batch_full(ql, st, &r);
    check_swapped(ql, st, &r);
    cur_v = ql->v; /* (check_swapped ran another query) */
    if (st != CDIST_OK) return;
    if (signed_kind(ql->kind->name)) {
        /* swept: the witness points realise the signed distance's magnitude (tests/swept checks
         * that they lie on the surfaces) */
        ld tol = 1e-7L * ((ld)magnitude(ql) + fabsl((ld)r.distance)) + 1e-300L;
        for (int i = 0; i < r.num_pairs; i++)
            if (!(fabsl(lnorm(lsub(lvp(r.pairs[i].point[0]), lvp(r.pairs[i].point[1]))) - fabsl((ld)r.distance)) <= tol))
                violation(ql->kind->name, "a witness pair does not realise the distance", &r);
        return;
    }
    obj o0, o1;
    objects_of(ql, &o0, &o1);
    check_pairs(ql->kind->name, &o0, &o1, magnitude(ql), &r);
}

static int fuzz_curve(void *user, double t, cdist_vec3 *p, cdist_vec3 *d)
{
    const double *v = user;
    p->x = v[0] + t * v[3];
    p->y = v[1] + t * v[4];
    p->z = v[2] + t * v[5];
    *d = (cdist_vec3){v[3], v[4], v[5]};
    return v[6] > 1e300 ? 1 : 0;
}

/* One input: as text, then as raw doubles for the query kind `only` (an index into cdq_kinds;
 * the count of kinds: the two callback-curve queries; -1: every kind and both callbacks). */
/* ---- scenes: pairs within delta against the loop of single queries ---- */

static void scene_violation(const char *what, const double *v, double delta)
{
    fprintf(stderr, "fuzz: scene contract violated: %s; delta %.17g, tori:", what, delta);
    for (int i = 0; i < 24; i++) fprintf(stderr, " %.17g", v[i]);
    fprintf(stderr, "\n");
    abort();
}

enum { SCENE_N = 4 };

/* The scene's pairs within delta are exactly the pairs i < j of valid objects whose single
 * torus-torus query answers with a distance <= delta: same order, distances and points to the
 * bit. A pair whose single query fails is left out of the comparison. */
static void scene_vs_single(cdist_scene *s, const cdist_torus *t, const cdist_status *valid, double delta,
                            const double *v)
{
    cdist_scene_pair out[SCENE_N * SCENE_N];
    size_t count = 0, m = 0;
    cdist_status st = cdist_scene_pairs_within(q, s, delta, out, SCENE_N * SCENE_N, &count);
    if (isnan(delta)) {
        if (st == CDIST_OK) scene_violation("NaN delta accepted", v, delta);
        return;
    }
    if (count > SCENE_N * (SCENE_N - 1) / 2) scene_violation("more pairs than the scene has", v, delta);
    for (size_t i = 0; i < SCENE_N; i++)
        for (size_t j = i + 1; j < SCENE_N; j++) {
            cdist_contact c;
            cdist_status sc = valid[i] || valid[j] ? CDIST_ERR_BAD_KIND : cdist_torus_torus(q, &t[i], &t[j], &c);
            while (m < count && (out[m].i < i || (out[m].i == i && out[m].j < j))) {
                if (out[m].status == CDIST_OK) scene_violation("a pair the single query does not report", v, delta);
                m++;
            }
            int there = m < count && out[m].i == i && out[m].j == j;
            if (sc != CDIST_OK) {
                m += (size_t)there;
                continue;
            }
            if (!(c.distance <= delta)) {
                if (there) scene_violation("a pair beyond delta reported", v, delta);
                continue;
            }
            if (!there) scene_violation("a pair within delta missed", v, delta);
            if (memcmp(&out[m].distance, &c.distance, sizeof c.distance) ||
                memcmp(&out[m].point[0][0], &c.pairs[0].point[0], sizeof(cdist_vec3)) ||
                memcmp(&out[m].point[0][1], &c.pairs[0].point[1], sizeof(cdist_vec3)))
                scene_violation("distance or points differ from the single query's", v, delta);
            m++;
        }
    for (; m < count; m++)
        if (out[m].status == CDIST_OK) scene_violation("a pair the single query does not report", v, delta);
}

/* Three tori from the raw doubles (or, for half the selectors, with unit normals and radii of
 * either sign made positive) and a copy of the first (identical objects), invalid ones included;
 * queried, then moved twice (every pose passed on to the next id) and queried again,
 * which reaches the refit and the pair list. */
static void check_scene(const double *v, unsigned sel)
{
    static const double deltas[] = {0.0, 1.0, 1e300, -1e-3, 0.25, NAN};
    double delta = deltas[sel % (sizeof deltas / sizeof deltas[0])];
    cdist_torus t[SCENE_N];
    cdist_status valid[SCENE_N];
    for (int k = 0; k < 3; k++) {
        const double *w = v + 8 * k;
        cdist_torus x = {{{w[0], w[1], w[2]}, {w[3], w[4], w[5]}, w[6]}, w[7]};
        double n = sqrt(w[3] * w[3] + w[4] * w[4] + w[5] * w[5]);
        if (sel & 8 && n > 0 && isfinite(n)) { /* half the time valid tori, for the deep paths */
            x.circle.normal.x /= n, x.circle.normal.y /= n, x.circle.normal.z /= n;
            x.circle.radius = fabs(x.circle.radius), x.tube_radius = 0.25 * fabs(x.tube_radius);
        }
        t[k] = x;
    }
    t[3] = t[0];
    cdist_scene *s = cdist_scene_new();
    if (!s) return;
    cdist_scene_add(q, s, CDIST_SCENE_TORUS, SCENE_N, t, sizeof t[0], NULL, valid);
    for (int round = 0; round < 3; round++) {
        scene_vs_single(s, t, valid, delta, v);
        cdist_torus first = t[0];
        for (int k = 0; k + 1 < SCENE_N; k++) t[k] = t[k + 1];
        t[SCENE_N - 1] = first;
        cdist_scene_update(q, s, SCENE_N, NULL, CDIST_SCENE_TORUS, t, sizeof t[0], valid);
    }
    cdist_scene_free(s);
}

static void fuzz_input(const uint8_t *data, size_t size, int only)
{
    if (!q) {
        q = cdist_query_new();
    }
    if (size < 1) return;
    /* Options from the first byte: method (bits 0-1), unit tolerance INFINITY (bit 2), curve
     * samples (bits 3-4), coordinate scale (bits 5-7). */
    static const int samples[4] = {512, 8, 17, 64};
    static const int scale_exp[8] = {0, 0, 0, 0, -1000, -1060, 480, -40};
    cdist_query_set_method(q, (cdist_method)(data[0] % 4));
    cdist_query_set_unit_tolerance(q, (data[0] >> 2) & 1 ? INFINITY : 1e-6);
    cdist_query_set_curve_samples(q, samples[(data[0] >> 3) & 3]);
    double scale = ldexp(1.0, scale_exp[data[0] >> 5]);
    /* 1. As text. */
    char *text = malloc(size + 1);
    memcpy(text, data, size);
    text[size] = '\0';
    cdq_line ql;
    char err[256];
    char *save = NULL;
    for (char *line = strtok_r(text, "\n", &save); line; line = strtok_r(NULL, "\n", &save)) {
        if (cdq_parse(line, &ql, err, sizeof err) == 1) run_checked(&ql);
    }
    free(text);
    /* 2. As raw doubles, for every query kind. */
    double v[CDQ_MAX_VALUES] = {0};
    size_t nd = (size - 1) / sizeof(double);
    if (nd > CDQ_MAX_VALUES) nd = CDQ_MAX_VALUES;
    memcpy(v, data + 1, nd * sizeof(double));
    int nkinds = 0;
    for (const cdq_kind *k = cdq_kinds; k->name; k++, nkinds++) {
        if (only >= 0 && only != nkinds) continue;
        ql.kind = k;
        ql.nvalues = k->nvalues;
        memcpy(ql.v, v, sizeof v);
        for (int i = 0; i < k->nvalues; i++)
            if (!is_angle(k->name, i)) ql.v[i] *= scale;
        run_checked(&ql);
    }
    if (only < 0 || only == nkinds + 1) {
        double w[CDQ_MAX_VALUES];
        for (int i = 0; i < CDQ_MAX_VALUES; i++) w[i] = i % 8 < 3 || i % 8 >= 6 ? v[i] * scale : v[i];
        check_scene(w, (unsigned)(data[0] ^ size));
    }
    if (only >= 0 && only != nkinds) return;
    for (int i = 0; i < 14; i++) v[i] *= scale;
    cdist_result r;
    cdist_circle c = {{v[7], v[8], v[9]}, {v[10], v[11], v[12]}, v[13]};
    obj oc = {O_CURVE, v, v[14], v[15]}, ot = {O_CIRCLE, v + 7, 0, 0};
    double mag = 0;
    for (int i = 0; i < 14; i++) mag = fmax(mag, isfinite(v[i]) ? fabs(v[i]) : 0);
    mag = fmax(mag, fabs(v[3]) * fmax(fabs(v[14]), fabs(v[15])) + fabs(v[4]) * fmax(fabs(v[14]), fabs(v[15])) +
                        fabs(v[5]) * fmax(fabs(v[14]), fabs(v[15])));
    cur_v = v;
    cur_n = 16;
    for (int disk = 0; disk < 2; disk++) {
        cdist_status st = (disk ? cdist_curve_disk : cdist_curve_circle)(q, fuzz_curve, v, v[14], v[15], &c, &r);
        check_result(disk ? "curve-disk" : "curve-circle", st, &r);
        ot.type = disk ? O_DISK : O_CIRCLE;
        if (st == CDIST_OK) check_pairs(disk ? "curve-disk" : "curve-circle", &oc, &ot, mag, &r);
    }
    cur_v = NULL;
}

#ifdef CDIST_LIBFUZZER
static int kind_count(void)
{
    int n = 0;
    while (cdq_kinds[n].name) n++;
    return n;
}
#endif

/* Under libFuzzer the raw doubles go to one query kind, the curve queries or the scene, chosen by
 * the input's last byte: every execution costs one query (plus the text's lines), and new
 * coverage is credited to the kind that found it. */
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1) return 0;
#ifdef CDIST_LIBFUZZER
    fuzz_input(data, size, data[size - 1] % (kind_count() + 2));
#else
    fuzz_input(data, size, -1);
#endif
    return 0;
}

#ifndef CDIST_LIBFUZZER
/* Smoke driver: mutated valid lines plus raw random doubles with special values. */
static uint64_t rng = 0x1234567887654321ull;
static uint64_t next(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return rng;
}

int main(int argc, char **argv)
{
    long iters = argc > 1 ? atol(argv[1]) : 3000;
    /* Every family is held to the contract (known_open stays NULL: a violation aborts). A kind can
     * be listed here while a known violation is being fixed ("cc,cd"); --strict ignores the list. */
    known_open = NULL;
    if (argc > 2 && !strcmp(argv[2], "--strict")) known_open = NULL;
    static const double special[] = {0.0, -0.0, 1.0, -1.0, 1e-300, 1e300, 1e151, 1e149, INFINITY, -INFINITY,
                                     NAN, 5e-324, 0.5, 2.0, 1e-8, 3.0};
    uint8_t buf[1 + CDQ_MAX_VALUES * sizeof(double)];
    for (long i = 0; i < iters; i++) {
        double v[CDQ_MAX_VALUES];
        for (int k = 0; k < CDQ_MAX_VALUES; k++) {
            uint64_t x = next();
            if (x % 4 == 0) v[k] = special[(x >> 8) % (sizeof special / sizeof special[0])];
            else if (x % 4 == 1) memcpy(&v[k], &x, sizeof x); /* any bit pattern */
            else v[k] = ((double)(x >> 11) / 9007199254740992.0) * 4 - 2;
        }
        /* Unit normals most of the time, so deep paths are reached. */
        if (i % 2) {
            for (int k = 0; k + 2 < CDQ_MAX_VALUES; k += 7) {
                double n = sqrt(v[k] * v[k] + v[k + 1] * v[k + 1] + v[k + 2] * v[k + 2]);
                if (n > 0 && isfinite(n)) v[k] /= n, v[k + 1] /= n, v[k + 2] /= n;
            }
        }
        buf[0] = (uint8_t)next();
        memcpy(buf + 1, v, sizeof v);
        LLVMFuzzerTestOneInput(buf, sizeof buf);
        char line[512];
        int n = snprintf(line, sizeof line, "%s %.17g %.3g %g nan 1e999 -- %c\n", cdq_kinds[next() % 19].name, v[0],
                         v[1], v[2], (char)(next() % 256));
        LLVMFuzzerTestOneInput((const uint8_t *)line, (size_t)n);
    }
    cdist_query_free(q);
    q = NULL;
    printf("fuzz_smoke: %ld passed, 0 failed (%ld violations in known-open kinds %s)\n", iters, open_violations,
           known_open ? known_open : "-");
    return 0;
}
#endif
