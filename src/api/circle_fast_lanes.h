/* SPDX-License-Identifier: MIT */
/* cdist__circle_fast_body (src/api/api-priv.h) in lanes, with its arithmetic: the mask of the
 * circles (centre c, normal d, radius r) it accepts and their unit normals n. Included after
 * lanes_def.h and lanes_vec.h, once per lane width; no include guard. */

CD_INLINE M KN(circle_fast)(const V c[3], const V d[3], V r, double unit_tol, V n[3])
{
    const V one = vset(1.0);
    M ok = mand(KN(in_range)(c[0], c[1], c[2]), mand(vge(r, vset(0.0)), vle(r, vset(CD_MAX_ABS))));
    ok = mand(ok, mand(KN(in_range)(d[0], d[1], d[2]), vge(KN(max3)(d[0], d[1], d[2]), vset(CD_MIN_NORMAL_FAST))));
    V len = vsqrt(KN(dot)(d[0], d[1], d[2], d[0], d[1], d[2]));
    ok = mand(ok, vle(vabs(vsub(len, one)), vset(unit_tol)));
    V il = vdiv(one, len);
    /* written out: gcc vectorises a loop over the components into round trips through memory */
    n[0] = vmul(il, d[0]), n[1] = vmul(il, d[1]), n[2] = vmul(il, d[2]);
    return ok;
}
