/* SPDX-License-Identifier: MIT */
/* Long double 3-vectors for the brute-force references of the tests (independent of the
 * library), and a circle's frame in them. Header-only; every function static. */
#ifndef CDIST_TEST_LD_H
#define CDIST_TEST_LD_H

#include <math.h>

#include "circledist.h"

typedef long double ld;
typedef struct { ld x, y, z; } lv;
static inline lv lvv(ld x, ld y, ld z) { lv r = {x, y, z}; return r; }
static inline lv lfrom(cdist_vec3 a) { return lvv(a.x, a.y, a.z); }
static inline lv ladd(lv a, lv b) { return lvv(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline lv lsub(lv a, lv b) { return lvv(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline lv lsc(ld s, lv a) { return lvv(s * a.x, s * a.y, s * a.z); }
static inline ld ldot(lv a, lv b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline lv lcross(lv a, lv b) { return lvv(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x); }
static inline ld lnorm(lv a) { return sqrtl(ldot(a, a)); }

/* A circle's centre relative to the double point O (exact in long double, so inputs far from
 * the coordinate origin keep their precision), its unit normal n and an orthonormal basis u, v
 * of its plane (any basis: the references sample whole circles). */
static inline void lframe(cdist_circle c, cdist_vec3 O, lv *centre, lv *n, lv *u, lv *v)
{
    *centre = lsub(lfrom(c.center), lfrom(O));
    *n = lsc(1 / lnorm(lfrom(c.normal)), lfrom(c.normal));
    lv e = fabsl(n->x) < 0.5L ? lvv(1, 0, 0) : lvv(0, 1, 0);
    *u = lsub(e, lsc(ldot(e, *n), *n));
    *u = lsc(1 / lnorm(*u), *u);
    *v = lcross(*n, *u);
}

#endif
