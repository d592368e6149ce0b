/* SPDX-License-Identifier: MIT */
/* Scenes against brute force: for random and degenerate scenes (coplanar, concentric, coaxial,
 * duplicates, mixed kinds, scales 1e-6 .. 1e6 mixed, 1e8 spread) every query equals the O(N^2)
 * loop over the pair queries: the same pairs, distances and points bit for bit, for 1 and 2
 * threads, and after random updates, removals and additions. The loop's pair query is the swept
 * query of the two objects (internal; its agreement with the public single queries is checked
 * on the side), so what is tested is that the broad phase never loses a pair and the
 * bookkeeping never mixes them up. Bad input gets its statuses. */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "test_rand.h"
#include "scene/scene-priv.h"

/* One object as the caller gives it. */
typedef struct tobj {
    cdist_scene_kind kind;
    union {
        cdist_vec3 point;
        cdist_segment segment;
        cdist_circle circle;
        cdist_arc arc;
        cdist_sphere sphere;
        cdist_capsule capsule;
        cdist_torus torus;
        cdist_rounded_disk rdisk;
    } u;
    int live; /* 1 live, 0 removed or invalid */
    unsigned group, chain;
} tobj;

static double rsym(void) { return 2 * rnd01() - 1; }
static cdist_vec3 rvec(double s) { return tv(s * rsym(), s * rsym(), s * rsym()); }
static cdist_vec3 vadd(cdist_vec3 a, cdist_vec3 b) { return tv(a.x + b.x, a.y + b.y, a.z + b.z); }

static tobj make(cdist_scene_kind kind, cdist_vec3 c, double size, cdist_vec3 n)
{
    tobj o;
    memset(&o, 0, sizeof o);
    o.kind = kind;
    o.live = 1;
    double R = size * (0.5 + rnd01()), r = size * 0.2 * rnd01();
    cdist_vec3 d = rvec(size);
    switch (kind) {
    case CDIST_SCENE_POINT: o.u.point = c; break;
    case CDIST_SCENE_SEGMENT: o.u.segment = (cdist_segment){c, vadd(c, d)}; break;
    case CDIST_SCENE_CIRCLE:
    case CDIST_SCENE_DISK: o.u.circle = (cdist_circle){c, n, R}; break;
    case CDIST_SCENE_ARC: {
        double a0 = 3 * rsym();
        o.u.arc = (cdist_arc){{c, n, R}, rnd_unit_vec(), a0, a0 + 6 * rnd01()};
        break;
    }
    case CDIST_SCENE_SPHERE: o.u.sphere = (cdist_sphere){c, r}; break;
    case CDIST_SCENE_CAPSULE: o.u.capsule = (cdist_capsule){{c, vadd(c, d)}, r}; break;
    case CDIST_SCENE_TORUS: o.u.torus = (cdist_torus){{c, n, R}, r}; break;
    case CDIST_SCENE_ROUNDED_DISK: o.u.rdisk = (cdist_rounded_disk){{c, n, R}, r}; break;
    }
    return o;
}

/* ---- the brute-force reference ---- */

typedef struct tpair {
    size_t i, j;
    double d;
    int status, num_pairs, flags;
    cdist_vec3 p[2][2];
} tpair;

static cdist_query *Q;

/* The pair query of objects a (first) and b, as the reference answers it. */
static int ref_pair(const tobj *a, const tobj *b, tpair *t)
{
    cdist__scene_item oa, ob;
    if (cdist__scene_make(Q, a->kind, &a->u, &oa.o, &oa.arc) || cdist__scene_make(Q, b->kind, &b->u, &ob.o, &ob.arc))
        return -1;
    cdist__core_obj ca = cdist__scene_core(&oa.o, &oa.arc), cb = cdist__scene_core(&ob.o, &ob.arc);
    if ((ca.type == CD_CORE_POINT && cb.type == CD_CORE_ARC) || (ca.type == CD_CORE_ARC && cb.type == CD_CORE_POINT))
        return 1; /* no exact query: the scene reports the pair with CDIST_ERR_BAD_KIND or excludes it */
    cdist_contact c;
    cdist_status st = cdist__swept_query(Q, &ca, &cb, &c, NULL);
    if (st) {
        fprintf(stderr, "reference query failed: %s\n", cdist_query_last_error(Q));
        return -1;
    }
    t->d = c.distance;
    t->status = 0;
    t->num_pairs = c.num_pairs;
    t->flags = (c.equidistant ? 1 : 0) | ((c.flags & 1) ? 2 : 0);
    for (int k = 0; k < c.num_pairs; k++) {
        t->p[k][0] = c.pairs[k].point[0];
        t->p[k][1] = c.pairs[k].point[1];
    }
    return 0;
}

static int skip_ref(const tobj *o, size_t i, size_t j)
{
    if (o[i].group && o[i].group == o[j].group) return 1;
    return j == i + 1 && o[i].chain && o[i].chain == o[j].chain;
}

static int same_bits(double a, double b) { return memcmp(&a, &b, sizeof a) == 0; }
static int same_vec(cdist_vec3 a, cdist_vec3 b) { return same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.z, b.z); }

static int pair_equal(const cdist_scene_pair *s, const tpair *t)
{
    if (s->i != t->i || s->j != t->j || s->status != 0 || !same_bits(s->distance, t->d) ||
        s->num_pairs != t->num_pairs || s->flags != t->flags)
        return 0;
    for (int k = 0; k < t->num_pairs; k++)
        if (!same_vec(s->point[k][0], t->p[k][0]) || !same_vec(s->point[k][1], t->p[k][1])) return 0;
    return 1;
}

/* Compare the scene's pairs (sorted) with the reference list over the same index pairs: every
 * supported pair equal, unsupported pairs may appear only with CDIST_ERR_BAD_KIND. */
static int compare(const char *what, const cdist_scene_pair *got, size_t ng, const tpair *want, size_t nw,
                   const tobj *oa, const tobj *ob)
{
    size_t a = 0, b = 0;
    int bad = 0;
    while (a < ng || b < nw) {
        if (a < ng && got[a].status == CDIST_ERR_BAD_KIND) {
            tpair t;
            if (ref_pair(&oa[got[a].i], got[a].j == SIZE_MAX ? ob : &ob[got[a].j], &t) != 1) bad++;
            a++;
            continue;
        }
        if (a < ng && b < nw && pair_equal(&got[a], &want[b])) {
            a++, b++;
            continue;
        }
        bad++;
        if (bad <= 5) {
            if (a < ng && b < nw)
                fprintf(stderr, "%s: got (%zu,%zu) d=%.17g st=%d, want (%zu,%zu) d=%.17g\n", what, got[a].i, got[a].j,
                        got[a].distance, got[a].status, want[b].i, want[b].j, want[b].d);
            else if (a < ng)
                fprintf(stderr, "%s: extra (%zu,%zu) d=%.17g\n", what, got[a].i, got[a].j, got[a].distance);
            else
                fprintf(stderr, "%s: missing (%zu,%zu) d=%.17g\n", what, want[b].i, want[b].j, want[b].d);
        }
        /* advance the smaller */
        if (a < ng && (b >= nw || got[a].i < want[b].i || (got[a].i == want[b].i && got[a].j < want[b].j))) a++;
        else if (b < nw && (a >= ng || want[b].i < got[a].i || (want[b].i == got[a].i && want[b].j < got[a].j))) b++;
        else a++, b++;
    }
    CHECK(bad == 0, "%s: %d mismatches (%zu got, %zu want)", what, bad, ng, nw);
    return bad;
}

/* All distances of the scene's live pairs (for choosing delta) and the pairs within delta. */
static size_t ref_within(const tobj *o, size_t n, double delta, tpair *out)
{
    size_t m = 0;
    for (size_t i = 0; i < n; i++) {
        if (!o[i].live) continue;
        for (size_t j = i + 1; j < n; j++) {
            if (!o[j].live || skip_ref(o, i, j)) continue;
            tpair t;
            if (ref_pair(&o[i], &o[j], &t) == 0 && t.d <= delta) {
                t.i = i, t.j = j;
                out[m++] = t;
            }
        }
    }
    return m;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* A delta that catches about `frac` of the pairs (exactly one pair's distance: the boundary
 * case <= is exercised). */
static double pick_delta(const tobj *o, size_t n, double frac)
{
    size_t cap = 20000, m = 0;
    double *d = malloc(cap * sizeof *d);
    for (int s = 0; s < 20000; s++) {
        size_t i = next_rand() % n, j = next_rand() % n;
        if (i == j || !o[i].live || !o[j].live) continue;
        tpair t;
        if (ref_pair(&o[i < j ? i : j], &o[i < j ? j : i], &t) == 0) d[m++] = t.d;
    }
    qsort(d, m, sizeof *d, cmp_double);
    double r = m ? d[(size_t)(frac * (double)(m - 1))] : 0.0;
    free(d);
    return r;
}

static cdist_scene *build_scene(const tobj *o, size_t n)
{
    cdist_scene *s = cdist_scene_new();
    for (size_t i = 0; i < n; i++) {
        size_t id;
        cdist_scene_add(Q, s, o[i].kind, 1, &o[i].u, 0, &id, NULL);
        if (id != i) CHECK(0, "id %zu for object %zu", id, i);
        if (o[i].group || o[i].chain) cdist_scene_set_groups(Q, s, 1, &id, &o[i].group, &o[i].chain);
    }
    return s;
}

/* pairs_within with 1 and 2 threads and with the callback: all equal the reference. */
static void check_within(const char *what, cdist_scene *s, const tobj *o, size_t n, double delta)
{
    size_t cap = n * (n - 1) / 2 + 1;
    tpair *want = malloc(cap * sizeof *want);
    size_t nw = ref_within(o, n, delta, want);
    cdist_scene_pair *got = malloc(cap * sizeof *got);
    for (int threads = 1; threads <= 2; threads++) {
        cdist_query_set_threads(Q, threads);
        size_t ng = 0;
        cdist_status st = cdist_scene_pairs_within(Q, s, delta, got, cap, &ng);
        CHECK(st == CDIST_OK || st == CDIST_ERR_BAD_KIND, "%s: status %d (%s)", what, st, cdist_query_last_error(Q));
        char label[160];
        snprintf(label, sizeof label, "%s, %d thread(s), delta %.3g", what, threads, delta);
        compare(label, got, ng, want, nw, o, o);
    }
    cdist_query_set_threads(Q, 1);
    free(want);
    free(got);
}

/* ---- scene generators ---- */

static const cdist_scene_kind all_kinds[] = {CDIST_SCENE_POINT,  CDIST_SCENE_SEGMENT, CDIST_SCENE_CIRCLE,
                                             CDIST_SCENE_DISK,   CDIST_SCENE_ARC,     CDIST_SCENE_SPHERE,
                                             CDIST_SCENE_CAPSULE, CDIST_SCENE_TORUS,  CDIST_SCENE_ROUNDED_DISK};

static void gen_random(tobj *o, size_t n, double box, double size, int mixed)
{
    for (size_t i = 0; i < n; i++) {
        cdist_scene_kind k = mixed ? all_kinds[next_rand() % 9] : CDIST_SCENE_TORUS;
        o[i] = make(k, rvec(box), size, rnd_unit_vec());
    }
}

static void gen_coplanar(tobj *o, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        cdist_scene_kind k = (i % 3 == 0) ? CDIST_SCENE_DISK : (i % 3 == 1 ? CDIST_SCENE_CIRCLE : CDIST_SCENE_TORUS);
        o[i] = make(k, tv(8 * rsym(), 8 * rsym(), 0.0), 1.0, tv(0, 0, (i & 1) ? 1.0 : -1.0));
    }
}

static void gen_concentric(tobj *o, size_t n)
{
    cdist_vec3 c = tv(0.3, -0.2, 0.1);
    for (size_t i = 0; i < n; i++) {
        static const cdist_scene_kind ks[] = {CDIST_SCENE_CIRCLE, CDIST_SCENE_DISK, CDIST_SCENE_TORUS,
                                               CDIST_SCENE_ROUNDED_DISK, CDIST_SCENE_SPHERE};
        cdist_scene_kind k = ks[next_rand() % 5];
        o[i] = make(k, c, 1.0 + (double)(i % 7), (i % 3) ? tv(0, 0, 1) : rnd_unit_vec());
    }
}

static void gen_coaxial(tobj *o, size_t n)
{
    cdist_vec3 ax = tv(0.6, 0.0, 0.8);
    for (size_t i = 0; i < n; i++) {
        double t = 4 * rsym();
        cdist_scene_kind k = (i % 4 == 0) ? CDIST_SCENE_DISK : (i % 4 == 1 ? CDIST_SCENE_TORUS : CDIST_SCENE_CIRCLE);
        if (i % 5 == 4) k = CDIST_SCENE_CAPSULE;
        o[i] = make(k, tv(1 + t * ax.x, 2 + t * ax.y, t * ax.z), 1.0, ax);
        if (k == CDIST_SCENE_CAPSULE) o[i].u.capsule.segment = (cdist_segment){tv(1 - ax.x, 2, -ax.z), tv(1 + ax.x, 2, ax.z)};
    }
}

static void gen_duplicates(tobj *o, size_t n)
{
    gen_random(o, n / 3, 3.0, 1.0, 1);
    for (size_t i = n / 3; i < n; i++) o[i] = o[next_rand() % (n / 3)];
}

static void gen_scales(tobj *o, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        double size = pow(10.0, -6 + 12 * rnd01());
        cdist_vec3 c = rvec(pow(10.0, -6 + 14 * rnd01()));
        /* clusters of tiny objects next to each other and to huge ones */
        if (i % 4 == 1) c = vadd(o[i - 1].u.point, rvec(size));
        o[i] = make(all_kinds[next_rand() % 9], c, size, rnd_unit_vec());
    }
}

static void scenario(const char *name, size_t n, void (*gen)(tobj *, size_t), double frac)
{
    tobj *o = calloc(n, sizeof *o);
    gen(o, n);
    cdist_scene *s = build_scene(o, n);
    double delta = pick_delta(o, n, frac);
    check_within(name, s, o, n, delta);
    check_within(name, s, o, n, 0.0);
    cdist_scene_free(s);
    free(o);
}

static void gen_random_mixed(tobj *o, size_t n) { gen_random(o, n, 10.0, 1.0, 1); }
static void gen_random_tori(tobj *o, size_t n) { gen_random(o, n, 25.0, 1.0, 0); }

/* ---- updates, removals, additions ---- */

/* x moved by d. */
static tobj translate(tobj x, cdist_vec3 d)
{
    switch (x.kind) {
    case CDIST_SCENE_POINT: x.u.point = vadd(x.u.point, d); break;
    case CDIST_SCENE_SEGMENT: x.u.segment.p0 = vadd(x.u.segment.p0, d); x.u.segment.p1 = vadd(x.u.segment.p1, d); break;
    case CDIST_SCENE_SPHERE: x.u.sphere.center = vadd(x.u.sphere.center, d); break;
    case CDIST_SCENE_CAPSULE:
        x.u.capsule.segment.p0 = vadd(x.u.capsule.segment.p0, d);
        x.u.capsule.segment.p1 = vadd(x.u.capsule.segment.p1, d);
        break;
    case CDIST_SCENE_ARC: x.u.arc.circle.center = vadd(x.u.arc.circle.center, d); break;
    default: x.u.circle.center = vadd(x.u.circle.center, d); break;
    }
    return x;
}

static void moving(size_t n, int steps)
{
    size_t cap = n + (size_t)steps * 20;
    tobj *o = calloc(cap, sizeof *o);
    gen_random(o, n, 8.0, 1.0, 1);
    for (size_t i = 0; i < n; i++) {
        if (i < n / 2) o[i].chain = 1 + (unsigned)(i / 5);
        if (i % 13 == 0) o[i].group = 7;
    }
    cdist_scene *s = build_scene(o, n);
    double delta = pick_delta(o, n, 0.05);
    for (int step = 0; step < steps; step++) {
        /* move some a little, some far (out of their boxes) */
        size_t m = 1 + next_rand() % (n / 8);
        size_t *ids = malloc(m * sizeof *ids);
        tobj *no = malloc(m * sizeof *no);
        size_t k = 0;
        for (size_t t = 0; t < m; t++) {
            size_t id = next_rand() % n;
            if (!o[id].live) continue;
            tobj x = translate(o[id], rvec(step % 3 == 0 ? 3.0 : 0.05));
            if (x.kind != CDIST_SCENE_POINT && x.kind != CDIST_SCENE_SEGMENT && x.kind != CDIST_SCENE_SPHERE &&
                x.kind != CDIST_SCENE_CAPSULE)
                x.u.circle.normal = rnd_unit_vec(); /* an arc's circle is its first member */
            ids[k] = id;
            no[k] = x;
            k++;
        }
        /* one kind per update call */
        for (size_t t = 0; t < k; t++) {
            cdist_status st = cdist_scene_update(Q, s, 1, &ids[t], no[t].kind, &no[t].u, 0, NULL);
            CHECK(st == CDIST_OK, "update: %s", cdist_query_last_error(Q));
            o[ids[t]] = (tobj){no[t].kind, no[t].u, 1, o[ids[t]].group, o[ids[t]].chain};
        }
        /* remove a few, add a few */
        for (int t = 0; t < 3; t++) {
            size_t id = next_rand() % n;
            cdist_scene_remove(Q, s, 1, &id);
            o[id].live = 0;
        }
        for (int t = 0; t < 2 && n < cap && step % 2 == 1; t++) {
            o[n] = make(all_kinds[next_rand() % 9], rvec(8.0), 1.0, rnd_unit_vec());
            size_t id;
            cdist_scene_add(Q, s, o[n].kind, 1, &o[n].u, 0, &id, NULL);
            CHECK(id == n, "added id %zu, want %zu", id, n);
            n++;
        }
        char name[64];
        snprintf(name, sizeof name, "moving step %d", step);
        check_within(name, s, o, n, delta);
        free(ids);
        free(no);
    }
    cdist_scene_stats st;
    cdist_scene_get_stats(s, &st);
    CHECK(st.refits > 0, "moving: no refit happened (%zu rebuilds)", st.rebuilds);
    cdist_scene_free(s);
    free(o);
}

/* ---- small motions: the pair list of a moving scene reused ---- */

/* A rough size of the object (for a motion relative to it). */
static double obj_size(const tobj *o)
{
    switch (o->kind) {
    case CDIST_SCENE_POINT: return 1e-3;
    case CDIST_SCENE_SPHERE: return o->u.sphere.radius + 1e-3;
    case CDIST_SCENE_SEGMENT:
    case CDIST_SCENE_CAPSULE: {
        cdist_segment g = o->kind == CDIST_SCENE_SEGMENT ? o->u.segment : o->u.capsule.segment;
        return fabs(g.p1.x - g.p0.x) + fabs(g.p1.y - g.p0.y) + fabs(g.p1.z - g.p0.z);
    }
    default: return o->u.circle.radius;
    }
}

/* When set, tilted normals get lengths other than 1 (run with the unit tolerance INFINITY):
 * unit only to float precision, or 0.1 to 10. */
static int any_length;

static cdist_vec3 tilt(cdist_vec3 n, double e)
{
    cdist_vec3 m = vadd(n, rvec(e));
    double l = sqrt(m.x * m.x + m.y * m.y + m.z * m.z);
    if (any_length) l /= next_rand() % 2 ? 1.0 + 1e-7 * rsym() : pow(10.0, rsym());
    return tv(m.x / l, m.y / l, m.z / l);
}

/* Move object o by about eps times its size: translation, tilt, radius and ball radius
 * changes, now and then a flipped normal (the same circle), a reversed segment (the same
 * segment), no change at all, or a change of kind with the same core (torus and circle,
 * sphere and point); arcs move rarely (their motion has no bound: the list is made again). */
static void nudge(tobj *o, double eps)
{
    double e = eps * obj_size(o);
    int what = (int)(next_rand() % 8);
    if (what == 0) return;
    switch (o->kind) {
    case CDIST_SCENE_POINT: o->u.point = vadd(o->u.point, rvec(e)); break;
    case CDIST_SCENE_SPHERE:
        o->u.sphere.center = vadd(o->u.sphere.center, rvec(e));
        if (what == 1) o->kind = CDIST_SCENE_POINT;
        else o->u.sphere.radius = fabs(o->u.sphere.radius + e * rsym());
        break;
    case CDIST_SCENE_SEGMENT:
    case CDIST_SCENE_CAPSULE: {
        cdist_segment *g = o->kind == CDIST_SCENE_SEGMENT ? &o->u.segment : &o->u.capsule.segment;
        if (what == 1) {
            cdist_vec3 t = g->p0;
            g->p0 = g->p1, g->p1 = t;
        } else {
            g->p0 = vadd(g->p0, rvec(e)), g->p1 = vadd(g->p1, rvec(e));
        }
        if (o->kind == CDIST_SCENE_CAPSULE) o->u.capsule.radius = fabs(o->u.capsule.radius + e * rsym());
        break;
    }
    case CDIST_SCENE_ARC:
        if (what == 1) o->u.arc.circle.center = vadd(o->u.arc.circle.center, rvec(e));
        break;
    default: {
        cdist_circle *c = &o->u.circle;
        c->center = vadd(c->center, rvec(e));
        c->normal = what == 1 ? tv(-c->normal.x, -c->normal.y, -c->normal.z) : tilt(c->normal, eps);
        c->radius = fabs(c->radius + e * rsym()) + 1e-300;
        if (o->kind == CDIST_SCENE_TORUS) {
            o->u.torus.tube_radius = fabs(o->u.torus.tube_radius + e * rsym());
            if (what == 2) o->kind = CDIST_SCENE_CIRCLE;
        } else if (o->kind == CDIST_SCENE_CIRCLE && what == 2) {
            o->kind = CDIST_SCENE_TORUS;
            o->u.torus.tube_radius = e;
        } else if (o->kind == CDIST_SCENE_ROUNDED_DISK) {
            o->u.rdisk.radius = fabs(o->u.rdisk.radius + e * rsym());
        }
        break;
    }
    }
}

/* Every object nudged a little at each step (some steps only a few), then pairs within a delta
 * that changes from step to step (0, negative, about 5% and 20% of the pairs): equal to the
 * loop for 1 and 2 threads; the list must have been reused. */
static void drifting(const char *name, size_t n, void (*gen)(tobj *, size_t), int steps)
{
    size_t cap = n + 2;
    tobj *o = calloc(cap, sizeof *o);
    gen(o, n);
    for (size_t i = 0; i < n; i += 11) o[i].chain = 3;
    /* one invalid object (a zero normal), revived half-way */
    size_t bad_id = n;
    o[n] = o[0];
    o[n].u.circle.normal = tv(0, 0, 0);
    o[n].kind = CDIST_SCENE_CIRCLE;
    o[n].live = 0;
    o[n].group = o[n].chain = 0;
    n++;
    cdist_scene *s = build_scene(o, n);
    double delta = pick_delta(o, n, 0.05);
    check_within(name, s, o, n, delta);
    for (int step = 0; step < steps; step++) {
        double eps = step % 3 == 2 ? 1e-9 : 1e-3 * (1 + step % 4);
        for (size_t i = 0; i < n; i++) {
            if (!o[i].live || (step % 4 == 3 && next_rand() % 10)) continue;
            if (o[i].kind == CDIST_SCENE_ARC && next_rand() % 4) continue;
            tobj x = o[i];
            nudge(&x, eps);
            cdist_status st = cdist_scene_update(Q, s, 1, &i, x.kind, &x.u, 0, NULL);
            CHECK(st == CDIST_OK, "%s: update %zu: %s", name, i, cdist_query_last_error(Q));
            x.group = o[i].group, x.chain = o[i].chain, x.live = o[i].live;
            o[i] = x;
        }
        if (step == steps / 2 && n < cap) {
            /* an addition next to an object, and an invalid object revived there: the list
             * lacks their pairs */
            o[n] = o[next_rand() % n];
            nudge(&o[n], 1e-3);
            o[n].group = o[n].chain = 0;
            size_t id;
            cdist_scene_add(Q, s, o[n].kind, 1, &o[n].u, 0, &id, NULL);
            CHECK(id == n, "%s: added id %zu, want %zu", name, id, n);
            n++;
            if (bad_id != SIZE_MAX) {
                o[bad_id] = o[next_rand() % bad_id];
                o[bad_id].group = o[bad_id].chain = 0;
                cdist_status st = cdist_scene_update(Q, s, 1, &bad_id, o[bad_id].kind, &o[bad_id].u, 0, NULL);
                CHECK(st == CDIST_OK, "%s: revive: %s", name, cdist_query_last_error(Q));
                o[bad_id].live = 1;
                bad_id = SIZE_MAX;
            }
        }
        static const double frac[] = {0.05, 0.2, 0.01, 0.05};
        double d = step % 5 == 4 ? 0.0 : pick_delta(o, n, frac[step % 4]);
        if (step % 7 == 6) d = -0.01 * fabs(delta);
        char label[96];
        snprintf(label, sizeof label, "%s drifting step %d", name, step);
        check_within(label, s, o, n, d);
    }
    CHECK(s->list_reuses > 0, "%s: the pair list was never reused (%zu made)", name, s->list_builds);
    cdist_scene_free(s);
    free(o);
}

/* Two objects: after each small motion, delta exactly their new computed distance reports the
 * pair and one ulp below does not (the list's bounds and the motion bounds meet their exact
 * boundary: without their margins pairs are lost). */
static void drifting_boundary(int count)
{
    int missed = 0, extra = 0;
    for (int t = 0; t < count; t++) {
        tobj o[2];
        double size = pow(10.0, -3 + 6 * rnd01());
        for (int k = 0; k < 2; k++)
            o[k] = make(all_kinds[next_rand() % 9], vadd(rvec(2 * size), tv(1e3 * size, 0, 0)), size, rnd_unit_vec());
        cdist_scene *s = build_scene(o, 2);
        cdist_scene_pair got[2];
        size_t ng = 0;
        for (int step = 0; step < 4; step++) {
            size_t id = next_rand() % 2;
            nudge(&o[id], step == 0 ? 1e-3 : pow(10.0, -14 + 4 * step));
            cdist_scene_update(Q, s, 1, &id, o[id].kind, &o[id].u, 0, NULL);
            tpair r;
            if (ref_pair(&o[0], &o[1], &r) != 0) break;
            cdist_scene_pairs_within(Q, s, r.d, got, 2, &ng);
            missed += ng != 1;
            cdist_scene_pairs_within(Q, s, nextafter(r.d, -INFINITY), got, 2, &ng);
            extra += ng != 0;
        }
        cdist_scene_free(s);
    }
    CHECK(missed == 0 && extra == 0, "drifting boundary: %d pairs missed at delta = distance, %d reported below it",
          missed, extra);
}

/* A circle with a normal of length 0.1 (unit tolerance INFINITY) turned by 0.2 towards a point
 * above its rim: the distance falls by 0.198, the motion bound must be the unit normals' turn
 * (0.19967), not the given normals' (0.02), or the pair list skips the pair. */
static void turning_short_normal(void)
{
    double unit_tol = cdist_query_get_unit_tolerance(Q);
    cdist_query_set_unit_tolerance(Q, INFINITY);
    cdist_circle c = {{0, 0, 0}, {0, 0, 0.1}, 1.0};
    cdist_vec3 p = {1, 0, 0.5};
    cdist_scene *s = cdist_scene_new();
    CHECK(cdist_scene_add(Q, s, CDIST_SCENE_CIRCLE, 1, &c, 0, NULL, NULL) == CDIST_OK &&
              cdist_scene_add(Q, s, CDIST_SCENE_POINT, 1, &p, 0, NULL, NULL) == CDIST_OK,
          "turning short normal: add: %s", cdist_query_last_error(Q));
    cdist_scene_pair got[2];
    size_t ng = 0, id = 0;
    for (int step = 0; step < 3; step++) { /* small moves, after a first query: the list is made */
        c.center.x += 0.01 * (step % 2 ? -1 : 1);
        cdist_scene_update(Q, s, 1, &id, CDIST_SCENE_CIRCLE, &c, 0, NULL);
        cdist_scene_pairs_within(Q, s, 0.6, got, 2, &ng);
    }
    double t = 0.2;
    c.normal = tv(-0.1 * sin(t), 0, 0.1 * cos(t));
    cdist_scene_update(Q, s, 1, &id, CDIST_SCENE_CIRCLE, &c, 0, NULL);
    cdist_result r;
    cdist_point_circle(Q, &p, &c, &r);
    cdist_status st = cdist_scene_pairs_within(Q, s, r.distance, got, 2, &ng);
    CHECK(st == CDIST_OK && ng == 1 && got[0].distance == r.distance && r.distance < 0.31,
          "turning short normal: %zu pairs within %.17g (status %d)", ng, r.distance, st);
    CHECK(s->list_reuses > 0, "turning short normal: the pair list was not used (%zu made)", s->list_builds);
    cdist_scene_free(s);
    cdist_query_set_unit_tolerance(Q, unit_tol);
}

/* delta = -(r_a + r_b), "the cores meet", for identical tori: the screen's cutoff is computed
 * from terms that cancel, far below their ulp (stepping ulp by ulp from there does not end). */
static void cores_meet(void)
{
    static const double tube[] = {0.1, 0.25, 0.3, 0.5, 1e-9, 3e5};
    for (size_t t = 0; t < sizeof tube / sizeof tube[0]; t++) {
        cdist_torus tor[2] = {{{{0, 0, 0}, {0, 0, 1}, 1.0}, tube[t]}, {{{0, 0, 0}, {0, 0, 1}, 1.0}, tube[t]}};
        cdist_scene *s = cdist_scene_new();
        cdist_scene_add(Q, s, CDIST_SCENE_TORUS, 2, tor, sizeof tor[0], NULL, NULL);
        cdist_scene_pair got[2];
        size_t ng = 0;
        double delta = -(tube[t] + tube[t]);
        cdist_status st = cdist_scene_pairs_within(Q, s, delta, got, 2, &ng);
        CHECK(st == CDIST_OK && ng == 1 && got[0].distance == delta, "cores meet, tube %g: status %d, %zu pairs",
              tube[t], st, ng);
        st = cdist_scene_pairs_within(Q, s, nextafter(delta, -INFINITY), got, 2, &ng);
        CHECK(st == CDIST_OK && ng == 0, "cores meet, tube %g, below: status %d, %zu pairs", tube[t], st, ng);
        cdist_scene_free(s);
    }
}

/* Closest pair and nearest on scenes with pairs that have no exact query (a point or sphere
 * against an arc): the status and answer depend on the objects alone, not on the tree's order.
 * Scene a is built at the poses; scene b is built with the objects permuted and then updated to
 * them (the refit keeps b's order). */
static void unanswered_order(int count)
{
    static const cdist_scene_kind kinds[] = {CDIST_SCENE_POINT, CDIST_SCENE_SPHERE, CDIST_SCENE_ARC, CDIST_SCENE_TORUS};
    int differ = 0, failing = 0;
    for (int t = 0; t < count; t++) {
        enum { N = 12 };
        tobj o[N], p[N];
        for (int i = 0; i < N; i++)
            o[i] = make(kinds[next_rand() % 4], rvec(t % 2 ? 10.0 : 40.0), 1.0, rnd_unit_vec());
        for (int i = 0; i < N; i++) p[i] = o[(i + 5) % N];
        cdist_scene *a = build_scene(o, N), *b = build_scene(p, N);
        cdist_scene_pair ra, rb;
        cdist_scene_closest_pair(Q, b, &rb);
        for (size_t i = 0; i < N; i++) cdist_scene_update(Q, b, 1, &i, o[i].kind, &o[i].u, 0, NULL);
        cdist_status sa = cdist_scene_closest_pair(Q, a, &ra), sb = cdist_scene_closest_pair(Q, b, &rb);
        differ += sa != sb || ra.i != rb.i || ra.j != rb.j || memcmp(&ra.distance, &rb.distance, sizeof ra.distance);
        failing += sa != CDIST_OK;
        cdist_sphere qs = {rvec(10.0), 0.5};
        cdist_scene_pair na[3], nb[3];
        size_t ca = 0, cb = 0;
        sa = cdist_scene_nearest(Q, a, CDIST_SCENE_SPHERE, &qs, 3, na, &ca);
        sb = cdist_scene_nearest(Q, b, CDIST_SCENE_SPHERE, &qs, 3, nb, &cb);
        differ += sa != sb || ca != cb;
        for (size_t k = 0; k < ca && k < cb; k++) differ += na[k].i != nb[k].i;
        cdist_scene_free(a);
        cdist_scene_free(b);
    }
    CHECK(differ == 0, "unanswered pairs: %d of %d scenes answer differently after updates", differ, count);
    CHECK(failing > 0 && failing < count, "unanswered pairs: %d of %d closest-pair queries failed (want some)", failing,
          count);
}

/* ---- closest pair, nearest, within, between ---- */

static void others(size_t n)
{
    tobj *o = calloc(n, sizeof *o), *p = calloc(n, sizeof *p);
    gen_random(o, n, 10.0, 1.0, 1);
    gen_random(p, n, 10.0, 1.0, 1);
    /* no point-arc pairs here: closest and nearest need every pair answered */
    for (size_t i = 0; i < n; i++) {
        if (o[i].kind == CDIST_SCENE_POINT) o[i] = make(CDIST_SCENE_SPHERE, o[i].u.point, 1.0, rnd_unit_vec());
        if (p[i].kind == CDIST_SCENE_ARC) p[i] = make(CDIST_SCENE_TORUS, p[i].u.circle.center, 1.0, p[i].u.circle.normal);
        if (p[i].kind == CDIST_SCENE_POINT) p[i] = make(CDIST_SCENE_SPHERE, p[i].u.point, 1.0, rnd_unit_vec());
        if (o[i].kind == CDIST_SCENE_ARC) o[i] = make(CDIST_SCENE_TORUS, o[i].u.circle.center, 1.0, o[i].u.circle.normal);
    }
    cdist_scene *a = build_scene(o, n), *b = build_scene(p, n);
    /* closest pair */
    tpair best = {0};
    best.d = INFINITY;
    for (size_t i = 0; i < n; i++)
        for (size_t j = i + 1; j < n; j++) {
            tpair t;
            if (ref_pair(&o[i], &o[j], &t) == 0 && t.d < best.d) best = t, best.i = i, best.j = j;
        }
    cdist_scene_pair cp;
    cdist_status st = cdist_scene_closest_pair(Q, a, &cp);
    CHECK(st == CDIST_OK && pair_equal(&cp, &best), "closest pair: (%zu,%zu) %.17g vs (%zu,%zu) %.17g", cp.i, cp.j,
          cp.distance, best.i, best.j, best.d);
    /* closest between and pairs between */
    best.d = INFINITY;
    double delta = 0.5;
    tpair *want = malloc(n * n * sizeof *want);
    size_t nw = 0;
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++) {
            tpair t;
            if (ref_pair(&o[i], &p[j], &t) != 0) continue;
            t.i = i, t.j = j;
            if (t.d < best.d) best = t;
            if (t.d <= delta) want[nw++] = t;
        }
    st = cdist_scene_closest_pair_between(Q, a, b, &cp);
    CHECK(st == CDIST_OK && pair_equal(&cp, &best), "closest between: (%zu,%zu) %.17g vs (%zu,%zu) %.17g", cp.i, cp.j,
          cp.distance, best.i, best.j, best.d);
    cdist_scene_pair *got = malloc(n * n * sizeof *got);
    size_t ng;
    for (int threads = 1; threads <= 2; threads++) {
        cdist_query_set_threads(Q, threads);
        st = cdist_scene_pairs_between(Q, a, b, delta, got, n * n, &ng);
        CHECK(st == CDIST_OK, "pairs between: %s", cdist_query_last_error(Q));
        compare("pairs between", got, ng, want, nw, o, p);
    }
    cdist_query_set_threads(Q, 1);
    /* nearest k and within delta of each kind of query object */
    for (int t = 0; t < 9; t++) {
        tobj x = make(all_kinds[t], rvec(10.0), 1.0, rnd_unit_vec());
        nw = 0;
        for (size_t i = 0; i < n; i++) {
            tpair r;
            if (ref_pair(&o[i], &x, &r) != 0) continue;
            r.i = i, r.j = SIZE_MAX;
            want[nw++] = r;
        }
        /* within */
        size_t m = 0;
        for (size_t k = 0; k < nw; k++)
            if (want[k].d <= 1.0) want[m++] = want[k];
        st = cdist_scene_within(Q, a, x.kind, &x.u, 1.0, got, n, &ng);
        CHECK(st == CDIST_OK || st == CDIST_ERR_BAD_KIND, "within: %s", cdist_query_last_error(Q));
        compare("within", got, ng, want, m, o, &x);
        /* nearest 5 */
        nw = 0;
        for (size_t i = 0; i < n; i++) {
            tpair r;
            if (ref_pair(&o[i], &x, &r) != 0) continue;
            r.i = i, r.j = SIZE_MAX;
            size_t at = nw++;
            while (at > 0 && (want[at - 1].d > r.d || (want[at - 1].d == r.d && want[at - 1].i > i))) {
                want[at] = want[at - 1];
                at--;
            }
            want[at] = r;
        }
        if (all_kinds[t] == CDIST_SCENE_POINT || all_kinds[t] == CDIST_SCENE_ARC) continue;
        st = cdist_scene_nearest(Q, a, x.kind, &x.u, 5, got, &ng);
        CHECK(st == CDIST_OK && ng == 5, "nearest: %s (%zu)", cdist_query_last_error(Q), ng);
        for (size_t k = 0; k < ng && k < 5; k++)
            CHECK(pair_equal(&got[k], &want[k]), "nearest %zu of kind %d: %zu %.17g vs %zu %.17g", k, t, got[k].i,
                  got[k].distance, want[k].i, want[k].d);
    }
    free(want);
    free(got);
    cdist_scene_free(a);
    cdist_scene_free(b);
    free(o);
    free(p);
}

/* ---- the pair query against the public single queries ---- */

static void public_agreement(void)
{
    for (int t = 0; t < 300; t++) {
        tobj a = make(CDIST_SCENE_TORUS, rvec(2), 1, rnd_unit_vec()), b = make(CDIST_SCENE_TORUS, rvec(2), 1, rnd_unit_vec());
        tobj c = make(CDIST_SCENE_CAPSULE, rvec(2), 1, rnd_unit_vec()), d = make(CDIST_SCENE_SPHERE, rvec(2), 1, rnd_unit_vec());
        tobj e = make(CDIST_SCENE_CIRCLE, rvec(2), 1, rnd_unit_vec());
        tpair r;
        cdist_contact k;
        cdist_result res;
        ref_pair(&a, &b, &r);
        cdist_torus_torus(Q, &a.u.torus, &b.u.torus, &k);
        CHECK(same_bits(r.d, k.distance), "torus-torus %.17g vs %.17g", r.d, k.distance);
        ref_pair(&a, &c, &r);
        cdist_torus_capsule(Q, &a.u.torus, &c.u.capsule, &k);
        CHECK(same_bits(r.d, k.distance), "torus-capsule %.17g vs %.17g", r.d, k.distance);
        ref_pair(&d, &c, &r);
        cdist_capsule_sphere(Q, &c.u.capsule, &d.u.sphere, &k);
        CHECK(same_bits(r.d, k.distance), "sphere-capsule %.17g vs %.17g", r.d, k.distance);
        ref_pair(&e, &a, &r);
        cdist_circle_circle(Q, &e.u.circle, &a.u.torus.circle, &res);
        CHECK(same_bits(r.d, res.distance - a.u.torus.tube_radius), "circle-torus %.17g vs %.17g", r.d,
              res.distance - a.u.torus.tube_radius);
    }
}

/* ---- the boundary: delta equal to a pair's distance ---- */

/* Two objects, delta exactly their computed distance: the pair is reported; one ulp below: it
 * is not. Every bound meets its exact boundary here (axis-aligned and tilted objects, touching
 * boxes, shared planes), so a bound without its rounding margin loses pairs. */
static void boundary(int count)
{
    int missed = 0, extra = 0;
    for (int t = 0; t < count; t++) {
        tobj o[2];
        double size = pow(10.0, -3 + 6 * rnd01());
        cdist_vec3 n = (t % 3 == 0) ? tv(0, 0, 1) : rnd_unit_vec();
        for (int k = 0; k < 2; k++) {
            cdist_vec3 c = (t % 2 == 0) ? tv(size * (double)(next_rand() % 8), 0.0, 0.0) : rvec(3 * size);
            o[k] = make(all_kinds[next_rand() % 9], vadd(c, tv(1e3 * size, 0, 0)), size, (t % 3 == 0) ? n : rnd_unit_vec());
        }
        tpair r;
        if (ref_pair(&o[0], &o[1], &r) != 0) continue;
        cdist_scene *s = build_scene(o, 2);
        cdist_scene_pair got[2];
        size_t ng = 0;
        cdist_scene_pairs_within(Q, s, r.d, got, 2, &ng);
        missed += ng != 1;
        cdist_scene_pairs_within(Q, s, nextafter(r.d, -INFINITY), got, 2, &ng);
        extra += ng != 0;
        cdist_scene_free(s);
    }
    CHECK(missed == 0 && extra == 0, "boundary: %d pairs missed at delta = distance, %d reported below it", missed,
          extra);
}

/* Objects that change kind in place, also into and out of arcs (kept beside the objects), in a
 * scene that had no arc: the pairs still equal the reference. */
static void kind_changes(size_t n)
{
    tobj *o = calloc(n, sizeof *o);
    gen_random_tori(o, n);
    cdist_scene *s = build_scene(o, n);
    for (int round = 0; round < 4; round++) {
        for (int k = 0; k < 12; k++) {
            size_t id = next_rand() % n;
            cdist_scene_kind kind = round % 2 == 0 || k % 3 == 0 ? CDIST_SCENE_ARC : all_kinds[next_rand() % 9];
            o[id] = make(kind, o[id].u.circle.center, 1.0, rnd_unit_vec());
            cdist_status st = cdist_scene_update(Q, s, 1, &id, o[id].kind, &o[id].u, 0, NULL);
            CHECK(st == CDIST_OK, "kind change of %zu: %s", id, cdist_query_last_error(Q));
        }
        check_within("kind changes", s, o, n, pick_delta(o, n, 0.05));
    }
    cdist_scene_free(s);
    free(o);
}

/* The outward rounding of the boxes' corners: below (above) x, within three float ulps, also
 * at zero, the subnormals, the overflow and infinities. */
static void float_rounding(void)
{
    const double special[] = {0.0, -0.0, 1e-320, -1e-320, 0x1p-149, -0x1p-149, 0x1p-150, -0x1p-150, 1.0, -1.0, 0.1,
                              -0.1, 16777217.0, -16777217.0, FLT_MAX, -FLT_MAX, 3.40282356e38, -3.40282356e38, 1e39,
                              -1e39, 1e300, -1e300, INFINITY, -INFINITY};
    int bad = 0, loose = 0, ns = (int)(sizeof special / sizeof special[0]);
    for (int t = 0; t < ns + 200000; t++) {
        double x = t < ns ? special[t] : ldexp(rsym(), (int)(next_rand() % 300) - 150);
        if (t >= ns && t % 2) x = (float)x; /* floats themselves: no step needed, one allowed */
        float d = cdist__float_down(x), u = cdist__float_up(x);
        bad += !((double)d <= x) || !((double)u >= x);
        if (isfinite(x) && fabs(x) > 0x1p-126 && fabs(x) < 0x1p127)
            loose += x - d > 0x1p-21 * fabs(x) || u - x > 0x1p-21 * fabs(x);
    }
    CHECK(bad == 0 && loose == 0, "float rounding: %d on the wrong side, %d more than three ulps away", bad, loose);
}

/* ---- bad input ---- */

static void bad_input(void)
{
    cdist_scene *s = cdist_scene_new();
    cdist_torus t[4];
    for (int i = 0; i < 4; i++) t[i] = (cdist_torus){{tv(3.0 * i, 0, 0), tv(0, 0, 1), 1.0}, 0.1};
    t[1].circle.normal = tv(0, 0, 0);
    t[2].tube_radius = -1;
    cdist_status sts[4];
    size_t first;
    cdist_status st = cdist_scene_add(Q, s, CDIST_SCENE_TORUS, 4, t, sizeof t[0], &first, sts);
    CHECK(st == CDIST_ERR_ZERO_VECTOR && first == 0, "add: %d", st);
    CHECK(sts[0] == 0 && sts[1] == CDIST_ERR_ZERO_VECTOR && sts[2] == CDIST_ERR_NEGATIVE_RADIUS && sts[3] == 0,
          "statuses %d %d %d %d", sts[0], sts[1], sts[2], sts[3]);
    CHECK(strstr(cdist_query_last_error(Q), "entry 1") != NULL, "message: %s", cdist_query_last_error(Q));
    CHECK(cdist_scene_count(s) == 4 && cdist_scene_object_status(s, 1) == CDIST_ERR_ZERO_VECTOR &&
              cdist_scene_object_status(s, 3) == CDIST_OK && cdist_scene_object_status(s, 9) == CDIST_ERR_OUT_OF_RANGE,
          "object statuses");
    cdist_scene_pair out[8];
    size_t cnt = 99;
    CHECK(cdist_scene_pairs_within(Q, s, NAN, out, 8, &cnt) == CDIST_ERR_NOT_FINITE && cnt == 0, "NaN delta");
    CHECK(cdist_scene_pairs_within(Q, s, 1.0, NULL, 3, &cnt) == CDIST_ERR_NULL_ARGUMENT, "NULL output");
    CHECK(cdist_scene_pairs_within(Q, s, 10.0, NULL, 0, &cnt) == CDIST_OK && cnt == 1, "count only: %zu", cnt);
    CHECK(cdist_scene_pairs_within(Q, s, 10.0, out, 8, &cnt) == CDIST_OK && cnt == 1 && out[0].i == 0 && out[0].j == 3,
          "valid pair kept: %zu", cnt);
    /* Linked pairs: the valid rings 0 and 3 are apart; the invalid ones take no part. */
    cdist_scene_link lk[4];
    CHECK(cdist_scene_linked_pairs(Q, s, NULL, 3, &cnt) == CDIST_ERR_NULL_ARGUMENT, "linked pairs: NULL output");
    CHECK(cdist_scene_linked_pairs(NULL, s, lk, 4, &cnt) == CDIST_ERR_NULL_ARGUMENT, "linked pairs: NULL handle");
    CHECK(cdist_scene_linked_pairs(Q, NULL, lk, 4, &cnt) == CDIST_ERR_NULL_ARGUMENT, "linked pairs: NULL scene");
    CHECK(cdist_scene_linked_pairs(Q, s, lk, 4, &cnt) == CDIST_OK && cnt == 0, "linked pairs: %zu", cnt);
    {
        /* Two linked rings (one through the other's centre): counted with capacity 0, then given. */
        cdist_scene *s2 = cdist_scene_new();
        cdist_circle c[2] = {{tv(0, 0, 0), tv(0, 0, 1), 1.0}, {tv(1, 0, 0), tv(0, 1, 0), 1.0}};
        cdist_link want;
        CHECK(cdist_scene_add(Q, s2, CDIST_SCENE_CIRCLE, 2, c, sizeof c[0], NULL, NULL) == CDIST_OK, "add circles");
        CHECK(cdist_scene_linked_pairs(Q, s2, NULL, 0, &cnt) == CDIST_OK && cnt == 1, "linked count: %zu", cnt);
        CHECK(cdist_scene_linked_pairs(Q, s2, lk, 4, &cnt) == CDIST_OK && cnt == 1 && lk[0].i == 0 && lk[0].j == 1,
              "linked pair: %zu", cnt);
        CHECK(cdist_link_circles(Q, &c[0], &c[1], &want) == CDIST_OK && lk[0].link.linking == want.linking &&
                  (want.linking == 1 || want.linking == -1) && same_bits(lk[0].link.distance, want.distance),
              "linked value %d vs %d", lk[0].link.linking, want.linking);
        cdist_scene_free(s2);
    }
    {
        /* Time of impact: the live tori 0 and 3 (centres 9 apart, radii 1, tubes 0.1) meet after 6.8 of 8. */
        cdist_motion m[4];
        memset(m, 0, sizeof m);
        m[3].translation = tv(-8.0, 0, 0);
        cdist_scene_toi_result r;
        CHECK(cdist_scene_toi(Q, s, m, sizeof m[0], 0.0, 1e-12, 1000, &r) == CDIST_OK && r.i == 0 && r.j == 3 &&
                  r.toi.state == CDIST_TOI_HIT && fabs(r.toi.t - 0.85) < 1e-9,
              "scene toi: (%zu, %zu) t %.17g", r.i, r.j, r.toi.t);
        CHECK(cdist_scene_toi(Q, s, NULL, 0, 0.0, 1e-12, 1000, &r) == CDIST_OK && r.i == SIZE_MAX &&
                  r.toi.state == CDIST_TOI_NONE,
              "scene toi, still: %zu", r.i);
        CHECK(cdist_scene_toi(Q, s, m, 0, NAN, 1e-12, 1000, &r) == CDIST_ERR_NOT_FINITE, "scene toi: NaN target");
        CHECK(cdist_scene_toi(Q, s, m, 0, 0.0, 0.0, 1000, &r) == CDIST_ERR_BAD_OPTION, "scene toi: tolerance 0");
        CHECK(cdist_scene_toi(Q, s, m, 0, 0.0, 1e-12, 0, &r) == CDIST_ERR_BAD_OPTION, "scene toi: cap 0");
        CHECK(cdist_scene_toi(Q, s, m, 0, 0.0, 1e-12, 1000, NULL) == CDIST_ERR_NULL_ARGUMENT, "scene toi: NULL out");
        m[2].rotation = tv(INFINITY, 0, 0); /* object 2 is invalid: its motion is ignored */
        CHECK(cdist_scene_toi(Q, s, m, 0, 0.0, 1e-12, 1000, &r) == CDIST_OK && r.i == 0 && r.j == 3,
              "scene toi: motion of an invalid object");
        m[3].rotation = tv(NAN, 0, 0);
        CHECK(cdist_scene_toi(Q, s, m, 0, 0.0, 1e-12, 1000, &r) == CDIST_ERR_NOT_FINITE, "scene toi: bad motion");
    }
    size_t ids[2] = {0, 17};
    CHECK(cdist_scene_update(Q, s, 2, ids, CDIST_SCENE_TORUS, t, 0, sts) == CDIST_ERR_OUT_OF_RANGE && sts[0] == 0 &&
              sts[1] == CDIST_ERR_OUT_OF_RANGE,
          "update out of range");
    CHECK(cdist_scene_remove(Q, s, 2, ids) == CDIST_ERR_OUT_OF_RANGE, "remove out of range");
    CHECK(cdist_scene_object_status(s, 0) == CDIST_ERR_OUT_OF_RANGE, "removed");
    CHECK(cdist_scene_update(Q, s, 1, ids, CDIST_SCENE_TORUS, t, 0, sts) == CDIST_ERR_OUT_OF_RANGE, "update removed");
    /* the invalid object made valid */
    size_t one = 1;
    t[1].circle.normal = tv(0, 0, 1);
    CHECK(cdist_scene_update(Q, s, 1, &one, CDIST_SCENE_TORUS, &t[1], 0, NULL) == CDIST_OK, "revive");
    CHECK(cdist_scene_pairs_within(Q, s, 10.0, out, 8, &cnt) == CDIST_OK && cnt == 1 && out[0].i == 1 && out[0].j == 3,
          "revived pair: %zu", cnt);
    CHECK(cdist_scene_add(Q, s, (cdist_scene_kind)42, 1, t, 0, NULL, NULL) == CDIST_ERR_BAD_KIND, "bad kind");
    CHECK(cdist_scene_pairs_within(NULL, s, 1.0, out, 8, &cnt) == CDIST_ERR_NULL_ARGUMENT, "NULL handle");
    CHECK(cdist_scene_pairs_within(Q, NULL, 1.0, out, 8, &cnt) == CDIST_ERR_NULL_ARGUMENT, "NULL scene");
    /* point-arc: reported with its status, never approximated */
    cdist_scene *u = cdist_scene_new();
    cdist_vec3 pt = tv(0, 0, 0.5);
    cdist_arc arc = {{tv(0, 0, 0), tv(0, 0, 1), 1.0}, tv(1, 0, 0), 0.0, 1.0};
    cdist_scene_add(Q, u, CDIST_SCENE_POINT, 1, &pt, 0, NULL, NULL);
    cdist_scene_add(Q, u, CDIST_SCENE_ARC, 1, &arc, 0, NULL, NULL);
    st = cdist_scene_pairs_within(Q, u, 5.0, out, 8, &cnt);
    CHECK(st == CDIST_ERR_BAD_KIND && cnt == 1 && out[0].status == CDIST_ERR_BAD_KIND && isnan(out[0].distance),
          "point-arc: %d %zu", st, cnt);
    /* capacity too small: the count of all, the first ones written */
    cdist_scene *v = cdist_scene_new();
    cdist_sphere sp[6];
    for (int i = 0; i < 6; i++) sp[i] = (cdist_sphere){tv(0.1 * i, 0, 0), 1.0};
    cdist_scene_add(Q, v, CDIST_SCENE_SPHERE, 6, sp, sizeof sp[0], NULL, NULL);
    CHECK(cdist_scene_pairs_within(Q, v, 0.0, out, 4, &cnt) == CDIST_OK && cnt == 15, "count %zu", cnt);
    CHECK(out[0].i == 0 && out[0].j == 1 && out[3].i == 0 && out[3].j == 4, "prefix order");
    cdist_scene_free(s);
    cdist_scene_free(u);
    cdist_scene_free(v);
}

/* ---- any sequence of operations ---- */

static cdist_vec3 center_of(const tobj *o)
{
    switch (o->kind) {
    case CDIST_SCENE_POINT: return o->u.point;
    case CDIST_SCENE_SEGMENT: return o->u.segment.p0;
    case CDIST_SCENE_SPHERE: return o->u.sphere.center;
    case CDIST_SCENE_CAPSULE: return o->u.capsule.segment.p0;
    case CDIST_SCENE_ARC: return o->u.arc.circle.center;
    default: return o->u.circle.center;
    }
}

/* Another kind in the same place (any kind to any kind: the motion bound is then infinite). */
static tobj rekind(const tobj *o, cdist_scene_kind k)
{
    tobj x = make(k, center_of(o), obj_size(o) + 1e-3, rnd_unit_vec());
    x.group = o->group, x.chain = o->chain, x.live = o->live;
    return x;
}

/* An invalid pose of the object's kind (NaN, infinite, negative radius, zero normal). */
static tobj invalid_of(const tobj *o)
{
    tobj x = *o;
    int w = (int)(next_rand() % 3);
    double bad = w == 0 ? NAN : (w == 1 ? INFINITY : -INFINITY);
    switch (x.kind) {
    case CDIST_SCENE_POINT: x.u.point.y = bad; break;
    case CDIST_SCENE_SEGMENT: x.u.segment.p1.z = bad; break;
    case CDIST_SCENE_SPHERE: x.u.sphere.radius = w == 2 ? -1.0 : bad; break;
    case CDIST_SCENE_CAPSULE: x.u.capsule.radius = w == 2 ? -1.0 : bad; break;
    case CDIST_SCENE_ARC: x.u.arc.circle.normal = tv(0, 0, 0); break;
    default:
        if (w == 2) x.u.circle.normal = tv(0, 0, 0);
        else x.u.circle.center.x = bad;
        break;
    }
    return x;
}

/* Deltas a caller may pass: 0, negative, hugely negative, beyond any list's reach, infinite,
 * tiny, or one pair's distance. */
static double churn_delta(const tobj *o, size_t n)
{
    int r = (int)(next_rand() % 12);
    switch (r) {
    case 0: return 0.0;
    case 1: return -0.01 * (1 + rnd01());
    case 2: return -1e300;
    case 3: return 1e3 * (1 + rnd01());
    case 4: return INFINITY;
    case 5: return 1e-12;
    default: return pick_delta(o, n, r == 6 ? 0.3 : 0.03);
    }
}

/* pairs_within against the loop, with 1 or 2 threads, through the callback, or with a capacity
 * below the count (which must be the full count, the pairs given a prefix of the full answer). */
typedef struct churn_acc {
    cdist_scene_pair *p;
    size_t n, cap;
} churn_acc;
static int churn_cb(void *u, const cdist_scene_pair *p, size_t n)
{
    churn_acc *a = u;
    for (size_t k = 0; k < n; k++, a->n++)
        if (a->n < a->cap) a->p[a->n] = p[k];
    return 0;
}

static void churn_within(const char *what, cdist_scene *s, const tobj *o, size_t n, double delta)
{
    size_t cap = n * (n - 1) / 2 + 1;
    tpair *want = malloc(cap * sizeof *want);
    size_t nw = ref_within(o, n, delta, want);
    cdist_scene_pair *got = malloc(cap * sizeof *got);
    int threads = 1 + (int)(next_rand() % 2);
    cdist_query_set_threads(Q, threads);
    size_t ng = 0;
    int mode = (int)(next_rand() % 4);
    cdist_status st;
    if (mode == 0) {
        churn_acc a = {got, 0, cap};
        st = cdist_scene_pairs_within_fn(Q, s, delta, churn_cb, &a, &ng);
        CHECK(ng == a.n, "%s: callback count %zu vs delivered %zu", what, ng, a.n);
    } else if (mode == 1 && nw > 1) {
        size_t c = next_rand() % nw;
        st = cdist_scene_pairs_within(Q, s, delta, got, c, &ng);
        size_t c2 = 0;
        CHECK(ng >= c, "%s: capacity %zu count %zu", what, c, ng);
        cdist_scene_pair *g2 = malloc(cap * sizeof *g2);
        cdist_status st2 = cdist_scene_pairs_within(Q, s, delta, g2, cap, &c2);
        CHECK(c2 == ng && st2 == st, "%s: capped count %zu/%d, full %zu/%d", what, ng, st, c2, st2);
        for (size_t k = 0; k < c && k < c2; k++)
            if (memcmp(&got[k], &g2[k], sizeof *got)) {
                CHECK(0, "%s: capped prefix differs at %zu", what, k);
                break;
            }
        memcpy(got, g2, cap * sizeof *got);
        ng = c2;
        free(g2);
    } else {
        st = cdist_scene_pairs_within(Q, s, delta, got, cap, &ng);
    }
    CHECK(st == CDIST_OK || st == CDIST_ERR_BAD_KIND, "%s: status %d (%s)", what, st, cdist_query_last_error(Q));
    CHECK(ng < cap, "%s: %zu pairs of %zu objects", what, ng, n);
    for (size_t k = 0; k < ng && k < cap; k++)
        if (got[k].i >= got[k].j || (k > 0 && (got[k].i < got[k - 1].i || (got[k].i == got[k - 1].i && got[k].j <= got[k - 1].j)))) {
            CHECK(0, "%s: pair %zu (%zu,%zu) after (%zu,%zu)", what, k, got[k].i, got[k].j, k ? got[k - 1].i : 0, k ? got[k - 1].j : 0);
            break;
        }
    char label[200];
    snprintf(label, sizeof label, "%s, %d thr, delta %.3g", what, threads, delta);
    compare(label, got, ng, want, nw, o, o);
    free(want);
    free(got);
}

/* closest_pair against the loop (ties: smallest (i, j)). */
static void churn_closest(const char *what, cdist_scene *s, const tobj *o, size_t n)
{
    cdist_scene_pair got;
    cdist_query_set_threads(Q, 1 + (int)(next_rand() % 2));
    cdist_status st = cdist_scene_closest_pair(Q, s, &got);
    if (st == CDIST_ERR_BAD_KIND) return;
    tpair best;
    int have = 0;
    for (size_t i = 0; i < n; i++) {
        if (!o[i].live) continue;
        for (size_t j = i + 1; j < n; j++) {
            if (!o[j].live || skip_ref(o, i, j)) continue;
            tpair t;
            if (ref_pair(&o[i], &o[j], &t) != 0) continue;
            if (!have || t.d < best.d) best = t, best.i = i, best.j = j, have = 1;
        }
    }
    if (!have) {
        CHECK(st == CDIST_ERR_BAD_INTERVAL, "%s closest: status %d without pairs", what, st);
        return;
    }
    if (st || !pair_equal(&got, &best))
        CHECK(0, "%s closest: got (%zu,%zu) %.17g st %d, want (%zu,%zu) %.17g", what, got.i, got.j, got.distance, st,
              best.i,
           best.j, best.d);
}

/* within and nearest k of a query object against the loop. */
static void churn_query_object(const char *what, cdist_scene *s, const tobj *o, size_t n, const tobj *qo, double delta)
{
    cdist_scene_pair *got = malloc((n + 1) * sizeof *got);
    tpair *want = malloc((n + 1) * sizeof *want);
    size_t nw = 0, ng = 0;
    for (size_t i = 0; i < n; i++) {
        if (!o[i].live) continue;
        tpair t;
        if (ref_pair(&o[i], qo, &t) == 0 && t.d <= delta) t.i = i, t.j = SIZE_MAX, want[nw++] = t;
    }
    cdist_query_set_threads(Q, 1 + (int)(next_rand() % 2));
    cdist_status st = cdist_scene_within(Q, s, qo->kind, &qo->u, delta, got, n + 1, &ng);
    CHECK(st == CDIST_OK || st == CDIST_ERR_BAD_KIND, "%s within: status %d", what, st);
    char label[200];
    snprintf(label, sizeof label, "%s within obj delta %.3g", what, delta);
    compare(label, got, ng, want, nw, o, qo);
    size_t k = 1 + next_rand() % 5, nn = 0;
    st = cdist_scene_nearest(Q, s, qo->kind, &qo->u, k, got, &nn);
    CHECK(st == CDIST_OK || st == CDIST_ERR_BAD_KIND, "%s nearest: status %d", what, st);
    if (st == CDIST_OK) {
        /* every live object's distance, sorted by (distance, id) */
        size_t m = 0;
        for (size_t i = 0; i < n; i++) {
            if (!o[i].live) continue;
            tpair t;
            if (ref_pair(&o[i], qo, &t) != 0) continue;
            t.i = i, t.j = SIZE_MAX;
            want[m++] = t;
        }
        for (size_t a = 1; a < m; a++)
            for (size_t b = a; b > 0 && (want[b].d < want[b - 1].d ||
                                         (want[b].d == want[b - 1].d && want[b].i < want[b - 1].i));
                 b--) {
                tpair t = want[b];
                want[b] = want[b - 1];
                want[b - 1] = t;
            }
        size_t live = 0;
        for (size_t i = 0; i < n; i++) live += o[i].live;
        size_t expect = k < live ? k : live;
        CHECK(nn == expect, "%s nearest: count %zu want %zu", what, nn, expect);
        for (size_t a = 0; a < nn && a < m; a++)
            if (!pair_equal(&got[a], &want[a])) {
                CHECK(0, "%s nearest[%zu]: got %zu %.17g want %zu %.17g", what, a, got[a].i, got[a].distance,
                      want[a].i, want[a].d);
                break;
            }
    }
    free(got);
    free(want);
}

/* Rings linked in rows (linked_pairs has answers), and one object repeated. */
static void gen_chain(tobj *o, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        cdist_vec3 nrm = i % 2 ? tv(0, 1, 0) : tv(0, 0, 1);
        cdist_vec3 c = tv(1.5 * (double)(i % 20), 3.0 * (double)(i / 20), 0);
        o[i] = make(i % 5 == 4 ? CDIST_SCENE_CIRCLE : CDIST_SCENE_TORUS, c, 1.0, nrm);
        o[i].u.torus.circle.radius = 1.0;
        if (o[i].kind == CDIST_SCENE_TORUS) o[i].u.torus.tube_radius = 0.1 + 0.05 * rnd01();
    }
}
static void gen_identical(tobj *o, size_t n)
{
    o[0] = make(all_kinds[next_rand() % 9], rvec(1), 1.0, rnd_unit_vec());
    for (size_t i = 1; i < n; i++) o[i] = o[0];
}
/* When set, far moves go up to 1e303 (boxes past the float range) instead of 1e8. */
static int churn_huge;
/* pairs_between against the loop; a == b is the one-scene query. */
static void churn_between(const char *what, cdist_scene *a, const tobj *oa, size_t na, cdist_scene *b, const tobj *ob,
                          size_t nb, double delta)
{
    size_t cap = na * nb + 1, nw = 0, ng = 0;
    tpair *want = malloc(cap * sizeof *want);
    cdist_scene_pair *got = malloc(cap * sizeof *got);
    if (a == b) {
        nw = ref_within(oa, na, delta, want);
    } else {
        for (size_t i = 0; i < na; i++) {
            if (oa[i].live != 1) continue;
            for (size_t j = 0; j < nb; j++) {
                if (ob[j].live != 1) continue;
                tpair t;
                if (ref_pair(&oa[i], &ob[j], &t) == 0 && t.d <= delta) t.i = i, t.j = j, want[nw++] = t;
            }
        }
    }
    cdist_query_set_threads(Q, 1 + (int)(next_rand() % 2));
    cdist_status st = cdist_scene_pairs_between(Q, a, b, delta, got, cap, &ng);
    CHECK(st == CDIST_OK || st == CDIST_ERR_BAD_KIND, "%s: between status %d", what, st);
    compare(what, got, ng, want, nw, oa, ob);
    free(want);
    free(got);
}

/* linked_pairs against cdist_link_tori() over every pair of rings. */
static void churn_linked(const char *what, cdist_scene *s, const tobj *o, size_t n)
{
    size_t cap = n * n + 1, nw = 0, ng = 0;
    cdist_scene_link *got = malloc(cap * sizeof *got);
    size_t *wi = malloc(cap * sizeof *wi), *wj = malloc(cap * sizeof *wj);
    cdist_link *wl = malloc(cap * sizeof *wl);
    for (size_t i = 0; i < n; i++) {
        if (o[i].live != 1 || (o[i].kind != CDIST_SCENE_TORUS && o[i].kind != CDIST_SCENE_CIRCLE)) continue;
        for (size_t j = i + 1; j < n; j++) {
            if (o[j].live != 1 || (o[j].kind != CDIST_SCENE_TORUS && o[j].kind != CDIST_SCENE_CIRCLE)) continue;
            cdist_torus a = o[i].kind == CDIST_SCENE_TORUS ? o[i].u.torus : (cdist_torus){o[i].u.circle, 0.0};
            cdist_torus b = o[j].kind == CDIST_SCENE_TORUS ? o[j].u.torus : (cdist_torus){o[j].u.circle, 0.0};
            cdist_link l;
            if (cdist_link_tori(Q, &a, &b, &l)) continue;
            if (l.linking != 0 || l.core_linking != 0) wi[nw] = i, wj[nw] = j, wl[nw] = l, nw++;
        }
    }
    cdist_query_set_threads(Q, 1 + (int)(next_rand() % 2));
    cdist_status st = cdist_scene_linked_pairs(Q, s, got, cap, &ng);
    CHECK(st == CDIST_OK, "%s linked: status %d", what, st);
    CHECK(ng == nw, "%s linked: %zu pairs, want %zu", what, ng, nw);
    for (size_t k = 0; k < ng && k < nw; k++)
        if (got[k].i != wi[k] || got[k].j != wj[k] || memcmp(&got[k].link, &wl[k], sizeof wl[k])) {
            CHECK(0, "%s linked[%zu]: (%zu,%zu) want (%zu,%zu)", what, k, got[k].i, got[k].j, wi[k], wj[k]);
            break;
        }
    free(got), free(wi), free(wj), free(wl);
}

/* A random sequence of operations on one scene, each followed by a check of the object
 * statuses and zero to two pairs_within queries: batched updates mixing small, tiny, far
 * (then back home) and invalid poses and kind changes (the invalid ones get their status at
 * their index, the others are applied), updates of removed ids, removals, additions (valid,
 * invalid and revived later), group changes, rebuilds, and the other queries (which take the
 * pair list's buffer) in between. */
static void churn_run(uint64_t seed, size_t n0, int steps)
{
    test_rng = seed;
    size_t cap = n0 + (size_t)steps * 3 + 4;
    tobj *o = calloc(cap, sizeof *o);
    int fam = (int)(next_rand() % 8);
    void (*gens[])(tobj *, size_t) = {gen_random_mixed, gen_coplanar, gen_concentric, gen_coaxial,
                                      gen_duplicates,   gen_scales,   gen_chain,      gen_identical};
    size_t n = n0;
    if (n >= 3) gens[fam](o, n);
    else gen_random_mixed(o, n);
    for (size_t i = 0; i < n; i++) o[i].group = (unsigned)(next_rand() % 4 == 0), o[i].chain = (unsigned)(i % 3 == 0);
    tobj *home = calloc(cap, sizeof *home);
    cdist_scene *s = build_scene(o, n);
    memcpy(home, o, n * sizeof *o);
    char label[96];
    for (int step = 0; step < steps; step++) {
        int r = (int)(next_rand() % 24), op = r < 12 ? 0 : 6 + (r - 12) % 9; /* half the steps update */
        if (n == 0) op = 9;
        size_t m = 1 + next_rand() % (n ? n : 1);
        size_t *ids = malloc(m * sizeof *ids);
        tobj *no = malloc(m * sizeof *no);
        cdist_status *sts = malloc(m * sizeof *sts);
        if (op <= 5) {
            /* one update call per run of objects of the same new kind */
            size_t k = 0;
            int wild = next_rand() % 5 < 2; /* else only small motions: the pair list lives on */
            for (size_t t = 0; t < m && n; t++) {
                size_t id = next_rand() % n;
                if (o[id].live != 1 && next_rand() % 2) continue;
                tobj x = o[id].live ? o[id] : home[id];
                x.live = 1;
                int w = (int)(next_rand() % 10);
                if (!wild && w >= 4 && w != 8) w = w % 2 ? 9 : 1;
                if (w < 4) nudge(&x, w == 0 ? 1e-12 : 1e-3);
                else if (w == 4) x = translate(x, rvec(pow(10.0, 3 + (churn_huge ? 300 * rnd01() : 5) * rnd01())));
                else if (w == 5) x = home[id], x.group = o[id].group, x.chain = o[id].chain, x.live = 1;
                else if (w == 6) x = rekind(&x, all_kinds[next_rand() % 9]);
                else if (w == 7) x = invalid_of(&x);
                else if (w == 8) x = translate(x, rvec(1e-300)); /* below rounding, or a subnormal move */
                /* w == 9: unchanged */
                ids[k] = id, no[k] = x, k++;
            }
            for (size_t t = 0; t < k; t++) {
                size_t run_n = 1;
                while (t + run_n < k && no[t + run_n].kind == no[t].kind) run_n++;
                char *raw = malloc(run_n * sizeof no[0].u);
                for (size_t u = 0; u < run_n; u++) memcpy(raw + u * sizeof no[0].u, &no[t + u].u, sizeof no[0].u);
                cdist_status st = cdist_scene_update(Q, s, run_n, &ids[t], no[t].kind, raw, sizeof no[0].u, sts);
                cdist_status first = CDIST_OK;
                for (size_t u = 0; u < run_n; u++) {
                    size_t id = ids[t + u];
                    tobj x = no[t + u];
                    cdist__scene_item it;
                    cdist_status v = home[id].live == -1 ? CDIST_ERR_OUT_OF_RANGE
                                                         : cdist__scene_make(Q, x.kind, &x.u, &it.o, &it.arc);
                    CHECK(sts[u] == v, "update status at %zu: %d want %d", u, sts[u], v);
                    if (!first && v) first = v;
                    if (v == CDIST_OK) {
                        x.group = o[id].group, x.chain = o[id].chain, x.live = 1;
                        o[id] = x;
                    }
                }
                CHECK(st == first, "update returned %d, first failing %d", st, first);
                free(raw);
                t += run_n - 1;
            }
        } else if (op == 6) {
            size_t id = next_rand() % n;
            cdist_scene_remove(Q, s, 1, &id);
            if (o[id].live) o[id].live = 0;
            home[id].live = -1;
        } else if (op == 7 && n < cap) {
            o[n] = make(all_kinds[next_rand() % 9], n ? center_of(&o[next_rand() % n]) : rvec(2), 1.0, rnd_unit_vec());
            size_t id;
            cdist_status st = cdist_scene_add(Q, s, o[n].kind, 1, &o[n].u, 0, &id, NULL);
            CHECK(st == CDIST_OK && id == n, "add %zu: %d", id, st);
            home[n] = o[n];
            n++;
        } else if (op == 8 && n) {
            /* new groups and chains for several objects: pairs the list skipped may now count */
            unsigned g[8], c[8];
            size_t gi[8], gm = 1 + next_rand() % 8;
            for (size_t t = 0; t < gm; t++) {
                gi[t] = next_rand() % n, g[t] = (unsigned)(next_rand() % 3), c[t] = (unsigned)(next_rand() % 2);
                o[gi[t]].group = g[t], o[gi[t]].chain = c[t];
            }
            cdist_scene_set_groups(Q, s, gm, gi, g, c);
        } else if (op == 9 && n < cap) {
            /* an invalid object (revived by an update later) */
            tobj x = make(CDIST_SCENE_TORUS, rvec(2), 1.0, tv(0, 0, 0));
            size_t id;
            cdist_status st2;
            cdist_scene_add(Q, s, x.kind, 1, &x.u, 0, &id, &st2);
            CHECK(st2 != CDIST_OK, "invalid add accepted");
            o[n] = x, o[n].live = 0;
            home[n] = make(CDIST_SCENE_TORUS, rvec(2), 1.0, rnd_unit_vec());
            n++;
        } else if (op == 10) {
            snprintf(label, sizeof label, "seed %llu step %d", (unsigned long long)seed, step);
            churn_closest(label, s, o, n);
        } else if (op == 11 && n) {
            tobj qo = make(all_kinds[next_rand() % 9], center_of(&o[next_rand() % n]), 1.0, rnd_unit_vec());
            snprintf(label, sizeof label, "seed %llu step %d", (unsigned long long)seed, step);
            churn_query_object(label, s, o, n, &qo, n > 1 ? pick_delta(o, n, 0.1) : 1.0);
        } else if (op == 12) {
            cdist_scene_rebuild(Q, s);
        } else if (op == 14) {
            snprintf(label, sizeof label, "seed %llu step %d", (unsigned long long)seed, step);
            churn_linked(label, s, o, n);
        } else if (op == 13 && n > 1) {
            /* pairs_between the scene and itself, and with a static copy of its home poses */
            snprintf(label, sizeof label, "seed %llu step %d between", (unsigned long long)seed, step);
            churn_between(label, s, o, n, s, o, n, churn_delta(o, n));
            cdist_scene *h = build_scene(home, n);
            tobj *hh = malloc(n * sizeof *hh);
            for (size_t i = 0; i < n; i++) {
                hh[i] = home[i];
                cdist__scene_item it;
                hh[i].live = cdist__scene_make(Q, hh[i].kind, &hh[i].u, &it.o, &it.arc) == CDIST_OK;
            }
            if (next_rand() % 2) churn_between(label, s, o, n, h, hh, n, churn_delta(o, n));
            else churn_between(label, h, hh, n, s, o, n, churn_delta(o, n));
            cdist_scene_free(h);
            free(hh);
        }
        free(ids);
        free(no);
        free(sts);
        /* live exactly when the loop's copy is */
        for (size_t i = 0; i < n; i++) {
            cdist_status os = cdist_scene_object_status(s, i);
            CHECK((os == CDIST_OK) == (o[i].live == 1), "object %zu status %d live %d", i, os, o[i].live);
        }
        int nq = 1 + (int)(next_rand() % 2);
        for (int qq = 0; qq < nq; qq++) {
            snprintf(label, sizeof label, "seed %llu step %d q%d", (unsigned long long)seed, step, qq);
            if (n >= 1) churn_within(label, s, o, n, n > 1 ? churn_delta(o, n) : 0.0);
        }
    }
    cdist_scene_free(s);
    free(o);
    free(home);
}

static void churn(int runs)
{
    for (int k = 0; k < runs; k++) {
        churn_huge = k % 2;
        churn_run((uint64_t)k * 7919 + 13, k % 4 == 3 ? (size_t)(k % 3) : 40, 40);
    }
    churn_huge = 0;
    cdist_query_set_threads(Q, 1);
}

/* Groups changed under a live pair list: the list is made while two spheres share a group (their
 * pair skipped), so it lacks that pair; when they leave the group the list must be dropped, or
 * the pair within delta is missed. */
static void groups_under_list(void)
{
    tobj o[3];
    for (int i = 0; i < 3; i++) {
        memset(&o[i], 0, sizeof o[i]);
        o[i].kind = CDIST_SCENE_SPHERE;
        o[i].live = 1;
        o[i].u.sphere = (cdist_sphere){tv(1.0 * i, 0, 0), 0.25};
    }
    o[0].group = o[1].group = 5;
    cdist_scene *s = build_scene(o, 3);
    for (int step = 0; step < 8; step++) {
        if (step == 4) {
            size_t ids[2] = {0, 1};
            unsigned none[2] = {0, 0};
            CHECK(cdist_scene_set_groups(Q, s, 2, ids, none, none) == CDIST_OK, "groups: %s", cdist_query_last_error(Q));
            o[0].group = o[1].group = 0;
        }
        for (size_t i = 0; i < 3; i++) {
            o[i].u.sphere.center.y += 1e-3 * (double)(i + 1);
            CHECK(cdist_scene_update(Q, s, 1, &i, o[i].kind, &o[i].u, 0, NULL) == CDIST_OK, "update: %s",
                  cdist_query_last_error(Q));
        }
        char label[64];
        snprintf(label, sizeof label, "groups under a pair list, step %d", step);
        check_within(label, s, o, 3, 2.0);
        if (step == 3) CHECK(s->list_reuses > 0, "groups under a pair list: no list reused before the change");
    }
    cdist_scene_free(s);
}

int main(int argc, char **argv)
{
    int big = argc > 1 && strcmp(argv[1], "--big") == 0;
    Q = cdist_query_new();
    public_agreement();
    float_rounding();
    bad_input();
    boundary(big ? 100000 : 10000);
    scenario("random tori", big ? 2000 : 600, gen_random_tori, 0.02);
    scenario("random mixed", big ? 2000 : 500, gen_random_mixed, 0.05);
    scenario("coplanar", 300, gen_coplanar, 0.1);
    scenario("concentric", 120, gen_concentric, 0.3);
    scenario("coaxial", 200, gen_coaxial, 0.2);
    scenario("duplicates", 240, gen_duplicates, 0.05);
    scenario("scales 1e-6..1e6", big ? 2000 : 400, gen_scales, 0.05);
    moving(300, 8);
    drifting("random tori", 400, gen_random_tori, 8);
    drifting("random mixed", 300, gen_random_mixed, 8);
    drifting("coplanar", 200, gen_coplanar, 6);
    drifting("concentric", 100, gen_concentric, 6);
    drifting("coaxial", 150, gen_coaxial, 6);
    drifting("duplicates", 180, gen_duplicates, 6);
    drifting("scales 1e-6..1e6", 300, gen_scales, 6);
    drifting_boundary(big ? 20000 : 3000);
    turning_short_normal();
    cores_meet();
    unanswered_order(big ? 2000 : 300);
    /* normals not unit to double precision: the motion bounds normalise them */
    double unit_tol = cdist_query_get_unit_tolerance(Q);
    cdist_query_set_unit_tolerance(Q, INFINITY);
    any_length = 1;
    drifting("normals of any length", 300, gen_random_mixed, 8);
    drifting_boundary(big ? 20000 : 3000);
    any_length = 0;
    cdist_query_set_unit_tolerance(Q, unit_tol);
    others(300);
    kind_changes(200);
    groups_under_list();
    /* The pair list under the methods without a certificate, whose answers renew only the
     * upper bounds (the reference loop uses the same method). */
    cdist_query_set_method(Q, CDIST_METHOD_POLYNOMIAL);
    drifting("random tori, POLYNOMIAL", 200, gen_random_tori, 6);
    cdist_query_set_method(Q, CDIST_METHOD_ITERATION);
    drifting("random tori, ITERATION", 200, gen_random_tori, 6);
    cdist_query_set_method(Q, CDIST_METHOD_AUTO);
    churn(big ? 40 : 4);
    cdist_query_free(Q);
    return check_summary("scene");
}
