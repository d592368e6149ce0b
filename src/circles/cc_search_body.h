/* SPDX-License-Identifier: MIT */
/* The arithmetic of the circle-circle certified search (docs/circles.md), written once over a
 * lane type (src/base/lanes/lanes_def.h) and included once per instruction set: by the single
 * query's search (cc_search.c, lanes are angles) and by the batch kernel (src/batch/cc_kernel.c,
 * lanes are entries). Needs cc_search.h, and lanes_vec.h and base/dd.h of the same lanes.
 * No include guard. */

/* a b + c: the hardware fma where the variant has one, else a multiply and an add (the search
 * needs no particular rounding: the final distance is recomputed in scalar code) */
#if W == 1
#define ck_madd(a, b, c) vadd(vmul(a, b), c)
#else
#define ck_madd(a, b, c) vfma(a, b, c)
#endif

/* sqrt(x) and 1 / sqrt(x) of x >= 0 for the search: with AVX-512, the 14-bit reciprocal square
 * root and two Newton steps (relative error about 1e-16, no division: F then carries 1e-15 of
 * error, far below CD_CCK_CERT_MARGIN); below 2^-1000 (where the steps would give NaN) the root
 * is taken as 0 and its reciprocal as infinity, as the division gives at 0 (F moves by less than
 * 2^-498 s). Elsewhere the square root and a division. */
CD_INLINE V KN(ck_sqrt_inv)(V x, V *inv)
{
#if W == 8
    M big = vge(x, vset(0x1p-1000));
    V xs = vsel(big, x, vset(1.0));
    V y = _mm512_rsqrt14_pd(xs), h = vmul(vset(0.5), xs);
    y = vmul(y, vfma(vneg(h), vmul(y, y), vset(1.5)));
    y = vmul(y, vfma(vneg(h), vmul(y, y), vset(1.5)));
    *inv = vsel(big, y, vset(INFINITY));
    return vsel(big, vmul(xs, y), vset(0.0));
#else
    V r = vsqrt(x);
    *inv = vdiv(vset(1.0), r);
    return r;
#endif
}

CD_INLINE V KN(ck_sqrt)(V x)
{
#if W == 8
    V inv;
    return KN(ck_sqrt_inv)(x, &inv);
#else
    return vsqrt(x);
#endif
}

/* The ring of one lane group: w = al c + be s + ga, h = ha c + hb s + hc, B's radius s, R^2 and
 * the bounds W1 = |al| + |be|, Hh = |ha| + |hb|, Hc0 = |hc|, Lw = 2 R + |C| (cdist__cc_frame). */
typedef struct KN(ck_ring) {
    V alx, aly, alz, bex, bey, bez, gax, gay, gaz, ha, hb, hc, s, R2, W1, Hh, Hc0, Lw;
} KN(ck_ring);

/* F at (c, s): (|w| - s)^2 + h^2. At a hull point (c, s scaled by 1/cos) this is F_ext of the
 * header comment. */
CD_INLINE V KN(ck_f)(const KN(ck_ring) *r, V c, V s)
{
    V wx = ck_madd(r->alx, c, ck_madd(r->bex, s, r->gax));
    V wy = ck_madd(r->aly, c, ck_madd(r->bey, s, r->gay));
    V wz = ck_madd(r->alz, c, ck_madd(r->bez, s, r->gaz));
    V dr = vsub(KN(ck_sqrt)(ck_madd(wx, wx, ck_madd(wy, wy, vmul(wz, wz)))), r->s);
    V h = ck_madd(r->ha, c, ck_madd(r->hb, s, r->hc));
    return ck_madd(dr, dr, vmul(h, h));
}

/* F'/2, F''/2 (ring_eval.h), rho, rho'' and the rounding bound e2 of F''/2 at (c, s). */
CD_INLINE void KN(ck_f2)(const KN(ck_ring) *r, V c, V s, V *F0, V *F1, V *F2, V *rho, V *rho2, V *e2)
{
    V wx = ck_madd(r->alx, c, ck_madd(r->bex, s, r->gax));
    V wy = ck_madd(r->aly, c, ck_madd(r->bey, s, r->gay));
    V wz = ck_madd(r->alz, c, ck_madd(r->bez, s, r->gaz));
    V w1x = vsub(vmul(r->bex, c), vmul(r->alx, s));
    V w1y = vsub(vmul(r->bey, c), vmul(r->aly, s));
    V w1z = vsub(vmul(r->bez, c), vmul(r->alz, s));
    V Q = ck_madd(wx, wx, ck_madd(wy, wy, vmul(wz, wz)));
    V g = ck_madd(wx, w1x, ck_madd(wy, w1y, vmul(wz, w1z)));
    V g1 = vsub(vadd(ck_madd(w1x, w1x, ck_madd(w1y, w1y, vmul(w1z, w1z))),
                     ck_madd(wx, r->gax, ck_madd(wy, r->gay, vmul(wz, r->gaz)))),
                Q);
    V h = ck_madd(r->ha, c, ck_madd(r->hb, s, r->hc));
    V h1 = vsub(vmul(r->hb, c), vmul(r->ha, s));
    V h2 = vsub(r->hc, h);
    V irh, rh = KN(ck_sqrt_inv)(Q, &irh), dr = vsub(rh, r->s);
    V rp = vmul(g, irh), rpp = vmul(vsub(g1, vmul(rp, rp)), irh);
    *F0 = ck_madd(dr, dr, vmul(h, h));
    *F1 = ck_madd(dr, rp, vmul(h, h1));
    *F2 = vadd(ck_madd(rp, rp, vmul(dr, rpp)), ck_madd(h1, h1, vmul(h, h2)));
    *rho = rh;
    *rho2 = rpp;
    V W1 = r->W1, W12 = vmul(W1, W1), Lw = r->Lw;
    /* g1 = w'.w' + w.ga - Q carries eps (W1^2 + (rho + Lw) |ga| + Q), |ga| <= |C| <= Lw */
    V g1e = vadd(vadd(vabs(g1), W12), vadd(vmul(Lw, W1), vadd(vmul(vadd(rh, Lw), Lw), Q)));
    V t = vmul(vmul(vadd(Lw, vabs(dr)), g1e), irh);
    *e2 = vmul(vset(CD_CCK_F2_ULPS * DBL_EPSILON),
               vadd(vadd(W12, t), vadd(vmul(r->Hh, r->Hh), vmul(vadd(vabs(h), Lw), r->Hh))));
}

/* (c, s) rotated by the angles whose cosines and sines are (co, si), lane by lane. */
CD_INLINE void KN(ck_rot)(V c, V s, V co, V si, V *cr, V *sr)
{
    *cr = vsub(vmul(c, co), vmul(s, si));
    *sr = vadd(vmul(s, co), vmul(c, si));
}

/* F convex on [t - h, t + h]: F''/2 at both ends less its rounding exceeds M3 h, M3 >= |F'''/2|
 * on the interval: the engine's bounds (cdist__cc_convex) with |rho''| bounded from its end values
 * (docs/circles.md, "The bounds of F's derivatives"). */
CD_INLINE M KN(ck_convex)(const KN(ck_ring) *r, V c, V s, int l, M *near_axis)
{
    V ca, sa, cb, sb, F0, F1, F2a, F2b, ra, rb, xa, xb, ea, eb;
    KN(ck_rot)(c, s, vset(cdist__cc_tab.end_c[l]), vset(-cdist__cc_tab.end_s[l]), &ca, &sa);
    KN(ck_rot)(c, s, vset(cdist__cc_tab.end_c[l]), vset(cdist__cc_tab.end_s[l]), &cb, &sb);
    KN(ck_f2)(r, ca, sa, &F0, &F1, &F2a, &ra, &xa, &ea);
    KN(ck_f2)(r, cb, sb, &F0, &F1, &F2b, &rb, &xb, &eb);
    V h = vset(cdist__cc_tab.half[l]), W1 = r->W1, hw = vmul(W1, h), three = vset(3.0);
    V rlo = vsub(vmul(vset(0.5), vadd(ra, rb)), hw), rhi = vadd(vmax(ra, rb), hw);
    *near_axis = mnot(vgt(rlo, vset(0.0)));
    /* The bounds above multiplied through by rho_lo > 0, for one division in the chain:
     * base = b / rho_lo, 1 - 3 W1 h / rho_lo = k / rho_lo, B3 rho_lo = b + 3 W1 X, and the
     * test F''/2 > M3 h becomes (F''/2) rho_lo > (M3 rho_lo) h. X0 carries a margin for the
     * rounding of rho'' (relative 1e-9, and 1e-9 of base). */
    V b = vmul(W1, vadd(vmul(three, W1), rhi)), k = vsub(rlo, vmul(three, hw));
    V X0r = vadd(vmul(vmul(vmax(vabs(xa), vabs(xb)), vset(1.0 + CD_CC_BOUND_REL)), rlo), vmul(b, vset(CD_CC_BOUND_REL)));
    V X = vdiv(ck_madd(h, b, X0r), k), W3X = vmul(vmul(three, W1), X);
    V M3r = vadd(vadd(vmul(W3X, rlo), vmul(vadd(rhi, r->s), vadd(b, W3X))),
                 vmul(vmul(r->Hh, vadd(vmul(vset(4.0), r->Hh), r->Hc0)), rlo));
    V lhs = vmin(vsub(F2a, ea), vsub(F2b, eb));
    return mand(mand(vgt(rlo, vset(0.0)), vgt(k, vset(0.0))),
                vgt(vmul(lhs, rlo), vmul(vmul(M3r, h), vset(1.0 + CD_CC_CERT_REL))));
}

/* cos and sin of the offsets of Newton in a certified basin, |d| <= 0.0123 (the half-width at
 * level CK_FIRST_CONVEX), by their Taylor series to d^8 and d^7 (errors below 1e-25 and
 * 2e-23; fewer terms, a shorter chain in every Newton step). */
_Static_assert(CK_GRID >= 32 && CK_FIRST_CONVEX >= 2, "ck_sincos_small: |d| <= 2 pi / 32 / 16");
CD_INLINE void KN(ck_sincos_small)(V d, V *c, V *s)
{
    /* coefficients of d^(2k), k = 3 .. 0 and 4 .. 0 */
    static const double fs[4] = {-1.0 / 5040.0, 1.0 / 120.0, -1.0 / 6.0, 1.0};
    static const double fc[5] = {1.0 / 40320.0, -1.0 / 720.0, 1.0 / 24.0, -1.0 / 2.0, 1.0};
    V d2 = vmul(d, d), ps = vset(fs[0]), pc = vset(fc[0]);
    for (int k = 1; k < 4; k++) ps = ck_madd(ps, d2, vset(fs[k]));
    for (int k = 1; k < 5; k++) pc = ck_madd(pc, d2, vset(fc[k]));
    *s = vmul(ps, d);
    *c = pc;
}

/* Newton's start in a certified basin [-h, h] (offsets from its centre): the vertex of the
 * parabola through F at -h, 0, h (Fl, F0, Fr; F0 is the smallest, so the vertex is within
 * [-h/2, h/2]), 0 where they are level. From there Newton settles a step sooner. */
CD_INLINE V KN(ck_vertex)(V Fl, V F0, V Fr, V h)
{
    V den = vmul(vset(2.0), vadd(vsub(Fl, F0), vsub(Fr, F0)));
    V x = vdiv(vmul(h, vsub(Fl, Fr)), den);
    return vsel(vgt(den, vset(0.0)), vmin(vmax(x, vneg(h)), h), vset(0.0));
}

/* The cosine and sine of the answer, the basin's centre (c, s) rotated by Newton's offset d,
 * without a sincos call: the rotations from the grid leave |(c, s)| - 1 at a few ulps, which
 * would move the point off A by as many ulps of R; one step x (3 - |x|^2) / 2 of Newton's
 * iteration for the norm brings it back to about an ulp. */
CD_INLINE void KN(ck_answer_cs)(V c, V s, V d, V *cf, V *sf)
{
    V cd, sd;
    KN(ck_sincos_small)(d, &cd, &sd);
    V x, y;
    KN(ck_rot)(c, s, cd, sd, &x, &y);
    V k = vmul(vset(0.5), vsub(vset(3.0), vadd(vmul(x, x), vmul(y, y))));
    *cf = vmul(x, k);
    *sf = vmul(y, k);
}

/* The squared distance from A's point at (c, sn) = (cos t, sin t) to B (radius r->s) from the
 * ring r in double-double (base/dd.h): cdist__cc_point_d2 is the 1-lane instance, the batch
 * kernel's final distance the wider ones. */
CD_INLINE V KN(cc_point_d2)(const KN(ck_ring) *r, V c, V sn)
{
    V wxl, wyl, wzl, hl, zero = vset(0.0);
    V wx = KN(dd_trig)(r->alx, r->bex, r->gax, c, sn, &wxl);
    V wy = KN(dd_trig)(r->aly, r->bey, r->gay, c, sn, &wyl);
    V wz = KN(dd_trig)(r->alz, r->bez, r->gaz, c, sn, &wzl);
    V h = KN(dd_trig)(r->ha, r->hb, r->hc, c, sn, &hl);
    V Ql, Qh = KN(dd_sqr_add)(wx, wxl, zero, zero, &Ql);
    Qh = KN(dd_sqr_add)(wy, wyl, Qh, Ql, &Ql);
    Qh = KN(dd_sqr_add)(wz, wzl, Qh, Ql, &Ql);
    /* rho = sqrt(Q) with one Newton correction of the double root; on B's axis the low parts
     * may tip Q below 0 */
    V q = vadd(Qh, Ql), ql = vsub(Ql, vsub(q, Qh));
    M pos = vgt(q, zero);
    q = vsel(pos, q, zero);
    ql = vsel(pos, ql, zero);
    V e, rho = vsqrt(q), r2 = KN(dd_two_prod)(rho, rho, &e);
    V rl = vdiv(vadd(vsub(vsub(q, r2), e), ql), vmul(vset(2.0), rho));
    rl = vsel(vgt(rho, zero), rl, zero);
    V dr = KN(dd_two_sum)(rho, vneg(r->s), &e);
    V dl, d2 = KN(dd_sqr_add)(dr, vadd(e, rl), zero, zero, &dl);
    d2 = KN(dd_sqr_add)(h, hl, d2, dl, &dl);
    /* >= 0: the dropped squares of the low parts can tip a zero distance below 0 */
    return KN(fmax)(zero, vadd(d2, dl));
}

#undef ck_madd
