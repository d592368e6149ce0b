/* SPDX-License-Identifier: MIT */
/* Body of the line/ray/segment-circle distance kernel (src/batch/line_kernel.c), written once
 * over lanes for the lanes the includer chose (CD_LANES, with LK_CHAINS), compiled for their
 * instruction set, over the solver (base/roots_halley.h) and the model's arithmetic
 * (src/lines/line_circle_body.h, which the single query runs in one lane); no include guard.
 * The framing and scaling repeat the scalar path's (run_scaled, run and
 * cdist__line_near_centre, src/lines/line_circle.c) lane by lane; validation takes the checks of
 * src/api/validate.c as a mask. The distance of an entry the kernel answers is the single
 * query's, bit for bit. An entry whose inputs would take any other branch of the scalar path (a
 * failed check, a tiny or subnormal vector, the perpendicular or zero-radius cases, a NaN, a
 * nearly multiple root) is left to the scalar path.
 * Stages over a block of up to 64 entries: 1 (all entries, W at a time) validation, frame and
 * model; 2 (the entries where F' is not monotone) the branch brackets; 3 (every bracket) the
 * solver; 4 (all entries) the distance. */

#if CD_LANES == 8
CD_LANES_TARGET_PUSH("avx512f,fma")
#elif CD_LANES == 4
CD_LANES_TARGET_PUSH("avx2,fma")
#endif
#include "base/lanes/lanes_def.h"
#include "base/lanes/lanes_vec.h"
#include "base/roots_halley.h"
#include "lines/line_circle_body.h"
#include "api/circle_fast_lanes.h"

/* offer_end's squared distance at t. */
CD_INLINE V KN(end_d2)(V Bx, V By, V Bz, V Mx, V My, V Mz, V t, V nx, V ny, V nz, V r)
{
    V P[3], np[3], rho;
    return KN(lc_end)(Bx, By, Bz, Mx, My, Mz, t, nx, ny, nz, r, P, np, &rho);
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
    const V cc[3] = {cx, cy, cz}, nd[3] = {ndx, ndy, ndz};
    V un[3];
    M ok = mand(mand(KN(in_range)(ax, ay, az), KN(in_range)(bx, by, bz)), KN(circle_fast)(cc, nd, r, tol, un));
    V nx = un[0], ny = un[1], nz = un[2], u[3], v[3];
    KN(basis)(un, u, v);

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

    /* ---- cdist__line_near_centre ---- */
    V Bx, By, Bz;
    V t = KN(lc_near_centre)(Ox, Oy, Oz, Dx, Dy, Dz, cx, cy, cz, tmin, tmax, &Bx, &By, &Bz);
    /* run: the range in units of M */
    V lo = vsel(veq(tmin, t), zero, vmul(vsub(tmin, t), len));
    V hi = vsel(veq(tmax, t), zero, vmul(vsub(tmax, t), len));

    /* ---- linear_circle (ROBUST) ---- */
    ok = mand(ok, vlt(lo, hi));
    ok = mand(ok, mand(KN(in_range)(Bx, By, Bz), vgt(r, zero))); /* finite B (|B| <= 4 here); r = 0: scalar */
    V B0x, B0y, B0z;
    V t0 = KN(lc_nearest)(Bx, By, Bz, Mx, My, Mz, &B0x, &B0y, &B0z);
    KN(lc_frame) fr;
    fr.nx = nx, fr.ny = ny, fr.nz = nz, fr.ux = u[0], fr.uy = u[1], fr.uz = u[2];
    fr.vx = v[0], fr.vy = v[1], fr.vz = v[2];
    KN(lc_frame_line)(&fr, r, B0x, B0y, B0z, Mx, My, Mz);
    V umin = vmul(vsub(lo, t0), fr.sg), umax = vmul(vsub(hi, t0), fr.sg);
    ok = mand(ok, vgt(fr.m0, vset(CD_LC_PERP_ULPS * DBL_EPSILON))); /* perpendicular to the plane: scalar */
    KN(lc_model) md;
    V uO;
    KN(lc_model_init)(&md, &fr, vmul(r, fr.sg), &uO);
    V smin = vsub(umin, uO), smax = vsub(umax, uO);
    /* robust_roots: one bracket where F' increases everywhere, else up to one per branch
     * (stage_branches) */
    V blo, bhi, mu, R, B;
    M single = KN(lc_bracket)(&md, &blo, &bhi, &mu, &R, &B);
    V x0 = vsel(single, KN(lc_start_single)(&md, mu, R, B), vset(NAN));
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
                            &fr.up, &UP, &blo, &bhi, &x0, &smin, &smax, &best};
    for (int f = 0; f < LK_NF; f++) vst(&b->f[f][base], *cols[f]);
    unsigned okb = mbits(ok), singleb = mbits(single), failb = mbits(fail);
    for (int l = 0; l < W; l++) {
        int real = l < n;
        b->ok[base + l] = (unsigned char)(real && (okb >> l & 1) && !(failb >> l & 1));
        b->two[base + l] = (unsigned char)(b->ok[base + l] && !(singleb >> l & 1));
    }
}

/* The model of W entries e[0..W-1] of block b. */
CD_INLINE void KN(load_model)(const lk_block *b, const int *e, KN(lc_model) *m)
{
    double col[10][W];
    for (int f = 0; f < 10; f++)
        for (int l = 0; l < W; l++) col[f][l] = b->f[f][e[l]];
    m->r = vld(col[0]), m->a = vld(col[1]), m->m0 = vld(col[2]), m->x1 = vld(col[3]), m->ax1 = vld(col[4]);
    m->c2 = vld(col[5]), m->h = vld(col[6]), m->k = vld(col[7]), m->rr2 = vld(col[8]), m->dfc = vld(col[9]);
    m->x1sq = vmul(m->x1, m->x1);
    m->d2c = vmul(vmul(vset(-3.0), m->m0), m->dfc);
    m->e2x = m->e2y = vset(0.0); /* not used by the kernels */
}

/* Field f of W entries e[0..W-1]. */
CD_INLINE V KN(load_field)(const lk_block *b, int f, const int *e)
{
    double col[W];
    for (int l = 0; l < W; l++) col[l] = b->f[f][e[l]];
    return vld(col);
}

/* y[i] = KN(cbrt)(x[i]), n a multiple of W (for the tests). */
static inline void KN(cbrt_lanes)(const double *x, double *y, int n)
{
    for (int i = 0; i < n; i += W) vst(&y[i], KN(cbrt)(vld(&x[i])));
}

/* Stage 2, the entries e[0..n-1] (n <= W; the rest of e repeats e[0]) where F' is not monotone:
 * the brackets of the branches that hold a local minimum, written to b->br (A: left, B: right)
 * and b->has. */
static void KN(stage_branches)(lk_block *b, const int *e, int n)
{
    KN(lc_model) md;
    KN(load_model)(b, e, &md);
    V lo, hi, mu, R, B, hiA, x0A, loB, x0B;
    M hasA, hasB;
    KN(lc_bracket)(&md, &lo, &hi, &mu, &R, &B);
    KN(lc_branches)(&md, lo, hi, mu, R, B, &hasA, &hiA, &x0A, &hasB, &loB, &x0B);
    double hiAs[W], loBs[W], x0As[W], x0Bs[W];
    vst(hiAs, hiA), vst(loBs, loB), vst(x0As, x0A), vst(x0Bs, x0B);
    unsigned ha = mbits(hasA), hb = mbits(hasB);
    for (int l = 0; l < n; l++) {
        int i = e[l];
        b->br[0][0][i] = b->f[LK_F_BLO][i], b->br[0][1][i] = hiAs[l], b->br[0][2][i] = x0As[l];
        b->br[1][0][i] = loBs[l], b->br[1][1][i] = b->f[LK_F_BHI][i], b->br[1][2][i] = x0Bs[l];
        b->has[0][i] = (unsigned char)(ha >> l & 1), b->has[1][i] = (unsigned char)(hb >> l & 1);
    }
}

/* The squared distance at the root s of W entries e[0..W-1] (offer_model's), unscaled. */
CD_INLINE V KN(root_d2)(const lk_block *b, const KN(lc_model) *m, V s, const int *e)
{
    V x2, rho, up = KN(load_field)(b, LK_F_UP, e);
    return vmul(vmul(KN(lc_f)(m, s, &x2, &rho), up), up);
}

/* Stage 3, the brackets k[0..n-1] of the item list (n <= LK_CHAINS * W; the rest of k repeats
 * k[0]): the root of each (cdist__root_halley_accel) and the squared distance there (offer_model),
 * to b->item_d2. The iteration is a chain of dependent square roots and divisions:
 * LK_CHAINS groups of W brackets iterate side by side to keep the units busy. */
static void KN(stage_solve)(lk_block *b, const int *k, int n)
{
    KN(lc_model) md[LK_CHAINS];
    KN(halley) s[LK_CHAINS];
    int e[LK_CHAINS][W];
    for (int c = 0; c < LK_CHAINS; c++) {
        double lo[W], hi[W], x0[W], act[W];
        for (int l = 0; l < W; l++) {
            int j = k[c * W + l];
            e[c][l] = b->item_entry[j], lo[l] = b->item_lo[j], hi[l] = b->item_hi[j], x0[l] = b->item_x0[j];
            act[l] = c * W + l < n ? 1.0 : 0.0;
        }
        KN(load_model)(b, e[c], &md[c]);
        s[c] = KN(halley_start)(vld(lo), vld(hi), vld(x0), vgt(vld(act), vset(0.0)));
    }
    for (int it = 0; it < LK_LANE_ITER; it++) {
        M act = s[0].act;
        for (int c = 1; c < LK_CHAINS; c++) act = mor(act, s[c].act);
        if (!many(act)) break;
        for (int c = 0; c < LK_CHAINS; c++) KN(lc_iterate)(&md[c], &s[c]);
    }
    /* a lane still iterating (a bracket bisected down to its end, as when the root lies beyond
     * a ray's start: ~50 iterations) goes on in stage_long, with the other such lanes */
    for (int c = 0; c < LK_CHAINS; c++) {
        unsigned rest = mbits(s[c].act);
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
        V d2 = KN(root_d2)(b, &md[c], s[c].res, e[c]);
        double out[W];
        vst(out, d2);
        unsigned fb = mbits(vne(d2, d2));
        for (int l = 0; l < W && c * W + l < n; l++) {
            b->item_d2[k[c * W + l]] = out[l];
            b->item_fail[k[c * W + l]] = (unsigned char)(fb >> l & 1);
        }
    }
}

/* Stage 3b, the long brackets j[0..n-1] (n <= W; the rest of j repeats j[0]) that stage_solve
 * left: their iterations go on together up to CD_ROOT_MAX_ITER in all, where
 * cdist__root_halley_accel returns its last x. A root that took that long and is not at an end
 * of the range is a nearly multiple root of F' (a tangent line), where solvers stop at different
 * points of a flat bottom: left to the scalar path, whatever solver that uses. */
static void KN(stage_long)(lk_block *b, const int *j, int n)
{
    int e[W];
    double st[LK_NS][W], act[W];
    for (int l = 0; l < W; l++) {
        e[l] = b->item_entry[b->long_item[j[l]]];
        for (int f = 0; f < LK_NS; f++) st[f][l] = b->long_st[f][j[l]];
        act[l] = l < n ? 1.0 : 0.0;
    }
    KN(lc_model) md;
    KN(load_model)(b, e, &md);
    KN(halley) s;
    s.x = vld(st[LK_S_X]), s.lo = vld(st[LK_S_LO]), s.hi = vld(st[LK_S_HI]), s.dx = vld(st[LK_S_DX]);
    s.dxold = vld(st[LK_S_DXOLD]), s.p1 = vld(st[LK_S_P1]), s.p2 = vld(st[LK_S_P2]);
    s.jumped = vgt(vld(st[LK_S_JUMPED]), vset(0.0));
    s.ph = vgt(vld(st[LK_S_PH]), vset(0.0));
    s.cp = vld(st[LK_S_CP]), s.xp = vld(st[LK_S_XP]);
    s.res = s.x;
    s.act = vgt(vld(act), vset(0.0));
    for (int it = LK_LANE_ITER; it < CD_ROOT_MAX_ITER && many(s.act); it++) KN(lc_iterate)(&md, &s);
    s.res = vsel(s.act, s.x, s.res);
    V smin = KN(load_field)(b, LK_F_SMIN, e), smax = KN(load_field)(b, LK_F_SMAX, e);
    V tol = vset(CD_LK_END_REL_ULPS * DBL_EPSILON), atol = vset(CD_LK_END_ABS);
    V big = vset(DBL_MAX); /* a finite end only (a line has none) */
    M at_min = mand(vle(vabs(smin), big), vle(vabs(vsub(s.res, smin)), vadd(vmul(tol, vabs(smin)), atol)));
    M at_max = mand(vle(vabs(smax), big), vle(vabs(vsub(s.res, smax)), vadd(vmul(tol, vabs(smax)), atol)));
    M fail = mnot(mor(at_min, at_max));
    V d2 = KN(root_d2)(b, &md, s.res, e);
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
static uint64_t KN(kernel)(const cdist__job *job, int shape, double tol, size_t lo, size_t count)
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

#if W > 1
CD_LANES_TARGET_POP
#endif
#include "base/lanes/lanes_undef.h"
#undef LK_CHAINS
