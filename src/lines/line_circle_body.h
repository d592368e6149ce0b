/* SPDX-License-Identifier: MIT */
/* The straight-line arithmetic of the line-circle ROBUST core (the model, its derivatives, the
 * brackets and starts of the solver, one solver iteration), written once over lanes; the model
 * and its derivation are described in line_circle.c and docs/lines.md. Included after
 * lanes_def.h, lanes_vec.h and base/roots_halley.h: src/lines/line_circle.c includes it for 1
 * lane (the single query), src/batch/line_kernel.c for 4 and 8 lanes (the batch kernels), so
 * an entry the kernels answer gets the single query's distance bit for bit. Cases lanes do not
 * follow are returned as masks for the caller to branch on. No include guard. */

#include "base/point_circle_lanes.h"

/* The model in the frame of the line (scaled units): h(s) = h + a s, x2(s) = c2 + m0 s, x1. */
typedef struct KN(lc_model) {
    V r;        /* radius */
    V a;        /* N . M */
    V m0;       /* length of the in-plane part of M */
    V x1, ax1;  /* in-plane offset of the line across e2, and |x1| */
    V c2;       /* x2 at s = 0 */
    V h;        /* height at s = 0 */
    V e2x, e2y; /* e2 in the circle basis (U, V) */
    V x1sq, k, rr2, dfc, d2c; /* invariants of the evaluators: x1^2, a^2 + m0^2, (|x1| - r)(|x1| + r),
                               * -(r m0^2) x1^2, 3 r m0^3 x1^2 */
} KN(lc_model);

/* rho - r without cancellation, given x2 and rho. */
CD_INLINE V KN(lc_rho_minus_r)(const KN(lc_model) *m, V x2, V rho)
{
    return vdiv(vmadd(x2, x2, m->rr2), vadd(rho, m->r));
}

/* Squared distance F at s; *x2 and *rho of that point. */
CD_INLINE V KN(lc_f)(const KN(lc_model) *m, V s, V *x2, V *rho)
{
    V h = vmadd(m->a, s, m->h);
    *x2 = vmadd(m->m0, s, m->c2);
    *rho = vsqrt(vmadd(m->x1, m->x1, vmul(*x2, *x2)));
    V dr = KN(lc_rho_minus_r)(m, *x2, *rho);
    return vmadd(h, h, vmul(dr, dr));
}

/* F'/2 at height h and in-plane coordinate x2. On the axis (rho = 0) F' is undefined: side = -1
 * or +1 gives the one-sided limit (x2/rho -> side). */
CD_INLINE V KN(lc_fp_at)(const KN(lc_model) *m, V h, V x2, double side)
{
    V rho = vsqrt(vmadd(m->x1, m->x1, vmul(x2, x2)));
    V on_axis = vsub(vmul(m->a, h), vmul(vmul(vset(side), m->r), m->m0));
    V off = vmadd(m->a, h, vmul(vmul(m->m0, x2), vdiv(KN(lc_rho_minus_r)(m, x2, rho), rho)));
    return vsel(veq(rho, vset(0.0)), on_axis, off);
}

/* F'/2 and F''/2 together: one square root and one division. With w = 1 / (rho (rho + r)):
 * (rho - r)/rho = num w and 1/rho = (rho + r) w. On the axis F'' is -infinity. */
CD_INLINE V KN(lc_fdf)(const KN(lc_model) *m, V s, V *df)
{
    V h = vmadd(m->a, s, m->h), x2 = vmadd(m->m0, s, m->c2);
    V rho = vsqrt(vmadd(m->x1, m->x1, vmul(x2, x2)));
    M axis = veq(rho, vset(0.0));
    V w = vdiv(vset(1.0), vmul(rho, vadd(rho, m->r)));
    V num = vmadd(x2, x2, m->rr2);
    V ir = vmul(vadd(rho, m->r), w), q = vmul(m->ax1, ir);
    *df = vsel(axis, vset(-INFINITY), vsub(m->k, vmul(vmul(vmul(vmul(vmul(m->r, m->m0), m->m0), q), q), ir)));
    return vsel(axis, vmul(m->a, h), vmadd(m->a, h, vmul(vmul(m->m0, x2), vmul(num, w))));
}

/* lc_fdf and F'''/2 = 3 r m0^3 x1^2 x2 / rho^5 (infinite or NaN within ~2^-200 of the axis, where
 * the solver then takes Newton's step). */
CD_INLINE V KN(lc_fd2f)(const KN(lc_model) *m, V s, V *df, V *d2f)
{
    V f = KN(lc_fdf)(m, s, df);
    V x2 = vmadd(m->m0, s, m->c2);
    V ir = vdiv(vset(1.0), vsqrt(vmadd(m->x1, m->x1, vmul(x2, x2)))), ir2 = vmul(ir, ir);
    *d2f = vmul(vmul(m->d2c, x2), vmul(vmul(ir2, ir2), ir));
    return f;
}

/* lc_fd2f times P = rho^5 (rho + r) > 0, for the solver (docs/lines.md, "ROBUST": one division
 * per step instead of three). Only where lc_scaled_range holds (rho^2 in [2^-100, 2^100]; near
 * the axis P would underflow, and lc_fd2f is taken). */
CD_INLINE M KN(lc_scaled_range)(const KN(lc_model) *m, V s)
{
    V x2 = vmadd(m->m0, s, m->c2), rho2 = vmadd(x2, x2, m->x1sq);
    return mand(vge(rho2, vset(0x1p-100)), vle(rho2, vset(0x1p100)));
}

CD_INLINE V KN(lc_fd2f_scaled)(const KN(lc_model) *m, V s, V *df, V *d2f)
{
    V h = vmadd(m->a, s, m->h), x2 = vmadd(m->m0, s, m->c2);
    V rho2 = vmadd(x2, x2, m->x1sq);
    V rho = vsqrt(rho2);
    V num = vmadd(x2, x2, m->rr2);
    V ah = vmul(m->a, h), r2 = vmul(m->r, rho2), q2 = vmul(rho2, rho2), c3 = vmul(m->d2c, x2);
    *df = vmadd(vmul(vmadd(m->k, r2, m->dfc), rho2), rho, vmul(vmadd(m->k, q2, vmul(m->dfc, m->r)), rho2));
    *d2f = vmadd(c3, rho, vmul(c3, m->r));
    return vmadd(vmul(vmul(ah, r2), rho2), rho, vmul(vmadd(ah, q2, vmul(vmul(m->m0, x2), vmul(num, rho2))), rho2));
}

/* One iteration of the solver (base/roots_halley.h) on F' in the lanes of s->act, at
 * CD_ROOT_REL_ULPS * eps and CD_ROOT_ABS. One lane evaluates one of the two forms. */
CD_INLINE void KN(lc_iterate)(const KN(lc_model) *m, KN(halley) *s)
{
    V f, df, d2f;
    M near_axis = mandn(KN(lc_scaled_range)(m, s->x), s->act);
    if (W == 1 && many(near_axis)) {
        f = KN(lc_fd2f)(m, s->x, &df, &d2f);
    } else {
        f = KN(lc_fd2f_scaled)(m, s->x, &df, &d2f);
        if (many(near_axis)) {
            V df1, d2f1, f1 = KN(lc_fd2f)(m, s->x, &df1, &d2f1);
            f = vsel(near_axis, f1, f), df = vsel(near_axis, df1, df), d2f = vsel(near_axis, d2f1, d2f);
        }
    }
    KN(halley_step)(s, f, df, d2f, vset(CD_ROOT_REL_ULPS * DBL_EPSILON), vset(CD_ROOT_ABS));
}

/* A finite end of the range: the point P = B + t M against the circle (normal n, radius r);
 * returns the squared distance, writes P, n x P and rho = |n x P|. */
CD_INLINE V KN(lc_end)(V Bx, V By, V Bz, V Mx, V My, V Mz, V t, V nx, V ny, V nz, V r, V P[3], V np[3], V *rho)
{
    P[0] = vfma(t, Mx, Bx), P[1] = vfma(t, My, By), P[2] = vfma(t, Mz, Bz);
    const V n[3] = {nx, ny, nz};
    KN(pc_parts) e = KN(point_circle)(n, P, r);
    np[0] = e.np[0], np[1] = e.np[1], np[2] = e.np[2];
    *rho = e.rho;
    return e.d2;
}

/* ---- the frame and the model ---- */

/* cdist__line_near_centre (lines-priv.h): origin O - C kept exactly as h + l (TwoSum), moved
 * along D to the point nearest C, clamped to [tmin, tmax]; returns that t (in units of D) and
 * writes B = h + t D + l. D is scaled by the power of two 2^-e of its largest component m
 * (exact): one division, and t is exactly 2^k times itself for a query scaled by 2^k; outside
 * [2^-1021, 2^1022) by 1 / m (|D|^2 may underflow or overflow, |D / m|^2 cannot). */
CD_INLINE V KN(lc_near_centre)(V Ox, V Oy, V Oz, V Dx, V Dy, V Dz, V Cx, V Cy, V Cz, V tmin, V tmax, V *Bx, V *By,
                               V *Bz)
{
    V hx = vsub(Ox, Cx), hy = vsub(Oy, Cy), hz = vsub(Oz, Cz), b;
    b = vsub(hx, Ox);
    V lx = vadd(vsub(Ox, vsub(hx, b)), vsub(vneg(Cx), b));
    b = vsub(hy, Oy);
    V ly = vadd(vsub(Oy, vsub(hy, b)), vsub(vneg(Cy), b));
    b = vsub(hz, Oz);
    V lz = vadd(vsub(Oz, vsub(hz, b)), vsub(vneg(Cz), b));
    V m = KN(max3)(Dx, Dy, Dz);
    M wide = mnot(mand(vge(m, vset(0x1p-1021)), vlt(m, vset(0x1p1022))));
    V p = vrecip2(vexpbits(m));
    V Dsx = vmul(p, Dx), Dsy = vmul(p, Dy), Dsz = vmul(p, Dz);
    V t = vmul(vneg(vdiv(KN(dot)(hx, hy, hz, Dsx, Dsy, Dsz), KN(dot)(Dsx, Dsy, Dsz, Dsx, Dsy, Dsz))), p);
    if (many(wide)) {
        V im = vdiv(vset(1.0), m);
        Dsx = vmul(im, Dx), Dsy = vmul(im, Dy), Dsz = vmul(im, Dz);
        V tw = vdiv(vneg(vdiv(KN(dot)(hx, hy, hz, Dsx, Dsy, Dsz), KN(dot)(Dsx, Dsy, Dsz, Dsx, Dsy, Dsz))), m);
        t = vsel(wide, tw, t);
    }
    t = vsel(vle(vabs(t), vset(DBL_MAX)), t, vset(0.0));
    t = KN(fmin)(KN(fmax)(t, tmin), tmax); /* rays and segments: stay on the object (no cancellation in t) */
    *Bx = vadd(vfma(t, Dx, hx), lx), *By = vadd(vfma(t, Dy, hy), ly), *Bz = vadd(vfma(t, Dz, hz), lz);
    return t;
}

/* B0 = B + t0 M, the line point nearest the centre (one correction step for orthogonality). */
CD_INLINE V KN(lc_nearest)(V Bx, V By, V Bz, V Mx, V My, V Mz, V *B0x, V *B0y, V *B0z)
{
    V t0 = vneg(KN(dot)(Bx, By, Bz, Mx, My, Mz));
    *B0x = vfma(t0, Mx, Bx), *B0y = vfma(t0, My, By), *B0z = vfma(t0, Mz, Bz);
    V dt = vneg(KN(dot)(*B0x, *B0y, *B0z, Mx, My, Mz));
    M cor = vne(dt, vset(0.0));
    if (many(cor)) {
        t0 = vsel(cor, vadd(t0, dt), t0);
        *B0x = vsel(cor, vfma(t0, Mx, Bx), *B0x);
        *B0y = vsel(cor, vfma(t0, My, By), *B0y);
        *B0z = vsel(cor, vfma(t0, Mz, Bz), *B0z);
    }
    return t0;
}

/* The circle's frame (centre at the origin, unit normal n, basis u, v) and the line's data in
 * it, scaled by sg = 1 / up (a power of two) so that max(r, |B0|) is in [1, 2). */
typedef struct KN(lc_frame) {
    V nx, ny, nz, ux, uy, uz, vx, vy, vz;
    V sg, up;     /* the scale and its inverse */
    V b2x, b2y;   /* B0's in-plane coordinates (scaled) */
    V h0;         /* B0's height (scaled) */
    V m2x, m2y;   /* the in-plane part of M */
    V a, mm, m0;  /* N . M, m2x^2 + m2y^2, sqrt(mm) */
} KN(lc_frame);

/* The scale and the line's coordinates in f (whose basis is set). The in-plane coordinates and
 * the height of B0 are taken before the scale is known and scaled after (exact), so that they do
 * not wait for the square root of |B0|, unless B0 is within 2^-400 of the centre (then on the
 * scaled B0: no subnormal products). r > 0: the scale is 2^-e of cdist__scale_exponent. */
CD_INLINE void KN(lc_frame_line)(KN(lc_frame) *f, V r, V B0x, V B0y, V B0z, V Mx, V My, V Mz)
{
    V S = KN(fmax)(r, vsqrt(KN(dot)(B0x, B0y, B0z, B0x, B0y, B0z)));
    f->up = KN(pow2_of)(S), f->sg = vrecip2(f->up);
    V nbx, nby, nbz, wx, wy, wz;
    KN(cross)(f->nx, f->ny, f->nz, B0x, B0y, B0z, &nbx, &nby, &nbz);
    f->b2x = vmul(KN(dot)(f->vx, f->vy, f->vz, nbx, nby, nbz), f->sg);
    f->b2y = vmul(vneg(KN(dot)(f->ux, f->uy, f->uz, nbx, nby, nbz)), f->sg);
    f->h0 = vmul(KN(dot)(f->nx, f->ny, f->nz, B0x, B0y, B0z), f->sg);
    M late = mnot(vge(KN(max3)(B0x, B0y, B0z), vset(0x1p-400)));
    if (many(late)) {
        V Bsx = vmul(f->sg, B0x), Bsy = vmul(f->sg, B0y), Bsz = vmul(f->sg, B0z);
        KN(cross)(f->nx, f->ny, f->nz, Bsx, Bsy, Bsz, &nbx, &nby, &nbz);
        f->b2x = vsel(late, KN(dot)(f->vx, f->vy, f->vz, nbx, nby, nbz), f->b2x);
        f->b2y = vsel(late, vneg(KN(dot)(f->ux, f->uy, f->uz, nbx, nby, nbz)), f->b2y);
        f->h0 = vsel(late, KN(dot)(f->nx, f->ny, f->nz, Bsx, Bsy, Bsz), f->h0);
    }
    KN(cross)(f->nx, f->ny, f->nz, Mx, My, Mz, &wx, &wy, &wz);
    f->m2x = KN(dot)(f->vx, f->vy, f->vz, wx, wy, wz), f->m2y = vneg(KN(dot)(f->ux, f->uy, f->uz, wx, wy, wz));
    f->a = KN(dot)(f->nx, f->ny, f->nz, Mx, My, Mz);
    f->mm = vadd(vmul(f->m2x, f->m2x), vmul(f->m2y, f->m2y)), f->m0 = vsqrt(f->mm);
}

/* The model of a line not perpendicular to the plane (m0 > 0), radius rs (scaled); *uO the
 * frame origin along M (scaled): the canonical point x2 = 0 when it is near (CD_LC_CANON_MAX), where
 * F is exactly even in s for a symmetric configuration, so symmetric minima come out
 * bit-identical; otherwise (nearly perpendicular lines) B0 itself, to keep t free of
 * cancellation. */
CD_INLINE void KN(lc_model_init)(KN(lc_model) *m, const KN(lc_frame) *f, V rs, V *uO)
{
    m->r = rs;
    m->a = f->a;
    m->m0 = f->m0;
    m->e2x = vdiv(f->m2x, f->m0), m->e2y = vdiv(f->m2y, f->m0);
    m->x1 = vsub(vmul(m->e2x, f->b2y), vmul(m->e2y, f->b2x));
    m->ax1 = vabs(m->x1);
    V c2 = vfma(m->e2x, f->b2x, vmul(m->e2y, f->b2y));
    V us = vdiv(vneg(vfma(f->m2x, f->b2x, vmul(f->m2y, f->b2y))), f->mm); /* -c2 / m0 with one division */
    M canon = vle(vabs(us), vset(CD_LC_CANON_MAX));
    *uO = vsel(canon, us, vset(0.0));
    m->c2 = vsel(canon, vset(0.0), c2);
    m->h = vsel(canon, vfma(f->a, us, f->h0), f->h0);
    m->x1sq = vmul(m->x1, m->x1);
    m->k = vmadd(f->a, f->a, vmul(f->m0, f->m0));
    m->rr2 = vmul(vsub(m->ax1, rs), vadd(m->ax1, rs));
    m->dfc = vmul(vneg(vmul(vmul(rs, f->m0), f->m0)), vmul(m->ax1, m->ax1));
    m->d2c = vmul(vmul(vset(-3.0), f->m0), m->dfc);
}

/* ---- brackets and starts (§4.2: from the shape of G, odd, increasing, slope at most
 * r m0^2/|x1| at x2 = 0; local minima only) ---- */

/* The bracket [*lo, *hi] of every root of F' (G in (-r m0, r m0)), mu = M . O, R = r m0^2 and
 * B = mu m0 - c2; returns the lanes where G' <= 1 everywhere (R <= |x1|): F' increasing, one
 * root. */
CD_INLINE M KN(lc_bracket)(const KN(lc_model) *m, V *lo, V *hi, V *mu, V *R, V *B)
{
    *mu = vfma(m->a, m->h, vmul(m->m0, m->c2));
    V rm0 = vmul(m->r, m->m0);
    *lo = vsub(vneg(*mu), rm0), *hi = vadd(vneg(*mu), rm0);
    *R = vmul(rm0, m->m0);
    *B = vfma(*mu, m->m0, vneg(m->c2));
    return vle(*R, m->ax1);
}

/* The solver's starts (docs/lines.md, "The starts"): far from the centre on the side
 * sigma = +-1 of x2, s = -mu + sigma r m0 (1 - x1^2 / (2 x2^2)) with x2 at its limit sigma R - B.
 * NaN or far outside the bracket where that x2 is 0 (the solver then starts at the midpoint). */
CD_INLINE V KN(lc_start_far)(const KN(lc_model) *m, V mu, V R, V B, V sigma)
{
    V x2 = vsub(vmul(sigma, R), B);
    V q = vdiv(m->x1sq, vmul(x2, x2));
    return vfma(vmul(sigma, vmul(m->r, m->m0)), vsub(vset(1.0), vmul(vset(0.5), q)), vneg(mu));
}

/* The single root of F' when g <= 1. Near the centre (the linear part's root x2l = N / e with
 * N = -B |x1|, e = |x1| - R >= 0, within |x1|), x2 / rho to third order, (x2 / |x1|)(1 -
 * x2^2 / (2 x1^2)): one Newton step on that cubic from x2l, x2 = N (x1^2 e^3 + R N^2) /
 * (e (x1^2 e^3 + 3/2 R N^2)), in s with the same one division; otherwise lc_start_far on the
 * side opposite to B. */
CD_INLINE V KN(lc_start_single)(const KN(lc_model) *m, V mu, V R, V B)
{
    V e = vsub(m->ax1, R), N = vmul(vneg(B), m->ax1);
    M near = vle(vabs(N), vmul(m->ax1, e)), far = mnot(near);
    V x0 = vset(0.0);
    if (many(far))
        x0 = KN(lc_start_far)(m, mu, R, B, vsel(vgt(B, vset(0.0)), vset(-1.0), vset(1.0)));
    if (many(near)) {
        V e3 = vmul(m->x1sq, vmul(vmul(e, e), e)), RN2 = vmul(R, vmul(N, N));
        V D = vmul(e, vfma(vset(1.5), RN2, e3));
        x0 = vsel(near, vdiv(vfma(N, vadd(e3, RN2), vmul(vneg(m->c2), D)), vmul(m->m0, D)), x0);
    }
    return x0;
}

#ifdef vfrexp_m
/* cdist__cbrt (src/base/numeric.h: glibc's algorithm) for positive normal x, operation by
 * operation. */
CD_INLINE V KN(cbrt_normal)(V x)
{
    V xm = vfrexp_m(x), xe = vfrexp_e(x); /* x = xm 2^xe, xm in [0.5, 1) */
    V u = vsub(vset(0.784932344976639262), vmul(vset(0.145263899385486377), xm));
    u = vadd(vset(-1.83469277483613086), vmul(u, xm));
    u = vadd(vset(2.44693122563534430), vmul(u, xm));
    u = vadd(vset(-2.11499494167371287), vmul(u, xm));
    u = vadd(vset(1.50819193781584896), vmul(u, xm));
    u = vadd(vset(0.354895765043919860), vmul(u, xm));
    V t2 = vmul(vmul(u, u), u);
    V q = vtrunc(vdiv(xe, vset(3.0))), r = vsub(xe, vmul(vset(3.0), q)); /* xe / 3 and xe % 3 of C */
    V f = vsel(veq(r, vset(-2.0)), vset(cdist__cbrt_factor[0]),
               vsel(veq(r, vset(-1.0)), vset(cdist__cbrt_factor[1]),
                    vsel(veq(r, vset(1.0)), vset(cdist__cbrt_factor[3]),
                         vsel(veq(r, vset(2.0)), vset(cdist__cbrt_factor[4]), vset(1.0)))));
    V ym = vmul(vdiv(vmul(u, vadd(t2, vmul(vset(2.0), xm))), vadd(vmul(vset(2.0), t2), xm)), f);
    return vscale2(ym, q);
}
#endif

/* cdist__cbrt in lanes: KN(cbrt_normal) where every lane is a positive normal number, else
 * cdist__cbrt lane by lane (the 1-lane instance always). */
CD_INLINE V KN(cbrt)(V x)
{
#ifdef vfrexp_m
    if (!many(mnot(mand(vge(x, vset(0x1p-1022)), vle(x, vset(DBL_MAX)))))) return KN(cbrt_normal)(x);
#endif
    double a[W];
    vst(a, x);
    for (int l = 0; l < W; l++) a[l] = cdist__cbrt(a[l]);
    return vld(a);
}

/* Where F' is not monotone (R > |x1|): the tangent points of slope 1, rho^3 = r m0^2 x1^2
 * (eq. (14)), x2 = -+ x2hat; F' increases left of sL, decreases between, increases right of sR.
 * A local minimum on the left branch exists iff F'(sL) >= 0 (then *hasA, bracket [lo, *hiA],
 * start *x0A), on the right branch iff F'(sR) <= 0 (*hasB, [*loB, hi], *x0B). */
CD_INLINE void KN(lc_branches)(const KN(lc_model) *m, V lo, V hi, V mu, V R, V B, M *hasA, V *hiA, V *x0A, M *hasB,
                               V *loB, V *x0B)
{
    V cm = KN(cbrt)(vmul(m->m0, m->ax1));
    V rhohat = vmul(vmul(KN(cbrt)(m->r), cm), cm);
    V x2hat = vsqrt(KN(fmax)(vset(0.0), vmul(vsub(rhohat, m->ax1), vadd(rhohat, m->ax1))));
    V sc = vneg(vdiv(m->c2, m->m0)), xm = vdiv(x2hat, m->m0);
    V sL = vsub(sc, xm), sR = vadd(sc, xm);
    M left = vge(KN(lc_fp_at)(m, vfma(m->a, sL, m->h), vneg(x2hat), -1.0), vset(0.0));
    M right = vle(KN(lc_fp_at)(m, vfma(m->a, sR, m->h), x2hat, +1.0), vset(0.0));
    /* Exactly, F'(sL) > F'(sR), so one of them holds; near a flat tangency rounding can break
     * that, and then both branches are searched. */
    M neither = mnot(mor(left, right));
    *hasA = mand(mor(left, neither), vle(lo, sL));
    *hasB = mand(mor(right, neither), vle(sR, hi));
    *hiA = KN(fmin)(sL, hi), *loB = KN(fmax)(sR, lo);
    *x0A = *x0B = vset(NAN);
    if (many(*hasA)) *x0A = KN(lc_start_far)(m, mu, R, B, vset(-1.0));
    if (many(*hasB)) *x0B = KN(lc_start_far)(m, mu, R, B, vset(1.0));
}
