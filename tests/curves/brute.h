/* SPDX-License-Identifier: MIT */
/* Independent brute-force references for the curve tests, in 80-bit long double: closed-form
 * point-to-circle/disk/arc/segment distances, and one-parameter minimisation by dense sampling
 * plus golden-section polishing of every sampled local minimum. Nothing here calls the library
 * except for reading the documented basis of a circle (not needed: frames are rebuilt here). */
#ifndef CURVE_BRUTE_H
#define CURVE_BRUTE_H

#include <math.h>

#include "check.h"
#include "test_ld.h"

typedef struct bf_circle {
    lv c, n;
    ld r;
} bf_circle;

static inline bf_circle bf_circ(cdist_circle c)
{
    bf_circle o = {lv_of(c.center), lv_unit(lv_of(c.normal)), c.radius};
    return o;
}

static inline ld bf_point_circle(lv p, const bf_circle *c)
{
    lv d = lv_sub(p, c->c);
    ld h = lv_dot(c->n, d), rho = lv_norm(lv_cross(c->n, d));
    return sqrtl((rho - c->r) * (rho - c->r) + h * h);
}

static inline ld bf_point_disk(lv p, const bf_circle *c)
{
    lv d = lv_sub(p, c->c);
    ld h = lv_dot(c->n, d), rho = lv_norm(lv_cross(c->n, d));
    if (rho <= c->r) return fabsl(h);
    return sqrtl((rho - c->r) * (rho - c->r) + h * h);
}

typedef struct bf_arc {
    bf_circle c;
    lv u, v;
    ld a0, a1;
} bf_arc;

static inline bf_arc bf_arc_of(const cdist_arc *a)
{
    bf_arc o;
    o.c = bf_circ(a->circle);
    lv z = lv_of(a->zero_direction);
    o.u = lv_unit(lv_sub(z, lv_scale(lv_dot(z, o.c.n), o.c.n)));
    o.v = lv_cross(o.c.n, o.u);
    o.a0 = a->start;
    o.a1 = a->end;
    return o;
}

static inline lv bf_arc_point(const bf_arc *a, ld t)
{
    return lv_add(a->c.c, lv_add(lv_scale(a->c.r * cosl(t), a->u), lv_scale(a->c.r * sinl(t), a->v)));
}

/* Point to arc: the closest circle point when its angle lies in [a0, a1], else an endpoint. */
static inline ld bf_point_arc(lv p, const bf_arc *a)
{
    ld best = fminl(lv_norm(lv_sub(p, bf_arc_point(a, a->a0))), lv_norm(lv_sub(p, bf_arc_point(a, a->a1))));
    lv d = lv_sub(p, a->c.c);
    ld x = lv_dot(a->u, d), y = lv_dot(a->v, d);
    if (x == 0 && y == 0) return fminl(best, bf_point_circle(p, &a->c));
    ld ang = atan2l(y, x);
    ld k = fmodl(ang - a->a0, 2 * 3.14159265358979323846264338327950288L);
    if (k < 0) k += 2 * 3.14159265358979323846264338327950288L;
    if (a->a0 + k <= a->a1) best = fminl(best, bf_point_circle(p, &a->c));
    return best;
}

static inline ld bf_point_segment(lv p, lv a, lv b)
{
    lv m = lv_sub(b, a);
    ld mm = lv_dot(m, m);
    ld s = mm > 0 ? lv_dot(lv_sub(p, a), m) / mm : 0;
    if (s < 0) s = 0;
    if (s > 1) s = 1;
    return lv_norm(lv_sub(p, lv_add(a, lv_scale(s, m))));
}

typedef ld (*bf_fn)(const void *ctx, ld t);

static inline ld bf_golden(bf_fn f, const void *ctx, ld a, ld b)
{
    const ld gr = 0.61803398874989484820458683436563811772L;
    ld x1 = b - gr * (b - a), x2 = a + gr * (b - a);
    ld f1 = f(ctx, x1), f2 = f(ctx, x2);
    for (int i = 0; i < 110; i++) {
        if (f1 < f2) {
            b = x2; x2 = x1; f2 = f1;
            x1 = b - gr * (b - a);
            f1 = f(ctx, x1);
        } else {
            a = x1; x1 = x2; f1 = f2;
            x2 = a + gr * (b - a);
            f2 = f(ctx, x2);
        }
    }
    return fminl(f1, f2);
}

/* Minimum of f over [t0, t1]: n samples, then golden section around each sampled local minimum. */
static inline ld bf_min1d(bf_fn f, const void *ctx, ld t0, ld t1, int n)
{
    if (!(t0 < t1)) return f(ctx, t0);
    ld prev2 = 0, prev = f(ctx, t0), best = prev;
    ld fend = f(ctx, t1);
    best = fminl(best, fend);
    for (int i = 1; i <= n; i++) {
        ld t = (i == n) ? t1 : t0 + (t1 - t0) * i / n;
        ld cur = (i == n) ? fend : f(ctx, t);
        /* sample i-1 is a local minimum (or the first sample going up) */
        if ((i == 1 && prev <= cur) || (i > 1 && prev <= prev2 && prev <= cur)) {
            ld a = t0 + (t1 - t0) * (i - 2 < 0 ? 0 : i - 2) / n, b = t;
            best = fminl(best, bf_golden(f, ctx, a, b));
        }
        if (i == n && cur <= prev) best = fminl(best, bf_golden(f, ctx, t0 + (t1 - t0) * (n - 1) / n, t1));
        prev2 = prev;
        prev = cur;
    }
    return best;
}

/* Distance from p to the axis of circle c. */
static inline ld bf_axis_dist(lv p, const bf_circle *c) { return lv_norm(lv_cross(c->n, lv_sub(p, c->c))); }

/* Where the curve passes (nearly) through a circle's axis, the distance to the circle can have a
 * dip as narrow as the closest approach (the kink -2 r rho of F rounded off: depth ~ 2 r rho_min,
 * width ~ rho_min / speed), far too narrow for sampling when the rest of F is flat (e.g. a
 * circle through the other's centre, linked so that F is constant in exact arithmetic). So:
 * find every local minimum of rho(t) (sampling + golden section; rho is V-shaped, not narrow),
 * and minimise f by golden section in a window of a few rho_min / speed around it. */
static inline ld bf_axis_dips(bf_fn f, bf_fn rho, const void *ctx, ld t0, ld t1, int n, ld speed)
{
    ld best = INFINITY;
    if (!(t0 < t1)) return best;
    ld prev2 = 0, prev = rho(ctx, t0);
    for (int i = 1; i <= n; i++) {
        ld t = (i == n) ? t1 : t0 + (t1 - t0) * i / n;
        ld cur = rho(ctx, t);
        if ((i == 1 && prev <= cur) || (i > 1 && prev <= prev2 && prev <= cur)) {
            ld a = t0 + (t1 - t0) * (i - 2 < 0 ? 0 : i - 2) / n, b = t;
            /* golden section on rho, keeping the location */
            const ld gr = 0.61803398874989484820458683436563811772L;
            ld x1 = b - gr * (b - a), x2 = a + gr * (b - a), f1 = rho(ctx, x1), f2 = rho(ctx, x2);
            for (int k = 0; k < 120; k++) {
                if (f1 < f2) { b = x2; x2 = x1; f2 = f1; x1 = b - gr * (b - a); f1 = rho(ctx, x1); }
                else { a = x1; x1 = x2; f1 = f2; x2 = a + gr * (b - a); f2 = rho(ctx, x2); }
            }
            ld ta = f1 < f2 ? x1 : x2, rmin = fminl(f1, f2);
            ld w = 20 * rmin / speed + 1e-18L * (fabsl(ta) + 1);
            ld lo = fmaxl(t0, ta - w), hi = fminl(t1, ta + w);
            best = fminl(best, f(ctx, ta));
            if (lo < hi) best = fminl(best, bf_golden(f, ctx, lo, hi));
        }
        prev2 = prev;
        prev = cur;
    }
    return best;
}

/* A helix against a circle or disk, in long double: its point at t and the point-circle/disk
 * distance there (the function bf_min1d minimises). */
typedef struct bf_helix {
    lv c, n, u, v;
    ld r, rise;
    bf_circle k;
    int disk;
} bf_helix;

static inline bf_helix bf_helix_of(const cdist_helix *h, const cdist_circle *c, int disk)
{
    bf_helix x;
    x.c = lv_of(h->center);
    x.n = lv_unit(lv_of(h->axis));
    lv z = lv_of(h->zero_direction);
    x.u = lv_unit(lv_sub(z, lv_scale(lv_dot(z, x.n), x.n)));
    x.v = lv_cross(x.n, x.u);
    x.r = h->radius;
    x.rise = (ld)h->pitch / (2 * 3.14159265358979323846264338327950288L);
    x.k = bf_circ(*c);
    x.disk = disk;
    return x;
}

static inline ld bf_f_helix(const void *p, ld t)
{
    const bf_helix *h = p;
    lv pt = lv_add(h->c, lv_add(lv_scale(h->r * cosl(t), h->u), lv_add(lv_scale(h->r * sinl(t), h->v), lv_scale(h->rise * t, h->n))));
    return h->disk ? bf_point_disk(pt, &h->k) : bf_point_circle(pt, &h->k);
}

/* A cubic Bezier curve against a circle or disk, in long double (the function bf_min1d minimises). */
typedef struct bf_bez {
    lv p[4];
    bf_circle k;
    int disk;
} bf_bez;

static inline lv bf_bez_point(const bf_bez *b, ld t)
{
    ld m = 1 - t;
    return lv_add(lv_add(lv_scale(m * m * m, b->p[0]), lv_scale(3 * m * m * t, b->p[1])),
                  lv_add(lv_scale(3 * m * t * t, b->p[2]), lv_scale(t * t * t, b->p[3])));
}

static inline ld bf_f_bez(const void *p, ld t)
{
    const bf_bez *b = p;
    lv pt = bf_bez_point(b, t);
    return b->disk ? bf_point_disk(pt, &b->k) : bf_point_circle(pt, &b->k);
}

#endif
