/* SPDX-License-Identifier: MIT */
/* Scenes (src/scene): objects, certified bounds, the bounding-volume tree and the queries.
 * Nothing here is exported. */
#ifndef CDIST_SCENE_PRIV_H
#define CDIST_SCENE_PRIV_H

#include <float.h>
#include <math.h>
#include <stdatomic.h>
#include <stdint.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "base/mem.h"
#include "base/pool.h"
#include "internal.h"
#include "swept/swept-priv.h"

/* One object's geometry: the core; of an arc its circle, the arc itself kept beside (an arc is
 * 96 bytes, a circle 56: the objects stay small for the scenes without arcs). */
typedef union cdist__scene_geom {
    cdist_vec3 point;
    cdist_segment segment;
    cdist_circle circle; /* circle, disk, or an arc's circle */
} cdist__scene_geom;

enum { CD_SCENE_LIVE = 0, CD_SCENE_INVALID = 1, CD_SCENE_REMOVED = 2 };

typedef struct cdist__scene_obj {
    cdist__scene_geom g;
    double r;       /* ball radius: 0 for the plain kinds */
    uint8_t kind;   /* cdist_scene_kind */
    uint8_t state;  /* CD_SCENE_LIVE, _INVALID, _REMOVED */
    uint8_t status; /* the validation status of an invalid object */
    float scale;    /* a valid object's coordinate scale (largest |coordinate| plus the radii),
                     * rounded up: its share of a pair's bound margin (cdist__scene_margin) */
} cdist__scene_obj;

/* An object outside a scene (a query object, an update's new pose) with room for its arc. */
typedef struct cdist__scene_item {
    cdist__scene_obj o;
    cdist_arc arc;
} cdist__scene_item;

/* An axis-aligned box that contains its object's solid (rounding included): single-precision
 * corners rounded outward (half the memory of the traversals' reads); lane 3 is not used. */
typedef struct cdist__box {
    float lo[4], hi[4];
} cdist__box;

/* Tree node: a leaf (count > 0) holds the tree positions first .. first + count - 1; an inner
 * node (count == 0) has its children at first and first + 1 (children come after their
 * parent, so a backward loop refits bottom-up). */
typedef struct cdist__node {
    cdist__box box;
    uint32_t first, count;
} cdist__node;

#define CD_SCENE_NO_POS UINT32_MAX
enum { CD_SCENE_T_GONE, CD_SCENE_T_OTHER, CD_SCENE_T_CIRCLE };
/* The most objects a leaf holds (src/scene/scene.c builds leaves of up to CD_SCENE_LEAF). */
#define CD_SCENE_LEAF_MAX 8

struct cdist_scene {
    atomic_int busy;
    size_t n, cap;           /* ids given out, allocated */
    cdist__scene_obj *obj;   /* by id */
    cdist_arc *arc;          /* by id, the arcs' arcs (NULL until an arc is added) */
    uint32_t *filter;        /* by id, 2 each: group, chain (NULL until cdist_scene_set_groups) */
    uint32_t *pos;           /* by id: position in the tree, CD_SCENE_NO_POS when not in it */
    /* The tree over the live objects at its last build: positions 0 .. tree_n - 1. */
    size_t tree_n;
    uint32_t *perm;          /* by position: the id */
    cdist__box *box;         /* by position: the object's box (empty when removed) */
    uint8_t *tcore;          /* by position: CD_SCENE_T_GONE (removed), _T_CIRCLE (a circle
                              * core: circle, torus) or _T_OTHER; what the broad phase asks of
                              * an object, kept in tree order so that it reads no object */
    cdist__node *node;
    size_t node_n, node_cap;
    int dirty;               /* objects added or revived since the build: rebuild before a query */
    int refit_pending;       /* boxes changed since the last refit */
    double built_leaves;     /* the sum of the leaves' box sizes at the build */
    size_t live;
    /* Workspaces, kept between queries. */
    uint64_t *cand;
    size_t cand_cap;
    cdist_query **worker;    /* handles of the extra threads */
    int worker_n;
    cdist_query **screen;    /* one per thread: the batch distance screen (1 thread each) */
    int screen_n;
    cdist_scene_pair *chunk_buf;
    size_t chunk_buf_cap;
    cdist_scene_stats stats;
    /* Reuse between queries of a moving scene (pairs_within, docs/scene.md): */
    double *moved;           /* by id: how far any point of the solid may have moved since the
                              * list's poses (NULL until the first update) */
    double step_moved;       /* the largest motion of an object since the last query */
    size_t step_count;       /* objects moved since the last query */
    int list_ok;             /* cand holds the pair list: every pair whose boxes were within
                              * list_reach at its poses, sorted */
    double list_reach;
    size_t list_n;
    float *list_lo, *list_hi; /* by list entry: lower (upper) bound of the pair's distance
                               * plus (minus) the two objects' moved at the time it was known */
    size_t list_cap;
    size_t list_builds, list_reuses; /* pairs_within queries that made the list, that reused it */
    size_t moved_queries;    /* pairs_within queries that followed updates */
};

/* The pair list's skin: the list made after an update reaches this many times twice the
 * largest motion of an object in that update beyond delta (at most the mean box extent of an
 * object), so that as many more similar updates keep it valid (docs/scene.md). */
#define CD_SCENE_SKIN_STEPS 6.0

/* Tolerances of the scene's bounds (src/base/tolerances.h has the reasons). */

/* The core descriptor of an object for cdist__swept_query (arc: the object's arc when it is
 * one, else not read). */
cdist__core_obj cdist__scene_core(const cdist__scene_obj *o, const cdist_arc *arc);
/* The certified solid box of a valid object. */
void cdist__scene_box(const cdist__scene_obj *o, cdist__box *b);
/* 1 when the signed distance of a and b is certified > lim (balls, circle-plane slabs and the
 * ring screen, each lowered by the bound margin); 0 when the pair must be answered. */
int cdist__scene_excluded(const cdist__scene_obj *a, const cdist__scene_obj *b, double lim, int ring);
/* ring 0 leaves the ring screen out for two circle cores (cdist__scene_circle_pair: circles and
 * tori), which the narrow phase screens with the batch distance kernel instead. */
int cdist__scene_circle_pair(const cdist__scene_obj *a, const cdist__scene_obj *b);
/* An object's tcore value (CD_SCENE_T_OTHER or _T_CIRCLE). */
uint8_t cdist__scene_tcore(const cdist__scene_obj *o);
/* The bound margin of a pair: CD_SCENE_BOUND_REL times the two objects' coordinate scales (the
 * stored ones, rounded up: a larger margin only decides fewer pairs). */
static inline double cdist__scene_margin(const cdist__scene_obj *a, const cdist__scene_obj *b)
{
    return CD_SCENE_BOUND_REL * ((double)a->scale + (double)b->scale);
}
/* A bound of how far any point of a's solid is from b's when the object changes from a to b
 * (the radius change included; INFINITY when the core kind changes or for an arc that changes;
 * arc_a, arc_b: their arcs when they are arcs), rounded up. */
double cdist__scene_motion(const cdist__scene_obj *a, const cdist_arc *arc_a, const cdist__scene_obj *b,
                           const cdist_arc *arc_b);
/* Validate one object of a kind (q's tolerance) into o, an arc's arc into *arc (not touched
 * for the other kinds); returns the status (o->state set). */
cdist_status cdist__scene_make(cdist_query *q, cdist_scene_kind kind, const void *src, cdist__scene_obj *o,
                              cdist_arc *arc);
/* Object id's arc (when it is an arc) of scene s. */
static inline const cdist_arc *cdist__scene_arc(const cdist_scene *s, size_t id) { return s->arc ? &s->arc[id] : NULL; }
/* Bring the tree up to date (rebuild when dirty or degraded, refit when boxes grew). */
cdist_status cdist__scene_prepare(cdist_query *q, cdist_scene *s);
/* Take / release the scene's in-use flag. */
int cdist__scene_take(cdist_scene *s);
void cdist__scene_release(cdist_scene *s);
/* Every scene call starts with cdist__scene_enter (the handle's batch flag, which also keeps
 * its options and threads fixed, then the scene's flag; the message cleared) and ends with
 * cdist__scene_leave, which releases both and returns st. */
cdist_status cdist__scene_enter(cdist_query *q, cdist_scene *s);
cdist_status cdist__scene_leave(cdist_query *q, cdist_scene *s, cdist_status st);
/* Sort 64-bit keys ascending (tmp: n entries of scratch). */
void cdist__radix_sort_keys(uint64_t *key, uint64_t *tmp, size_t n);
/* Sort pair keys (i << 32 | j, every i < ids) ascending: a counting pass by i, then each i's
 * run by j. tmp: n keys of scratch, cnt: ids + 1 counters of scratch. */
void cdist__sort_pair_keys(uint64_t *key, uint64_t *tmp, uint32_t *cnt, size_t ids, size_t n);

/* A float <= x (>= x) within three ulps, without a branch (which way rounding to nearest goes
 * is random): x moved away by more than an ulp of float (relative 2^-23, absolute 2^-149 for
 * the subnormals), then rounded to nearest, which moves it back by at most half an ulp; the
 * overflow to +inf (-inf) and the NaN of an infinite x clamp to the largest float. */
static inline float cdist__float_down(double x)
{
    float f = (float)(x - fabs(x) * 0x1p-23 - 0x1p-149);
    return f < FLT_MAX ? f : FLT_MAX;
}
static inline float cdist__float_up(double x)
{
    float f = (float)(x + fabs(x) * 0x1p-23 + 0x1p-149);
    return f > -FLT_MAX ? f : -FLT_MAX;
}
/* lim for cdist__box_near: rounded up to single precision. */
static inline float cdist__box_lim(double lim) { return cdist__float_up(lim); }

/* Box gap test: every axis gap <= lim (a cdist__box_lim; false for a NaN gap). Rounding is
 * monotone, so a gap of the boxes <= lim stays <= lim when the subtraction rounds. With SSE,
 * the three axes at a time. */
static inline int cdist__box_near(const cdist__box *a, const cdist__box *b, float lim)
{
#if defined(__SSE2__)
    __m128 l = _mm_set1_ps(lim);
    __m128 x = _mm_sub_ps(_mm_loadu_ps(b->lo), _mm_loadu_ps(a->hi));
    __m128 y = _mm_sub_ps(_mm_loadu_ps(a->lo), _mm_loadu_ps(b->hi));
    return (_mm_movemask_ps(_mm_and_ps(_mm_cmple_ps(x, l), _mm_cmple_ps(y, l))) & 7) == 7;
#else
    return (b->lo[0] - a->hi[0] <= lim) & (a->lo[0] - b->hi[0] <= lim) & (b->lo[1] - a->hi[1] <= lim) &
           (a->lo[1] - b->hi[1] <= lim) & (b->lo[2] - a->hi[2] <= lim) & (a->lo[2] - b->hi[2] <= lim);
#endif
}
/* The largest axis gap of two boxes, rounded down (a lower bound of the distance of their
 * contents when > 0): the difference of two floats in double is exact unless their exponents
 * are far apart, and then within an ulp. */
static inline double cdist__box_gap(const cdist__box *a, const cdist__box *b)
{
    double g = 0.0;
    for (int k = 0; k < 3; k++) {
        double x = (double)b->lo[k] - (double)a->hi[k], y = (double)a->lo[k] - (double)b->hi[k];
        if (x > g) g = x;
        if (y > g) g = y;
    }
    return g * (1.0 - DBL_EPSILON);
}
/* The sum of a box's extents: which of two subtrees the walks split first. */
static inline double cdist__box_size(const cdist__box *x)
{
    return (x->hi[0] - x->lo[0]) + (x->hi[1] - x->lo[1]) + (x->hi[2] - x->lo[2]);
}
/* The largest axis gap of two boxes (0 when they overlap) to the rounding of float: an order of
 * pairs of boxes, not a bound (cdist__box_near with a cdist__box_lim decides). */
static inline float cdist__box_gap_f(const cdist__box *a, const cdist__box *b)
{
#if defined(__SSE2__)
    __m128 m = _mm_max_ps(_mm_sub_ps(_mm_loadu_ps(b->lo), _mm_loadu_ps(a->hi)),
                          _mm_sub_ps(_mm_loadu_ps(a->lo), _mm_loadu_ps(b->hi))); /* lane 3: 0 */
    m = _mm_max_ps(m, _mm_movehl_ps(m, m));
    return _mm_cvtss_f32(_mm_max_ss(m, _mm_shuffle_ps(m, m, 1)));
#else
    return (float)cdist__box_gap(a, b);
#endif
}

/* ---- The queries: the broad phase (scene_broad.c), the exact answers and the narrow phase
 * (scene_pairs.c) and the threads of a call (scene_threads.c), which the per-pair queries
 * (scene_jobs.c) and the searches (scene_search.c) use too. ---- */

/* Keys answered by one thread at a time (narrow phase, linked pairs). */
#define CD_SCENE_CHUNK 256

/* Pair (i, j), i < j, left out by the filter of cdist_scene_set_groups: one group, or
 * neighbours in one chain. */
static inline int cdist__scene_skipped(const cdist_scene *s, size_t i, size_t j)
{
    if (!s->filter) return 0;
    uint32_t ga = s->filter[2 * i], gb = s->filter[2 * j], ca = s->filter[2 * i + 1], cb = s->filter[2 * j + 1];
    if (ga != 0 && ga == gb) return 1;
    return j == i + 1 && ca != 0 && ca == cb;
}

/* The core of object id of s, of a query object. */
static inline cdist__core_obj cdist__scene_core_of(const cdist_scene *s, size_t id)
{
    return cdist__scene_core(&s->obj[id], cdist__scene_arc(s, id));
}
static inline cdist__core_obj cdist__scene_item_core(const cdist__scene_item *x)
{
    return cdist__scene_core(&x->o, &x->arc);
}

/* The threads of one call: for the handle's thread count T, a pool of T - 1 threads
 * (src/base/pool.h) started for the call, each running fn(ctx, t) once per
 * cdist__scene_pool_run with its thread number t (the caller is t = 0). When the threads cannot
 * be started the caller runs alone, with the same answers. */
typedef struct cdist__scene_pool {
    int threads; /* including the caller */
    cdist__pool *workers;
} cdist__scene_pool;

void cdist__scene_pool_start(cdist__scene_pool *p, int threads);
void cdist__scene_pool_run(cdist__scene_pool *p, void (*fn)(void *ctx, int t), void *ctx);
void cdist__scene_pool_stop(cdist__scene_pool *p);
/* The threads of a call: the handle's count (1 when their handles cannot be made ready), their
 * handles, and one screening handle per thread (*screen NULL when those cannot be made). */
int cdist__scene_call_threads(cdist_query *q, cdist_scene *s, cdist_query **handles, cdist_query ***screen);

/* Broad phase: pairs within delta. */
typedef struct cdist__scene_broad {
    cdist_scene *sa, *sb;
    int self;        /* one scene: pairs i < j, the skip filter applies */
    float lim;       /* box test: max(delta, 0) (boxes bound the solids, not the signed distance),
                      * rounded up (cdist__box_lim) */
    double delta;
    size_t box_pairs;
    uint64_t *key;
    size_t n, cap;
    int oom;
    int link;        /* linked pairs: rings only, the ball screen of link_excluded, no skip filter */
    const double *reach; /* time of impact: by id, how far the object's solid moves; a pair is
                          * kept when its distance may be <= delta + reach[i] + reach[j] */
    int list;        /* the pair list of a moving scene: every pair whose boxes are within lim */
    int screen;      /* the narrow phase screens pairs of circle cores (cdist__batch_screen), whose
                      * first stage costs about what the bounds of cdist__scene_excluded cost and
                      * decides far more pairs: those bounds are left out for them */
} cdist__scene_broad;
/* Append a key to b->key (b->oom set when memory runs out). */
void cdist__scene_push(cdist__scene_broad *b, uint64_t key);
/* The objects at tree positions pa of sa and pb of sb, ordered i < j within one scene (self):
 * 0 when either is removed (the objects in a tree are live otherwise) or the pair is skipped.
 * The objects themselves are not read. */
int cdist__scene_pair_at(const cdist_scene *sa, const cdist_scene *sb, int self, int filter, uint32_t pa, uint32_t pb,
                         size_t *pi, size_t *pj, const cdist__scene_obj **poa, const cdist__scene_obj **pob);
/* The tree of s against itself from node x: each leaf (its positions first .. first + count - 1)
 * to leaf(ctx, first, count), and each pair of sibling subtrees to cross(ctx, x, y). */
void cdist__scene_self_walk(const cdist_scene *s, uint32_t x, void (*leaf)(void *, uint32_t, uint32_t),
                            void (*cross)(void *, uint32_t, uint32_t), void *ctx);
/* The candidate keys of sa x sb into sa->cand (unsorted), on the pool's threads. */
cdist_status cdist__scene_broad_run(cdist_query *q, cdist__scene_broad *b, cdist__scene_pool *p, const char *what);
/* Sort the candidate keys, whose i are ids of s (the scratch lives for the sort only: it would
 * double the candidates' share of the scene's memory). By i first when the ids are not many
 * more than the keys, else by the radix sort alone. */
cdist_status cdist__scene_sort_keys(cdist_query *q, const cdist_scene *s, uint64_t *key, size_t n);

/* Exact answers and the narrow phase. A failed pair's record (NaN distance and points): */
void cdist__scene_pair_error(cdist_scene_pair *p, size_t i, size_t j, cdist_status st);
/* The exact answer of the pair of cores (a first) into *p: 1 when it is to be reported
 * (distance <= lim, or a failure, reported always); *dist (when not NULL) its distance, NaN on
 * failure. */
int cdist__scene_answer(cdist_query *h, cdist__core_obj ca, cdist__core_obj cb, size_t i, size_t j, double lim,
                        cdist_scene_pair *p, double *dist);
/* The message of a failed pair's status. */
const char *cdist__scene_pair_message(cdist_status st);
/* delta and the output array of a query that reports pairs. */
cdist_status cdist__scene_check_delta(cdist_query *q, double delta, const void *out, size_t capacity);
/* One narrow phase: its keys, its sink, its threads' handles and the chunks of its round. */
typedef struct cdist__scene_narrow {
    cdist_scene *sa, *sb;            /* pair (i of sa, j of sb) */
    const cdist__scene_item *qo;     /* or (key of sa, the query object): j = SIZE_MAX */
    const uint64_t *key;
    size_t n;
    double lim;
    cdist_scene_pair *out;           /* sink: the caller's array ... */
    size_t capacity;
    cdist_scene_pair_fn fn;          /* ... or its callback */
    void *user;
    size_t count;                    /* pairs reported */
    int stopped;                     /* the callback asked to stop */
    cdist_status fail;               /* first failing pair (in key order) */
    size_t fail_i, fail_j;
    cdist_query **h;                 /* handle of thread t */
    cdist_query **hs;                /* its screening handle (NULL: no screen) */
    size_t round_lo, round_hi;       /* chunks of the current round */
    atomic_size_t next;
    cdist_scene_pair *buf;           /* CD_SCENE_CHUNK answers per chunk of the round */
    size_t *buf_n;                   /* answers kept per chunk */
    size_t *buf_full;                /* full queries per chunk */
    size_t full;                     /* full queries in all */
    /* The pair list of a moving scene (keys: its entries): each entry is decided here, from its
     * bounds and the objects' motions first, and its bounds are renewed from what is learnt. */
    float *lo, *hi;
    int certified;                   /* the exact answers are certified minima (AUTO, ROBUST) */
    size_t *buf_box, *buf_past;      /* per chunk: pairs whose boxes are near, past the bounds */
    size_t box_pairs, past;
} cdist__scene_narrow;
/* Answer w->n keys with the pool's threads; reports go to the sink in key order. */
cdist_status cdist__scene_run_narrow(cdist_query *q, cdist_scene *s, cdist__scene_narrow *w, cdist__scene_pool *p);
/* The status of a finished narrow phase, with the message of its first failing pair. */
cdist_status cdist__scene_narrow_status(cdist_query *q, const cdist__scene_narrow *w, const char *what);

#endif
