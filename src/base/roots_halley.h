/* SPDX-License-Identifier: MIT */
/* The one safeguarded bracketed root finder (cdist__root_halley_accel, src/base/roots.h, where
 * its steps and stopping rule are described), written once over lanes: one step of the solver
 * in every lane of a state, each branch as a select. Included after lanes_def.h (and
 * lanes_vec.h) once per variant: the 1-lane instance is the scalar solver (roots.c, and the
 * line-circle query with its evaluator inlined), the 4- and 8-lane instances run the batch
 * kernels' brackets side by side, bit for bit as the scalar solver. No include guard. */

/* CD_MADD of the scalar code in lanes: a hardware fma only when the whole build targets it. */
#ifndef vmadd
#ifdef FP_FAST_FMA
#define vmadd(a, b, c) vfma(a, b, c)
#else
#define vmadd(a, b, c) vadd(vmul(a, b), c)
#endif
#endif

/* Comparisons under a mask: m and (a op b); vngt_m: m and !(a > b) (one instruction on
 * AVX-512, whose mask logic is a bottleneck of the step). Redefined for each variant. */
#undef veq_m
#undef vlt_m
#undef vgt_m
#undef vle_m
#undef vge_m
#undef vngt_m
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

/* The solver's state in each lane: x the point to evaluate next, [lo, hi] the bracket, act =
 * still iterating, res = the answer of a lane that stopped (lo for an empty bracket, NaN where
 * f was NaN); dx, dxold the last two moves; p1, p2 the last two steps' lengths (0: none since a
 * bisection or an extrapolation), ph = the last of them was Halley's; cp, xp C = f'' / (2 f')
 * and x at the last point; jumped = the last step went to near an end of the bracket. A lane
 * still active after the caller's iteration cap answers x. */
typedef struct KN(halley) {
    V x, lo, hi, dx, dxold, p1, p2, cp, xp, res;
    M jumped, ph, act;
} KN(halley);

CD_INLINE KN(halley) KN(halley_start)(V lo, V hi, V x0, M act)
{
    KN(halley) s;
    s.res = lo;
    s.act = mand(act, vlt(lo, hi));
    s.x = vsel(mand(vgt(x0, lo), vlt(x0, hi)), x0, vmul(vset(0.5), vadd(lo, hi)));
    s.lo = lo, s.hi = hi;
    s.dxold = vsub(hi, lo), s.dx = s.dxold;
    s.p1 = s.p2 = s.cp = s.xp = vset(0.0);
    s.jumped = s.ph = mfalse();
    return s;
}

/* One step in the lanes of s->act from f, f' and f'' at s->x (f increasing through its root;
 * the three may share one positive factor). A lane that stops writes s->res and leaves s->act. */
CD_INLINE void KN(halley_step)(KN(halley) *s, V f, V df, V d2f, V rel, V abs_)
{
    const V zero = vset(0.0);
    V x = s->x, lo = s->lo, hi = s->hi, res = s->res;
    M act = s->act;
    M bad = mandn(veq_m(act, f, f), act);
    res = vsel(bad, vset(NAN), res);
    act = mandn(bad, act);
    M z = veq_m(act, f, zero);
    res = vsel(z, x, res);
    act = mandn(z, act);
    /* f is a number in the lanes of act: f >= 0 is !(f < 0) */
    lo = vsel(vlt_m(act, f, zero), x, lo);
    hi = vsel(vgt_m(act, f, zero), x, hi);
    /* Halley's step where |f f''| < f'^2 (the denominator in (f'^2, 3 f'^2)), Newton's
     * otherwise, as f / f' where f'^2 leaves [2^-1000, 2^1000]: one division either way */
    V dd = vmul(df, df), fd = vmul(f, df);
    M scaled = mand(vge(dd, vset(0x1p-1000)), vle(dd, vset(0x1p1000)));
    M halley = vlt_m(scaled, vabs(vmul(f, d2f)), dd), unscaled = mnot(scaled);
    V num = fd, den = dd;
    if (many(halley)) {
        num = vsel(halley, vmul(vset(2.0), fd), num);
        den = vsel(halley, vmadd(vneg(f), d2f, vmul(vset(2.0), dd)), den);
    }
    if (many(unscaled)) num = vsel(unscaled, f, num), den = vsel(unscaled, df, den);
    V step = vdiv(num, den);
    V xn = vsub(x, step), as = vabs(step);
    M dfpos = vgt(df, zero);
    M conv = mand(act, mor(vle_m(dfpos, as, vmul(rel, vabs(x))), vle_m(dfpos, as, abs_)));
    res = vsel(conv, xn, res);
    act = mandn(conv, act);
    if (W == 1 && !many(act)) goto out;
    V c = vdiv(d2f, vmul(vset(2.0), df)); /* C, free of the callback's factor */
    M past = mandn(vlt_m(vgt(xn, lo), xn, hi), dfpos);
    /* to near an end of the bracket (a step lands on or past it, not twice in a row) */
    M jump = mand(act, mandn(s->jumped, past));
    /* a plain step: df > 0, not past, |2 f| <= |dxold df|; the others bisect */
    M plain = vngt_m(mandn(past, mand(act, dfpos)), vabs(vmul(vset(2.0), f)), vabs(vmul(s->dxold, df)));
    plain = mandn(jump, plain);
    M bis = mandn(mor(jump, plain), act);
    /* a fast convergence: the next step below the tolerance with a margin of 4 returns the
     * point after this step */
    V p1 = s->p1, p2 = s->p2;
    V tol = vmax(vmul(rel, vabs(xn)), abs_), dxp = vsub(x, s->xp);
    M quad = vgt_m(mand(plain, halley), p1, zero), quadn = mandn(mor(halley, s->ph), plain);
    if (many(quad))
        quad = vle_m(quad, vmul(vmul(vset(4.0), vabs(vmadd(vmul(c, c), dxp, vsub(s->cp, c)))), vmul(vmul(as, as), as)),
                     vmul(vmul(vset(3.0), tol), vabs(dxp)));
    if (many(quadn)) {
        quadn = vle_m(quadn, vmul(vset(4.0), as), p1);
        quad = mor(quad, vle_m(quadn, vmul(vmul(vset(4.0), vmul(as, as)), as), vmul(tol, vmul(p1, p1))));
    }
    res = vsel(quad, xn, res);
    act = mandn(quad, act);
    if (W == 1 && !many(act)) goto out;
    plain = mandn(quad, plain);
    /* a steady linear shrink q in [1/3, 1), |q - p1/p2| <= q/8 (a multiple root): the step
     * times 1 / (1 - q), kept inside the bracket */
    M lin = vlt_m(vge_m(plain, vmul(vset(3.0), as), p1), as, p1);
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
    V xb = xn;
    if (many(bis)) xb = vsel(bis, vmul(vset(0.5), vadd(lo, hi)), xn);
    if (many(jump))
        xb = vsel(jump, vsel(vge(xn, hi), vsub(hi, vmul(vset(0x1p-10), vsub(hi, x))), vadd(lo, vmul(vset(0x1p-10), vsub(x, lo)))),
                  xb);
    /* the step lengths: kept after a plain step, cleared after the others */
    M kept = mandn(lin, plain);
    s->p2 = vsel(kept, p1, vsel(act, zero, p2));
    s->p1 = vsel(kept, as, vsel(act, zero, p1));
    s->ph = mor(mand(kept, halley), mandn(kept, s->ph));
    s->cp = vsel(act, c, s->cp);
    s->xp = vsel(act, x, s->xp);
    s->jumped = mor(jump, mandn(act, s->jumped));
    s->dxold = vsel(act, s->dx, s->dxold);
    V dx = vsel(act, vabs(vsub(xb, x)), s->dx);
    x = vsel(act, xb, x);
    M stop = mor(vle_m(act, dx, vmul(rel, vabs(x))), vngt_m(act, vsub(hi, lo), abs_));
    res = vsel(stop, x, res);
    act = mandn(stop, act);
    s->x = x, s->dx = dx;
out:
    s->lo = lo, s->hi = hi, s->res = res, s->act = act;
}
