/* SPDX-License-Identifier: MIT */
/* The single query of one batch entry, written independently of the library's kind table
 * (for the batch test and benchmark). */
#ifndef CDIST_TEST_BATCH_SINGLE_H
#define CDIST_TEST_BATCH_SINGLE_H

#include "circledist.h"

static inline cdist_status single(cdist_query *q, cdist_kind k, const void *a, const void *b, cdist_result *r)
{
    switch (k) {
    case CDIST_KIND_POINT_CIRCLE: return cdist_point_circle(q, a, b, r);
    case CDIST_KIND_POINT_DISK: return cdist_point_disk(q, a, b, r);
    case CDIST_KIND_LINE_CIRCLE: return cdist_line_circle(q, a, b, r);
    case CDIST_KIND_RAY_CIRCLE: return cdist_ray_circle(q, a, b, r);
    case CDIST_KIND_SEGMENT_CIRCLE: return cdist_segment_circle(q, a, b, r);
    case CDIST_KIND_CIRCLE_CIRCLE: return cdist_circle_circle(q, a, b, r);
    case CDIST_KIND_LINE_DISK: return cdist_line_disk(q, a, b, r);
    case CDIST_KIND_RAY_DISK: return cdist_ray_disk(q, a, b, r);
    case CDIST_KIND_SEGMENT_DISK: return cdist_segment_disk(q, a, b, r);
    case CDIST_KIND_CIRCLE_DISK: return cdist_circle_disk(q, a, b, r);
    case CDIST_KIND_DISK_DISK: return cdist_disk_disk(q, a, b, r);
    case CDIST_KIND_CURVE_CIRCLE: {
        const cdist_curve *c = a;
        return cdist_curve_circle(q, c->fn, c->user, c->t0, c->t1, b, r);
    }
    case CDIST_KIND_CURVE_DISK: {
        const cdist_curve *c = a;
        return cdist_curve_disk(q, c->fn, c->user, c->t0, c->t1, b, r);
    }
    case CDIST_KIND_ARC_CIRCLE: return cdist_arc_circle(q, a, b, r);
    case CDIST_KIND_ARC_ARC: return cdist_arc_arc(q, a, b, r);
    case CDIST_KIND_SEGMENT_ARC: return cdist_segment_arc(q, a, b, r);
    case CDIST_KIND_ARC_DISK: return cdist_arc_disk(q, a, b, r);
    case CDIST_KIND_HELIX_CIRCLE: return cdist_helix_circle(q, a, b, r);
    case CDIST_KIND_HELIX_DISK: return cdist_helix_disk(q, a, b, r);
    case CDIST_KIND_BEZIER3_CIRCLE: return cdist_bezier3_circle(q, a, b, r);
    case CDIST_KIND_BEZIER3_DISK: return cdist_bezier3_disk(q, a, b, r);
    default: break; /* contact kinds: single_contact() */
    }
    return CDIST_ERR_BAD_KIND;
}

/* The contact query of a contact kind (r: cdist_contact). */
static inline cdist_status single_contact(cdist_query *q, cdist_kind k, const void *a, const void *b, cdist_contact *r)
{
    switch (k) {
    case CDIST_KIND_TORUS_TORUS: return cdist_torus_torus(q, a, b, r);
    case CDIST_KIND_TORUS_CAPSULE: return cdist_torus_capsule(q, a, b, r);
    case CDIST_KIND_TORUS_SPHERE: return cdist_torus_sphere(q, a, b, r);
    case CDIST_KIND_TORUS_ROUNDED_DISK: return cdist_torus_rounded_disk(q, a, b, r);
    case CDIST_KIND_CAPSULE_CAPSULE: return cdist_capsule_capsule(q, a, b, r);
    case CDIST_KIND_CAPSULE_SPHERE: return cdist_capsule_sphere(q, a, b, r);
    case CDIST_KIND_CAPSULE_ROUNDED_DISK: return cdist_capsule_rounded_disk(q, a, b, r);
    case CDIST_KIND_SPHERE_SPHERE: return cdist_sphere_sphere(q, a, b, r);
    case CDIST_KIND_SPHERE_ROUNDED_DISK: return cdist_sphere_rounded_disk(q, a, b, r);
    case CDIST_KIND_ROUNDED_DISK_ROUNDED_DISK: return cdist_rounded_disk_rounded_disk(q, a, b, r);
    case CDIST_KIND_TORUS_LINE: return cdist_torus_line(q, a, b, r);
    case CDIST_KIND_TORUS_RAY: return cdist_torus_ray(q, a, b, r);
    case CDIST_KIND_TORUS_SEGMENT: return cdist_torus_segment(q, a, b, r);
    case CDIST_KIND_CAPSULE_CIRCLE: return cdist_capsule_circle(q, a, b, r);
    case CDIST_KIND_CAPSULE_DISK: return cdist_capsule_disk(q, a, b, r);
    case CDIST_KIND_SPHERE_CIRCLE: return cdist_sphere_circle(q, a, b, r);
    case CDIST_KIND_SPHERE_DISK: return cdist_sphere_disk(q, a, b, r);
    default: return CDIST_ERR_BAD_KIND;
    }
}

/* The _grad query of a kind (r: cdist_result, or cdist_contact for a contact kind). */
static inline cdist_status single_grad(cdist_query *q, cdist_kind k, const void *a, const void *b, void *r, cdist_grad *g)
{
    switch (k) {
    case CDIST_KIND_POINT_CIRCLE: return cdist_point_circle_grad(q, a, b, r, g);
    case CDIST_KIND_POINT_DISK: return cdist_point_disk_grad(q, a, b, r, g);
    case CDIST_KIND_LINE_CIRCLE: return cdist_line_circle_grad(q, a, b, r, g);
    case CDIST_KIND_RAY_CIRCLE: return cdist_ray_circle_grad(q, a, b, r, g);
    case CDIST_KIND_SEGMENT_CIRCLE: return cdist_segment_circle_grad(q, a, b, r, g);
    case CDIST_KIND_CIRCLE_CIRCLE: return cdist_circle_circle_grad(q, a, b, r, g);
    case CDIST_KIND_LINE_DISK: return cdist_line_disk_grad(q, a, b, r, g);
    case CDIST_KIND_RAY_DISK: return cdist_ray_disk_grad(q, a, b, r, g);
    case CDIST_KIND_SEGMENT_DISK: return cdist_segment_disk_grad(q, a, b, r, g);
    case CDIST_KIND_CIRCLE_DISK: return cdist_circle_disk_grad(q, a, b, r, g);
    case CDIST_KIND_DISK_DISK: return cdist_disk_disk_grad(q, a, b, r, g);
    case CDIST_KIND_ARC_CIRCLE: return cdist_arc_circle_grad(q, a, b, r, g);
    case CDIST_KIND_ARC_ARC: return cdist_arc_arc_grad(q, a, b, r, g);
    case CDIST_KIND_SEGMENT_ARC: return cdist_segment_arc_grad(q, a, b, r, g);
    case CDIST_KIND_ARC_DISK: return cdist_arc_disk_grad(q, a, b, r, g);
    case CDIST_KIND_TORUS_TORUS: return cdist_torus_torus_grad(q, a, b, r, g);
    case CDIST_KIND_TORUS_CAPSULE: return cdist_torus_capsule_grad(q, a, b, r, g);
    case CDIST_KIND_TORUS_SPHERE: return cdist_torus_sphere_grad(q, a, b, r, g);
    case CDIST_KIND_TORUS_ROUNDED_DISK: return cdist_torus_rounded_disk_grad(q, a, b, r, g);
    case CDIST_KIND_CAPSULE_CAPSULE: return cdist_capsule_capsule_grad(q, a, b, r, g);
    case CDIST_KIND_CAPSULE_SPHERE: return cdist_capsule_sphere_grad(q, a, b, r, g);
    case CDIST_KIND_CAPSULE_ROUNDED_DISK: return cdist_capsule_rounded_disk_grad(q, a, b, r, g);
    case CDIST_KIND_SPHERE_SPHERE: return cdist_sphere_sphere_grad(q, a, b, r, g);
    case CDIST_KIND_SPHERE_ROUNDED_DISK: return cdist_sphere_rounded_disk_grad(q, a, b, r, g);
    case CDIST_KIND_ROUNDED_DISK_ROUNDED_DISK: return cdist_rounded_disk_rounded_disk_grad(q, a, b, r, g);
    case CDIST_KIND_TORUS_LINE: return cdist_torus_line_grad(q, a, b, r, g);
    case CDIST_KIND_TORUS_RAY: return cdist_torus_ray_grad(q, a, b, r, g);
    case CDIST_KIND_TORUS_SEGMENT: return cdist_torus_segment_grad(q, a, b, r, g);
    case CDIST_KIND_CAPSULE_CIRCLE: return cdist_capsule_circle_grad(q, a, b, r, g);
    case CDIST_KIND_CAPSULE_DISK: return cdist_capsule_disk_grad(q, a, b, r, g);
    case CDIST_KIND_SPHERE_CIRCLE: return cdist_sphere_circle_grad(q, a, b, r, g);
    case CDIST_KIND_SPHERE_DISK: return cdist_sphere_disk_grad(q, a, b, r, g);
    default: return CDIST_ERR_BAD_KIND;
    }
}

#endif
