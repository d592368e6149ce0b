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
 * builds it (scaled_pair operation by operation, the ring and the tests by
 * cdist__cc_frame_ring's body): the fields the search reads into *f[l] (the ring, R, s, W1,
 * Hh, Hc0, Lw) and the scaling into sc[l]; returns the lanes whose search is not to run (the
 * query takes the engine). */
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
    KN(cc_ring) o;
    KN(cc_ring_init)(R, s, u, v, C, m, &o);
    bad = mor(bad, mnot(o.quick));
    double x[19][W];
    const V *src[19] = {&o.al[0], &o.al[1], &o.al[2], &o.be[0], &o.be[1], &o.be[2], &o.ga[0], &o.ga[1], &o.ga[2], &o.ha,
                        &o.hb,    &o.hc,    &R,       &s,       &o.W1,    &o.Hh,    &o.Hc0,   &o.Lw,    &down};
    for (int j = 0; j < 19; j++) vst(x[j], *src[j]);
    for (int l = 0; l < n; l++) {
        cdist__cc_frame *y = f[l];
        y->rg = (cdist__ring){v3(x[0][l], x[1][l], x[2][l]), v3(x[3][l], x[4][l], x[5][l]),
                              v3(x[6][l], x[7][l], x[8][l]), x[9][l], x[10][l], x[11][l]};
        y->R = x[12][l];
        y->s = x[13][l];
        y->W1 = x[14][l];
        y->Hh = x[15][l];
        y->Hc0 = x[16][l];
        y->Lw = x[17][l];
        sc[l] = x[18][l];
    }
    return mbits(bad) & ((1u << n) - 1u);
}

#if W > 1
CD_LANES_TARGET_POP
#endif
#include "base/lanes/lanes_undef.h"
