/* SPDX-License-Identifier: MIT */
/* The ring of a circle pair and the magnitudes that bound it (cdist__cc_frame_ring), written
 * once over lanes: A (radius R, basis u, v, centre at the origin) seen from B (radius s, centre
 * C, unit normal m). The single query's frame (cc_frame.c) is the one-lane instance, the batch
 * kernels' set-ups (src/batch/cc_kernel_body.h, cd_kernel_body.h) the wider ones, so the search
 * reads the same numbers in both. Included after lanes_def.h and lanes_vec.h; no include
 * guard. */
typedef struct KN(cc_ring) {
    V al[3], be[3], ga[3], ha, hb, hc;       /* w and h of ring_eval.h */
    V Cu, Cv, L, Lw, W1, nga, Hh, Hc0, epsL; /* cdist__cc_frame's fields of these names */
    M parallel, quick;                       /* and these */
} KN(cc_ring);

CD_INLINE void KN(cc_ring_init)(V R, V s, const V *u, const V *v, const V *C, const V *m, KN(cc_ring) *o)
{
    KN(cross)(m[0], m[1], m[2], u[0], u[1], u[2], &o->al[0], &o->al[1], &o->al[2]);
    KN(cross)(m[0], m[1], m[2], v[0], v[1], v[2], &o->be[0], &o->be[1], &o->be[2]);
    KN(cross)(m[0], m[1], m[2], C[0], C[1], C[2], &o->ga[0], &o->ga[1], &o->ga[2]);
    for (int j = 0; j < 3; j++) {
        o->al[j] = vmul(R, o->al[j]);
        o->be[j] = vmul(R, o->be[j]);
        o->ga[j] = vneg(o->ga[j]);
    }
    o->ha = vmul(R, KN(ring_dot)(m[0], m[1], m[2], u[0], u[1], u[2]));
    o->hb = vmul(R, KN(ring_dot)(m[0], m[1], m[2], v[0], v[1], v[2]));
    o->hc = vneg(KN(ring_dot)(m[0], m[1], m[2], C[0], C[1], C[2]));
    o->Cu = KN(ring_dot)(C[0], C[1], C[2], u[0], u[1], u[2]);
    o->Cv = KN(ring_dot)(C[0], C[1], C[2], v[0], v[1], v[2]);
    V aa = KN(ring_dot)(o->al[0], o->al[1], o->al[2], o->al[0], o->al[1], o->al[2]);
    V bb = KN(ring_dot)(o->be[0], o->be[1], o->be[2], o->be[0], o->be[1], o->be[2]);
    V gg = KN(ring_dot)(o->ga[0], o->ga[1], o->ga[2], o->ga[0], o->ga[1], o->ga[2]);
    V Lc = vsqrt(KN(dot)(C[0], C[1], C[2], C[0], C[1], C[2]));
    o->epsL = vmul(vset(DBL_EPSILON), vadd(R, Lc));
    o->L = KN(fmax)(KN(fmax)(R, s), Lc);
    o->Lw = vadd(vmul(vset(2.0), R), Lc);
    o->W1 = vadd(vsqrt(aa), vsqrt(bb));
    o->nga = vsqrt(gg);
    o->Hh = vadd(vabs(o->ha), vabs(o->hb));
    o->Hc0 = vabs(o->hc);
    /* A's height over B's plane varies by at most CD_CC_PARALLEL_ULPS eps L. The search is not
     * tried there, nor where B's centre lies within CD_CC_QUICK_CENTRE_REL s of A (with
     * e = |C| in A's plane the squared distance from C to A is (e - R)^2 + (|C|^2 - e^2)), nor
     * where a centre lies on the other circle's axis (e or |ga| = |m x C| within
     * CD_CC_QUICK_AXIS_REL L): it cannot certify there. */
    V hn = vsqrt(vadd(vmul(o->ha, o->ha), vmul(o->hb, o->hb)));
    o->parallel = vle(hn, vmul(vset(CD_CC_PARALLEL_ULPS * DBL_EPSILON), o->L));
    V e2 = vadd(vmul(o->Cu, o->Cu), vmul(o->Cv, o->Cv)), dr = vsub(vsqrt(e2), R);
    V lim = vmul(vset(CD_CC_QUICK_CENTRE_REL), s), axis = vmul(vset(CD_CC_QUICK_AXIS_REL), o->L);
    M centre = vle(vadd(vmul(dr, dr), vsub(KN(ring_dot)(C[0], C[1], C[2], C[0], C[1], C[2]), e2)), vmul(lim, lim));
    o->quick = mandn(mor(o->parallel, centre), mand(vgt(e2, vmul(axis, axis)), vgt(o->nga, axis)));
}
