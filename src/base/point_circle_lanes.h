/* SPDX-License-Identifier: MIT */
/* The one point-to-circle evaluation, written over a lane type: the includer defines the lanes
 * (src/base/lanes/lanes_def.h) and includes lanes_vec.h before this file. No include guard: one
 * instance per lane width; the scalar instance and its vec3 form are src/base/point_circle.h.
 * For a point D relative to the centre of a circle of unit normal n and radius r:
 *     np = n x D (as v_cross),  h = n . D (as v_dot, fma),  q2 = |np|^2,  rho = sqrt(q2),
 *     dr = rho - r,  hh = h^2,  d2 = fma(dr, dr, hh) = the squared distance to the circle.
 * rho is the distance to the axis taken from the cross product: accurate near the axis, where
 * sqrt(|D|^2 - h^2) would cancel. */

typedef struct KN(pc_parts) {
    V np[3];
    V h, q2, rho, dr, hh, d2;
} KN(pc_parts);

CD_INLINE KN(pc_parts) KN(point_circle)(const V n[3], const V D[3], V r)
{
    KN(pc_parts) e;
    KN(cross)(n[0], n[1], n[2], D[0], D[1], D[2], &e.np[0], &e.np[1], &e.np[2]);
    e.h = KN(dot)(n[0], n[1], n[2], D[0], D[1], D[2]);
    e.q2 = KN(dot)(e.np[0], e.np[1], e.np[2], e.np[0], e.np[1], e.np[2]);
    e.rho = vsqrt(e.q2);
    e.dr = vsub(e.rho, r);
    e.hh = vmul(e.h, e.h);
    e.d2 = vfma(e.dr, e.dr, e.hh);
    return e;
}
