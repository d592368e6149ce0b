/* SPDX-License-Identifier: MIT */
/* The scene queries answered by a public pair query per candidate pair: linked pairs and the
 * time of impact of a moving scene. */
#include <stdlib.h>
#include <string.h>

#include "scene-priv.h"

/* Pairs per grab of a time-of-impact thread: each pair costs tens of distance queries. */
#define CD_SCENE_TOI_CHUNK 64

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
static cdist_status pair_job_run(cdist_query *q, cdist_scene *s, cdist__scene_broad *b, const char *what, pair_job *job)
{
    cdist_status st = cdist__scene_prepare(q, s);
    if (st) return st;
    cdist_query *handles[256], **screen;
    cdist__scene_pool p;
    cdist__scene_pool_start(&p, cdist__scene_call_threads(q, s, handles, &screen));
    if (!screen) st = cdist__fail(q, CDIST_ERR_NO_MEMORY, "scene %s: out of memory for the thread handles", what);
    else if (!(st = cdist__scene_broad_run(q, b, &p, what)) && !(st = cdist__scene_sort_keys(q, s, s->cand, b->n)) && b->n > 0) {
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
            if (p.threads > 1 && b->n > job->chunk) cdist__scene_pool_run(&p, pair_job_round, job);
            else pair_job_round(job, 0);
        }
    }
    cdist__scene_pool_stop(&p);
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
    cdist__scene_broad b = {s, s, 1, cdist__box_lim(link_box_reach(s)), 0.0, 0, s->cand, 0, s->cand_cap, 0, 1, NULL, 0, 0};
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
    cdist__scene_broad b = {s, s, 1, cdist__box_lim(fmax(lim, 0.0) + 2.0 * most), lim, 0, s->cand, 0, s->cand_cap, 0, 0, reach,
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
