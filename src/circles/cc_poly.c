/* SPDX-License-Identifier: MIT */
/* Circle-circle by the degree-8 polynomial (Eberly, distance-to-circles-3d §5), plus the helpers
 * shared with the geometric iteration (cc_iteration.c): the true distance function with its
 * derivatives, the Newton polish, and the closed forms of the special configurations. The
 * frame, the polynomial and the special cases: docs/circles.md. */
#include <math.h>

#include "base/point_circle.h"
#include "circles/circles-priv.h"

/* ---------------------------------------------------------------------------------------- */
/* Shared helpers (prototypes in the cc_methods block of internal.h)                          */
/* ---------------------------------------------------------------------------------------- */

/* Plain arithmetic on purpose: without hardware FMA in the build flags fma() is a library call,
 * and this function is the inner loop of every method. */
static inline double eval_cs(const cdist__cc *g, int side, double ct, double st, double *f1, double *f2, vec3 *P,
                             vec3 *K)
{
    const cdist__circle *m = g->c[side], *f = g->c[1 - side];
    double sg = side ? 1.0 : -1.0; /* moving centre relative to the fixed centre: +-D */
    double a = m->r * ct, bb = m->r * st;
    vec3 p = v3(a * m->u.x + bb * m->v.x, a * m->u.y + bb * m->v.y, a * m->u.z + bb * m->v.z);
    vec3 dp = v3(a * m->v.x - bb * m->u.x, a * m->v.y - bb * m->u.y, a * m->v.z - bb * m->u.z);
    vec3 dl = v3(sg * g->D.x + p.x, sg * g->D.y + p.y, sg * g->D.z + p.z);
    vec3 n = f->n;
    double h = n.x * dl.x + n.y * dl.y + n.z * dl.z;
    vec3 nd = v_cross(n, dl);
    double rho = sqrt(nd.x * nd.x + nd.y * nd.y + nd.z * nd.z);
    double e = rho - f->r;
    double F = e * e + h * h;
    vec3 k, E;
    double d2f = 2.0 * m->r * m->r;
    if (rho > 0.0) {
        vec3 w = v_cross(nd, n);
        double kr = f->r / rho, er = e / rho;
        k = v3(kr * w.x, kr * w.y, kr * w.z);
        /* near the axis nd is rounding noise of the cross product, not orthogonal to n, so
         * |w| < rho and r w / rho falls inside the circle (within 1e-150 rho is inexact too):
         * the point normalised from w itself (only where it is reported) */
        if (K && (rho < CD_MIN_NORMAL_FAST || rho < CD_CC_AXIS_NOISE_REL * v_maxabs(dl)))
            k = v_scale(f->r, v_unit_or_zero(w));
        E = v3(h * n.x + er * w.x, h * n.y + er * w.y, h * n.z + er * w.z);
        double tp = (nd.x * dp.x + nd.y * dp.y + nd.z * dp.z) / rho;
        d2f -= 2.0 * f->r * tp * tp / rho;
    } else { /* on the other circle's axis: every point of it is closest (a kink of F) */
        k = v_scale(f->r, f->u);
        E = v_sub(dl, k);
    }
    if (f1) *f1 = 2.0 * (E.x * dp.x + E.y * dp.y + E.z * dp.z);
    if (f2) *f2 = d2f - 2.0 * (E.x * p.x + E.y * p.y + E.z * p.z);
    if (P) *P = p;
    if (K) *K = k;
    return F;
}

double cdist__cc_eval(const cdist__cc *g, int side, double t, double *f1, double *f2, vec3 *P, vec3 *K)
{
    return eval_cs(g, side, cos(t), sin(t), f1, f2, P, K);
}

double cdist__cc_polish(const cdist__cc *g, int side, double t, double *Fout)
{
    double f1, f2;
    double F = cdist__cc_eval(g, side, t, &f1, &f2, NULL, NULL);
    double L = g->L;
    for (int it = 0; it < 60; it++) {
        double step;
        if (f2 > 0.0) step = -f1 / f2;
        else if (f1 != 0.0) step = (f1 > 0.0) ? -0.25 : 0.25; /* concave: walk downhill */
        else break;                                             /* a stationary point; keep it */
        if (step > 0.5) step = 0.5;
        if (step < -0.5) step = -0.5;
        /* F carries rounding of about eps * L * (|E| + eps L); a step must not increase it more. */
        double tolF = 8.0 * DBL_EPSILON * L * (sqrt(F) + DBL_EPSILON * L);
        double tn = t, Fn = F, g1 = f1, g2 = f2;
        int ok = 0;
        for (int half = 0; half < 40; half++) {
            tn = t + step;
            Fn = cdist__cc_eval(g, side, tn, &g1, &g2, NULL, NULL);
            if (Fn <= F + tolF) {
                ok = 1;
                break;
            }
            step *= 0.5;
        }
        if (!ok) break;
        t = tn;
        F = Fn;
        f1 = g1;
        f2 = g2;
        if (fabs(step) <= 4.0 * DBL_EPSILON) break;
    }
    if (Fout) *Fout = F;
    return t;
}

void cdist__cc_offer(const cdist__cc *g, int side, double t, cdist__best *b)
{
    vec3 P, K;
    double F = cdist__cc_eval(g, side, t, NULL, NULL, &P, &K);
    const cdist__circle *m = g->c[side], *f = g->c[1 - side];
    double am = cdist__circle_angle(m, P), af = cdist__circle_angle(f, K);
    if (m->r == 0.0) am = NAN;
    if (f->r == 0.0) af = NAN;
    if (side == 0) cdist__best_offer(b, F, P, v_add(K, g->D), am, af);
    else cdist__best_offer(b, F, K, v_add(P, g->D), af, am);
}

void cdist__cc_scale(const cdist__circle *c0, const cdist__circle *c1, double L, cdist__circle *a, cdist__circle *b, double *s)
{
    double k, up;
    cdist__circles_scale(L, 0, &k, &up);
    *a = *c0;
    *b = *c1;
    a->c = v3(0, 0, 0);
    a->r = c0->r * k;
    b->c = v_scale(k, c1->c);
    b->r = c1->r * k;
    *s = k;
}

void cdist__cc_unscale(const cdist__best *sc, double s, cdist__best *b)
{
    double is = 1.0 / s; /* a power of two: exact */
    for (int i = 0; i < sc->n; i++) {
        const cdist__cand *c = &sc->c[i];
        cdist__best_offer_flag(b, c->equidistant, c->d2 * is * is, v_scale(is, c->p[0]), v_scale(is, c->p[1]),
                           c->param[0], c->param[1]);
    }
    b->equidistant |= sc->equidistant;
}

/* Angle on c0 of the pair found at angle t of side s. */
static double c0_angle(const cdist__cc *g, int side, double t)
{
    if (side == 0) return t;
    vec3 K;
    cdist__cc_eval(g, 1, t, NULL, NULL, NULL, &K);
    double a = cdist__circle_angle(g->c[0], K);
    return isnan(a) ? 0.0 : a;
}

/* Is F_s within `tie` of dbest (in distance) at 64 evenly spread angles? (A smooth variation
 * is seen at >= cos(pi / 64) of its amplitude.) */
static int flat_side(const cdist__cc *g, int s, double dbest, double tie)
{
    for (int i = 0; i < 64; i++) {
        double F = cdist__cc_eval(g, s, -M_PI + (M_PI / 32.0) * (i + 0.37), NULL, NULL, NULL, NULL);
        if (!(sqrt(F) - dbest <= tie)) return 0;
    }
    return 1;
}

void cdist__cc_offer_minima(const cdist__cc *g, int n, const int *side, const double *t, const double *F, cdist__best *b)
{
    if (n <= 0) return;
    int ib = 0;
    for (int i = 1; i < n; i++)
        if (F[i] < F[ib]) ib = i;
    double dbest = sqrt(F[ib]), tie = CD_TIE_ULPS * DBL_EPSILON * g->L;
    double abest = c0_angle(g, side[ib], t[ib]);
    cdist__cc_offer(g, side[ib], t[ib], b);
    /* A circle at constant distance from the other has F_s'' = 0 everywhere; only then are the
     * samples taken (a flat minimum that is not constant fails them). */
    vec3 K;
    double f2[2];
    int sb = side[ib];
    cdist__cc_eval(g, sb, t[ib], NULL, &f2[sb], NULL, &K);
    double ao = cdist__circle_angle(g->c[1 - sb], K);
    cdist__cc_eval(g, 1 - sb, isnan(ao) ? 0.0 : ao, NULL, &f2[1 - sb], NULL, NULL);
    for (int s = 0; s < 2; s++) {
        if (fabs(f2[s]) <= CD_CC_POLY_FLAT_REL * g->c[s]->r * g->L && flat_side(g, s, dbest, tie)) {
            b->equidistant = 1;
            return;
        }
    }
    for (int i = 0; i < n; i++) {
        if (i == ib) continue;
        if (sqrt(F[i]) - dbest <= tie) {
            /* A tie: two closest pairs only when both arcs of c0 between them rise above the
             * tie level (distinct minima, e.g. mirror images); otherwise they are points of
             * one flat minimum and the best represents it. */
            double ai = c0_angle(g, side[i], t[i]);
            double mid = ai + 0.5 * remainder(abest - ai, 2.0 * M_PI);
            double f1 = cdist__cc_eval(g, 0, mid, NULL, NULL, NULL, NULL);
            double f2 = cdist__cc_eval(g, 0, mid + M_PI, NULL, NULL, NULL, NULL);
            if (!(sqrt(f1) - dbest > tie && sqrt(f2) - dbest > tie)) continue;
        }
        cdist__cc_offer(g, side[i], t[i], b);
    }
}

int cdist__cc_closed_form(const cdist__cc *g, cdist__best *b)
{
    const cdist__circle *c0 = g->c[0], *c1 = g->c[1];
    if (c1->r == 0.0) { /* c1 is the point D (c0 may be a point too) */
        cdist__point_circle_core(g->D, c0, b, 1);
        return 1;
    }
    if (c0->r == 0.0) { /* c0 is the origin: point-circle relative to c1, moved back by D */
        cdist__best t;
        cdist__best_init(&t, b->scale);
        cdist__point_circle_core(v_neg(g->D), c1, &t, 0);
        for (int i = 0; i < t.n; i++)
            cdist__best_offer_flag(b, t.c[i].equidistant, t.c[i].d2, v3(0, 0, 0), v_add(t.c[i].p[1], g->D), NAN,
                               t.c[i].param[1]);
        return 1;
    }
    /* Coaxial to the tie tolerance: a bound of the distance's variation over either circle
     * (docs/circles.md, "Coaxial"). */
    double sn = v_norm(v_cross(c0->n, c1->n));
    double d0 = cdist__point_circle(c0->n, g->D, c0->r).rho, d1 = cdist__point_circle(c1->n, g->D, c1->r).rho;
    double var = fmin(2.0 * d0 + c1->r * sn * (2.0 + sn), 2.0 * d1 + c0->r * sn * (2.0 + sn));
    if (var <= CD_TIE_ULPS * DBL_EPSILON * g->L) {
        double F;
        double t = cdist__cc_polish(g, 0, 0.0, &F);
        cdist__cc_offer(g, 0, t, b);
        b->equidistant = 1;
        return 1;
    }
    return 0;
}

static double angle_of(const cdist__circle *c, vec3 dir)
{
    double a = cdist__circle_angle(c, dir);
    return isnan(a) ? 0.0 : a;
}

int cdist__cc_parallel_candidates(const cdist__cc *g, double *t0)
{
    const cdist__circle *c0 = g->c[0], *c1 = g->c[1];
    vec3 n = c0->n;
    cdist__pc_parts e = cdist__point_circle(n, g->D, c0->r);
    vec3 nd = e.np;
    double din = e.rho;
    if (!(din > 0.0)) {
        t0[0] = 0.0, t0[1] = 0.5 * M_PI, t0[2] = M_PI, t0[3] = -0.5 * M_PI;
        return 4;
    }
    vec3 W = v_scale(1.0 / din, cdist__pc_inplane(nd, n)); /* in-plane direction towards c1's centre */
    vec3 T = v_scale(1.0 / din, nd); /* n x W */
    double r0 = c0->r, r1 = c1->r;
    int k = 0;
    if (din >= r0 + r1 || din + r1 <= r0) {
        t0[k++] = angle_of(c0, W); /* separated, tangent, or c1 inside c0 */
    } else if (din + r0 <= r1) {
        t0[k++] = angle_of(c0, v_neg(W)); /* c0 inside c1 */
    } else {
        /* overlapping projections: the two crossings cos a W +- sin a T, by the half angle (a
         * chord y from x = (d^2 + r0^2 - r1^2) / 2d lost the crossings of a tiny c1 across c0's
         * rim, x rounding to r0) */
        double a = cdist__crossing_angle(r0, din, r1), x = cos(a), y = sin(a);
        t0[k++] = angle_of(c0, v_axpy(v_scale(x, W), y, T));
        t0[k++] = angle_of(c0, v_axpy(v_scale(x, W), -y, T));
    }
    return k;
}

int cdist__cc_mirror(const cdist__cc *g, vec3 *m)
{
    vec3 c = v_cross(g->c[0]->n, g->c[1]->n);
    double s = v_norm(c);
    if (!(s > CD_CC_POLY_PARALLEL)) return 0;
    vec3 mm = v_scale(1.0 / s, c);
    if (fabs(v_dot(g->D, mm)) > CD_CC_MIRROR_REL * g->L) return 0;
    *m = mm;
    return 1;
}

/* ---------------------------------------------------------------------------------------- */
/* Candidate bookkeeping shared by the polynomial method                                    */
/* ---------------------------------------------------------------------------------------- */

#define CC_MAXCAND 48

/* Candidates are kept as (cos t, sin t): roots come as (gamma, sigma), and most candidates are
 * only evaluated, never polished, so atan2/sincos are spent only on the few that are. */
typedef struct cc_cands {
    int n;
    int side[CC_MAXCAND];
    double ct[CC_MAXCAND], st[CC_MAXCAND];
    double F[CC_MAXCAND];
} cc_cands;

static void cand_add_cs(cc_cands *c, int side, double ct, double st)
{
    if (c->n >= CC_MAXCAND || !isfinite(ct) || !isfinite(st)) return;
    c->side[c->n] = side;
    c->ct[c->n] = ct;
    c->st[c->n] = st;
    c->n++;
}

static void cand_add(cc_cands *c, int side, double t) { cand_add_cs(c, side, cos(t), sin(t)); }

/* Angle on circle `side` of the mirror image (plane through both axes, normal m) of the point
 * at angle t. */
static double mirror_angle(const cdist__cc *g, int side, vec3 m, double t)
{
    const cdist__circle *c = g->c[side];
    vec3 p = v_axpy(v_scale(cos(t), c->u), sin(t), c->v);
    p = v_axpy(p, -2.0 * v_dot(p, m), m);
    return angle_of(c, p);
}

/* Evaluate every candidate, polish those near the best value, add mirror images when the axes
 * meet, offer the polished minima. */
static void finish_candidates(const cdist__cc *g, cc_cands *c, cdist__best *b)
{
    double Fmin = INFINITY;
    for (int i = 0; i < c->n; i++) {
        c->F[i] = eval_cs(g, c->side[i], c->ct[i], c->st[i], NULL, NULL, NULL, NULL);
        if (c->F[i] < Fmin) Fmin = c->F[i];
    }
    /* A root found to ~sqrt(eps) (near a double root) has F within ~1e-8 L^2 of its minimum;
     * the margin keeps every candidate that could polish below the best. */
    double margin = CD_CC_KEEP_REL * Fmin + CD_CC_KEEP_ABS * g->L * g->L;
    vec3 m;
    int mir = cdist__cc_mirror(g, &m);
    double pt[CC_MAXCAND], pF[CC_MAXCAND];
    int ps[CC_MAXCAND], np = 0;
    double best = INFINITY;
    for (int i = 0; i < c->n; i++) {
        if (!(c->F[i] <= Fmin + margin)) continue;
        int dup = 0;
        for (int j = 0; j < i; j++)
            if (c->side[j] == c->side[i] && c->ct[j] == c->ct[i] && c->st[j] == c->st[i] &&
                c->F[j] <= Fmin + margin)
                dup = 1;
        if (dup) continue;
        double F;
        double t = cdist__cc_polish(g, c->side[i], atan2(c->st[i], c->ct[i]), &F);
        ps[np] = c->side[i], pt[np] = t, pF[np] = F, np++;
        if (F < best) best = F;
    }
    int n0 = np;
    if (mir) {
        for (int i = 0; i < n0 && np < CC_MAXCAND; i++) {
            if (!(pF[i] <= best + margin)) continue;
            double F;
            double t = cdist__cc_polish(g, ps[i], mirror_angle(g, ps[i], m, pt[i]), &F);
            ps[np] = ps[i], pt[np] = t, pF[np] = F, np++;
        }
    }
    cdist__cc_offer_minima(g, np, ps, pt, pF, b);
}

/* Candidates shared by both sides' special structure: parallel closed forms, and the points
 * of each circle in the mirror plane when the axes meet (critical by symmetry; §5.3's
 * t = 0, pi when the centres are on the normal line). */
static void special_candidates(const cdist__cc *g, cc_cands *c)
{
    double sn = v_norm(v_cross(g->c[0]->n, g->c[1]->n));
    if (sn <= CD_CC_POLY_NEAR_PARALLEL) {
        double t0[4];
        int k = cdist__cc_parallel_candidates(g, t0);
        for (int i = 0; i < k; i++) cand_add(c, 0, t0[i]);
    }
    vec3 m;
    if (cdist__cc_mirror(g, &m)) {
        for (int s = 0; s < 2; s++) {
            vec3 dir = v_cross(m, g->c[s]->n);
            double a = angle_of(g->c[s], dir);
            cand_add(c, s, a);
            cand_add(c, s, a > 0.0 ? a - M_PI : a + M_PI);
        }
    }
}

/* ---------------------------------------------------------------------------------------- */
/* The polynomial                                                                            */
/* ---------------------------------------------------------------------------------------- */

/* out = a + s * b (out may alias a), returns the degree max(da, db). */
static int paxpy(double *out, int da, double s, const double *b, int db)
{
    int d = da > db ? da : db;
    for (int i = da + 1; i <= d; i++) out[i] = 0.0;
    for (int i = 0; i <= db; i++) out[i] += s * b[i];
    return d;
}

/* Eberly (19)-(21) for the moving circle `side` against the fixed circle. H is homogeneous of
 * degree 6 in the lengths, so a common scale changes no root: lengths are divided by
 * max(r_fixed, |D|) (the fixed circle becomes the unit circle unless the circles are far apart,
 * when the centre distance becomes 1) so that no coefficient overflows. Writes p6 (deg 4),
 * p7 (deg 3), phi (deg 8). */
static void build_phi(const cdist__cc *g, int side, double *p6, double *p7, double *phi)
{
    const cdist__circle *m = g->c[side], *f = g->c[1 - side];
    double k = 1.0 / fmax(f->r, v_norm(g->D));
    vec3 D = v_scale(side ? k : -k, g->D);
    double r1 = m->r * k, r0 = f->r * k, r02 = r0 * r0;
    vec3 N0 = f->n, U1 = m->u, V1 = m->v;
    vec3 ND = v_cross(N0, D), NU = v_cross(N0, U1), NV = v_cross(N0, V1);
    double nu = v_dot(N0, U1), nv = v_dot(N0, V1);
    double a0 = r1 * v_dot(D, U1), a1 = r1 * v_dot(D, V1);
    double a2 = v_sqr(ND);
    double a3 = r1 * v_dot(ND, NU), a4 = r1 * v_dot(ND, NV);
    double r12 = r1 * r1;
    double a6 = r12 * v_dot(NU, NV), a7 = r12 * v_sqr(NV);
    double a57 = r12 * (nv - nu) * (nv + nu); /* a5 - a7 */
    double P0[3] = {a2 + a7, 2.0 * a3, a57};
    double P1[2] = {2.0 * a4, 2.0 * a6};
    double P2[2] = {0.0, a1};
    double P3[1] = {-a0};
    double P4[3] = {-a6, a4, 2.0 * a6};
    double P5[2] = {-a3, -a57};
    const double OM[3] = {1.0, 0.0, -1.0}; /* 1 - g^2 */
    double t1[9], t2[9], t3[9], t4[9];
    /* S = p2^2 + (1 - g^2) p3^2 (deg 2) */
    double S[3];
    cdist__poly_mul(P2, 1, P2, 1, 0, S);
    double p33 = P3[0] * P3[0];
    paxpy(S, 2, p33, OM, 2);
    /* p6 = p0 S + (1 - g^2) 2 p1 p2 p3 - r0^2 (p4^2 + (1 - g^2) p5^2) */
    cdist__poly_mul(P0, 2, S, 2, 0, p6); /* deg 4 */
    cdist__poly_mul(P1, 1, P2, 1, 0, t1); /* deg 2 */
    cdist__poly_mul(t1, 2, OM, 2, 0, t2); /* deg 4 */
    paxpy(p6, 4, 2.0 * P3[0], t2, 4);
    cdist__poly_mul(P4, 2, P4, 2, 0, t1); /* deg 4 */
    paxpy(p6, 4, -r02, t1, 4);
    cdist__poly_mul(P5, 1, P5, 1, 0, t3); /* deg 2 */
    cdist__poly_mul(t3, 2, OM, 2, 0, t4); /* deg 4 */
    paxpy(p6, 4, -r02, t4, 4);
    /* p7 = 2 p0 p2 p3 + p1 S - 2 r0^2 p4 p5 */
    cdist__poly_mul(P0, 2, P2, 1, 0, p7); /* deg 3 */
    for (int i = 0; i <= 3; i++) p7[i] *= 2.0 * P3[0];
    cdist__poly_mul(P1, 1, S, 2, 0, t1); /* deg 3 */
    paxpy(p7, 3, 1.0, t1, 3);
    cdist__poly_mul(P4, 2, P5, 1, 0, t1); /* deg 3 */
    paxpy(p7, 3, -2.0 * r02, t1, 3);
    /* phi = p6^2 - (1 - g^2) p7^2 */
    cdist__poly_mul(p6, 4, p6, 4, 0, phi);
    cdist__poly_mul(p7, 3, p7, 3, 0, t1); /* deg 6 */
    cdist__poly_mul(t1, 6, OM, 2, 0, t2); /* deg 8 */
    paxpy(phi, 8, -1.0, t2, 8);
}

static cdist_status polynomial(cdist_query *q, const cdist__circle *c0, const cdist__circle *c1, cdist__best *b);

cdist_status cdist__cc_polynomial(cdist_query *q, const cdist__circle *c0, const cdist__circle *c1, cdist__best *b)
{
    cdist__circle a, bb;
    double s;
    cdist__cc_scale(c0, c1, b->scale, &a, &bb, &s);
    cdist__best sb;
    cdist__best_init(&sb, b->scale * s);
    cdist_status st = polynomial(q, &a, &bb, &sb);
    if (st == CDIST_OK) cdist__cc_unscale(&sb, s, b);
    return st;
}

static cdist_status polynomial(cdist_query *q, const cdist__circle *c0, const cdist__circle *c1, cdist__best *b)
{
    cdist__cc g = {{c0, c1}, c1->c, b->scale};
    if (cdist__cc_closed_form(&g, b)) return CDIST_OK;
    cc_cands c;
    c.n = 0;
    special_candidates(&g, &c);
    double sn = v_norm(v_cross(c0->n, c1->n));
    /* Moving circle: the smaller; the larger is the fixed unit circle of the polynomial. */
    int side = (c1->r <= c0->r) ? 1 : 0;
    /* Concentric (to 1e-6): F(t + pi) = F(t), phi is (nearly) even, and GSL's QR has been seen
     * to fail to converge on such a polynomial (its error handler aborts by default), so the
     * closed-form critical points of concentric circles are used instead: |P| is constant, so
     * F' = 0 where (N_f . e)(N_f . e') = 0, e(t) = cos t u + sin t v: e orthogonal to N_f (the
     * line where the planes meet) or e' orthogonal to N_f (the points furthest from the other
     * plane). Both sides; the small offset moves the minima by O(|D|), well inside their basins. */
    int concentric = v_norm(c1->c) <= CD_CC_POLY_CONCENTRIC_REL * fmax(c0->r, c1->r);
    if (concentric) {
        for (int s = 0; s < 2; s++) {
            const cdist__circle *m = g.c[s], *f = g.c[1 - s];
            double nu = v_dot(f->n, m->u), nv = v_dot(f->n, m->v);
            double a1 = atan2(-nu, nv), a2 = atan2(nv, nu);
            cand_add(&c, s, a1);
            cand_add(&c, s, a1 + M_PI);
            cand_add(&c, s, a2);
            cand_add(&c, s, a2 + M_PI);
        }
    }
    if (!concentric && (sn > CD_CC_POLY_PARALLEL || c.n == 0)) {
        double p6[5], p7[4], phi[9], roots[8];
        build_phi(&g, side, p6, p7, phi);
        int nr = cdist__poly_real_roots(q->poly, phi, 8, CD_CC_POLY_IMAG_TOL, roots);
        if (nr == CD_POLY_FAIL) return cdist__fail(q, CDIST_ERR_INTERNAL, "circle-circle: polynomial solver failed");
        double s7 = 0.0;
        for (int i = 0; i <= 3; i++) s7 += fabs(p7[i]);
        for (int i = 0; i < nr; i++) {
            double gm = roots[i];
            if (!(fabs(gm) <= 1.0 + CD_CC_POLY_COS_SLACK)) continue;
            gm = fmax(-1.0, fmin(1.0, gm));
            double sg = sqrt((1.0 - gm) * (1.0 + gm));
            double v6 = (((p6[4] * gm + p6[3]) * gm + p6[2]) * gm + p6[1]) * gm + p6[0];
            double v7 = ((p7[3] * gm + p7[2]) * gm + p7[1]) * gm + p7[0];
            /* sigma = -p6/p7 (Eberly); where p7 is within rounding of zero (the p7 = 0 branch)
             * both signs. Near-double roots (near-symmetric configurations) make even a
             * clearly non-zero p6/p7 sign unreliable, and the other sign costs one evaluation
             * (no measurable time), so it is always offered second. */
            double sgn = (v6 > 0.0) == (v7 > 0.0) ? -sg : sg;
            if (fabs(v7) <= CD_CC_POLY_P7_REL * s7) sgn = sg;
            cand_add_cs(&c, side, gm, sgn);
            if (sg > 0.0) cand_add_cs(&c, side, gm, -sgn);
        }
    }
    /* Safety samples: four angles of the moving circle (only polished when they beat every
     * root, i.e. if the solver missed the minimum's basin). */
    for (int i = 0; i < 4; i++) cand_add_cs(&c, side, (i == 1 || i == 2) ? M_SQRT1_2 : -M_SQRT1_2, i < 2 ? -M_SQRT1_2 : M_SQRT1_2);
    finish_candidates(&g, &c, b);
    return CDIST_OK;
}
