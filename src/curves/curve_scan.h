/* SPDX-License-Identifier: MIT */
/* The curve engine (curve_scan.c, its certification curve_cert.c) shared by the curves of this
 * folder: callback curves (curve_user.c), helix (helix.c), Bezier (bezier.c), arcs (arc.c).
 * Private to src/curves. */
#ifndef CDIST_CURVE_SCAN_H
#define CDIST_CURVE_SCAN_H

#include "internal.h"

/* Candidate collector: cdist__best plus the smallest squared distance among candidates that have
 * infinitely many closest pairs (set as the result's equidistant flag only if that candidate
 * ends up the minimum). */
typedef struct cdist__cs_coll {
    cdist__best b;
    double eq_d2;
    int flat_ties; /* set on the degenerate sampling paths (a constant function was scanned):
                    * three distinct tied candidates then mean a continuum */
} cdist__cs_coll;

void cdist__cs_coll_init(cdist__cs_coll *k, double scale);
void cdist__cs_coll_offer(cdist__cs_coll *k, double d2, vec3 p0, vec3 p1, double a0, double a1, int eq);
/* The families work on a copy of the problem scaled by down = 2^-e (cdist__scale_exponent of its
 * scale: exact, and squared distances neither underflow nor overflow). Unscale the collector by
 * up = 2^e, finish it (b.equidistant from the equidistant candidates and, with flat_ties, from
 * three-way ties) and write the result, points moved by origin; returns CDIST_OK (the query's
 * status from here on). */
cdist_status cdist__cs_coll_result(cdist__cs_coll *k, double up, vec3 origin, cdist_result *r);
/* Offer point p (any frame) with parameter t against circle/disk c (c->c in the same frame);
 * swap puts p second. */
void cdist__cs_offer_point(cdist__cs_coll *k, vec3 p, double t, const cdist__circle *c, int disk, int swap);

/* rel (relative to c's centre) is on c's axis up to the rounding of the problem's scale
 * (CD_CURVE_AXIS_ULPS). */
int cdist__cs_near_axis(const cdist__cs_coll *k, vec3 rel, const cdist__circle *c);

/* A curve: position and derivative at t, in the scan's frame. Returns CDIST_OK or a status
 * (already recorded with cdist__fail). */
typedef cdist_status (*cdist__cs_eval_fn)(cdist_query *q, const void *ctx, double t, vec3 *p, vec3 *dp);

/* A built-in curve's position alone (cannot fail): the certification's midpoints need no
 * derivative. */
typedef vec3 (*cdist__cs_pos_fn)(const void *ctx, double t);

typedef struct cdist__cs_scan cdist__cs_scan;
/* Receives each candidate parameter t (and its point p) instead of the default point offer. */
typedef void (*cdist__cs_cand_fn)(const cdist__cs_scan *s, double t, vec3 p);
/* A curve-specific rigorous lower bound of the distance from the curve's points over [a, b] to
 * the target (rounding included), or 0. */
typedef double (*cdist__cs_lb_fn)(const cdist__cs_scan *s, double a, double b);

struct cdist__cs_scan {
    cdist_query *q;
    cdist__cs_eval_fn ev;
    const void *ctx;
    const cdist__circle *c; /* target circle/disk, its centre c->c in the scan's frame */
    int disk;
    cdist__cs_coll *k;
    cdist__cs_cand_fn cand;    /* NULL: offer the point against c into k */
    const void *cand_ctx;
    int update_scale;   /* raise k->b.scale to the sampled extent */
    double span;        /* set by cdist__cs_scan_run */
    double frame_mag;   /* magnitude of the frame's coordinates (rounding level of positions) */
    /* Certification (see cdist__cs_scan_run): bounds over the whole parameter range of |P'|,
     * |P''| and |n . P''| (n the target's normal), in the scan's frame. certify = 0 (callback
     * curves, candidate callbacks, a function known constant): no certification. */
    int certify;
    double speed_max, accel_max, accel_normal_max, accel_plane_max; /* |n x P''| last */
    int speed_varies; /* |P'| may be well below speed_max: a local bound is worth its cost */
    cdist__cs_lb_fn lb; /* optional extra bound (NULL) */
    cdist__cs_pos_fn pos; /* optional position-only form of ev (NULL: ev) */
    const void *lb_ctx;
    long cert_nodes;    /* nodes of the certification spent so far (the cost limit) */
    /* Evaluations the query may still spend (NULL: no limit; a scan charges its samples at
     * once), then CDIST_ERR_COST_LIMIT; evals_max: the budget it started with. */
    long *evals_left;
    long evals_max;
};

/* Bound, refine and offer every minimum of the distance over [t0, t1] with n samples
 * (at most the handle's curve sample count); with s->certify, then certify the answer
 * (every part of [t0, t1] bounded below by the answer minus the certification tolerance, or
 * searched). CDIST_ERR_COST_LIMIT when the certification exceeds its node budget or the
 * query's budget of evaluations is spent. */
cdist_status cdist__cs_scan_run(cdist__cs_scan *s, double t0, double t1, int n);
/* Polish a candidate minimum near t (from another method) within [lo, hi]: walk to the nearest
 * sign change of g in the direction of descent, refine, and offer the result. */
cdist_status cdist__cs_polish(cdist__cs_scan *s, double t, double lo, double hi);
/* After the scans: flag equidistance when the distance is flat (within the tie tolerance)
 * at t* +- delta around the best parameter (a curve lying on a continuum of minima). */
cdist_status cdist__cs_flat_check(cdist__cs_scan *s, double t0, double t1, double delta);
/* t0, t1 finite (NOT_FINITE), t0 <= t1 and t1 - t0 finite (BAD_INTERVAL). */
cdist_status cdist__cs_check_interval(cdist_query *q, double t0, double t1, const char *what);
/* U = zd projected onto the plane of unit normal n, normalised; V = n x U. ZERO_VECTOR when zd
 * is zero or within CD_CURVE_PARALLEL_SIN of n. */
cdist_status cdist__cs_zero_frame(cdist_query *q, vec3 n, const cdist_vec3 *zd, const char *what, vec3 *U, vec3 *V);

/* Run a curve (evaluated in the frame whose origin is `origin`) against circle or disk cc
 * (its centre already relative to that frame) with the handle's sample count and write the
 * result. bounds: |P'|, |P''|, |n . P''| and |n x P''| over [t0, t1] (certified search), or NULL
 * (sampling only). */
cdist_status cdist__cs_run_curve(cdist_query *q, cdist__cs_eval_fn ev, cdist__cs_pos_fn pos, const void *ctx, double t0,
                                 double t1, const cdist__circle *cc, int disk, vec3 origin, double scale,
                                 double frame_mag, double up, const double *bounds, cdist_result *r);

/* A curve object (helix, Bezier, arc...) against a circle or, disk = 1, a disk. */
typedef cdist_status (*cdist__cs_query_fn)(cdist_query *q, const void *obj, const cdist_circle *c, cdist_result *r,
                                           int disk);
/* The public entry of such a query: takes the handle, runs it, reports its status. */
static inline cdist_status cdist__cs_entry(cdist_query *q, cdist__cs_query_fn fn, const void *obj,
                                           const cdist_circle *c, cdist_result *r, int disk)
{
    cdist_status st = cdist__enter(q, r);
    if (st) return st;
    return cdist__leave(q, r, fn(q, obj, c, r, disk), CDIST_METHOD_ROBUST);
}

/* The evaluations of the curve spent by the last helix query of the calling thread that got
 * past validation (at most CD_CURVE_HELIX_MAX_EVALS + 1: the one refused); for the tests of the
 * helix's cost bound. */
long cdist__helix_last_evals(void);

/* ---- shared by the engine, its certification and the helix ---- */

static inline double cdist__cs_min2(double a, double b) { return a < b ? a : b; }
static inline double cdist__cs_max2(double a, double b) { return a > b ? a : b; }

/* Sample i of n over [t0, t1] (the last exactly t1). */
static inline double cdist__cs_t_at(double t0, double t1, int i, int n)
{
    if (i == n) return t1;
    return t0 + (t1 - t0) * ((double)i / n);
}

/* The certification tolerance tau (CD_CURVE_CERT_ULPS of the collector's scale). */
static inline double cdist__cs_cert_tol(const cdist__cs_scan *s)
{
    return CD_CURVE_CERT_ULPS * DBL_EPSILON * s->k->b.scale;
}

/* Position and F (or D) at t alone (the position-only form when the curve has one). */
cdist_status cdist__cs_eval_point(const cdist__cs_scan *s, double t, vec3 *p, double *f);
/* Certify the n sample intervals of a scan over [t0, t1] (F: d^2, P: positions per sample),
 * after the scan offered its candidates (curve_cert.c). */
cdist_status cdist__cs_certify_samples(cdist__cs_scan *s, double t0, double t1, int n, const double *F, const vec3 *P);

#endif
