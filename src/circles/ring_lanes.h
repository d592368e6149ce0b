/* SPDX-License-Identifier: MIT */
/* cdist__ring_init (ring_eval.h) in lanes, operation by operation: the ring of A (radius R,
 * basis u, v, centre at the origin) seen from B (centre C, unit normal m). Included after
 * lanes_def.h and lanes_vec.h, once per lane width (the batch kernels' set-ups); no include
 * guard. */
CD_INLINE void KN(ring_init)(V R, const V *u, const V *v, const V *C, const V *m, V *al, V *be, V *ga, V *ha, V *hb,
                             V *hc)
{
    KN(cross)(m[0], m[1], m[2], u[0], u[1], u[2], &al[0], &al[1], &al[2]);
    KN(cross)(m[0], m[1], m[2], v[0], v[1], v[2], &be[0], &be[1], &be[2]);
    KN(cross)(m[0], m[1], m[2], C[0], C[1], C[2], &ga[0], &ga[1], &ga[2]);
    for (int j = 0; j < 3; j++) {
        al[j] = vmul(R, al[j]);
        be[j] = vmul(R, be[j]);
        ga[j] = vneg(ga[j]);
    }
    *ha = vmul(R, KN(ring_dot)(m[0], m[1], m[2], u[0], u[1], u[2]));
    *hb = vmul(R, KN(ring_dot)(m[0], m[1], m[2], v[0], v[1], v[2]));
    *hc = vneg(KN(ring_dot)(m[0], m[1], m[2], C[0], C[1], C[2]));
}
