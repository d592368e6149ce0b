/* SPDX-License-Identifier: MIT */
/* Lines, rays and segments to circles (Eberly, "Distance to Circles in 3D" §4; "Distance Between
 * Line and Circle or Disk in 3D" §1). The model (the line's frame at the point nearest the
 * centre, scaled by a power of two; F(s) = h^2 + (rho - r)^2 and its cancellation-free
 * derivative): docs/lines.md, "Reduction" and "Derivative". */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "internal.h"

#define EPS DBL_EPSILON

/* Multiply-add in the model's hot loop (the FMA policy of base/numeric.h). */
#define MADD(a, b, c) CD_MADD(a, b, c)

/* The model's arithmetic (line_circle_body.h) for one lane: the batch kernels run the same
 * body in 4 and 8 lanes. */
#define CD_LANES 1
#include "base/lanes/lanes_def.h"
#include "base/lanes/lanes_vec.h"
#include "base/roots_halley.h"
#include "lines/line_circle_body.h"
#include "base/lanes/lanes_undef.h"

typedef lc_model_1 lc_model;

/* F'/2 and F''/2, the polishing's callback (base/roots.h). */
CD_INLINE double fdf(const void *ctx, double s, double *df) { return lc_fdf_1(ctx, s, df); }

/* Squared distance (scaled) at s. */
CD_INLINE double f_at(const lc_model *m, double s)
{
    double x2, rho;
    return lc_f_1(m, s, &x2, &rho);
}

/* Root of F' in [lo, hi] where F' increases, from x0: the safeguarded Halley solver
 * (base/roots.h), which commutes with s -> -s when F' is odd, so mirrored brackets give
 * mirrored roots; the accelerated variant (near a tangent line F' is nearly cubic about its
 * root). */
CD_INLINE double solve(const lc_model *m, double lo, double hi, double x0)
{
    halley_1 s = halley_start_1(lo, hi, x0, 1);
    for (int it = 0; it < CD_ROOT_MAX_ITER && s.act; it++) lc_iterate_1(m, &s);
    return s.act ? s.x : s.res;
}

/* Newton on F' from a polynomial root, kept only while |F'| decreases. */
CD_INLINE double polish(const lc_model *m, double x)
{
    return cdist__root_polish(fdf, m, x, CD_ROOT_REL_ULPS * EPS, CD_ROOT_ABS, CD_POLISH_MAX_ITER);
}

/* ---- candidates ---- */

#define LC_MAX_CAND 8

typedef struct lc_ctx {
    const cdist__circle *c;
    vec3 B, M;        /* the caller's line (unscaled, relative to the centre) */
    double t0;        /* t of B0 */
    double sigma;     /* scale factor (power of two) */
    double up;        /* 1 / sigma */
    double uO;        /* frame origin, scaled u */
    double eqtol;     /* on-axis tolerance for rho (scaled) */
    int n;
    cdist__cand cand[LC_MAX_CAND]; /* .equidistant: an on-axis point (every circle point as close) */
} lc_ctx;

CD_INLINE void push(lc_ctx *x, double d2, vec3 P, vec3 K, double t, double ang, int eq)
{
    if (x->n >= LC_MAX_CAND) return;
    cdist__cand *c = &x->cand[x->n];
    c->d2 = d2;
    c->p[0] = P;
    c->p[1] = K;
    c->param[0] = t;
    c->param[1] = ang;
    c->equidistant = eq;
    x->n++;
}

/* Circle point in direction (X, Y) of the basis; (0, 0) gives the representative angle 0. */
CD_INLINE vec3 circle_pt(const cdist__circle *c, double X, double Y, double *ang)
{
    double n2 = MADD(X, X, Y * Y);
    /* the core runs on scaled input (X, Y ~ 1): sqrt, with hypot only as a guard */
    double n = (n2 >= 0x1p-1000 && n2 <= 0x1p1000) ? sqrt(n2) : hypot(X, Y);
    if (c->r == 0.0) {
        *ang = NAN;
        return v3(0, 0, 0);
    }
    if (n == 0.0) {
        *ang = 0.0;
        return v_scale(c->r, c->u);
    }
    *ang = cdist__polar_angle(X, Y);
    if (n < 0x1p-500) {
        /* (X, Y) within 1e-150 of the scale from the axis: r / n may overflow (then 0 * inf is
         * NaN); the direction scaled to its largest component first (exact) */
        double m = cdist__fmax(fabs(X), fabs(Y));
        X /= m;
        Y /= m;
        n = sqrt(MADD(X, X, Y * Y));
    }
    double k = c->r / n;
    return v_add(v_scale(k * X, c->u), v_scale(k * Y, c->v));
}

/* A critical point of the model at s. */
CD_INLINE void offer_model(lc_ctx *x, const lc_model *m, double s)
{
    double x2, rho;
    double d2 = (lc_f_1(m, s, &x2, &rho) * x->up) * x->up;
    double t = x->t0 + (x->uO + s) * x->up; /* exact: a power of two */
    vec3 P = v_axpy(x->B, t, x->M);
    /* X = x1 e1 + x2 e2, e1 = (-e2y, e2x) */
    double X = MADD(m->x1, -m->e2y, x2 * m->e2x), Y = MADD(m->x1, m->e2x, x2 * m->e2y);
    double ang;
    vec3 K = circle_pt(x->c, X, Y, &ang);
    push(x, d2, P, K, t, ang, rho <= x->eqtol);
}

/* A finite end of the range: point-circle (cdist__point_circle_core semantics, parameter t). */
CD_INLINE void offer_end(lc_ctx *x, double t)
{
    const cdist__circle *c = x->c;
    double p[3], q[3], rho;
    double d2 = lc_end_1(x->B.x, x->B.y, x->B.z, x->M.x, x->M.y, x->M.z, t, c->n.x, c->n.y, c->n.z, c->r, p, q, &rho);
    vec3 P = v3(p[0], p[1], p[2]), np = v3(q[0], q[1], q[2]);
    vec3 w = v_cross(np, c->n);
    int on_axis = rho <= CD_ON_AXIS_ULPS * EPS * v_norm(P);
    double ang;
    vec3 K = on_axis ? circle_pt(c, 0, 0, &ang) : circle_pt(c, v_dot(c->u, w), v_dot(c->v, w), &ang);
    push(x, d2, P, K, t, ang, on_axis && c->r > 0.0);
}

/* Two candidates are the same minimum unless the distance rises between them by more than the
 * tie tolerance: near a flat minimum (a tangent line, F ~ s^4) the solvers may stop at several
 * points of the flat bottom, which are not distinct minima, so only the lowest is kept. Genuine
 * pairs of minima (symmetric configurations) have a maximum between them. */
CD_INLINE void merge_basins(lc_ctx *x, const lc_model *m, double tol)
{
    /* sort by t */
    for (int i = 1; i < x->n; i++)
        for (int j = i; j > 0 && x->cand[j].param[0] < x->cand[j - 1].param[0]; j--) {
            cdist__cand tc = x->cand[j];
            x->cand[j] = x->cand[j - 1];
            x->cand[j - 1] = tc;
        }
    for (int i = 0; i + 1 < x->n;) {
        double sa = (x->cand[i].param[0] - x->t0) * x->sigma - x->uO;
        double sb = (x->cand[i + 1].param[0] - x->t0) * x->sigma - x->uO;
        double fmaxv = 0.0;
        for (int k = 1; k <= 3; k++) fmaxv = cdist__fmax(fmaxv, f_at(m, sa + 0.25 * k * (sb - sa)));
        double dmid = sqrt(fmaxv) * x->up;
        double d0 = sqrt(x->cand[i].d2), d1 = sqrt(x->cand[i + 1].d2);
        if (dmid > cdist__fmax(d0, d1) + tol) {
            i++;
            continue;
        }
        int drop = (x->cand[i + 1].d2 < x->cand[i].d2) ? i : i + 1;
        for (int j = drop; j + 1 < x->n; j++) x->cand[j] = x->cand[j + 1];
        x->n--;
    }
}

/* ---- the two solvers on the general model (m0 > 0) ---- */

/* §4.2: brackets from the shape of G (line_circle_body.h), local minima only, each solved by
 * the safeguarded solver. */
CD_FMA_CLONES static void robust_roots(const lc_model *m, double smin, double smax, double *roots, int *nr)
{
    double lo, hi, mu, R, B, br[2][3]; /* lo, hi, start */
    int nb = 0;
    *nr = 0;
    if (lc_bracket_1(m, &lo, &hi, &mu, &R, &B)) {
        br[nb][0] = lo, br[nb][1] = hi, br[nb][2] = lc_start_single_1(m, mu, R, B);
        nb++;
    } else {
        int hasA, hasB;
        double hiA, x0A, loB, x0B;
        lc_branches_1(m, lo, hi, mu, R, B, &hasA, &hiA, &x0A, &hasB, &loB, &x0B);
        if (hasA) br[nb][0] = lo, br[nb][1] = hiA, br[nb][2] = x0A, nb++;
        if (hasB) br[nb][0] = loB, br[nb][1] = hi, br[nb][2] = x0B, nb++;
    }
    for (int i = 0; i < nb; i++) {
        double a = cdist__fmax(br[i][0], smin), b = cdist__fmin(br[i][1], smax);
        if (a > b) continue;
        roots[(*nr)++] = solve(m, a, b, br[i][2]);
    }
}

/* §4.1: the quartic H(s) = (s + mu)^2 |N x Delta|^2 - r^2 (N x M . N x Delta)^2 (eq. (9), the d0..d4
 * of line-circle-disk §1 with a1 = 1), in the frame of the model:
 *   |N x Delta|^2 = m0^2 s^2 + 2 c2 m0 s + (x1^2 + c2^2),  N x M . N x Delta = m0 (m0 s + c2).
 * Every real root (generous imaginary tolerance: tangent lines give a root of multiplicity 4,
 * which the solver returns spread by ~eps^(1/4)) is polished by Newton on the true F'.
 * Returns the number of candidates, or -1 when the polynomial module failed. */
CD_FMA_CLONES static int poly_roots(cdist_query *q, const lc_model *m, double smin, double smax, double *roots)
{
    double mu = fma(m->a, m->h, m->m0 * m->c2);
    double m0 = m->m0, c2 = m->c2, r2 = m->r * m->r;
    double A2 = m0 * m0, A1 = 2.0 * c2 * m0, A0 = fma(m->x1, m->x1, c2 * c2);
    double d[5];
    d[4] = A2;
    d[3] = fma(2.0 * mu, A2, A1);
    d[2] = A0 + 2.0 * mu * A1 + mu * mu * A2 - r2 * A2 * A2;
    d[1] = 2.0 * mu * A0 + mu * mu * A1 - 2.0 * r2 * A2 * m0 * c2;
    d[0] = mu * mu * A0 - r2 * A2 * c2 * c2;
    double z[4];
    int n = cdist__poly_real_roots(q->poly, d, 4, CD_LC_POLY_IMAG, z);
    if (n < 0) return -1;
    int k = 0;
    for (int i = 0; i < n; i++) {
        double s = polish(m, z[i]);
        if (s >= smin && s <= smax) roots[k++] = s;
    }
    return k;
}

/* ---- the core ---- */

CD_INLINE cdist_status linear_circle(cdist_query *q, cdist_method method, vec3 B, vec3 M, double tmin, double tmax,
                                  const cdist__circle *c, cdist__best *b, cdist_method *used)
{
    if (method != CDIST_METHOD_POLYNOMIAL) method = CDIST_METHOD_ROBUST;
    if (used) *used = method;
    if (!(tmin <= tmax) || isnan(tmin) || isnan(tmax) || !v_isfinite(B) || !v_isfinite(M))
        return cdist__fail(q, CDIST_ERR_INTERNAL, "line-circle core: bad range [%g, %g] or input", tmin, tmax);
    lc_ctx x;
    x.c = c;
    x.B = B;
    x.M = M;
    x.n = 0;
    vec3 B0;
    double t0 = lc_nearest_1(B.x, B.y, B.z, M.x, M.y, M.z, &B0.x, &B0.y, &B0.z);
    x.t0 = t0;
    double umin = tmin - t0, umax = tmax - t0; /* unscaled u = t - t0 */
    if (tmin == tmax) umin = umax;

    if (c->r == 0.0) {
        /* The circle is its centre: nearest point of the range to the origin. */
        double u = cdist__fmin(cdist__fmax(0.0, umin), umax);
        double t = (u == 0.0) ? t0 : t0 + u;
        if (tmin == tmax) t = tmin;
        vec3 P = (u == 0.0) ? B0 : v_axpy(B, t, M);
        push(&x, v_sqr(P), P, v3(0, 0, 0), t, NAN, 0);
        goto done;
    }

    lc_frame_1 f = {.nx = c->n.x, .ny = c->n.y, .nz = c->n.z, .ux = c->u.x, .uy = c->u.y, .uz = c->u.z,
                    .vx = c->v.x, .vy = c->v.y, .vz = c->v.z};
    lc_frame_line_1(&f, c->r, B0.x, B0.y, B0.z, M.x, M.y, M.z);
    double sg = f.sg;
    x.sigma = sg;
    x.up = f.up;
    double rs = c->r * sg;
    x.eqtol = CD_LC_AXIS_ULPS * EPS * cdist__fmax(1.0, sg * v_norm(B));
    umin *= sg;
    umax *= sg;

    if (tmin == tmax) {
        offer_end(&x, tmin);
        goto done;
    }

    if (f.m0 <= CD_LC_PERP_ULPS * EPS) {
        /* Perpendicular to the plane (§4.1 cases 1, 2): F = (h0 + a u)^2 + (rho - r)^2 with rho
         * constant to rounding, so the minimum is the plane crossing, clamped to the range. On
         * the axis every circle point is equally close (equidistant, also for rays/segments). */
        double u = cdist__fmin(cdist__fmax(-f.h0 / f.a, umin), umax);
        double X = fma(u, f.m2x, f.b2x), Y = fma(u, f.m2y, f.b2y);
        double rho = sqrt(X * X + Y * Y), h = fma(f.a, u, f.h0), dr = rho - rs;
        double t = x.t0 + u / sg;
        if (u == umin && isfinite(tmin)) t = tmin;
        if (u == umax && isfinite(tmax)) t = tmax;
        vec3 P = v_axpy(B, t, M);
        double ang;
        vec3 K = circle_pt(c, X, Y, &ang);
        push(&x, (fma(h, h, dr * dr) * x.up) * x.up, P, K, t, ang, rho <= x.eqtol);
        goto done;
    }

    lc_model m;
    lc_model_init_1(&m, &f, rs, &x.uO);
    double smin = umin - x.uO, smax = umax - x.uO;

    double roots[4];
    int nr = -1;
    if (method == CDIST_METHOD_POLYNOMIAL) {
        nr = poly_roots(q, &m, smin, smax, roots);
        if (nr < 0 && used) *used = CDIST_METHOD_ROBUST; /* polynomial module failed: fall back */
    }
    if (nr == 0 && !isfinite(smin) && !isfinite(smax)) {
        nr = -1; /* a whole line always has a minimum: the polynomial path lost it, fall back */
        if (used) *used = CDIST_METHOD_ROBUST;
    }
    if (nr < 0) robust_roots(&m, smin, smax, roots, &nr);
    for (int i = 0; i < nr; i++) offer_model(&x, &m, roots[i]);
    if (isfinite(tmin)) offer_end(&x, tmin);
    if (isfinite(tmax)) offer_end(&x, tmax);
    merge_basins(&x, &m, cdist__best_tie_tol(b));

done:;
    /* Offer everything; an on-axis candidate makes the result equidistant only if it ends up
     * the best in b (an on-axis end that is not the minimum sets nothing). */
    for (int i = 0; i < x.n; i++) {
        const cdist__cand *k = &x.cand[i];
        cdist__best_offer_flag(b, k->equidistant, k->d2, k->p[0], k->p[1], k->param[0], k->param[1]);
    }
    return CDIST_OK;
}

CD_FMA_CLONES cdist_status cdist__linear_circle_ex(cdist_query *q, cdist_method method, vec3 B, vec3 M, double tmin, double tmax,
                                 const cdist__circle *c, cdist__best *b, cdist_method *used)
{
    return linear_circle(q, method, B, M, tmin, tmax, c, b, used);
}

/* ---- public queries ---- */

/* Scale L for tie and distinctness tests: max(r, distance from the centre to the nearest point
 * of the line, ray or segment), the quantity ../shared/cases/README.md measures errors against. */
CD_INLINE double range_scale(vec3 B, vec3 M, double tmin, double tmax, double r)
{
    double t = cdist__fmin(cdist__fmax(-v_dot(B, M), tmin), tmax);
    return cdist__fmax(r, v_norm(v_axpy(B, t, M)));
}

/* Runs the core for the points origin + t D, t in [tmin, tmax] (D as the caller passed it, M its
 * unit direction, len its length); pairs' param[0] is that t. The origin is first moved along D to
 * the point nearest the circle centre (clamped to the ray or segment), on origin - C kept exactly
 * as two doubles, and only then translated (why: docs/lines.md, "Origin moved first"). */
CD_INLINE vec3 near_centre(vec3 origin, vec3 D, vec3 C, double tmin, double tmax, double *t0)
{
    vec3 B;
    *t0 = lc_near_centre_1(origin.x, origin.y, origin.z, D.x, D.y, D.z, C.x, C.y, C.z, tmin, tmax, &B.x, &B.y, &B.z);
    return B;
}

CD_FMA_CLONES vec3 cdist__line_near_centre(vec3 origin, vec3 D, vec3 C, double tmin, double tmax, double *t0)
{
    return near_centre(origin, D, C, tmin, tmax, t0);
}

/* The core for origin + t D, t in [tmin, tmax] (M = D/|D|, len = |D|), circle cc; writes r
 * (without its method) and the method that answered. Inlined into the public entries' clones
 * with the validation and framing before it: one function from the inputs to the solver. */
CD_INLINE cdist_status run(cdist_query *q, vec3 origin, vec3 D, vec3 M, double len, double tmin, double tmax,
                        const cdist__circle *cc, cdist_result *r, cdist_method *used)
{
    double t0;
    vec3 B = near_centre(origin, D, cc->c, tmin, tmax, &t0);
    double lo = (tmin - t0) * len, hi = (tmax - t0) * len;
    if (tmin == t0) lo = 0.0;
    if (tmax == t0) hi = 0.0;
    cdist__best b;
    cdist__best_init(&b, range_scale(B, M, lo, hi, cc->r));
    cdist_status st = linear_circle(q, cdist__family_method(q, CD_FAM_LINE_CIRCLE), B, M, lo, hi, cc, &b, used);
    if (st) return st;
    if (b.n == 0) return cdist__fail(q, CDIST_ERR_INTERNAL, "line-circle: no candidate");
    cdist__best_to_result(&b, cc->c, 0, r);
    cdist__result_finish(r, r->num_pairs);
    for (int i = 0; i < r->num_pairs; i++) {
        double t = t0 + r->pairs[i].param[0] / len;
        r->pairs[i].param[0] = cdist__fmin(cdist__fmax(t, tmin), tmax);
    }
    return CDIST_OK;
}

/* FMA clone: the circle's basis (v_basis) inlined here is a chain of fma() calls, which outside
 * a clone are calls to the C library's fma (same results, slower). */
CD_FMA_CLONES static cdist_status linear_public(cdist_query *q, const cdist_vec3 *origin, const cdist_vec3 *dir,
                                                const void *obj, int is_ray, const cdist_circle *c, cdist_result *r)
{
    return cdist__linear_query(q, obj, origin, dir, is_ray, c, 0, run, r);
}

cdist_status cdist_line_circle(cdist_query *q, const cdist_line *l, const cdist_circle *c, cdist_result *r)
{
    return linear_public(q, l ? &l->origin : NULL, l ? &l->direction : NULL, l, 0, c, r);
}

cdist_status cdist_ray_circle(cdist_query *q, const cdist_ray *l, const cdist_circle *c, cdist_result *r)
{
    return linear_public(q, l ? &l->origin : NULL, l ? &l->direction : NULL, l, 1, c, r);
}

/* The segment's core: the line's, on t in [0, 1]. */
CD_INLINE cdist_status segment_core(cdist_query *q, vec3 p0, vec3 p1, vec3 Ds, vec3 M, double len,
                                    const cdist__circle *cc, cdist_result *r, cdist_method *used)
{
    (void)p1;
    return run(q, p0, Ds, M, len, 0.0, 1.0, cc, r, used);
}

/* FMA clone, as linear_public (the core is inlined into it). */
CD_FMA_CLONES static cdist_status segment_public(cdist_query *q, const cdist_segment *s, const cdist_circle *c,
                                                cdist_result *r)
{
    return cdist__segment_query(q, s, c, 0, segment_core, r);
}

cdist_status cdist_segment_circle(cdist_query *q, const cdist_segment *s, const cdist_circle *c, cdist_result *r)
{
    return segment_public(q, s, c, r);
}
