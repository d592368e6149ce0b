/* SPDX-License-Identifier: MIT */
/* Circular arcs: arc-circle, arc-arc, segment-arc, arc-disk. An arc's angle is measured in its
 * own frame (U = zero_direction projected onto the plane, V = N x U) over [start, end]; why the
 * candidates (endpoints, critical angles in range, the sampling engine as fallback) are
 * complete: docs/curves.md, "Arcs". */
#include <math.h>
#include <stdio.h>

#include "curve_scan.h"

#define TWO_PI (2.0 * M_PI)
#define CRIT_CAP 64

typedef struct arcx {
    cdist__circle c; /* centre in the query's frame; u, v the library basis */
    vec3 U, V;   /* the arc's frame */
    double start, end; /* the range, start taken modulo 2 pi when |start| > 4 pi (arc_ref) */
    double user_start, user_end; /* the caller's range */
    double phi0; /* library-basis angle of U: library angle = arc angle + phi0 */
} arcx;

/* An angle equal to t modulo 2 pi (within a few ulps of pi), t itself when |t| <= 4 pi: offsets
 * from a start such as 1e17 would round by whole radians. */
static double arc_ref(double t) { return fabs(t) <= 2.0 * TWO_PI ? t : atan2(sin(t), cos(t)); }

/* The span rule: end <= RU(start + 2 pi), RU rounding the exact sum up to a double (2 pi itself
 * rounded up). Exact, with a slack below one ulp of the end whatever |start|: an end computed in
 * double as start + 2 * M_PI is always accepted, a longer span never. The exact sum is s + err
 * (two-sum, round to nearest). */
static int arc_span_ok(double start, double end)
{
    const double two_pi_up = 0x1.921fb54442d19p+2; /* the double just above 2 pi */
    double s = start + two_pi_up;
    double bb = s - start;
    double err = (start - (s - bb)) + (two_pi_up - bb);
    double up = err > 0.0 ? nextafter(s, INFINITY) : s;
    return end <= up;
}

static cdist_status check_arc(cdist_query *q, const cdist_arc *a, const char *what, arcx *x)
{
    char buf[64];
    if (!a) return cdist__fail(q, CDIST_ERR_NULL_ARGUMENT, "%s pointer is NULL", what);
    cdist_status st = cdist__check_circle(q, &a->circle, what, &x->c);
    if (st) return st;
    snprintf(buf, sizeof buf, "%s zero_direction", what);
    if ((st = cdist__cs_zero_frame(q, x->c.n, &a->zero_direction, buf, &x->U, &x->V))) return st;
    if (!isfinite(a->start) || !isfinite(a->end))
        return cdist__fail(q, CDIST_ERR_NOT_FINITE, "%s angles [%g, %g] are not finite", what, a->start, a->end);
    if (a->start > a->end)
        return cdist__fail(q, CDIST_ERR_BAD_INTERVAL, "%s start %.17g > end %.17g", what, a->start, a->end);
    if (!arc_span_ok(a->start, a->end))
        return cdist__fail(q, CDIST_ERR_BAD_INTERVAL, "%s end %.17g exceeds start %.17g + 2 pi (rounded up)", what,
                           a->end, a->start);
    x->user_start = a->start;
    x->user_end = a->end;
    x->start = arc_ref(a->start);
    x->end = x->start == a->start ? a->end : x->start + (a->end - a->start);
    x->phi0 = atan2(v_dot(x->U, x->c.v), v_dot(x->U, x->c.u));
    return CDIST_OK;
}

static vec3 arc_point(const arcx *a, double ang)
{
    double s = sin(ang), c = cos(ang);
    return v_axpy(v_axpy(a->c.c, a->c.r * c, a->U), a->c.r * s, a->V);
}

CD_FMA_CLONES static cdist_status arc_eval(cdist_query *q, const void *ctx, double t, vec3 *p, vec3 *dp)
{
    (void)q;
    const arcx *a = ctx;
    double s = sin(t), c = cos(t);
    *p = v_axpy(v_axpy(a->c.c, a->c.r * c, a->U), a->c.r * s, a->V);
    *dp = v_axpy(v_scale(-a->c.r * s, a->U), a->c.r * c, a->V);
    return CDIST_OK;
}

/* Angle m of the direction rel (in the plane) in the arc's frame, as start + [0, 2 pi);
 * *inside says whether m <= end. */
static double arc_angle(const arcx *a, vec3 rel, int *inside)
{
    double x = v_dot(a->U, rel), y = v_dot(a->V, rel);
    *inside = 0;
    if (x == 0.0 && y == 0.0) return NAN;
    double k = fmod(atan2(y, x) - a->start, TWO_PI);
    if (k < 0.0) k += TWO_PI;
    double m = a->start + k;
    *inside = m <= a->end;
    return m;
}

/* Offer point p (the query's frame; parameter tp on its own object) against arc a: the closest
 * point of a's circle when its angle is in range, and (ends != 0) both endpoints. p_first: p is
 * on the query's first object. */
static void offer_point_arc(cdist__cs_coll *k, vec3 p, double tp, const arcx *a, int p_first, int ends)
{
    if (a->c.r == 0.0) {
        vec3 c = a->c.c;
        if (p_first) cdist__cs_coll_offer(k, v_sqr(v_sub(p, c)), p, c, tp, NAN, 0);
        else cdist__cs_coll_offer(k, v_sqr(v_sub(p, c)), c, p, NAN, tp, 0);
        return;
    }
    if (ends) {
        for (int e = 0; e < 2; e++) {
            double ang = e ? a->end : a->start;
            vec3 E = arc_point(a, ang);
            double d2 = v_sqr(v_sub(p, E));
            if (p_first) cdist__cs_coll_offer(k, d2, p, E, tp, ang, 0);
            else cdist__cs_coll_offer(k, d2, E, p, ang, tp, 0);
        }
    }
    cdist__best tmp;
    cdist__best_init(&tmp, k->b.scale);
    vec3 rel = v_sub(p, a->c.c);
    cdist__point_circle_core(rel, &a->c, &tmp, 0);
    if (tmp.n == 0) return;
    double d2 = tmp.c[0].d2;
    vec3 K;
    double ang;
    int eq = 0;
    if (cdist__best_is_equidistant(&tmp) || cdist__cs_near_axis(k, rel, &a->c)) {
        /* p on the axis (within rounding of the problem's scale): every arc point is closest;
         * the start point represents them. */
        ang = a->start;
        K = arc_point(a, ang);
        d2 = v_sqr(v_sub(p, K));
        eq = a->end > a->start;
    } else {
        int inside;
        ang = arc_angle(a, tmp.c[0].p[1], &inside);
        if (!inside) return;
        K = v_add(tmp.c[0].p[1], a->c.c);
    }
    if (p_first) cdist__cs_coll_offer(k, d2, p, K, tp, ang, eq);
    else cdist__cs_coll_offer(k, d2, K, p, ang, tp, eq);
}

/* Candidate callback: the scanned object's point p at parameter t against the arc in cand_ctx
 * (interior closest point only; its endpoints are offered separately). */
typedef struct cand_arc_ctx {
    const arcx *target;
    int scanned_first;
} cand_arc_ctx;

static void cand_arc(const cdist__cs_scan *s, double t, vec3 p)
{
    const cand_arc_ctx *cx = s->cand_ctx;
    offer_point_arc(s->k, p, t, cx->target, cx->scanned_first, 0);
}

/* Polish the candidate at arc angle a (any representative modulo 2 pi) if it falls in X's
 * range. */
static cdist_status polish_in_range(cdist__cs_scan *s, const arcx *X, double a)
{
    double k = fmod(a - X->start, TWO_PI);
    if (k < 0.0) k += TWO_PI;
    double m = X->start + k;
    if (!(m <= X->end)) return CDIST_OK;
    return cdist__cs_polish(s, m, X->start, X->end);
}

/* Lower bound of the distance from the points X(theta), theta in [a, b], to Y (circle or disk),
 * from X's heights over Y's plane and squared distances from Y's axis as trigonometric
 * polynomials (docs/curves.md, "the curve's own bound"). */
typedef struct arc_lb_ctx {
    vec3 Cp, Up, Vp;
    double hc, A, B, dh2, drho2, sq, slack, r;
    int disk;
} arc_lb_ctx;

static arc_lb_ctx arc_lb_init(const arcx *X, const cdist__circle *Y, int disk)
{
    arc_lb_ctx c;
    vec3 n = Y->n, C = v_sub(X->c.c, Y->c), U = v_scale(X->c.r, X->U), V = v_scale(X->c.r, X->V);
    c.hc = v_dot(n, C);
    c.A = v_dot(n, U);
    c.B = v_dot(n, V);
    c.Cp = v_sub(C, v_scale(c.hc, n));
    c.Up = v_sub(U, v_scale(c.A, n));
    c.Vp = v_sub(V, v_scale(c.B, n));
    c.dh2 = hypot(c.A, c.B);
    double m1 = 2.0 * hypot(v_dot(c.Cp, c.Up), v_dot(c.Cp, c.Vp));
    double m2 = hypot(0.5 * (v_sqr(c.Up) - v_sqr(c.Vp)), v_dot(c.Up, c.Vp));
    c.drho2 = m1 + 4.0 * m2;
    double mag = v_norm(C) + X->c.r;
    c.sq = CD_CURVE_HELIX_BOUND_ULPS * DBL_EPSILON * mag * mag;
    c.slack = CD_CURVE_HELIX_BOUND_ULPS * DBL_EPSILON * mag;
    c.r = Y->r;
    c.disk = disk;
    return c;
}

static double arc_lb(const cdist__cs_scan *s, double a, double b)
{
    const arc_lb_ctx *c = s->lb_ctx;
    double ca = cos(a), sa = sin(a), cb = cos(b), sb = sin(b), w2 = 0.125 * (b - a) * (b - a);
    double ha = c->hc + c->A * ca + c->B * sa, hb = c->hc + c->A * cb + c->B * sb;
    double hg = 0.0;
    if ((ha > 0.0 && hb > 0.0) || (ha < 0.0 && hb < 0.0))
        hg = fmax(0.0, fmin(fabs(ha), fabs(hb)) - c->dh2 * w2 - c->slack);
    double ra = v_sqr(v_axpy(v_axpy(c->Cp, ca, c->Up), sa, c->Vp));
    double rb = v_sqr(v_axpy(v_axpy(c->Cp, cb, c->Up), sb, c->Vp)), d2 = c->drho2 * w2 + c->sq;
    double rg = fmax(0.0, sqrt(fmax(0.0, fmin(ra, rb) - d2)) - c->r);
    if (!c->disk) rg = fmax(rg, c->r - sqrt(fmax(ra, rb) + d2));
    return sqrt(hg * hg + rg * rg);
}

/* Y (a disk) lies within CD_CC_EQUI_ULPS eps L / 2 of a point of X's axis (arc_minima). */
static int disk_point_on_axis(const arcx *X, const cdist__circle *Y)
{
    vec3 d = v_sub(Y->c, X->c.c);
    double L = fmax(fmax(X->c.r, Y->r), v_norm(d));
    return 2.0 * (v_norm(v_cross(d, X->c.n)) + Y->r) <= CD_CC_EQUI_ULPS * DBL_EPSILON * L;
}

/* Every minimum of theta -> dist^2(X(theta), circle or disk Y) over X's range, handed to the
 * scan's candidate callback (s->cand, or the default offer). Uses the circle-circle critical
 * angles when available, else samples. *exact says which. For a disk, also the closed-form
 * angles where the height or its derivative vanishes (why: docs/curves.md, "arc–disk"); an angle
 * that falls in the other region is merely an extra candidate. */
static cdist_status arc_minima(cdist__cs_scan *s, const arcx *X, const cdist__circle *Y, int *exact, int *n_const)
{
    cdist_query *q = s->q;
    cdist_status st;
    int n = 0;
    if (n_const) *n_const = 0;
    s->ev = arc_eval;
    s->ctx = X;
    s->c = Y;
    s->frame_mag = fmax(v_norm(X->c.c), v_norm(Y->c));
    *exact = 0;
    if (X->end > X->start) {
        double th[CRIT_CAP];
        cdist__circle c0 = X->c, c1 = *Y;
        c1.c = v_sub(Y->c, X->c.c);
        c0.c = v3(0, 0, 0);
        n = cdist__circle_circle_critical(q, &c0, &c1, INFINITY, th, CRIT_CAP, NULL);
        double A = 0.0, B = 0.0, hc = 0.0, R = 0.0;
        if (s->disk) {
            A = X->c.r * v_dot(Y->n, X->U);
            B = X->c.r * v_dot(Y->n, X->V);
            hc = v_dot(Y->n, v_sub(X->c.c, Y->c));
            R = hypot(A, B);
        }
        /* A constant function with a candidate callback (arc-arc): every interior pair is a
         * global minimum of the two circles, and the set of X's angles whose closest point lies
         * in Y's range is bounded by angles where X or Y is at an endpoint; so the endpoint
         * candidates already hold its ends, and the caller decides the continuum (no scan). */
        if (n == -1 && s->cand && !s->disk) {
            if (n_const) *n_const = 1;
            *exact = 1;
            return CDIST_OK;
        }
        /* n == 0 (unavailable) or -1 (constant: the sampled scan sees a flat function, offers
         * it everywhere and the ties mark the continuum); for the disk also parallel planes
         * (h constant). */
        /* (n == CRIT_CAP may have been truncated: sample instead.) */
        if (n > 0 && n < CRIT_CAP && (!s->disk || R > CD_ARC_PARALLEL_ULPS * DBL_EPSILON * X->c.r)) {
            *exact = 1;
            /* th is in c0's library basis; the arc's angle 0 is U at library angle phi0. */
            for (int i = 0; i < n; i++)
                if ((st = polish_in_range(s, X, th[i] - X->phi0))) return st;
            if (s->disk) {
                double phi = atan2(B, A);
                if ((st = polish_in_range(s, X, phi)) || (st = polish_in_range(s, X, phi + M_PI))) return st;
                if (fabs(hc) <= R) {
                    double w = acos(-hc / R);
                    if ((st = polish_in_range(s, X, phi + w)) || (st = polish_in_range(s, X, phi - w))) return st;
                }
            }
            return CDIST_OK;
        }
    }
    s->k->flat_ties = 1;
    /* A disk within delta = e + r of a point of X's axis (e its centre's axis distance) is within
     * delta of its own rotations about that axis, so its distance varies by at most 2 delta
     * along X: constant to the circle-circle tolerance when 2 delta is within it, and answered
     * as the circle's constant case (certifying a constant function cannot end). */
    int flat = n == -1 && (!s->disk || disk_point_on_axis(X, Y));
    if (n_const) *n_const = flat;
    /* Certified unless the distance is known constant or the candidates go through a callback
     * (whose collector holds another function's minimum). */
    s->certify = !s->cand && !flat;
    s->speed_max = X->c.r;
    s->accel_max = X->c.r;
    s->accel_normal_max = X->c.r * v_norm(v_cross(Y->n, X->c.n));
    s->accel_plane_max = X->c.r;
    arc_lb_ctx lbc = arc_lb_init(X, Y, s->disk);
    s->lb = arc_lb;
    s->lb_ctx = &lbc;
    st = cdist__cs_scan_run(s, X->start, X->end, q->curve_samples);
    s->lb = NULL; /* lbc goes out of scope */
    return st;
}

/* The frame of arc A and circle C (A's circle, or another arc's): A's centre moves to the
 * origin (*origin, its old place) and both are scaled by 2^-e (exact), e from the problem scale;
 * the collector k starts at their scale. Returns e. */
static int arc_frame(arcx *A, cdist__circle *C, vec3 *origin, cdist__cs_coll *k)
{
    *origin = A->c.c;
    A->c.c = v3(0, 0, 0);
    C->c = v_sub(C->c, *origin);
    int e = cdist__scale_exponent(fmax(fmax(A->c.r, C->r), v_maxabs(C->c)));
    double down = cdist__pow2(-e);
    A->c.r *= down;
    C->r *= down;
    C->c = v_scale(down, C->c);
    cdist__cs_coll_init(k, fmax(fmax(A->c.r, C->r), v_dist(A->c.c, C->c)));
    return e;
}

/* ---- arc to circle / disk ---- */

/* The arc's parameters in r (which: 0 the first object, 1 the second) back in the caller's
 * range when check_arc took the start modulo 2 pi. */
static cdist_status arc_params_back(cdist_status st, const arcx *x, cdist_result *r, int which)
{
    if (st || x->start == x->user_start) return st;
    for (int i = 0; i < r->num_pairs; i++) {
        double t = r->pairs[i].param[which];
        if (t == t) r->pairs[i].param[which] = fmin(fmax(x->user_start + (t - x->start), x->user_start), x->user_end);
    }
    return st;
}

static cdist_status arc_target(cdist_query *q, const void *obj, const cdist_circle *c, cdist_result *r, int disk)
{
    const cdist_arc *a = obj;
    cdist_status st;
    arcx A;
    cdist__circle C;
    if ((st = check_arc(q, a, "arc", &A)) || (st = cdist__check_circle(q, c, disk ? "disk" : "circle", &C))) return st;
    vec3 origin;
    cdist__cs_coll k;
    int e = arc_frame(&A, &C, &origin, &k);
    if (A.c.r == 0.0) {
        cdist__cs_offer_point(&k, A.c.c, NAN, &C, disk, 0);
    } else {
        cdist__cs_scan s = {.q = q, .ev = arc_eval, .ctx = &A, .c = &C, .disk = disk, .k = &k};
        /* Endpoints always; then the interior minima. */
        cdist__cs_offer_point(&k, arc_point(&A, A.start), A.start, &C, disk, 0);
        cdist__cs_offer_point(&k, arc_point(&A, A.end), A.end, &C, disk, 0);
        int exact, constant;
        if ((st = arc_minima(&s, &A, &C, &exact, &constant))) return st;
        if (!exact && (st = cdist__cs_flat_check(&s, A.start, A.end, (A.end - A.start) / q->curve_samples))) return st;
        /* The circle-circle function is constant (within its own tolerance, as
         * cdist_circle_circle flags it): every arc point is closest. */
        if (constant && A.end > A.start) k.b.equidistant = 1;
    }
    return arc_params_back(cdist__cs_coll_result(&k, cdist__pow2(e), origin, r), &A, r, 0);
}

cdist_status cdist_arc_circle(cdist_query *q, const cdist_arc *a, const cdist_circle *c, cdist_result *r)
{
    return cdist__cs_entry(q, arc_target, a, c, r, 0);
}

cdist_status cdist_arc_disk(cdist_query *q, const cdist_arc *a, const cdist_circle *d, cdist_result *r)
{
    return cdist__cs_entry(q, arc_target, a, d, r, 1);
}

/* ---- arc to arc ---- */

/* Arcs on coaxial circles (parallel normals, centres on one axis, within CD_ARC_COAXIAL_ULPS):
 * the distance between the circles is constant, every pair at one azimuth is closest. Offers
 * the pair at the first azimuth the two ranges share (the distance in closed form when the
 * circles are exactly coaxial, 0 for the same circle) and flags the continuum when they share
 * an interval. Returns 0 when the circles are not coaxial. */
static int coaxial_offer(cdist__cs_coll *k, const arcx *A, const arcx *B)
{
    vec3 n = A->c.n, d = v_sub(B->c.c, A->c.c);
    double sn = v_norm(v_cross(n, B->c.n)), h = v_dot(n, d);
    double e = v_norm(v_sub(d, v_scale(h, n)));
    if (!(sn <= CD_ARC_COAXIAL_ULPS * DBL_EPSILON && e <= CD_ARC_COAXIAL_ULPS * DBL_EPSILON * k->b.scale)) return 0;
    double sg = v_dot(n, B->c.n) > 0.0 ? 1.0 : -1.0;
    /* B's angle phi is A's angle delta + sg phi. */
    double delta = atan2(v_dot(A->V, B->U), v_dot(A->U, B->U));
    double y0 = sg > 0 ? delta + B->start : delta - B->end, len = B->end - B->start;
    double a = A->start + fmod(y0 - A->start, TWO_PI);
    if (a < A->start) a += TWO_PI;
    double th = NAN, shared = 0.0;
    if (a <= A->end) {
        th = a;
        shared += fmin(a + len, A->end) - a;
    }
    if (a + len - TWO_PI >= A->start) {
        th = A->start;
        shared += fmin(a + len - TWO_PI, A->end) - A->start;
    }
    if (th != th) return 1; /* no shared azimuth: the endpoints hold the minimum */
    double ct = cos(th), st = sin(th);
    vec3 radial = v_axpy(v_scale(ct, A->U), st, A->V);
    vec3 P = v_axpy(A->c.c, A->c.r, radial), Q = v_axpy(B->c.c, B->c.r, radial);
    double phi = sg * (th - delta);
    phi = B->start + fmod(phi - B->start, TWO_PI);
    if (phi < B->start) phi += TWO_PI;
    double dr = B->c.r - A->c.r;
    double d2 = (sn == 0.0 && e == 0.0) ? h * h + dr * dr : v_sqr(v_sub(Q, P));
    cdist__cs_coll_offer(k, d2, P, Q, th, fmin(phi, B->end), shared > 0.0);
    return 1;
}

static cdist_status arc_arc(cdist_query *q, const cdist_arc *a0, const cdist_arc *a1, cdist_result *r)
{
    cdist_status st;
    arcx A, B;
    if ((st = check_arc(q, a0, "first arc", &A)) || (st = check_arc(q, a1, "second arc", &B))) return st;
    vec3 origin;
    cdist__cs_coll k;
    int e = arc_frame(&A, &B.c, &origin, &k);
    /* The four endpoint-to-arc distances (a radius-0 arc is its centre). */
    if (A.c.r == 0.0) offer_point_arc(&k, A.c.c, NAN, &B, 1, 1);
    else {
        offer_point_arc(&k, arc_point(&A, A.start), A.start, &B, 1, 1);
        offer_point_arc(&k, arc_point(&A, A.end), A.end, &B, 1, 1);
    }
    if (B.c.r == 0.0) offer_point_arc(&k, B.c.c, NAN, &A, 0, 1);
    else {
        offer_point_arc(&k, arc_point(&B, B.start), B.start, &A, 0, 1);
        offer_point_arc(&k, arc_point(&B, B.end), B.end, &A, 0, 1);
    }
    /* Interior pairs, from both sides. */
    if (A.c.r > 0.0 && B.c.r > 0.0) {
        int exact, const_a, const_b;
        cand_arc_ctx ca = {&B, 1}, cb = {&A, 0};
        cdist__cs_scan s = {.q = q, .ev = arc_eval, .ctx = &A, .c = &B.c, .k = &k, .cand = cand_arc, .cand_ctx = &ca};
        if ((st = arc_minima(&s, &A, &B.c, &exact, &const_a))) return st;
        cdist__cs_scan t = {.q = q, .ev = arc_eval, .ctx = &B, .c = &A.c, .k = &k, .cand = cand_arc, .cand_ctx = &cb};
        if ((st = arc_minima(&t, &B, &A.c, &exact, &const_b))) return st;
        if ((const_a || const_b) && !coaxial_offer(&k, &A, &B)) {
            /* constant but not coaxial (a circle through the other's centre, linked): sample */
            k.flat_ties = 1;
            if ((st = cdist__cs_scan_run(&s, A.start, A.end, q->curve_samples)) ||
                (st = cdist__cs_scan_run(&t, B.start, B.end, q->curve_samples)))
                return st;
        }
    }
    return arc_params_back(arc_params_back(cdist__cs_coll_result(&k, cdist__pow2(e), origin, r), &A, r, 0), &B, r,
                           1);
}

/* ---- segment to arc ---- */

typedef struct seg_x {
    vec3 p0, m;
} seg_x;

static cdist_status seg_eval(cdist_query *q, const void *ctx, double t, vec3 *p, vec3 *dp)
{
    (void)q;
    const seg_x *g = ctx;
    *p = v_axpy(g->p0, t, g->m);
    *dp = g->m;
    return CDIST_OK;
}

static cdist_status segment_arc(cdist_query *q, const cdist_segment *sg, const cdist_arc *a, cdist_result *r)
{
    cdist_status st;
    if ((st = cdist__check_segment(q, sg))) return st;
    arcx A;
    if ((st = check_arc(q, a, "arc", &A))) return st;
    vec3 origin = A.c.c;
    A.c.c = v3(0, 0, 0);
    seg_x S = {v_sub(sg->p0, origin), v_sub(sg->p1, sg->p0)};
    vec3 S1 = v_sub(sg->p1, origin);
    int e = cdist__scale_exponent(fmax(A.c.r, fmax(v_maxabs(S.p0), v_maxabs(S1))));
    double down = cdist__pow2(-e);
    A.c.r *= down;
    S.p0 = v_scale(down, S.p0);
    S.m = v_scale(down, S.m);
    S1 = v_scale(down, S1);
    cdist__cs_coll k;
    cdist__cs_coll_init(&k, fmax(A.c.r, fmax(v_norm(S.p0), v_norm(S1))));
    /* Segment endpoints to the arc. */
    offer_point_arc(&k, S.p0, 0.0, &A, 1, 1);
    offer_point_arc(&k, S1, 1.0, &A, 1, 1);
    double mm = v_sqr(S.m);
    /* Arc endpoints (the centre of a radius-0 arc) to the segment (closed form). */
    for (int e = 0; e < 2; e++) {
        double ang = A.c.r > 0.0 ? (e ? A.end : A.start) : NAN;
        vec3 E = A.c.r > 0.0 ? arc_point(&A, ang) : A.c.c;
        if (A.c.r == 0.0 && e) break;
        double s = mm > 0.0 ? v_dot(v_sub(E, S.p0), S.m) / mm : 0.0;
        s = s < 0.0 ? 0.0 : (s > 1.0 ? 1.0 : s);
        vec3 P = s == 1.0 ? S1 : v_axpy(S.p0, s, S.m);
        cdist__cs_coll_offer(&k, v_sqr(v_sub(P, E)), P, E, s, ang, 0);
    }
    /* Interior: minima of s -> dist^2(seg(s), circle) within r/|M| of the foot. */
    if (mm > 0.0 && A.c.r > 0.0) {
        double len = sqrt(mm);
        double foot = -v_dot(S.p0, S.m) / mm;
        double half = A.c.r / len * (1.0 + CD_SEG_ARC_WINDOW_REL) + CD_SEG_ARC_WINDOW_ULPS * DBL_EPSILON * (v_norm(S.p0) / len + 1.0);
        double lo = fmax(0.0, foot - half), hi = fmin(1.0, foot + half);
        if (lo <= hi) {
            cand_arc_ctx ca = {&A, 1};
            cdist__cs_scan s = {.q = q, .ev = seg_eval, .ctx = &S, .c = &A.c, .k = &k, .cand = cand_arc,
                                .cand_ctx = &ca, .frame_mag = fmax(v_norm(S.p0), v_norm(S1))};
            /* The local minima of the segment's distance to the full circle in the window, from
             * the lines family's robust (GSL-free) core on the line through the foot, each
             * polished on the true derivative and offered when its circle point is in range. */
            cdist__best lm;
            cdist__best_init(&lm, k.b.scale);
            vec3 M = v_scale(1.0 / len, S.m), B = v_axpy(S.p0, foot, S.m);
            st = cdist__linear_circle_ex(q, CDIST_METHOD_ROBUST, B, M, (lo - foot) * len, (hi - foot) * len, &A.c, &lm,
                                     NULL);
            if (st == CDIST_OK) {
                for (int i = 0; i < lm.n; i++) {
                    double t = fmin(fmax(foot + lm.c[i].param[0] / len, lo), hi);
                    if ((st = cdist__cs_polish(&s, t, lo, hi))) return st;
                }
            } else if ((st = cdist__cs_scan_run(&s, lo, hi, q->curve_samples))) {
                return st;
            }
        }
    }
    return arc_params_back(cdist__cs_coll_result(&k, cdist__pow2(e), origin, r), &A, r, 1);
}

/* Lexicographic order of two arcs' numbers (circle, zero direction, start, end): 1 when a comes
 * first. */
static int arc_less(const cdist_arc *a, const cdist_arc *b)
{
    if (cdist__circle_less(&a->circle, &b->circle)) return 1;
    if (cdist__circle_less(&b->circle, &a->circle)) return 0;
    const double va[5] = {a->zero_direction.x, a->zero_direction.y, a->zero_direction.z, a->start, a->end};
    const double vb[5] = {b->zero_direction.x, b->zero_direction.y, b->zero_direction.z, b->start, b->end};
    for (int i = 0; i < 5; i++)
        if (va[i] != vb[i]) return va[i] < vb[i];
    return 0;
}

/* The arcs are taken in lexicographic order, so f(a, b) and f(b, a) are the same computation:
 * the frame, the scale and every near-tie decision (equidistant flag, pair count) do not depend
 * on the argument order. */
cdist_status cdist_arc_arc(cdist_query *q, const cdist_arc *a0, const cdist_arc *a1, cdist_result *r)
{
    cdist_status st = cdist__enter(q, r);
    if (st) return st;
    if (a0 && a1 && arc_less(a1, a0)) {
        st = arc_arc(q, a1, a0, r);
        if (st == CDIST_OK) cdist__result_swap(r);
    } else {
        st = arc_arc(q, a0, a1, r);
    }
    return cdist__leave(q, r, st, CDIST_METHOD_ROBUST);
}

cdist_status cdist_segment_arc(cdist_query *q, const cdist_segment *sg, const cdist_arc *a, cdist_result *r)
{
    cdist_status st = cdist__enter(q, r);
    if (st) return st;
    return cdist__leave(q, r, segment_arc(q, sg, a, r), CDIST_METHOD_ROBUST);
}
