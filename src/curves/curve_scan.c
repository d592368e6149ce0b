/* SPDX-License-Identifier: MIT */
/* The curve engine: the candidate collector, the objective F (or D) and g = F'/2 along a curve,
 * the sampled scan that brackets and refines every critical point, the descent from a point
 * (polish) and the flat check. The formulas, the scan's steps and its limitation (two minima
 * closer than about one sample interval can merge where nothing certifies the scan) are in
 * docs/curves.md, "The engine"; the certification is in curve_cert.c. Interface:
 * curve_scan.h. */
#include <math.h>

#include "base/point_circle.h"
#include "curve_scan.h"

/* ---- collector ---- */

void cdist__cs_coll_init(cdist__cs_coll *k, double scale)
{
    cdist__best_init(&k->b, scale);
    k->eq_d2 = INFINITY;
    k->flat_ties = 0;
}

void cdist__cs_coll_offer(cdist__cs_coll *k, double d2, vec3 p0, vec3 p1, double a0, double a1, int eq)
{
    cdist__best_offer(&k->b, d2, p0, p1, a0, a1);
    if (eq && d2 < k->eq_d2) k->eq_d2 = d2;
}

static void coll_finish(cdist__cs_coll *k)
{
    cdist__best *b = &k->b;
    if (b->n == 0) return;
    double d0 = sqrt(b->c[0].d2);
    /* A candidate with infinitely many closest pairs (a point on the circle's axis, ...). */
    if (k->eq_d2 < INFINITY && sqrt(k->eq_d2) - d0 <= cdist__best_tie_tol(&k->b)) b->equidistant = 1;
    /* On a scan of a constant function (coaxial or concentric arcs...), three distinct pairs at
     * the same distance mean the continuum. (Not in general: a curve may cross a circle at
     * three isolated points.) */
    if (k->flat_ties && b->n >= 3 && sqrt(b->c[2].d2) - d0 <= cdist__best_tie_tol(&k->b)) b->equidistant = 1;
}

cdist_status cdist__cs_coll_result(cdist__cs_coll *k, double up, vec3 origin, cdist_result *r)
{
    coll_finish(k);
    if (k->b.n == 0) {
        r->distance = NAN; /* no candidate: cdist__leave reports an internal failure */
        return CDIST_OK;
    }
    cdist__best_to_result(&k->b, v3(0, 0, 0), 0, r);
    cdist__result_finish(r, r->num_pairs);
    /* The distance from the scaled one (its square may underflow when the distance is below
     * 1e-154: sqr_distance is then 0 or subnormal, the distance is still exact). */
    r->distance *= up;
    r->sqr_distance = (r->sqr_distance * up) * up;
    for (int i = 0; i < r->num_pairs; i++)
        for (int j = 0; j < 2; j++) r->pairs[i].point[j] = v_axpy(origin, up, r->pairs[i].point[j]);
    return CDIST_OK;
}

void cdist__cs_offer_point(cdist__cs_coll *k, vec3 p, double t, const cdist__circle *c, int disk, int swap)
{
    cdist__best tmp;
    cdist__best_init(&tmp, k->b.scale);
    vec3 rel = v_sub(p, c->c);
    if (disk) cdist__point_disk_core(rel, c, &tmp, 0);
    else cdist__point_circle_core(rel, c, &tmp, 0);
    if (tmp.n == 0) return;
    const cdist__cand *x = &tmp.c[0];
    vec3 kp = v_add(x->p[1], c->c);
    int eq = cdist__best_is_equidistant(&tmp) || (!disk && cdist__cs_near_axis(k, rel, c));
    if (swap) cdist__cs_coll_offer(k, x->d2, kp, p, x->param[1], t, eq);
    else cdist__cs_coll_offer(k, x->d2, p, kp, t, x->param[1], eq);
}

int cdist__cs_near_axis(const cdist__cs_coll *k, vec3 rel, const cdist__circle *c)
{
    /* Within this distance of the axis the distance to the circle's points varies by less
     * than the tie tolerance: the closest pairs form a continuum up to rounding. */
    return c->r > 0.0 && cdist__point_circle(c->n, rel, c->r).rho <= CD_CURVE_AXIS_ULPS * DBL_EPSILON * k->b.scale;
}

/* ---- the objective ---- */

typedef struct sample {
    vec3 p;     /* position (the scan's frame) */
    double g;   /* F'/2 (or D'/2) */
    double f;   /* F (or D) */
    double h;     /* height over the circle's plane */
    double rho;   /* distance from the axis */
    double tol;   /* rounding level of g */
    double speed; /* |P'| (1-norm) */
} sample;

/* The query's budget of evaluations is spent (out of line: the hot path is one decrement). */
static __attribute__((noinline, cold)) cdist_status budget_spent(const cdist__cs_scan *s)
{
    return cdist__fail(s->q, CDIST_ERR_COST_LIMIT, "curve: the query needs more than its %ld evaluations", s->evals_max);
}

/* count evaluations more of the query's budget (s->evals_left); CDIST_ERR_COST_LIMIT when spent. */
static inline cdist_status spend(const cdist__cs_scan *s, long count)
{
    if (s->evals_left && (*s->evals_left -= count) < 0) return budget_spent(s);
    return CDIST_OK;
}

/* The sample at t, not charged to the budget (the scan charges its samples at once). */
static cdist_status eval_uncharged(const cdist__cs_scan *s, double t, sample *o)
{
    vec3 P, D;
    cdist_status st = s->ev(s->q, s->ctx, t, &P, &D);
    if (st) return st;
    /* Plain arithmetic (no fma calls: this is the inner loop); g only needs its sign right
     * away from its rounding level `tol`, and every offered candidate is re-evaluated by the
     * accurate point-circle/disk cores. */
    const cdist__circle *c = s->c;
    vec3 n = c->n;
    vec3 rel = v_sub(P, c->c);
    double h = n.x * rel.x + n.y * rel.y + n.z * rel.z;
    double hd = n.x * D.x + n.y * D.y + n.z * D.z;
    vec3 w = v_cross(n, rel), wd = v_cross(n, D);
    double rho = sqrt(w.x * w.x + w.y * w.y + w.z * w.z);
    double wwd = w.x * wd.x + w.y * wd.y + w.z * wd.z;
    double dr = rho - c->r;
    if (s->disk) {
        double o2 = dr > 0.0 ? dr : 0.0;
        o->g = h * hd + (o2 > 0.0 ? o2 * (wwd / rho) : 0.0);
        o->f = o2 * o2 + h * h;
    } else {
        o->g = h * hd + (rho > 0.0 ? dr * (wwd / rho) : 0.0);
        o->f = dr * dr + h * h;
    }
    o->p = P;
    o->h = h;
    o->rho = rho;
    double rn = fabs(rel.x) + fabs(rel.y) + fabs(rel.z), dn = fabs(D.x) + fabs(D.y) + fabs(D.z);
    o->tol = CD_CURVE_G_ULPS * DBL_EPSILON * (rn + c->r + s->frame_mag) * dn;
    o->speed = dn;
    return CDIST_OK;
}

/* The sample at t, charged to the budget. */
static inline cdist_status eval(const cdist__cs_scan *s, double t, sample *o)
{
    cdist_status st = spend(s, 1);
    return st ? st : eval_uncharged(s, t, o);
}

/* Position and F (or D) alone, the same arithmetic as eval. */
cdist_status cdist__cs_eval_point(const cdist__cs_scan *s, double t, vec3 *p, double *f)
{
    if (!s->pos) {
        sample x;
        cdist_status st = eval(s, t, &x);
        *p = x.p;
        *f = x.f;
        return st;
    }
    cdist_status st = spend(s, 1);
    if (st) return st;
    vec3 P = s->pos(s->ctx, t);
    const cdist__circle *c = s->c;
    vec3 n = c->n;
    vec3 rel = v_sub(P, c->c);
    double h = n.x * rel.x + n.y * rel.y + n.z * rel.z;
    vec3 w = v_cross(n, rel);
    double rho = sqrt(w.x * w.x + w.y * w.y + w.z * w.z);
    double dr = rho - c->r;
    if (s->disk) {
        double o2 = dr > 0.0 ? dr : 0.0;
        *f = o2 * o2 + h * h;
    } else {
        *f = dr * dr + h * h;
    }
    *p = P;
    return CDIST_OK;
}

static void offer_sample(const cdist__cs_scan *s, double t, const sample *x)
{
    if (s->cand) s->cand(s, t, x->p);
    else cdist__cs_offer_point(s->k, x->p, t, s->c, s->disk, 0);
}

static cdist_status offer_at(const cdist__cs_scan *s, double t)
{
    sample x;
    cdist_status st = eval(s, t, &x);
    if (st) return st;
    offer_sample(s, t, &x);
    return CDIST_OK;
}

/* ---- the scan's functions for the root and minimum module (src/base/roots.h) ---- */

enum { CS_F_G, CS_F_H, CS_F_RIM, CS_F_RHO, CS_F_DIP };

/* Context of one solve: which function of the sample, the sign for the dip search, and the
 * status of a failed evaluation (a user callback's error: the solver then gets NaN and stops). */
typedef struct cdist__cs_fn_ctx {
    const cdist__cs_scan *s;
    int what;
    double sg;
    cdist_status st;
} cdist__cs_fn_ctx;

static double cdist__cs_fn(const void *ctx, double t)
{
    cdist__cs_fn_ctx *c = (cdist__cs_fn_ctx *)ctx; /* the status is recorded here (roots.h convention) */
    sample x;
    if (c->st) return NAN;
    if ((c->st = eval(c->s, t, &x))) return NAN;
    switch (c->what) {
    case CS_F_G: return x.g;
    case CS_F_H: return x.h;
    case CS_F_RIM: return x.rho - c->s->c->r;
    case CS_F_RHO: return x.rho;
    default: return c->sg * x.g;
    }
}

/* Bracket resolution of the scan's solvers: the resolution of t plus a fraction of an ulp of
 * the scanned span (CD_CURVE_SPAN_ULPS). */
static double cdist__cs_abs_tol(const cdist__cs_scan *s) { return CD_CURVE_SPAN_ULPS * DBL_EPSILON * s->span; }

/* The root of the function `what` bracketed by [a, b] (fa, fb of opposite signs), offered. */
static cdist_status root_offer(const cdist__cs_scan *s, int what, double a, double fa, double b, double fb)
{
    cdist__cs_fn_ctx c = {s, what, 1.0, CDIST_OK};
    double t = cdist__root_brent(cdist__cs_fn, &c, a, fa, b, fb, CD_ROOT_REL_ULPS * DBL_EPSILON, cdist__cs_abs_tol(s), CD_CURVE_ROOT_MAX_ITER,
                             NULL);
    if (c.st) return c.st;
    if (t != t) return CDIST_OK;
    return offer_at(s, t);
}

/* Refine the minimum of F bracketed by g(a) < 0 < g(b) and offer it. */
static cdist_status refine_offer(const cdist__cs_scan *s, double a, double ga, double b, double gb)
{
    return root_offer(s, CS_F_G, a, ga, b, gb);
}

/* g keeps the sign sg at a and b; look for an extremum of g in between that crosses zero
 * (golden section on sg * g) and refine the minimum of F it brackets. */
static cdist_status dip_search(const cdist__cs_scan *s, double a, double b, double sg)
{
    cdist__cs_fn_ctx c = {s, CS_F_DIP, sg, CDIST_OK};
    double vm, tol = CD_CURVE_GOLDEN_ULPS * DBL_EPSILON * (fabs(a) + fabs(b)) + cdist__cs_abs_tol(s);
    double tm = cdist__min_golden(cdist__cs_fn, &c, a, b, tol, CD_CURVE_GOLDEN_MAX_ITER, &vm);
    if (c.st) return c.st;
    if (!(vm < 0.0)) return CDIST_OK;
    /* g > 0 dips below: the minimum of F is right of tm; g < 0 bumps above: left. */
    cdist__cs_fn_ctx e = {s, CS_F_G, 1.0, CDIST_OK};
    if (sg > 0) {
        double gb = cdist__cs_fn(&e, b);
        return e.st ? e.st : refine_offer(s, tm, sg * vm, b, gb);
    }
    double ga = cdist__cs_fn(&e, a);
    return e.st ? e.st : refine_offer(s, a, ga, tm, sg * vm);
}

/* The curve's closest approach to the circle's axis in [a, b] (golden section on rho), offered:
 * where the curve crosses the axis F has a kink, and in a flat configuration the kink rounded by
 * a near miss is a dip as narrow as the miss distance, invisible to the samples. */
static cdist_status axis_offer(const cdist__cs_scan *s, double a, double b)
{
    cdist__cs_fn_ctx c = {s, CS_F_RHO, 1.0, CDIST_OK};
    double tol = CD_CURVE_GOLDEN_ULPS / 2.0 * DBL_EPSILON * (fabs(a) + fabs(b)) + cdist__cs_abs_tol(s);
    double t = cdist__min_golden(cdist__cs_fn, &c, a, b, tol, 2 * CD_CURVE_GOLDEN_MAX_ITER, NULL);
    if (c.st) return c.st;
    if (t != t) return CDIST_OK;
    return offer_at(s, t);
}

cdist_status cdist__cs_scan_run(cdist__cs_scan *s, double t0, double t1, int n)
{
    cdist_query *q = s->q;
    cdist_status st;
    if (!(t0 < t1)) return offer_at(s, t0);
    if (n > q->curve_samples) n = q->curve_samples;
    double *G = q->scratch, *Fv = G + (n + 1), *R = Fv + (n + 1), *T = R + (n + 1);
    vec3 *Pv = (vec3 *)(T + (n + 1)); /* three doubles per sample */
    s->span = t1 - t0;
    if ((st = spend(s, n + 1))) return st; /* the samples */
    double ext = 0.0, h_prev = 0.0;
    for (int i = 0; i <= n; i++) {
        sample x;
        if ((st = eval_uncharged(s, cdist__cs_t_at(t0, t1, i, n), &x))) return st;
        /* Disk: every plane crossing, wherever it is (including the end intervals), located on
         * h itself. Where the crossing is inside the disk the distance is 0, a minimum that
         * g = h h' shows only at the rounding level of g when the curve lies nearly flat (h'
         * tiny), so the g brackets cannot be trusted to see it. */
        if (s->disk) {
            if (x.h == 0.0) offer_sample(s, cdist__cs_t_at(t0, t1, i, n), &x);
            else if (i > 0 && (x.h > 0.0) != (h_prev > 0.0) && h_prev != 0.0 &&
                     (st = root_offer(s, CS_F_H, cdist__cs_t_at(t0, t1, i - 1, n), h_prev, cdist__cs_t_at(t0, t1, i, n), x.h)))
                return st;
            h_prev = x.h;
        }
        G[i] = x.g;
        Fv[i] = x.f;
        R[i] = x.rho - s->c->r;
        T[i] = x.tol;
        Pv[i] = x.p;
        ext = fmax(ext, v_dist(x.p, s->c->c));
    }
    if (s->update_scale) s->k->b.scale = fmax(s->k->b.scale, ext);
    if ((st = offer_at(s, t0)) || (st = offer_at(s, t1))) return st;
    /* R (rho - r) at the axis: rho within CD_CURVE_AXIS_ULPS of the scale. */
    double axis_r = CD_CURVE_AXIS_ULPS * DBL_EPSILON * s->k->b.scale - s->c->r;
    for (int i = 0; i <= n; i++) {
        double t = cdist__cs_t_at(t0, t1, i, n);
        int zero = fabs(G[i]) <= T[i];
        if (zero && i > 0 && i < n && (st = offer_at(s, t))) return st;
        if (i < n) {
            int zr = fabs(G[i + 1]) <= T[i + 1];
            /* Both ends at g's rounding level: refine only when F itself varies beyond its own
             * rounding between them (a shallow minimum near the target, e.g. a curve in a disk's
             * plane just outside the rim); on a flat function (F constant up to rounding) the
             * sign changes are noise and the samples were offered above. */
            double fmax_i = fmax(Fv[i], Fv[i + 1]);
            int varies = fabs(Fv[i] - Fv[i + 1]) >
                         2.0 * CD_CURVE_G_ULPS * DBL_EPSILON * (s->k->b.scale + s->frame_mag) * sqrt(fmax_i);
            if (G[i] < 0 && G[i + 1] > 0 && (!(zero && zr) || varies)) {
                if ((st = refine_offer(s, t, G[i], cdist__cs_t_at(t0, t1, i + 1, n), G[i + 1]))) return st;
            }
            /* the rim's partition point: the sign change of rho - r */
            if (s->disk && ((R[i] > 0) != (R[i + 1] > 0))) {
                if ((st = root_offer(s, CS_F_RIM, t, R[i], cdist__cs_t_at(t0, t1, i + 1, n), R[i + 1]))) return st;
            }
        }
        if (zero) continue;
        /* A dip of g towards zero between samples of one sign. */
        double sg = G[i] > 0 ? 1.0 : -1.0;
        if (i > 0 && i < n) {
            if (sg * G[i - 1] > 0 && sg * G[i + 1] > 0 && fabs(G[i]) <= fabs(G[i - 1]) &&
                fabs(G[i]) <= fabs(G[i + 1]) && fabs(G[i - 1]) > T[i - 1] && fabs(G[i + 1]) > T[i + 1]) {
                if ((st = dip_search(s, cdist__cs_t_at(t0, t1, i - 1, n), cdist__cs_t_at(t0, t1, i + 1, n), sg))) return st;
            }
        } else {
            int j = i == 0 ? 1 : n - 1;
            if (sg * G[j] > 0 && fabs(G[i]) <= fabs(G[j]) && fabs(G[j]) > T[j]) {
                double a = cdist__cs_t_at(t0, t1, i == 0 ? 0 : n - 1, n), b = cdist__cs_t_at(t0, t1, i == 0 ? 1 : n, n);
                if ((st = dip_search(s, a, b, sg))) return st;
            }
        }
        /* A sampled closest approach to the axis that may reach it between samples (not where
         * the curve runs along the axis, on it at three samples: F is smooth there). */
        if (!s->disk && s->c->r > 0.0 && i > 0 && i < n && R[i] <= R[i - 1] && R[i] <= R[i + 1] &&
            !(R[i - 1] <= axis_r && R[i + 1] <= axis_r)) {
            sample x;
            if ((st = eval(s, t, &x))) return st;
            if (x.rho <= 2.0 * x.speed * (s->span / n) &&
                (st = axis_offer(s, cdist__cs_t_at(t0, t1, i - 1, n), cdist__cs_t_at(t0, t1, i + 1, n))))
                return st;
        }
        /* Safety net: a sampled local minimum of F. */
        if (i > 0 && i < n && Fv[i] <= Fv[i - 1] && Fv[i] <= Fv[i + 1] && (st = offer_at(s, t))) return st;
    }
    if (!s->certify || !s->k->b.n) return CDIST_OK; /* (both ends were offered: n >= 1) */
    return cdist__cs_certify_samples(s, t0, t1, n, Fv, Pv);
}

cdist_status cdist__cs_flat_check(cdist__cs_scan *s, double t0, double t1, double delta)
{
    cdist__cs_coll *k = s->k;
    if (k->b.n == 0 || k->b.equidistant || !(t0 < t1) || s->cand) return CDIST_OK;
    double t = k->b.c[0].param[0];
    if (!isfinite(t)) return CDIST_OK;
    double d0 = sqrt(k->b.c[0].d2);
    for (int side = -1; side <= 1; side += 2) {
        double u = t + side * delta;
        if (u < t0 || u > t1) continue;
        sample x;
        cdist_status st = eval(s, u, &x);
        if (st) return st;
        if (sqrt(x.f) - d0 <= cdist__best_tie_tol(&k->b)) {
            k->b.equidistant = 1;
            break;
        }
    }
    return CDIST_OK;
}

cdist_status cdist__cs_polish(cdist__cs_scan *s, double t, double lo, double hi)
{
    sample x, y;
    cdist_status st;
    s->span = hi - lo;
    if ((st = eval(s, t, &x))) return st;
    if (fabs(x.g) <= x.tol || !(lo < hi)) {
        offer_sample(s, t, &x);
        return CDIST_OK;
    }
    /* The minimum lies to the right where g < 0, to the left where g > 0: step outwards
     * (geometrically growing steps) until g changes sign, then refine the bracket. */
    double dir = x.g < 0 ? 1.0 : -1.0;
    double step = CD_CURVE_POLISH_STEP_REL * fmax(s->span, fabs(t));
    double prev = t;
    for (int it = 0; it < CD_CURVE_POLISH_STEPS; it++) {
        double u = prev + dir * step;
        int bound = 0;
        if (u >= hi) { u = hi; bound = 1; }
        if (u <= lo) { u = lo; bound = 1; }
        if ((st = eval(s, u, &y))) return st;
        if ((y.g > 0) != (x.g > 0) || y.g == 0.0) {
            if (dir > 0) return refine_offer(s, prev, x.g, u, y.g);
            return refine_offer(s, u, y.g, prev, x.g);
        }
        if (bound) {
            offer_sample(s, u, &y);
            return CDIST_OK;
        }
        prev = u;
        x = y;
        step *= 4.0;
    }
    return offer_at(s, t);
}

cdist_status cdist__cs_check_interval(cdist_query *q, double t0, double t1, const char *what)
{
    if (!isfinite(t0) || !isfinite(t1))
        return cdist__fail(q, CDIST_ERR_NOT_FINITE, "%s interval [%g, %g] is not finite", what, t0, t1);
    if (t0 > t1) return cdist__fail(q, CDIST_ERR_BAD_INTERVAL, "%s interval [%.17g, %.17g] is reversed", what, t0, t1);
    if (!isfinite(t1 - t0))
        return cdist__fail(q, CDIST_ERR_BAD_INTERVAL, "%s interval [%g, %g] is too long", what, t0, t1);
    return CDIST_OK;
}

/* Run a curve (evaluated in the frame whose origin is `origin`) against circle or disk cc
 * (its centre already relative to that frame) and write the result. bounds: |P'|, |P''|,
 * |n . P''| and |n x P''| over [t0, t1] (certified search), or NULL (sampling only). */
cdist_status cdist__cs_run_curve(cdist_query *q, cdist__cs_eval_fn ev, cdist__cs_pos_fn pos, const void *ctx, double t0, double t1,
                              const cdist__circle *cc, int disk, vec3 origin, double scale, double frame_mag,
                              double up, const double *bounds, cdist_result *r)
{
    cdist__cs_coll k;
    cdist__cs_coll_init(&k, scale);
    cdist__cs_scan s = {.q = q, .ev = ev, .ctx = ctx, .c = cc, .disk = disk, .k = &k, .update_scale = 1,
                        .frame_mag = frame_mag, .pos = pos};
    if (bounds) {
        s.certify = 1;
        s.speed_max = bounds[0];
        s.accel_max = bounds[1];
        s.accel_normal_max = bounds[2];
        s.accel_plane_max = bounds[3];
        s.speed_varies = 1;
    }
    cdist_status st = cdist__cs_scan_run(&s, t0, t1, q->curve_samples);
    if (!st) st = cdist__cs_flat_check(&s, t0, t1, (t1 - t0) / q->curve_samples);
    if (st) return st;
    return cdist__cs_coll_result(&k, up, origin, r);
}

/* ---- frames ---- */

cdist_status cdist__cs_zero_frame(cdist_query *q, vec3 n, const cdist_vec3 *zd, const char *what, vec3 *U, vec3 *V)
{
    vec3 z;
    cdist_status st = cdist__check_direction(q, zd, what, 0, &z, NULL);
    if (st) return st;
    vec3 w = v_cross(n, z);
    double sn = v_norm(w);
    /* U = (n x z) x n / |n x z| is z projected onto the plane; refuse an ill-defined one. */
    if (!(sn > CD_CURVE_PARALLEL_SIN))
        return cdist__fail(q, CDIST_ERR_ZERO_VECTOR, "%s is parallel to the normal/axis (sin %.3g)", what, sn);
    *U = v_scale(1.0 / sn, v_cross(w, n));
    *V = v_cross(n, *U);
    return CDIST_OK;
}
