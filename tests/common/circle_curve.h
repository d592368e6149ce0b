/* SPDX-License-Identifier: MIT */
/* A circle as a cdist_curve_fn callback (t = angle), for curve tests and benchmarks. */
#ifndef CDIST_TEST_CIRCLE_CURVE_H
#define CDIST_TEST_CIRCLE_CURVE_H

#include <math.h>

#include "circledist.h"

typedef struct circ_curve {
    cdist_vec3 c, u, v; /* centre and in-plane basis */
    double r;
} circ_curve;

static inline int circ_fn(void *user, double t, cdist_vec3 *p, cdist_vec3 *d)
{
    const circ_curve *k = user;
    double s = sin(t), c = cos(t);
    p->x = k->c.x + k->r * (c * k->u.x + s * k->v.x);
    p->y = k->c.y + k->r * (c * k->u.y + s * k->v.y);
    p->z = k->c.z + k->r * (c * k->u.z + s * k->v.z);
    d->x = k->r * (-s * k->u.x + c * k->v.x);
    d->y = k->r * (-s * k->u.y + c * k->v.y);
    d->z = k->r * (-s * k->u.z + c * k->v.z);
    return 0;
}

/* The callback curve of circle c, in the basis of cdist_circle_basis(). */
static inline circ_curve circ_curve_of(const cdist_circle *c)
{
    circ_curve k;
    k.c = c->center;
    k.r = c->radius;
    cdist_circle_basis(c, &k.u, &k.v);
    return k;
}

#endif
