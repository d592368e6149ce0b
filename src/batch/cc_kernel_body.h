/* SPDX-License-Identifier: MIT */
/* Body of the circle-circle distance kernel (src/batch/cc_kernel.c), written once over a lane
 * type (lanes_def.h) and included once per instruction set after src/circles/cc_search_body.h:
 * the set-up of W entries in lanes, the search over them (lanes are entries) and the distance at
 * the angles found. */

#include "api/circle_fast_lanes.h"
#include "circles/ring_lanes.h"

/* The ring of the lane group from g (the block's columns). */
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

/* ---- per-entry set-up in lanes ---- */

/* The two circles of the entries [lo + base, lo + base + n), n <= W (the lanes from n repeat
 * the first entry), as 7 columns each: centre, normal, radius. */
CD_INLINE void KN(ck_load_pairs)(const cdist__job *job, size_t lo, int base, int n, V *ca, V *cb)
{
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
}

/* The two circles of the entries [lo + base, lo + base + n), n <= W, exchanged in the lanes of
 * swap, as the single query takes them, operation by operation: its fast check
 * (cdist__circle_fast_body) and cdist__circles_frame; c[o] the centre (a's the origin) and
 * radius (c[o][6]), scaled by 1 / *up, nn[o] the unit normal; returns the mask of the lanes it
 * takes (a full check or the scalar path decides the others). */
CD_INLINE M KN(ck_pair)(const cdist__job *job, double unit_tol, size_t lo, int base, int n, unsigned swap,
                        V c[2][8], V nn[2][3], V *up)
{
    KN(ck_load_pairs)(job, lo, base, n, c[0], c[1]);
    M ok = mand(KN(circle_fast)(c[0], c[0] + 3, c[0][6], unit_tol, nn[0]),
                KN(circle_fast)(c[1], c[1] + 3, c[1][6], unit_tol, nn[1]));
    if (swap) {
        double sw[W];
        for (int l = 0; l < W; l++) sw[l] = swap >> l & 1 ? 1.0 : 0.0;
        M m = veq(vld(sw), vset(1.0));
        V *x[7] = {&c[0][0], &c[0][1], &c[0][2], &c[0][6], &nn[0][0], &nn[0][1], &nn[0][2]};
        V *y[7] = {&c[1][0], &c[1][1], &c[1][2], &c[1][6], &nn[1][0], &nn[1][1], &nn[1][2]};
        for (int j = 0; j < 7; j++) {
            V t = *x[j];
            *x[j] = vsel(m, *y[j], t);
            *y[j] = vsel(m, t, *y[j]);
        }
    }
    for (int j = 0; j < 3; j++) c[1][j] = vsub(c[1][j], c[0][j]), c[0][j] = vset(0.0);
    V L = KN(fmax)(KN(fmax)(c[0][6], c[1][6]), KN(max3)(c[1][0], c[1][1], c[1][2]));
    ok = mand(ok, vge(L, vset(0x1p-1022))); /* a subnormal or zero scale: the scalar path */
    *up = KN(pow2_of)(L);
    V down = vrecip2(*up);
    for (int o = 0; o < 2; o++) c[o][6] = vmul(c[o][6], down);
    for (int j = 0; j < 3; j++) c[1][j] = vmul(down, c[1][j]);
    return ok;
}

/* The circles of ck_pair with their bases (cdist__circle_fast_basis) into a[k], b[k] (k < n),
 * up[k] the scale and bscale[k] the collector's (cdist__circles_frame); returns the lanes it
 * does not take. */
static unsigned KN(ck_circles)(const cdist__job *job, double unit_tol, size_t lo, int base, int n, unsigned swap,
                               cdist__circle *a, cdist__circle *b, double *up, double *bscale)
{
    V c[2][8], nn[2][3], u[2][3], v[2][3], p;
    M ok = KN(ck_pair)(job, unit_tol, lo, base, n, swap, c, nn, &p);
    for (int o = 0; o < 2; o++) KN(basis)(nn[o], u[o], v[o]);
    V sc = KN(fmax)(KN(fmax)(c[0][6], c[1][6]), vsqrt(KN(dot)(c[1][0], c[1][1], c[1][2], c[1][0], c[1][1], c[1][2])));
    sc = vsel(mand(vgt(sc, vset(0.0)), vle(sc, vset(DBL_MAX))), sc, vset(1.0)); /* cdist__best_init */
    double pu[W], ps[W];
    vst(pu, p);
    vst(ps, sc);
    for (int k = 0; k < n; k++) {
        up[k] = pu[k];
        bscale[k] = ps[k];
    }
    for (int o = 0; o < 2; o++) {
        double col[13][W];
        const V *comp[13] = {&c[o][0], &c[o][1], &c[o][2], &nn[o][0], &nn[o][1], &nn[o][2], &u[o][0],
                             &u[o][1], &u[o][2], &v[o][0], &v[o][1], &v[o][2], &c[o][6]};
        for (int j = 0; j < 13; j++) vst(col[j], *comp[j]);
        cdist__circle *out = o ? b : a;
        for (int k = 0; k < n; k++)
            out[k] = (cdist__circle){v3(col[0][k], col[1][k], col[2][k]), v3(col[3][k], col[4][k], col[5][k]),
                                     v3(col[6][k], col[7][k], col[8][k]), v3(col[9][k], col[10][k], col[11][k]),
                                     col[12][k]};
    }
    return mbits(mnot(ok)) & ((1u << n) - 1u);
}

/* The single query's validation, framing (ck_pair) and problem (cdist__cc_prepare, operation by
 * operation) of the entries [lo + base, lo + base + n), n <= W, and its ring (ring_lanes.h, the
 * frame's own body), into the block's columns from base; returns the lanes left to the scalar
 * path (also the lanes >= n, and where the radii are equal: the tie rule of cdist__cc_prepare is
 * not repeated here). */
static unsigned KN(ck_setup)(const cdist__job *job, double unit_tol, size_t lo, int base, int n, ck_block *b)
{
    V c[2][8], nn[2][3], up;
    M ok = KN(ck_pair)(job, unit_tol, lo, base, n, 0, c, nn, &up);
    V r0 = c[0][6], r1 = c[1][6], Cx = c[1][0], Cy = c[1][1], Cz = c[1][2];
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
        nA[k] = vsel(sw, nn[1][k], nn[0][k]);
        m[k] = vsel(sw, nn[0][k], nn[1][k]);
    }
    KN(basis)(nA, u, v);
    KN(cc_ring) o;
    const V CB[3] = {CBx, CBy, CBz};
    KN(cc_ring_init)(R, s, u, v, CB, m, &o);
    V cut = vset(NAN);
    if (job->cutoffs) {
        double cv[W];
        for (int l = 0; l < W; l++) cv[l] = job->cutoffs[lo + (size_t)base + (size_t)(l < n ? l : 0)];
        cut = vld(cv);
    }
    const V cols[CK_NC] = {o.al[0], o.al[1], o.al[2], o.be[0], o.be[1], o.be[2], o.ga[0], o.ga[1], o.ga[2], o.ha, o.hb,
                           o.hc,    s,       vmul(R, R), o.W1, o.Hh, o.Hc0, o.Lw, unsc, up, cut};
    V zero = vset(0.0);
    for (int c = 0; c < CK_NC; c++) vst(&b->col[c][base], vsel(ok, cols[c], zero));
    unsigned left = mbits(mnot(ok)) & ((1u << W) - 1u);
    if (n < W) left |= ((1u << W) - 1u) & ~((1u << n) - 1u);
    return left;
}

/* The bound of F on grid interval j: the smaller end value, and the concave hull bound. */
CD_INLINE V KN(ck_grid_lb)(const KN(ck_ring) *r, const V *Fg, int j, V R2tan)
{
    return vmin(vmin(Fg[j], Fg[(j + 1) % CK_GRID]),
                vsub(KN(ck_f)(r, vset(cdist__cc_tab.hull_c[j]), vset(cdist__cc_tab.hull_s[j])), R2tan));
}

/* The search for the W entries of the block from g: angles t[] of the closest points of the
 * entries it certifies; returns the lane mask (bit k: entry g + k) of those it does not. quick
 * (a constant): certify exactly what the single query's search (cdist__cc_quick,
 * src/circles/cc_quick_body.h) certifies, which gives up earlier (CK_QUICK_LEVELS, a basin
 * near B's axis, an F below CD_CCK_MIN_F on the way, a near-tie seen before the end, a NaN);
 * where both certify, the angle and its cos and sin are the same. */
CD_INLINE unsigned KN(ck_search_mode)(ck_block *b, int g, int quick)
{
    KN(ck_ring) r;
    KN(ck_load)(b, g, &r);
    V margin = vset(CD_CCK_CERT_MARGIN);

    /* Grid: F at the CK_GRID angles, the best one. */
    V Fg[CK_GRID], bestF = vset(INFINITY), bestJ = vset(0.0);
    for (int j = 0; j < CK_GRID; j++) {
        Fg[j] = KN(ck_f)(&r, vset(cdist__cc_tab.grid_c[j]), vset(cdist__cc_tab.grid_s[j]));
        M lt = vlt(Fg[j], bestF);
        bestF = vsel(lt, Fg[j], bestF);
        bestJ = vsel(lt, vset((double)j), bestJ);
    }
    /* The concave hull bound of every interval outside the basin (the two around the best
     * angle), the smallest kept in minlb; the basin's centre and the F at its ends. */
    M fail = mfalse();
    V minlb = vset(INFINITY), R2tan = vmul(r.R2, vset(cdist__cc_tab.grid_tan2));
    M nan = mfalse(); /* a NaN bound would drop out of minlb (min keeps the other operand) */
    V c = vset(0.0), s = vset(0.0), Fl = vset(0.0), Fr = vset(0.0), lbb = vset(INFINITY);
    for (int j = 0; j < CK_GRID; j++) {
        int jn = (j + 1) % CK_GRID, jp = (j + CK_GRID - 1) % CK_GRID;
        V lb = KN(ck_grid_lb)(&r, Fg, j, R2tan);
        M at = veq(vset((double)j), bestJ), before = veq(vset((double)jn), bestJ);
        minlb = vsel(mor(at, before), minlb, vmin(minlb, lb));
        if (quick) {
            lbb = vsel(mor(at, before), vmin(lbb, lb), lbb);
            nan = mor(nan, vne(Fg[j], Fg[j]));
        }
        nan = mor(nan, vne(lb, lb));
        c = vsel(at, vset(cdist__cc_tab.grid_c[j]), c);
        s = vsel(at, vset(cdist__cc_tab.grid_s[j]), s);
        Fl = vsel(before, Fg[j], Fl);
        Fr = vsel(veq(vset((double)jp), bestJ), Fg[j], Fr);
    }
    V t = vmul(bestJ, vset(2.0 * M_PI / CK_GRID));
    const V margin_q = vset(CD_CCK_CERT_MARGIN);
    if (quick) fail = mor(nan, mnot(vgt(minlb, vadd(lbb, margin_q))));
    const int levels = quick ? CK_QUICK_LEVELS : CK_LEVELS;

    /* Zoom: certify the basin [t - h, t + h] convex, else split it in 8, keep the two
     * subintervals around the best point and add the hull bounds of the other six to minlb. */
    M done = mfalse();
    V hdone = vset(0.0);
    for (int l = 0; l < levels; l++) {
        M active = mnot(mor(done, fail));
        if (quick) {
            fail = mor(fail, mandn(vge(bestF, vset(CD_CCK_MIN_F)), active));
            active = mnot(mor(done, fail));
        }
        if (!many(active)) break;
        M near_axis = mfalse();
        M conv = l < CK_FIRST_CONVEX ? mfalse() : mand(active, KN(ck_convex)(&r, c, s, l, &near_axis));
        done = mor(done, conv);
        hdone = vsel(conv, vset(cdist__cc_tab.half[l]), hdone);
        active = mandn(conv, active);
        if (quick) {
            fail = mor(fail, mand(active, near_axis));
            active = mandn(near_axis, active);
        }
        if (!many(active) || l + 1 == levels) break;
        V Fk[9], Ck[9], Sk[9];
        Fk[0] = Fl;
        Fk[4] = bestF;
        Fk[8] = Fr;
        Ck[4] = c;
        Sk[4] = s;
        Ck[0] = Ck[8] = Sk[0] = Sk[8] = vset(0.0);
        for (int k = 1; k <= 3; k++) {
            KN(ck_rot)(c, s, vset(cdist__cc_tab.sub_c[l][k]), vset(cdist__cc_tab.sub_s[l][k]), &Ck[4 + k], &Sk[4 + k]);
            KN(ck_rot)(c, s, vset(cdist__cc_tab.sub_c[l][k]), vset(-cdist__cc_tab.sub_s[l][k]), &Ck[4 - k], &Sk[4 - k]);
            Fk[4 + k] = KN(ck_f)(&r, Ck[4 + k], Sk[4 + k]);
            Fk[4 - k] = KN(ck_f)(&r, Ck[4 - k], Sk[4 - k]);
        }
        V nF = Fk[4], kb = vset(4.0);
        M nanF = mfalse();
        for (int k = 0; k < 9; k++) {
            M lt = vlt(Fk[k], nF);
            nF = vsel(lt, Fk[k], nF);
            kb = vsel(lt, vset((double)k), kb);
            if (quick) nanF = mor(nanF, vne(Fk[k], Fk[k]));
        }
        M edge = mor(veq(kb, vset(0.0)), veq(kb, vset(8.0)));
        V R2tan_sub = vmul(r.R2, vset(cdist__cc_tab.sub_tan2[l])), lbk = vset(INFINITY);
        for (int i = 0; i < 8; i++) {
            int m = i < 4 ? 3 - i : i - 4; /* hull point of [i, i+1] at (2 (i - 4) + 1) h / 8 */
            double sg = i < 4 ? -1.0 : 1.0;
            V hc, hs;
            KN(ck_rot)(c, s, vset(cdist__cc_tab.hull_sub_c[l][m]), vset(sg * cdist__cc_tab.hull_sub_s[l][m]), &hc, &hs);
            V lb = vmin(vmin(Fk[i], Fk[i + 1]), vsub(KN(ck_f)(&r, hc, hs), R2tan_sub));
            M keep = mor(veq(vset((double)i), kb), veq(vset((double)(i + 1)), kb));
            minlb = vsel(mandn(keep, active), vmin(minlb, lb), minlb);
            if (quick) lbk = vsel(keep, vmin(lbk, lb), lbk);
            nan = mor(nan, mand(active, vne(lb, lb)));
        }
        if (quick) edge = mor(edge, mor(mor(nanF, nan), mnot(vgt(minlb, vadd(lbk, margin_q)))));
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
        t = vsel(active, vadd(t, vmul(vsub(kb, vset(4.0)), vset(0.25 * cdist__cc_tab.half[l]))), t);
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

static unsigned KN(ck_search)(ck_block *b, int g) { return KN(ck_search_mode)(b, g, 0); }
static unsigned KN(ck_search_quick)(ck_block *b, int g) { return KN(ck_search_mode)(b, g, 1); }
/* The screen of the entries of the lane group from g (cdist__batch_screen): the verdicts into
 * b->screen, and the mask of the lanes it leaves undecided. */
static unsigned KN(ck_screen)(ck_block *b, int g)
{
    KN(ck_ring) r;
    KN(ck_load)(b, g, &r);
    V margin = vset(CD_CCK_CERT_MARGIN), R2tan = vmul(r.R2, vset(cdist__cc_tab.grid_tan2));
    M nan = mfalse();
    /* The circle lies in the polygon of the hull points H_j, so F >= min_j F(H_j) - R^2 tan^2
     * on it (the convex bound of ck_grid_lb over the whole polygon): the distance is above the
     * cutoff when that bound, less the margin, is (its square root scaled back and rounded
     * down: a certified lower bound, the verdict); it is at most the cutoff when F at one of
     * the circle's points of the interval of the smallest F(H_j) (its ends and middle) is
     * (-inf: the caller answers in full). */
    V hmin = vset(INFINITY), hc = vset(0.0), hs = vset(0.0);
    for (int j = 0; j < CK_GRID; j++) {
        V c = vset(cdist__cc_tab.hull_c[j]), s = vset(cdist__cc_tab.hull_s[j]), Fh = KN(ck_f)(&r, c, s);
        M lt = vlt(Fh, hmin);
        hmin = vsel(lt, Fh, hmin);
        hc = vsel(lt, c, hc);
        hs = vsel(lt, s, hs);
        nan = mor(nan, vne(Fh, Fh));
    }
    V co = vset(cdist__cc_tab.grid_half_c), si = vset(cdist__cc_tab.grid_half_s);
    V mc = vmul(hc, co), ms = vmul(hs, co), lc, ls, rc, rs;
    KN(ck_rot)(mc, ms, co, vneg(si), &lc, &ls);
    KN(ck_rot)(mc, ms, co, si, &rc, &rs);
    V Fon = vmin(KN(ck_f)(&r, mc, ms), vmin(KN(ck_f)(&r, lc, ls), KN(ck_f)(&r, rc, rs)));
    V cut = vld(&b->col[CK_C_CUT][g]), scale = vmul(vld(&b->col[CK_C_UNSC][g]), vld(&b->col[CK_C_UP][g]));
    V dlb = vmul(vmul(vsqrt(vmax(vsub(vsub(hmin, R2tan), margin), vset(0.0))), scale), vset(1.0 - 4.0 * DBL_EPSILON));
    M above = mandn(nan, vgt(dlb, cut)), below = vle(vmul(vsqrt(Fon), scale), cut);
    vst(&b->screen[g], vsel(above, dlb, vset(-INFINITY)));
    return mbits(mnot(mor(above, below)));
}

/* ---- the distance at the angle found, in lanes ---- */

/* The distances of the lanes of the group from g at their angles (b->ct, b->st: cosine and
 * sine): the single query's formula (cc_point_d2 of cc_search_body.h), scaled back as the
 * single query scales its answer. Into b->d. */
static void KN(ck_final)(ck_block *b, int g)
{
    KN(ck_ring) r;
    KN(ck_load)(b, g, &r);
    V d2 = KN(cc_point_d2)(&r, vld(&b->ct[g]), vld(&b->st[g]));
    V u = vld(&b->col[CK_C_UNSC][g]);
    vst(&b->d[g], vmul(vsqrt(vmul(vmul(d2, u), u)), vld(&b->col[CK_C_UP][g])));
}


/* The squared distances at the angles found (b->ct, b->st) of the lane group from g, in the
 * ring's units (no scaling back), into b->d: cdist__cc_point_d2 in lanes. */
static void KN(ck_point_d2)(ck_block *b, int g)
{
    KN(ck_ring) r;
    KN(ck_load)(b, g, &r);
    vst(&b->d[g], KN(cc_point_d2)(&r, vld(&b->ct[g]), vld(&b->st[g])));
}
