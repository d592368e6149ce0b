/* SPDX-License-Identifier: MIT */
/* The broad phase of the scene queries: the tree walked two subtrees at a time (on several
 * threads, from tasks made of the traversal's first levels) keeps the object pairs that no
 * certified bound excludes, as keys (i << 32 | j), which are then sorted. */
#include <stdlib.h>
#include <string.h>

#include "scene-priv.h"

void cdist__scene_push(cdist__scene_broad *b, uint64_t key)
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

int cdist__scene_pair_at(const cdist_scene *sa, const cdist_scene *sb, int self, int filter, uint32_t pa, uint32_t pb,
                         size_t *pi, size_t *pj, const cdist__scene_obj **poa, const cdist__scene_obj **pob)
{
    if (sa->tcore[pa] == CD_SCENE_T_GONE || sb->tcore[pb] == CD_SCENE_T_GONE) return 0;
    size_t i = sa->perm[pa], j = sb->perm[pb];
    if (self && i > j) {
        size_t t = i;
        i = j, j = t;
    }
    if (self && filter && cdist__scene_skipped(sa, i, j)) return 0;
    *pi = i, *pj = j, *poa = &sa->obj[i], *pob = &sb->obj[j];
    return 1;
}

/* Both objects at tree positions pa of sa and pb of sb have circle cores. */
static int circle_pair_at(const cdist__scene_broad *b, uint32_t pa, uint32_t pb)
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
static void near_pos(cdist__scene_broad *b, uint32_t pa, uint32_t pb)
{
    size_t i, j;
    const cdist__scene_obj *oa, *ob;
    if (!cdist__scene_pair_at(b->sa, b->sb, b->self, !b->link, pa, pb, &i, &j, &oa, &ob)) return;
    if (b->link && !circle_pair_at(b, pa, pb)) return;
    b->box_pairs++;
    if (b->list) {
        cdist__scene_push(b, (uint64_t)i << 32 | j);
        return;
    }
    if (b->link ? link_excluded(oa, ob)
                : !(b->screen && circle_pair_at(b, pa, pb)) &&
                      cdist__scene_excluded(oa, ob, b->reach ? b->delta + b->reach[i] + b->reach[j] : b->delta, 0))
        return;
    cdist__scene_push(b, (uint64_t)i << 32 | j);
}

/* The pairs of positions (px[u], py[v]) whose boxes are within lim, v > u only when upper (a
 * leaf against itself), found without a branch per pair (which pairs pass is no pattern a
 * predictor learns), then taken in (u, v) order. */
static void near_pairs(cdist__scene_broad *b, const uint32_t *px, uint32_t mx, const uint32_t *py, uint32_t my, int upper)
{
    uint32_t hit[CD_SCENE_LEAF_MAX * CD_SCENE_LEAF_MAX], nh = 0;
    for (uint32_t u = 0; u < mx; u++)
        for (uint32_t v = upper ? u + 1 : 0; v < my; v++) {
            hit[nh] = u << 8 | v;
            nh += (uint32_t)cdist__box_near(&b->sa->box[px[u]], &b->sb->box[py[v]], b->lim);
        }
    for (uint32_t k = 0; k < nh; k++) near_pos(b, px[hit[k] >> 8], py[hit[k] & 255]);
}

static void cross(cdist__scene_broad *b, uint32_t x, uint32_t y)
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
    } else if (ny->count || (!nx->count && cdist__box_size(&nx->box) >= cdist__box_size(&ny->box))) {
        cross(b, nx->first, y);
        cross(b, nx->first + 1, y);
    } else {
        cross(b, x, ny->first);
        cross(b, x, ny->first + 1);
    }
}

void cdist__scene_self_walk(const cdist_scene *s, uint32_t x, void (*leaf)(void *, uint32_t, uint32_t),
                            void (*cross)(void *, uint32_t, uint32_t), void *ctx)
{
    const cdist__node *nx = &s->node[x];
    if (nx->count) {
        leaf(ctx, nx->first, nx->count);
        return;
    }
    cdist__scene_self_walk(s, nx->first, leaf, cross, ctx);
    cdist__scene_self_walk(s, nx->first + 1, leaf, cross, ctx);
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
static void self(cdist__scene_broad *b, uint32_t x) { cdist__scene_self_walk(b->sa, x, self_leaf, cross_fn, b); }

cdist_status cdist__scene_sort_keys(cdist_query *q, const cdist_scene *s, uint64_t *key, size_t n)
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
    cdist__scene_broad *b; /* one per thread */
    const btask *task;
    size_t n_tasks;
    atomic_size_t next;
} broad_par;

static void broad_round(void *ctx, int t)
{
    broad_par *bp = ctx;
    cdist__scene_broad *b = &bp->b[t];
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
static btask *make_tasks(const cdist__scene_broad *b, size_t want, size_t *n_out)
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
            } else if (ny_->count || (!nx_->count && cdist__box_size(&nx_->box) >= cdist__box_size(&ny_->box))) {
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

cdist_status cdist__scene_broad_run(cdist_query *q, cdist__scene_broad *b, cdist__scene_pool *p, const char *what)
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
    cdist__scene_broad per[256];
    for (int t = 0; t < p->threads; t++) {
        per[t] = *b;
        per[t].key = NULL;
        per[t].n = per[t].cap = 0;
    }
    per[0].key = b->key; /* the scene's kept list */
    per[0].cap = b->cap;
    broad_par bp = {per, task, n_tasks, 0};
    atomic_init(&bp.next, 0);
    if (task) cdist__scene_pool_run(p, broad_round, &bp);
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
