/* SPDX-License-Identifier: MIT */
/* Swept objects and gradients: shared between swept.c and grad.c. Built on the public API;
 * from the internals only validation/status recording (internal.h) and vec.h are used. */
#ifndef CDIST_SWEPT_PRIV_H
#define CDIST_SWEPT_PRIV_H

#include "internal.h"

struct cdist_grad; /* public header, gradient section */

/* The core of an object: what a swept object sweeps, or the plain object itself. */
typedef enum cdist__core_type {
    CD_CORE_POINT,
    CD_CORE_SEGMENT,
    CD_CORE_LINE,
    CD_CORE_RAY,
    CD_CORE_CIRCLE,
    CD_CORE_DISK,
    CD_CORE_ARC
} cdist__core_type;

typedef struct cdist__core_obj {
    cdist__core_type type;
    const void *obj; /* cdist_vec3, cdist_segment, cdist_line, cdist_ray, cdist_circle, cdist_arc */
    double radius;   /* the ball radius (0 for a plain object) */
    int swept;       /* 1 for a swept object (its radius is an input) */
} cdist__core_obj;

/* The core of a swept object (its radius read only when the object is given: a NULL object
 * stays NULL so that the query reports it), and a plain object as its own core. */
static inline cdist__core_obj cdist__swept_core(cdist__core_type type, const void *core, const double *radius)
{
    cdist__core_obj o = {type, core, core ? *radius : 0.0, 1};
    return o;
}
static inline cdist__core_obj cdist__plain_core(cdist__core_type type, const void *obj)
{
    cdist__core_obj o = {type, obj, 0.0, 0};
    return o;
}
/* The core of each object type of the contact kinds (src/api/kinds.def; a swept struct starts
 * with its core). */
#define CD_SWEPT_TORUS(x) cdist__swept_core(CD_CORE_CIRCLE, (x) ? &(x)->circle : NULL, (x) ? &(x)->tube_radius : NULL)
#define CD_SWEPT_CAPSULE(x) cdist__swept_core(CD_CORE_SEGMENT, (x) ? &(x)->segment : NULL, (x) ? &(x)->radius : NULL)
#define CD_SWEPT_SPHERE(x) cdist__swept_core(CD_CORE_POINT, (x) ? &(x)->center : NULL, (x) ? &(x)->radius : NULL)
#define CD_SWEPT_RDISK(x) cdist__swept_core(CD_CORE_DISK, (x) ? &(x)->disk : NULL, (x) ? &(x)->radius : NULL)
#define CD_SWEPT_LINE(x) cdist__plain_core(CD_CORE_LINE, x)
#define CD_SWEPT_RAY(x) cdist__plain_core(CD_CORE_RAY, x)
#define CD_SWEPT_SEGMENT(x) cdist__plain_core(CD_CORE_SEGMENT, x)
#define CD_SWEPT_CIRCLE(x) cdist__plain_core(CD_CORE_CIRCLE, x)
#define CD_SWEPT_DISK(x) cdist__plain_core(CD_CORE_DISK, x)

/* The core query between a and b (any order: a missing order is answered swapped). */
cdist_status cdist__core_query(cdist_query *q, const cdist__core_obj *a, const cdist__core_obj *b, cdist_result *r);
/* The cores touch at pair i of r: their distance within the rounding of the points'
 * coordinates (CD_CONTACT_TOUCH_ULPS), or the two points equal. */
static inline int cdist__cores_touch(const cdist_result *r, int i)
{
    vec3 p = r->pairs[i].point[0], q = r->pairs[i].point[1];
    return !(r->distance > CD_CONTACT_TOUCH_ULPS * DBL_EPSILON * cdist__fmax(v_maxabs(p), v_maxabs(q))) ||
           v_maxabs(v_sub(q, p)) == 0.0;
}

/* A swept query: validates the radii, answers the core query, writes the contact. core
 * (may be NULL) receives the core result. */
cdist_status cdist__swept_query(cdist_query *q, const cdist__core_obj *a, const cdist__core_obj *b, cdist_contact *c,
                            cdist_result *core);
/* The radius passes the swept query's check (finite, >= 0, <= CD_MAX_ABS; one comparison each,
 * false for NaN), or the object has none. */
static inline int cdist__radius_valid(const cdist__core_obj *o)
{
    return !o->swept || (o->radius >= 0.0 && o->radius <= CD_MAX_ABS);
}
/* Both objects given with valid radii: the contact follows from the core query's answer. */
static inline int cdist__contact_ready(const cdist__core_obj *a, const cdist__core_obj *b)
{
    return a->obj && b->obj && cdist__radius_valid(a) && cdist__radius_valid(b);
}
/* The contact c of a swept query whose core query answered r with CDIST_OK (contact ready). */
void cdist__contact_of_core(const cdist__core_obj *a, const cdist__core_obj *b, const cdist_result *r, cdist_contact *c);
/* cdist__swept_query(q, a, b, c, core) for a contact c given, when the core query has already
 * answered (status st, *core): the same contact and status, to the bit. */
cdist_status cdist__contact_of_core_query(cdist_query *q, const cdist__core_obj *a, const cdist__core_obj *b,
                                          cdist_status st, cdist_result *core, cdist_contact *c);
/* A contact in the error state (NaN, no pairs, flags 0). */
void cdist__contact_set_error(cdist_contact *c);
/* Unit tangent of a curve core at its point X of parameter t (0 for points and disks, or where
 * undefined); *interior (when not NULL): X is not an end of a segment, ray or arc. */
vec3 cdist__core_tangent(const cdist__core_obj *o, vec3 X, double t, int *interior);
/* Fill g from the core result r (the query succeeded). */
void cdist__grad_fill(const cdist__core_obj *a, const cdist__core_obj *b, const cdist_result *r, struct cdist_grad *g);
/* Gradient in the error state (all NaN, flags 0). */
void cdist__grad_set_error(struct cdist_grad *g);

#endif
