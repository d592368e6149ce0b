/* SPDX-License-Identifier: MIT */
/* The one evaluator of the circles family: a point P(t) moving on a circle A, seen from a circle
 * B (radius s, unit normal m, centre C): its squared distance F(t) to B and the derivatives
 * (formulas: docs/circles.md, "The robust method"), from the trigonometric coefficients of
 *     w(t) = m x (P(t) - C) = al cos t + be sin t + ga     (offset from B's axis, |w| = rho)
 *     h(t) = m . (P(t) - C) = ha cos t + hb sin t + hc     (height over B's plane).
 * Circle-disk forms its point-disk distance (h^2 where the point projects into the disk) itself.
 * Plain arithmetic, no fma(): without -mfma fma() is a libm call, and every caller recomputes
 * its final distances separately. */
#ifndef CDIST_RING_EVAL_H
#define CDIST_RING_EVAL_H

#include <math.h>

#include "base/vec.h"

/* Trigonometric coefficients of w and h (above) for one pair (A moving, B fixed). */
typedef struct cdist__ring {
    vec3 al, be, ga;
    double ha, hb, hc;
} cdist__ring;

/* Values at one angle; the caller asks for an order: 0 (F), 1 (also F'/2), 2 (also F''/2). */
typedef struct cdist__ring_val {
    vec3 w, w1;         /* w, w' (from cdist__ring_eval) */
    double Q, g, g1;    /* rho^2 = w.w, w.w', (w.w')' = w'.w' + w.w'' */
    double h, h1, h2;   /* h, h', h'' */
    double rho, dr;     /* rho, rho - s */
    double F, F1, F2;   /* F, F'/2, F''/2 */
} cdist__ring_val;

/* The distance part: rho, F and its derivatives from Q, g, g1, h, h1, h2 (set by the caller up
 * to the order asked). */
static inline void cdist__ring_dist(cdist__ring_val *v, double s, int order)
{
    double rho = sqrt(v->Q), dr = rho - s;
    v->rho = rho;
    v->dr = dr;
    v->F = dr * dr + v->h * v->h;
    if (order < 1) return;
    double rp = rho > 0 ? v->g / rho : 0.0;
    v->F1 = dr * rp + v->h * v->h1;
    if (order < 2) return;
    double rpp = rho > 0 ? (v->g1 - rp * rp) / rho : 0.0;
    v->F2 = rp * rp + dr * rpp + v->h1 * v->h1 + v->h * v->h2;
}

static inline double cdist__ring_dot(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

/* Everything up to `order` at angle t given (c, sn) = (cos t, sin t). */
static inline void cdist__ring_eval(const cdist__ring *r, double s, double c, double sn, int order, cdist__ring_val *v)
{
    v->w.x = r->al.x * c + r->be.x * sn + r->ga.x;
    v->w.y = r->al.y * c + r->be.y * sn + r->ga.y;
    v->w.z = r->al.z * c + r->be.z * sn + r->ga.z;
    v->Q = cdist__ring_dot(v->w, v->w);
    v->h = r->ha * c + r->hb * sn + r->hc;
    if (order >= 1) {
        v->w1.x = r->be.x * c - r->al.x * sn;
        v->w1.y = r->be.y * c - r->al.y * sn;
        v->w1.z = r->be.z * c - r->al.z * sn;
        v->g = cdist__ring_dot(v->w, v->w1);
        v->h1 = r->hb * c - r->ha * sn;
    }
    if (order >= 2) {
        v->g1 = cdist__ring_dot(v->w1, v->w1) + cdist__ring_dot(v->w, r->ga) - v->Q; /* w'' = ga - w */
        v->h2 = r->hc - v->h;
    }
    cdist__ring_dist(v, s, order);
}

#endif
