/* SPDX-License-Identifier: MIT */
/* One instance of the circle-disk kernel's stages in lanes (src/batch/cd_kernel.c) for the lanes
 * the includer chose (CD_LANES), compiled for their instruction set: the candidates over the
 * disk's face of W entries at once (src/circles/cd_body.h, the single query's arithmetic) and the
 * rim search's frame. No include guard. */
#if CD_LANES == 8
CD_LANES_TARGET_PUSH("avx512f,fma")
#elif CD_LANES == 4
CD_LANES_TARGET_PUSH("avx2,fma")
#endif
#include "base/lanes/lanes_def.h"
#include "base/lanes/lanes_vec.h"
#include "circles/cd_body.h"
#include "circles/ring_lanes.h"

/* The circle c and disk d of the lanes in the frame of c's centre: d's centre, or with neg (the
 * other half of disk-disk, the circle c being the disk at C, d the one at the origin) -C;
 * lanes >= n repeat lane 0. */
CD_INLINE void KN(cd_load)(const cdist__circle *const *c, const cdist__circle *const *d, int neg, int n, V *D, V *dn,
                           V *du, V *dv, V *cu, V *cv, V *r, V *R)
{
    double col[17][W];
    for (int l = 0; l < W; l++) {
        const cdist__circle *a = c[l < n ? l : 0], *e = d[l < n ? l : 0];
        const double v[17] = {neg ? -a->c.x : e->c.x, neg ? -a->c.y : e->c.y, neg ? -a->c.z : e->c.z,
                              e->n.x, e->n.y, e->n.z, e->u.x, e->u.y, e->u.z, e->v.x, e->v.y, e->v.z,
                              a->u.x, a->u.y, a->u.z, a->v.x, a->v.y};
        for (int j = 0; j < 17; j++) col[j][l] = v[j];
    }
    for (int j = 0; j < 3; j++) {
        D[j] = vld(col[j]);
        dn[j] = vld(col[3 + j]);
        du[j] = vld(col[6 + j]);
        dv[j] = vld(col[9 + j]);
    }
    cu[0] = vld(col[12]), cu[1] = vld(col[13]), cu[2] = vld(col[14]);
    cv[0] = vld(col[15]), cv[1] = vld(col[16]);
    double z[W], rr[W], RR[W];
    for (int l = 0; l < W; l++) {
        z[l] = c[l < n ? l : 0]->v.z;
        rr[l] = c[l < n ? l : 0]->r;
        RR[l] = d[l < n ? l : 0]->r;
    }
    cv[2] = vld(z), *r = vld(rr), *R = vld(RR);
}

/* The lanes' values x[l] (l < n), lanes >= n repeating lane 0. */
CD_INLINE V KN(cd_vld)(const double *x, int n)
{
    double a[W];
    for (int l = 0; l < W; l++) a[l] = x[l < n ? l : 0];
    return vld(a);
}

/* The pairs (c[l], d[l]), l < n <= W, the circle in the disk's frame: with g not NULL, into
 * *g[l] that frame and into scale[l] the scale of the rim search's thresholds; with min not
 * NULL, the candidates over the face (cdk_height) into min[l], from min[l] on (INFINITY: the
 * query's own start; a distance attained elsewhere drops the candidates far above it, which
 * cannot be the answer). Returns the lanes the stages do not take (a zero radius, parallel
 * planes). */
static unsigned KN(cd_face)(const cdist__circle *const *c, const cdist__circle *const *d, int neg, const double *bscale,
                            int n, cdk_lanes_1 *const *g, double *scale, double *min)
{
    V D[3], dn[3], du[3], dv[3], cu[3], cv[3], r, R;
    KN(cd_load)(c, d, neg, n, D, dn, du, dv, cu, cv, &r, &R);
    KN(cdk_lanes) k;
    KN(cdk_lanes_init)(&k, D, dn, du, dv, cu, cv, r, R);
    M bad = mor(mor(veq(r, vset(0.0)), veq(R, vset(0.0))), KN(cdk_parallel)(&k));
    double f[13][W];
    if (min) {
        V m = KN(cd_vld)(min, n);
        KN(cdk_height)(&k, &m, KN(cd_vld)(bscale, n), NULL);
        vst(f[0], m);
        for (int l = 0; l < n; l++) min[l] = f[0][l];
    }
    if (!g) return mbits(bad) & ((1u << n) - 1u);
    const V s = KN(cdk_scale)(&k), *src[13] = {&s,       &k.X[0], &k.X[1], &k.X[2], &k.Y[0], &k.Y[1], &k.Y[2],
                                               &k.Z[0], &k.Z[1], &k.Z[2], &k.E0,   &k.R,    &k.rho};
    for (int j = 0; j < 13; j++) vst(f[j], *src[j]);
    for (int l = 0; l < n; l++) {
        cdk_lanes_1 *o = g[l];
        scale[l] = f[0][l];
        for (int j = 0; j < 3; j++) {
            o->X[j] = f[1 + j][l];
            o->Y[j] = f[4 + j][l];
            o->Z[j] = f[7 + j][l];
        }
        o->E0 = f[10][l];
        o->R = f[11][l];
        o->rho = f[12][l];
        o->small = o->rho <= o->R;
    }
    return mbits(bad) & ((1u << n) - 1u);
}

/* The rim search's frame of the pairs (c[l], d[l]), l < n <= W, as cdist__cc_quick_frame
 * builds it (scaled_pair, cdist__cc_frame_ring, the parallel and worth tests) operation by
 * operation: the fields the search reads into *f[l] (the ring, R, s, W1, Hh, Hc0, Lw) and the
 * scaling into sc[l]; returns the lanes whose search is not to run (the query takes the
 * engine). */
static unsigned KN(cd_rim_frame)(const cdist__circle *const *c, const cdist__circle *const *d, int n,
                                 cdist__cc_frame *const *f, double *sc)
{
    double col[14][W];
    for (int l = 0; l < W; l++) {
        const cdist__circle *a = c[l < n ? l : 0], *e = d[l < n ? l : 0];
        const double v[14] = {e->c.x, e->c.y, e->c.z, e->n.x, e->n.y, e->n.z, a->u.x,
                              a->u.y, a->u.z, a->v.x, a->v.y, a->v.z, a->r,   e->r};
        for (int j = 0; j < 14; j++) col[j][l] = v[j];
    }
    V C[3], m[3], u[3], v[3];
    for (int j = 0; j < 3; j++) {
        C[j] = vld(col[j]);
        m[j] = vld(col[3 + j]);
        u[j] = vld(col[6 + j]);
        v[j] = vld(col[9 + j]);
    }
    V r0 = vld(col[12]), r1 = vld(col[13]);
    /* scaled_pair: the pair scaled by 2^-(e + 1), L 2^-e in [1, 2) */
    V L0 = KN(fmax)(KN(fmax)(r0, r1), vsqrt(KN(dot)(C[0], C[1], C[2], C[0], C[1], C[2])));
    M bad = mnot(vge(L0, vset(0x1p-1022)));
    V down = vmul(vrecip2(KN(pow2_of)(L0)), vset(0.5));
    V R = vmul(r0, down), s = vmul(r1, down);
    for (int j = 0; j < 3; j++) C[j] = vmul(down, C[j]);
    V al[3], be[3], ga[3], ha, hb, hc;
    KN(ring_init)(R, u, v, C, m, al, be, ga, &ha, &hb, &hc);
    /* cdist__cc_frame_ring's bounds */
    V Cu = KN(ring_dot)(C[0], C[1], C[2], u[0], u[1], u[2]), Cv = KN(ring_dot)(C[0], C[1], C[2], v[0], v[1], v[2]);
    V aa = KN(ring_dot)(al[0], al[1], al[2], al[0], al[1], al[2]), bb = KN(ring_dot)(be[0], be[1], be[2], be[0], be[1], be[2]);
    V gg = KN(ring_dot)(ga[0], ga[1], ga[2], ga[0], ga[1], ga[2]), Lc = vsqrt(KN(dot)(C[0], C[1], C[2], C[0], C[1], C[2]));
    V L = KN(fmax)(KN(fmax)(R, s), Lc), Lw = vadd(vmul(vset(2.0), R), Lc);
    V W1 = vadd(vsqrt(aa), vsqrt(bb)), nga = vsqrt(gg), Hh = vadd(vabs(ha), vabs(hb)), Hc0 = vabs(hc);
    /* cdist__cc_parallel_critical's test and cdist__cc_quick_worth */
    bad = mor(bad, vle(vsqrt(vadd(vmul(ha, ha), vmul(hb, hb))), vmul(vset(CD_CC_PARALLEL_ULPS * DBL_EPSILON), L)));
    V e2 = vadd(vmul(Cu, Cu), vmul(Cv, Cv)), dr = vsub(vsqrt(e2), R), lim = vmul(vset(CD_CC_QUICK_CENTRE_REL), s);
    bad = mor(bad, vle(vadd(vmul(dr, dr), vsub(KN(ring_dot)(C[0], C[1], C[2], C[0], C[1], C[2]), e2)), vmul(lim, lim)));
    V axis = vmul(vset(CD_CC_QUICK_AXIS_REL), L);
    bad = mor(bad, mnot(mand(vgt(e2, vmul(axis, axis)), vgt(nga, axis))));
    double o[19][W];
    const V *src[19] = {&al[0], &al[1], &al[2], &be[0], &be[1], &be[2], &ga[0], &ga[1], &ga[2], &ha,
                        &hb,    &hc,    &R,     &s,     &W1,    &Hh,    &Hc0,   &Lw,    &down};
    for (int j = 0; j < 19; j++) vst(o[j], *src[j]);
    for (int l = 0; l < n; l++) {
        cdist__cc_frame *x = f[l];
        x->rg = (cdist__ring){v3(o[0][l], o[1][l], o[2][l]), v3(o[3][l], o[4][l], o[5][l]),
                              v3(o[6][l], o[7][l], o[8][l]), o[9][l], o[10][l], o[11][l]};
        x->R = o[12][l];
        x->s = o[13][l];
        x->W1 = o[14][l];
        x->Hh = o[15][l];
        x->Hc0 = o[16][l];
        x->Lw = o[17][l];
        sc[l] = o[18][l];
    }
    return mbits(bad) & ((1u << n) - 1u);
}

#if W > 1
CD_LANES_TARGET_POP
#endif
#include "base/lanes/lanes_undef.h"
