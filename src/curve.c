/* SPDX-License-Identifier: MIT */
/* Parametric curves, helices and cubic Bezier curves to circles and disks: the generic
 * root-bounding engine (distance-to-circles-3d §3, point-curve-circle-to-disk §3). The arc
 * queries (src/arc.c) use the same engine through the small interface in src/curve_scan.h.
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
 *  - for the disk, sign changes of rho - r are bisected and offered (partition points);
 *  - for the circle, the closest approaches to the axis that may reach it between samples are
 *    located (golden section on rho) and offered: the non-smooth points of F.
 * Limitation (documented in docs/curves.md): roots are bounded only up to the sample spacing:
 * two minima closer than about one sample interval can merge, and a minimum hidden in a pair of
 * critical points inside one interval is found only when the extremum search detects it.
 * cdist_query_set_curve_samples() trades speed for resolution. */
#include <math.h>

#include "curve_scan.h"

/* ---- collector ---- */

void cs_coll_init(cs_coll *k, double scale)
{
    cd_best_init(&k->b, scale);
    k->eq_d2 = INFINITY;
    k->flat_ties = 0;
}

void cs_coll_offer(cs_coll *k, double d2, vec3 p0, vec3 p1, double a0, double a1, int eq)
{
    cd_best_offer(&k->b, d2, p0, p1, a0, a1);
    if (eq && d2 < k->eq_d2) k->eq_d2 = d2;
}

static double tie_tol(const cs_coll *k) { return CD_TIE_ULPS * DBL_EPSILON * k->b.scale; }

void cs_coll_finish(cs_coll *k)
{
    cd_best *b = &k->b;
    if (b->n == 0) return;
    double d0 = sqrt(b->c[0].d2);
    /* A candidate with infinitely many closest pairs (a point on the circle's axis, ...). */
    if (k->eq_d2 < INFINITY && sqrt(k->eq_d2) - d0 <= tie_tol(k)) b->equidistant = 1;
    /* On a scan of a constant function (coaxial or concentric arcs...), three distinct pairs at
     * the same distance mean the continuum. (Not in general: a curve may cross a circle at
     * three isolated points.) */
    if (k->flat_ties && b->n >= 3 && sqrt(b->c[2].d2) - d0 <= tie_tol(k)) b->equidistant = 1;
}

void cs_offer_point(cs_coll *k, vec3 p, double t, const cd_circle *c, int disk, int swap)
{
    cd_best tmp;
    cd_best_init(&tmp, k->b.scale);
    vec3 rel = v_sub(p, c->c);
    if (disk) cd_point_disk_core(rel, c, &tmp, 0);
    else cd_point_circle_core(rel, c, &tmp, 0);
    if (tmp.n == 0) return;
    const cd_cand *x = &tmp.c[0];
    vec3 kp = v_add(x->p[1], c->c);
    int eq = cd_best_is_equidistant(&tmp) || (!disk && cs_near_axis(k, rel, c));
    if (swap) cs_coll_offer(k, x->d2, kp, p, x->param[1], t, eq);
    else cs_coll_offer(k, x->d2, p, kp, t, x->param[1], eq);
}

int cs_near_axis(const cs_coll *k, vec3 rel, const cd_circle *c)
{
    /* Within this distance of the axis the distance to the circle's points varies by less
     * than the tie tolerance: the closest pairs form a continuum up to rounding. */
    return c->r > 0.0 && v_norm(v_cross(c->n, rel)) <= CS_AXIS_ULPS * DBL_EPSILON * k->b.scale;
}

/* ---- the objective ---- */

typedef struct sample {
    vec3 p;     /* position (the scan's frame) */
    double g;   /* F'/2 (or D'/2) */
    double f;   /* F (or D) */
    double rho;   /* distance from the axis */
    double tol;   /* rounding level of g */
    double speed; /* |P'| (1-norm) */
} sample;

static cdist_status eval(const cs_scan *s, double t, sample *o)
{
    vec3 P, D;
    cdist_status st = s->ev(s->q, s->ctx, t, &P, &D);
    if (st) return st;
    /* Plain arithmetic (no fma calls: this is the inner loop); g only needs its sign right
     * away from its rounding level `tol`, and every offered candidate is re-evaluated by the
     * accurate point-circle/disk cores. */
    const cd_circle *c = s->c;
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
    o->rho = rho;
    double rn = fabs(rel.x) + fabs(rel.y) + fabs(rel.z), dn = fabs(D.x) + fabs(D.y) + fabs(D.z);
    o->tol = 32.0 * DBL_EPSILON * (rn + c->r + s->frame_mag) * dn;
    o->speed = dn;
    return CDIST_OK;
}

static void offer_sample(const cs_scan *s, double t, const sample *x)
{
    if (s->cand) s->cand(s, t, x->p);
    else cs_offer_point(s->k, x->p, t, s->c, s->disk, 0);
}

static cdist_status offer_at(const cs_scan *s, double t)
{
    sample x;
    cdist_status st = eval(s, t, &x);
    if (st) return st;
    offer_sample(s, t, &x);
    return CDIST_OK;
}

/* Root of g in [a, b] with ga < 0 < gb (or the reverse): Brent's zeroin (inverse quadratic /
 * secant steps, bisection whenever they do not shrink the bracket fast enough). */
static cdist_status refine(const cs_scan *s, double a, double ga, double b, double gb, double *root, sample *out)
{
    double span = s->span;
    double c = a, gc = ga, d = b - a, e = d;
    sample x;
    int have = 0;
    for (int it = 0; it < 300; it++) {
        if ((gb > 0) == (gc > 0)) {
            c = a;
            gc = ga;
            d = e = b - a;
        }
        if (fabs(gc) < fabs(gb)) {
            a = b; b = c; c = a;
            ga = gb; gb = gc; gc = ga;
            have = 0;
        }
        double tol = 2.0 * DBL_EPSILON * fabs(b) + 0.25 * DBL_EPSILON * span;
        double m = 0.5 * (c - b);
        if (fabs(m) <= tol || gb == 0.0) break;
        if (fabs(e) >= tol && fabs(ga) > fabs(gb)) {
            double p, qq, r2, s2 = gb / ga;
            if (a == c) {
                p = 2.0 * m * s2;
                qq = 1.0 - s2;
            } else {
                qq = ga / gc;
                r2 = gb / gc;
                p = s2 * (2.0 * m * qq * (qq - r2) - (b - a) * (r2 - 1.0));
                qq = (qq - 1.0) * (r2 - 1.0) * (s2 - 1.0);
            }
            if (p > 0) qq = -qq;
            else p = -p;
            if (2.0 * p < fmin(3.0 * m * qq - fabs(tol * qq), fabs(e * qq))) {
                e = d;
                d = p / qq;
            } else {
                d = m;
                e = m;
            }
        } else {
            d = m;
            e = m;
        }
        a = b;
        ga = gb;
        b += (fabs(d) > tol) ? d : (m > 0 ? tol : -tol);
        cdist_status st = eval(s, b, &x);
        if (st) return st;
        gb = x.g;
        have = 1;
    }
    if (!have) {
        cdist_status st = eval(s, b, &x);
        if (st) return st;
    }
    *root = b;
    *out = x;
    return CDIST_OK;
}

/* Refine the minimum of F bracketed by g(a) < 0 < g(b) and offer it. */
static cdist_status refine_offer(const cs_scan *s, double a, double ga, double b, double gb)
{
    double t;
    sample x;
    cdist_status st = refine(s, a, ga, b, gb, &t, &x);
    if (st) return st;
    offer_sample(s, t, &x);
    return CDIST_OK;
}

/* g keeps the sign sg at a and b; look for an extremum of g in between that crosses zero
 * (golden section on sg * g) and refine the minimum of F it brackets. */
static cdist_status dip_search(const cs_scan *s, double a, double b, double sg)
{
    const double gr = 0.6180339887498949;
    double x1 = b - gr * (b - a), x2 = a + gr * (b - a);
    sample s1, s2;
    cdist_status st;
    if ((st = eval(s, x1, &s1)) || (st = eval(s, x2, &s2))) return st;
    double lo = a, hi = b;
    for (int it = 0; it < 60; it++) {
        double v1 = sg * s1.g, v2 = sg * s2.g;
        if (v1 < 0.0 || v2 < 0.0) {
            double tm = v1 <= v2 ? x1 : x2;
            double gm = v1 <= v2 ? s1.g : s2.g;
            sample ea, eb;
            /* g > 0 dips below: the minimum of F is right of tm; g < 0 bumps above: left. */
            if (sg > 0) {
                if ((st = eval(s, b, &eb))) return st;
                return refine_offer(s, tm, gm, b, eb.g);
            }
            if ((st = eval(s, a, &ea))) return st;
            return refine_offer(s, a, ea.g, tm, gm);
        }
        if (v1 < v2) {
            hi = x2;
            x2 = x1;
            s2 = s1;
            x1 = hi - gr * (hi - lo);
            if ((st = eval(s, x1, &s1))) return st;
        } else {
            lo = x1;
            x1 = x2;
            s1 = s2;
            x2 = lo + gr * (hi - lo);
            if ((st = eval(s, x2, &s2))) return st;
        }
        if (hi - lo <= 4.0 * DBL_EPSILON * (fabs(lo) + fabs(hi)) + 0.25 * DBL_EPSILON * s->span) break;
    }
    return CDIST_OK;
}

/* Bisect rho - r between a and b (opposite signs) and offer the partition point. */
static cdist_status partition_offer(const cs_scan *s, double a, double da, double b)
{
    sample x;
    cdist_status st;
    for (int it = 0; it < 80; it++) {
        double m = 0.5 * (a + b);
        if (m == a || m == b) break;
        if ((st = eval(s, m, &x))) return st;
        double dm = x.rho - s->c->r;
        if ((dm > 0) == (da > 0)) {
            a = m;
            da = dm;
        } else {
            b = m;
        }
    }
    return offer_at(s, a);
}

/* The curve's closest approach to the circle's axis in [a, b] (golden section on rho), offered:
 * where the curve crosses the axis F has a kink, and in a flat configuration the kink rounded by
 * a near miss is a dip as narrow as the miss distance, invisible to the samples. */
static cdist_status axis_offer(const cs_scan *s, double a, double b)
{
    const double gr = 0.6180339887498949;
    double x1 = b - gr * (b - a), x2 = a + gr * (b - a);
    sample s1, s2;
    cdist_status st;
    if ((st = eval(s, x1, &s1)) || (st = eval(s, x2, &s2))) return st;
    for (int it = 0; it < 120; it++) {
        if (b - a <= 2.0 * DBL_EPSILON * (fabs(a) + fabs(b)) + 0.25 * DBL_EPSILON * s->span) break;
        if (s1.rho < s2.rho) {
            b = x2; x2 = x1; s2 = s1;
            x1 = b - gr * (b - a);
            if ((st = eval(s, x1, &s1))) return st;
        } else {
            a = x1; x1 = x2; s1 = s2;
            x2 = a + gr * (b - a);
            if ((st = eval(s, x2, &s2))) return st;
        }
    }
    if (s1.rho < s2.rho) offer_sample(s, x1, &s1);
    else offer_sample(s, x2, &s2);
    return CDIST_OK;
}

static double t_at(double t0, double t1, int i, int n)
{
    if (i == n) return t1;
    return t0 + (t1 - t0) * ((double)i / n);
}

cdist_status cs_scan_run(cs_scan *s, double t0, double t1, int n)
{
    cdist_query *q = s->q;
    cdist_status st;
    if (!(t0 < t1)) return offer_at(s, t0);
    if (n > q->curve_samples) n = q->curve_samples;
    double *G = q->scratch, *Fv = G + (n + 1), *R = Fv + (n + 1), *T = R + (n + 1);
    s->span = t1 - t0;
    double ext = 0.0;
    for (int i = 0; i <= n; i++) {
        sample x;
        if ((st = eval(s, t_at(t0, t1, i, n), &x))) return st;
        G[i] = x.g;
        Fv[i] = x.f;
        R[i] = x.rho - s->c->r;
        T[i] = x.tol;
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
            if (G[i] < 0 && G[i + 1] > 0 && !(zero && zr)) {
                if ((st = refine_offer(s, t, G[i], t_at(t0, t1, i + 1, n), G[i + 1]))) return st;
            }
            if (s->disk && ((R[i] > 0) != (R[i + 1] > 0))) {
                if ((st = partition_offer(s, t, R[i], t_at(t0, t1, i + 1, n)))) return st;
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
    return CDIST_OK;
}

cdist_status cs_flat_check(cs_scan *s, double t0, double t1, double delta)
{
    cs_coll *k = s->k;
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

cdist_status cs_polish(cs_scan *s, double t, double lo, double hi)
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
    double step = 1e-10 * fmax(s->span, fabs(t));
    double prev = t;
    for (int it = 0; it < 40; it++) {
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
} user_curve;

static cdist_status user_eval(cdist_query *q, const void *ctx, double t, vec3 *p, vec3 *dp)
{
    const user_curve *u = ctx;
    cdist_vec3 P = {NAN, NAN, NAN}, D = {NAN, NAN, NAN};
    int rc = u->f(u->user, t, &P, &D);
    if (rc) return cd_fail(q, CDIST_ERR_CALLBACK_FAILED, "curve callback returned %d at t = %.17g", rc, t);
    if (!v_isfinite(P) || !v_isfinite(D))
        return cd_fail(q, CDIST_ERR_CALLBACK_NOT_FINITE,
                       "curve callback gave a non-finite %s at t = %.17g", v_isfinite(P) ? "derivative" : "position",
                       t);
    if (v_maxabs(P) > CD_MAX_ABS || v_maxabs(D) > CD_MAX_ABS)
        return cd_fail(q, CDIST_ERR_OUT_OF_RANGE, "curve callback gave a value beyond 1e150 at t = %.17g", t);
    *p = v_sub(P, u->origin);
    *dp = D;
    return CDIST_OK;
}

cdist_status cs_check_interval(cdist_query *q, double t0, double t1, const char *what)
{
    if (!isfinite(t0) || !isfinite(t1))
        return cd_fail(q, CDIST_ERR_NOT_FINITE, "%s interval [%g, %g] is not finite", what, t0, t1);
    if (t0 > t1) return cd_fail(q, CDIST_ERR_BAD_INTERVAL, "%s interval [%.17g, %.17g] is reversed", what, t0, t1);
    if (!isfinite(t1 - t0))
        return cd_fail(q, CDIST_ERR_BAD_INTERVAL, "%s interval [%g, %g] is too long", what, t0, t1);
    return CDIST_OK;
}

/* Run a curve (evaluated in the frame whose origin is `origin`) against circle or disk cc
 * (its centre already relative to that frame) and write the result. */
static cdist_status run_curve(cdist_query *q, cs_eval_fn ev, const void *ctx, double t0, double t1,
                              const cd_circle *cc, int disk, vec3 origin, double scale, double frame_mag,
                              cdist_result *r)
{
    cs_coll k;
    cs_coll_init(&k, scale);
    cs_scan s = {q, ev, ctx, cc, disk, &k, NULL, NULL, 1, 0.0, frame_mag};
    cdist_status st = cs_scan_run(&s, t0, t1, q->curve_samples);
    if (!st) st = cs_flat_check(&s, t0, t1, (t1 - t0) / q->curve_samples);
    if (st) return st;
    cs_coll_finish(&k);
    cd_best_to_result(&k.b, origin, 0, r);
    return cd_ok(q, r, CDIST_METHOD_ROBUST);
}

static cdist_status curve_query(cdist_query *q, cdist_curve_fn f, void *user, double t0, double t1,
                                const cdist_circle *c, cdist_result *r, int disk)
{
    cdist_status st = cd_check_handle(q, r);
    if (st) return st;
    if (!f) return cd_fail(q, CDIST_ERR_NULL_ARGUMENT, "curve callback is NULL");
    cd_circle cc;
    if ((st = cd_check_circle(q, c, disk ? "disk" : "circle", &cc))) return st;
    if ((st = cs_check_interval(q, t0, t1, "curve"))) return st;
    user_curve u = {f, user, cc.c};
    vec3 origin = cc.c;
    cc.c = v3(0, 0, 0);
    /* The callback's positions are absolute: their rounding is relative to |origin| too. */
    return run_curve(q, user_eval, &u, t0, t1, &cc, disk, origin, cc.r, v_maxabs(origin), r);
}

cdist_status cdist_curve_circle(cdist_query *q, cdist_curve_fn f, void *user, double t0, double t1,
                                const cdist_circle *c, cdist_result *r)
{
    return curve_query(q, f, user, t0, t1, c, r, 0);
}

cdist_status cdist_curve_disk(cdist_query *q, cdist_curve_fn f, void *user, double t0, double t1,
                              const cdist_circle *d, cdist_result *r)
{
    return curve_query(q, f, user, t0, t1, d, r, 1);
}

/* ---- frames ---- */

cdist_status cs_zero_frame(cdist_query *q, vec3 n, const cdist_vec3 *zd, const char *what, vec3 *U, vec3 *V)
{
    vec3 z;
    cdist_status st = cd_check_direction(q, zd, what, 0, &z, NULL);
    if (st) return st;
    vec3 w = v_cross(n, z);
    double sn = v_norm(w);
    /* U = (n x z) x n / |n x z| is z projected onto the plane; refuse an ill-defined one. */
    if (!(sn > CS_PARALLEL_SIN))
        return cd_fail(q, CDIST_ERR_ZERO_VECTOR, "%s is parallel to the normal/axis (sin %.3g)", what, sn);
    *U = v_scale(1.0 / sn, v_cross(w, n));
    *V = v_cross(n, *U);
    return CDIST_OK;
}

/* ---- helix ---- */

typedef struct helix_x {
    vec3 c, n, u, v; /* c relative to the circle's centre */
    double r, rise;  /* rise = pitch / (2 pi) */
} helix_x;

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

#define CS_MAX_HELIX_TURNS 1e6

static cdist_status helix_query(cdist_query *q, const cdist_helix *h, const cdist_circle *c, cdist_result *r,
                                int disk)
{
    cdist_status st = cd_check_handle(q, r);
    if (st) return st;
    if (!h) return cd_fail(q, CDIST_ERR_NULL_ARGUMENT, "helix pointer is NULL");
    cd_circle cc;
    helix_x hx;
    if ((st = cd_check_point(q, &h->center, "helix centre")) ||
        (st = cd_check_direction(q, &h->axis, "helix axis", 1, &hx.n, NULL)) ||
        (st = cs_zero_frame(q, hx.n, &h->zero_direction, "helix zero_direction", &hx.u, &hx.v)) ||
        (st = cd_check_scalar(q, h->radius, "helix radius")) || (st = cd_check_scalar(q, h->pitch, "helix pitch")))
        return st;
    if (h->radius < 0.0) return cd_fail(q, CDIST_ERR_NEGATIVE_RADIUS, "helix radius is negative (%g)", h->radius);
    if ((st = cs_check_interval(q, h->t0, h->t1, "helix"))) return st;
    if ((st = cd_check_circle(q, c, disk ? "disk" : "circle", &cc))) return st;
    double t0 = h->t0, t1 = h->t1;
    if ((t1 - t0) > 2.0 * M_PI * CS_MAX_HELIX_TURNS)
        return cd_fail(q, CDIST_ERR_BAD_INTERVAL, "helix has more than %g turns", CS_MAX_HELIX_TURNS);
    if (fabs(t1) * fabs(h->pitch) > CD_MAX_ABS || fabs(t0) * fabs(h->pitch) > CD_MAX_ABS)
        return cd_fail(q, CDIST_ERR_OUT_OF_RANGE, "helix reaches beyond 1e150");
    hx.r = h->radius;
    hx.rise = h->pitch / (2.0 * M_PI);
    /* Pitch 0 repeats one circle: one turn covers it. (Radius 0 is a segment of the axis: one
     * piece, below.) */
    if (h->pitch == 0.0 && t1 - t0 > 2.0 * M_PI) t1 = t0 + 2.0 * M_PI;
    vec3 origin = cc.c;
    hx.c = v_sub(h->center, origin);
    cc.c = v3(0, 0, 0);
    /* Pieces of at most one turn, each sampled with the handle's sample count. A piece lies in
     * the ball around its mid-axis point of radius sqrt(r^2 + (half its rise)^2): pieces whose
     * ball is farther from the circle than the best ball-based upper bound are skipped. */
    double len = t1 - t0;
    long pieces = (h->radius == 0.0) ? 1 : (long)ceil(len / (2.0 * M_PI));
    if (pieces < 1) pieces = 1;
    double plen = len / (double)pieces;
    double ball = hypot(h->radius, 0.5 * fabs(hx.rise) * plen);
    cs_coll k;
    cs_coll_init(&k, fmax(cc.r, v_norm(hx.c)));
    cs_scan s = {q, helix_eval, &hx, &cc, disk, &k, NULL, NULL, 1, 0.0, 0.0};
    double ub = INFINITY;
    if (pieces > 1) {
        for (long i = 0; i < pieces; i++) {
            double tm = t0 + ((double)i + 0.5) * plen;
            vec3 m = v_axpy(hx.c, hx.rise * tm, hx.n);
            cd_best tb;
            cd_best_init(&tb, 1.0);
            if (disk) cd_point_disk_core(m, &cc, &tb, 0);
            else cd_point_circle_core(m, &cc, &tb, 0);
            ub = fmin(ub, sqrt(tb.c[0].d2) + ball);
        }
    }
    for (long i = 0; i < pieces; i++) {
        double a = (i == 0) ? t0 : t0 + (double)i * plen, b = (i == pieces - 1) ? t1 : t0 + (double)(i + 1) * plen;
        if (pieces > 1) {
            double tm = 0.5 * (a + b);
            vec3 m = v_axpy(hx.c, hx.rise * tm, hx.n);
            cd_best tb;
            cd_best_init(&tb, 1.0);
            if (disk) cd_point_disk_core(m, &cc, &tb, 0);
            else cd_point_circle_core(m, &cc, &tb, 0);
            if (sqrt(tb.c[0].d2) - ball > ub * (1.0 + 1e-12)) continue;
        }
        if ((st = cs_scan_run(&s, a, b, q->curve_samples))) return st;
    }
    if ((st = cs_flat_check(&s, t0, t1, plen / q->curve_samples))) return st;
    cs_coll_finish(&k);
    cd_best_to_result(&k.b, origin, 0, r);
    return cd_ok(q, r, CDIST_METHOD_ROBUST);
}

cdist_status cdist_helix_circle(cdist_query *q, const cdist_helix *h, const cdist_circle *c, cdist_result *r)
{
    return helix_query(q, h, c, r, 0);
}

cdist_status cdist_helix_disk(cdist_query *q, const cdist_helix *h, const cdist_circle *d, cdist_result *r)
{
    return helix_query(q, h, d, r, 1);
}

/* ---- cubic Bezier ---- */

typedef struct bez_x {
    vec3 p[4]; /* relative to the circle's centre */
} bez_x;

static cdist_status bez_eval(cdist_query *q, const void *ctx, double t, vec3 *p, vec3 *dp)
{
    (void)q;
    const bez_x *b = ctx;
    double mt = 1.0 - t;
    double b0 = mt * mt * mt, b1 = 3.0 * mt * mt * t, b2 = 3.0 * mt * t * t, b3 = t * t * t;
    *p = v_axpy(v_axpy(v_axpy(v_scale(b0, b->p[0]), b1, b->p[1]), b2, b->p[2]), b3, b->p[3]);
    vec3 d0 = v_sub(b->p[1], b->p[0]), d1 = v_sub(b->p[2], b->p[1]), d2 = v_sub(b->p[3], b->p[2]);
    *dp = v_axpy(v_axpy(v_scale(3.0 * mt * mt, d0), 6.0 * mt * t, d1), 3.0 * t * t, d2);
    return CDIST_OK;
}

static cdist_status bezier_query(cdist_query *q, const cdist_bezier3 *bz, const cdist_circle *c, cdist_result *r,
                                 int disk)
{
    cdist_status st = cd_check_handle(q, r);
    if (st) return st;
    if (!bz) return cd_fail(q, CDIST_ERR_NULL_ARGUMENT, "Bezier pointer is NULL");
    static const char *names[4] = {"Bezier control point 0", "Bezier control point 1", "Bezier control point 2",
                                   "Bezier control point 3"};
    for (int i = 0; i < 4; i++)
        if ((st = cd_check_point(q, &bz->p[i], names[i]))) return st;
    cd_circle cc;
    if ((st = cd_check_circle(q, c, disk ? "disk" : "circle", &cc))) return st;
    vec3 origin = cc.c;
    bez_x bx;
    double scale = cc.r;
    for (int i = 0; i < 4; i++) {
        bx.p[i] = v_sub(bz->p[i], origin);
        scale = fmax(scale, v_norm(bx.p[i]));
    }
    cc.c = v3(0, 0, 0);
    return run_curve(q, bez_eval, &bx, 0.0, 1.0, &cc, disk, origin, scale, 0.0, r);
}

cdist_status cdist_bezier3_circle(cdist_query *q, const cdist_bezier3 *b, const cdist_circle *c, cdist_result *r)
{
    return bezier_query(q, b, c, r, 0);
}

cdist_status cdist_bezier3_disk(cdist_query *q, const cdist_bezier3 *b, const cdist_circle *d, cdist_result *r)
{
    return bezier_query(q, b, d, r, 1);
}
