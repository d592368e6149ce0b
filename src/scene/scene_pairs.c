/* SPDX-License-Identifier: MIT */
/* The narrow phase of the scene queries and the pairs within delta. Each sorted key of the
 * broad phase is answered by the exact query, chunks of keys spread over the handle's threads
 * and committed in key order, so the output is the same for every thread count. A moving
 * scene keeps its pair list between queries. */
#include <stdlib.h>
#include <string.h>

#include "batch/batch-priv.h"
#include "scene-priv.h"

/* Chunks per thread and round of the narrow phase (a round's answers are committed in order
 * before the next round starts). */
#define CD_SCENE_CHUNKS_PER_THREAD 8

/* ---- exact answers of pairs ---- */

static int unsupported(cdist__core_type a, cdist__core_type b)
{
    return (a == CD_CORE_POINT && b == CD_CORE_ARC) || (a == CD_CORE_ARC && b == CD_CORE_POINT);
}

void cdist__scene_pair_error(cdist_scene_pair *p, size_t i, size_t j, cdist_status st)
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
        cdist__scene_pair_error(p, i, j, st);
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

int cdist__scene_answer(cdist_query *h, cdist__core_obj ca, cdist__core_obj cb, size_t i, size_t j, double lim,
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

const char *cdist__scene_pair_message(cdist_status st)
{
    return st == CDIST_ERR_BAD_KIND ? "no exact query for a point (or sphere) and an arc" : cdist_status_string(st);
}

/* ---- narrow phase: threads, rounds, ordered commit ---- */

/* The objects of key k: i, j (SIZE_MAX for the query object) and the second object. */
static const cdist__scene_obj *key_pair(const cdist__scene_narrow *w, size_t k, size_t *i, size_t *j)
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
static void list_learn(cdist__scene_narrow *w, size_t k, double mm, double lo, double hi)
{
    double nl = lo + mm, nh = hi - mm;
    if (nl > (double)w->lo[k]) w->lo[k] = fmaxf(w->lo[k], cdist__float_down(nl));
    if (nh < (double)w->hi[k]) w->hi[k] = fminf(w->hi[k], cdist__float_up(nh));
}

enum { ACT_SKIP, ACT_ANSWER, ACT_SCREEN };

/* What list entry k needs. Its bounds, moved by the two objects' motions since they were
 * known (each point moves at most moved[i]; the distance changes at most by the sum), decide
 * first; then the boxes and the bounds of the current poses, whose results the entry keeps. */
static int list_action(cdist__scene_narrow *w, size_t k, const cdist__scene_obj *a, const cdist__scene_obj *b,
                       size_t i, size_t j, size_t *box, int *decided, double *moved, double *pmargin)
{
    const cdist_scene *s = w->sa;
    *decided = 0;
    if (a->state != CD_SCENE_LIVE || b->state != CD_SCENE_LIVE || cdist__scene_skipped(s, i, j)) return ACT_SKIP;
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
static void run_chunk(cdist__scene_narrow *w, cdist_query *h, cdist_query *hs, size_t c)
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
            cdist__core_obj cb = w->qo ? cdist__scene_item_core(w->qo) : cdist__scene_core_of(w->sb, j);
            m += cdist__scene_answer(h, cdist__scene_core_of(w->sa, i), cb, i, j, w->lim, &out[m], &d);
        }
        /* A method without a certificate (POLYNOMIAL, ITERATION) may answer a local minimum:
         * an upper bound, never a lower one. */
        if (w->lo) list_learn(w, k, mm[k - lo], w->certified ? d - margin : NAN, d + margin);
        full++;
    }
    w->buf_n[slot] = m;
    w->buf_full[slot] = full;
    if (w->lo) w->buf_box[slot] = box, w->buf_past[slot] = past;
}

static void drain(cdist__scene_narrow *w, cdist_query *h, cdist_query *hs)
{
    for (;;) {
        size_t c = atomic_fetch_add_explicit(&w->next, 1, memory_order_relaxed);
        if (c >= w->round_hi) return;
        run_chunk(w, h, hs, c);
    }
}

static void narrow_round(void *ctx, int t)
{
    cdist__scene_narrow *w = ctx;
    drain(w, w->h[t], w->hs ? w->hs[t] : NULL);
}

static void commit(cdist__scene_narrow *w, const cdist_scene_pair *p, size_t m)
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

cdist_status cdist__scene_run_narrow(cdist_query *q, cdist_scene *s, cdist__scene_narrow *w, cdist__scene_pool *p)
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
        if (p->threads > 1 && w->round_hi - w->round_lo > 1) cdist__scene_pool_run(p, narrow_round, w);
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

cdist_status cdist__scene_narrow_status(cdist_query *q, const cdist__scene_narrow *w, const char *what)
{
    cdist__begin(q, NULL);
    if (w->stopped) return cdist__fail(q, CDIST_ERR_CALLBACK_FAILED, "scene %s: the pair callback stopped the query", what);
    if (w->fail == CDIST_OK) return CDIST_OK;
    if (w->fail_j == SIZE_MAX)
        return cdist__fail(q, w->fail, "scene %s: object %zu and the query object: %s", what, w->fail_i,
                           cdist__scene_pair_message(w->fail));
    return cdist__fail(q, w->fail, "scene %s: pair (%zu, %zu): %s", what, w->fail_i, w->fail_j, cdist__scene_pair_message(w->fail));
}

/* ---- pairs within delta ---- */

cdist_status cdist__scene_check_delta(cdist_query *q, double delta, const void *out, size_t capacity)
{
    if (isnan(delta)) return cdist__fail(q, CDIST_ERR_NOT_FINITE, "scene: delta is NaN");
    if (!out && capacity > 0)
        return cdist__fail(q, CDIST_ERR_NULL_ARGUMENT, "scene: output array is NULL with capacity %zu", capacity);
    return CDIST_OK;
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
static cdist_status list_make(cdist_query *q, cdist_scene *s, double delta, cdist__scene_pool *p)
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
    cdist__scene_broad b = {s, s, 1, cdist__box_lim(reach), delta, 0, s->cand, 0, s->cand_cap, 0, 0, NULL, 1, 0};
    cdist_status st = cdist__scene_broad_run(q, &b, p, "pairs_within");
    if (!st) st = cdist__scene_sort_keys(q, s, s->cand, b.n);
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
static cdist_status pairs_run(cdist_query *q, cdist_scene *sa, cdist_scene *sb, double delta, cdist__scene_narrow *w,
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
    cdist__scene_pool p;
    cdist__scene_pool_start(&p, cdist__scene_call_threads(q, sa, handles, &screen));
    cdist__scene_broad b = {sa, sb, sa == sb, cdist__box_lim(fmax(delta, 0.0)), delta, 0, sa->cand, 0, sa->cand_cap, 0, 0, NULL, 0,
               screen != NULL};
    if (list) {
        if (reuse || !(st = list_make(q, sa, delta, &p))) b.n = sa->list_n;
    } else if (!(st = cdist__scene_broad_run(q, &b, &p, what))) {
        st = cdist__scene_sort_keys(q, sa, sa->cand, b.n);
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
        w->certified = q->method == CDIST_METHOD_AUTO || q->method == CDIST_METHOD_ROBUST;
        st = cdist__scene_run_narrow(q, sa, w, &p);
    }
    cdist__scene_pool_stop(&p);
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
    return cdist__scene_narrow_status(q, w, what);
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
    else if (!fn && (st = cdist__scene_check_delta(q, delta, out, capacity))) (void)0;
    else if (fn && isnan(delta)) st = cdist__fail(q, CDIST_ERR_NOT_FINITE, "scene: delta is NaN");
    else {
        cdist__scene_narrow w;
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
