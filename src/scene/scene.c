/* SPDX-License-Identifier: MIT */
/* Scenes: object storage and validation, certified bounds, the tree (build, refit) and the
 * editing calls. The queries are in scene_broad.c, scene_pairs.c, scene_jobs.c and scene_search.c. */
#include <math.h>
#include <stddef.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "scene-priv.h"

/* Leaves hold up to this many objects (chosen by measurement: docs/scene.md, "Why this
 * structure"). */
#define CD_SCENE_LEAF CD_SCENE_LEAF_MAX

/* ---- objects ---- */

static const size_t kind_size[] = {sizeof(cdist_vec3),   sizeof(cdist_segment), sizeof(cdist_circle),
                                   sizeof(cdist_circle), sizeof(cdist_arc),     sizeof(cdist_sphere),
                                   sizeof(cdist_capsule), sizeof(cdist_torus),  sizeof(cdist_rounded_disk)};
#define KIND_COUNT (sizeof kind_size / sizeof kind_size[0])

size_t cdist_scene_kind_size(cdist_scene_kind kind) { return (unsigned)kind < KIND_COUNT ? kind_size[kind] : 0; }
size_t cdist_scene_pair_size(void) { return sizeof(cdist_scene_pair); }
size_t cdist_scene_stats_size(void) { return sizeof(cdist_scene_stats); }

static cdist__core_type core_type(int kind)
{
    switch (kind) {
    case CDIST_SCENE_POINT:
    case CDIST_SCENE_SPHERE: return CD_CORE_POINT;
    case CDIST_SCENE_SEGMENT:
    case CDIST_SCENE_CAPSULE: return CD_CORE_SEGMENT;
    case CDIST_SCENE_CIRCLE:
    case CDIST_SCENE_TORUS: return CD_CORE_CIRCLE;
    case CDIST_SCENE_DISK:
    case CDIST_SCENE_ROUNDED_DISK: return CD_CORE_DISK;
    default: return CD_CORE_ARC;
    }
}

cdist__core_obj cdist__scene_core(const cdist__scene_obj *o, const cdist_arc *arc)
{
    cdist__core_type t = core_type(o->kind);
    const void *g = t == CD_CORE_ARC ? (const void *)arc : (const void *)&o->g;
    cdist__core_obj c = {t, g, o->r, o->kind >= CDIST_SCENE_SPHERE};
    return c;
}

/* An arc is checked by the arc query itself (against a unit circle), so a scene accepts
 * exactly the arcs the arc queries accept. */
static cdist_status check_arc(cdist_query *q, const cdist_arc *a)
{
    static const cdist_circle unit = {{0, 0, 0}, {0, 0, 1}, 1.0};
    cdist_result r;
    return cdist_arc_circle(q, a, &unit, &r);
}

/* A swept kind is its plain core kind (sphere: point, capsule: segment, torus: circle, rounded
 * disk: disk) followed by one double, the ball radius, in its struct. */
#define SWEPT_FIRST CDIST_SCENE_SPHERE
_Static_assert(offsetof(cdist_sphere, radius) == sizeof(cdist_vec3), "sphere: point, radius");
_Static_assert(offsetof(cdist_capsule, radius) == sizeof(cdist_segment), "capsule: segment, radius");
_Static_assert(offsetof(cdist_torus, tube_radius) == sizeof(cdist_circle), "torus: circle, radius");
_Static_assert(offsetof(cdist_rounded_disk, radius) == sizeof(cdist_circle), "rounded disk: disk, radius");

static float object_scale(const cdist__scene_obj *o);

cdist_status cdist__scene_make(cdist_query *q, cdist_scene_kind kind, const void *src, cdist__scene_obj *o,
                              cdist_arc *arc)
{
    static const char *const what[] = {"point", "segment", "circle", "disk", "arc"};
    cdist__circle tmp;
    cdist_status st = CDIST_OK;
    memset(&o->g, 0, sizeof o->g);
    o->r = 0.0;
    o->kind = (uint8_t)kind;
    if ((unsigned)kind >= KIND_COUNT) {
        st = cdist__fail(q, CDIST_ERR_BAD_KIND, "%d is not a cdist_scene_kind", (int)kind);
    } else {
        int core = kind >= SWEPT_FIRST ? kind - SWEPT_FIRST : kind;
        if (core == CDIST_SCENE_ARC) {
            memcpy(arc, src, sizeof *arc);
            o->g.circle = arc->circle;
        } else {
            memcpy(&o->g, src, kind_size[core]);
        }
        if (kind >= SWEPT_FIRST) memcpy(&o->r, (const char *)src + kind_size[core], sizeof o->r);
        switch (core) {
        case CDIST_SCENE_POINT: st = cdist__check_point(q, &o->g.point, what[core]); break;
        case CDIST_SCENE_SEGMENT: st = cdist__check_segment(q, &o->g.segment); break;
        case CDIST_SCENE_CIRCLE:
        case CDIST_SCENE_DISK: st = cdist__check_circle_nobasis(q, &o->g.circle, what[core], &tmp); break;
        default: st = check_arc(q, arc); break;
        }
        if (!st && kind >= SWEPT_FIRST) st = cdist__check_radius(q, o->r, "radius");
    }
    o->state = st ? CD_SCENE_INVALID : CD_SCENE_LIVE;
    o->scale = st ? 0.0f : object_scale(o);
    o->status = (uint8_t)st;
    return st;
}

/* ---- bounds ---- */
/* Plain arithmetic throughout (no fma: without -mfma the C library's fma is a call); every
 * rounding is covered by the margin CD_SCENE_BOUND_REL of the coordinate scale. */

static inline double dot3(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline vec3 sub3(vec3 a, vec3 b) { return v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline vec3 axpy3(vec3 a, double s, vec3 b) { return v3(a.x + s * b.x, a.y + s * b.y, a.z + s * b.z); }
static inline double norm3(vec3 a) { return sqrt(dot3(a, a)); }

/* n / |n|: validated normals are unit within the handle's tolerance; any other length (a
 * tolerance of INFINITY) takes the library's overflow-safe rule. */
static inline vec3 unit3(vec3 n)
{
    double l2 = dot3(n, n);
    if (l2 > 0.25 && l2 < 4.0) return v_scale(1.0 / sqrt(l2), n);
    return v_unit_or_zero(n);
}

/* An object's core as the bounds see it: an arc is its circle (a superset: lower bounds stay
 * lower bounds). */
typedef struct bound {
    cdist__core_type type; /* POINT, SEGMENT, CIRCLE or DISK */
    vec3 p0, p1;           /* point (p0), segment */
    vec3 c, n;             /* circle or disk: centre, unit normal (set where used) */
    double R;
    vec3 m;                /* bounding ball of the core */
    double rho;
    double r;              /* the object's ball radius */
    double scale;          /* largest |coordinate| plus the radii */
} bound;

CD_INLINE void bound_of(const cdist__scene_obj *o, bound *x)
{
    x->type = core_type(o->kind);
    x->r = o->r;
    switch (x->type) {
    case CD_CORE_POINT:
        x->p0 = x->p1 = x->m = o->g.point;
        x->rho = 0.0;
        break;
    case CD_CORE_SEGMENT:
        x->p0 = o->g.segment.p0;
        x->p1 = o->g.segment.p1;
        x->m = v_scale(0.5, v_add(x->p0, x->p1));
        x->rho = 0.5 * norm3(sub3(x->p1, x->p0));
        break;
    default:
        if (x->type == CD_CORE_ARC) x->type = CD_CORE_CIRCLE;
        x->p0 = x->p1 = x->c = x->m = o->g.circle.center; /* an arc's circle is its first member */
        x->R = x->rho = o->g.circle.radius;
        break;
    }
    x->scale = v_maxabs(x->m) + x->rho + x->r;
}

static float object_scale(const cdist__scene_obj *o)
{
    bound x;
    bound_of(o, &x);
    return cdist__float_up(x.scale);
}

static int is_planar(const bound *x) { return x->type == CD_CORE_CIRCLE || x->type == CD_CORE_DISK; }

void cdist__scene_box(const cdist__scene_obj *o, cdist__box *b)
{
    bound x;
    bound_of(o, &x);
    double pad = x.r + CD_SCENE_BOUND_REL * (double)o->scale, lo[3], hi[3];
    if (!is_planar(&x)) {
        vec3 a = x.p0, c = x.type == CD_CORE_SEGMENT ? x.p1 : x.p0;
        lo[0] = fmin(a.x, c.x) - pad, hi[0] = fmax(a.x, c.x) + pad;
        lo[1] = fmin(a.y, c.y) - pad, hi[1] = fmax(a.y, c.y) + pad;
        lo[2] = fmin(a.z, c.z) - pad, hi[2] = fmax(a.z, c.z) + pad;
    } else {
        /* A circle's extent along axis k is R sqrt(1 - n_k^2) = R sqrt(n_i^2 + n_j^2) (no
         * cancellation) for the unit normal n: R sqrt((n_i^2 + n_j^2) / n.n) for the given one
         * (normalised first when n.n is far from 1, where it could overflow). */
        vec3 n = o->g.circle.normal, m = x.m;
        double q = dot3(n, n);
        if (!(q > 0.25 && q < 4.0)) n = unit3(n), q = dot3(n, n);
        double u = 1.0 / q, ex = x.R * sqrt((n.y * n.y + n.z * n.z) * u);
        double ey = x.R * sqrt((n.x * n.x + n.z * n.z) * u), ez = x.R * sqrt((n.x * n.x + n.y * n.y) * u);
        lo[0] = m.x - ex - pad, hi[0] = m.x + ex + pad;
        lo[1] = m.y - ey - pad, hi[1] = m.y + ey + pad;
        lo[2] = m.z - ez - pad, hi[2] = m.z + ez + pad;
    }
    for (int k = 0; k < 3; k++) b->lo[k] = cdist__float_down(lo[k]), b->hi[k] = cdist__float_up(hi[k]);
    b->lo[3] = b->hi[3] = 0.0f;
}

/* Lower bound of the distance from the plane of planar core a to core b: the distance of the
 * interval of b's heights over a's plane from 0. */
static double slab_bound(const bound *a, const bound *b)
{
    double lo, hi;
    switch (b->type) {
    case CD_CORE_POINT: lo = hi = dot3(a->n, sub3(b->p0, a->c)); break;
    case CD_CORE_SEGMENT: {
        double h0 = dot3(a->n, sub3(b->p0, a->c)), h1 = dot3(a->n, sub3(b->p1, a->c));
        lo = fmin(h0, h1);
        hi = fmax(h0, h1);
        break;
    }
    default: {
        /* A circle of unit normal nb tilted from n leaves its centre's height by at most
         * R |n x nb| (the cross product, not sqrt(1 - (n.nb)^2), which cancels). */
        double h = dot3(a->n, sub3(b->c, a->c));
        double e = b->R * norm3(v_cross(a->n, b->n));
        lo = h - e;
        hi = h + e;
        break;
    }
    }
    return fmax(0.0, fmax(lo, -hi));
}

/* Distance from p to the core (to rounding of a few eps times the coordinates). */
static double point_distance(const bound *x, vec3 p)
{
    switch (x->type) {
    case CD_CORE_POINT: return norm3(sub3(p, x->p0));
    case CD_CORE_SEGMENT: {
        vec3 d = sub3(x->p1, x->p0), w = sub3(p, x->p0);
        double dd = dot3(d, d), t = dd > 0.0 ? dot3(w, d) / dd : 0.0;
        t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
        return norm3(sub3(p, axpy3(x->p0, t, d)));
    }
    default: {
        vec3 w = sub3(p, x->c);
        double h = dot3(w, x->n);
        double e = norm3(axpy3(w, -h, x->n)) - x->R;
        if (x->type == CD_CORE_DISK && e < 0.0) e = 0.0;
        return sqrt(h * h + e * e);
    }
    }
}

/* Initial samples and the finest subdivision of the ring screen (chosen by measurement:
 * docs/scene.md, "Why this structure"; the finest spacing decides the candidates). */
#define RING_SAMPLES 4
#define RING_DEPTH 6
#define RING_ANGLES (RING_SAMPLES << RING_DEPTH)

/* cos and sin of the screen's angles 2 pi k / RING_ANGLES, filled once. */
static double ring_cos[RING_ANGLES], ring_sin[RING_ANGLES];
static pthread_once_t ring_once = PTHREAD_ONCE_INIT;
static void ring_table(void)
{
    for (int k = 0; k < RING_ANGLES; k++) {
        ring_cos[k] = cos(2.0 * M_PI * k / RING_ANGLES);
        ring_sin[k] = sin(2.0 * M_PI * k / RING_ANGLES);
    }
}

/* Ring screen: 1 when every point of the circle of ring is certified farther than thr from
 * core x. The distance to x is R-Lipschitz in the circle's angle, so on an interval of width w
 * with end values f0, f1 it is >= (f0 + f1) / 2 - R w / 2; intervals that do not clear thr are
 * halved down to RING_DEPTH, and a sample within thr ends the screen (the pair is close).
 * Angles are table indices and u, v an orthonormal basis of the ring's plane (to rounding), so
 * every sample is a point of the circle to rounding. */
static int ring_clears(const bound *x, const bound *ring, double thr)
{
    vec3 n = ring->n, c = ring->c, e;
    double R = ring->R;
    double ax = fabs(n.x), ay = fabs(n.y), az = fabs(n.z);
    e = ax <= ay && ax <= az ? v3(1, 0, 0) : (ay <= az ? v3(0, 1, 0) : v3(0, 0, 1));
    vec3 w = axpy3(e, -dot3(e, n), n);
    vec3 u = v_scale(1.0 / norm3(w), w), v = v_cross(n, u);
    pthread_once(&ring_once, ring_table);
#define RING_AT(k) point_distance(x, axpy3(axpy3(c, R * ring_cos[(k) % RING_ANGLES], u), R * ring_sin[(k) % RING_ANGLES], v))
    const int step0 = RING_ANGLES / RING_SAMPLES;
    double f[RING_SAMPLES + 1];
    for (int k = 0; k < RING_SAMPLES; k++)
        if ((f[k] = RING_AT(k * step0)) <= thr) return 0;
    f[RING_SAMPLES] = f[0];
    struct {
        int k0, step;
        double f0, f1;
    } stack[RING_SAMPLES + RING_DEPTH + 2];
    int top = 0;
    for (int k = RING_SAMPLES - 1; k >= 0; k--) {
        stack[top].k0 = k * step0, stack[top].step = step0, stack[top].f0 = f[k], stack[top].f1 = f[k + 1];
        top++;
    }
    const double w1 = 2.0 * M_PI / RING_ANGLES;
    while (top > 0) {
        top--;
        int k0 = stack[top].k0, step = stack[top].step;
        double f0 = stack[top].f0, f1 = stack[top].f1;
        if (0.5 * (f0 + f1) - 0.5 * R * (w1 * step) > thr) continue;
        if (step == 1) return 0;
        int km = k0 + step / 2;
        double fm = RING_AT(km);
        if (fm <= thr) return 0;
        stack[top].k0 = km, stack[top].step = step / 2, stack[top].f0 = fm, stack[top].f1 = f1;
        top++;
        stack[top].k0 = k0, stack[top].step = step / 2, stack[top].f0 = f0, stack[top].f1 = fm;
        top++;
    }
#undef RING_AT
    return 1;
}

uint8_t cdist__scene_tcore(const cdist__scene_obj *o)
{
    return core_type(o->kind) == CD_CORE_CIRCLE ? CD_SCENE_T_CIRCLE : CD_SCENE_T_OTHER;
}

int cdist__scene_circle_pair(const cdist__scene_obj *a, const cdist__scene_obj *b)
{
    return cdist__scene_tcore(a) == CD_SCENE_T_CIRCLE && cdist__scene_tcore(b) == CD_SCENE_T_CIRCLE;
}

int cdist__scene_excluded(const cdist__scene_obj *oa, const cdist__scene_obj *ob, double lim, int ring)
{
    bound a, b;
    bound_of(oa, &a);
    bound_of(ob, &b);
    double margin = cdist__scene_margin(oa, ob);
    /* Certified lower bounds of the core distance against thr, the core distance the pair
     * must not exceed to be within lim. */
    double thr = lim + (a.r + b.r) + margin;
    if (norm3(sub3(a.m, b.m)) - a.rho - b.rho > thr) return 1;
    if (!(thr < INFINITY)) return 0;
    if (is_planar(&a)) a.n = unit3(oa->g.circle.normal);
    if (is_planar(&b)) b.n = unit3(ob->g.circle.normal);
    if (is_planar(&a) && slab_bound(&a, &b) > thr) return 1;
    if (is_planar(&b) && slab_bound(&b, &a) > thr) return 1;
    /* The ring screen samples the circle of smaller radius (of a circle or arc core) against
     * the other core. */
    int ca = a.type == CD_CORE_CIRCLE, cb = b.type == CD_CORE_CIRCLE;
    if (!(ca || cb) || (!ring && cdist__scene_circle_pair(oa, ob))) return 0;
    return cb && (!ca || b.R <= a.R) ? ring_clears(&a, &b, thr) : ring_clears(&b, &a, thr);
}

/* |n' - n| or |n' + n|, the smaller, of the unit normals n, n' along the given ones. Normals unit
 * to CD_SCENE_UNIT_SLACK need no normalising: |n / |n| - n| = ||n| - 1| <= |n.n - 1|, so the
 * difference of the given normals plus both |n.n - 1| bounds it (a slack below the bound margin). */
static double normal_turn(vec3 na, vec3 nb)
{
    double qa = fabs(dot3(na, na) - 1.0), qb = fabs(dot3(nb, nb) - 1.0);
    if (qa <= CD_SCENE_UNIT_SLACK && qb <= CD_SCENE_UNIT_SLACK) {
        vec3 dm = sub3(nb, na), dp = v_add(nb, na);
        double m = dot3(dm, dm), p = dot3(dp, dp);
        return sqrt(m < p ? m : p) + qa + qb;
    }
    na = unit3(na), nb = unit3(nb);
    return fmin(norm3(sub3(nb, na)), norm3(v_add(nb, na)));
}

double cdist__scene_motion(const cdist__scene_obj *oa, const cdist_arc *arc_a, const cdist__scene_obj *ob,
                           const cdist_arc *arc_b)
{
    cdist__core_type ta = core_type(oa->kind), tb = core_type(ob->kind);
    if (ta != tb) return INFINITY;
    double core;
    switch (ta) {
    case CD_CORE_POINT: core = norm3(sub3(ob->g.point, oa->g.point)); break;
    case CD_CORE_SEGMENT: {
        /* the point at t moves to the point at t of the new segment (or of its reverse) */
        const cdist_segment *a = &oa->g.segment, *b = &ob->g.segment;
        double same = fmax(norm3(sub3(b->p0, a->p0)), norm3(sub3(b->p1, a->p1)));
        double swap = fmax(norm3(sub3(b->p1, a->p0)), norm3(sub3(b->p0, a->p1)));
        core = fmin(same, swap);
        break;
    }
    case CD_CORE_ARC: core = memcmp(arc_a, arc_b, sizeof *arc_a) == 0 ? 0.0 : INFINITY; break;
    default: {
        /* The rotation taking n to n' (or to -n': the same circle or disk) by the least angle
         * moves every vector of length R by at most R |n' - n|; with the centre's move and the
         * radius change that bounds the move of every point. */
        const cdist_circle *a = &oa->g.circle, *b = &ob->g.circle;
        core = norm3(sub3(b->center, a->center)) + fabs(b->radius - a->radius) +
               a->radius * normal_turn(a->normal, b->normal);
        break;
    }
    }
    return (core + fabs(ob->r - oa->r)) * (1.0 + CD_SCENE_BOUND_REL);
}

/* ---- tree ---- */

static void box_empty(cdist__box *b)
{
    for (int k = 0; k < 3; k++) b->lo[k] = INFINITY, b->hi[k] = -INFINITY;
    b->lo[3] = b->hi[3] = 0.0f;
}

static void box_join(cdist__box *b, const cdist__box *x)
{
#if defined(__SSE2__)
    _mm_storeu_ps(b->lo, _mm_min_ps(_mm_loadu_ps(b->lo), _mm_loadu_ps(x->lo)));
    _mm_storeu_ps(b->hi, _mm_max_ps(_mm_loadu_ps(b->hi), _mm_loadu_ps(x->hi)));
#else
    for (int k = 0; k < 3; k++) {
        if (x->lo[k] < b->lo[k]) b->lo[k] = x->lo[k];
        if (x->hi[k] > b->hi[k]) b->hi[k] = x->hi[k];
    }
#endif
}

static uint64_t spread21(uint64_t x)
{
    x &= 0x1fffff;
    x = (x | x << 32) & 0x1f00000000ffffULL;
    x = (x | x << 16) & 0x1f0000ff0000ffULL;
    x = (x | x << 8) & 0x100f00f00f00f00fULL;
    x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
    x = (x | x << 2) & 0x1249249249249249ULL;
    return x;
}

/* Stable LSD radix sort of keys with their payload (8 bits a pass; the digits counted in one
 * read; passes whose digit is the same for every key are skipped; the arrays and their
 * workspaces take turns, one copy at the end at most). */
static void radix_sort(uint64_t *key, uint32_t *val, uint64_t *key_tmp, uint32_t *val_tmp, size_t n)
{
    if (n == 0) return;
    size_t cnt[8][256] = {{0}};
    for (size_t i = 0; i < n; i++)
        for (int d = 0; d < 8; d++) cnt[d][(key[i] >> (8 * d)) & 255]++;
    uint64_t *ks = key, *kd = key_tmp;
    uint32_t *vs = val, *vd = val_tmp;
    for (int d = 0; d < 8; d++) {
        int shift = 8 * d;
        size_t *c = cnt[d];
        if (c[(key[0] >> shift) & 255] == n) continue;
        size_t sum = 0;
        for (int x = 0; x < 256; x++) {
            size_t t = c[x];
            c[x] = sum;
            sum += t;
        }
        for (size_t i = 0; i < n; i++) {
            size_t at = c[(ks[i] >> shift) & 255]++;
            kd[at] = ks[i];
            if (val) vd[at] = vs[i];
        }
        uint64_t *kt = ks;
        ks = kd, kd = kt;
        uint32_t *vt = vs;
        vs = vd, vd = vt;
    }
    if (ks != key) {
        memcpy(key, ks, n * sizeof *key);
        if (val) memcpy(val, vs, n * sizeof *val);
    }
}

void cdist__radix_sort_keys(uint64_t *key, uint64_t *tmp, size_t n) { radix_sort(key, NULL, tmp, NULL, n); }

/* Runs of one i up to this long are sorted by insertion (a scene pair list has a few per i). */
#define PAIR_RUN_INSERT 32

void cdist__sort_pair_keys(uint64_t *key, uint64_t *tmp, uint32_t *cnt, size_t ids, size_t n)
{
    memset(cnt, 0, (ids + 1) * sizeof *cnt);
    for (size_t k = 0; k < n; k++) cnt[(key[k] >> 32) + 1]++;
    for (size_t i = 0; i < ids; i++) cnt[i + 1] += cnt[i];
    for (size_t k = 0; k < n; k++) tmp[cnt[key[k] >> 32]++] = key[k];
    /* cnt[i] is now the end of run i */
    size_t lo = 0;
    for (size_t i = 0; i < ids; i++) {
        size_t hi = cnt[i], m = hi - lo;
        if (m > PAIR_RUN_INSERT) {
            memcpy(key + lo, tmp + lo, m * sizeof *key);
            radix_sort(key + lo, NULL, tmp + lo, NULL, m);
        } else {
            for (size_t k = lo; k < hi; k++) {
                uint64_t x = tmp[k];
                size_t at = k;
                while (at > lo && key[at - 1] > x) {
                    key[at] = key[at - 1];
                    at--;
                }
                key[at] = x;
            }
        }
        lo = hi;
    }
}

/* Node boxes bottom-up from the object boxes; returns the sum of the leaves' box sizes (the
 * tree's quality: it grows as objects move away from the neighbours they were built with). */
static double refit(cdist_scene *s)
{
    double leaves = 0.0;
    for (size_t i = s->node_n; i-- > 0;) {
        cdist__node *nd = &s->node[i];
        box_empty(&nd->box);
        if (nd->count) {
            for (uint32_t p = nd->first; p < nd->first + nd->count; p++) box_join(&nd->box, &s->box[p]);
            if (nd->box.lo[0] <= nd->box.hi[0])
                leaves += (nd->box.hi[0] - nd->box.lo[0]) + (nd->box.hi[1] - nd->box.lo[1]) + (nd->box.hi[2] - nd->box.lo[2]);
        } else {
            box_join(&nd->box, &s->node[nd->first].box);
            box_join(&nd->box, &s->node[nd->first + 1].box);
        }
    }
    s->refit_pending = 0;
    return leaves;
}

/* Median split of Morton-ordered positions [lo, hi) into node ni. */
static void build_node(cdist_scene *s, size_t ni, uint32_t lo, uint32_t hi)
{
    for (;;) {
        cdist__node *nd = &s->node[ni];
        if (hi - lo <= CD_SCENE_LEAF) {
            nd->first = lo;
            nd->count = hi - lo;
            return;
        }
        size_t c = s->node_n;
        s->node_n += 2;
        nd->first = (uint32_t)c;
        nd->count = 0;
        uint32_t mid = lo + (hi - lo) / 2;
        build_node(s, c, lo, mid);
        ni = c + 1;
        lo = mid;
    }
}

static cdist_status build(cdist_query *q, cdist_scene *s)
{
    size_t m = 0;
    for (size_t i = 0; i < s->n; i++) m += s->obj[i].state == CD_SCENE_LIVE;
    uint64_t *key = cdist__big_malloc((m ? m : 1) * sizeof *key), *key_tmp = cdist__big_malloc((m ? m : 1) * sizeof *key_tmp);
    uint32_t *perm = cdist__big_malloc((m ? m : 1) * sizeof *perm), *perm_tmp = cdist__big_malloc((m ? m : 1) * sizeof *perm_tmp);
    cdist__box *box = cdist__big_malloc((m ? m : 1) * sizeof *box);
    cdist__node *node = cdist__big_malloc((m ? m : 1) * sizeof *node);
    uint8_t *tcore = cdist__big_malloc(m ? m : 1);
    if (!key || !key_tmp || !perm || !perm_tmp || !box || !node || !tcore) {
        free(key), free(key_tmp), free(perm), free(perm_tmp), free(box), free(node), free(tcore);
        return cdist__fail(q, CDIST_ERR_NO_MEMORY, "scene: out of memory for the tree of %zu objects", m);
    }
    /* The centres of the cores' bounding balls (the centres of their boxes) by id order first
     * (perm = ids; their bytes kept in box[] until the boxes are made in tree order), then their
     * Morton keys. */
    _Static_assert(sizeof(cdist__box) >= 3 * sizeof(double), "a box holds a centre");
    double clo[3] = {INFINITY, INFINITY, INFINITY}, chi[3] = {-INFINITY, -INFINITY, -INFINITY};
    size_t k = 0;
    for (size_t i = 0; i < s->n; i++) {
        if (s->obj[i].state != CD_SCENE_LIVE) {
            s->pos[i] = CD_SCENE_NO_POS;
            continue;
        }
        perm[k] = (uint32_t)i;
        bound x;
        bound_of(&s->obj[i], &x);
        const double c[3] = {x.m.x, x.m.y, x.m.z};
        memcpy(&box[k++], c, sizeof c);
        for (int a = 0; a < 3; a++) {
            if (c[a] < clo[a]) clo[a] = c[a];
            if (c[a] > chi[a]) chi[a] = c[a];
        }
    }
    /* One scale for the three axes: a flat scene (a sheet) gets few bits across its thin axis,
     * so its order follows the sheet instead of the noise across it. */
    double ext = 0.0;
    for (int a = 0; a < 3; a++) ext = fmax(ext, chi[a] - clo[a]);
    double scale[3];
    for (int a = 0; a < 3; a++) scale[a] = ext > 0.0 && isfinite(ext) ? 2097151.0 / ext : 0.0;
    for (size_t p = 0; p < m; p++) {
        uint64_t code = 0;
        double c[3];
        memcpy(c, &box[p], sizeof c);
        for (int a = 0; a < 3; a++) {
            double x = (c[a] - clo[a]) * scale[a];
            uint64_t qx = x > 0.0 ? (x < 2097151.0 ? (uint64_t)x : 2097151u) : 0u;
            code |= spread21(qx) << a;
        }
        key[p] = code;
    }
    radix_sort(key, perm, key_tmp, perm_tmp, m);
    free(key), free(key_tmp), free(perm_tmp);
    /* Boxes into tree order. */
    for (size_t p = 0; p < m; p++) cdist__scene_box(&s->obj[perm[p]], &box[p]);
    for (size_t p = 0; p < m; p++) s->pos[perm[p]] = (uint32_t)p;
    for (size_t p = 0; p < m; p++) tcore[p] = cdist__scene_tcore(&s->obj[perm[p]]);
    free(s->perm), free(s->box), free(s->node), free(s->tcore);
    s->perm = perm;
    s->box = box;
    s->tcore = tcore;
    s->node = node;
    s->node_cap = m ? m : 1;
    s->tree_n = m;
    s->node_n = 0;
    if (m > 0) {
        s->node_n = 1;
        build_node(s, 0, 0, (uint32_t)m);
    }
    /* The node array was sized for the worst case (one node per object). */
    cdist__node *fit = realloc(s->node, (s->node_n ? s->node_n : 1) * sizeof *fit);
    if (fit) s->node = fit, s->node_cap = s->node_n ? s->node_n : 1;
    s->built_leaves = refit(s);
    s->dirty = 0;
    s->stats.rebuilds++;
    return CDIST_OK;
}

cdist_status cdist__scene_prepare(cdist_query *q, cdist_scene *s)
{
    if (s->dirty) return build(q, s);
    if (s->refit_pending) {
        /* Moved objects keep their place in the tree; once the leaves' boxes have grown to twice
         * their size at the build (objects far from their former neighbours), a rebuild pays. */
        double leaves = refit(s);
        if (leaves > 2.0 * s->built_leaves) return build(q, s);
        s->stats.refits++;
    }
    return CDIST_OK;
}

/* ---- scene handle ---- */

cdist_scene *cdist_scene_new(void)
{
    cdist_scene *s = calloc(1, sizeof *s);
    if (s) atomic_init(&s->busy, 0);
    return s;
}

void cdist_scene_free(cdist_scene *s)
{
    if (!s) return;
    for (int i = 0; i < s->worker_n; i++) cdist_query_free(s->worker[i]);
    for (int i = 0; i < s->screen_n; i++) cdist_query_free(s->screen[i]);
    free(s->worker);
    free(s->screen);
    free(s->obj), free(s->arc), free(s->pos), free(s->perm), free(s->box), free(s->node), free(s->tcore);
    free(s->cand), free(s->filter), free(s->chunk_buf);
    free(s->moved), free(s->list_lo), free(s->list_hi);
    free(s);
}

int cdist__scene_take(cdist_scene *s) { return !atomic_exchange_explicit(&s->busy, 1, memory_order_acquire); }
void cdist__scene_release(cdist_scene *s) { atomic_store_explicit(&s->busy, 0, memory_order_release); }

/* Every scene call: the handle's batch flag (one scene or batch call per handle at a time; the
 * handle's own flag is taken by each exact query) and the scene's flag. */
static cdist_status enter(cdist_query *q, cdist_scene *s)
{
    if (!q) return CDIST_ERR_NULL_ARGUMENT;
    if (atomic_exchange_explicit(&q->batch_busy, 1, memory_order_acquire)) return CDIST_ERR_HANDLE_BUSY;
    cdist__begin(q, NULL);
    if (!s) {
        atomic_store_explicit(&q->batch_busy, 0, memory_order_release);
        return cdist__fail(q, CDIST_ERR_NULL_ARGUMENT, "scene pointer is NULL");
    }
    if (!cdist__scene_take(s)) {
        atomic_store_explicit(&q->batch_busy, 0, memory_order_release);
        return cdist__fail(q, CDIST_ERR_HANDLE_BUSY, "scene: in use by another call");
    }
    return CDIST_OK;
}

static cdist_status leave(cdist_query *q, cdist_scene *s, cdist_status st)
{
    cdist__scene_release(s);
    atomic_store_explicit(&q->batch_busy, 0, memory_order_release);
    return st;
}

cdist_status cdist__scene_enter(cdist_query *q, cdist_scene *s) { return enter(q, s); }
cdist_status cdist__scene_leave(cdist_query *q, cdist_scene *s, cdist_status st) { return leave(q, s, st); }

static cdist_status reserve(cdist_query *q, cdist_scene *s, size_t need)
{
    if (need >= UINT32_MAX) return cdist__fail(q, CDIST_ERR_OUT_OF_RANGE, "scene: more than 2^32 - 2 objects");
    if (need <= s->cap) return CDIST_OK;
    size_t cap = s->cap + s->cap / 2;
    if (cap < need) cap = need; /* a bulk add gets exactly its size */
    cdist__scene_obj *o = cdist__big_realloc(s->obj, cap * sizeof *o);
    if (!o) return cdist__fail(q, CDIST_ERR_NO_MEMORY, "scene: out of memory for %zu objects", need);
    s->obj = o;
    uint32_t *p = cdist__big_realloc(s->pos, cap * sizeof *p);
    if (!p) return cdist__fail(q, CDIST_ERR_NO_MEMORY, "scene: out of memory for %zu objects", need);
    s->pos = p;
    if (s->filter) {
        uint32_t *g = cdist__big_realloc(s->filter, 2 * cap * sizeof *g);
        if (!g) return cdist__fail(q, CDIST_ERR_NO_MEMORY, "scene: out of memory for %zu objects", need);
        memset(g + 2 * s->cap, 0, 2 * (cap - s->cap) * sizeof *g);
        s->filter = g;
    }
    if (s->arc) {
        cdist_arc *a = cdist__big_realloc(s->arc, cap * sizeof *a);
        if (!a) return cdist__fail(q, CDIST_ERR_NO_MEMORY, "scene: out of memory for %zu objects", need);
        s->arc = a;
    }
    if (s->moved) {
        double *m = cdist__big_realloc(s->moved, cap * sizeof *m);
        if (!m) return cdist__fail(q, CDIST_ERR_NO_MEMORY, "scene: out of memory for %zu objects", need);
        memset(m + s->cap, 0, (cap - s->cap) * sizeof *m);
        s->moved = m;
    }
    s->cap = cap;
    return CDIST_OK;
}

/* The arcs' array, made when the first arc comes (an object's entry is read only when it is an
 * arc). */
static cdist_status arcs_ready(cdist_query *q, cdist_scene *s, cdist_scene_kind kind)
{
    if (kind != CDIST_SCENE_ARC || s->arc) return CDIST_OK;
    if (!(s->arc = cdist__big_malloc((s->cap ? s->cap : 1) * sizeof *s->arc)))
        return cdist__fail(q, CDIST_ERR_NO_MEMORY, "scene: out of memory for the arcs");
    return CDIST_OK;
}

/* First failing entry of a call: its status and message, kept while later entries overwrite
 * the handle's message. */
typedef struct first_fail {
    size_t index;
    cdist_status status;
    char message[CD_MESSAGE_LEN];
} first_fail;

static void note_fail(cdist_query *q, first_fail *f, size_t index, cdist_status st)
{
    if (st == CDIST_OK || f->status != CDIST_OK) return;
    f->index = index;
    f->status = st;
    memcpy(f->message, q->message, sizeof f->message);
}

static cdist_status report(cdist_query *q, const first_fail *f, const char *what)
{
    cdist__begin(q, NULL);
    if (f->status == CDIST_OK) return CDIST_OK;
    return cdist__fail(q, f->status, "scene %s, entry %zu: %.200s", what, f->index, f->message);
}

/* The arguments of an add or update call: a kind and an object array (every status set on failure). */
static cdist_status check_objects(cdist_query *q, cdist_scene_kind kind, size_t n, const void *objects,
                                  cdist_status *statuses, const char *what)
{
    cdist_status st = CDIST_OK;
    if ((unsigned)kind >= KIND_COUNT)
        st = cdist__fail(q, CDIST_ERR_BAD_KIND, "scene %s: %d is not a cdist_scene_kind", what, (int)kind);
    else if (n > 0 && !objects) st = cdist__fail(q, CDIST_ERR_NULL_ARGUMENT, "scene %s: object array is NULL", what);
    for (size_t k = 0; st && statuses && k < n; k++) statuses[k] = st;
    return st;
}

cdist_status cdist_scene_add(cdist_query *q, cdist_scene *s, cdist_scene_kind kind, size_t n, const void *objects,
                             ptrdiff_t stride, size_t *first_id, cdist_status *statuses)
{
    cdist_status st = enter(q, s);
    if (st) return st;
    if (first_id) *first_id = s->n;
    if ((st = check_objects(q, kind, n, objects, statuses, "add"))) return leave(q, s, st);
    if ((st = reserve(q, s, s->n + n)) || (st = arcs_ready(q, s, kind))) return leave(q, s, st);
    first_fail f = {0, CDIST_OK, ""};
    for (size_t k = 0; k < n; k++) {
        cdist__scene_obj *o = &s->obj[s->n];
        const void *src = (const char *)objects + (ptrdiff_t)k * stride;
        st = cdist__scene_make(q, kind, src, o, s->arc ? &s->arc[s->n] : NULL);
        s->pos[s->n] = CD_SCENE_NO_POS;
        if (statuses) statuses[k] = st;
        note_fail(q, &f, k, st);
        s->live += o->state == CD_SCENE_LIVE;
        s->n++;
    }
    if (n > 0) s->dirty = 1, s->list_ok = 0; /* the pair list lacks the new objects */
    return leave(q, s, report(q, &f, "add"));
}

static cdist_status bad_id(cdist_query *q, size_t id, size_t n)
{
    return cdist__fail(q, CDIST_ERR_OUT_OF_RANGE, "id %zu is out of range or removed (%zu ids)", id, n);
}

/* Accumulate the motion of a live object in the tree (docs/scene.md, moving objects). */
static cdist_status note_motion(cdist_query *q, cdist_scene *s, size_t id, const cdist__scene_item *o)
{
    const cdist__scene_obj *t = &s->obj[id];
    if (t->state != CD_SCENE_LIVE || s->pos[id] == CD_SCENE_NO_POS) return CDIST_OK;
    if (!s->moved) {
        if (!(s->moved = calloc(s->cap, sizeof *s->moved)))
            return cdist__fail(q, CDIST_ERR_NO_MEMORY, "scene update: out of memory for the motion bounds");
        s->list_ok = 0;
    }
    double m = cdist__scene_motion(t, cdist__scene_arc(s, id), &o->o, &o->arc);
    s->moved[id] += m;
    if (!(m <= s->step_moved)) s->step_moved = m;
    s->step_count++;
    return CDIST_OK;
}

cdist_status cdist_scene_update(cdist_query *q, cdist_scene *s, size_t n, const size_t *ids, cdist_scene_kind kind,
                                const void *objects, ptrdiff_t stride, cdist_status *statuses)
{
    cdist_status st = enter(q, s);
    if (st) return st;
    if ((st = check_objects(q, kind, n, objects, statuses, "update")) || (st = arcs_ready(q, s, kind)))
        return leave(q, s, st);
    first_fail f = {0, CDIST_OK, ""};
    for (size_t k = 0; k < n; k++) {
        size_t id = ids ? ids[k] : k;
        if (id >= s->n || s->obj[id].state == CD_SCENE_REMOVED) {
            st = bad_id(q, id, s->n);
        } else {
            cdist__scene_item o;
            st = cdist__scene_make(q, kind, (const char *)objects + (ptrdiff_t)k * stride, &o.o, &o.arc);
            if (st == CDIST_OK && !(st = note_motion(q, s, id, &o))) {
                cdist__scene_obj *t = &s->obj[id];
                if (t->state != CD_SCENE_LIVE) s->live++;
                *t = o.o;
                if (kind == CDIST_SCENE_ARC) s->arc[id] = o.arc;
                uint32_t p = s->pos[id];
                if (p == CD_SCENE_NO_POS) {
                    s->dirty = 1, s->list_ok = 0;
                } else {
                    /* The tree keeps its shape; the boxes above are refitted before the
                     * next query (cdist__scene_prepare). */
                    cdist__scene_box(t, &s->box[p]);
                    s->tcore[p] = cdist__scene_tcore(t);
                    s->refit_pending = 1;
                }
            }
        }
        if (statuses) statuses[k] = st;
        note_fail(q, &f, k, st);
    }
    return leave(q, s, report(q, &f, "update"));
}

cdist_status cdist_scene_remove(cdist_query *q, cdist_scene *s, size_t n, const size_t *ids)
{
    cdist_status st = enter(q, s);
    if (st) return st;
    if (n > 0 && !ids) return leave(q, s, cdist__fail(q, CDIST_ERR_NULL_ARGUMENT, "scene remove: id array is NULL"));
    first_fail f = {0, CDIST_OK, ""};
    for (size_t k = 0; k < n; k++) {
        size_t id = ids[k];
        if (id >= s->n) {
            note_fail(q, &f, k, bad_id(q, id, s->n));
            continue;
        }
        cdist__scene_obj *o = &s->obj[id];
        if (o->state == CD_SCENE_LIVE) s->live--;
        o->state = CD_SCENE_REMOVED;
        /* An empty box is near nothing; the node boxes above it only stay larger than needed. */
        if (s->pos[id] != CD_SCENE_NO_POS) {
            box_empty(&s->box[s->pos[id]]);
            s->tcore[s->pos[id]] = CD_SCENE_T_GONE;
        }
    }
    return leave(q, s, report(q, &f, "remove"));
}

cdist_status cdist_scene_set_groups(cdist_query *q, cdist_scene *s, size_t n, const size_t *ids, const unsigned *group,
                                    const unsigned *chain)
{
    cdist_status st = enter(q, s);
    if (st) return st;
    if (!s->filter && n > 0) {
        s->filter = calloc(s->cap ? 2 * s->cap : 2, sizeof *s->filter);
        if (!s->filter) return leave(q, s, cdist__fail(q, CDIST_ERR_NO_MEMORY, "scene: out of memory for the groups"));
    }
    first_fail f = {0, CDIST_OK, ""};
    for (size_t k = 0; k < n; k++) {
        size_t id = ids ? ids[k] : k;
        if (id >= s->n) {
            note_fail(q, &f, k, bad_id(q, id, s->n));
            continue;
        }
        s->list_ok = 0; /* the list holds the pairs the filter let through */
        if (group) s->filter[2 * id] = group[k];
        if (chain) s->filter[2 * id + 1] = chain[k];
    }
    return leave(q, s, report(q, &f, "set_groups"));
}

size_t cdist_scene_count(const cdist_scene *s) { return s ? s->n : 0; }

cdist_status cdist_scene_object_status(const cdist_scene *s, size_t id)
{
    if (!s) return CDIST_ERR_NULL_ARGUMENT;
    if (id >= s->n || s->obj[id].state == CD_SCENE_REMOVED) return CDIST_ERR_OUT_OF_RANGE;
    return (cdist_status)s->obj[id].status;
}

cdist_status cdist_scene_rebuild(cdist_query *q, cdist_scene *s)
{
    cdist_status st = enter(q, s);
    if (st) return st;
    return leave(q, s, build(q, s));
}

cdist_status cdist_scene_get_stats(const cdist_scene *s, cdist_scene_stats *out)
{
    if (!s || !out) return CDIST_ERR_NULL_ARGUMENT;
    *out = s->stats;
    out->objects = s->n;
    out->live = s->live;
    out->nodes = s->node_n;
    out->bytes = sizeof *s + s->cap * (sizeof *s->obj + sizeof *s->pos + (s->arc ? sizeof *s->arc : 0)) +
                 s->tree_n * (sizeof *s->perm + sizeof *s->box + sizeof *s->tcore) + s->node_cap * sizeof *s->node +
                 s->cand_cap * sizeof *s->cand + (s->filter ? 2 * s->cap * sizeof *s->filter : 0) + s->chunk_buf_cap * sizeof *s->chunk_buf +
                 (s->moved ? s->cap * sizeof *s->moved : 0) + 2 * s->list_cap * sizeof *s->list_lo +
                 (size_t)(s->worker_n + s->screen_n) * sizeof(cdist_query);
    return CDIST_OK;
}
