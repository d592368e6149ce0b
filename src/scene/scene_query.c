/* SPDX-License-Identifier: MIT */
/* Scene queries. A query runs in two phases: the broad phase walks the tree (two subtrees at a
 * time) and keeps the object pairs that no certified bound excludes, as keys (i << 32 | j);
 * the keys are sorted, and the narrow phase answers each with the exact query, chunks of keys
 * spread over the handle's threads and committed in key order, so the output is the same for
 * every thread count. */
#include <stdlib.h>
#include <string.h>

#include "base/pool.h"
#include "batch/batch-priv.h"
#include "scene-priv.h"

/* Keys answered by one thread at a time, and chunks per thread and round of the narrow phase
 * (a round's answers are committed in order before the next round starts). */
#define CD_SCENE_CHUNK 256
#define CD_SCENE_CHUNKS_PER_THREAD 8
/* Pairs per grab of a time-of-impact thread: each pair costs tens of distance queries. */
#define CD_SCENE_TOI_CHUNK 64

/* ---- pair filters ---- */

static int skipped(const cdist_scene *s, size_t i, size_t j)
{
    if (!s->filter) return 0;
    uint32_t ga = s->filter[2 * i], gb = s->filter[2 * j], ca = s->filter[2 * i + 1], cb = s->filter[2 * j + 1];
    if (ga != 0 && ga == gb) return 1;
    return j == i + 1 && ca != 0 && ca == cb;
}

static int unsupported(cdist__core_type a, cdist__core_type b)
{
    return (a == CD_CORE_POINT && b == CD_CORE_ARC) || (a == CD_CORE_ARC && b == CD_CORE_POINT);
}

static void pair_error(cdist_scene_pair *p, size_t i, size_t j, cdist_status st)
{
    p->i = i;
    p->j = j;
    p->distance = NAN;
    p->status = st;
    p->num_pairs = 0;
    p->flags = 0;
    p->reserved = 0;
    for (int k = 0; k < 2; k++) p->point[k][0] = p->point[k][1] = v3(NAN, NAN, NAN);
}

/* The record of pair (i, j) from its contact c (status st; c is not read on failure): 1 when it
 * is to be reported (distance <= lim, or a failure, reported always); *dist its distance (NaN
 * on failure). */
static int pair_record(const cdist_contact *c, cdist_status st, size_t i, size_t j, double lim, cdist_scene_pair *p,
                       double *dist)
{
    if (dist) *dist = NAN;
    if (st) {
        pair_error(p, i, j, st);
        return 1;
    }
    if (dist) *dist = c->distance;
    if (!(c->distance <= lim)) return 0;
    p->i = i;
    p->j = j;
    p->distance = c->distance;
    p->status = CDIST_OK;
    p->num_pairs = c->num_pairs;
    p->flags = (c->equidistant ? CDIST_SCENE_PAIR_EQUIDISTANT : 0) |
               ((c->flags & CDIST_CONTACT_CORE_TOUCH) ? CDIST_SCENE_PAIR_CORE_TOUCH : 0);
    p->reserved = 0;
    for (int k = 0; k < 2; k++) {
        p->point[k][0] = k < c->num_pairs ? c->pairs[k].point[0] : v3(NAN, NAN, NAN);
        p->point[k][1] = k < c->num_pairs ? c->pairs[k].point[1] : v3(NAN, NAN, NAN);
    }
    return 1;
}

/* The core of object id of s, of a query object. */
static cdist__core_obj core_of(const cdist_scene *s, size_t id)
{
    return cdist__scene_core(&s->obj[id], cdist__scene_arc(s, id));
}
static cdist__core_obj core_of_item(const cdist__scene_item *x) { return cdist__scene_core(&x->o, &x->arc); }

/* The exact answer of the pair of cores (a first), as pair_record reports it. */
static int answer(cdist_query *h, cdist__core_obj ca, cdist__core_obj cb, size_t i, size_t j, double lim,
                  cdist_scene_pair *p, double *dist)
{
    if (unsupported(ca.type, cb.type)) return pair_record(NULL, CDIST_ERR_BAD_KIND, i, j, lim, p, dist);
    cdist_contact c;
    cdist_status st = cdist__swept_query(h, &ca, &cb, &c, NULL);
    return pair_record(&c, st, i, j, lim, p, dist);
}

/* The exact answers of pairs of circle cores (circles, tori), CIRCLES at a time: their cores'
 * certified searches run in lanes together (cdist__circle_circle_many), each answer the swept
 * query's to the bit. */
enum { CIRCLES = 16 };
typedef struct circles_ahead {
    cdist__core_obj a[CIRCLES], b[CIRCLES];
    cdist_result core[CIRCLES];
    cdist_contact c[CIRCLES];
    cdist_status st[CIRCLES];
    cdist_query *h;
    int n, used; /* answers made, taken */
} circles_ahead;

static void circles_done(void *ctx, size_t k, cdist_status st)
{
    circles_ahead *x = ctx;
    x->st[k] = cdist__contact_of_core_query(x->h, &x->a[k], &x->b[k], st, &x->core[k], &x->c[k]);
}

static void circles_answer(circles_ahead *x)
{
    const cdist_circle *pa[CIRCLES], *pb[CIRCLES];
    cdist_result *pr[CIRCLES];
    for (int k = 0; k < x->n; k++) {
        pa[k] = x->a[k].obj;
        pb[k] = x->b[k].obj;
        pr[k] = &x->core[k];
    }
    cdist__circle_circle_many(x->h, (size_t)x->n, pa, pb, pr, circles_done, x);
    x->used = 0;
}

static const char *pair_message(cdist_status st)
{
    return st == CDIST_ERR_BAD_KIND ? "no exact query for a point (or sphere) and an arc" : cdist_status_string(st);
}

/* ---- broad phase: pairs within delta ---- */

typedef struct broad {
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
} broad;

static void push(broad *b, uint64_t key)
{
    if (b->n == b->cap) {
        size_t cap = b->cap ? 2 * b->cap : 1024;
        uint64_t *k = cdist__big_realloc(b->key, cap * sizeof *k);
        if (!k) {
            b->oom = 1;
            return;
        }
        b->key = k;
        b->cap = cap;
    }
    b->key[b->n++] = key;
}

/* The objects at tree positions pa of sa and pb of sb, ordered i < j within one scene (self):
 * 0 when either is removed (the objects in a tree are live otherwise) or the pair is skipped.
 * The objects themselves are not read. */
static int pair_at(const cdist_scene *sa, const cdist_scene *sb, int self, int filter, uint32_t pa, uint32_t pb,
                   size_t *pi, size_t *pj, const cdist__scene_obj **poa, const cdist__scene_obj **pob)
{
    if (sa->tcore[pa] == CD_SCENE_T_GONE || sb->tcore[pb] == CD_SCENE_T_GONE) return 0;
    size_t i = sa->perm[pa], j = sb->perm[pb];
    if (self && i > j) {
        size_t t = i;
        i = j, j = t;
    }
    if (self && filter && skipped(sa, i, j)) return 0;
    *pi = i, *pj = j, *poa = &sa->obj[i], *pob = &sb->obj[j];
    return 1;
}

/* Both objects at tree positions pa of sa and pb of sb have circle cores. */
static int circle_pair_at(const broad *b, uint32_t pa, uint32_t pb)
{
    return b->sa->tcore[pa] == CD_SCENE_T_CIRCLE && b->sb->tcore[pb] == CD_SCENE_T_CIRCLE;
}

/* Two rings (circle or torus objects) whose solids' bounding balls are apart by more than
 * CD_SCENE_LINK_REACH_REL * L plus the bound margin: certified unlinked (a linked circle crosses
 * the other's disk, inside both balls) and apart, and answered 0 by the linking query. */
static int link_excluded(const cdist__scene_obj *a, const cdist__scene_obj *b)
{
    const cdist_circle *ca = &a->g.circle, *cb = &b->g.circle;
    double c = v_dist(v3(ca->center.x, ca->center.y, ca->center.z), v3(cb->center.x, cb->center.y, cb->center.z));
    double L = fmax(fmax(ca->radius, cb->radius), c);
    return c - (ca->radius + a->r + cb->radius + b->r) > CD_SCENE_LINK_REACH_REL * L + cdist__scene_margin(a, b);
}

/* The leaves' box tests note a pair of leaf offsets u, v as u << 8 | v. */
_Static_assert(CD_SCENE_LEAF_MAX <= 256, "leaf offsets fit in 8 bits");

/* The pair at tree positions pa, pb, whose boxes are within lim. */
static void near_pos(broad *b, uint32_t pa, uint32_t pb)
{
    size_t i, j;
    const cdist__scene_obj *oa, *ob;
    if (!pair_at(b->sa, b->sb, b->self, !b->link, pa, pb, &i, &j, &oa, &ob)) return;
    if (b->link && !circle_pair_at(b, pa, pb)) return;
    b->box_pairs++;
    if (b->list) {
        push(b, (uint64_t)i << 32 | j);
        return;
    }
    if (b->link ? link_excluded(oa, ob)
                : !(b->screen && circle_pair_at(b, pa, pb)) &&
                      cdist__scene_excluded(oa, ob, b->reach ? b->delta + b->reach[i] + b->reach[j] : b->delta, 0))
        return;
    push(b, (uint64_t)i << 32 | j);
}

/* The pairs of positions (px[u], py[v]) whose boxes are within lim, v > u only when upper (a
 * leaf against itself), found without a branch per pair (which pairs pass is no pattern a
 * predictor learns), then taken in (u, v) order. */
static void near_pairs(broad *b, const uint32_t *px, uint32_t mx, const uint32_t *py, uint32_t my, int upper)
{
    uint32_t hit[CD_SCENE_LEAF_MAX * CD_SCENE_LEAF_MAX], nh = 0;
    for (uint32_t u = 0; u < mx; u++)
        for (uint32_t v = upper ? u + 1 : 0; v < my; v++) {
            hit[nh] = u << 8 | v;
            nh += (uint32_t)cdist__box_near(&b->sa->box[px[u]], &b->sb->box[py[v]], b->lim);
        }
    for (uint32_t k = 0; k < nh; k++) near_pos(b, px[hit[k] >> 8], py[hit[k] & 255]);
}

static double box_size(const cdist__box *x) { return (x->hi[0] - x->lo[0]) + (x->hi[1] - x->lo[1]) + (x->hi[2] - x->lo[2]); }

static void cross(broad *b, uint32_t x, uint32_t y)
{
    const cdist__node *nx = &b->sa->node[x], *ny = &b->sb->node[y];
    if (!cdist__box_near(&nx->box, &ny->box, b->lim)) return;
    if (nx->count && ny->count) {
        /* Only the objects near the other leaf's box can pair: a pass per leaf first, also
         * without a branch per object. */
        uint32_t px[CD_SCENE_LEAF_MAX], py[CD_SCENE_LEAF_MAX], mx = 0, my = 0;
        for (uint32_t p = nx->first; p < nx->first + nx->count; p++) {
            px[mx] = p;
            mx += (uint32_t)cdist__box_near(&b->sa->box[p], &ny->box, b->lim);
        }
        for (uint32_t q = ny->first; q < ny->first + ny->count; q++) {
            py[my] = q;
            my += (uint32_t)cdist__box_near(&b->sb->box[q], &nx->box, b->lim);
        }
        near_pairs(b, px, mx, py, my, 0);
    } else if (ny->count || (!nx->count && box_size(&nx->box) >= box_size(&ny->box))) {
        cross(b, nx->first, y);
        cross(b, nx->first + 1, y);
    } else {
        cross(b, x, ny->first);
        cross(b, x, ny->first + 1);
    }
}

/* The tree of s against itself from node x: each leaf (its positions first .. first + count - 1)
 * to leaf(ctx, first, count), and each pair of sibling subtrees to cross(ctx, x, y). */
static void self_walk(const cdist_scene *s, uint32_t x, void (*leaf)(void *, uint32_t, uint32_t),
                      void (*cross)(void *, uint32_t, uint32_t), void *ctx)
{
    const cdist__node *nx = &s->node[x];
    if (nx->count) {
        leaf(ctx, nx->first, nx->count);
        return;
    }
    self_walk(s, nx->first, leaf, cross, ctx);
    self_walk(s, nx->first + 1, leaf, cross, ctx);
    cross(ctx, nx->first, nx->first + 1);
}

/* The pairs p < q of a leaf whose boxes are near. */
static void self_leaf(void *ctx, uint32_t first, uint32_t count)
{
    uint32_t p[CD_SCENE_LEAF_MAX];
    for (uint32_t u = 0; u < count; u++) p[u] = first + u;
    near_pairs(ctx, p, count, p, count, 1);
}
static void cross_fn(void *b, uint32_t x, uint32_t y) { cross(b, x, y); }
static void self(broad *b, uint32_t x) { self_walk(b->sa, x, self_leaf, cross_fn, b); }

/* ---- narrow phase: threads, rounds, ordered commit ---- */

typedef struct narrow {
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
    size_t *buf_box, *buf_past;      /* per chunk: pairs whose boxes are near, past the bounds */
    size_t box_pairs, past;
} narrow;

/* The objects of key k: i, j (SIZE_MAX for the query object) and the second object. */
static const cdist__scene_obj *key_pair(const narrow *w, size_t k, size_t *i, size_t *j)
{
    if (w->qo) {
        *i = (size_t)w->key[k];
        *j = SIZE_MAX;
        return &w->qo->o;
    }
    *i = (size_t)(w->key[k] >> 32);
    *j = (size_t)(w->key[k] & 0xffffffffu);
    return &w->sb->obj[*j];
}

/* Entry k, whose objects have moved mm together, learns that its distance is >= lo and <= hi
 * now (NaN: nothing learnt). */
static void list_learn(narrow *w, size_t k, double mm, double lo, double hi)
{
    double nl = lo + mm, nh = hi - mm;
    if (nl > (double)w->lo[k]) w->lo[k] = fmaxf(w->lo[k], cdist__float_down(nl));
    if (nh < (double)w->hi[k]) w->hi[k] = fminf(w->hi[k], cdist__float_up(nh));
}

enum { ACT_SKIP, ACT_ANSWER, ACT_SCREEN };

/* What list entry k needs. Its bounds, moved by the two objects' motions since they were
 * known (each point moves at most moved[i]; the distance changes at most by the sum), decide
 * first; then the boxes and the bounds of the current poses, whose results the entry keeps. */
static int list_action(narrow *w, size_t k, const cdist__scene_obj *a, const cdist__scene_obj *b, size_t i, size_t j,
                       size_t *box, int *decided, double *moved, double *pmargin)
{
    const cdist_scene *s = w->sa;
    *decided = 0;
    if (a->state != CD_SCENE_LIVE || b->state != CD_SCENE_LIVE || skipped(s, i, j)) return ACT_SKIP;
    double mm = s->moved[i] + s->moved[j], margin = cdist__scene_margin(a, b);
    *moved = mm, *pmargin = margin;
    if ((double)w->lo[k] - mm - margin > w->lim) return ACT_SKIP;
    if ((double)w->hi[k] + mm + margin <= w->lim) {
        *decided = 1; /* certainly within: the screens cannot exclude it */
        return ACT_ANSWER;
    }
    uint32_t pa = s->pos[i], pb = s->pos[j];
    if (pa != CD_SCENE_NO_POS && pb != CD_SCENE_NO_POS) {
        double gap = cdist__box_gap(&s->box[pa], &s->box[pb]);
        if (gap > fmax(w->lim, 0.0)) {
            list_learn(w, k, mm, gap, NAN);
            return ACT_SKIP;
        }
    }
    (*box)++;
    if (!(w->hs && cdist__scene_circle_pair(a, b)) && cdist__scene_excluded(a, b, w->lim, 0)) {
        list_learn(w, k, mm, w->lim, NAN);
        return ACT_SKIP;
    }
    return ACT_ANSWER;
}

/* The cutoff of a screened pair: a core distance c with (c - radii) - margin > lim in floating
 * point, so that a distance the screen puts above it passes the same test: the first one from
 * (lim + margin) + radii upward, or, when a few ulps of c do not reach it (c far below the
 * terms that cancelled in it, as for lim = -radii), one a few ulps of the terms above. */
static double screen_cutoff(double lim, double margin, double radii)
{
    double c = (lim + margin) + radii, step = DBL_EPSILON * (fabs(lim) + margin + radii);
    for (int k = 0; !((c - radii) - margin > lim) && c < INFINITY; k++) {
        if (k < 4) {
            c = nextafter(c, INFINITY);
        } else {
            c += step;
            step *= 2.0;
        }
    }
    return c;
}

/* One chunk of keys. Pairs of two circle cores are screened first by the circle-circle kernel
 * (hs, one thread; cdist__batch_screen): its distance is within 2 ulps of the scale of the full
 * query's, far inside the bound margin, so a pair it puts above lim + margin is above lim; its
 * first stage alone often decides (a certified lower bound above the cutoff, or a point within
 * it). The others get the full query. */
static void run_chunk(narrow *w, cdist_query *h, cdist_query *hs, size_t c)
{
    size_t lo = c * CD_SCENE_CHUNK, hi = lo + CD_SCENE_CHUNK < w->n ? lo + CD_SCENE_CHUNK : w->n;
    size_t slot = c - w->round_lo, m = 0, nc = 0, full = 0, box = 0, past = 0;
    cdist_scene_pair *out = w->buf + slot * CD_SCENE_CHUNK;
    cdist_circle ca[CD_SCENE_CHUNK], cb[CD_SCENE_CHUNK];
    double dist[CD_SCENE_CHUNK], cut[CD_SCENE_CHUNK];
    unsigned char act[CD_SCENE_CHUNK];
    double mm[CD_SCENE_CHUNK], mg[CD_SCENE_CHUNK]; /* the objects' motions (list), the margin */
    for (size_t k = lo; k < hi; k++) {
        size_t i, j;
        const cdist__scene_obj *b = key_pair(w, k, &i, &j), *a = &w->sa->obj[i];
        int decided = 0;
        int what = w->lo ? list_action(w, k, a, b, i, j, &box, &decided, &mm[k - lo], &mg[k - lo]) : ACT_ANSWER;
        if (what == ACT_ANSWER && !decided && hs && cdist__scene_circle_pair(a, b)) {
            what = ACT_SCREEN;
            ca[nc] = a->g.circle;
            cb[nc] = b->g.circle;
            if (!w->lo) mg[k - lo] = cdist__scene_margin(a, b);
            cut[nc] = screen_cutoff(w->lim, mg[k - lo], a->r + b->r);
            nc++;
        }
        past += what != ACT_SKIP;
        act[k - lo] = (unsigned char)what;
    }
    if (nc > 0 && cdist__batch_screen(hs, nc, ca, cb, cut, dist) == CDIST_ERR_HANDLE_BUSY)
        for (size_t t = 0; t < nc; t++) dist[t] = NAN;
    nc = 0;
    /* the pairs to answer exactly, in key order; those of two circle cores are answered
     * CIRCLES at a time ahead of their turn */
    size_t todo[CD_SCENE_CHUNK], nt = 0;
    for (size_t k = lo; k < hi; k++) {
        if (act[k - lo] == ACT_SKIP) continue;
        if (act[k - lo] == ACT_SCREEN) {
            size_t i, j;
            const cdist__scene_obj *b = key_pair(w, k, &i, &j), *a = &w->sa->obj[i];
            double d = dist[nc++] - (a->r + b->r);
            /* above: d is the distance or a lower bound of it; otherwise the full query below
             * learns the exact distance */
            if (d - mg[k - lo] > w->lim) {
                if (w->lo) list_learn(w, k, mm[k - lo], d - mg[k - lo], INFINITY);
                continue;
            }
        }
        todo[nt++] = k;
    }
    circles_ahead ahead;
    ahead.h = h;
    ahead.n = ahead.used = 0;
    size_t scan = 0; /* todo[scan ..] not yet looked at for the answers ahead */
    for (size_t t = 0; t < nt; t++) {
        size_t k = todo[t], i, j;
        const cdist__scene_obj *b = key_pair(w, k, &i, &j), *a = &w->sa->obj[i];
        double margin = act[k - lo] == ACT_SCREEN || w->lo ? mg[k - lo] : 0.0, d;
        if (cdist__scene_circle_pair(a, b)) {
            if (ahead.used == ahead.n) {
                ahead.n = 0;
                for (scan = scan > t ? scan : t; scan < nt && ahead.n < CIRCLES; scan++) {
                    size_t si, sj;
                    const cdist__scene_obj *sb = key_pair(w, todo[scan], &si, &sj), *sa = &w->sa->obj[si];
                    if (!cdist__scene_circle_pair(sa, sb)) continue;
                    ahead.a[ahead.n] = cdist__scene_core(sa, NULL); /* circles: no arc */
                    ahead.b[ahead.n++] = cdist__scene_core(sb, NULL);
                }
                circles_answer(&ahead);
            }
            int u = ahead.used++;
            m += pair_record(&ahead.c[u], ahead.st[u], i, j, w->lim, &out[m], &d);
        } else {
            cdist__core_obj cb = w->qo ? core_of_item(w->qo) : core_of(w->sb, j);
            m += answer(h, core_of(w->sa, i), cb, i, j, w->lim, &out[m], &d);
        }
        if (w->lo) list_learn(w, k, mm[k - lo], d - margin, d + margin);
        full++;
    }
    w->buf_n[slot] = m;
    w->buf_full[slot] = full;
    if (w->lo) w->buf_box[slot] = box, w->buf_past[slot] = past;
}

static void drain(narrow *w, cdist_query *h, cdist_query *hs)
{
    for (;;) {
        size_t c = atomic_fetch_add_explicit(&w->next, 1, memory_order_relaxed);
        if (c >= w->round_hi) return;
        run_chunk(w, h, hs, c);
    }
}

static void narrow_round(void *ctx, int t)
{
    narrow *w = ctx;
    drain(w, w->h[t], w->hs ? w->hs[t] : NULL);
}

/* ---- threads of one call ----
 * The handle's thread count T: a pool of T - 1 threads (src/base/pool.h) started for the call,
 * each running fn(ctx, t) once per pool_run with its thread number t (the caller is t = 0).
 * When the threads cannot be started the caller runs alone, with the same answers. */

typedef struct pool {
    int threads; /* including the caller */
    cdist__pool *workers;
} pool;

static void pool_start(pool *p, int threads)
{
    int error, failed;
    p->workers = threads > 1 ? cdist__pool_new(threads - 1, &error, &failed) : NULL;
    p->threads = p->workers ? threads : 1;
}

static void pool_run(pool *p, void (*fn)(void *ctx, int t), void *ctx)
{
    if (p->workers) cdist__pool_start(p->workers, fn, ctx);
    fn(ctx, 0);
    if (p->workers) cdist__pool_wait(p->workers);
}

static void pool_stop(pool *p) { cdist__pool_free(p->workers); }

static void commit(narrow *w, const cdist_scene_pair *p, size_t m)
{
    for (size_t k = 0; k < m; k++) {
        if (p[k].status != CDIST_OK && w->fail == CDIST_OK) {
            w->fail = (cdist_status)p[k].status;
            w->fail_i = p[k].i;
            w->fail_j = p[k].j;
        }
        if (w->out && w->count + k < w->capacity) w->out[w->count + k] = p[k];
    }
    if (w->fn && m > 0 && !w->stopped && w->fn(w->user, p, m) != 0) w->stopped = 1;
    w->count += m;
}

/* Handles with the options of q, created once per scene and kept: *list grows to n. */
static cdist_status sync_handles(cdist_query *q, cdist_query ***list, int *have, int n)
{
    if (*have < n) {
        cdist_query **h = realloc(*list, (size_t)n * sizeof *h);
        if (!h) return cdist__fail(q, CDIST_ERR_NO_MEMORY, "scene: out of memory for %d thread handles", n);
        *list = h;
        while (*have < n) {
            if (!(h[*have] = cdist_query_new()))
                return cdist__fail(q, CDIST_ERR_NO_MEMORY, "scene: out of memory for %d thread handles", n);
            (*have)++;
        }
    }
    for (int t = 0; t < n; t++) {
        cdist_query *w = (*list)[t];
        cdist_status st;
        if ((st = cdist_query_set_method(w, cdist_query_get_method(q))) ||
            (st = cdist_query_set_unit_tolerance(w, cdist_query_get_unit_tolerance(q))) ||
            (st = cdist_query_set_curve_samples(w, cdist_query_get_curve_samples(q))) ||
            (st = cdist_query_set_max_iterations(w, cdist_query_get_max_iterations(q))))
            return cdist__fail(q, st, "scene: thread handle: %s", cdist_query_last_error(w));
    }
    return CDIST_OK;
}

/* The threads of a call: the handle's count (1 when their handles cannot be made ready), their
 * handles, and one screening handle per thread (*screen NULL when those cannot be made). */
static int call_threads(cdist_query *q, cdist_scene *s, cdist_query **handles, cdist_query ***screen)
{
    int threads = cdist_query_get_threads(q);
    if (threads > 1 && sync_handles(q, &s->worker, &s->worker_n, threads - 1)) threads = 1;
    handles[0] = q;
    for (int t = 1; t < threads; t++) handles[t] = s->worker[t - 1];
    *screen = sync_handles(q, &s->screen, &s->screen_n, threads) ? NULL : s->screen;
    return threads;
}

/* Answer w->n keys with the pool's threads; reports go to the sink in key order. */
static cdist_status run_narrow(cdist_query *q, cdist_scene *s, narrow *w, pool *p)
{
    size_t chunks = (w->n + CD_SCENE_CHUNK - 1) / CD_SCENE_CHUNK;
    size_t per_round = (size_t)p->threads * CD_SCENE_CHUNKS_PER_THREAD;
    size_t need = per_round * CD_SCENE_CHUNK;
    if (s->chunk_buf_cap < need) {
        cdist_scene_pair *b = realloc(s->chunk_buf, need * sizeof *b);
        if (!b) return cdist__fail(q, CDIST_ERR_NO_MEMORY, "scene: out of memory for the answer buffers");
        s->chunk_buf = b;
        s->chunk_buf_cap = need;
    }
    size_t buf_n[256 * CD_SCENE_CHUNKS_PER_THREAD], buf_full[256 * CD_SCENE_CHUNKS_PER_THREAD];
    size_t buf_box[256 * CD_SCENE_CHUNKS_PER_THREAD], buf_past[256 * CD_SCENE_CHUNKS_PER_THREAD];
    w->buf = s->chunk_buf;
    w->buf_n = buf_n;
    w->buf_full = buf_full;
    w->buf_box = buf_box;
    w->buf_past = buf_past;
    for (size_t r = 0; r < chunks && !w->stopped; r += per_round) {
        w->round_lo = r;
        w->round_hi = r + per_round < chunks ? r + per_round : chunks;
        atomic_store_explicit(&w->next, r, memory_order_relaxed);
        if (p->threads > 1 && w->round_hi - w->round_lo > 1) pool_run(p, narrow_round, w);
        else narrow_round(w, 0);
        for (size_t c = w->round_lo; c < w->round_hi && !w->stopped; c++) {
            commit(w, w->buf + (c - w->round_lo) * CD_SCENE_CHUNK, buf_n[c - w->round_lo]);
            w->full += buf_full[c - w->round_lo];
            if (w->lo) w->box_pairs += buf_box[c - w->round_lo], w->past += buf_past[c - w->round_lo];
        }
    }
    w->buf_n = w->buf_full = w->buf_box = w->buf_past = NULL;
    return CDIST_OK;
}

/* The status of a finished narrow phase, with the message of its first failing pair. */
static cdist_status narrow_status(cdist_query *q, const narrow *w, const char *what)
{
    cdist__begin(q, NULL);
    if (w->stopped) return cdist__fail(q, CDIST_ERR_CALLBACK_FAILED, "scene %s: the pair callback stopped the query", what);
    if (w->fail == CDIST_OK) return CDIST_OK;
    if (w->fail_j == SIZE_MAX)
        return cdist__fail(q, w->fail, "scene %s: object %zu and the query object: %s", what, w->fail_i,
                           pair_message(w->fail));
    return cdist__fail(q, w->fail, "scene %s: pair (%zu, %zu): %s", what, w->fail_i, w->fail_j, pair_message(w->fail));
}

/* ---- pairs within delta ---- */

static cdist_status check_delta(cdist_query *q, double delta, const void *out, size_t capacity)
{
    if (isnan(delta)) return cdist__fail(q, CDIST_ERR_NOT_FINITE, "scene: delta is NaN");
    if (!out && capacity > 0)
        return cdist__fail(q, CDIST_ERR_NULL_ARGUMENT, "scene: output array is NULL with capacity %zu", capacity);
    return CDIST_OK;
}

/* Sort the candidate keys, whose i are ids of s (the scratch lives for the sort only: it would
 * double the candidates' share of the scene's memory). By i first when the ids are not many
 * more than the keys, else by the radix sort alone. */
static cdist_status sort_keys(cdist_query *q, const cdist_scene *s, uint64_t *key, size_t n)
{
    if (n < 2) return CDIST_OK;
    int by_id = s->n <= 4 * n && n < UINT32_MAX; /* the counters are 32-bit */
    size_t cnt_words = by_id ? (s->n + 2) / 2 : 0;   /* the ids' counters after the keys' scratch */
    uint64_t *tmp = cdist__big_malloc((n + cnt_words) * sizeof *tmp);
    if (!tmp) return cdist__fail(q, CDIST_ERR_NO_MEMORY, "scene: out of memory for sorting %zu candidate pairs", n);
    if (by_id) cdist__sort_pair_keys(key, tmp, (uint32_t *)(tmp + n), s->n, n);
    else cdist__radix_sort_keys(key, tmp, n);
    free(tmp);
    return CDIST_OK;
}

/* ---- the broad phase on several threads: subtree pairs from the top of the traversal as
 * tasks, each thread with its own key list; the lists are joined and sorted, so the keys are
 * those of the one-thread traversal in the same order. */

typedef struct btask {
    uint32_t x, y;
    int self;
} btask;

typedef struct broad_par {
    broad *b; /* one per thread */
    const btask *task;
    size_t n_tasks;
    atomic_size_t next;
} broad_par;

static void broad_round(void *ctx, int t)
{
    broad_par *bp = ctx;
    broad *b = &bp->b[t];
    for (;;) {
        size_t k = atomic_fetch_add_explicit(&bp->next, 1, memory_order_relaxed);
        if (k >= bp->n_tasks) return;
        const btask *x = &bp->task[k];
        if (x->self) self(b, x->x);
        else cross(b, x->x, x->y);
    }
}

/* At least `want` tasks (fewer when the tree is small), by expanding the traversal's first
 * levels exactly as self() and cross() would. NULL when memory runs out. */
static btask *make_tasks(const broad *b, size_t want, size_t *n_out)
{
    size_t n = 1, cap = 16;
    btask *cur = malloc(cap * sizeof *cur);
    if (!cur) return NULL;
    cur[0] = (btask){0, 0, b->self};
    for (int level = 0; level < 32 && n < want; level++) {
        btask *nx = malloc(3 * n * sizeof *nx);
        if (!nx) {
            free(cur);
            return NULL;
        }
        size_t m = 0;
        int grew = 0;
        for (size_t k = 0; k < n; k++) {
            btask t = cur[k];
            const cdist__node *nx_ = &b->sa->node[t.x], *ny_ = &b->sb->node[t.y];
            if (t.self) {
                if (nx_->count) {
                    nx[m++] = t;
                } else {
                    nx[m++] = (btask){nx_->first, nx_->first, 1};
                    nx[m++] = (btask){nx_->first + 1, nx_->first + 1, 1};
                    nx[m++] = (btask){nx_->first, nx_->first + 1, 0};
                    grew = 1;
                }
                continue;
            }
            if (!cdist__box_near(&nx_->box, &ny_->box, b->lim)) continue;
            if (nx_->count && ny_->count) {
                nx[m++] = t;
            } else if (ny_->count || (!nx_->count && box_size(&nx_->box) >= box_size(&ny_->box))) {
                nx[m++] = (btask){nx_->first, t.y, 0};
                nx[m++] = (btask){nx_->first + 1, t.y, 0};
                grew = 1;
            } else {
                nx[m++] = (btask){t.x, ny_->first, 0};
                nx[m++] = (btask){t.x, ny_->first + 1, 0};
                grew = 1;
            }
        }
        free(cur);
        cur = nx;
        n = m;
        if (!grew) break;
    }
    *n_out = n;
    return cur;
}

/* The candidate keys of sa x sb into sa->cand (unsorted), on the pool's threads. */
static cdist_status broad_run(cdist_query *q, broad *b, pool *p, const char *what)
{
    cdist_scene *sa = b->sa;
    sa->list_ok = 0; /* the candidates overwrite it */
    if (sa->node_n == 0 || b->sb->node_n == 0) return CDIST_OK;
    if (p->threads == 1) {
        if (b->self) self(b, 0);
        else cross(b, 0, 0);
        sa->cand = b->key;
        sa->cand_cap = b->cap;
        return b->oom ? cdist__fail(q, CDIST_ERR_NO_MEMORY, "scene %s: out of memory for the candidate pairs", what)
                      : CDIST_OK;
    }
    size_t n_tasks = 0;
    btask *task = make_tasks(b, (size_t)p->threads * 32, &n_tasks);
    broad per[256];
    for (int t = 0; t < p->threads; t++) {
        per[t] = *b;
        per[t].key = NULL;
        per[t].n = per[t].cap = 0;
    }
    per[0].key = b->key; /* the scene's kept list */
    per[0].cap = b->cap;
    broad_par bp = {per, task, n_tasks, 0};
    atomic_init(&bp.next, 0);
    if (task) pool_run(p, broad_round, &bp);
    size_t total = 0;
    int oom = !task;
    for (int t = 0; t < p->threads; t++) total += per[t].n, oom |= per[t].oom;
    uint64_t *key = per[0].key;
    size_t cap = per[0].cap;
    if (!oom && total > cap) {
        uint64_t *k = cdist__big_realloc(key, total * sizeof *k);
        if (k) key = k, cap = total;
        else oom = 1;
    }
    size_t n = per[0].n;
    for (int t = 1; t < p->threads; t++) {
        if (!oom && per[t].n > 0) memcpy(key + n, per[t].key, per[t].n * sizeof *key);
        n += per[t].n;
        free(per[t].key);
        b->box_pairs += per[t].box_pairs;
    }
    b->box_pairs += per[0].box_pairs;
    b->n = n;
    sa->cand = key;
    sa->cand_cap = cap;
    free(task);
    return oom ? cdist__fail(q, CDIST_ERR_NO_MEMORY, "scene %s: out of memory for the candidate pairs", what) : CDIST_OK;
}

/* The pair list of a moving scene still holds every pair that may be within delta: each
 * object moved at most moved[] since the list's poses, and a pair not in the list was farther
 * than list_reach then (box gap), so it is farther than list_reach - moved[i] - moved[j] now. */
static int list_usable(const cdist_scene *s, double delta)
{
    if (!s->list_ok || s->dirty) return 0;
    double m1 = 0.0, m2 = 0.0;
    for (size_t i = 0; i < s->n; i++) {
        double m = s->moved[i];
        if (s->obj[i].state != CD_SCENE_LIVE || m <= m2) continue;
        if (m > m1) m2 = m1, m1 = m;
        else m2 = m;
    }
    return fmax(delta, 0.0) + (m1 + m2) <= s->list_reach;
}

/* The bounds of the n sorted keys from the list being replaced (old keys ok[0..on), bounds
 * olo, ohi, known with the objects' motions moved[]) as they stand now, into lo, hi: a pair
 * distance moves at most by its objects' motions; keys new to the list know nothing. */
static void list_carry(const cdist_scene *s, const uint64_t *ok, size_t on, const float *olo, const float *ohi,
                       const uint64_t *key, size_t n, float *lo, float *hi)
{
    size_t o = 0;
    for (size_t k = 0; k < n; k++) {
        while (o < on && ok[o] < key[k]) o++;
        lo[k] = -INFINITY, hi[k] = INFINITY;
        if (o == on || ok[o] != key[k]) continue;
        double mm = s->moved[key[k] >> 32] + s->moved[key[k] & 0xffffffffu];
        double l = (double)olo[o] - mm, h = (double)ohi[o] + mm;
        if (l == l) lo[k] = cdist__float_down(l); /* a NaN would clamp to the largest float */
        if (h == h) hi[k] = cdist__float_up(h);
    }
}

/* Make the pair list at the current poses: every pair whose boxes are within the reach of
 * delta plus a skin for the coming motions (CD_SCENE_SKIN_STEPS times twice the largest motion
 * of an object since the last query, so that as many updates like it keep the list valid; at
 * most the mean box extent, so that a few far moves do not make the list quadratic), sorted;
 * the entries of the list it replaces keep their bounds (list_carry), the others know none;
 * moved[] restarts at 0. */
static cdist_status list_make(cdist_query *q, cdist_scene *s, double delta, pool *p)
{
    double extent = 0.0;
    size_t boxes = 0;
    for (size_t k = 0; k < s->tree_n; k++) {
        const cdist__box *x = &s->box[k];
        if (!(x->lo[0] <= x->hi[0])) continue; /* removed */
        extent += ((x->hi[0] - x->lo[0]) + (x->hi[1] - x->lo[1]) + (x->hi[2] - x->lo[2])) / 3.0;
        boxes++;
    }
    double skin = fmin(CD_SCENE_SKIN_STEPS * 2.0 * s->step_moved, boxes ? extent / (double)boxes : 0.0);
    double reach = fmax(delta, 0.0) + skin;
    /* The old list's keys (cand, when it holds the list) and bounds stay until its bounds are
     * carried over; otherwise cand is the broad phase's buffer again. */
    int carry = s->list_ok;
    uint64_t *old_key = carry ? s->cand : NULL;
    size_t old_n = carry ? s->list_n : 0;
    if (carry) {
        s->cand = NULL, s->cand_cap = 0;
    } else {
        free(s->list_lo), free(s->list_hi);
        s->list_lo = s->list_hi = NULL, s->list_cap = 0;
    }
    broad b = {s, s, 1, cdist__box_lim(reach), delta, 0, s->cand, 0, s->cand_cap, 0, 0, NULL, 1, 0};
    cdist_status st = broad_run(q, &b, p, "pairs_within");
    if (!st) st = sort_keys(q, s, s->cand, b.n);
    size_t cap = b.n > 0 ? b.n : 1;
    float *lo = st ? NULL : cdist__big_malloc(cap * sizeof *lo), *hi = lo ? cdist__big_malloc(cap * sizeof *hi) : NULL;
    if (!st && !hi) st = cdist__fail(q, CDIST_ERR_NO_MEMORY, "scene pairs_within: out of memory for the pair list");
    if (!st) list_carry(s, old_key, old_n, s->list_lo, s->list_hi, s->cand, b.n, lo, hi);
    free(old_key);
    if (st) {
        free(lo);
        return st;
    }
    free(s->list_lo), free(s->list_hi);
    s->list_lo = lo, s->list_hi = hi, s->list_cap = cap;
    memset(s->moved, 0, s->n * sizeof *s->moved);
    s->list_n = b.n;
    s->list_reach = reach;
    s->list_ok = 1;
    return CDIST_OK;
}

/* Broad and narrow phase of pairs within delta of sa (x) sb (self when sa == sb). A scene that
 * has moved keeps its pair list between queries and decides its entries from their bounds and
 * the motions first. */
static cdist_status pairs_run(cdist_query *q, cdist_scene *sa, cdist_scene *sb, double delta, narrow *w,
                              const char *what)
{
    cdist_status st;
    /* A list is first made at the second query after updates: a scene updated once and
     * queried once gets the plain query. */
    int moving = sa == sb && sa->moved && sa->step_count > 0;
    int list = sa == sb && sa->moved && (sa->list_ok || (moving && sa->moved_queries > 0)) && sa->step_moved < INFINITY;
    sa->moved_queries += moving;
    int reuse = list && list_usable(sa, delta);
    if (reuse) {
        sa->list_reuses++;
    } else {
        if ((st = cdist__scene_prepare(q, sa)) || (sb != sa && (st = cdist__scene_prepare(q, sb)))) return st;
        if (list) sa->list_builds++;
    }
    cdist_query *handles[256], **screen;
    pool p;
    pool_start(&p, call_threads(q, sa, handles, &screen));
    broad b = {sa, sb, sa == sb, cdist__box_lim(fmax(delta, 0.0)), delta, 0, sa->cand, 0, sa->cand_cap, 0, 0, NULL, 0,
               screen != NULL};
    if (list) {
        if (reuse || !(st = list_make(q, sa, delta, &p))) b.n = sa->list_n;
    } else if (!(st = broad_run(q, &b, &p, what))) {
        st = sort_keys(q, sa, sa->cand, b.n);
    }
    if (!st) {
        w->sa = sa;
        w->sb = sb;
        w->key = sa->cand;
        w->n = b.n;
        w->lim = delta;
        w->h = handles;
        w->hs = screen;
        if (list) w->lo = sa->list_lo, w->hi = sa->list_hi;
        st = run_narrow(q, sa, w, &p);
    }
    pool_stop(&p);
    sa->step_moved = 0.0;
    sa->step_count = 0;
    if (st) {
        sa->list_ok = 0;
        return st;
    }
    sa->stats.box_pairs = list ? w->box_pairs : b.box_pairs;
    sa->stats.screened = list ? w->past : b.n;
    sa->stats.candidates = w->full;
    sa->stats.reported = w->count;
    return narrow_status(q, w, what);
}

static cdist_status pairs_entry(cdist_query *q, cdist_scene *sa, cdist_scene *sb, double delta, cdist_scene_pair *out,
                                size_t capacity, cdist_scene_pair_fn fn, void *user, size_t *count)
{
    if (count) *count = 0;
    cdist_status st = cdist__scene_enter(q, sa);
    if (st) return st;
    if (sb != sa && sb && !cdist__scene_take(sb))
        return cdist__scene_leave(q, sa, cdist__fail(q, CDIST_ERR_HANDLE_BUSY, "scene: in use by another call"));
    const char *what = sb == sa ? "pairs_within" : "pairs_between";
    if (!sb) st = cdist__fail(q, CDIST_ERR_NULL_ARGUMENT, "scene pointer is NULL");
    else if (!fn && (st = check_delta(q, delta, out, capacity))) (void)0;
    else if (fn && isnan(delta)) st = cdist__fail(q, CDIST_ERR_NOT_FINITE, "scene: delta is NaN");
    else {
        narrow w;
        memset(&w, 0, sizeof w);
        w.out = out;
        w.capacity = out ? capacity : 0;
        w.fn = fn;
        w.user = user;
        st = pairs_run(q, sa, sb, delta, &w, what);
        if (count) *count = w.count;
    }
    if (sb && sb != sa) cdist__scene_release(sb);
    return cdist__scene_leave(q, sa, st);
}

cdist_status cdist_scene_pairs_within(cdist_query *q, cdist_scene *s, double delta, cdist_scene_pair *out,
                                      size_t capacity, size_t *count)
{
    return pairs_entry(q, s, s, delta, out, capacity, NULL, NULL, count);
}

cdist_status cdist_scene_pairs_within_fn(cdist_query *q, cdist_scene *s, double delta, cdist_scene_pair_fn fn,
                                         void *user, size_t *count)
{
    if (!fn) {
        if (count) *count = 0;
        cdist_status st = cdist__scene_enter(q, s);
        if (st) return st;
        return cdist__scene_leave(q, s, cdist__fail(q, CDIST_ERR_NULL_ARGUMENT, "scene: pair callback is NULL"));
    }
    return pairs_entry(q, s, s, delta, NULL, 0, fn, user, count);
}

cdist_status cdist_scene_pairs_between(cdist_query *q, cdist_scene *a, cdist_scene *b, double delta,
                                       cdist_scene_pair *out, size_t capacity, size_t *count)
{
    return pairs_entry(q, a, b, delta, out, capacity, NULL, NULL, count);
}

/* ---- per-pair queries (linked pairs, time of impact): the broad phase's sorted keys, each
 * answered by a public pair query on a free handle of its thread (the caller's own handle is
 * taken by the call), one answer and status per key ---- */

typedef struct pair_job {
    const cdist_scene *s;
    const uint64_t *key;
    size_t n, chunk;       /* keys, and keys per grab of a thread */
    void *res;             /* res_size bytes per key */
    size_t res_size;
    cdist_status *st;      /* by key */
    cdist_query **h;       /* free handle of thread t */
    const void *ctx;       /* the query's own arguments */
    cdist_status (*one)(const struct pair_job *job, cdist_query *h, size_t i, size_t j, void *res);
    atomic_size_t next;
} pair_job;

static void pair_job_round(void *ctx, int t)
{
    pair_job *w = ctx;
    for (;;) {
        size_t lo = atomic_fetch_add_explicit(&w->next, w->chunk, memory_order_relaxed);
        if (lo >= w->n) return;
        size_t hi = lo + w->chunk < w->n ? lo + w->chunk : w->n;
        for (size_t k = lo; k < hi; k++)
            w->st[k] = w->one(w, w->h[t], (size_t)(w->key[k] >> 32), (size_t)(w->key[k] & 0xffffffffu),
                              (char *)w->res + k * w->res_size);
    }
}

/* The broad phase b on the handle's threads, then job->one for every key on the same threads;
 * job->res and job->st are allocated here (the caller frees them; NULL when no key). */
static cdist_status pair_job_run(cdist_query *q, cdist_scene *s, broad *b, const char *what, pair_job *job)
{
    cdist_status st = cdist__scene_prepare(q, s);
    if (st) return st;
    cdist_query *handles[256], **screen;
    pool p;
    pool_start(&p, call_threads(q, s, handles, &screen));
    if (!screen) st = cdist__fail(q, CDIST_ERR_NO_MEMORY, "scene %s: out of memory for the thread handles", what);
    else if (!(st = broad_run(q, b, &p, what)) && !(st = sort_keys(q, s, s->cand, b->n)) && b->n > 0) {
        job->res = malloc(b->n * job->res_size);
        job->st = malloc(b->n * sizeof *job->st);
        if (!job->res || !job->st) {
            st = cdist__fail(q, CDIST_ERR_NO_MEMORY, "scene %s: out of memory for %zu answers", what, b->n);
        } else {
            job->s = s;
            job->key = s->cand;
            job->n = b->n;
            job->h = screen;
            atomic_init(&job->next, 0);
            if (p.threads > 1 && b->n > job->chunk) pool_run(&p, pair_job_round, job);
            else pair_job_round(job, 0);
        }
    }
    pool_stop(&p);
    if (!st) {
        s->stats.box_pairs = b->box_pairs;
        s->stats.screened = b->n;
        s->stats.candidates = b->n;
    }
    return st;
}

/* ---- linked pairs ---- */

size_t cdist_scene_link_size(void) { return sizeof(cdist_scene_link); }

static cdist_status link_one(const pair_job *job, cdist_query *h, size_t i, size_t j, void *res)
{
    const cdist__scene_obj *a = &job->s->obj[i], *b = &job->s->obj[j];
    cdist_torus ta = {a->g.circle, a->r}, tb = {b->g.circle, b->r};
    return cdist_link_tori(h, &ta, &tb, res);
}

/* The box reach of the linked-pair traversal: CD_SCENE_LINK_REACH_REL * L plus the bound margin
 * of any pair, through S = the largest |C| + r + tube of the live rings (L and each object's
 * coordinate scale are at most 2 S). */
static double link_box_reach(const cdist_scene *s)
{
    double S = 0.0;
    for (size_t i = 0; i < s->n; i++) {
        const cdist__scene_obj *o = &s->obj[i];
        if (o->state != CD_SCENE_LIVE || !cdist__scene_circle_pair(o, o)) continue;
        const cdist_circle *c = &o->g.circle;
        S = fmax(S, v_norm(v3(c->center.x, c->center.y, c->center.z)) + c->radius + o->r);
    }
    return 4.0 * (CD_SCENE_LINK_REACH_REL + CD_SCENE_BOUND_REL) * S;
}

static cdist_status linked_run(cdist_query *q, cdist_scene *s, cdist_scene_link *out, size_t capacity, size_t *count)
{
    broad b = {s, s, 1, cdist__box_lim(link_box_reach(s)), 0.0, 0, s->cand, 0, s->cand_cap, 0, 1, NULL, 0, 0};
    pair_job job = {.chunk = CD_SCENE_CHUNK, .res_size = sizeof(cdist_link), .one = link_one};
    cdist_status st = pair_job_run(q, s, &b, "linked_pairs", &job);
    cdist_link *res = job.res;
    cdist_status *pst = job.st;
    cdist_query *screen0 = s->screen ? s->screen[0] : NULL;
    size_t m = 0, fail_k = SIZE_MAX;
    if (!st) {
        for (size_t k = 0; k < b.n; k++) {
            if (pst[k] != CDIST_OK && fail_k == SIZE_MAX) fail_k = k;
            if (pst[k] == CDIST_OK && res[k].linking == 0 && res[k].core_linking == 0) continue;
            if (out && m < capacity) {
                cdist_scene_link *r = &out[m];
                memset(r, 0, sizeof *r);
                r->i = (size_t)(s->cand[k] >> 32);
                r->j = (size_t)(s->cand[k] & 0xffffffffu);
                r->status = pst[k];
                r->link = res[k];
            }
            m++;
        }
        s->stats.reported = m;
        *count = m;
        cdist__begin(q, NULL);
        if (fail_k != SIZE_MAX) {
            /* Its message, from the first thread's handle (the answer does not depend on the thread). */
            size_t i = (size_t)(s->cand[fail_k] >> 32), j = (size_t)(s->cand[fail_k] & 0xffffffffu);
            cdist_torus ta = {s->obj[i].g.circle, s->obj[i].r}, tb = {s->obj[j].g.circle, s->obj[j].r};
            cdist_link again;
            (void)cdist_link_tori(screen0, &ta, &tb, &again);
            st = cdist__fail(q, pst[fail_k], "scene linked_pairs: pair (%zu, %zu): %s", i, j,
                             cdist_query_last_error(screen0));
        }
    }
    free(res);
    free(pst);
    return st;
}

cdist_status cdist_scene_linked_pairs(cdist_query *q, cdist_scene *s, cdist_scene_link *out, size_t capacity,
                                      size_t *count)
{
    size_t dummy;
    if (!count) count = &dummy;
    *count = 0;
    cdist_status st = cdist__scene_enter(q, s);
    if (st) return st;
    if (!out && capacity > 0)
        st = cdist__fail(q, CDIST_ERR_NULL_ARGUMENT, "scene linked_pairs: output array is NULL with capacity %zu",
                         capacity);
    else st = linked_run(q, s, out, out ? capacity : 0, count);
    return cdist__scene_leave(q, s, st);
}

/* ---- time of impact of a moving scene ---- */

size_t cdist_scene_toi_size(void) { return sizeof(cdist_scene_toi_result); }

/* The object as a swept shape (the plain kinds with radius 0); 0 for an arc (no shape). Each
 * swept struct is its core followed by the ball radius (scene.c asserts the layout). */
static int scene_shape(const cdist__scene_obj *o, cdist_shape *sh)
{
    size_t core;
    memset(sh, 0, sizeof *sh);
    switch (cdist__scene_core(o, NULL).type) { /* the type only */
    case CD_CORE_POINT: sh->type = CDIST_SHAPE_SPHERE, core = sizeof(cdist_vec3); break;
    case CD_CORE_SEGMENT: sh->type = CDIST_SHAPE_CAPSULE, core = sizeof(cdist_segment); break;
    case CD_CORE_CIRCLE: sh->type = CDIST_SHAPE_TORUS, core = sizeof(cdist_circle); break;
    case CD_CORE_DISK: sh->type = CDIST_SHAPE_ROUNDED_DISK, core = sizeof(cdist_circle); break;
    default: return 0;
    }
    memcpy(&sh->u, &o->g, core);
    memcpy((char *)&sh->u + core, &o->r, sizeof o->r);
    return 1;
}

static vec3 vec_of(cdist_vec3 a) { return v3(a.x, a.y, a.z); }

/* How far any point of the object's solid moves over [0, 1]: its speed is at most
 * |T| + |omega| rho, rho the largest distance of the solid from the rotation centre. */
static double motion_reach(const cdist__scene_obj *o, const cdist_motion *m)
{
    vec3 c = vec_of(m->center);
    double rho;
    switch (cdist__scene_core(o, NULL).type) { /* the type only */
    case CD_CORE_POINT: rho = v_dist(vec_of(o->g.point), c); break;
    case CD_CORE_SEGMENT: rho = fmax(v_dist(vec_of(o->g.segment.p0), c), v_dist(vec_of(o->g.segment.p1), c)); break;
    default: rho = v_dist(vec_of(o->g.circle.center), c) + o->g.circle.radius; break;
    }
    return v_norm(vec_of(m->translation)) + v_norm(vec_of(m->rotation)) * (rho + o->r);
}

typedef struct toi_args {
    const cdist_motion *motions;
    ptrdiff_t stride;
    double target, tolerance;
    int max_iterations;
} toi_args;

static const cdist_motion *motion_of(const toi_args *w, size_t id)
{
    return w->motions ? (const cdist_motion *)((const char *)w->motions + (ptrdiff_t)id * w->stride) : NULL;
}

static cdist_status toi_one(const pair_job *job, cdist_query *h, size_t i, size_t j, void *res)
{
    const toi_args *w = job->ctx;
    cdist_toi_result *r = res;
    cdist_shape a, b;
    if (!scene_shape(&job->s->obj[i], &a) || !scene_shape(&job->s->obj[j], &b)) {
        memset(r, 0, sizeof *r);
        r->t = r->distance = NAN;
        return CDIST_ERR_BAD_KIND;
    }
    return cdist_toi(h, &a, motion_of(w, i), &b, motion_of(w, j), w->target, w->tolerance, w->max_iterations, r);
}

static cdist_status toi_run(cdist_query *q, cdist_scene *s, const cdist_motion *motions, ptrdiff_t stride, double target,
                            double tolerance, int max_iterations, cdist_scene_toi_result *out)
{
    cdist_status st;
    double *reach = calloc(s->n ? s->n : 1, sizeof *reach);
    if (!reach) return cdist__fail(q, CDIST_ERR_NO_MEMORY, "scene toi: out of memory for %zu reaches", s->n);
    double most = 0.0;
    for (size_t i = 0; i < s->n && motions; i++) {
        const cdist_motion *m = (const cdist_motion *)((const char *)motions + (ptrdiff_t)i * stride);
        if (s->obj[i].state != CD_SCENE_LIVE) continue;
        if (!cdist__in_range(m->center) || !cdist__in_range(m->translation) || !cdist__in_range(m->rotation)) {
            free(reach);
            return cdist__fail(q, CDIST_ERR_NOT_FINITE, "scene toi: motion of object %zu is not finite", i);
        }
        reach[i] = motion_reach(&s->obj[i], m);
        most = fmax(most, reach[i]);
    }
    /* A pair hits only if its distance at 0 is <= target + tolerance + both reaches (the
     * distance shrinks no faster than the two solids move). */
    double lim = target + tolerance;
    for (size_t i = 0; i < s->n; i++) reach[i] *= 1.0 + CD_SCENE_TOI_REACH_REL;
    most *= 1.0 + CD_SCENE_TOI_REACH_REL;
    broad b = {s, s, 1, cdist__box_lim(fmax(lim, 0.0) + 2.0 * most), lim, 0, s->cand, 0, s->cand_cap, 0, 0, reach,
               0, 0};
    toi_args args = {motions, stride, target, tolerance, max_iterations};
    pair_job job = {.chunk = CD_SCENE_TOI_CHUNK, .res_size = sizeof(cdist_toi_result), .ctx = &args, .one = toi_one};
    st = pair_job_run(q, s, &b, "toi", &job);
    cdist_toi_result *res = job.res;
    cdist_status *pst = job.st;
    free(reach);
    if (!st) {
        /* The earliest time among the pairs (a hit, or where a capped search stopped: every pair
         * is then free of contact before it); ties: the smallest (i, j). */
        size_t best = SIZE_MAX, fail_k = SIZE_MAX;
        for (size_t k = 0; k < b.n; k++) {
            if (pst[k] != CDIST_OK) {
                if (fail_k == SIZE_MAX) fail_k = k;
                continue;
            }
            if (res[k].state == CDIST_TOI_NONE) continue;
            if (best == SIZE_MAX || res[k].t < res[best].t) best = k;
        }
        out->candidates = b.n;
        if (best != SIZE_MAX) {
            out->i = (size_t)(s->cand[best] >> 32);
            out->j = (size_t)(s->cand[best] & 0xffffffffu);
            out->toi = res[best];
        }
        s->stats.reported = best != SIZE_MAX;
        cdist__begin(q, NULL);
        if (fail_k != SIZE_MAX) {
            size_t i = (size_t)(s->cand[fail_k] >> 32), j = (size_t)(s->cand[fail_k] & 0xffffffffu);
            st = cdist__fail(q, pst[fail_k], "scene toi: pair (%zu, %zu): %s", i, j,
                             pst[fail_k] == CDIST_ERR_BAD_KIND ? "an arc has no time of impact" : cdist_status_string(pst[fail_k]));
            out->i = i;
            out->j = j;
            out->toi = res[fail_k];
        }
    }
    free(res);
    free(pst);
    return st;
}

cdist_status cdist_scene_toi(cdist_query *q, cdist_scene *s, const cdist_motion *motions, ptrdiff_t stride,
                             double target, double tolerance, int max_iterations, cdist_scene_toi_result *out)
{
    if (out) {
        memset(out, 0, sizeof *out);
        out->i = out->j = SIZE_MAX;
        out->toi.state = CDIST_TOI_NONE;
        out->toi.t = 1.0;
        out->toi.distance = NAN;
    }
    cdist_status st = cdist__scene_enter(q, s);
    if (st) return st;
    if (!out) st = cdist__fail(q, CDIST_ERR_NULL_ARGUMENT, "scene toi: output pointer is NULL");
    else if (!isfinite(target)) st = cdist__fail(q, CDIST_ERR_NOT_FINITE, "scene toi: target is not finite");
    else if (!(tolerance > 0.0) || !isfinite(tolerance))
        st = cdist__fail(q, CDIST_ERR_BAD_OPTION, "scene toi: tolerance must be finite and > 0 (%g)", tolerance);
    else if (max_iterations < 1)
        st = cdist__fail(q, CDIST_ERR_BAD_OPTION, "scene toi: max_iterations must be >= 1 (%d)", max_iterations);
    else st = toi_run(q, s, motions, motions ? (stride ? stride : (ptrdiff_t)sizeof *motions) : 0, target, tolerance,
                      max_iterations, out);
    return cdist__scene_leave(q, s, st);
}

/* ---- closest pair and nearest: pairs that could not be answered ----
 * A search's threshold falls as it goes, so which unanswerable pairs (a point against an arc)
 * it meets depends on the traversal order. They are kept, and at the end the first (by key) of
 * those whose bounds do not exclude them at the final threshold decides the status: every pair
 * the search passed over was excluded at a threshold at least as large, so the choice depends on
 * the objects alone. */

typedef struct unanswered {
    struct {
        uint64_t key;
        cdist_status st;
    } *e;
    size_t n, cap;
    int oom;
} unanswered;

static void unanswered_add(unanswered *u, uint64_t key, cdist_status st)
{
    if (u->n == u->cap) {
        size_t cap = u->cap ? 2 * u->cap : 16;
        void *e = realloc(u->e, cap * sizeof *u->e);
        if (!e) {
            u->oom = 1;
            return;
        }
        u->e = e;
        u->cap = cap;
    }
    u->e[u->n].key = key;
    u->e[u->n++].st = st;
}

/* The entry of u with the smallest key for which open(ctx, key) holds (SIZE_MAX: none). */
static size_t unanswered_first(const unanswered *u, int (*open)(const void *ctx, uint64_t key), const void *ctx)
{
    size_t pick = SIZE_MAX;
    for (size_t k = 0; k < u->n; k++)
        if ((pick == SIZE_MAX || u->e[k].key < u->e[pick].key) && open(ctx, u->e[k].key)) pick = k;
    return pick;
}

/* ---- closest pair: branch and bound over the tree ---- */

typedef struct closest {
    cdist_scene *sa, *sb;
    int self;
    cdist_query *h;
    double best;              /* distance of the best pair so far */
    uint64_t best_key;
    cdist_scene_pair rec;
    int have;
    unanswered un;            /* failing pairs */
    size_t box_pairs, candidates;
} closest;

/* Boxes bound the solids: a box gap g > 0 means a signed distance >= g, and says nothing about
 * overlapping solids; so a box pair is pruned when its gap exceeds max(best, 0). */
static double box_cut(const closest *c) { return c->best > 0.0 ? c->best : 0.0; }

/* Objects i of sa and j of sb at their tree positions pa, pb: may their distance be at most
 * best (their boxes and bounds do not exclude it)? */
static int best_open(const closest *c, uint32_t pa, uint32_t pb, size_t i, size_t j)
{
    return cdist__box_near(&c->sa->box[pa], &c->sb->box[pb], cdist__box_lim(box_cut(c))) &&
           !cdist__scene_excluded(&c->sa->obj[i], &c->sb->obj[j], c->best, 1);
}

static int best_open_key(const void *ctx, uint64_t key)
{
    const closest *c = ctx;
    size_t i = (size_t)(key >> 32), j = (size_t)(key & 0xffffffffu);
    return best_open(c, c->sa->pos[i], c->sb->pos[j], i, j);
}

static void best_pos(closest *c, uint32_t pa, uint32_t pb)
{
    if (!cdist__box_near(&c->sa->box[pa], &c->sb->box[pb], cdist__box_lim(box_cut(c)))) return;
    size_t i, j;
    const cdist__scene_obj *oa, *ob;
    if (!pair_at(c->sa, c->sb, c->self, 1, pa, pb, &i, &j, &oa, &ob)) return;
    c->box_pairs++;
    if (cdist__scene_excluded(oa, ob, c->best, 1)) return;
    c->candidates++;
    cdist_scene_pair p;
    answer(c->h, core_of(c->sa, i), core_of(c->sb, j), i, j, INFINITY, &p, NULL);
    uint64_t key = (uint64_t)i << 32 | j;
    if (p.status != CDIST_OK) {
        unanswered_add(&c->un, key, (cdist_status)p.status);
        return;
    }
    if (!c->have || p.distance < c->best || (p.distance == c->best && key < c->best_key)) {
        c->have = 1;
        c->best = p.distance;
        c->best_key = key;
        c->rec = p;
    }
}

static void best_cross(closest *c, uint32_t x, uint32_t y)
{
    const cdist__node *nx = &c->sa->node[x], *ny = &c->sb->node[y];
    if (!cdist__box_near(&nx->box, &ny->box, cdist__box_lim(box_cut(c)))) return;
    if (nx->count && ny->count) {
        for (uint32_t p = nx->first; p < nx->first + nx->count; p++)
            for (uint32_t q = ny->first; q < ny->first + ny->count; q++) best_pos(c, p, q);
        return;
    }
    uint32_t a0, a1, b0, b1;
    if (ny->count || (!nx->count && box_size(&nx->box) >= box_size(&ny->box)))
        a0 = nx->first, a1 = nx->first + 1, b0 = b1 = y;
    else
        a0 = a1 = x, b0 = ny->first, b1 = ny->first + 1;
    /* The nearer pair of subtrees first: a small best early prunes the rest. */
    float g0 = cdist__box_gap_f(&c->sa->node[a0].box, &c->sb->node[b0].box);
    float g1 = cdist__box_gap_f(&c->sa->node[a1].box, &c->sb->node[b1].box);
    if (g1 < g0) {
        best_cross(c, a1, b1);
        best_cross(c, a0, b0);
    } else {
        best_cross(c, a0, b0);
        best_cross(c, a1, b1);
    }
}

static void best_leaf(void *c, uint32_t first, uint32_t count)
{
    for (uint32_t p = first; p < first + count; p++)
        for (uint32_t q = p + 1; q < first + count; q++) best_pos(c, p, q);
}
static void best_cross_fn(void *c, uint32_t x, uint32_t y) { best_cross(c, x, y); }
static void best_self(closest *c, uint32_t x) { self_walk(c->sa, x, best_leaf, best_cross_fn, c); }

static cdist_status closest_entry(cdist_query *q, cdist_scene *sa, cdist_scene *sb, cdist_scene_pair *out)
{
    cdist_status st = cdist__scene_enter(q, sa);
    if (st) {
        if (out) pair_error(out, SIZE_MAX, SIZE_MAX, st);
        return st;
    }
    if (sb != sa && sb && !cdist__scene_take(sb)) {
        if (out) pair_error(out, SIZE_MAX, SIZE_MAX, CDIST_ERR_HANDLE_BUSY);
        return cdist__scene_leave(q, sa, cdist__fail(q, CDIST_ERR_HANDLE_BUSY, "scene: in use by another call"));
    }
    const char *what = sb == sa ? "closest_pair" : "closest_pair_between";
    if (!sb) st = cdist__fail(q, CDIST_ERR_NULL_ARGUMENT, "scene pointer is NULL");
    else if (!out) st = cdist__fail(q, CDIST_ERR_NULL_ARGUMENT, "scene %s: output pointer is NULL", what);
    else if (!(st = cdist__scene_prepare(q, sa)) && (sb == sa || !(st = cdist__scene_prepare(q, sb)))) {
        closest c;
        memset(&c, 0, sizeof c);
        c.sa = sa;
        c.sb = sb;
        c.self = sa == sb;
        c.h = q;
        c.best = INFINITY;
        if (sa->node_n > 0 && sb->node_n > 0) {
            if (c.self) best_self(&c, 0);
            else best_cross(&c, 0, 0);
        }
        sa->stats.box_pairs = c.box_pairs;
        sa->stats.screened = c.candidates;
        sa->stats.candidates = c.candidates;
        sa->stats.reported = c.have;
        cdist__begin(q, NULL);
        size_t e = unanswered_first(&c.un, best_open_key, &c);
        if (c.un.oom) {
            pair_error(out, SIZE_MAX, SIZE_MAX, CDIST_ERR_NO_MEMORY);
            st = cdist__fail(q, CDIST_ERR_NO_MEMORY, "scene %s: out of memory for the failing pairs", what);
        } else if (e != SIZE_MAX) {
            size_t i = (size_t)(c.un.e[e].key >> 32), j = (size_t)(c.un.e[e].key & 0xffffffffu);
            pair_error(out, i, j, c.un.e[e].st);
            st = cdist__fail(q, c.un.e[e].st, "scene %s: pair (%zu, %zu): %s", what, i, j, pair_message(c.un.e[e].st));
        } else if (!c.have) {
            pair_error(out, SIZE_MAX, SIZE_MAX, CDIST_ERR_BAD_INTERVAL);
            st = cdist__fail(q, CDIST_ERR_BAD_INTERVAL, "scene %s: no pair of live objects", what);
        } else {
            *out = c.rec;
        }
        free(c.un.e);
    }
    if (st && out && st != CDIST_ERR_BAD_KIND && st != CDIST_ERR_BAD_INTERVAL && out->status == CDIST_OK)
        pair_error(out, SIZE_MAX, SIZE_MAX, st);
    if (sb && sb != sa) cdist__scene_release(sb);
    return cdist__scene_leave(q, sa, st);
}

cdist_status cdist_scene_closest_pair(cdist_query *q, cdist_scene *s, cdist_scene_pair *out)
{
    return closest_entry(q, s, s, out);
}

cdist_status cdist_scene_closest_pair_between(cdist_query *q, cdist_scene *a, cdist_scene *b, cdist_scene_pair *out)
{
    return closest_entry(q, a, b, out);
}

/* ---- a query object: nearest k, within delta ---- */

typedef struct near_q {
    cdist_scene *s;
    const cdist__scene_item *qo;
    cdist__box qbox;
    cdist_query *h;
    /* nearest: the k best (distance, id) so far, sorted */
    cdist_scene_pair *res;
    size_t k, n;
    unanswered un;           /* failing objects (their ids) */
    /* within: the keys */
    broad *b;
} near_q;

static double near_cut(const near_q *c) { return c->n < c->k ? INFINITY : c->res[c->k - 1].distance; }

/* May live object i, at tree position p, be among the k nearest (its box and bounds do not
 * exclude it at the cut)? */
static int near_open(const near_q *c, uint32_t p, size_t i)
{
    double cut = near_cut(c);
    return cdist__box_near(&c->s->box[p], &c->qbox, cdist__box_lim(cut > 0.0 ? cut : 0.0)) &&
           !cdist__scene_excluded(&c->s->obj[i], &c->qo->o, cut, 1);
}

static int near_open_key(const void *ctx, uint64_t key)
{
    const near_q *c = ctx;
    return near_open(c, c->s->pos[key], (size_t)key);
}

static void near_obj(near_q *c, uint32_t p)
{
    size_t i = c->s->perm[p];
    if (c->s->obj[i].state != CD_SCENE_LIVE || !near_open(c, p, i)) return;
    cdist_scene_pair r;
    answer(c->h, core_of(c->s, i), core_of_item(c->qo), i, SIZE_MAX, INFINITY, &r, NULL);
    if (r.status != CDIST_OK) {
        unanswered_add(&c->un, i, (cdist_status)r.status);
        return;
    }
    /* insert by (distance, id) */
    size_t at = c->n < c->k ? c->n : c->k;
    while (at > 0 && (c->res[at - 1].distance > r.distance ||
                      (c->res[at - 1].distance == r.distance && c->res[at - 1].i > i))) {
        if (at < c->k) c->res[at] = c->res[at - 1];
        at--;
    }
    if (at < c->k) {
        c->res[at] = r;
        if (c->n < c->k) c->n++;
    }
}

static void near_node(near_q *c, uint32_t x)
{
    const cdist__node *nx = &c->s->node[x];
    double cut = near_cut(c);
    if (!cdist__box_near(&nx->box, &c->qbox, cdist__box_lim(cut > 0.0 ? cut : 0.0))) return;
    if (nx->count) {
        for (uint32_t p = nx->first; p < nx->first + nx->count; p++) near_obj(c, p);
        return;
    }
    uint32_t a = nx->first, b = nx->first + 1;
    if (cdist__box_gap_f(&c->s->node[b].box, &c->qbox) < cdist__box_gap_f(&c->s->node[a].box, &c->qbox))
        a = b, b = nx->first;
    near_node(c, a);
    near_node(c, b);
}

static void within_node(near_q *c, uint32_t x)
{
    const cdist__node *nx = &c->s->node[x];
    if (!cdist__box_near(&nx->box, &c->qbox, c->b->lim)) return;
    if (nx->count) {
        for (uint32_t p = nx->first; p < nx->first + nx->count; p++) {
            if (!cdist__box_near(&c->s->box[p], &c->qbox, c->b->lim)) continue;
            size_t i = c->s->perm[p];
            const cdist__scene_obj *o = &c->s->obj[i];
            if (o->state != CD_SCENE_LIVE) continue;
            c->b->box_pairs++;
            if (cdist__scene_excluded(o, &c->qo->o, c->b->delta, 0)) continue;
            push(c->b, i);
        }
        return;
    }
    within_node(c, nx->first);
    within_node(c, nx->first + 1);
}

static cdist_status query_object(cdist_query *q, cdist_scene_kind kind, const void *object, cdist__scene_item *o)
{
    if (!object) return cdist__fail(q, CDIST_ERR_NULL_ARGUMENT, "scene: query object pointer is NULL");
    cdist_status st = cdist__scene_make(q, kind, object, &o->o, &o->arc);
    if (st) return cdist__fail(q, st, "scene: query object: %.200s", cdist_query_last_error(q));
    return CDIST_OK;
}

cdist_status cdist_scene_nearest(cdist_query *q, cdist_scene *s, cdist_scene_kind kind, const void *object, size_t k,
                                 cdist_scene_pair *out, size_t *count)
{
    if (count) *count = 0;
    cdist_status st = cdist__scene_enter(q, s);
    if (st) return st;
    cdist__scene_item qo;
    if (!out && k > 0) st = cdist__fail(q, CDIST_ERR_NULL_ARGUMENT, "scene nearest: output array is NULL with k = %zu", k);
    else if (!(st = query_object(q, kind, object, &qo)) && !(st = cdist__scene_prepare(q, s)) && k > 0) {
        near_q c;
        memset(&c, 0, sizeof c);
        c.s = s;
        c.qo = &qo;
        cdist__scene_box(&qo.o, &c.qbox);
        c.h = q;
        c.res = out;
        c.k = k;
        if (s->node_n > 0) near_node(&c, 0);
        if (count) *count = c.n;
        cdist__begin(q, NULL);
        size_t e = unanswered_first(&c.un, near_open_key, &c);
        if (c.un.oom)
            st = cdist__fail(q, CDIST_ERR_NO_MEMORY, "scene nearest: out of memory for the failing objects");
        else if (e != SIZE_MAX)
            st = cdist__fail(q, c.un.e[e].st, "scene nearest: object %zu and the query object: %s",
                             (size_t)c.un.e[e].key, pair_message(c.un.e[e].st));
        free(c.un.e);
    }
    return cdist__scene_leave(q, s, st);
}

cdist_status cdist_scene_within(cdist_query *q, cdist_scene *s, cdist_scene_kind kind, const void *object, double delta,
                                cdist_scene_pair *out, size_t capacity, size_t *count)
{
    if (count) *count = 0;
    cdist_status st = cdist__scene_enter(q, s);
    if (st) return st;
    cdist__scene_item qo;
    if (!(st = check_delta(q, delta, out, capacity)) && !(st = query_object(q, kind, object, &qo)) &&
        !(st = cdist__scene_prepare(q, s))) {
        broad b = {s, s, 0, cdist__box_lim(fmax(delta, 0.0)), delta, 0, s->cand, 0, s->cand_cap, 0, 0, NULL, 0, 0};
        s->list_ok = 0;
        near_q c;
        memset(&c, 0, sizeof c);
        c.s = s;
        c.qo = &qo;
        cdist__scene_box(&qo.o, &c.qbox);
        c.b = &b;
        if (s->node_n > 0) within_node(&c, 0);
        s->cand = b.key;
        s->cand_cap = b.cap;
        if (b.oom) {
            st = cdist__fail(q, CDIST_ERR_NO_MEMORY, "scene within: out of memory for the candidates");
        } else {
            if (!(st = sort_keys(q, s, s->cand, b.n))) {
                narrow w;
                memset(&w, 0, sizeof w);
                w.sa = s;
                w.qo = &qo;
                w.key = s->cand;
                w.n = b.n;
                w.lim = delta;
                w.out = out;
                w.capacity = out ? capacity : 0;
                cdist_query *handles[256], **screen;
                pool p;
                pool_start(&p, call_threads(q, s, handles, &screen));
                w.h = handles;
                w.hs = screen;
                st = run_narrow(q, s, &w, &p);
                pool_stop(&p);
                if (!st) {
                    s->stats.box_pairs = b.box_pairs;
                    s->stats.screened = b.n;
                    s->stats.candidates = w.full;
                    s->stats.reported = w.count;
                    if (count) *count = w.count;
                    st = narrow_status(q, &w, "within");
                }
            }
        }
    }
    return cdist__scene_leave(q, s, st);
}
