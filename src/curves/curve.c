/* SPDX-License-Identifier: MIT */
/* Parametric curves, helices and cubic Bezier curves to circles and disks: the generic
 * root-bounding engine (distance-to-circles-3d §3, point-curve-circle-to-disk §3). The arc
 * queries (src/curves/arc.c) use the same engine through the small interface in src/curves/curve_scan.h.
 *
 * Curve to circle. With Delta(t) = P(t) - C, h = N.Delta, w = N x Delta, rho = |w|:
 *     F(t) = h^2 + (rho - r)^2                      (squared distance, closed-form point-circle)
 *     g(t) = F'(t) / 2 = h h' + (rho - r) (w.w') / rho
 * (this is the paper's Delta.Delta' - r (w.w')/rho with Delta.Delta' = h h' + w.w' regrouped, so
 * that near a minimum the two small factors h and rho - r multiply instead of cancelling). g is
 * undefined where the curve crosses the circle's axis (rho = 0); there F has a kink that is a
 * local maximum of -2 r rho (so never a minimum when r > 0), and g jumps from + to -: the
 * bracketing below treats it like a root, which merely adds a harmless candidate. When the
 * curve runs along the axis, w' = 0 as well and g = h h' is smooth (the paper's limit).
 *
 * Curve to disk. D(t) = h^2 + max(rho - r, 0)^2 is the squared distance from P(t) to the disk
 * (inside the cylinder rho <= r the distance is |h|, outside it is the rim distance). The two
 * pieces meet with equal value and equal derivative at rho = r (the rim term is quadratic in
 * rho - r), so D is C^1 and g = D'/2 = h h' + max(rho - r, 0) (w.w') / rho is continuous:
 * the paper's split into inside (z z' = 0) and outside (rim) subintervals is exactly the
 * sign-change search on this single function. The partition points rho = r are located too and
 * offered as candidates, as the paper asks.
 *
 * The engine (scan_run): sample g at n+1 equally spaced parameters (n = the handle's curve
 * sample count; values kept in the handle's scratch, no allocation), then
 *  - offer both endpoints;
 *  - every sample where |g| is below its rounding level is a critical point already: offer it;
 *  - every bracket with g < 0 on the left and g > 0 on the right holds a minimum of F: refine
 *    it by Brent's safeguarded inverse-interpolation/bisection on g to full precision, offer it;
 *  - where |g| has a local minimum over three samples of one sign, g may dip through zero and
 *    back between samples (two close critical points, a min-max pair): search the extremum of g
 *    over the two intervals by golden section; if it crosses zero, the bracket it makes is
 *    refined as above (same at the two ends, with the one interval there);
 *  - sampled local minima of F are offered as a last safety net (an upper bound within F'' h^2);
 *  - for the disk, sign changes of rho - r are bisected and offered (partition points), and
 *    every sign change of the height h between samples (end intervals included) is located on
 *    h itself and offered: a crossing inside the disk is a zero of D that g = h h' shows only
 *    at its rounding level when the curve lies nearly flat;
 *  - for the circle, the closest approaches to the axis that may reach it between samples are
 *    located (golden section on rho) and offered: the non-smooth points of F.
 * Limitation (documented in docs/curves.md): roots are bounded only up to the sample spacing:
 * two minima closer than about one sample interval can merge, and a minimum hidden in a pair of
 * critical points inside one interval is found only when the extremum search detects it.
 * cdist_query_set_curve_samples() trades speed for resolution. */
#include <math.h>

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

static double tie_tol(const cdist__cs_coll *k) { return CD_TIE_ULPS * DBL_EPSILON * k->b.scale; }

void cdist__cs_coll_finish(cdist__cs_coll *k)
{
    cdist__best *b = &k->b;
    if (b->n == 0) return;
    double d0 = sqrt(b->c[0].d2);
    /* A candidate with infinitely many closest pairs (a point on the circle's axis, ...). */
    if (k->eq_d2 < INFINITY && sqrt(k->eq_d2) - d0 <= tie_tol(k)) b->equidistant = 1;
    /* On a scan of a constant function (coaxial or concentric arcs...), three distinct pairs at
     * the same distance mean the continuum. (Not in general: a curve may cross a circle at
     * three isolated points.) */
    if (k->flat_ties && b->n >= 3 && sqrt(b->c[2].d2) - d0 <= tie_tol(k)) b->equidistant = 1;
}

void cdist__cs_coll_result(cdist__cs_coll *k, double up, vec3 origin, cdist_result *r)
{
    cdist__cs_coll_finish(k);
    if (k->b.n == 0) {
        r->distance = NAN; /* no candidate: cdist__leave reports an internal failure */
        return;
    }
    cdist__best_to_result(&k->b, v3(0, 0, 0), 0, r);
    cdist__result_finish(r, r->num_pairs);
    /* The distance from the scaled one (its square may underflow when the distance is below
     * 1e-154: sqr_distance is then 0 or subnormal, the distance is still exact). */
    r->distance *= up;
    r->sqr_distance = (r->sqr_distance * up) * up;
    for (int i = 0; i < r->num_pairs; i++)
        for (int j = 0; j < 2; j++) {
            cdist_vec3 *P = &r->pairs[i].point[j];
            vec3 w = v_axpy(origin, up, v3(P->x, P->y, P->z));
            P->x = w.x;
            P->y = w.y;
            P->z = w.z;
        }
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
    return c->r > 0.0 && v_norm(v_cross(c->n, rel)) <= CD_CURVE_AXIS_ULPS * DBL_EPSILON * k->b.scale;
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

/* Height over the circle's plane and in-plane coordinates (along the circle's u, v) of a point,
 * relative to the centre: the certification's component bounds (computed only there). */
static void plane_coords(const cdist__cs_scan *s, vec3 p, double *h, double *px, double *py)
{
    const cdist__circle *c = s->c;
    vec3 rel = v_sub(p, c->c);
    *h = c->n.x * rel.x + c->n.y * rel.y + c->n.z * rel.z;
    *px = c->u.x * rel.x + c->u.y * rel.y + c->u.z * rel.z;
    *py = c->v.x * rel.x + c->v.y * rel.y + c->v.z * rel.z;
}

static cdist_status eval(const cdist__cs_scan *s, double t, sample *o)
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

/* Position and F (or D) alone, the same arithmetic as eval. */
static cdist_status eval_point(const cdist__cs_scan *s, double t, vec3 *p, double *f)
{
    if (!s->pos) {
        sample x;
        cdist_status st = eval(s, t, &x);
        *p = x.p;
        *f = x.f;
        return st;
    }
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

/* The curve crosses the disk's plane between a and b (ha, hb of opposite signs): locate the
 * crossing on h itself and offer it. Where the crossing is inside the disk the distance is 0, a
 * minimum that g = h h' shows only at the rounding level of g when the curve lies nearly flat
 * (h' tiny), so the g brackets cannot be trusted to see it. */
static cdist_status crossing_offer(const cdist__cs_scan *s, double a, double ha, double b, double hb)
{
    return root_offer(s, CS_F_H, a, ha, b, hb);
}

/* Locate the sign change of rho - r between a and b and offer the partition point. */
static cdist_status partition_offer(const cdist__cs_scan *s, double a, double da, double b, double db)
{
    return root_offer(s, CS_F_RIM, a, da, b, db);
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

/* ---- certification ----
 * Every interval [a, b] of the samples is bounded below; an interval whose bound is below the
 * answer minus tau (the certification tolerance) is split at its midpoint, and a midpoint
 * below that level starts a descent (cdist__cs_polish) to its basin's minimum, offered. Bounds
 * (d the distance to the target, f = d^2 sampled at a and b, w = b - a, S >= |P'|,
 * K >= |P''|, Kn >= |n . P''| over the interval, mu the rounding of a sampled distance):
 *  - Lipschitz: d is S-Lipschitz (the distance to a set is 1-Lipschitz in the point), so
 *    d >= (d(a) + d(b) - S w) / 2;
 *  - second order: f(t) = min over target points Y of |P(t) - Y|^2, and each of these has second
 *    derivative 2 |P'|^2 + 2 (P - Y).P'' <= 2 S^2 + 2 |P - Y| K; where d(t) < best, the Y that
 *    is closest at t is within best + S w of every P(s), so with M = 2 (S^2 + (best + S w) K)
 *    f lies above its chord minus M s (w - s) / 2 (s = t - a; a function whose second
 *    derivative is at most M): its minimum over [a, b] (chord_excluded) at least (best - tau)^2
 *    means no t of [a, b] has d(t) < best - tau;
 *  - components: d^2 = h^2 + (rho - r)^2 (circle), h^2 + max(rho - r, 0)^2 (disk). Where h keeps
 *    its sign, |h| >= min(|h(a)|, |h(b)|) - Kn w^2 / 8 (the chord argument on h, whose second
 *    derivative is n . P'', |n . P''| <= Kn); the in-plane offset q(t) (|q| = rho) stays within
 *    Kp w^2 / 8 of its chord (|q''| <= Kp), so rho lies between the chord's distance from the
 *    centre minus that and max(rho(a), rho(b)) plus that (the norm is convex along the chord).
 *    Second order in w whatever the distance (a near touch of the circle, a curve lying flat
 *    over a disk, where the distance is constant, exactly);
 *  - the curve's own bound s->lb (the helix's cylinder and slab bound).
 * The answer is then within tau of the global minimum (plus the rounding of the final
 * candidate). Intervals at the resolution of t are not split further. */
typedef struct cert_node {
    double a, b, da, db, ha, hb; /* da, db: the sampled distances at a and b */
    double xa, ya, xb, yb; /* in-plane coordinates at a and b */
} cert_node;

static double cert_tol(const cdist__cs_scan *s) { return CD_CURVE_CERT_ULPS * DBL_EPSILON * s->k->b.scale; }

/* Rounding of a sampled distance (positions, h, rho and F in plain arithmetic). */
static double cert_mu(const cdist__cs_scan *s)
{
    return CD_CURVE_CERT_EVAL_ULPS * DBL_EPSILON * (2.0 * s->k->b.scale + s->c->r + s->frame_mag);
}

static inline double min2(double a, double b) { return a < b ? a : b; }
static inline double max2(double a, double b) { return a > b ? a : b; }

/* The first- and second-order bounds of the distance over an interval of width w whose end
 * distances are at least da, db (rounding already subtracted) and whose end points are pab
 * apart (as computed; negative: not used): 1 when no point of it is below lim (> 0). The speed bound is the
 * curve's, or the local one: P' differs from its mean (P(b) - P(a)) / w by at most K w / 2
 * (|P''| <= K), the positions' rounding (mu each) included. */
static int chord_excluded(const cdist__cs_scan *s, double w, double da, double db, double pab, double mu, double best,
                          double lim)
{
    double K = s->accel_max, S = s->speed_max;
    if (pab >= 0.0) S = min2(S, ((pab + 4.0 * mu) / w + 0.5 * K * w) * (1.0 + 0x1p-40));
    if (0.5 * (da + db - S * w) >= lim) return 1;
    double dl = min2(da, db), dh = max2(da, db);
    if (!(dl > 0.0)) return 0;
    /* The chord from the lower end (fl) to the higher one (fh) minus M s (w - s) / 2, s from the
     * lower end: its minimum is at s = w/2 - (fh - fl) / (M w), clipped to [0, w/2]. */
    double fl = dl * dl, fh = dh * dh, M = 2.0 * (S * S + (best + S * w) * K), mw = M * w;
    double sm = mw > 0.0 ? 0.5 * w - (fh - fl) / mw : 0.5 * w;
    return (sm > 0.0 ? fl - 0.5 * M * sm * sm : fl) >= lim * lim;
}

/* The interval cannot hold a distance below lim (> 0); mu: cert_mu(s). */
static int cert_excluded(const cdist__cs_scan *s, const cert_node *nd, double best, double lim, double mu)
{
    double w = nd->b - nd->a, lim2 = lim * lim;
    double eh = nd->hb - nd->ha, ex = nd->xb - nd->xa, ey = nd->yb - nd->ya;
    double pab = s->speed_varies ? sqrt(eh * eh + ex * ex + ey * ey) : -1.0;
    if (chord_excluded(s, w, nd->da - mu, nd->db - mu, pab, mu, best, lim)) return 1;
    double hl = 0.0;
    if ((nd->ha > 0.0 && nd->hb > 0.0) || (nd->ha < 0.0 && nd->hb < 0.0))
        hl = max2(0.0, min2(fabs(nd->ha), fabs(nd->hb)) - mu - s->accel_normal_max * w * w * 0.125);
    /* (plain squares: the scan's frame is scaled to L ~ 1) */
    double dx = nd->xb - nd->xa, dy = nd->yb - nd->ya, ll = dx * dx + dy * dy;
    double u = ll > 0.0 ? -(nd->xa * dx + nd->ya * dy) / ll : 0.0;
    u = u < 0.0 ? 0.0 : (u > 1.0 ? 1.0 : u);
    double sag = s->accel_plane_max * w * w * 0.125 + 2.0 * mu, r = s->c->r;
    double cx = nd->xa + u * dx, cy = nd->ya + u * dy;
    double rl = max2(0.0, sqrt(cx * cx + cy * cy) - sag - r);
    if (!s->disk) {
        double ra2 = nd->xa * nd->xa + nd->ya * nd->ya, rb2 = nd->xb * nd->xb + nd->yb * nd->yb;
        rl = max2(rl, r - sqrt(max2(ra2, rb2)) - sag);
    }
    if (hl * hl + rl * rl >= lim2) return 1;
    return s->lb && s->lb(s, nd->a, nd->b) >= lim;
}

static cdist_status certify(cdist__cs_scan *s, cert_node nd)
{
    cert_node stack[CD_CURVE_CERT_DEPTH];
    int top = 0;
    cdist_status st;
    double mu = cert_mu(s);
    for (;;) {
        double best = s->k->b.n ? sqrt(s->k->b.c[0].d2) : INFINITY;
        double lim = best - cert_tol(s);
        double m = 0.5 * (nd.a + nd.b);
        if (lim > 0.0 && !cert_excluded(s, &nd, best, lim, mu) && m > nd.a && m < nd.b) {
            if (++s->cert_nodes > CD_CURVE_CERT_MAX_NODES)
                return cdist__fail(s->q, CDIST_ERR_COST_LIMIT,
                                   "curve: certifying the minimum needs more than %ld bound evaluations",
                                   (long)CD_CURVE_CERT_MAX_NODES);
            vec3 pm;
            double fm;
            if ((st = eval_point(s, m, &pm, &fm))) return st;
            if (fm < lim * lim) {
                /* A point below the answer: descend to its basin's minimum. */
                double span = s->span;
                st = cdist__cs_polish(s, m, nd.a, nd.b);
                s->span = span;
                if (st) return st;
            }
            double dm = sqrt(fm), hm, px, py;
            plane_coords(s, pm, &hm, &px, &py);
            cert_node right = {m, nd.b, dm, nd.db, hm, nd.hb, px, py, nd.xb, nd.yb};
            nd.b = m;
            nd.db = dm;
            nd.hb = hm;
            nd.xb = px;
            nd.yb = py;
            if (top < CD_CURVE_CERT_DEPTH) {
                stack[top++] = right;
            } else if ((st = certify(s, right))) {
                return st;
            }
            continue;
        }
        if (top == 0) return CDIST_OK;
        nd = stack[--top];
    }
}

static double t_at(double t0, double t1, int i, int n)
{
    if (i == n) return t1;
    return t0 + (t1 - t0) * ((double)i / n);
}

/* Certify the sample intervals of a scan (F: d^2, P: positions per sample). Lipschitz screen
 * first (the bound of cert_excluded, for the longest interval of the scan: t_at's widths differ
 * by rounding only, covered by the 1 + 2^-40 factor), on the squares where an end is below half
 * of it (each low sample opens its two intervals, each interval looked at once); then the chord
 * bound; then, where the curve has its own bound, that bound over the whole range once and over
 * the block of CD_CURVE_CERT_BLOCK intervals holding the interval (a bound that is tight over
 * long ranges, as in coaxial and concentric configurations, settles a block in one call); the
 * component bounds (heights and in-plane coordinates from the positions) only where all fail. */
static cdist_status certify_samples(cdist__cs_scan *s, double t0, double t1, int n, const double *F, const vec3 *P)
{
    double best = sqrt(s->k->b.c[0].d2);
    double lim = best - cert_tol(s), mu = cert_mu(s);
    double screen = 2.0 * (lim + mu) + s->speed_max * ((t1 - t0) / n) * (1.0 + 0x1p-40);
    double half2 = screen > 0.0 ? 0.25 * screen * screen * (1.0 + 0x1p-40) : 0.0;
    int whole = 0;      /* the curve's bound was tried over the whole range */
    int block_end = -1; /* intervals below this index are settled by their block's bound */
    int block_tried = -1; /* start of the last block whose bound was tried */
    for (int e = 0; e <= n; e++) {
        if (F[e] >= half2) continue;
        for (int m = (e > 0 && F[e - 1] >= half2) ? e - 1 : e; m <= e && m < n; m++) {
            if (m < block_end) continue;
            double da = sqrt(F[m]), db = sqrt(F[m + 1]);
            if (da + db >= screen) continue;
            double a = t_at(t0, t1, m, n), b = t_at(t0, t1, m + 1, n);
            if (!(lim > 0.0)) return CDIST_OK;
            double pab = s->speed_varies ? v_dist(P[m], P[m + 1]) : -1.0;
            if (chord_excluded(s, b - a, da - mu, db - mu, pab, mu, best, lim)) continue;
            if (s->lb && n > 1) {
                if (!whole) {
                    whole = 1;
                    if (s->lb(s, t0, t1) >= lim) return CDIST_OK;
                }
                int b0 = m - m % CD_CURVE_CERT_BLOCK, b1 = b0 + CD_CURVE_CERT_BLOCK < n ? b0 + CD_CURVE_CERT_BLOCK : n;
                if (b0 != block_tried && b1 - b0 > 1) {
                    block_tried = b0;
                    if (s->lb(s, t_at(t0, t1, b0, n), t_at(t0, t1, b1, n)) >= lim) {
                        block_end = b1;
                        continue;
                    }
                }
            }
            cert_node nd;
            nd.a = a;
            nd.b = b;
            nd.da = da;
            nd.db = db;
            plane_coords(s, P[m], &nd.ha, &nd.xa, &nd.ya);
            plane_coords(s, P[m + 1], &nd.hb, &nd.xb, &nd.yb);
            cdist_status st = certify(s, nd);
            if (st) return st;
            best = sqrt(s->k->b.c[0].d2);
            lim = best - cert_tol(s);
        }
    }
    return CDIST_OK;
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
    double ext = 0.0, h_prev = 0.0;
    for (int i = 0; i <= n; i++) {
        sample x;
        if ((st = eval(s, t_at(t0, t1, i, n), &x))) return st;
        /* Disk: every plane crossing, wherever it is (including the end intervals). */
        if (s->disk) {
            if (x.h == 0.0) offer_sample(s, t_at(t0, t1, i, n), &x);
            else if (i > 0 && (x.h > 0.0) != (h_prev > 0.0) && h_prev != 0.0 &&
                     (st = crossing_offer(s, t_at(t0, t1, i - 1, n), h_prev, t_at(t0, t1, i, n), x.h)))
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
    for (int i = 0; i <= n; i++) {
        double t = t_at(t0, t1, i, n);
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
                if ((st = refine_offer(s, t, G[i], t_at(t0, t1, i + 1, n), G[i + 1]))) return st;
            }
            if (s->disk && ((R[i] > 0) != (R[i + 1] > 0))) {
                if ((st = partition_offer(s, t, R[i], t_at(t0, t1, i + 1, n), R[i + 1]))) return st;
            }
        }
        if (zero) continue;
        /* A dip of g towards zero between samples of one sign. */
        double sg = G[i] > 0 ? 1.0 : -1.0;
        if (i > 0 && i < n) {
            if (sg * G[i - 1] > 0 && sg * G[i + 1] > 0 && fabs(G[i]) <= fabs(G[i - 1]) &&
                fabs(G[i]) <= fabs(G[i + 1]) && fabs(G[i - 1]) > T[i - 1] && fabs(G[i + 1]) > T[i + 1]) {
                if ((st = dip_search(s, t_at(t0, t1, i - 1, n), t_at(t0, t1, i + 1, n), sg))) return st;
            }
        } else {
            int j = i == 0 ? 1 : n - 1;
            if (sg * G[j] > 0 && fabs(G[i]) <= fabs(G[j]) && fabs(G[j]) > T[j]) {
                double a = t_at(t0, t1, i == 0 ? 0 : n - 1, n), b = t_at(t0, t1, i == 0 ? 1 : n, n);
                if ((st = dip_search(s, a, b, sg))) return st;
            }
        }
        /* A sampled closest approach to the axis that may reach it between samples. */
        if (!s->disk && s->c->r > 0.0 && i > 0 && i < n && R[i] <= R[i - 1] && R[i] <= R[i + 1]) {
            sample x;
            if ((st = eval(s, t, &x))) return st;
            if (x.rho <= 2.0 * x.speed * (s->span / n) &&
                (st = axis_offer(s, t_at(t0, t1, i - 1, n), t_at(t0, t1, i + 1, n))))
                return st;
        }
        /* Safety net: a sampled local minimum of F. */
        if (i > 0 && i < n && Fv[i] <= Fv[i - 1] && Fv[i] <= Fv[i + 1] && (st = offer_at(s, t))) return st;
    }
    if (!s->certify || !s->k->b.n) return CDIST_OK; /* (both ends were offered: n >= 1) */
    return certify_samples(s, t0, t1, n, Fv, Pv);
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
        if (sqrt(x.f) - d0 <= tie_tol(k)) {
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

/* ---- user curves ---- */

typedef struct user_curve {
    cdist_curve_fn f;
    void *user;
    vec3 origin;
    double down; /* the power-of-two scale of the query's frame */
} user_curve;

static cdist_status user_eval(cdist_query *q, const void *ctx, double t, vec3 *p, vec3 *dp)
{
    const user_curve *u = ctx;
    cdist_vec3 P = {NAN, NAN, NAN}, D = {NAN, NAN, NAN};
    int rc = u->f(u->user, t, &P, &D);
    if (rc) return cdist__fail(q, CDIST_ERR_CALLBACK_FAILED, "curve callback returned %d at t = %.17g", rc, t);
    if (!v_isfinite(P) || !v_isfinite(D))
        return cdist__fail(q, CDIST_ERR_CALLBACK_NOT_FINITE,
                       "curve callback gave a non-finite %s at t = %.17g", v_isfinite(P) ? "derivative" : "position",
                       t);
    if (v_maxabs(P) > CD_MAX_ABS || v_maxabs(D) > CD_MAX_ABS)
        return cdist__fail(q, CDIST_ERR_OUT_OF_RANGE, "curve callback gave a value beyond 1e150 at t = %.17g", t);
    *p = v_scale(u->down, v_sub(P, u->origin));
    *dp = v_scale(u->down, D);
    return CDIST_OK;
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
static cdist_status run_curve(cdist_query *q, cdist__cs_eval_fn ev, cdist__cs_pos_fn pos, const void *ctx, double t0, double t1,
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
    cdist__cs_coll_result(&k, up, origin, r);
    return CDIST_OK;
}

static cdist_status curve_query(cdist_query *q, cdist_curve_fn f, void *user, double t0, double t1,
                                const cdist_circle *c, cdist_result *r, int disk)
{
    cdist_status st;
    if (!f) return cdist__fail(q, CDIST_ERR_NULL_ARGUMENT, "curve callback is NULL");
    cdist__circle cc;
    if ((st = cdist__check_circle(q, c, disk ? "disk" : "circle", &cc))) return st;
    if ((st = cdist__cs_check_interval(q, t0, t1, "curve"))) return st;
    user_curve u = {f, user, cc.c, 1.0};
    vec3 origin = cc.c;
    cc.c = v3(0, 0, 0);
    /* The scale of the frame from a few positions (the callback's positions are only known as
     * it is called): squares stay free of overflow even where the curve reaches 2^400 times
     * farther between these positions, and of underflow for tiny curves. */
    double L = cc.r;
    for (int i = 0; i <= CD_CURVE_SCALE_PROBES; i++) {
        vec3 P = v3(0, 0, 0), D; /* set by user_eval on success (gcc 12 cannot see it) */
        double t = i == CD_CURVE_SCALE_PROBES ? t1 : t0 + (t1 - t0) * ((double)i / CD_CURVE_SCALE_PROBES);
        if ((st = user_eval(q, &u, t, &P, &D))) return st;
        L = fmax(L, v_maxabs(P));
    }
    int e = cdist__scale_exponent(L);
    u.down = cdist__pow2(-e);
    cc.r *= u.down;
    /* The callback's positions are absolute: their rounding is relative to |origin| too. */
    return run_curve(q, user_eval, NULL, &u, t0, t1, &cc, disk, origin, cc.r, v_maxabs(origin) * u.down, cdist__pow2(e), NULL,
                     r);
}

cdist_status cdist_curve_circle(cdist_query *q, cdist_curve_fn f, void *user, double t0, double t1,
                                const cdist_circle *c, cdist_result *r)
{
    cdist_status st = cdist__enter(q, r);
    if (st) return st;
    return cdist__leave(q, r, curve_query(q, f, user, t0, t1, c, r, 0), CDIST_METHOD_ROBUST);
}

cdist_status cdist_curve_disk(cdist_query *q, cdist_curve_fn f, void *user, double t0, double t1,
                              const cdist_circle *d, cdist_result *r)
{
    cdist_status st = cdist__enter(q, r);
    if (st) return st;
    return cdist__leave(q, r, curve_query(q, f, user, t0, t1, d, r, 1), CDIST_METHOD_ROBUST);
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

/* ---- helix ---- */

typedef struct helix_x {
    vec3 c, n, u, v; /* c relative to the circle's centre */
    double r, rise;  /* rise = pitch / (2 pi) */
} helix_x;

static vec3 helix_pos(const void *ctx, double t)
{
    const helix_x *h = ctx;
    vec3 radial = v_axpy(v_scale(cos(t), h->u), sin(t), h->v);
    return v_axpy(v_axpy(h->c, h->r, radial), h->rise * t, h->n);
}

static cdist_status helix_eval(cdist_query *q, const void *ctx, double t, vec3 *p, vec3 *dp)
{
    (void)q;
    const helix_x *h = ctx;
    double sn = sin(t), cs = cos(t);
    vec3 radial = v_axpy(v_scale(cs, h->u), sn, h->v);
    vec3 tang = v_axpy(v_scale(-sn, h->u), cs, h->v);
    *p = v_axpy(v_axpy(h->c, h->r, radial), h->rise * t, h->n);
    *dp = v_axpy(v_scale(h->r, tang), h->rise, h->n);
    return CDIST_OK;
}


/* Lower bound of the distance between the circle or disk and the helix piece whose axis points
 * have axial coordinates (along hx->n, from the circle's centre) in [za, zb]: every piece point
 * X is at distance r from the axis, every target point Y has an axial coordinate in [zlo, zhi]
 * and a distance from the axis in [rlo, rhi], and |X - Y|^2 >= (axial gap)^2 + (radial gap)^2. */
typedef struct helix_bound {
    double zlo, zhi; /* axial range of the target */
    double rgap;     /* distance from the helix radius to the target's radial range */
} helix_bound;

/* Axial and radial ranges of a circle (or, filled, a disk) relative to an axis: for the circle
 * C + R (cos f u + sin f v) (C relative to a point of the axis, unit direction n), every point's
 * coordinate along n lies in [zlo, zhi] and its distance from the axis in [rlo, rhi], rounding
 * included. */
typedef struct circle_ranges {
    double zlo, zhi, rlo, rhi;
} circle_ranges;

static circle_ranges circle_axis_ranges(vec3 C, vec3 n, vec3 u, vec3 v, double R, int filled)
{
    circle_ranges g;
    double zc = v_dot(C, n), za = hypot(v_dot(u, n), v_dot(v, n));
    /* The offset from the axis: Y_perp = C_p + R (cos f u_p + sin f v_p), whose square is
     * a0 + a1 cos f + b1 sin f + a2 cos 2f + b2 sin 2f. */
    vec3 Cp = v_sub(C, v_scale(zc, n));
    vec3 up = v_sub(u, v_scale(v_dot(u, n), n)), vp = v_sub(v, v_scale(v_dot(v, n), n));
    double a0 = v_sqr(Cp) + 0.5 * R * R * (v_sqr(up) + v_sqr(vp));
    double m1 = 2.0 * R * hypot(v_dot(Cp, up), v_dot(Cp, vp));
    double m2 = R * R * hypot(0.5 * (v_sqr(up) - v_sqr(vp)), v_dot(up, vp));
    /* Rounding: the squares' range is widened by a few ulps of their magnitude (before the
     * square roots, which would amplify it near 0), the lengths by a few ulps of the problem's. */
    double mag = v_norm(C) + R;
    double sq = CD_CURVE_HELIX_BOUND_ULPS * DBL_EPSILON * mag * mag;
    double slack = CD_CURVE_HELIX_BOUND_ULPS * DBL_EPSILON * mag;
    g.rhi = sqrt(fmax(0.0, a0 + m1 + m2 + sq)) + slack;
    g.rlo = fmax(0.0, sqrt(fmax(0.0, a0 - m1 - m2 - sq)) - slack);
    if (filled) g.rlo = fmax(0.0, v_norm(Cp) - R - slack); /* the filled ellipse around C_p */
    g.zlo = zc - R * za - slack;
    g.zhi = zc + R * za + slack;
    return g;
}

/* zext: the helix's largest |axial coordinate| (rise times the largest |t|), whose rounding the
 * pieces' axial ranges carry. */
static helix_bound helix_bound_init(const helix_x *hx, const cdist__circle *c, int disk, double zext)
{
    helix_bound hb;
    /* The helix axis through the helix centre; the target relative to it. */
    circle_ranges g = circle_axis_ranges(v_scale(-1.0, hx->c), hx->n, c->u, c->v, c->r, disk);
    double slack = CD_CURVE_HELIX_BOUND_ULPS * DBL_EPSILON * (hx->r + zext);
    hb.zlo = g.zlo - slack;
    hb.zhi = g.zhi + slack;
    double rlo = fmax(0.0, g.rlo - slack), rhi = g.rhi + slack;
    hb.rgap = hx->r < rlo ? rlo - hx->r : (hx->r > rhi ? hx->r - rhi : 0.0);
    return hb;
}

static double helix_piece_lb(const helix_bound *hb, const helix_x *hx, double a, double b)
{
    double z0 = hx->rise * a, z1 = hx->rise * b;
    double za = min2(z0, z1), zb = max2(z0, z1);
    double gap = za > hb->zhi ? za - hb->zhi : (zb < hb->zlo ? hb->zlo - zb : 0.0);
    if (gap == 0.0 || hb->rgap == 0.0) return gap + hb->rgap; /* hypot's value, without its cost */
    return hypot(gap, hb->rgap);
}

typedef struct helix_lb_ctx {
    helix_bound hb;
    const helix_x *hx;
} helix_lb_ctx;

static double helix_lb(const cdist__cs_scan *s, double a, double b)
{
    const helix_lb_ctx *c = s->lb_ctx;
    return helix_piece_lb(&c->hb, c->hx, a, b);
}

/* Cost limit of one helix query (CD_CURVE_HELIX_MAX_SAMPLES samples over the pieces that cannot
 * be skipped: 4096 turns at the default 512 samples). Pieces are skipped when their lower bound
 * exceeds the distance found on the axially nearest piece, so only configurations where that
 * many turns are about equally close (a target threading a long tight coil) reach it; they get
 * CDIST_ERR_COST_LIMIT before the long scan.
 * After the nearest piece: the pieces whose bound does not exceed the distance found there are
 * all the pieces that may be scanned (the best only decreases); refuse when they cost too much. */
static cdist_status helix_cost_check(const cdist__cs_scan *s, const helix_x *hx, const helix_bound *hb, double t0,
                                     double plen, long pieces, long mid)
{
    double best = s->k->b.n ? sqrt(s->k->b.c[0].d2) : INFINITY;
    double margin = best - cert_tol(s);
    long limit = (long)(CD_CURVE_HELIX_MAX_SAMPLES / s->q->curve_samples), count = 1;
    for (long i = mid - 1; i >= 0 && count <= limit; i--, count++)
        if (helix_piece_lb(hb, hx, t0 + (double)i * plen, t0 + (double)(i + 1) * plen) >= margin) break;
    for (long i = mid + 1; i < pieces && count <= limit; i++, count++)
        if (helix_piece_lb(hb, hx, t0 + (double)i * plen, t0 + (double)(i + 1) * plen) >= margin) break;
    if (count > limit)
        return cdist__fail(s->q, CDIST_ERR_COST_LIMIT,
                       "helix: more than %ld turns are about equally close to the target (cost limit: %.0f "
                       "samples)",
                       limit, CD_CURVE_HELIX_MAX_SAMPLES);
    return CDIST_OK;
}

/* Scan the pieces [t0 + i plen, t0 + (i+1) plen] (the last ending at t1) in order of increasing
 * lower bound, from the piece nearest the target axially outwards (the bound is unimodal in i:
 * the axial gap shrinks, stays 0 while the pieces overlap the target's range, then grows),
 * stopping on each side at the first piece that neither the certification nor a possible tie
 * needs. */
static cdist_status helix_pieces(cdist__cs_scan *s, const helix_x *hx, double t0, double plen, long pieces, double t1)
{
    cdist_query *q = s->q;
    const helix_bound hb = ((const helix_lb_ctx *)s->lb_ctx)->hb;
    /* The piece whose axis range is nearest the middle of the target's axial range. */
    long mid = 0;
    if (hx->rise != 0.0) {
        double tm = 0.5 * (hb.zlo + hb.zhi) / hx->rise;
        double f = floor((tm - t0) / plen);
        mid = f < 0.0 ? 0 : (f >= (double)pieces ? pieces - 1 : (long)f);
    }
    long lo = mid, hi = mid; /* next candidates: lo - 1 and hi + 1 (mid first) */
    int first = 1, done_lo = 0, done_hi = 0;
    long ties = 0; /* pieces scanned only for a possible tie */
    cdist_status st;
    while (first || !done_lo || !done_hi) {
        long i;
        if (first) {
            i = mid;
            first = 0;
        } else {
            double blo = INFINITY, bhi = INFINITY;
            if (!done_lo && lo > 0) blo = helix_piece_lb(&hb, hx, t0 + (double)(lo - 1) * plen, t0 + (double)lo * plen);
            else done_lo = 1;
            if (!done_hi && hi < pieces - 1)
                bhi = helix_piece_lb(&hb, hx, t0 + (double)(hi + 1) * plen, t0 + (double)(hi + 2) * plen);
            else done_hi = 1;
            double best = s->k->b.n ? sqrt(s->k->b.c[0].d2) : INFINITY;
            /* A piece must be scanned when its bound is below the best minus the certification
             * tolerance; one whose bound is within the tie margin of the best may hold a second
             * closest pair: these are scanned too, within CD_CURVE_HELIX_TIE_SAMPLES samples. */
            double need = best - cert_tol(s);
            double tie = best * (1.0 + CD_CURVE_HELIX_SKIP_REL) + CD_CURVE_HELIX_SKIP_ABS * s->k->b.scale;
            int tie_ok = (double)(ties + 1) * q->curve_samples <= CD_CURVE_HELIX_TIE_SAMPLES;
            if (!(blo < need || (tie_ok && blo <= tie))) done_lo = 1;
            if (!(bhi < need || (tie_ok && bhi <= tie))) done_hi = 1;
            if (done_lo && done_hi) break;
            if (!done_lo && (done_hi || blo <= bhi)) i = --lo;
            else i = ++hi;
            if ((i == lo ? blo : bhi) >= need) ties++;
        }
        double a = t0 + (double)i * plen, b = (i == pieces - 1) ? t1 : t0 + (double)(i + 1) * plen;
        if ((st = cdist__cs_scan_run(s, a, b, q->curve_samples))) return st;
        if (i == mid && (st = helix_cost_check(s, hx, &hb, t0, plen, pieces, mid))) return st;
    }
    return CDIST_OK;
}


static cdist_status helix_query(cdist_query *q, const cdist_helix *h, const cdist_circle *c, cdist_result *r,
                                int disk)
{
    cdist_status st;
    if (!h) return cdist__fail(q, CDIST_ERR_NULL_ARGUMENT, "helix pointer is NULL");
    cdist__circle cc;
    helix_x hx;
    if ((st = cdist__check_point(q, &h->center, "helix centre")) ||
        (st = cdist__check_direction(q, &h->axis, "helix axis", 1, &hx.n, NULL)) ||
        (st = cdist__cs_zero_frame(q, hx.n, &h->zero_direction, "helix zero_direction", &hx.u, &hx.v)) ||
        (st = cdist__check_scalar(q, h->radius, "helix radius")) || (st = cdist__check_scalar(q, h->pitch, "helix pitch")))
        return st;
    if (h->radius < 0.0) return cdist__fail(q, CDIST_ERR_NEGATIVE_RADIUS, "helix radius is negative (%g)", h->radius);
    if ((st = cdist__cs_check_interval(q, h->t0, h->t1, "helix"))) return st;
    if ((st = cdist__check_circle(q, c, disk ? "disk" : "circle", &cc))) return st;
    double t0 = h->t0, t1 = h->t1;
    if ((t1 - t0) > 2.0 * M_PI * CD_CURVE_HELIX_MAX_TURNS)
        return cdist__fail(q, CDIST_ERR_BAD_INTERVAL, "helix has more than %g turns", CD_CURVE_HELIX_MAX_TURNS);
    if (fabs(t1) * fabs(h->pitch) > CD_MAX_ABS || fabs(t0) * fabs(h->pitch) > CD_MAX_ABS)
        return cdist__fail(q, CDIST_ERR_OUT_OF_RANGE, "helix reaches beyond 1e150");
    hx.r = h->radius;
    hx.rise = h->pitch / (2.0 * M_PI);
    /* Pitch 0 repeats one circle: one turn covers it. (Radius 0 is a segment of the axis: one
     * piece, below.) */
    if (h->pitch == 0.0 && t1 - t0 > 2.0 * M_PI) t1 = t0 + 2.0 * M_PI;
    vec3 origin = cc.c;
    hx.c = v_sub(h->center, origin);
    cc.c = v3(0, 0, 0);
    int e = cdist__scale_exponent(fmax(fmax(cc.r, hx.r), fmax(v_maxabs(hx.c), fabs(hx.rise) * fmax(fabs(t0), fabs(t1)))));
    double down = cdist__pow2(-e);
    hx.c = v_scale(down, hx.c);
    hx.r *= down;
    /* scaled before the division (exact for a normal pitch either way): a subnormal pitch keeps
     * its bits, which pitch / (2 pi) would lose */
    hx.rise = (h->pitch * down) / (2.0 * M_PI);
    cc.r *= down;
    /* Pieces of at most one turn, each sampled with the handle's sample count. */
    double len = t1 - t0;
    long pieces = (h->radius == 0.0) ? 1 : (long)ceil(len / (2.0 * M_PI));
    if (pieces < 1) pieces = 1;
    double plen = len / (double)pieces;
    cdist__cs_coll k;
    cdist__cs_coll_init(&k, fmax(cc.r, v_norm(hx.c)));
    cdist__cs_scan s = {.q = q, .ev = helix_eval, .ctx = &hx, .c = &cc, .disk = disk, .k = &k, .update_scale = 1,
                        .pos = helix_pos};
    helix_lb_ctx lbc = {helix_bound_init(&hx, &cc, disk, fabs(hx.rise) * fmax(fabs(t0), fabs(t1))), &hx};
    s.certify = 1;
    s.speed_max = hypot(hx.r, hx.rise);
    s.accel_max = hx.r;
    s.accel_normal_max = hx.r * v_norm(v_cross(cc.n, hx.n));
    s.accel_plane_max = hx.r;
    s.lb = helix_lb;
    s.lb_ctx = &lbc;
    if (pieces == 1) {
        if ((st = cdist__cs_scan_run(&s, t0, t1, q->curve_samples))) return st;
    } else if ((st = helix_pieces(&s, &hx, t0, plen, pieces, t1))) {
        return st;
    }
    if ((st = cdist__cs_flat_check(&s, t0, t1, plen / q->curve_samples))) return st;
    cdist__cs_coll_result(&k, cdist__pow2(e), origin, r);
    return CDIST_OK;
}

cdist_status cdist_helix_circle(cdist_query *q, const cdist_helix *h, const cdist_circle *c, cdist_result *r)
{
    cdist_status st = cdist__enter(q, r);
    if (st) return st;
    return cdist__leave(q, r, helix_query(q, h, c, r, 0), CDIST_METHOD_ROBUST);
}

cdist_status cdist_helix_disk(cdist_query *q, const cdist_helix *h, const cdist_circle *d, cdist_result *r)
{
    cdist_status st = cdist__enter(q, r);
    if (st) return st;
    return cdist__leave(q, r, helix_query(q, h, d, r, 1), CDIST_METHOD_ROBUST);
}

/* ---- cubic Bezier ---- */

typedef struct bez_x {
    vec3 p[4]; /* relative to the circle's centre */
} bez_x;

static inline vec3 bez_point(const bez_x *b, double t)
{
    double mt = 1.0 - t;
    double b0 = mt * mt * mt, b1 = 3.0 * mt * mt * t, b2 = 3.0 * mt * t * t, b3 = t * t * t;
    return v_axpy(v_axpy(v_axpy(v_scale(b0, b->p[0]), b1, b->p[1]), b2, b->p[2]), b3, b->p[3]);
}

static vec3 bez_pos(const void *ctx, double t) { return bez_point(ctx, t); }

static cdist_status bez_eval(cdist_query *q, const void *ctx, double t, vec3 *p, vec3 *dp)
{
    (void)q;
    const bez_x *b = ctx;
    double mt = 1.0 - t;
    *p = bez_point(b, t);
    vec3 d0 = v_sub(b->p[1], b->p[0]), d1 = v_sub(b->p[2], b->p[1]), d2 = v_sub(b->p[3], b->p[2]);
    *dp = v_axpy(v_axpy(v_scale(3.0 * mt * mt, d0), 6.0 * mt * t, d1), 3.0 * t * t, d2);
    return CDIST_OK;
}

static cdist_status bezier_query(cdist_query *q, const cdist_bezier3 *bz, const cdist_circle *c, cdist_result *r,
                                 int disk)
{
    cdist_status st;
    if (!bz) return cdist__fail(q, CDIST_ERR_NULL_ARGUMENT, "Bezier pointer is NULL");
    static const char *names[4] = {"Bezier control point 0", "Bezier control point 1", "Bezier control point 2",
                                   "Bezier control point 3"};
    for (int i = 0; i < 4; i++)
        if ((st = cdist__check_point(q, &bz->p[i], names[i]))) return st;
    cdist__circle cc;
    if ((st = cdist__check_circle(q, c, disk ? "disk" : "circle", &cc))) return st;
    vec3 origin = cc.c;
    bez_x bx;
    double scale = cc.r;
    for (int i = 0; i < 4; i++) {
        bx.p[i] = v_sub(bz->p[i], origin);
        scale = fmax(scale, v_maxabs(bx.p[i]));
    }
    int e = cdist__scale_exponent(scale);
    double down = cdist__pow2(-e);
    for (int i = 0; i < 4; i++) bx.p[i] = v_scale(down, bx.p[i]);
    cc.r *= down;
    cc.c = v3(0, 0, 0);
    /* Bounds of P' and P'' from their control points (the hodographs' convex hulls). */
    double S = 0.0, K = 0.0, Kn = 0.0, Kp = 0.0;
    for (int i = 0; i < 3; i++) S = fmax(S, 3.0 * v_norm(v_sub(bx.p[i + 1], bx.p[i])));
    for (int i = 0; i < 2; i++) {
        vec3 a2 = v_scale(6.0, v_add(v_sub(bx.p[i + 2], v_scale(2.0, bx.p[i + 1])), bx.p[i]));
        K = fmax(K, v_norm(a2));
        Kn = fmax(Kn, fabs(v_dot(cc.n, a2)));
        Kp = fmax(Kp, v_norm(v_cross(cc.n, a2)));
    }
    double bounds[4] = {S, K, Kn, Kp};
    return run_curve(q, bez_eval, bez_pos, &bx, 0.0, 1.0, &cc, disk, origin, scale * down, 0.0, cdist__pow2(e), bounds, r);
}

cdist_status cdist_bezier3_circle(cdist_query *q, const cdist_bezier3 *b, const cdist_circle *c, cdist_result *r)
{
    cdist_status st = cdist__enter(q, r);
    if (st) return st;
    return cdist__leave(q, r, bezier_query(q, b, c, r, 0), CDIST_METHOD_ROBUST);
}

cdist_status cdist_bezier3_disk(cdist_query *q, const cdist_bezier3 *b, const cdist_circle *d, cdist_result *r)
{
    cdist_status st = cdist__enter(q, r);
    if (st) return st;
    return cdist__leave(q, r, bezier_query(q, b, d, r, 1), CDIST_METHOD_ROBUST);
}
