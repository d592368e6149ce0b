/* SPDX-License-Identifier: MIT */
/* Long double 3-vectors for the brute-force references of the tests (independent of the
 * library), and a circle's frame in them. Header-only; every function static inline. */
#ifndef CDIST_TEST_LD_H
#define CDIST_TEST_LD_H

#include <math.h>

#include "circledist.h"

typedef long double ld;
typedef struct lv {
    ld x, y, z;
} lv;

static inline lv lv3(ld x, ld y, ld z) { lv r = {x, y, z}; return r; }
static inline lv lv_of(cdist_vec3 a) { return lv3(a.x, a.y, a.z); }
static inline lv lv_add(lv a, lv b) { return lv3(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline lv lv_sub(lv a, lv b) { return lv3(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline lv lv_scale(ld s, lv a) { return lv3(s * a.x, s * a.y, s * a.z); }
static inline ld lv_dot(lv a, lv b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline lv lv_cross(lv a, lv b) { return lv3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x); }
static inline ld lv_norm(lv a) { return sqrtl(lv_dot(a, a)); }
static inline lv lv_unit(lv a) { return lv_scale(1.0L / lv_norm(a), a); }

/* A circle's centre relative to the double point O (exact in long double, so inputs far from
 * the coordinate origin keep their precision), its unit normal n and an orthonormal basis u, v
 * of its plane (any basis: the references sample whole circles). */
static inline void lv_frame(cdist_circle c, cdist_vec3 O, lv *centre, lv *n, lv *u, lv *v)
{
    *centre = lv_sub(lv_of(c.center), lv_of(O));
    *n = lv_unit(lv_of(c.normal));
    lv e = fabsl(n->x) < 0.5L ? lv3(1, 0, 0) : lv3(0, 1, 0);
    *u = lv_unit(lv_sub(e, lv_scale(lv_dot(e, *n), *n)));
    *v = lv_cross(*n, *u);
}

#endif
