/* SPDX-License-Identifier: MIT */
/* Body of the line/ray/segment-circle distance kernel (src/batch/line_kernel.c), written once
 * over a lane type and included once per instruction set. The includer defines W (lanes), V (W
 * doubles), M (a lane mask), KN(name) (this instantiation's name for `name`), LK_CHAINS and
 * the operations (vadd, vsqrt, vfma, vsel, mand, ...; see line_kernel.c).
 * Every operation is the one of the scalar path (validation, src/api/validate.c; framing and
 * scaling, run_scaled/run/cdist__line_near_centre; the ROBUST core, linear_circle and
 * robust_roots with its starts and cdist__root_halley_accel on fd2f_scaled,
 * src/lines/line_circle.c), lane by lane, in the same order and with the same roundings (fma
 * where the scalar code calls fma, CD_MADD where it uses CD_MADD, cdist__cbrt's algorithm): the
 * distance of an entry the kernel answers is the single query's, bit for bit. An entry whose
 * inputs or intermediate values would take any other branch of the scalar path (a failed check,
 * a tiny or subnormal vector, the perpendicular or zero-radius cases, an iterate near the
 * circle's axis, a NaN) is left to the scalar path.
 * Stages over a block of up to 64 entries: 1 (all entries, W at a time) validation, frame and
 * model; 2 (the entries where F' is not monotone) the branch brackets; 3 (every bracket) the
 * solver; 4 (all entries) the distance. */

/* Comparisons under a mask: m and (a op b); vngt_m: m and !(a > b). */
#ifdef vcmp_mask
#define veq_m(m, a, b) vcmp_mask(m, a, b, _CMP_EQ_OQ)
#define vlt_m(m, a, b) vcmp_mask(m, a, b, _CMP_LT_OQ)
#define vgt_m(m, a, b) vcmp_mask(m, a, b, _CMP_GT_OQ)
#define vle_m(m, a, b) vcmp_mask(m, a, b, _CMP_LE_OQ)
#define vge_m(m, a, b) vcmp_mask(m, a, b, _CMP_GE_OQ)
#define vngt_m(m, a, b) vcmp_mask(m, a, b, _CMP_NGT_UQ)
#else
#define veq_m(m, a, b) mand(m, veq(a, b))
#define vlt_m(m, a, b) mand(m, vlt(a, b))
#define vgt_m(m, a, b) mand(m, vgt(a, b))
#define vle_m(m, a, b) mand(m, vle(a, b))
#define vge_m(m, a, b) mand(m, vge(a, b))
#define vngt_m(m, a, b) mandn(vgt(a, b), m)
#endif

/* The model of linear_circle (lc_model) in lanes. */
typedef struct KN(model) {
    V r, a, m0, x1, ax1, c2, h;
    V k, rr2, dfc, d2c; /* invariants of fd2f_scaled: a^2 + m0^2, (|x1| - r)(|x1| + r), -(r m0 m0)(x1^2),
                         * -3 m0 dfc (d2c: set by load_model, for the solver) */
} KN(model);

/* fd2f_scaled of line_circle.c; *ok cleared where it would call fd2f (rho^2 out of range). */
CD_INLINE V KN(fd2f_scaled)(const KN(model) *m, V s, V *df, V *d2f, M *ok)
{
    V h = vmadd(m->a, s, m->h), x2 = vmadd(m->m0, s, m->c2);
    V rho2 = vmadd(x2, x2, vmul(m->x1, m->x1));
    *ok = mand(vge(rho2, vset(0x1p-100)), vle(rho2, vset(0x1p100)));
    V rho = vsqrt(rho2);
    V num = vmadd(x2, x2, m->rr2);
    V ah = vmul(m->a, h), r2 = vmul(m->r, rho2), q2 = vmul(rho2, rho2), c3 = vmul(m->d2c, x2);
    *df = vmadd(vmul(vmadd(m->k, r2, m->dfc), rho2), rho, vmul(vmadd(m->k, q2, vmul(m->dfc, m->r)), rho2));
    *d2f = vmadd(c3, rho, vmul(c3, m->r));
    return vmadd(vmul(vmul(ah, r2), rho2), rho,
                 vmul(vmadd(ah, q2, vmul(vmul(m->m0, x2), vmul(num, rho2))), rho2));
}

/* The state of cdist__root_halley_accel(fd2f_scaled, m, lo, hi, x0, +1, CD_ROOT_REL_ULPS * eps,
 * CD_ROOT_ABS, CD_ROOT_MAX_ITER) in each lane: act = still iterating, res = the root of a lane
 * that stopped; p1, p2 the last two steps' lengths, ph = the last of them was Halley's, cp and xp
 * C = f'' / (2 f') and x at the last point, jumped = the last step went to near an end of the
 * bracket. */
typedef struct KN(solver) {
    V x, lo, hi, dx, dxold, p1, p2, cp, xp, res;
    M jumped, ph, act;
} KN(solver);

CD_INLINE KN(solver) KN(solver_start)(V lo, V hi, V x0, M act)
{
    KN(solver) s;
    s.res = lo; /* also the answer of an empty bracket */
    s.act = mand(act, vlt(lo, hi));
    s.x = vsel(mand(vgt(x0, lo), vlt(x0, hi)), x0, vmul(vset(0.5), vadd(lo, hi)));
    s.lo = lo, s.hi = hi;
    s.dxold = vsub(hi, lo), s.dx = s.dxold;
    s.p1 = s.p2 = s.cp = s.xp = vset(0.0);
    s.jumped = s.ph = mfalse();
    return s;
}

/* One iteration in the lanes of s->act, every branch of cdist__root_halley_accel as a select; a
 * lane that stops writes s->res and leaves s->act. Lanes meeting a branch the kernel does not
 * take (fd2f instead of fd2f_scaled, f'^2 out of the solver's range, NaN) are added to *fail.
 * Conditions are taken under the mask of the lanes they concern (vlt_m etc.: one instruction on
 * AVX-512, whose mask logic is a bottleneck here). */
CD_INLINE void KN(solver_step)(const KN(model) *m, KN(solver) *s, M *fail)
{
    const V rel = vset(CD_ROOT_REL_ULPS * DBL_EPSILON), abs_ = vset(CD_ROOT_ABS), half = vset(0.5), zero = vset(0.0);
    V x = s->x, lo = s->lo, hi = s->hi, res = s->res;
    M act = s->act;
    V df, d2f;
    M rok;
    V f = KN(fd2f_scaled)(m, x, &df, &d2f, &rok);
    M good = veq_m(rok, f, f); /* fd2f_scaled's own branch, and f not NaN */
    *fail = mor(*fail, mandn(good, act));
    act = mand(act, good);
    M z = veq_m(act, f, zero);
    res = vsel(z, x, res);
    act = mandn(z, act);
    /* f is a number in the lanes of act: f >= 0 is !(f < 0) */
    lo = vsel(vlt_m(act, f, zero), x, lo);
    hi = vsel(vgt_m(act, f, zero), x, hi);
    /* Halley's step where |f f''| < f'^2, else Newton's; one division */
    V dd = vmul(df, df), fd = vmul(f, df);
    M scaled = mand(vge(dd, vset(0x1p-1000)), vle(dd, vset(0x1p1000)));
    *fail = mor(*fail, mandn(scaled, act));
    act = mand(act, scaled);
    M halley = vlt(vabs(vmul(f, d2f)), dd);
    V step = vdiv(vsel(halley, vmul(vset(2.0), fd), fd), vsel(halley, vmadd(vneg(f), d2f, vmul(vset(2.0), dd)), dd));
    V xn = vsub(x, step);
    M dfpos = vgt(df, zero);
    V as = vabs(step);
    M conv = mor(vle_m(dfpos, as, vmul(rel, vabs(x))), vle_m(dfpos, as, abs_));
    conv = mand(act, conv);
    res = vsel(conv, xn, res);
    act = mandn(conv, act);
    V c = vdiv(d2f, vmul(vset(2.0), df));
    M past = mandn(vlt_m(vgt(xn, lo), xn, hi), dfpos);
    /* to near an end of the bracket (a step lands on or past it, not twice in a row) */
    M jump = mand(act, mandn(s->jumped, past));
    /* bisection: !(df > 0), past, or |2 f| > |dxold df| (and no jump) */
    M newt = vngt_m(mandn(past, mand(act, dfpos)), vabs(vmul(vset(2.0), f)), vabs(vmul(s->dxold, df)));
    newt = mandn(jump, newt);
    M bis = mandn(mor(jump, newt), act);
    /* a fast convergence ending below the tolerance returns the point after the step: the next
     * step 4 |K| as^3 after Halley's, K = (C^2 - C')/3 from C here and at the last point, or
     * 4 K as^2 after two of Newton's, K fitted to them */
    V p1 = s->p1, p2 = s->p2;
    /* cdist__fmax(rel |xn|, abs) is vmax's a > b ? a : b, abs_ being a number */
    V tol = vmax(vmul(rel, vabs(xn)), abs_), dxp = vsub(x, s->xp);
    M quadh = vle_m(vgt_m(mand(newt, halley), p1, zero),
                    vmul(vmul(vset(4.0), vabs(vmadd(vmul(c, c), dxp, vsub(s->cp, c)))), vmul(vmul(as, as), as)),
                    vmul(vmul(vset(3.0), tol), vabs(dxp)));
    M quadn = vle_m(vle_m(mandn(mor(halley, s->ph), newt), vmul(vset(4.0), as), p1), vmul(vmul(vset(4.0), vmul(as, as)), as),
                    vmul(tol, vmul(p1, p1)));
    M quad = mor(quadh, quadn);
    res = vsel(quad, xn, res);
    act = mandn(quad, act);
    newt = mandn(quad, newt);
    /* a steady linear shrink (a multiple root) extrapolated */
    M lin = vlt_m(vge_m(newt, vmul(vset(3.0), as), p1), as, p1);
    if (many(lin)) {
        V asp2 = vmul(as, p2);
        lin = vle_m(lin, vabs(vsub(asp2, vmul(p1, p1))), vmul(vset(0.125), asp2));
    }
    if (many(lin)) {
        V xm = vsub(x, vmul(step, vdiv(p1, vsub(p1, as))));
        xm = vsel(vlt(xm, hi), xm, vsub(hi, vmul(vset(0x1p-6), vsub(hi, x))));
        xm = vsel(vgt(xm, lo), xm, vadd(lo, vmul(vset(0x1p-6), vsub(x, lo))));
        xn = vsel(lin, xm, xn);
    }
    V xb = vsel(bis, vmul(half, vadd(lo, hi)), xn);
    if (many(jump))
        xb = vsel(jump, vsel(vge(xn, hi), vsub(hi, vmul(vset(0x1p-10), vsub(hi, x))), vadd(lo, vmul(vset(0x1p-10), vsub(x, lo)))), xb);
    /* the step lengths: kept after a plain step, cleared after the others */
    M plain = mandn(lin, newt);
    s->p2 = vsel(plain, p1, vsel(act, zero, p2));
    s->p1 = vsel(plain, as, vsel(act, zero, p1));
    s->ph = mor(mand(plain, halley), mandn(plain, s->ph));
    s->cp = vsel(act, c, s->cp);
    s->xp = vsel(act, x, s->xp);
    s->jumped = mor(jump, mandn(act, s->jumped));
    s->dxold = vsel(act, s->dx, s->dxold);
    V dx = vsel(act, vabs(vsub(xb, x)), s->dx);
    x = vsel(act, xb, x);
    M stop = mor(vle_m(act, dx, vmul(rel, vabs(x))), vngt_m(act, vsub(hi, lo), abs_));
    res = vsel(stop, x, res);
    act = mandn(stop, act);
    s->x = x, s->lo = lo, s->hi = hi, s->dx = dx, s->res = res, s->act = act;
}

/* start_far of line_circle.c on the side sigma (+-1 in each lane): R = r m0^2, B = mu m0 - c2. */
CD_INLINE V KN(start_far)(const KN(model) *m, V mu, V R, V B, V sigma)
{
    V x2 = vsub(vmul(sigma, R), B);
    V q = vdiv(vmul(m->x1, m->x1), vmul(x2, x2));
    return vfma(vmul(sigma, vmul(m->r, m->m0)), vsub(vset(1.0), vmul(vset(0.5), q)), vneg(mu));
}

/* start_single of line_circle.c (lanes where R <= |x1|). */
CD_INLINE V KN(start_single)(const KN(model) *m, V mu, V R, V B)
{
    V e = vsub(m->ax1, R), N = vmul(vneg(B), m->ax1);
    M near = vle(vabs(N), vmul(m->ax1, e));
    V e3 = vmul(vmul(m->x1, m->x1), vmul(vmul(e, e), e)), RN2 = vmul(R, vmul(N, N));
    V D = vmul(e, vfma(vset(1.5), RN2, e3));
    V sn = vdiv(vfma(N, vadd(e3, RN2), vmul(vneg(m->c2), D)), vmul(m->m0, D));
    V sf = KN(start_far)(m, mu, R, B, vsel(vgt(B, vset(0.0)), vset(-1.0), vset(1.0)));
    return vsel(near, sn, sf);
}

/* rho - r of the model (rho_minus_r) */
CD_INLINE V KN(rho_minus_r)(const KN(model) *m, V x2, V rho) { return vdiv(vmadd(x2, x2, m->rr2), vadd(rho, m->r)); }

/* fp_at of line_circle.c at height h and in-plane x2, side -1 or +1 on the axis. */
CD_INLINE V KN(fp_at)(const KN(model) *m, V h, V x2, double side)
{
    V rho = vsqrt(vmadd(m->x1, m->x1, vmul(x2, x2)));
    V on_axis = vsub(vmul(m->a, h), vmul(vmul(vset(side), m->r), m->m0));
    V off = vmadd(m->a, h, vmul(vmul(m->m0, x2), vdiv(KN(rho_minus_r)(m, x2, rho), rho)));
    return vsel(veq(rho, vset(0.0)), on_axis, off);
}

/* Squared distance of offer_model at s, times up twice. */
CD_INLINE V KN(model_d2)(const KN(model) *m, V s, V up)
{
    V h = vmadd(m->a, s, m->h), x2 = vmadd(m->m0, s, m->c2);
    V rho = vsqrt(vmadd(m->x1, m->x1, vmul(x2, x2)));
    V dr = KN(rho_minus_r)(m, x2, rho);
    return vmul(vmul(vmadd(h, h, vmul(dr, dr)), up), up);
}

/* offer_end's squared distance: the point B + t M against the circle (normal n, radius r). */
CD_INLINE V KN(end_d2)(V Bx, V By, V Bz, V Mx, V My, V Mz, V t, V nx, V ny, V nz, V r)
{
    V Px = vfma(t, Mx, Bx), Py = vfma(t, My, By), Pz = vfma(t, Mz, Bz);
    V qx, qy, qz;
    KN(cross)(nx, ny, nz, Px, Py, Pz, &qx, &qy, &qz);
    V h = KN(dot)(nx, ny, nz, Px, Py, Pz);
    V rho = vsqrt(KN(dot)(qx, qy, qz, qx, qy, qz));
    V dr = vsub(rho, r);
    return vfma(dr, dr, vmul(h, h));
}

/* Stage 1, entries base .. base + W - 1 of block b (n of them real): in[f][l] is field f of lane
 * l (the first object's six numbers, then the circle's seven); shape: LK_LINE, LK_RAY or
 * LK_SEGMENT. Validation, framing, scaling and the model of linear_circle; the brackets of
 * robust_roots where F' increases everywhere ("single"), the finite ends' candidates. */
static void KN(stage_frame)(double in[13][W], int shape, double tol, lk_block *b, int base, int n)
{
    const V zero = vset(0.0), one = vset(1.0);
    V ax = vld(in[0]), ay = vld(in[1]), az = vld(in[2]), bx = vld(in[3]), by = vld(in[4]), bz = vld(in[5]);
    V cx = vld(in[6]), cy = vld(in[7]), cz = vld(in[8]), ndx = vld(in[9]), ndy = vld(in[10]), ndz = vld(in[11]);
    V r = vld(in[12]);

    /* ---- validation: cdist__check_point / cdist__check_direction / circle_fast ---- */
    M ok = mand(mand(KN(in_range)(ax, ay, az), KN(in_range)(bx, by, bz)), KN(in_range)(cx, cy, cz));
    ok = mand(ok, mand(KN(in_range)(ndx, ndy, ndz), mand(vge(r, zero), vle(r, vset(CD_MAX_ABS)))));
    V nm = KN(max3)(ndx, ndy, ndz);
    ok = mand(ok, vge(nm, vset(CD_MIN_NORMAL_FAST)));
    V nlen = vsqrt(KN(dot)(ndx, ndy, ndz, ndx, ndy, ndz));
    ok = mand(ok, vle(vabs(vsub(nlen, one)), vset(tol)));
    V inl = vdiv(one, nlen);
    V nx = vmul(inl, ndx), ny = vmul(inl, ndy), nz = vmul(inl, ndz);
    /* v_basis: e = the axis of the smallest |n_k| (first on ties), u = normalise(e - (e.n) n), v = n x u */
    V anx = vabs(nx), any = vabs(ny), anz = vabs(nz);
    M kx = mand(vle(anx, any), vle(anx, anz));
    M ky = mandn(kx, vle(any, anz));
    M kz = mandn(mor(kx, ky), mtrue());
    V ex = vsel(kx, one, zero), ey = vsel(ky, one, zero), ez = vsel(kz, one, zero);
    V edn = vneg(KN(dot)(ex, ey, ez, nx, ny, nz));
    V wx = vfma(edn, nx, ex), wy = vfma(edn, ny, ey), wz = vfma(edn, nz, ez);
    V iw = vdiv(one, vsqrt(KN(dot)(wx, wy, wz, wx, wy, wz)));
    V ux = vmul(iw, wx), uy = vmul(iw, wy), uz = vmul(iw, wz);
    V vx, vy, vz;
    KN(cross)(nx, ny, nz, ux, uy, uz, &vx, &vy, &vz);

    /* ---- the first object: origin O, direction D (as the caller's, then scaled), unit M ---- */
    V Ox = ax, Oy = ay, Oz = az, Dx, Dy, Dz;
    V L;
    if (shape == LK_SEGMENT) {
        Dx = vsub(bx, ax), Dy = vsub(by, ay), Dz = vsub(bz, az);
        L = KN(fmax)(r, KN(max3)(vsub(ax, cx), vsub(ay, cy), vsub(az, cz)));
        L = KN(fmax)(L, KN(max3)(vsub(bx, cx), vsub(by, cy), vsub(bz, cz)));
    } else {
        Dx = bx, Dy = by, Dz = bz;
        L = KN(fmax)(r, KN(max3)(vsub(ax, cx), vsub(ay, cy), vsub(az, cz)));
    }
    /* run_scaled: scale exponent of L (normal L only) */
    ok = mand(ok, vge(L, vset(0x1p-1022)));
    V UP = KN(pow2_of)(L), down = vrecip2(UP);
    cx = vmul(down, cx), cy = vmul(down, cy), cz = vmul(down, cz);
    r = vmul(r, down);
    Ox = vmul(down, Ox), Oy = vmul(down, Oy), Oz = vmul(down, Oz);
    V dm, len, Mx, My, Mz;
    if (shape == LK_SEGMENT) {
        /* scaled before the normalisation; any length */
        Dx = vmul(down, Dx), Dy = vmul(down, Dy), Dz = vmul(down, Dz);
        dm = KN(max3)(Dx, Dy, Dz);
        ok = mand(ok, vge(dm, vset(CD_MIN_NORMAL_FAST)));
        len = vsqrt(KN(dot)(Dx, Dy, Dz, Dx, Dy, Dz));
        V il = vdiv(one, len);
        Mx = vmul(il, Dx), My = vmul(il, Dy), Mz = vmul(il, Dz);
    } else {
        /* unit within tol, normalised before the scaling */
        dm = KN(max3)(Dx, Dy, Dz);
        ok = mand(ok, vge(dm, vset(CD_MIN_NORMAL_FAST)));
        len = vsqrt(KN(dot)(Dx, Dy, Dz, Dx, Dy, Dz));
        ok = mand(ok, vle(vabs(vsub(len, one)), vset(tol)));
        V il = vdiv(one, len);
        Mx = vmul(il, Dx), My = vmul(il, Dy), Mz = vmul(il, Dz);
        Dx = vmul(down, Dx), Dy = vmul(down, Dy), Dz = vmul(down, Dz);
        len = vmul(len, down);
    }
    V tmin = vset(shape == LK_LINE ? -INFINITY : 0.0), tmax = vset(shape == LK_SEGMENT ? 1.0 : INFINITY);

    /* ---- cdist__line_near_centre: origin - C exactly (TwoSum), moved to the point nearest C ---- */
    V hx = vsub(Ox, cx), hy = vsub(Oy, cy), hz = vsub(Oz, cz);
    V lx, ly, lz;
    {
        V b, mcx = vneg(cx), mcy = vneg(cy), mcz = vneg(cz);
        b = vsub(hx, Ox), lx = vadd(vsub(Ox, vsub(hx, b)), vsub(mcx, b));
        b = vsub(hy, Oy), ly = vadd(vsub(Oy, vsub(hy, b)), vsub(mcy, b));
        b = vsub(hz, Oz), lz = vadd(vsub(Oz, vsub(hz, b)), vsub(mcz, b));
    }
    V m = KN(max3)(Dx, Dy, Dz);
    ok = mand(ok, mand(vge(m, vset(0x1p-1021)), vlt(m, vset(0x1p1022))));
    V p = vrecip2(vexpbits(m));
    V Dsx = vmul(p, Dx), Dsy = vmul(p, Dy), Dsz = vmul(p, Dz);
    V t = vmul(vneg(vdiv(KN(dot)(hx, hy, hz, Dsx, Dsy, Dsz), KN(dot)(Dsx, Dsy, Dsz, Dsx, Dsy, Dsz))), p);
    t = vsel(vle(vabs(t), vset(DBL_MAX)), t, zero);
    t = KN(fmin)(KN(fmax)(t, tmin), tmax);
    V Bx = vadd(vfma(t, Dx, hx), lx), By = vadd(vfma(t, Dy, hy), ly), Bz = vadd(vfma(t, Dz, hz), lz);
    /* run: the range in units of M */
    V lo = vsel(veq(tmin, t), zero, vmul(vsub(tmin, t), len));
    V hi = vsel(veq(tmax, t), zero, vmul(vsub(tmax, t), len));

    /* ---- linear_circle (ROBUST) ---- */
    ok = mand(ok, vlt(lo, hi));
    ok = mand(ok, mand(KN(in_range)(Bx, By, Bz), vgt(r, zero))); /* finite B (|B| <= 4 here); r = 0: scalar */
    V t0 = vneg(KN(dot)(Bx, By, Bz, Mx, My, Mz));
    V B0x = vfma(t0, Mx, Bx), B0y = vfma(t0, My, By), B0z = vfma(t0, Mz, Bz);
    V dt = vneg(KN(dot)(B0x, B0y, B0z, Mx, My, Mz));
    M cor = vne(dt, zero);
    t0 = vsel(cor, vadd(t0, dt), t0);
    B0x = vsel(cor, vfma(t0, Mx, Bx), B0x);
    B0y = vsel(cor, vfma(t0, My, By), B0y);
    B0z = vsel(cor, vfma(t0, Mz, Bz), B0z);
    V umin = vsub(lo, t0), umax = vsub(hi, t0);
    V S = KN(fmax)(r, vsqrt(KN(dot)(B0x, B0y, B0z, B0x, B0y, B0z)));
    ok = mand(ok, vge(S, vset(0x1p-1022)));
    V up = KN(pow2_of)(S), sg = vrecip2(up);
    V Bsx = vmul(sg, B0x), Bsy = vmul(sg, B0y), Bsz = vmul(sg, B0z);
    V rs = vmul(r, sg);
    umin = vmul(umin, sg), umax = vmul(umax, sg);
    /* B0's in-plane coordinates and height taken on B0 and scaled after (exact), unless B0 is
     * within 2^-400 of the centre: then on the scaled B0 */
    V wwx, wwy, wwz, nbx, nby, nbz;
    KN(cross)(nx, ny, nz, B0x, B0y, B0z, &nbx, &nby, &nbz);
    V b2x = vmul(KN(dot)(vx, vy, vz, nbx, nby, nbz), sg), b2y = vmul(vneg(KN(dot)(ux, uy, uz, nbx, nby, nbz)), sg);
    V h0 = vmul(KN(dot)(nx, ny, nz, B0x, B0y, B0z), sg);
    M late = mnot(vge(KN(max3)(B0x, B0y, B0z), vset(0x1p-400)));
    if (many(mand(late, ok))) {
        KN(cross)(nx, ny, nz, Bsx, Bsy, Bsz, &nbx, &nby, &nbz);
        b2x = vsel(late, KN(dot)(vx, vy, vz, nbx, nby, nbz), b2x);
        b2y = vsel(late, vneg(KN(dot)(ux, uy, uz, nbx, nby, nbz)), b2y);
        h0 = vsel(late, KN(dot)(nx, ny, nz, Bsx, Bsy, Bsz), h0);
    }
    KN(cross)(nx, ny, nz, Mx, My, Mz, &wwx, &wwy, &wwz);
    V m2x = KN(dot)(vx, vy, vz, wwx, wwy, wwz), m2y = vneg(KN(dot)(ux, uy, uz, wwx, wwy, wwz));
    V a = KN(dot)(nx, ny, nz, Mx, My, Mz);
    V mm = vadd(vmul(m2x, m2x), vmul(m2y, m2y)), m0 = vsqrt(mm);
    ok = mand(ok, vgt(m0, vset(CD_LC_PERP_ULPS * DBL_EPSILON))); /* perpendicular to the plane: scalar */

    KN(model) md;
    md.r = rs;
    md.a = a;
    md.m0 = m0;
    V e2x = vdiv(m2x, m0), e2y = vdiv(m2y, m0);
    md.x1 = vsub(vmul(e2x, b2y), vmul(e2y, b2x));
    md.ax1 = vabs(md.x1);
    V c2 = vfma(e2x, b2x, vmul(e2y, b2y));
    V us = vdiv(vneg(vfma(m2x, b2x, vmul(m2y, b2y))), mm); /* -c2 / m0 with one division */
    M canon = vle(vabs(us), vset(4.0));
    V uO = vsel(canon, us, zero);
    md.c2 = vsel(canon, zero, c2);
    md.h = vsel(canon, vfma(a, us, h0), h0);
    V smin = vsub(umin, uO), smax = vsub(umax, uO);
    md.k = vmadd(a, a, vmul(m0, m0));
    md.rr2 = vmul(vsub(md.ax1, rs), vadd(md.ax1, rs));
    md.dfc = vmul(vneg(vmul(vmul(rs, m0), m0)), vmul(md.ax1, md.ax1));

    /* robust_roots: one bracket where F' increases everywhere, else up to one per branch
     * (stage_branches) */
    V mu = vfma(a, md.h, vmul(m0, md.c2));
    V rm0 = vmul(rs, m0);
    V blo = vsub(vneg(mu), rm0), bhi = vadd(vneg(mu), rm0);
    V rm02 = vmul(rm0, m0);
    M single = vle(rm02, md.ax1);
    /* the start of a single bracket (the branches' are stage_branches') */
    V x0 = vsel(single, KN(start_single)(&md, mu, rm02, vfma(mu, m0, vneg(md.c2))), vset(NAN));
    V best = vset(INFINITY);
    M fail = mfalse();
    if (shape != LK_LINE) { /* the finite ends (offer_end), in the units of the core's range */
        V d2 = KN(end_d2)(Bx, By, Bz, Mx, My, Mz, lo, nx, ny, nz, r);
        best = vmin(best, d2);
        fail = mor(fail, vne(d2, d2));
        if (shape == LK_SEGMENT) {
            d2 = KN(end_d2)(Bx, By, Bz, Mx, My, Mz, hi, nx, ny, nz, r);
            best = vmin(best, d2);
            fail = mor(fail, vne(d2, d2));
        }
    }
    const V *cols[LK_NF] = {&md.r, &md.a, &md.m0, &md.x1, &md.ax1, &md.c2, &md.h, &md.k, &md.rr2, &md.dfc,
                            &up, &UP, &blo, &bhi, &x0, &smin, &smax, &best};
    for (int f = 0; f < LK_NF; f++) vst(&b->f[f][base], *cols[f]);
    unsigned okb = mbits(ok), singleb = mbits(single), failb = mbits(fail);
    for (int l = 0; l < W; l++) {
        int real = l < n;
        b->ok[base + l] = (unsigned char)(real && (okb >> l & 1) && !(failb >> l & 1));
        b->two[base + l] = (unsigned char)(b->ok[base + l] && !(singleb >> l & 1));
    }
}

/* The model of W entries e[0..W-1] of block b. */
CD_INLINE void KN(load_model)(const lk_block *b, const int *e, KN(model) *m)
{
    double col[10][W];
    for (int f = 0; f < 10; f++)
        for (int l = 0; l < W; l++) col[f][l] = b->f[f][e[l]];
    m->r = vld(col[0]), m->a = vld(col[1]), m->m0 = vld(col[2]), m->x1 = vld(col[3]), m->ax1 = vld(col[4]);
    m->c2 = vld(col[5]), m->h = vld(col[6]), m->k = vld(col[7]), m->rr2 = vld(col[8]), m->dfc = vld(col[9]);
    m->d2c = vmul(vmul(vset(-3.0), m->m0), m->dfc);
}

/* Field f of W entries e[0..W-1]. */
CD_INLINE V KN(load_field)(const lk_block *b, int f, const int *e)
{
    double col[W];
    for (int l = 0; l < W; l++) col[l] = b->f[f][e[l]];
    return vld(col);
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
 * cdist__cbrt lane by lane (the scalar instantiation always). */
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

/* y[i] = KN(cbrt)(x[i]), n a multiple of W (for the tests). */
static inline void KN(cbrt_lanes)(const double *x, double *y, int n)
{
    for (int i = 0; i < n; i += W) vst(&y[i], KN(cbrt)(vld(&x[i])));
}

/* Stage 2, the entries e[0..n-1] (n <= W; the rest of e repeats e[0]) where F' is not monotone:
 * the tangent points of slope 1 and the brackets of the branches that hold a local minimum,
 * written to b->br (A: left, B: right) and b->has. */
static void KN(stage_branches)(lk_block *b, const int *e, int n)
{
    const V zero = vset(0.0);
    KN(model) md;
    KN(load_model)(b, e, &md);
    V blo = KN(load_field)(b, LK_F_BLO, e), bhi = KN(load_field)(b, LK_F_BHI, e);
    V cm = KN(cbrt)(vmul(md.m0, md.ax1)), cr = KN(cbrt)(md.r);
    V rhohat = vmul(vmul(cr, cm), cm);
    V x2hat = vsqrt(KN(fmax)(zero, vmul(vsub(rhohat, md.ax1), vadd(rhohat, md.ax1))));
    V sc = vneg(vdiv(md.c2, md.m0));
    V xm = vdiv(x2hat, md.m0);
    V sL = vsub(sc, xm), sR = vadd(sc, xm);
    V fL = KN(fp_at)(&md, vfma(md.a, sL, md.h), vneg(x2hat), -1.0);
    V fR = KN(fp_at)(&md, vfma(md.a, sR, md.h), x2hat, +1.0);
    M left = vge(fL, zero), right = vle(fR, zero);
    M neither = mnot(mor(left, right));
    left = mor(left, neither), right = mor(right, neither);
    unsigned hasA = mbits(mand(left, vle(blo, sL))), hasB = mbits(mand(right, vle(sR, bhi)));
    double hiA[W], loB[W], x0A[W], x0B[W];
    vst(hiA, KN(fmin)(sL, bhi));
    vst(loB, KN(fmax)(sR, blo));
    V mu = vfma(md.a, md.h, vmul(md.m0, md.c2));
    V R = vmul(vmul(md.r, md.m0), md.m0), B = vfma(mu, md.m0, vneg(md.c2));
    vst(x0A, KN(start_far)(&md, mu, R, B, vset(-1.0)));
    vst(x0B, KN(start_far)(&md, mu, R, B, vset(1.0)));
    for (int l = 0; l < n; l++) {
        int i = e[l];
        b->br[0][0][i] = b->f[LK_F_BLO][i], b->br[0][1][i] = hiA[l], b->br[0][2][i] = x0A[l];
        b->br[1][0][i] = loB[l], b->br[1][1][i] = b->f[LK_F_BHI][i], b->br[1][2][i] = x0B[l];
        b->has[0][i] = (unsigned char)(hasA >> l & 1), b->has[1][i] = (unsigned char)(hasB >> l & 1);
    }
}

/* Stage 3, the brackets k[0..n-1] of the item list (n <= LK_CHAINS * W; the rest of k repeats
 * k[0]): the root of each (cdist__root_halley_accel) and the squared distance there (offer_model),
 * to b->item_d2. The iteration is a chain of dependent square roots and divisions:
 * LK_CHAINS groups of W brackets iterate side by side to keep the units busy. */
static void KN(stage_solve)(lk_block *b, const int *k, int n)
{
    KN(model) md[LK_CHAINS];
    KN(solver) s[LK_CHAINS];
    M fail[LK_CHAINS];
    int e[LK_CHAINS][W];
    for (int c = 0; c < LK_CHAINS; c++) {
        double lo[W], hi[W], x0[W], act[W];
        for (int l = 0; l < W; l++) {
            int j = k[c * W + l];
            e[c][l] = b->item_entry[j], lo[l] = b->item_lo[j], hi[l] = b->item_hi[j], x0[l] = b->item_x0[j];
            act[l] = c * W + l < n ? 1.0 : 0.0;
        }
        KN(load_model)(b, e[c], &md[c]);
        s[c] = KN(solver_start)(vld(lo), vld(hi), vld(x0), vgt(vld(act), vset(0.0)));
        fail[c] = mfalse();
    }
    for (int it = 0; it < LK_LANE_ITER; it++) {
        M act = s[0].act;
        for (int c = 1; c < LK_CHAINS; c++) act = mor(act, s[c].act);
        if (!many(act)) break;
        for (int c = 0; c < LK_CHAINS; c++) KN(solver_step)(&md[c], &s[c], &fail[c]);
    }
    /* a lane still iterating (a bracket bisected down to its end, as when the root lies beyond
     * a ray's start: ~50 iterations) goes on in stage_long, with the other such lanes */
    for (int c = 0; c < LK_CHAINS; c++) {
        unsigned rest = mbits(mandn(fail[c], s[c].act));
        if (!rest) continue;
        double st[LK_NS][W];
        vst(st[LK_S_X], s[c].x), vst(st[LK_S_LO], s[c].lo), vst(st[LK_S_HI], s[c].hi);
        vst(st[LK_S_DX], s[c].dx), vst(st[LK_S_DXOLD], s[c].dxold);
        vst(st[LK_S_P1], s[c].p1), vst(st[LK_S_P2], s[c].p2);
        vst(st[LK_S_JUMPED], vsel(s[c].jumped, vset(1.0), vset(0.0)));
        vst(st[LK_S_PH], vsel(s[c].ph, vset(1.0), vset(0.0)));
        vst(st[LK_S_CP], s[c].cp), vst(st[LK_S_XP], s[c].xp);
        for (int l = 0; l < W; l++) {
            if (!(rest >> l & 1)) continue;
            int j = b->n_long++;
            b->long_item[j] = k[c * W + l];
            for (int f = 0; f < LK_NS; f++) b->long_st[f][j] = st[f][l];
        }
    }
    for (int c = 0; c < LK_CHAINS; c++) {
        V d2 = KN(model_d2)(&md[c], s[c].res, KN(load_field)(b, LK_F_UP, e[c]));
        double out[W];
        vst(out, d2);
        unsigned fb = mbits(mor(fail[c], vne(d2, d2)));
        for (int l = 0; l < W && c * W + l < n; l++) {
            b->item_d2[k[c * W + l]] = out[l];
            b->item_fail[k[c * W + l]] = (unsigned char)(fb >> l & 1);
        }
    }
}

/* Stage 3b, the long brackets j[0..n-1] (n <= W; the rest of j repeats j[0]) that stage_solve
 * left: their iterations go on together up to CD_ROOT_MAX_ITER in all, where
 * cdist__root_halley_accel returns its last x.
 * The screen: a root that took that long and is not at an end of the range (a ray's start, a
 * segment's end: the bracket bisected down to the end where F' does not vanish, the end
 * candidate decides) is a nearly multiple root of F' (a tangent line), where the solvers stop
 * at different points of a flat bottom: such an entry is left to the scalar path, so that its
 * answer is the single query's whatever solver that uses. */
static void KN(stage_long)(lk_block *b, const int *j, int n)
{
    int e[W];
    double st[LK_NS][W], act[W];
    for (int l = 0; l < W; l++) {
        e[l] = b->item_entry[b->long_item[j[l]]];
        for (int f = 0; f < LK_NS; f++) st[f][l] = b->long_st[f][j[l]];
        act[l] = l < n ? 1.0 : 0.0;
    }
    KN(model) md;
    KN(load_model)(b, e, &md);
    KN(solver) s;
    s.x = vld(st[LK_S_X]), s.lo = vld(st[LK_S_LO]), s.hi = vld(st[LK_S_HI]), s.dx = vld(st[LK_S_DX]);
    s.dxold = vld(st[LK_S_DXOLD]), s.p1 = vld(st[LK_S_P1]), s.p2 = vld(st[LK_S_P2]);
    s.jumped = vgt(vld(st[LK_S_JUMPED]), vset(0.0));
    s.ph = vgt(vld(st[LK_S_PH]), vset(0.0));
    s.cp = vld(st[LK_S_CP]), s.xp = vld(st[LK_S_XP]);
    s.res = s.x;
    s.act = vgt(vld(act), vset(0.0));
    M fail = mfalse();
    for (int it = LK_LANE_ITER; it < CD_ROOT_MAX_ITER && many(s.act); it++) KN(solver_step)(&md, &s, &fail);
    s.res = vsel(s.act, s.x, s.res);
    V smin = KN(load_field)(b, LK_F_SMIN, e), smax = KN(load_field)(b, LK_F_SMAX, e);
    V tol = vset(8.0 * DBL_EPSILON), atol = vset(0x1p-60);
    V big = vset(DBL_MAX); /* a finite end only (a line has none) */
    M at_min = mand(vle(vabs(smin), big), vle(vabs(vsub(s.res, smin)), vadd(vmul(tol, vabs(smin)), atol)));
    M at_max = mand(vle(vabs(smax), big), vle(vabs(vsub(s.res, smax)), vadd(vmul(tol, vabs(smax)), atol)));
    fail = mor(fail, mnot(mor(at_min, at_max)));
    V d2 = KN(model_d2)(&md, s.res, KN(load_field)(b, LK_F_UP, e));
    double out[W];
    vst(out, d2);
    unsigned fb = mbits(mor(fail, vne(d2, d2)));
    for (int l = 0; l < n; l++) {
        int k = b->long_item[j[l]];
        b->item_d2[k] = out[l];
        b->item_fail[k] = (unsigned char)(fb >> l & 1);
    }
}

/* Stage 4, entries base .. base + W - 1: the distance from the smallest candidate, unscaled;
 * returns the mask of the entries left to the scalar path. */
static unsigned KN(stage_final)(lk_block *b, int base, double *out)
{
    V d = vmul(vsqrt(vld(&b->f[LK_F_BEST][base])), vld(&b->f[LK_F_OUTER][base]));
    vst(out, d);
    unsigned fin = mbits(vle(d, vset(DBL_MAX))), left = 0;
    for (int l = 0; l < W; l++) left |= (unsigned)(!(b->ok[base + l] && (fin >> l & 1))) << l;
    return left;
}

/* Entries [lo, lo + count) of the job, count <= 64: the four stages over the block; returns the
 * mask of the entries left to the scalar path. The stages after the first take the entries
 * that need them, W at a time, so that the lanes stay busy (a quarter of random lines need
 * stage 2, the iterations of a bracket vary). */
static uint64_t KN(block)(const cdist__job *job, int shape, double tol, size_t lo, size_t count)
{
    lk_block b;
    double in[13][W];
    int cnt = (int)count;
    for (int base = 0; base < cnt; base += W) {
        int n = cnt - base < W ? cnt - base : W;
#ifdef vload_objects /* a whole group of consecutive objects: loads and a transpose */
        if (n == W) {
            V cols[16];
            vload_objects(cdist__job_a(job, lo + (size_t)base), job->a_stride, 6, cols);
            vload_objects(cdist__job_b(job, lo + (size_t)base), job->b_stride, 7, cols + 8);
            for (int f = 0; f < 6; f++) vst(in[f], cols[f]);
            for (int f = 0; f < 7; f++) vst(in[6 + f], cols[8 + f]);
        } else
#endif
        for (int l = 0; l < W; l++) {
            size_t i = lo + (size_t)base + (size_t)(l < n ? l : 0);
            const double *pa = cdist__job_a(job, i), *pb = cdist__job_b(job, i);
            for (int f = 0; f < 6; f++) in[f][l] = pa[f];
            for (int f = 0; f < 7; f++) in[6 + f][l] = pb[f];
        }
        KN(stage_frame)(in, shape, tol, &b, base, n);
    }
    int e[W], ne = 0;
    for (int i = 0; i < cnt; i++) {
        if (!b.ok[i]) continue;
        if (!b.two[i]) {
            b.br[0][0][i] = b.f[LK_F_BLO][i], b.br[0][1][i] = b.f[LK_F_BHI][i], b.br[0][2][i] = b.f[LK_F_X0][i];
            b.has[0][i] = 1, b.has[1][i] = 0;
            continue;
        }
        e[ne++] = i;
        if (ne == W) {
            KN(stage_branches)(&b, e, W);
            ne = 0;
        }
    }
    if (ne) {
        for (int l = ne; l < W; l++) e[l] = e[0];
        KN(stage_branches)(&b, e, ne);
    }
    /* the brackets clipped to the range; an empty one has no root */
    int ni = 0;
    b.n_long = 0;
    for (int i = 0; i < cnt; i++) {
        if (!b.ok[i]) continue;
        for (int j = 0; j < 2; j++) {
            if (!b.has[j][i]) continue;
            double blo = cdist__fmax(b.br[j][0][i], b.f[LK_F_SMIN][i]);
            double bhi = cdist__fmin(b.br[j][1][i], b.f[LK_F_SMAX][i]);
            if (blo > bhi) continue;
            b.item_entry[ni] = i, b.item_lo[ni] = blo, b.item_hi[ni] = bhi, b.item_x0[ni] = b.br[j][2][i];
            ni++;
        }
    }
    int k[LK_CHAINS * W];
    for (int s0 = 0; s0 < ni; s0 += LK_CHAINS * W) {
        int n = ni - s0 < LK_CHAINS * W ? ni - s0 : LK_CHAINS * W;
        for (int l = 0; l < LK_CHAINS * W; l++) k[l] = s0 + (l < n ? l : 0);
        KN(stage_solve)(&b, k, n);
    }
    for (int s0 = 0; s0 < b.n_long; s0 += W) {
        int n = b.n_long - s0 < W ? b.n_long - s0 : W, j[W];
        for (int l = 0; l < W; l++) j[l] = s0 + (l < n ? l : 0);
        KN(stage_long)(&b, j, n);
    }
    unsigned char cand[64];
    memset(cand, shape != LK_LINE, sizeof cand); /* rays and segments: the ends */
    for (int j = 0; j < ni; j++) {
        int i = b.item_entry[j];
        if (b.item_fail[j]) b.ok[i] = 0;
        double d2 = b.item_d2[j], *best = &b.f[LK_F_BEST][i];
        *best = *best < d2 ? *best : d2;
        cand[i] = 1;
    }
    uint64_t left = 0;
    double out[W];
    for (int base = 0; base < cnt; base += W) {
        int n = cnt - base < W ? cnt - base : W;
        for (int l = 0; l < n; l++) b.ok[base + l] &= cand[base + l];
        unsigned lb = KN(stage_final)(&b, base, out) & ((1u << n) - 1u);
        for (int l = 0; l < n; l++)
            if (!(lb >> l & 1)) job->distances[lo + (size_t)(base + l)] = out[l];
        left |= (uint64_t)lb << base;
    }
    return left;
}

#undef veq_m
#undef vlt_m
#undef vgt_m
#undef vle_m
#undef vge_m
#undef vngt_m
