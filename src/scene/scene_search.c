/* SPDX-License-Identifier: MIT */
/* The scene searches: the closest pair (branch and bound over the tree), and the nearest
 * objects to a query object or those within delta of it. */
#include <stdlib.h>
#include <string.h>

#include "scene-priv.h"

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
    if (!cdist__scene_pair_at(c->sa, c->sb, c->self, 1, pa, pb, &i, &j, &oa, &ob)) return;
    c->box_pairs++;
    if (cdist__scene_excluded(oa, ob, c->best, 1)) return;
    c->candidates++;
    cdist_scene_pair p;
    cdist__scene_answer(c->h, cdist__scene_core_of(c->sa, i), cdist__scene_core_of(c->sb, j), i, j, INFINITY, &p, NULL);
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
    if (ny->count || (!nx->count && cdist__box_size(&nx->box) >= cdist__box_size(&ny->box)))
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
static void best_self(closest *c, uint32_t x) { cdist__scene_self_walk(c->sa, x, best_leaf, best_cross_fn, c); }

static cdist_status closest_entry(cdist_query *q, cdist_scene *sa, cdist_scene *sb, cdist_scene_pair *out)
{
    cdist_status st = cdist__scene_enter(q, sa);
    if (st) {
        if (out) cdist__scene_pair_error(out, SIZE_MAX, SIZE_MAX, st);
        return st;
    }
    if (sb != sa && sb && !cdist__scene_take(sb)) {
        if (out) cdist__scene_pair_error(out, SIZE_MAX, SIZE_MAX, CDIST_ERR_HANDLE_BUSY);
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
            cdist__scene_pair_error(out, SIZE_MAX, SIZE_MAX, CDIST_ERR_NO_MEMORY);
            st = cdist__fail(q, CDIST_ERR_NO_MEMORY, "scene %s: out of memory for the failing pairs", what);
        } else if (e != SIZE_MAX) {
            size_t i = (size_t)(c.un.e[e].key >> 32), j = (size_t)(c.un.e[e].key & 0xffffffffu);
            cdist__scene_pair_error(out, i, j, c.un.e[e].st);
            st = cdist__fail(q, c.un.e[e].st, "scene %s: pair (%zu, %zu): %s", what, i, j, cdist__scene_pair_message(c.un.e[e].st));
        } else if (!c.have) {
            cdist__scene_pair_error(out, SIZE_MAX, SIZE_MAX, CDIST_ERR_BAD_INTERVAL);
            st = cdist__fail(q, CDIST_ERR_BAD_INTERVAL, "scene %s: no pair of live objects", what);
        } else {
            *out = c.rec;
        }
        free(c.un.e);
    }
    if (st && out && st != CDIST_ERR_BAD_KIND && st != CDIST_ERR_BAD_INTERVAL && out->status == CDIST_OK)
        cdist__scene_pair_error(out, SIZE_MAX, SIZE_MAX, st);
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
    cdist__scene_broad *b;
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
    cdist__scene_answer(c->h, cdist__scene_core_of(c->s, i), cdist__scene_item_core(c->qo), i, SIZE_MAX, INFINITY, &r, NULL);
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
            cdist__scene_push(c->b, i);
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
                             (size_t)c.un.e[e].key, cdist__scene_pair_message(c.un.e[e].st));
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
    if (!(st = cdist__scene_check_delta(q, delta, out, capacity)) && !(st = query_object(q, kind, object, &qo)) &&
        !(st = cdist__scene_prepare(q, s))) {
        cdist__scene_broad b = {s, s, 0, cdist__box_lim(fmax(delta, 0.0)), delta, 0, s->cand, 0, s->cand_cap, 0, 0, NULL, 0, 0};
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
            if (!(st = cdist__scene_sort_keys(q, s, s->cand, b.n))) {
                cdist__scene_narrow w;
                memset(&w, 0, sizeof w);
                w.sa = s;
                w.qo = &qo;
                w.key = s->cand;
                w.n = b.n;
                w.lim = delta;
                w.out = out;
                w.capacity = out ? capacity : 0;
                cdist_query *handles[256], **screen;
                cdist__scene_pool p;
                cdist__scene_pool_start(&p, cdist__scene_call_threads(q, s, handles, &screen));
                w.h = handles;
                w.hs = screen;
                st = cdist__scene_run_narrow(q, s, &w, &p);
                cdist__scene_pool_stop(&p);
                if (!st) {
                    s->stats.box_pairs = b.box_pairs;
                    s->stats.screened = b.n;
                    s->stats.candidates = w.full;
                    s->stats.reported = w.count;
                    if (count) *count = w.count;
                    st = cdist__scene_narrow_status(q, &w, "within");
                }
            }
        }
    }
    return cdist__scene_leave(q, s, st);
}
