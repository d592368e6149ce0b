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
    }
    return CDIST_ERR_BAD_KIND;
}

#endif
