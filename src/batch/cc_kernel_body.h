/* SPDX-License-Identifier: MIT */
/* Body of the circle-circle distance kernel (src/batch/cc_kernel.c): the certified search for
 * the angle of the closest point, written once over a lane type (lanes_def.h) and included once
 * per instruction set. Lanes are entries; the method is described in cc_kernel.c. */

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

/* The ring of one lane group (columns of the block, see CK_C_*). */
typedef struct KN(ck_ring) {
    V alx, aly, alz, bex, bey, bez, gax, gay, gaz, ha, hb, hc, s, R2, W1, Hh, Hc0, Lw;
} KN(ck_ring);

CD_INLINE void KN(ck_load)(const ck_block *b, int g, KN(ck_ring) *r)
{
#define CK_LD(field, k) r->field = vld(&b->col[k][g])
    CK_LD(alx, CK_C_ALX), CK_LD(aly, CK_C_ALY), CK_LD(alz, CK_C_ALZ);
    CK_LD(bex, CK_C_BEX), CK_LD(bey, CK_C_BEY), CK_LD(bez, CK_C_BEZ);
    CK_LD(gax, CK_C_GAX), CK_LD(gay, CK_C_GAY), CK_LD(gaz, CK_C_GAZ);
    CK_LD(ha, CK_C_HA), CK_LD(hb, CK_C_HB), CK_LD(hc, CK_C_HC), CK_LD(s, CK_C_S), CK_LD(R2, CK_C_R2);
    CK_LD(W1, CK_C_W1), CK_LD(Hh, CK_C_HH), CK_LD(Hc0, CK_C_HC0), CK_LD(Lw, CK_C_LW);
#undef CK_LD
}

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
 * on the interval. The bounds are the engine's (convex(), cc_engine.c), with |rho''| bounded
 * from its end values instead of globally: with rho_lo <= rho <= rho_hi there (rho is
 * W1-Lipschitz), |w'|, |w''|, |w'''| <= W1 and X = max |rho''| on the interval,
 *     |rho'''| <= B3(X) = (3 W1^2 + rho_hi W1 + 3 W1 X) / rho_lo,
 * and every point is within h of an end, so X <= X0 + h B3(X), X0 the larger |rho''| at the
 * ends: X <= (X0 + h (3 W1^2 + rho_hi W1) / rho_lo) / (1 - 3 W1 h / rho_lo) when the divisor is
 * positive. Then |F'''/2| <= 3 W1 X + (rho_hi + s) B3(X) + Hh (4 Hh + Hc0). */
CD_INLINE M KN(ck_convex)(const KN(ck_ring) *r, V c, V s, int l, M *near_axis)
{
    V ca, sa, cb, sb, F0, F1, F2a, F2b, ra, rb, xa, xb, ea, eb;
    KN(ck_rot)(c, s, vset(ck_tab.end_c[l]), vset(-ck_tab.end_s[l]), &ca, &sa);
    KN(ck_rot)(c, s, vset(ck_tab.end_c[l]), vset(ck_tab.end_s[l]), &cb, &sb);
    KN(ck_f2)(r, ca, sa, &F0, &F1, &F2a, &ra, &xa, &ea);
    KN(ck_f2)(r, cb, sb, &F0, &F1, &F2b, &rb, &xb, &eb);
    V h = vset(ck_tab.half[l]), W1 = r->W1, hw = vmul(W1, h), three = vset(3.0);
    V rlo = vsub(vmul(vset(0.5), vadd(ra, rb)), hw), rhi = vadd(vmax(ra, rb), hw);
    *near_axis = mnot(vgt(rlo, vset(0.0)));
    /* The bounds above multiplied through by rho_lo > 0, for one division in the chain:
     * base = b / rho_lo, 1 - 3 W1 h / rho_lo = k / rho_lo, B3 rho_lo = b + 3 W1 X, and the
     * test F''/2 > M3 h becomes (F''/2) rho_lo > (M3 rho_lo) h. X0 carries a margin for the
     * rounding of rho'' (relative 1e-9, and 1e-9 of base). */
    V b = vmul(W1, vadd(vmul(three, W1), rhi)), k = vsub(rlo, vmul(three, hw));
    V X0r = vadd(vmul(vmul(vmax(vabs(xa), vabs(xb)), vset(1.0 + 1e-9)), rlo), vmul(b, vset(1e-9)));
    V X = vdiv(ck_madd(h, b, X0r), k), W3X = vmul(vmul(three, W1), X);
    V M3r = vadd(vadd(vmul(W3X, rlo), vmul(vadd(rhi, r->s), vadd(b, W3X))),
                 vmul(vmul(r->Hh, vadd(vmul(vset(4.0), r->Hh), r->Hc0)), rlo));
    V lhs = vmin(vsub(F2a, ea), vsub(F2b, eb));
    return mand(mand(vgt(rlo, vset(0.0)), vgt(k, vset(0.0))),
                vgt(vmul(lhs, rlo), vmul(vmul(M3r, h), vset(1.0 + 1e-12))));
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

/* ---- per-entry set-up in lanes ---- */

/* cdist__circle_fast (src/api/validate.c) of the circles in columns p (centre x y z, normal x y
 * z, radius): the mask of those it accepts and their unit normals n. */
CD_INLINE M KN(ck_circle_fast)(const V *p, double unit_tol, V *n)
{
    V m = vabs(p[3]); /* v_maxabs, as written */
    m = vsel(vgt(vabs(p[4]), m), vabs(p[4]), m);
    m = vsel(vgt(vabs(p[5]), m), vabs(p[5]), m);
    M ok = mand(KN(in_range)(p[0], p[1], p[2]), mand(vge(p[6], vset(0.0)), vle(p[6], vset(CD_MAX_ABS))));
    ok = mand(ok, mand(vge(m, vset(CD_MIN_NORMAL_FAST)), vle(m, vset(CD_MAX_ABS))));
    V len = vsqrt(KN(dot)(p[3], p[4], p[5], p[3], p[4], p[5]));
    ok = mand(ok, vle(vabs(vsub(len, vset(1.0))), vset(unit_tol)));
    V in = vdiv(vset(1.0), len);
    n[0] = vmul(in, p[3]);
    n[1] = vmul(in, p[4]);
    n[2] = vmul(in, p[5]);
    return ok;
}

/* v_basis (src/base/vec.h) of unit normals n: u, v. */
CD_INLINE void KN(ck_basis)(const V *n, V *u, V *v)
{
    V ax = vabs(n[0]), ay = vabs(n[1]), az = vabs(n[2]);
    M ex = mand(vle(ax, ay), vle(ax, az)), ey = mandn(ex, vle(ay, az)), ez = mnot(mor(ex, ey));
    V one = vset(1.0), zero = vset(0.0);
    V e0 = vsel(ex, one, zero), e1 = vsel(ey, one, zero), e2 = vsel(ez, one, zero);
    V k = vneg(KN(dot)(e0, e1, e2, n[0], n[1], n[2]));
    V wx = vfma(k, n[0], e0), wy = vfma(k, n[1], e1), wz = vfma(k, n[2], e2);
    V iw = vdiv(one, vsqrt(KN(dot)(wx, wy, wz, wx, wy, wz)));
    u[0] = vmul(iw, wx);
    u[1] = vmul(iw, wy);
    u[2] = vmul(iw, wz);
    KN(cross)(n[0], n[1], n[2], u[0], u[1], u[2], &v[0], &v[1], &v[2]);
}

/* a.x b.x + a.y b.y + a.z b.z as cdist__ring_dot, left to right */
CD_INLINE V KN(ck_rdot)(V ax, V ay, V az, V bx, V by, V bz)
{
    return vadd(vadd(vmul(ax, bx), vmul(ay, by)), vmul(az, bz));
}

/* The single query's validation, framing (cdist__circles_frame), problem (cdist__cc_prepare)
 * and ring (cdist__ring_init) of the entries [lo + base, lo + base + n), n <= W, operation by
 * operation, into the block's columns from base; returns the lanes left to the scalar path
 * (also the lanes >= n, and where the radii are equal: the tie rule of cdist__cc_prepare is not
 * repeated here). */
static unsigned KN(ck_setup)(const cdist__job *job, double unit_tol, size_t lo, int base, int n, ck_block *b)
{
    V ca[8], cb[8];
#ifdef vload_objects
    if (n == W) {
        vload_objects(cdist__job_a(job, lo + (size_t)base), job->a_stride, 7, ca);
        vload_objects(cdist__job_b(job, lo + (size_t)base), job->b_stride, 7, cb);
    } else
#endif
    {
        double in[14][W];
        for (int l = 0; l < W; l++) {
            size_t i = lo + (size_t)base + (size_t)(l < n ? l : 0);
            const double *pa = cdist__job_a(job, i), *pb = cdist__job_b(job, i);
            for (int f = 0; f < 7; f++) {
                in[f][l] = pa[f];
                in[7 + f][l] = pb[f];
            }
        }
        for (int f = 0; f < 7; f++) {
            ca[f] = vld(in[f]);
            cb[f] = vld(in[7 + f]);
        }
    }
    V na[3], nb[3];
    M ok = mand(KN(ck_circle_fast)(ca, unit_tol, na), KN(ck_circle_fast)(cb, unit_tol, nb));
    /* cdist__circles_frame: B's centre relative to A's, scaled by 2^-e */
    V Cx = vsub(cb[0], ca[0]), Cy = vsub(cb[1], ca[1]), Cz = vsub(cb[2], ca[2]);
    V mc = vabs(Cx);
    mc = vsel(vgt(vabs(Cy), mc), vabs(Cy), mc);
    mc = vsel(vgt(vabs(Cz), mc), vabs(Cz), mc);
    V L = KN(fmax)(KN(fmax)(ca[6], cb[6]), mc);
    ok = mand(ok, vge(L, vset(0x1p-1022))); /* a subnormal or zero scale: the scalar path */
    V up = KN(pow2_of)(L), down = vrecip2(up);
    V r0 = vmul(ca[6], down), r1 = vmul(cb[6], down);
    Cx = vmul(down, Cx);
    Cy = vmul(down, Cy);
    Cz = vmul(down, Cz);
    /* cdist__cc_prepare: A the larger circle (equal radii left), both scaled so that L is in
     * [0.5, 1) */
    M sw = vgt(r1, r0);
    ok = mand(ok, mand(vne(r0, r1), mand(vgt(r0, vset(0.0)), vgt(r1, vset(0.0)))));
    V L2 = KN(fmax)(KN(fmax)(r0, r1), vsqrt(KN(dot)(Cx, Cy, Cz, Cx, Cy, Cz)));
    V p2 = KN(pow2_of)(L2), sc = vmul(vrecip2(p2), vset(0.5)), unsc = vmul(p2, vset(2.0));
    V R = vmul(sc, vsel(sw, r1, r0)), s = vmul(sc, vsel(sw, r0, r1));
    V CBx = vmul(sc, vsel(sw, vneg(Cx), Cx)), CBy = vmul(sc, vsel(sw, vneg(Cy), Cy)),
      CBz = vmul(sc, vsel(sw, vneg(Cz), Cz));
    V nA[3], m[3], u[3], v[3];
    for (int k = 0; k < 3; k++) {
        nA[k] = vsel(sw, nb[k], na[k]);
        m[k] = vsel(sw, na[k], nb[k]);
    }
    KN(ck_basis)(nA, u, v);
    /* cdist__ring_init */
    V al[3], be[3], ga[3];
    KN(cross)(m[0], m[1], m[2], u[0], u[1], u[2], &al[0], &al[1], &al[2]);
    KN(cross)(m[0], m[1], m[2], v[0], v[1], v[2], &be[0], &be[1], &be[2]);
    KN(cross)(m[0], m[1], m[2], CBx, CBy, CBz, &ga[0], &ga[1], &ga[2]);
    for (int k = 0; k < 3; k++) {
        al[k] = vmul(R, al[k]);
        be[k] = vmul(R, be[k]);
        ga[k] = vneg(ga[k]);
    }
    V ha = vmul(R, KN(ck_rdot)(m[0], m[1], m[2], u[0], u[1], u[2]));
    V hb = vmul(R, KN(ck_rdot)(m[0], m[1], m[2], v[0], v[1], v[2]));
    V hc = vneg(KN(ck_rdot)(m[0], m[1], m[2], CBx, CBy, CBz));
    V W1 = vadd(vsqrt(KN(dot)(al[0], al[1], al[2], al[0], al[1], al[2])),
                vsqrt(KN(dot)(be[0], be[1], be[2], be[0], be[1], be[2])));
    V Lw = vadd(vmul(vset(2.0), R), vsqrt(KN(dot)(CBx, CBy, CBz, CBx, CBy, CBz)));
    const V cols[CK_NC] = {al[0], al[1], al[2], be[0], be[1], be[2], ga[0], ga[1], ga[2], ha, hb, hc, s,
                           vmul(R, R), W1, vadd(vabs(ha), vabs(hb)), vabs(hc), Lw, unsc, up};
    V zero = vset(0.0);
    for (int c = 0; c < CK_NC; c++) vst(&b->col[c][base], vsel(ok, cols[c], zero));
    unsigned left = mbits(mnot(ok)) & ((1u << W) - 1u);
    if (n < W) left |= ((1u << W) - 1u) & ~((1u << n) - 1u);
    return left;
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

/* The search for the W entries of the block from g: angles t[] of the closest points of the
 * entries it certifies; returns the lane mask (bit k: entry g + k) of those it does not. */
static unsigned KN(ck_search)(ck_block *b, int g)
{
    KN(ck_ring) r;
    KN(ck_load)(b, g, &r);
    V margin = vset(CD_CCK_CERT_MARGIN);

    /* Grid: F at the CK_GRID angles, the best one. */
    V Fg[CK_GRID], bestF = vset(INFINITY), bestJ = vset(0.0);
    for (int j = 0; j < CK_GRID; j++) {
        Fg[j] = KN(ck_f)(&r, vset(ck_tab.grid_c[j]), vset(ck_tab.grid_s[j]));
        M lt = vlt(Fg[j], bestF);
        bestF = vsel(lt, Fg[j], bestF);
        bestJ = vsel(lt, vset((double)j), bestJ);
    }
    /* The concave hull bound of every interval outside the basin (the two around the best
     * angle), the smallest kept in minlb; the basin's centre and the F at its ends. */
    M fail = mfalse();
    V minlb = vset(INFINITY), R2tan = vmul(r.R2, vset(ck_tab.grid_tan2));
    M nan = mfalse(); /* a NaN bound would drop out of minlb (min keeps the other operand) */
    V c = vset(0.0), s = vset(0.0), Fl = vset(0.0), Fr = vset(0.0);
    for (int j = 0; j < CK_GRID; j++) {
        int jn = (j + 1) % CK_GRID, jp = (j + CK_GRID - 1) % CK_GRID;
        V lb = vmin(vmin(Fg[j], Fg[jn]),
                    vsub(KN(ck_f)(&r, vset(ck_tab.hull_c[j]), vset(ck_tab.hull_s[j])), R2tan));
        M at = veq(vset((double)j), bestJ), before = veq(vset((double)jn), bestJ);
        minlb = vsel(mor(at, before), minlb, vmin(minlb, lb));
        nan = mor(nan, vne(lb, lb));
        c = vsel(at, vset(ck_tab.grid_c[j]), c);
        s = vsel(at, vset(ck_tab.grid_s[j]), s);
        Fl = vsel(before, Fg[j], Fl);
        Fr = vsel(veq(vset((double)jp), bestJ), Fg[j], Fr);
    }
    V t = vmul(bestJ, vset(2.0 * M_PI / CK_GRID));

    /* Zoom: certify the basin [t - h, t + h] convex, else split it in 8, keep the two
     * subintervals around the best point and add the hull bounds of the other six to minlb. */
    M done = mfalse();
    V hdone = vset(0.0);
    for (int l = 0; l < CK_LEVELS; l++) {
        M active = mnot(mor(done, fail));
        if (!many(active)) break;
        M near_axis;
        M conv = l < CK_FIRST_CONVEX ? mfalse() : mand(active, KN(ck_convex)(&r, c, s, l, &near_axis));
        done = mor(done, conv);
        hdone = vsel(conv, vset(ck_tab.half[l]), hdone);
        active = mandn(conv, active);
        if (!many(active) || l + 1 == CK_LEVELS) break;
        V Fk[9], Ck[9], Sk[9];
        Fk[0] = Fl;
        Fk[4] = bestF;
        Fk[8] = Fr;
        Ck[4] = c;
        Sk[4] = s;
        Ck[0] = Ck[8] = Sk[0] = Sk[8] = vset(0.0);
        for (int k = 1; k <= 3; k++) {
            KN(ck_rot)(c, s, vset(ck_tab.sub_c[l][k]), vset(ck_tab.sub_s[l][k]), &Ck[4 + k], &Sk[4 + k]);
            KN(ck_rot)(c, s, vset(ck_tab.sub_c[l][k]), vset(-ck_tab.sub_s[l][k]), &Ck[4 - k], &Sk[4 - k]);
            Fk[4 + k] = KN(ck_f)(&r, Ck[4 + k], Sk[4 + k]);
            Fk[4 - k] = KN(ck_f)(&r, Ck[4 - k], Sk[4 - k]);
        }
        V nF = Fk[4], kb = vset(4.0);
        for (int k = 0; k < 9; k++) {
            M lt = vlt(Fk[k], nF);
            nF = vsel(lt, Fk[k], nF);
            kb = vsel(lt, vset((double)k), kb);
        }
        M edge = mor(veq(kb, vset(0.0)), veq(kb, vset(8.0)));
        V R2tan_sub = vmul(r.R2, vset(ck_tab.sub_tan2[l]));
        for (int i = 0; i < 8; i++) {
            int m = i < 4 ? 3 - i : i - 4; /* hull point of [i, i+1] at (2 (i - 4) + 1) h / 8 */
            double sg = i < 4 ? -1.0 : 1.0;
            V hc, hs;
            KN(ck_rot)(c, s, vset(ck_tab.hull_sub_c[l][m]), vset(sg * ck_tab.hull_sub_s[l][m]), &hc, &hs);
            V lb = vmin(vmin(Fk[i], Fk[i + 1]), vsub(KN(ck_f)(&r, hc, hs), R2tan_sub));
            M keep = mor(veq(vset((double)i), kb), veq(vset((double)(i + 1)), kb));
            minlb = vsel(mandn(keep, active), vmin(minlb, lb), minlb);
            nan = mor(nan, mand(active, vne(lb, lb)));
        }
        fail = mor(fail, mand(active, edge));
        active = mandn(edge, active);
        V nc = c, ns = s, nl = Fl, nr = Fr;
        for (int k = 1; k < 8; k++) {
            M at = veq(vset((double)k), kb);
            nc = vsel(at, Ck[k], nc);
            ns = vsel(at, Sk[k], ns);
            nl = vsel(at, Fk[k - 1], nl);
            nr = vsel(at, Fk[k + 1], nr);
        }
        c = vsel(active, nc, c);
        s = vsel(active, ns, s);
        Fl = vsel(active, nl, Fl);
        Fr = vsel(active, nr, Fr);
        bestF = vsel(active, nF, bestF);
        t = vsel(active, vadd(t, vmul(vsub(kb, vset(4.0)), vset(0.25 * ck_tab.half[l]))), t);
    }
    fail = mor(fail, mnot(done));

    /* Newton on F' in the certified basin (one minimum there, F'' > 0), kept in [-h, h]. A lane
     * settles after its first step below CD_CCK_NEWTON_STEP (taken) and keeps its angle, so
     * that its answer does not depend on the other lanes of its group. */
    V d = KN(ck_vertex)(Fl, bestF, Fr, hdone), lo = vneg(hdone), Fs = vset(0.0);
    M settled = fail;
    for (int it = 0; it < CK_NEWTON_MAX; it++) {
        V cd, sd, cn, sn, F0, F1, F2, rho, rho2, e2;
        KN(ck_sincos_small)(d, &cd, &sd);
        KN(ck_rot)(c, s, cd, sd, &cn, &sn);
        KN(ck_f2)(&r, cn, sn, &F0, &F1, &F2, &rho, &rho2, &e2);
        V q = vdiv(F1, F2), nd = vmin(vmax(vsub(d, q), lo), hdone);
        M small = vle(vabs(vsub(nd, d)), vset(CD_CCK_NEWTON_STEP));
        /* a step cut at the basin's end would leave Fs (the parabola's vertex) below F there */
        M clamped = vne(nd, vsub(d, q));
        fail = mor(fail, mandn(settled, mand(small, clamped)));
        Fs = vsel(settled, Fs, vsub(F0, vmul(F1, q)));
        d = vsel(settled, d, nd);
        settled = mor(settled, small);
        M open = mnot(settled);
        if (!many(open)) break;
        if (it + 1 == CK_NEWTON_MAX) fail = mor(fail, open);
    }
    /* Certified: every region outside the final basin has its lower bound above F there; and
     * F there is not below CD_CCK_MIN_F (touching or crossing circles: the scalar path). F at
     * the angle found is Fs = F - F1^2 / F2 (F1, F2 = F'/2, F''/2) from the last Newton step's
     * values (the minimum of F's Taylor parabola there: the value after the step to
     * O(step^3), the step being below CD_CCK_NEWTON_STEP and not cut), which saves an
     * evaluation. */
    fail = mor(mor(fail, nan), mnot(mand(vgt(minlb, vadd(Fs, margin)), vge(Fs, vset(CD_CCK_MIN_F)))));
    vst(&b->t[g], vadd(t, d));
    V cf, sf;
    KN(ck_answer_cs)(c, s, d, &cf, &sf);
    vst(&b->ct[g], cf);
    vst(&b->st[g], sf);
    return mbits(fail);
}

/* ---- the distance at the angle found, in lanes ---- */

/* cdist__two_prod and cdist__two_sum (src/base/numeric.h) */
CD_INLINE V KN(ck_two_prod)(V a, V b, V *lo)
{
    V p = vmul(a, b);
    *lo = vfma(a, b, vneg(p));
    return p;
}
CD_INLINE V KN(ck_two_sum)(V a, V b, V *lo)
{
    V s = vadd(a, b), bb = vsub(s, a);
    *lo = vadd(vsub(a, vsub(s, bb)), vsub(b, bb));
    return s;
}
/* dd_trig and dd_sqr_add of cc_engine.c */
CD_INLINE V KN(ck_dd_trig)(V a, V b, V g, V c, V sn, V *lo)
{
    V e1, e2, e3, e4;
    V p = KN(ck_two_prod)(a, c, &e1), q = KN(ck_two_prod)(b, sn, &e2);
    V s1 = KN(ck_two_sum)(p, q, &e3), s2 = KN(ck_two_sum)(s1, g, &e4);
    *lo = vadd(vadd(e1, e2), vadd(e3, e4));
    return s2;
}
CD_INLINE V KN(ck_dd_sqr_add)(V xh, V xl, V ah, V al, V *lo)
{
    V e1, e2, p = KN(ck_two_prod)(xh, xh, &e1);
    V s = KN(ck_two_sum)(ah, p, &e2);
    *lo = vadd(vadd(vadd(al, e2), e1), vmul(vmul(vset(2.0), xh), xl));
    return s;
}

/* The distances of the lanes of the group from g at their angles (b->ct, b->st: cosine and
 * sine): cdist__cc_point_d2 (cc_engine.c) operation by operation, so bit for bit the single
 * query's formula; scaled back as the single query scales its answer. Into b->d. */
static void KN(ck_final)(ck_block *b, int g)
{
    V c = vld(&b->ct[g]), s = vld(&b->st[g]);
    const double(*col)[64] = b->col;
#define CK_COL(k) vld(&col[k][g])
    V wxl, wyl, wzl, hl;
    V wx = KN(ck_dd_trig)(CK_COL(CK_C_ALX), CK_COL(CK_C_BEX), CK_COL(CK_C_GAX), c, s, &wxl);
    V wy = KN(ck_dd_trig)(CK_COL(CK_C_ALY), CK_COL(CK_C_BEY), CK_COL(CK_C_GAY), c, s, &wyl);
    V wz = KN(ck_dd_trig)(CK_COL(CK_C_ALZ), CK_COL(CK_C_BEZ), CK_COL(CK_C_GAZ), c, s, &wzl);
    V h = KN(ck_dd_trig)(CK_COL(CK_C_HA), CK_COL(CK_C_HB), CK_COL(CK_C_HC), c, s, &hl);
    V zero = vset(0.0), Ql, Qh = KN(ck_dd_sqr_add)(wx, wxl, zero, zero, &Ql);
    Qh = KN(ck_dd_sqr_add)(wy, wyl, Qh, Ql, &Ql);
    Qh = KN(ck_dd_sqr_add)(wz, wzl, Qh, Ql, &Ql);
    V q = vadd(Qh, Ql), ql = vsub(Ql, vsub(q, Qh));
    M pos = vgt(q, zero);
    q = vsel(pos, q, zero);
    ql = vsel(pos, ql, zero);
    V r = vsqrt(q), e, r2 = KN(ck_two_prod)(r, r, &e);
    V rl = vdiv(vadd(vsub(vsub(q, r2), e), ql), vmul(vset(2.0), r));
    rl = vsel(vgt(r, zero), rl, zero);
    V dr = KN(ck_two_sum)(r, vneg(CK_COL(CK_C_S)), &e);
    V dl, d2h = KN(ck_dd_sqr_add)(dr, vadd(e, rl), zero, zero, &dl);
    d2h = KN(ck_dd_sqr_add)(h, hl, d2h, dl, &dl);
    V d2 = KN(fmax)(zero, vadd(d2h, dl)), u = CK_COL(CK_C_UNSC);
    vst(&b->d[g], vmul(vsqrt(vmul(vmul(d2, u), u)), CK_COL(CK_C_UP)));
#undef CK_COL
}

/* ---- one entry, lanes = angles: the single query's search (cdist__cc_quick) ---- */

/* Lane 0 of x. */
CD_INLINE double KN(ck_lane0)(V x)
{
    double a[W];
    vst(a, x);
    return a[0];
}

/* The smallest lane of x (x free of NaN). */
CD_INLINE double KN(ck_hmin)(V x)
{
#if W == 8
    return _mm512_reduce_min_pd(x);
#elif W == 4
    __m128d m = _mm_min_pd(_mm256_castpd256_pd128(x), _mm256_extractf128_pd(x, 1));
    return _mm_cvtsd_f64(_mm_min_sd(m, _mm_unpackhi_pd(m, m)));
#else
    return x;
#endif
}

/* The index of the smallest of x[0 .. n) (n a multiple of W): pref when x[pref] is the smallest
 * (pref < 0: none), else the first; -1 when one is NaN. In lanes: a scalar scan would chain
 * every comparison through a load of the best so far. */
CD_INLINE int KN(ck_argmin)(const double *x, int n, int pref)
{
    V m = vld(x);
    M nan = vne(m, m);
    for (int j = W; j < n; j += W) {
        V v = vld(x + j);
        m = vmin(m, v);
        nan = mor(nan, vne(v, v));
    }
    if (many(nan)) return -1;
    double b = KN(ck_hmin)(m);
    if (pref >= 0 && x[pref] == b) return pref;
    for (int j = 0; j < n; j += W) {
        unsigned bits = mbits(veq(vld(x + j), vset(b)));
        if (bits) return j + __builtin_ctz(bits);
    }
    return -1;
}

/* The smallest of x[0 .. n) but x[a] and x[b] (n a multiple of W); NaN when one is NaN. */
CD_INLINE double KN(ck_min_but)(const double *x, int n, int a, int b)
{
    V m = vset(INFINITY);
    M nan = mfalse();
    for (int j = 0; j < n; j += W) {
        V idx = vld(&ck_tab.lane_index[j]);
        M skip = mor(veq(idx, vset((double)a)), veq(idx, vset((double)b)));
        V v = vsel(skip, vset(INFINITY), vld(x + j));
        nan = mor(nan, vne(v, v));
        m = vmin(m, v);
    }
    return many(nan) ? NAN : KN(ck_hmin)(m);
}

/* The search of ck_search for the one pair of frame f, its angles spread over the lanes: the
 * grid and the hull points of its intervals W at a time, each zoom level's 8 points and 8 hull
 * points W at a time; the convexity test and Newton on the basin evaluate the same point in
 * every lane (their latency is that of scalar code). Returns 1, the angle *t of the closest
 * point on A and its cosine and sine (by rotation) when the same certificate as ck_search
 * holds, else 0. */
static int KN(ck_quick)(const cdist__cc_frame *f, double *t_out, double *c_out, double *s_out)
{
    KN(ck_ring) r = {
        vset(f->rg.al.x), vset(f->rg.al.y), vset(f->rg.al.z), vset(f->rg.be.x), vset(f->rg.be.y),
        vset(f->rg.be.z), vset(f->rg.ga.x), vset(f->rg.ga.y), vset(f->rg.ga.z), vset(f->rg.ha),
        vset(f->rg.hb), vset(f->rg.hc), vset(f->s), vset(f->R * f->R), vset(f->W1),
        vset(f->Hh), vset(f->Hc0), vset(f->Lw)};
    const double R2 = f->R * f->R;

    /* Grid: F at the CK_GRID angles, the interval bounds, the best angle. */
    double Fg[CK_GRID + 1], lb[CK_GRID];
    for (int j = 0; j < CK_GRID; j += W) vst(&Fg[j], KN(ck_f)(&r, vld(&ck_tab.grid_c[j]), vld(&ck_tab.grid_s[j])));
    Fg[CK_GRID] = Fg[0];
    V R2tan = vset(R2 * ck_tab.grid_tan2);
    for (int j = 0; j < CK_GRID; j += W) {
        V hull = vsub(KN(ck_f)(&r, vld(&ck_tab.hull_c[j]), vld(&ck_tab.hull_s[j])), R2tan);
        vst(&lb[j], vmin(vmin(vld(&Fg[j]), vld(&Fg[j + 1])), hull));
    }
    int jb = KN(ck_argmin)(Fg, CK_GRID, -1);
    if (jb < 0) return 0;
    int jp = (jb + CK_GRID - 1) % CK_GRID;
    double minlb = KN(ck_min_but)(lb, CK_GRID, jb, jp);
    if (minlb != minlb) return 0;
    /* The basin's own bounds are below F at any point of it, so the certificate cannot hold
     * once minlb is within the margin of them (a near-tie): leave early. */
    const double margin = CD_CCK_CERT_MARGIN;
    if (!(minlb > cdist__fmin(lb[jb], lb[jp]) + margin)) return 0;
    double c = ck_tab.grid_c[jb], s = ck_tab.grid_s[jb], bestF = Fg[jb], Fl = Fg[jp], Fr = Fg[jb + 1];
    double t = jb * (2.0 * M_PI / CK_GRID), hdone = 0.0;

    /* Zoom, as ck_search. */
    int done = 0;
    for (int l = 0; l < CK_QUICK_LEVELS && !done; l++) {
        /* F at the answer would be below bestF: touching or crossing circles (the scan) */
        if (!(bestF >= CD_CCK_MIN_F)) return 0;
        if (l >= CK_FIRST_CONVEX) {
            M near_axis;
            if (mbits(KN(ck_convex)(&r, vset(c), vset(s), l, &near_axis)) & 1u) {
                done = 1;
                hdone = ck_tab.half[l];
                break;
            }
            /* B's axis within W1 h of the basin: F's kink there (A crossing the axis) keeps
             * the basin from being certified convex at any level we try; the scan's kink
             * windows answer it */
            if (mbits(near_axis) & 1u) return 0;
        }
        if (l + 1 == CK_QUICK_LEVELS) break;
        double Fk[9], Ck[8], Sk[8], hb[8];
        V R2tan_sub = vset(R2 * ck_tab.sub_tan2[l]);
        for (int k = 0; k < 8; k += W) {
            V ck, sk, hc, hs;
            KN(ck_rot)(vset(c), vset(s), vld(&ck_tab.zoom_c[l][k]), vld(&ck_tab.zoom_s[l][k]), &ck, &sk);
            vst(&Fk[k], KN(ck_f)(&r, ck, sk));
            vst(&Ck[k], ck);
            vst(&Sk[k], sk);
            KN(ck_rot)(vset(c), vset(s), vld(&ck_tab.zoom_hull_c[l][k]), vld(&ck_tab.zoom_hull_s[l][k]), &hc, &hs);
            vst(&hb[k], vsub(KN(ck_f)(&r, hc, hs), R2tan_sub));
        }
        Fk[0] = Fl; /* the ends and the centre as they were found */
        Fk[4] = bestF;
        Fk[8] = Fr;
        int kb = KN(ck_argmin)(Fk, 8, 4);
        if (kb >= 0 && Fk[8] < Fk[kb]) kb = 8;
        if (kb <= 0 || kb == 8) return 0; /* NaN, or the best point at the basin's end */
        for (int i = 0; i < 8; i += W)
            vst(&hb[i], vmin(vmin(vld(&Fk[i]), vld(&Fk[i + 1])), vld(&hb[i])));
        double v = KN(ck_min_but)(hb, 8, kb - 1, kb);
        if (v != v) return 0;
        minlb = v < minlb ? v : minlb;
        if (!(minlb > cdist__fmin(hb[kb - 1], hb[kb]) + margin)) return 0;
        c = Ck[kb];
        s = Sk[kb];
        Fl = Fk[kb - 1];
        Fr = Fk[kb + 1];
        bestF = Fk[kb];
        t += (kb - 4) * (0.25 * ck_tab.half[l]);
    }
    if (!done) return 0;

    /* Newton, as ck_search. */
    double d = KN(ck_lane0)(KN(ck_vertex)(vset(Fl), vset(bestF), vset(Fr), vset(hdone))), Fs = 0.0;
    int settled = 0;
    for (int it = 0; it < CK_NEWTON_MAX && !settled; it++) {
        V cd, sd, F0, F1, F2, rho, rho2, e2;
        KN(ck_sincos_small)(vset(d), &cd, &sd);
        V cn, sn;
        KN(ck_rot)(vset(c), vset(s), cd, sd, &cn, &sn);
        KN(ck_f2)(&r, cn, sn, &F0, &F1, &F2, &rho, &rho2, &e2);
        double f1 = KN(ck_lane0)(F1), q = f1 / KN(ck_lane0)(F2), nd = d - q;
        nd = nd > -hdone ? nd : -hdone;
        nd = nd < hdone ? nd : hdone;
        settled = fabs(nd - d) <= CD_CCK_NEWTON_STEP;
        if (settled && nd != d - q) return 0; /* cut at the basin's end: Fs below F there */
        d = nd;
        Fs = KN(ck_lane0)(F0) - f1 * q;
    }
    if (!settled) return 0;

    /* The certificate of ck_search. */
    if (!(minlb > Fs + margin && Fs >= CD_CCK_MIN_F)) return 0;
    V cf, sf;
    KN(ck_answer_cs)(vset(c), vset(s), vset(d), &cf, &sf);
    *c_out = KN(ck_lane0)(cf);
    *s_out = KN(ck_lane0)(sf);
    *t_out = t + d;
    return 1;
}

#undef ck_madd
