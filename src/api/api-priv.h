/* SPDX-License-Identifier: MIT */
/* The API layer: the query handle, status recording, input validation, method choice. */
#ifndef CDIST_API_PRIV_H
#define CDIST_API_PRIV_H

#include <math.h>
#include <stdatomic.h>
#include <stddef.h>
#include <stdint.h>

#include "circledist.h"
#include "base/numeric.h"
#include "base/poly.h"
#include "base/pool.h"
#include "base/tolerances.h"
#include "base/vec.h"

#define CD_DEFAULT_CURVE_SAMPLES 512
#define CD_MAX_CURVE_SAMPLES (1 << 20)
/* Per-sample arrays of the curve scan (src/curves/curve_scan.c): the handle's scratch holds this
 * many arrays of curve_samples + 1 doubles. */
#define CD_CURVE_SCRATCH_ARRAYS 7
#define CD_DEFAULT_MAX_ITERATIONS 200
#define CD_MESSAGE_LEN 256

struct cdist_query {
    cdist_method method;
    double unit_tol;
    int curve_samples;
    int max_iterations;
    cdist_status last_status;
    char message[CD_MESSAGE_LEN];
    cdist__poly_ws *poly;
    /* Scratch owned by the handle (sized by the setters) so that queries never allocate. */
    double *scratch;
    size_t scratch_len;
    /* Set while a call uses the handle (cdist__enter .. cdist__leave): a second thread entering at the
     * same time gets CDIST_ERR_HANDLE_BUSY instead of corrupting the state above. */
    atomic_int busy;
    /* Set while a batch runs (src/batch/batch.c): the batch answers its entries with the public
     * queries on this handle, which take `busy` one by one, so the batch as a whole (the shared
     * worker pool and the worker handles) needs its own flag. Option setters and
     * cdist_query_set_threads refuse while it is set. */
    atomic_int batch_busy;
    struct cdist__workers *workers; /* worker threads and their handles (below); NULL = 1 thread */
    /* Progress reporting of long calls (cdist_query_set_progress): kept on the calling handle
     * only (worker handles never report), so it is not copied to the workers. */
    cdist_progress_fn progress_fn;
    void *progress_user;
    size_t progress_every; /* entries between reports, a multiple of 64 (0: no progress) */
};

/* Progress of a long call on q's calling thread: calls the handle's progress callback when one
 * is set (the caller rate-limits with q->progress_every); non-zero asks the call to stop. */
static inline int cdist__progress_report(const cdist_query *q, size_t done, size_t total)
{
    return q->progress_fn ? q->progress_fn(q->progress_user, done, total) != 0 : 0;
}

/* ---- worker threads (src/api/threads.c) ----
 * The lowest failing entry one thread met in a call of many entries (fail == SIZE_MAX: none),
 * with its status and message. */
typedef struct cdist__slot {
    size_t fail;
    cdist_status status;
    char message[CD_MESSAGE_LEN];
} cdist__slot;

/* A worker thread's own handle (workspaces included) and its failure record. */
typedef struct cdist__worker {
    cdist_query *handle;
    cdist__slot slot;
} cdist__worker;

/* The workers of a handle with T = threads > 1: T - 1 pool threads, pool worker k (1 .. T - 1)
 * answering with w[k - 1].handle; the calling thread is the T-th and answers with the handle
 * itself. */
struct cdist__workers {
    int threads;
    cdist__pool *pool;
    cdist__worker w[];
};

/* cdist__workers_free joins the threads and frees their handles (NULL allowed).
 * cdist__workers_sync gives every worker handle the options of q, sizing their workspaces
 * (called by every option setter, so that a batch never allocates). */
void cdist__workers_free(struct cdist__workers *w);
cdist_status cdist__workers_sync(cdist_query *q);


/* ---- validation and status ---- */

/* Start a query: sets the result to the error state (NaN, no pairs) and clears the message. */
void cdist__begin(cdist_query *q, cdist_result *r);
/* Record a failure (message printf-style) and return the status. q may be NULL. */
cdist_status cdist__fail(cdist_query *q, cdist_status st, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
cdist_status cdist__check_ptr(cdist_query *q, const void *p, const char *what);
cdist_status cdist__check_point_slow(cdist_query *q, const cdist_vec3 *p, const char *what);
/* A point: finite, |components| <= CD_MAX_ABS (one comparison each: false for NaN and inf). */
static inline cdist_status cdist__check_point(cdist_query *q, const cdist_vec3 *p, const char *what)
{
    if (p && fabs(p->x) <= CD_MAX_ABS && fabs(p->y) <= CD_MAX_ABS && fabs(p->z) <= CD_MAX_ABS) return CDIST_OK;
    return cdist__check_point_slow(q, p, what);
}
cdist_status cdist__check_scalar(cdist_query *q, double x, const char *what);
/* A radius: a scalar as above and not negative. */
cdist_status cdist__check_radius(cdist_query *q, double r, const char *what);
/* A direction or normal: finite, non-zero, unit within the handle's tolerance (or any length
 * when unit_required is 0). Writes the unit vector and the original length. */
cdist_status cdist__check_direction(cdist_query *q, const cdist_vec3 *d, const char *what, int unit_required,
                                vec3 *unit, double *length);
/* A circle or disk: writes the validated circle with its basis. */
cdist_status cdist__check_circle(cdist_query *q, const cdist_circle *c, const char *what, cdist__circle *out);

/* Bit of a method in a family's method set (cdist__family.methods). */
#define CD_HAS(m) (1u << (m))

/* ---- the one entry path (src/api/entry.c) ----
 * Every public query function runs
 *     st = cdist__enter(q, r);  if (st) return st;
 *     validate its inputs (cdist__check_*) -> frame and scale -> family core -> write r;
 *     return cdist__leave(q, r, st, method);
 * cdist__enter checks q and r and takes the handle's in-use flag: when another call holds it, it
 * returns CDIST_ERR_HANDLE_BUSY without touching the handle (r, when not NULL, gets the error
 * state). The result is not pre-filled: the core writes every field on success, and cdist__leave
 * puts r in the error state (NaN, no pairs) on failure. cdist__leave also turns a success with a
 * non-finite distance into CDIST_ERR_INTERNAL (never OK with NaN), records the status and
 * message, and releases the flag. */
cdist_status cdist__enter_slow(cdist_query *q, cdist_result *r);
static inline cdist_status cdist__enter(cdist_query *q, cdist_result *r)
{
    if (q && r && !atomic_exchange_explicit(&q->busy, 1, memory_order_acquire)) return CDIST_OK;
    return cdist__enter_slow(q, r);
}
cdist_status cdist__leave_slow(cdist_query *q, cdist_result *r, cdist_status st);
static inline cdist_status cdist__leave(cdist_query *q, cdist_result *r, cdist_status st, int method)
{
    if (st == CDIST_OK && isfinite(r->distance)) {
        r->method = method;
        q->last_status = CDIST_OK;
        q->message[0] = '\0';
        atomic_store_explicit(&q->busy, 0, memory_order_release);
        return CDIST_OK;
    }
    return cdist__leave_slow(q, r, st);
}
/* The same flag for the option setters (no result). */
cdist_status cdist__enter_setter(cdist_query *q);
void cdist__leave_setter(cdist_query *q);
/* An option setter takes the handle's flag and also refuses while a batch runs
 * (CDIST_ERR_HANDLE_BUSY): a batch copies the options to its worker handles once at its start and
 * its entries must all see the same options (and the thread count's pool is in use). */
cdist_status cdist__enter_option_setter(cdist_query *q);
/* A public option setter: the *_locked body under the handle's flag (cdist__enter_option_setter,
 * which refuses a NULL handle). */
#define CD_OPTION_SETTER(name, type, locked)                                                       \
    cdist_status name(cdist_query *q, type value)                                                  \
    {                                                                                              \
        cdist_status st = cdist__enter_option_setter(q);                                           \
        if (st) return st;                                                                         \
        st = locked(q, value);                                                                     \
        cdist__leave_setter(q);                                                                    \
        return st;                                                                                 \
    }
/* The bytes [lo, hi) spanned by n strided items of `size` bytes from p (n > 0). */
typedef struct cdist__span {
    uintptr_t lo, hi;
    const char *what;
} cdist__span;
cdist__span cdist__span_of(const void *p, size_t n, ptrdiff_t stride, size_t size, const char *what);
/* Batch arrays: s[0 .. n_inputs) are inputs (they may overlap each other), the rest outputs. 1
 * when an output overlaps any earlier array, with the two names in *x, *y. Checked before any
 * entry is read or written: an output written over a later entry's input would change that
 * entry's answer. */
int cdist__spans_overlap(const cdist__span *s, int count, int n_inputs, const char **x, const char **y);
#define CDIST__OVERLAP_MESSAGE                                                                                         \
    "batch: the %s overlap the %s (outputs must not overlap the inputs or each other); nothing was written"

/* The roles of the two objects exchanged: points and parameters of every pair (f(b, a) from
 * f(a, b)). */
void cdist__result_swap(cdist_result *r);
/* The error state of a result: NaN distances, points and parameters, no pairs. */
void cdist__result_set_error(cdist_result *r);
/* The unused fields of a successful result: pairs from index n on NaN, iterations and reserved
 * zero. Inline: a handful of stores, a fifth of a point query's instructions as a call. */
static inline void cdist__result_finish(cdist_result *r, int n)
{
    for (int i = n; i < 2; i++) {
        for (int k = 0; k < 2; k++) {
            r->pairs[i].point[k] = v3(NAN, NAN, NAN);
            r->pairs[i].param[k] = NAN;
        }
    }
    r->iterations = 0;
    for (int i = 0; i < 8; i++) r->reserved[i] = 0.0;
}

/* Scale a validated result back: distances and points times `up` (a power of two). */
static inline void cdist__result_unscale(cdist_result *r, double up)
{
    r->distance *= up;
    r->sqr_distance = (r->sqr_distance * up) * up;
    for (int i = 0; i < r->num_pairs; i++)
        for (int k = 0; k < 2; k++) r->pairs[i].point[k] = v_scale(up, r->pairs[i].point[k]);
}
/* A circle scaled by a power of two about the origin (centre and radius; n, u, v unchanged). */
static inline void cdist__circle_scale(cdist__circle *c, double s)
{
    c->c = v_scale(s, c->c);
    c->r *= s;
}

/* Finite and |components| <= CD_MAX_ABS (NaN fails every comparison). */
CD_INLINE int cdist__in_range(vec3 a)
{
    return (fabs(a.x) <= CD_MAX_ABS) & (fabs(a.y) <= CD_MAX_ABS) & (fabs(a.z) <= CD_MAX_ABS);
}

/* The accepting part of cdist__check_direction(q, d, ..., 1, unit, length) with its arithmetic,
 * inline for fused fast paths: 1 with *unit and *length when d is finite, in range, of largest
 * component at least CD_MIN_NORMAL_FAST and unit within unit_tol; 0 when the full check must
 * decide (and report). */
CD_INLINE int cdist__direction_fast_body(double unit_tol, const cdist_vec3 *d, vec3 *unit, double *length)
{
    vec3 v = *d;
    if (!cdist__in_range(v)) return 0;
    if (!(v_maxabs(v) >= CD_MIN_NORMAL_FAST)) return 0;
    /* |d| from d itself: for max|d_i| in [CD_MIN_NORMAL_FAST, CD_MAX_ABS] |d|^2 is finite and
     * normal, and a component whose square underflows errs by under 2^-22 ulp of it; so no
     * prescaling by 1 / max|d_i|, whose division headed every query's longest chain. The batch
     * kernels (src/batch) repeat this arithmetic and must agree with single calls. */
    double len = v_norm(v);
    if (!(fabs(len - 1.0) <= unit_tol)) return 0;
    *unit = v_scale(1.0 / len, v);
    *length = len;
    return 1;
}

/* Validation without message formatting: a valid circle formats no strings. One comparison
 * per number covers NaN, infinity and the range (|x| <= CD_MAX_ABS is false for all three);
 * the normal's squared length is taken directly when it is safely in range. Returns 0 on any
 * doubt; the slow path then finds and reports the problem, or accepts the circle. Inline here
 * for the paths that fuse it with their core (the point and line queries); cdist__circle_fast is
 * the same. */
CD_INLINE int cdist__circle_fast_body(double unit_tol, const cdist_circle *c, cdist__circle *out)
{
    vec3 p = c->center;
    double r = c->radius, len;
    if (!(cdist__in_range(p) && r >= 0.0 && r <= CD_MAX_ABS)) return 0;
    if (!cdist__direction_fast_body(unit_tol, &c->normal, &out->n, &len)) return 0;
    out->c = p;
    out->r = r;
    return 1;
}

/* The fast path of cdist__check_circle_nobasis alone, with its arithmetic (same FMA clone): 1
 * and *out (no basis) when it accepts c, 0 when the full check must decide (the batch kernels
 * then leave the entry to the scalar path; the cc kernel's test decides acceptance with it). */
int cdist__circle_fast(double unit_tol, const cdist_circle *c, cdist__circle *out);
/* The same with the basis (NULL c: 0), as cdist__check_circle builds it, inline for the caller's
 * FMA clone: for a query that starts the circle's normal and basis, its longest chain, before
 * its other checks (the lines), and runs cdist__check_circle afterwards only where this returns
 * 0 (to report the problem). */
static inline void cdist__frame_basis(cdist__circle *c) { v_basis(c->n, &c->u, &c->v); }
CD_INLINE int cdist__circle_fast_basis(double unit_tol, const cdist_circle *c, cdist__circle *out)
{
    if (!c || !cdist__circle_fast_body(unit_tol, c, out)) return 0;
    cdist__frame_basis(out);
    return 1;
}
/* A circle or disk checked without building its basis (c, n, r only; u, v left unset), for
 * families that do not need it; cdist__frame_basis completes it. */
cdist_status cdist__check_circle_nobasis(cdist_query *q, const cdist_circle *c, const char *what, cdist__circle *out);

/* The checks of a line or ray (the object, its origin, its unit direction: M, and the length
 * as passed: len) and of a segment (the object and both end points), shared by the lines
 * family's circle and disk queries (src/api/validate.c). The line's is inline for the entries' FMA clones: its fast part accepts, the
 * slow part (out of line) decides and reports whatever that doubts. */
cdist_status cdist__check_line_ray_slow(cdist_query *q, const void *obj, const cdist_vec3 *origin, const cdist_vec3 *dir,
                                       int is_ray, vec3 *M, double *len);
CD_INLINE cdist_status cdist__check_line_ray(cdist_query *q, const void *obj, const cdist_vec3 *origin,
                                             const cdist_vec3 *dir, int is_ray, vec3 *M, double *len)
{
    if (obj && cdist__in_range(*origin) && cdist__direction_fast_body(q->unit_tol, dir, M, len)) return CDIST_OK;
    return cdist__check_line_ray_slow(q, obj, origin, dir, is_ray, M, len);
}
cdist_status cdist__check_segment(cdist_query *q, const cdist_segment *s);

/* ---- the family table (src/api/family.c) ----
 * One row per query family, numbered like its cdist_kind (the registry src/api/kinds.def): the
 * methods it implements and what AUTO (or a method it lacks) runs. */
typedef enum cdist__fam {
#define CD_KIND(KIND, number, ...) CD_FAM_##KIND = number,
#define CD_CURVE_KIND(KIND, number, ...) CD_FAM_##KIND = number,
#include "api/kinds.def"
    CD_FAM_COUNT
} cdist__fam;

typedef struct cdist__family {
    unsigned methods;         /* CD_HAS(m) for every method the family implements */
    cdist_method auto_method; /* what AUTO and an unimplemented method run */
} cdist__family;

extern const cdist__family cdist__family_table[CD_FAM_COUNT];

/* The method family f runs for the handle's method. */
static inline cdist_method cdist__family_method(const cdist_query *q, cdist__fam f)
{
    const cdist__family *t = &cdist__family_table[f];
    cdist_method m = q->method;
    return (m == CDIST_METHOD_AUTO || !(t->methods & CD_HAS(m))) ? t->auto_method : m;
}

#endif
