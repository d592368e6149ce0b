/* SPDX-License-Identifier: MIT */
/* Vector helpers of the batch kernels in lanes, each the operation of the scalar code
 * (src/base/vec.h, numeric.h) lane by lane with the same roundings. Included after lanes_def.h
 * by each kernel body (line_kernel_body.h, cc_kernel_body.h); no include guard. */

/* each width's instance once per translation unit (a unit may hold several bodies of a width) */
#if (W == 1 && !defined(CD_LANES_VEC_1)) || (W == 4 && !defined(CD_LANES_VEC_4)) || (W == 8 && !defined(CD_LANES_VEC_8))
#if W == 1
#define CD_LANES_VEC_1
#elif W == 4
#define CD_LANES_VEC_4
#else
#define CD_LANES_VEC_8
#endif

/* |a| <= CD_MAX_ABS for each component (false for NaN and infinities) */
CD_INLINE M KN(in_range)(V x, V y, V z)
{
    V lim = vset(CD_MAX_ABS);
    return mand(mand(vle(vabs(x), lim), vle(vabs(y), lim)), vle(vabs(z), lim));
}

CD_INLINE V KN(max3)(V x, V y, V z) { return vmax(vmax(vabs(x), vabs(y)), vabs(z)); }

/* fma(a.x, b.x, fma(a.y, b.y, a.z * b.z)) as v_dot */
CD_INLINE V KN(dot)(V ax, V ay, V az, V bx, V by, V bz) { return vfma(ax, bx, vfma(ay, by, vmul(az, bz))); }

/* a.x b.x + a.y b.y + a.z b.z as cdist__ring_dot, left to right */
CD_INLINE V KN(ring_dot)(V ax, V ay, V az, V bx, V by, V bz)
{
    return vadd(vadd(vmul(ax, bx), vmul(ay, by)), vmul(az, bz));
}

/* v_cross: (a.y b.z - a.z b.y, a.z b.x - a.x b.z, a.x b.y - a.y b.x) */
CD_INLINE void KN(cross)(V ax, V ay, V az, V bx, V by, V bz, V *x, V *y, V *z)
{
    *x = vsub(vmul(ay, bz), vmul(az, by));
    *y = vsub(vmul(az, bx), vmul(ax, bz));
    *z = vsub(vmul(ax, by), vmul(ay, bx));
}

/* v_basis (vec.h) in lanes, for the kernels: e the axis of the smallest |n_k| (first on
 * ties), u = normalise(e - (e.n) n), v = n x u, of a unit normal n. */
CD_INLINE void KN(basis)(const V *n, V *u, V *v)
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

/* cdist__fmax / cdist__fmin: a > b ? a : (b == b ? b : a) */
CD_INLINE V KN(fmax)(V a, V b) { return vsel(vgt(a, b), a, vsel(veq(b, b), b, a)); }
CD_INLINE V KN(fmin)(V a, V b) { return vsel(vlt(a, b), a, vsel(veq(b, b), b, a)); }

/* 2^e of a positive normal x (its exponent bits), clamped as cdist__scale_exponent clamps e. */
CD_INLINE V KN(pow2_of)(V x)
{
    V p = vexpbits(x);
    return vmax(vmin(p, vset(0x1p1000)), vset(0x1p-1000));
}

#endif
