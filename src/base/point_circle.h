/* SPDX-License-Identifier: MIT */
/* The one point-to-circle evaluation (src/base/point_circle_lanes.h) for scalar code: its
 * one-lane instance on vec3, and the circle point closest to a point off the axis. */
#ifndef CDIST_BASE_POINT_CIRCLE_H
#define CDIST_BASE_POINT_CIRCLE_H

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "base/tolerances.h"
#include "base/vec.h"

/* The one-lane instance under its own names (CD_LANE1_KN), apart from any kernel's one-lane
 * instance in the same translation unit; a scalar body built on it is instantiated with
 * KN = CD_LANE1_KN after lanes_def.h (src/point/point.c). */
#define CD_LANE1_KN(name) cdist__##name##_lane1
#define CD_LANES 1
#include "base/lanes/lanes_def.h"
#undef KN
#define KN(name) CD_LANE1_KN(name)
#include "base/lanes/lanes_vec.h"
#include "base/point_circle_lanes.h"
#include "base/lanes/lanes_undef.h"

/* D relative to the centre of a circle of unit normal n and radius r: n x D, the height h, the
 * axis distance rho (q2 = rho^2), rho - r, h^2 and the squared distance d2 to the circle. */
typedef struct cdist__pc_parts {
    vec3 np;
    double h, q2, rho, dr, hh, d2;
} cdist__pc_parts;

CD_INLINE cdist__pc_parts cdist__pc_parts_of_lane(const cdist__pc_parts_lane1 *e)
{
    cdist__pc_parts o = {v3(e->np[0], e->np[1], e->np[2]), e->h, e->q2, e->rho, e->dr, e->hh, e->d2};
    return o;
}

CD_INLINE cdist__pc_parts cdist__point_circle(vec3 n, vec3 D, double r)
{
    const double nk[3] = {n.x, n.y, n.z}, Dk[3] = {D.x, D.y, D.z};
    cdist__pc_parts_lane1 e = cdist__point_circle_lane1(nk, Dk, r);
    return cdist__pc_parts_of_lane(&e);
}

/* The in-plane part of D, w = (n x D) x n: perpendicular to n and accurate in direction even
 * within a few ulps of the axis, where D - h n would cancel. */
CD_INLINE vec3 cdist__pc_inplane(vec3 np, vec3 n) { return v_cross(np, n); }

/* The point at distance r from the centre along the in-plane direction w (w != 0): r w / |w|.
 * |w|, not rho: near the axis the rounding of n x D leaves np slightly off perpendicular to n,
 * and only w (which is perpendicular) scaled by its own length lands on the circle. Where w's
 * squares would be subnormal (largest component below CD_MIN_NORMAL_FAST, a point within about
 * 1e-150 of the scale from the axis) a copy divided by its largest component is normalised. */
CD_INLINE vec3 cdist__pc_along(vec3 w, double r)
{
    vec3 ws = w;
    double m = v_maxabs(w);
    if (m < CD_MIN_NORMAL_FAST) ws = v3(w.x / m, w.y / m, w.z / m);
    return v_scale(r / v_norm(ws), ws);
}

#endif
