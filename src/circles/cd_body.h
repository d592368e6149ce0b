/* SPDX-License-Identifier: MIT */
/* The circle-disk query's candidates over the disk's face, written once over a lane type
 * (src/base/lanes/lanes_def.h, lanes_vec.h) and included once per instruction set: by the
 * single query (circle_disk.c, 1 lane) and by the batch kernel (src/batch/cd_kernel.c, 4 and 8
 * lanes, one entry per lane). The circle P(t) = rho (cos t A + sin t B) (centre at the origin)
 * in the disk's frame: x(t) = X0 + X1 cos t + X2 sin t, the same for y, z (docs/disk.md). The
 * library functions (atan2, acos, sincos, hypot) are called lane by lane, so every lane
 * computes what one lane computes. No include guard. */

/* one lane: cdk_lanes_1 of circles-priv.h */
#if W > 1
typedef struct KN(cdk_lanes) {
    CDK_LANES_FIELDS(V, M)
} KN(cdk_lanes);
#endif

/* At one lane, the single query's offers: CDK_OFFER_PAIR(ctx, t, cs, sn, x, y, z, ex, rho, d2),
 * defined by the includer, gets the point at angle t, (cs, sn) with its coordinates, in-plane
 * excess, axis distance and squared distance (ctx NULL: none). */
/* fn(a, b) in the lanes of m (others 0): the library function lane by lane. */
CD_INLINE V KN(cdk_call2)(double (*fn)(double, double), M m, V a, V b)
{
#if W == 1
    return m ? fn(a, b) : 0.0;
#else
    double x[W], y[W], r[W];
    unsigned bits = mbits(m);
    vst(x, a);
    vst(y, b);
    for (int l = 0; l < W; l++) r[l] = bits >> l & 1 ? fn(x[l], y[l]) : 0.0;
    return vld(r);
#endif
}

/* sincos(t) in the lanes of m (the others keep *sn, *cs). */
CD_INLINE void KN(cdk_sincos)(M m, V t, V *sn, V *cs)
{
#if W == 1
    if (m) sincos(t, sn, cs);
#else
    double x[W], s[W], c[W];
    unsigned bits = mbits(m);
    vst(x, t);
    vst(s, *sn);
    vst(c, *cs);
    for (int l = 0; l < W; l++)
        if (bits >> l & 1) sincos(x[l], &s[l], &c[l]);
    *sn = vld(s);
    *cs = vld(c);
#endif
}

/* acos(x) in the lanes of m (others 0). */
CD_INLINE V KN(cdk_acos)(M m, V x)
{
#if W == 1
    return m ? acos(x) : 0.0;
#else
    double a[W];
    unsigned bits = mbits(m);
    vst(a, x);
    for (int l = 0; l < W; l++) a[l] = bits >> l & 1 ? acos(a[l]) : 0.0;
    return vld(a);
#endif
}

/* The circle (radius r, basis cu, cv, centre at the origin) in the frame of the disk (centre
 * D, normal dn, basis du, dv, radius R); E0 by error-free products and sums (base/numeric.h):
 * the in-plane excess of the circle's centre over the rim, exact to rounding even when R is
 * huge and the gap tiny. */
CD_INLINE void KN(cdk_lanes_init)(KN(cdk_lanes) *k, const V *D, const V *dn, const V *du, const V *dv, const V *cu,
                                  const V *cv, V r, V R)
{
    k->X[0] = vneg(KN(dot)(du[0], du[1], du[2], D[0], D[1], D[2]));
    k->X[1] = vmul(r, KN(dot)(du[0], du[1], du[2], cu[0], cu[1], cu[2]));
    k->X[2] = vmul(r, KN(dot)(du[0], du[1], du[2], cv[0], cv[1], cv[2]));
    k->Y[0] = vneg(KN(dot)(dv[0], dv[1], dv[2], D[0], D[1], D[2]));
    k->Y[1] = vmul(r, KN(dot)(dv[0], dv[1], dv[2], cu[0], cu[1], cu[2]));
    k->Y[2] = vmul(r, KN(dot)(dv[0], dv[1], dv[2], cv[0], cv[1], cv[2]));
    k->Z[0] = vneg(KN(dot)(dn[0], dn[1], dn[2], D[0], D[1], D[2]));
    k->Z[1] = vmul(r, KN(dot)(dn[0], dn[1], dn[2], cu[0], cu[1], cu[2]));
    k->Z[2] = vmul(r, KN(dot)(dn[0], dn[1], dn[2], cv[0], cv[1], cv[2]));
    k->R = R;
    k->rho = r;
    V xh = vmul(k->X[0], k->X[0]), xl = vfma(k->X[0], k->X[0], vneg(xh));
    V yh = vmul(k->Y[0], k->Y[0]), yl = vfma(k->Y[0], k->Y[0], vneg(yh));
    V rh = vmul(R, R), rl = vfma(R, R, vneg(rh));
    V s1 = vadd(xh, yh), b1 = vsub(s1, xh), e1 = vadd(vsub(xh, vsub(s1, b1)), vsub(yh, b1));
    V mr = vneg(rh), s2 = vadd(s1, mr), b2 = vsub(s2, s1), e2 = vadd(vsub(s1, vsub(s2, b2)), vsub(mr, b2));
    k->E0 = vadd(s2, vsub(vadd(vadd(vadd(e2, e1), xl), yl), rl));
    k->small = vle(r, R);
}

/* a0 + a1 cos t + a2 sin t, and its derivative */
CD_INLINE V KN(cdk_trig)(const V *a, V cs, V sn) { return vfma(a[1], cs, vfma(a[2], sn, a[0])); }
CD_INLINE V KN(cdk_trigd)(const V *a, V cs, V sn) { return vfma(a[2], cs, vneg(vmul(a[1], sn))); }

/* x^2 + y^2 - R^2 at the circle point (cs, sn), with x, y its in-plane coordinates relative to
 * the disk centre, expanded around the circle's centre for a circle smaller than the disk (why:
 * docs/disk.md, "Over the face"). */
CD_INLINE V KN(cdk_rim_excess_near)(const KN(cdk_lanes) *k, V cs, V sn)
{
    V a = vadd(vmul(k->X[1], cs), vmul(k->X[2], sn)), b = vadd(vmul(k->Y[1], cs), vmul(k->Y[2], sn));
    return vadd(k->E0, vadd(vmul(vset(2.0), vadd(vmul(k->X[0], a), vmul(k->Y[0], b))), vadd(vmul(a, a), vmul(b, b))));
}

CD_INLINE V KN(cdk_rim_excess)(const KN(cdk_lanes) *k, V x, V y, V cs, V sn)
{
#if W == 1
    if (k->small) return KN(cdk_rim_excess_near)(k, cs, sn);
#endif
    V direct = vfma(x, x, vfma(y, y, vneg(vmul(k->R, k->R))));
    if (!many(k->small)) return direct;
    return vsel(k->small, KN(cdk_rim_excess_near)(k, cs, sn), direct);
}

/* The far limit of the candidates: the best so far (min, squared; INFINITY: none) plus
 * CD_CD_FAR_REL of the scale, squared. */
CD_INLINE V KN(cdk_far2)(V min, V scale)
{
    V far = vsel(vlt(min, vset(INFINITY)), vadd(vsqrt(min), vmul(vset(CD_CD_FAR_REL), scale)), vset(INFINITY));
    return vmul(far, far);
}

/* Offer the circle point at angle t, (cs, sn) = (cos t, sin t), in the lanes of m, with its
 * true distance to the disk: min takes its squared distance unless it is far above min
 * (CD_CD_FAR_REL); at one lane the offer hook (if any) gets the point. */
CD_INLINE void KN(cdk_offer)(const KN(cdk_lanes) *k, M m, V t, V cs, V sn, V *min, V scale, void *ctx)
{
    V far2 = KN(cdk_far2)(*min, scale);
    V x = KN(cdk_trig)(k->X, cs, sn), y = KN(cdk_trig)(k->Y, cs, sn), z = KN(cdk_trig)(k->Z, cs, sn), zz = vmul(z, z);
    m = mandn(vgt(zz, far2), m); /* the distance is at least |z| */
    if (!many(m)) return;
    V ex = KN(cdk_rim_excess)(k, x, y, cs, sn);
    M out = mnot(vle(ex, vset(0.0)));
#if W > 1
    /* The kernel: a candidate certainly above far2 by the plain root (within a few ulps of
     * hypot's; CD_CD_HYPOT_ULPS covers it and the roundings to d2) is dropped before hypot, as
     * the test below would drop it. */
    V ra = vsqrt(vadd(vmul(x, x), vmul(y, y)));
    V rlo = vmul(ra, vset(1.0 - CD_CD_HYPOT_ULPS * DBL_EPSILON)), rhi = vmul(ra, vset(1.0 + CD_CD_HYPOT_ULPS * DBL_EPSILON));
    V drl = vmax(vsel(k->small, vdiv(ex, vadd(rhi, k->R)), vsub(rlo, k->R)), vset(0.0));
    V d2l = vmul(vfma(drl, drl, zz), vset(1.0 - CD_CD_HYPOT_ULPS * DBL_EPSILON));
    m = mandn(mand(out, vgt(d2l, far2)), m);
    if (!many(m)) return;
#endif
#if W == 1
    double rho = 0.0, d2 = zz;
    if (out) {
        rho = hypot(x, y);
        double dr = k->small ? ex / (rho + k->R) : rho - k->R;
        d2 = fma(dr, dr, zz);
    }
#else
    V rho = KN(cdk_call2)(hypot, mand(m, out), x, y);
    V dr = vsel(k->small, vdiv(ex, vadd(rho, k->R)), vsub(rho, k->R));
    V d2 = vsel(out, vfma(dr, dr, zz), zz);
#endif
    m = mandn(vgt(d2, far2), m);
    *min = vsel(mand(m, vlt(d2, *min)), d2, *min);
    (void)t;
#if W == 1
    if (m && ctx) CDK_OFFER_PAIR(ctx, t, cs, sn, x, y, z, ex, out ? rho : 0.0, d2);
#else
    (void)ctx;
#endif
}

/* Whether the plane crossing first estimated at (cs, sn), with height z there, is certainly far
 * above the best (CD_CD_FAR_REL) wherever its two Newton steps take it: they move the circle
 * point by at most 2 CD_CD_Z_STEP rho (move = 2 CD_CD_Z_STEP; the distance to the disk is
 * 1-Lipschitz), and twice the far margin covers the plain square root used here for hypot. Its
 * offer would then be dropped anyway, so the steps and the offer are skipped. */
CD_INLINE M KN(cdk_crossing_far)(const KN(cdk_lanes) *k, V cs, V sn, V z, V min, V scale, double move)
{
#if W == 1
    if (!(min < INFINITY)) return 0;
#endif
    V x = KN(cdk_trig)(k->X, cs, sn), y = KN(cdk_trig)(k->Y, cs, sn), ex = KN(cdk_rim_excess)(k, x, y, cs, sn);
#if W == 1
    double g = fabs(z);
    if (ex > 0.0) {
        double rho = sqrt(x * x + y * y), dr = k->small ? ex / (rho + k->R) : rho - k->R;
        g = sqrt(dr * dr + z * z);
    }
#else
    V rho = vsqrt(vadd(vmul(x, x), vmul(y, y)));
    V dr = vsel(k->small, vdiv(ex, vadd(rho, k->R)), vsub(rho, k->R));
    V g = vsel(vgt(ex, vset(0.0)), vsqrt(vadd(vmul(dr, dr), vmul(z, z))), vabs(z));
#endif
    M far = vgt(vsub(g, vmul(vset(move), k->rho)),
                vadd(vsqrt(min), vmul(vset(2.0 * CD_CD_FAR_REL), scale)));
    return mand(vlt(min, vset(INFINITY)), far);
}

/* The candidates at the extremes and zeros of the height z(t) = Z0 + amp cos(t - phi) into
 * min (the smallest squared distance offered, INFINITY at first; scale: the collector's). */
CD_INLINE void KN(cdk_height)(const KN(cdk_lanes) *k, V *min, V scale, void *ctx)
{
    V amp = vsqrt(vadd(vmul(k->Z[1], k->Z[1]), vmul(k->Z[2], k->Z[2])));
    V cz = vdiv(vneg(k->Z[0]), amp);
    M all = mtrue(), cross = vle(vabs(cz), vset(1.0));
    /* phi: the extremes' angle (reported with the pairs) and the crossings' start (the kernel
     * takes it below, for the crossings it keeps) */
#if W == 1
    V phi = KN(cdk_call2)(atan2, ctx ? all : cross, k->Z[2], k->Z[1]);
#else
    V phi = vset(0.0);
#endif
    /* The extremes' cos and sin are (Z1, Z2) / amp and their negatives, as accurate as sincos of
     * the rounded phi and without it (the angles reported are still phi, phi + pi). */
    V ce = vdiv(k->Z[1], amp), se = vdiv(k->Z[2], amp);
    KN(cdk_offer)(k, all, phi, ce, se, min, scale, ctx);
    KN(cdk_offer)(k, all, vadd(phi, vset(M_PI)), vneg(ce), vneg(se), min, scale, ctx);
    if (!many(cross)) return;
#if W > 1
    /* The kernel: each crossing's start from (cos phi, sin phi) and cz by the angle sum, without
     * the library calls; a crossing certainly far from there (CD_CD_CROSS_START: its angle's
     * error) would be dropped or skipped anyway, and its calls are spared. */
    V sw = vsqrt(vmax(vsub(vset(1.0), vmul(cz, cz)), vset(0.0)));
    M near[2];
    for (int i = 0; i < 2; i++) {
        V ssw = i ? sw : vneg(sw);
        V c0 = vsub(vmul(ce, cz), vmul(se, ssw)), s0 = vadd(vmul(se, cz), vmul(ce, ssw));
        V z0 = KN(cdk_trig)(k->Z, c0, s0);
        near[i] = mandn(KN(cdk_crossing_far)(k, c0, s0, z0, *min, scale, 2.0 * CD_CD_Z_STEP + CD_CD_CROSS_START), cross);
    }
    cross = mor(near[0], near[1]);
    if (!many(cross)) return;
    phi = KN(cdk_call2)(atan2, cross, k->Z[2], k->Z[1]);
#endif
    V w = KN(cdk_acos)(cross, cz);
    for (int s = -1; s <= 1; s += 2) {
        V t = vadd(phi, vmul(vset((double)s), w));
        /* Newton on z itself (two steps of at most CD_CD_Z_STEP) to land on the plane. A step
         * below half an ulp of t leaves t as it was: its cos and sin are reused. */
        V tl = vset(NAN), sn = vset(0.0), cs = vset(0.0); /* the angle of the last sincos */
#if W > 1
        M live = near[s > 0], skip = mandn(live, cross);
#else
        M live = cross, skip = mfalse();
#endif
        for (int it = 0; it < 2; it++) {
            M fresh = mandn(veq(t, tl), live);
            KN(cdk_sincos)(fresh, t, &sn, &cs);
            tl = vsel(fresh, t, tl);
            V z = KN(cdk_trig)(k->Z, cs, sn), zp = KN(cdk_trigd)(k->Z, cs, sn);
            if (it == 0) {
                M far = mand(live, KN(cdk_crossing_far)(k, cs, sn, z, *min, scale, 2.0 * CD_CD_Z_STEP));
                skip = mor(skip, far);
                live = mandn(far, live);
            }
            live = mandn(mor(veq(zp, vset(0.0)), veq(z, vset(0.0))), live);
            V st = vdiv(z, zp);
            live = mandn(vgt(vabs(st), vset(CD_CD_Z_STEP)), live);
            t = vsel(live, vsub(t, st), t);
            if (!many(live)) break;
        }
        M offer = mandn(skip, cross), moved = mandn(veq(t, tl), offer);
        KN(cdk_sincos)(moved, t, &sn, &cs);
        KN(cdk_offer)(k, offer, t, cs, sn, min, scale, ctx);
    }
}

/* The scale of the rim search's thresholds (the flat test, the cut-off). */
CD_INLINE V KN(cdk_scale)(const KN(cdk_lanes) *k)
{
    V c = vsqrt(vadd(vadd(vmul(k->X[0], k->X[0]), vmul(k->Y[0], k->Y[0])), vmul(k->Z[0], k->Z[0])));
    return KN(fmax)(KN(fmax)(k->rho, k->R), c);
}

/* Whether the planes are parallel within rounding. */
CD_INLINE M KN(cdk_parallel)(const KN(cdk_lanes) *k)
{
    V s = vsqrt(vadd(vmul(k->Z[1], k->Z[1]), vmul(k->Z[2], k->Z[2])));
    return vle(s, vmul(vset(8.0 * DBL_EPSILON), k->rho));
}

/* Whether the whole circle is certainly further from the rim than the cap plus CD_CD_FAR_REL * L
 * (then no minimum of F can be the answer, nor tie with it): the rim distance is at least
 * sqrt((rho - R)^2 + z^2) with the axis distance rho within e +- m of the centre's (m >= the
 * circle's largest in-plane radius, the Frobenius norm of its projection) and the height z
 * within |Z0| -+ amp; the margin covers the rounding of these bounds. */
CD_INLINE M KN(cdk_rim_far)(const KN(cdk_lanes) *k, V dcap, V scale)
{
    V e = vsqrt(vadd(vmul(k->X[0], k->X[0]), vmul(k->Y[0], k->Y[0])));
    V m = vsqrt(vadd(vadd(vadd(vmul(k->X[1], k->X[1]), vmul(k->X[2], k->X[2])), vmul(k->Y[1], k->Y[1])),
                     vmul(k->Y[2], k->Y[2])));
    V zero = vset(0.0);
    V lr = KN(fmax)(KN(fmax)(vsub(vsub(e, m), k->R), vsub(vsub(k->R, e), m)), zero);
    V amp = vsqrt(vadd(vmul(k->Z[1], k->Z[1]), vmul(k->Z[2], k->Z[2])));
    V lz = KN(fmax)(vsub(vabs(k->Z[0]), amp), zero);
    M far = vgt(vsqrt(vadd(vmul(lr, lr), vmul(lz, lz))), vadd(dcap, vmul(vset(CD_CD_FAR_REL), scale)));
    return mand(vlt(dcap, vset(INFINITY)), far);
}
