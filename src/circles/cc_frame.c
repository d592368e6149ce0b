/* SPDX-License-Identifier: MIT */
/* The frame of the circle-circle engine (docs/circles.md): the ring of F, the magnitudes its
 * rounding bounds use, and the bounds M1..M3 of H's derivatives from H's Fourier coefficients,
 * formed from trigonometric polynomials of degree <= 4. */
#include <math.h>
#include <string.h>

#include "circles/circles-priv.h"

/* ---- trigonometric polynomials of degree <= 4 as complex coefficients c_k, k = -4..4 ---- */
typedef struct tpoly {
    double re[9], im[9];
} tpoly;

static void tp_zero(tpoly *p) { memset(p, 0, sizeof *p); }
/* Add a cos(k t) + b sin(k t). */
static void tp_term(tpoly *p, int k, double a, double b)
{
    if (k == 0) {
        p->re[4] += a;
        return;
    }
    p->re[4 + k] += 0.5 * a;
    p->im[4 + k] -= 0.5 * b;
    p->re[4 - k] += 0.5 * a;
    p->im[4 - k] += 0.5 * b;
}
/* z = x y for x of degree dx and y of degree dy (dx + dy <= 4); only the coefficients k >= 0
 * are formed (c_{-k} = conj(c_k) for real functions; every user reads k >= 0 only). */
static void tp_mul(const tpoly *x, int dx, const tpoly *y, int dy, tpoly *z)
{
    tpoly r;
    tp_zero(&r);
    for (int k = 0; k <= dx + dy; k++) {
        int lo = k - dy > -dx ? k - dy : -dx, hi = k + dy < dx ? k + dy : dx;
        double re = 0, im = 0;
        for (int i = lo; i <= hi; i++) {
            int j = k - i;
            re += x->re[4 + i] * y->re[4 + j] - x->im[4 + i] * y->im[4 + j];
            im += x->re[4 + i] * y->im[4 + j] + x->im[4 + i] * y->re[4 + j];
        }
        r.re[4 + k] = re;
        r.im[4 + k] = im;
        r.re[4 - k] = re;
        r.im[4 - k] = -im;
    }
    *z = r;
}

/* The ring and its magnitudes: the one-lane instance of ring_lanes.h, which the batch kernels
 * run in wider lanes. */
#define CD_LANES 1
#include "base/lanes/lanes_def.h"
#include "base/lanes/lanes_vec.h"
#include "circles/ring_lanes.h"
#include "base/lanes/lanes_undef.h"

CD_FMA_CLONES void cdist__cc_frame_ring(cdist__cc_frame *f, const cdist__circle *A, vec3 C, const cdist__circle *B)
{
    const double u[3] = {A->u.x, A->u.y, A->u.z}, v[3] = {A->v.x, A->v.y, A->v.z}, c[3] = {C.x, C.y, C.z},
                 m[3] = {B->n.x, B->n.y, B->n.z};
    cc_ring_1 o;
    cc_ring_init_1(A->r, B->r, u, v, c, m, &o);
    f->R = A->r, f->s = B->r, f->u = A->u, f->v = A->v, f->C = C, f->m = B->n;
    f->rg = (cdist__ring){v3(o.al[0], o.al[1], o.al[2]), v3(o.be[0], o.be[1], o.be[2]), v3(o.ga[0], o.ga[1], o.ga[2]),
                          o.ha, o.hb, o.hc};
    f->Cu = o.Cu, f->Cv = o.Cv, f->epsL = o.epsL, f->L = o.L, f->Lw = o.Lw, f->W1 = o.W1, f->nga = o.nga;
    f->Hh = o.Hh, f->Hc0 = o.Hc0, f->parallel = o.parallel, f->quick = o.quick;
}

void cdist__cc_frame_bounds(cdist__cc_frame *f)
{
    vec3 C = f->C;
    /* Fourier coefficients of Q, sigma, g = w.w' and H = Q sigma^2 - s^2 g^2. */
    double aa = cdist__cc_dot3(f->rg.al, f->rg.al), bb = cdist__cc_dot3(f->rg.be, f->rg.be), ab = cdist__cc_dot3(f->rg.al, f->rg.be);
    double ag = cdist__cc_dot3(f->rg.al, f->rg.ga), bg = cdist__cc_dot3(f->rg.be, f->rg.ga), gg = cdist__cc_dot3(f->rg.ga, f->rg.ga);
    tpoly Q, S, G, T, H;
    tp_zero(&Q);
    tp_term(&Q, 0, 0.5 * (aa + bb) + gg, 0);
    tp_term(&Q, 1, 2 * ag, 2 * bg);
    tp_term(&Q, 2, 0.5 * (aa - bb), ab);
    tp_zero(&S);
    tp_term(&S, 1, -f->R * f->Cv, f->R * f->Cu);
    tp_zero(&G);
    tp_term(&G, 1, bg, -ag);
    tp_term(&G, 2, ab, 0.5 * (bb - aa));
    tp_mul(&S, 1, &S, 1, &T);
    tp_mul(&Q, 2, &T, 2, &H);
    tp_mul(&G, 2, &G, 2, &T);
    double s2 = f->s * f->s;
    f->M1 = f->M2 = f->M3 = f->Hc = 0;
    for (int i = 4; i < 9; i++) {
        double cr = H.re[i] - s2 * T.re[i], ci = H.im[i] - s2 * T.im[i];
        /* the problem is scaled to L ~ 1: no overflow; c_{-k} has the same modulus */
        double c = (i == 4 ? 1 : 2) * sqrt(cr * cr + ci * ci);
        double k = (double)(i - 4);
        f->Hc += c;
        f->M1 += k * c;
        f->M2 += k * k * c;
        f->M3 += k * k * k * c;
    }
    /* Rounding of the coefficient arithmetic, then a margin. */
    double eps = DBL_EPSILON;
    f->M1 = f->M1 * (1 + CD_CC_BOUND_REL) + CD_CC_BOUND_ABS;
    f->M2 = f->M2 * (1 + CD_CC_BOUND_REL) + CD_CC_BOUND_ABS;
    f->M3 = f->M3 * (1 + CD_CC_BOUND_REL) + CD_CC_BOUND_ABS;

    /* First-order rounding bounds of H and H' as evaluated in cc_eval (all terms). */
    double Lc = v_norm(C);
    double W1 = f->W1, Wn = W1 + f->nga;
    double ew = 4 * eps * (2 * f->R + Lc), ew1 = 8 * eps * f->R;
    double sm = f->R * (fabs(f->Cu) + fabs(f->Cv)), dsm = 4 * eps * (sm + f->R * Lc);
    double Qm = Wn * Wn, gm = Wn * W1, g1m = W1 * W1 + Wn * W1;
    double dQ = 2 * Wn * ew + ew * ew + 4 * eps * Qm;
    double dg = ew * W1 + Wn * ew1 + 4 * eps * gm;
    double dg1 = 2 * W1 * ew1 + ew * W1 + Wn * ew1 + 4 * eps * g1m;
    f->eH = 2 * (dQ * sm * sm + 2 * Qm * sm * dsm + 2 * s2 * gm * dg + 6 * eps * (Qm * sm * sm + s2 * gm * gm));
    f->eH1 = 2 * (2 * (dg * sm * sm + 2 * gm * sm * dsm) + 2 * (dQ * sm * sm + 2 * Qm * sm * dsm) +
                  2 * s2 * (dg * g1m + gm * dg1) + 10 * eps * (gm * sm * sm + Qm * sm * sm + s2 * gm * g1m));
    /* H'' has the terms of H' with one more derivative (factors <= 4 on each): */
    f->eH2 = 4 * (f->eH1 + f->eH);
}

void cdist__cc_frame_init(cdist__cc_frame *f, const cdist__circle *A, vec3 C, const cdist__circle *B)
{
    cdist__cc_frame_ring(f, A, C, B);
    cdist__cc_frame_bounds(f);
}
