/* SPDX-License-Identifier: MIT */
/* The single circle-circle query's certified search (cdist__cc_quick, cc_search.c): one pair, its
 * angles spread over the lanes. Included once per instruction set after cc_search_body.h. No
 * include guard. */

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
        V idx = vld(&cdist__cc_tab.lane_index[j]);
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
    for (int j = 0; j < CK_GRID; j += W) vst(&Fg[j], KN(ck_f)(&r, vld(&cdist__cc_tab.grid_c[j]), vld(&cdist__cc_tab.grid_s[j])));
    Fg[CK_GRID] = Fg[0];
    V R2tan = vset(R2 * cdist__cc_tab.grid_tan2);
    for (int j = 0; j < CK_GRID; j += W) {
        V hull = vsub(KN(ck_f)(&r, vld(&cdist__cc_tab.hull_c[j]), vld(&cdist__cc_tab.hull_s[j])), R2tan);
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
    double c = cdist__cc_tab.grid_c[jb], s = cdist__cc_tab.grid_s[jb], bestF = Fg[jb], Fl = Fg[jp], Fr = Fg[jb + 1];
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
                hdone = cdist__cc_tab.half[l];
                break;
            }
            /* B's axis within W1 h of the basin: F's kink there (A crossing the axis) keeps
             * the basin from being certified convex at any level we try; the scan's kink
             * windows answer it */
            if (mbits(near_axis) & 1u) return 0;
        }
        if (l + 1 == CK_QUICK_LEVELS) break;
        double Fk[9], Ck[8], Sk[8], hb[8];
        V R2tan_sub = vset(R2 * cdist__cc_tab.sub_tan2[l]);
        for (int k = 0; k < 8; k += W) {
            V ck, sk, hc, hs;
            KN(ck_rot)(vset(c), vset(s), vld(&cdist__cc_tab.zoom_c[l][k]), vld(&cdist__cc_tab.zoom_s[l][k]), &ck, &sk);
            vst(&Fk[k], KN(ck_f)(&r, ck, sk));
            vst(&Ck[k], ck);
            vst(&Sk[k], sk);
            KN(ck_rot)(vset(c), vset(s), vld(&cdist__cc_tab.zoom_hull_c[l][k]), vld(&cdist__cc_tab.zoom_hull_s[l][k]), &hc, &hs);
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
        t += (kb - 4) * (0.25 * cdist__cc_tab.half[l]);
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

