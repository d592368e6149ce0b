/* SPDX-License-Identifier: MIT */
/* Helix to circle and to disk: pieces of at most one turn scanned by the engine and certified,
 * turns skipped by a lower bound from the axial and radial geometry (docs/curves.md, "Helix"). */
#include <math.h>

#include "curve_scan.h"

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

CD_FMA_CLONES static cdist_status helix_eval(cdist_query *q, const void *ctx, double t, vec3 *p, vec3 *dp)
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
    double za = cdist__cs_min2(z0, z1), zb = cdist__cs_max2(z0, z1);
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

/* The sample count m of the pieces after the first, which cost first_cost evaluations at turn_n
 * samples; CDIST_ERR_COST_LIMIT at once when the pieces that may be scanned cannot be paid for
 * (the rule: docs/curves.md, "Cost bound"). */
static cdist_status helix_piece_samples(const cdist__cs_scan *s, const helix_x *hx, const helix_bound *hb, double t0,
                                        double plen, long pieces, long mid, int turn_n, long first_cost, int *m)
{
    double best = s->k->b.n ? sqrt(s->k->b.c[0].d2) : INFINITY;
    double margin = best - cdist__cs_cert_tol(s);
    long left = *s->evals_left;
    long limit = left / (CD_CURVE_HELIX_MIN_SAMPLES + 1 + CD_CURVE_HELIX_PIECE_EVALS), count = 0;
    for (long i = mid - 1; i >= 0 && count <= limit; i--, count++)
        if (helix_piece_lb(hb, hx, t0 + (double)i * plen, t0 + (double)(i + 1) * plen) >= margin) break;
    for (long i = mid + 1; i < pieces && count <= limit; i++, count++)
        if (helix_piece_lb(hb, hx, t0 + (double)i * plen, t0 + (double)(i + 1) * plen) >= margin) break;
    if (count > limit)
        return cdist__fail(s->q, CDIST_ERR_COST_LIMIT,
                           "helix: more than %ld turns are about equally close to the target (cost limit: %ld "
                           "evaluations)",
                           limit, s->evals_max);
    long each = first_cost > turn_n + 1 + CD_CURVE_HELIX_PIECE_EVALS ? first_cost
                                                                     : turn_n + 1 + CD_CURVE_HELIX_PIECE_EVALS;
    *m = turn_n;
    if (count * each > left && turn_n > CD_CURVE_HELIX_MIN_SAMPLES) *m = (int)CD_CURVE_HELIX_MIN_SAMPLES;
    return CDIST_OK;
}

/* Scan the pieces [t0 + i plen, t0 + (i+1) plen] (the last ending at t1) in order of increasing
 * lower bound, from the piece nearest the target axially outwards (the bound is unimodal in i:
 * the axial gap shrinks, stays 0 while the pieces overlap the target's range, then grows),
 * stopping on each side at the first piece that neither the certification nor a possible tie
 * needs. */
static cdist_status helix_pieces(cdist__cs_scan *s, const helix_x *hx, double t0, double plen, long pieces, double t1,
                                 int turn_n)
{
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
    int m = turn_n; /* samples per piece */
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
            double need = best - cdist__cs_cert_tol(s);
            double tie = best * (1.0 + CD_CURVE_HELIX_SKIP_REL) + CD_CURVE_HELIX_SKIP_ABS * s->k->b.scale;
            int tie_ok = (double)(ties + 1) * m <= CD_CURVE_HELIX_TIE_SAMPLES;
            if (!(blo < need || (tie_ok && blo <= tie))) done_lo = 1;
            if (!(bhi < need || (tie_ok && bhi <= tie))) done_hi = 1;
            if (done_lo && done_hi) break;
            if (!done_lo && (done_hi || blo <= bhi)) i = --lo;
            else i = ++hi;
            if ((i == lo ? blo : bhi) >= need) ties++;
        }
        double a = t0 + (double)i * plen, b = (i == pieces - 1) ? t1 : t0 + (double)(i + 1) * plen;
        long left = *s->evals_left;
        if ((st = cdist__cs_scan_run(s, a, b, m))) return st;
        if (i == mid && (st = helix_piece_samples(s, hx, &hb, t0, plen, pieces, mid, turn_n, left - *s->evals_left, &m)))
            return st;
    }
    return CDIST_OK;
}


/* Evaluations spent by the last helix query of this thread that reached the search. */
static _Thread_local long helix_last_evals;

static cdist_status helix_query(cdist_query *q, const void *obj, const cdist_circle *c, cdist_result *r, int disk)
{
    const cdist_helix *h = obj;
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
    /* A target within delta = e + r of a point P of the helix's axis (e its centre's axis
     * distance): |X(t) - P|^2 = hr^2 + (rise t - zP)^2 is least at t* = zP / rise clamped to the
     * range (anywhere for pitch 0, where it is constant), and the target's distance is within
     * delta of P's, so X(t*) is within 2 delta of the minimum: exact to the circle-circle
     * constancy tolerance when 2 delta is within it. The scan could not end there (a function
     * constant, or nearly so over many turns, certifies nothing). */
    /* (first a necessary condition without square roots: Lp <= sqrt(3) max(hr, |c_i|) or r = 0) */
    if (hx.r > 0.0 && cc.r <= CD_CC_EQUI_ULPS * DBL_EPSILON * fmax(hx.r, v_maxabs(hx.c)) &&
        2.0 * (v_norm(v_cross(hx.c, hx.n)) + cc.r) <=
            CD_CC_EQUI_ULPS * DBL_EPSILON * fmax(fmax(cc.r, hx.r), v_norm(hx.c))) {
        double ts = t0;
        if (hx.rise != 0.0) ts = fmin(fmax(-v_dot(hx.c, hx.n) / hx.rise, t0), t1);
        cdist__cs_offer_point(&k, helix_pos(&hx, ts), ts, &cc, disk, 0);
        if (hx.rise == 0.0 && t1 > t0) k.b.equidistant = 1;
        return cdist__cs_coll_result(&k, cdist__pow2(e), origin, r);
    }
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
    long evals_left = CD_CURVE_HELIX_MAX_EVALS;
    s.evals_left = &evals_left;
    s.evals_max = CD_CURVE_HELIX_MAX_EVALS;
    /* Samples per turn: the handle's count up to CD_CURVE_HELIX_TURN_SAMPLES (certified, the count
     * trades speed only; more would spend the budget on one turn). */
    int turn_n = q->curve_samples < CD_CURVE_HELIX_TURN_SAMPLES ? q->curve_samples : CD_CURVE_HELIX_TURN_SAMPLES;
    if (pieces == 1) st = cdist__cs_scan_run(&s, t0, t1, turn_n);
    else st = helix_pieces(&s, &hx, t0, plen, pieces, t1, turn_n);
    if (!st) st = cdist__cs_flat_check(&s, t0, t1, plen / q->curve_samples);
    helix_last_evals = CD_CURVE_HELIX_MAX_EVALS - evals_left;
    if (st) return st;
    return cdist__cs_coll_result(&k, cdist__pow2(e), origin, r);
}

long cdist__helix_last_evals(void) { return helix_last_evals; }

cdist_status cdist_helix_circle(cdist_query *q, const cdist_helix *h, const cdist_circle *c, cdist_result *r)
{
    return cdist__cs_entry(q, helix_query, h, c, r, 0);
}

cdist_status cdist_helix_disk(cdist_query *q, const cdist_helix *h, const cdist_circle *d, cdist_result *r)
{
    return cdist__cs_entry(q, helix_query, h, d, r, 1);
}
