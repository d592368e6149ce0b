/* Circle-circle by the degree-8 polynomial (Eberly, distance-to-circles-3d §5), plus the helpers
 * shared with the geometric iteration (src/cc_iteration.c): the true distance function with its
 * derivatives, the Newton polish, and the closed forms of the special configurations.
 *
 * Frame. The dispatcher puts c0's centre at the origin and c1 at D. For a point P on circle s
 * (the "moving" circle, angle t in its own basis u, v) the distance to the other circle f is
 * closed form (point-circle, §2): with Delta = P - C_f, h = n_f . Delta, rho = |n_f x Delta|,
 *     F_s(t) = (rho - r_f)^2 + h^2                           (rho from the cross product: no
 *                                                              cancellation near the axis).
 * With E = Delta - K the vector from the closest point K = C_f + r_f w / rho (w the in-plane part
 * of Delta) to P, the gradient of the squared point-circle distance is 2E and its Hessian is
 * 2(I - (r_f / rho) tau tau^T) with tau = (n_f x Delta) / rho the circle's tangent at K, so
 *     F'  = 2 E . P',        P' = r_s(-sin t u + cos t v),
 *     F'' = 2 (r_s^2 - r_f (tau_rho . P')^2 / rho^3) - 2 E . P      (tau_rho = n_f x Delta).
 * E is formed as h n_f + ((rho - r_f) / rho) w, which stays accurate when the distance is tiny.
 * Every candidate angle (polynomial root, closed form, sample) is polished by safeguarded Newton
 * on F' and evaluated on F: the polynomial only brackets.
 *
 * Polynomial (§5). Eberly's F'(t) = 0 for the point P(t) of the moving circle against the fixed
 * circle of radius r0 is, squared to remove the root |N0 x Delta|,
 *     H(g, s) = (p0 + s p1)(p2 + s p3)^2 - r0^2 (p4 + s p5)^2 = p6(g) + s p7(g),  g = cos t,
 * s = sin t, and eliminating s with s^2 = 1 - g^2 gives phi(g) = p6^2 - (1 - g^2) p7^2 (degree
 * <= 8). Conditioning: the fixed circle is the LARGER one, scaled to the unit circle at the
 * origin (r0 = 1, everything divided by its radius), so the moving circle's radius is <= 1 and
 * the coefficients have comparable sizes. a5 - a7 = r1^2 ((N0.V1)^2 - (N0.U1)^2) is formed as a
 * product (it vanishes for parallel planes), a2, a3, a4 from the cross product N0 x D. For each
 * real root, s = -p6/p7; when p7 (or p6) is within rounding of zero at the root (the p7 = 0
 * branch; p7 == 0 identically when the centres lie on the normal line, §5.3) both signs
 * s = +-sqrt(1 - g^2) are tried. Double roots (tangency, §5.3's (g^2 - 1)^2 factor) come out of
 * the eigenvalue solver as complex pairs with imaginary parts ~ sqrt(eps): roots are accepted
 * with imaginary part up to 1e-6.
 * Special cases: zero radii (point-circle), coaxial circles (§5.1 concentric, §5.2 with the
 * centres on the common axis: equidistant), parallel planes (§5.1 separated / tangent /
 * overlapping / containing, §5.2): closed-form candidates; centres on the normal line (§5.3) and,
 * more generally, axes that meet: the configuration is symmetric about the plane through both
 * axes, so the points of the moving circle in that plane are candidates and every minimum's
 * mirror image is polished too (symmetric pairs come out equally accurate). */
#include <math.h>
#include <string.h>

#include "internal.h"

/* ---------------------------------------------------------------------------------------- */
/* Shared helpers (prototypes in the cc_methods block of internal.h)                          */
/* ---------------------------------------------------------------------------------------- */

double cd_cc_eval(const cd_cc *g, int side, double t, double *f1, double *f2, vec3 *P, vec3 *K)
{
    const cd_circle *m = g->c[side], *f = g->c[1 - side];
    vec3 dmf = side ? g->D : v_neg(g->D); /* moving centre relative to the fixed centre */
    double ct = cos(t), st = sin(t);
    vec3 p = v_axpy(v_scale(m->r * ct, m->u), m->r * st, m->v);
    vec3 dp = v_axpy(v_scale(-m->r * st, m->u), m->r * ct, m->v);
    vec3 dl = v_add(dmf, p);
    double h = v_dot(f->n, dl);
    vec3 nd = v_cross(f->n, dl);
    double rho = v_norm(nd);
    double e = rho - f->r;
    double F = fma(e, e, h * h);
    vec3 k, E;
    double d2f = 2.0 * m->r * m->r;
    if (rho > 0.0) {
        vec3 w = v_cross(nd, f->n);
        k = v_scale(f->r / rho, w);
        E = v_axpy(v_scale(h, f->n), e / rho, w);
        double tp = v_dot(nd, dp);
        d2f -= 2.0 * f->r * (tp / rho) * (tp / rho) / rho;
    } else { /* on the other circle's axis: every point of it is closest (a kink of F) */
        k = v_scale(f->r, f->u);
        E = v_sub(dl, k);
    }
    if (f1) *f1 = 2.0 * v_dot(E, dp);
    if (f2) *f2 = d2f - 2.0 * v_dot(E, p);
    if (P) *P = p;
    if (K) *K = k;
    return F;
}

double cd_cc_polish(const cd_cc *g, int side, double t, double *Fout)
{
    double f1, f2;
    double F = cd_cc_eval(g, side, t, &f1, &f2, NULL, NULL);
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
            Fn = cd_cc_eval(g, side, tn, &g1, &g2, NULL, NULL);
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

void cd_cc_offer(const cd_cc *g, int side, double t, cd_best *b)
{
    vec3 P, K;
    double F = cd_cc_eval(g, side, t, NULL, NULL, &P, &K);
    const cd_circle *m = g->c[side], *f = g->c[1 - side];
    double am = cd_circle_angle(m, P), af = cd_circle_angle(f, K);
    if (m->r == 0.0) am = NAN;
    if (f->r == 0.0) af = NAN;
    if (side == 0) cd_best_offer(b, F, P, v_add(K, g->D), am, af);
    else cd_best_offer(b, F, K, v_add(P, g->D), af, am);
}

/* Normals parallel to rounding: below this |n0 x n1| the planes are treated as parallel. */
#define CC_PARALLEL 1e-13
/* Closed-form candidates for parallel planes are added up to this |n0 x n1| (they are only
 * starting points; the polish finds the true minima of slightly tilted circles). */
#define CC_NEAR_PARALLEL 1e-4

int cd_cc_closed_form(const cd_cc *g, cd_best *b)
{
    const cd_circle *c0 = g->c[0], *c1 = g->c[1];
    if (c1->r == 0.0) { /* c1 is the point D (c0 may be a point too) */
        cd_point_circle_core(g->D, c0, b, 1);
        return 1;
    }
    if (c0->r == 0.0) { /* c0 is the origin: point-circle relative to c1, moved back by D */
        cd_best t;
        cd_best_init(&t, b->scale);
        cd_point_circle_core(v_neg(g->D), c1, &t, 0);
        for (int i = 0; i < t.n; i++)
            cd_best_offer(b, t.c[i].d2, v3(0, 0, 0), v_add(t.c[i].p[1], g->D), NAN, t.c[i].param[1]);
        b->equidistant |= t.equidistant;
        return 1;
    }
    /* Coaxial (Eberly §5.1 (a), §5.2; Li et al. §2.4): every point of either circle is equally
     * far from the other, distance sqrt((r1 - r0)^2 + h^2). The tolerances are rounding of the
     * normals and of D; the representative pair is polished on the true distance so that a
     * configuration that is coaxial only to rounding still gets its exact minimum. */
    double sn = v_norm(v_cross(c0->n, c1->n));
    double off = v_norm(v_cross(c0->n, g->D));
    if (sn <= 16.0 * DBL_EPSILON && off <= 16.0 * DBL_EPSILON * fmax(g->L, v_norm(g->D))) {
        double F;
        double t = cd_cc_polish(g, 0, 0.0, &F);
        cd_cc_offer(g, 0, t, b);
        b->equidistant = 1;
        return 1;
    }
    return 0;
}

static double angle_of(const cd_circle *c, vec3 dir)
{
    double a = cd_circle_angle(c, dir);
    return isnan(a) ? 0.0 : a;
}

int cd_cc_parallel_candidates(const cd_cc *g, double *t0)
{
    const cd_circle *c0 = g->c[0], *c1 = g->c[1];
    vec3 n = c0->n;
    vec3 nd = v_cross(n, g->D);
    double din = v_norm(nd);
    if (!(din > 0.0)) {
        t0[0] = 0.0, t0[1] = 0.5 * M_PI, t0[2] = M_PI, t0[3] = -0.5 * M_PI;
        return 4;
    }
    vec3 W = v_scale(1.0 / din, v_cross(nd, n)); /* in-plane direction towards c1's centre */
    vec3 T = v_scale(1.0 / din, nd);             /* n x W */
    double r0 = c0->r, r1 = c1->r;
    int k = 0;
    if (din >= r0 + r1 || din + r1 <= r0) {
        t0[k++] = angle_of(c0, W); /* separated, tangent, or c1 inside c0 */
    } else if (din + r0 <= r1) {
        t0[k++] = angle_of(c0, v_neg(W)); /* c0 inside c1 */
    } else {
        /* overlapping projections: the two crossings x W +- y T, x = (d^2 + r0^2 - r1^2) / 2d */
        double x = 0.5 * (din + (r0 - r1) * (r0 + r1) / din);
        double y2 = (r0 - x) * (r0 + x);
        double y = y2 > 0.0 ? sqrt(y2) : 0.0;
        t0[k++] = angle_of(c0, v_axpy(v_scale(x, W), y, T));
        t0[k++] = angle_of(c0, v_axpy(v_scale(x, W), -y, T));
    }
    return k;
}

int cd_cc_mirror(const cd_cc *g, vec3 *m)
{
    vec3 c = v_cross(g->c[0]->n, g->c[1]->n);
    double s = v_norm(c);
    if (!(s > CC_PARALLEL)) return 0;
    vec3 mm = v_scale(1.0 / s, c);
    if (fabs(v_dot(g->D, mm)) > 1e-9 * g->L) return 0;
    *m = mm;
    return 1;
}

/* ---------------------------------------------------------------------------------------- */
/* Candidate bookkeeping shared by the polynomial method                                    */
/* ---------------------------------------------------------------------------------------- */

#define CC_MAXCAND 48

typedef struct cc_cands {
    int n;
    int side[CC_MAXCAND];
    double t[CC_MAXCAND];
    double F[CC_MAXCAND];
} cc_cands;

static void cand_add(cc_cands *c, int side, double t)
{
    if (c->n >= CC_MAXCAND || !isfinite(t)) return;
    c->side[c->n] = side;
    c->t[c->n] = t;
    c->n++;
}

/* Angle on circle `side` of the mirror image (plane through both axes, normal m) of the point
 * at angle t. */
static double mirror_angle(const cd_cc *g, int side, vec3 m, double t)
{
    const cd_circle *c = g->c[side];
    vec3 p = v_axpy(v_scale(cos(t), c->u), sin(t), c->v);
    p = v_axpy(p, -2.0 * v_dot(p, m), m);
    return angle_of(c, p);
}

/* Evaluate every candidate, polish those near the best value, add mirror images when the axes
 * meet, offer the polished minima. */
static void finish_candidates(const cd_cc *g, cc_cands *c, cd_best *b)
{
    double Fmin = INFINITY;
    for (int i = 0; i < c->n; i++) {
        c->F[i] = cd_cc_eval(g, c->side[i], c->t[i], NULL, NULL, NULL, NULL);
        if (c->F[i] < Fmin) Fmin = c->F[i];
    }
    /* A root found to ~sqrt(eps) (near a double root) has F within ~1e-8 L^2 of its minimum;
     * the margin keeps every candidate that could polish below the best. */
    double margin = 1e-3 * Fmin + 1e-6 * g->L * g->L;
    vec3 m;
    int mir = cd_cc_mirror(g, &m);
    double pt[CC_MAXCAND], pF[CC_MAXCAND];
    int ps[CC_MAXCAND], np = 0;
    double best = INFINITY;
    for (int i = 0; i < c->n; i++) {
        if (!(c->F[i] <= Fmin + margin)) continue;
        int dup = 0;
        for (int j = 0; j < i; j++)
            if (c->side[j] == c->side[i] && c->t[j] == c->t[i] && c->F[j] <= Fmin + margin) dup = 1;
        if (dup) continue;
        double F;
        double t = cd_cc_polish(g, c->side[i], c->t[i], &F);
        ps[np] = c->side[i], pt[np] = t, pF[np] = F, np++;
        if (F < best) best = F;
    }
    int n0 = np;
    if (mir) {
        for (int i = 0; i < n0 && np < CC_MAXCAND; i++) {
            if (!(pF[i] <= best + margin)) continue;
            double F;
            double t = cd_cc_polish(g, ps[i], mirror_angle(g, ps[i], m, pt[i]), &F);
            ps[np] = ps[i], pt[np] = t, pF[np] = F, np++;
        }
    }
    for (int i = 0; i < np; i++) cd_cc_offer(g, ps[i], pt[i], b);
}

/* Candidates shared by both sides' special structure: parallel closed forms, and the points
 * of each circle in the mirror plane when the axes meet (critical by symmetry; §5.3's
 * t = 0, pi when the centres are on the normal line). */
static void special_candidates(const cd_cc *g, cc_cands *c)
{
    double sn = v_norm(v_cross(g->c[0]->n, g->c[1]->n));
    if (sn <= CC_NEAR_PARALLEL) {
        double t0[4];
        int k = cd_cc_parallel_candidates(g, t0);
        for (int i = 0; i < k; i++) cand_add(c, 0, t0[i]);
    }
    vec3 m;
    if (cd_cc_mirror(g, &m)) {
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

/* out = a * b (degrees da, db); out must not alias. */
static int pmul(const double *a, int da, const double *b, int db, double *out)
{
    for (int i = 0; i <= da + db; i++) out[i] = 0.0;
    for (int i = 0; i <= da; i++)
        for (int j = 0; j <= db; j++) out[i + j] = fma(a[i], b[j], out[i + j]);
    return da + db;
}

/* out = a + s * b (out may alias a), returns the degree max(da, db). */
static int paxpy(double *out, int da, double s, const double *b, int db)
{
    int d = da > db ? da : db;
    for (int i = da + 1; i <= d; i++) out[i] = 0.0;
    for (int i = 0; i <= db; i++) out[i] = fma(s, b[i], out[i]);
    return d;
}

/* Eberly (19)-(21) for the moving circle `side` against the fixed circle, scaled so the fixed
 * circle has radius 1. Writes p6 (deg 4), p7 (deg 3), phi (deg 8). */
static void build_phi(const cd_cc *g, int side, double *p6, double *p7, double *phi)
{
    const cd_circle *m = g->c[side], *f = g->c[1 - side];
    double k = 1.0 / f->r;
    vec3 D = v_scale(side ? k : -k, g->D);
    double r1 = m->r * k;
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
    pmul(P2, 1, P2, 1, S);
    double p33 = P3[0] * P3[0];
    paxpy(S, 2, p33, OM, 2);
    /* p6 = p0 S + (1 - g^2) 2 p1 p2 p3 - (p4^2 + (1 - g^2) p5^2) */
    pmul(P0, 2, S, 2, p6); /* deg 4 */
    pmul(P1, 1, P2, 1, t1); /* deg 2 */
    pmul(t1, 2, OM, 2, t2); /* deg 4 */
    paxpy(p6, 4, 2.0 * P3[0], t2, 4);
    pmul(P4, 2, P4, 2, t1); /* deg 4 */
    paxpy(p6, 4, -1.0, t1, 4);
    pmul(P5, 1, P5, 1, t3); /* deg 2 */
    pmul(t3, 2, OM, 2, t4); /* deg 4 */
    paxpy(p6, 4, -1.0, t4, 4);
    /* p7 = 2 p0 p2 p3 + p1 S - 2 p4 p5 */
    pmul(P0, 2, P2, 1, p7); /* deg 3 */
    for (int i = 0; i <= 3; i++) p7[i] *= 2.0 * P3[0];
    pmul(P1, 1, S, 2, t1); /* deg 3 */
    paxpy(p7, 3, 1.0, t1, 3);
    pmul(P4, 2, P5, 1, t1); /* deg 3 */
    paxpy(p7, 3, -2.0, t1, 3);
    /* phi = p6^2 - (1 - g^2) p7^2 */
    pmul(p6, 4, p6, 4, phi);
    pmul(p7, 3, p7, 3, t1); /* deg 6 */
    pmul(t1, 6, OM, 2, t2); /* deg 8 */
    paxpy(phi, 8, -1.0, t2, 8);
}

cdist_status cd_cc_polynomial(cdist_query *q, const cd_circle *c0, const cd_circle *c1, cd_best *b)
{
    cd_cc g = {{c0, c1}, c1->c, b->scale};
    if (cd_cc_closed_form(&g, b)) return CDIST_OK;
    cc_cands c;
    c.n = 0;
    special_candidates(&g, &c);
    double sn = v_norm(v_cross(c0->n, c1->n));
    /* Moving circle: the smaller; the larger is the fixed unit circle of the polynomial. */
    int side = (c1->r <= c0->r) ? 1 : 0;
    if (sn > CC_PARALLEL || c.n == 0) {
        double p6[5], p7[4], phi[9], roots[8];
        build_phi(&g, side, p6, p7, phi);
        int nr = cd_poly_real_roots(q->poly, phi, 8, 1e-6, roots);
        if (nr == CD_POLY_FAIL) return cd_fail(q, CDIST_ERR_INTERNAL, "circle-circle: polynomial solver failed");
        double s6 = 0.0, s7 = 0.0;
        for (int i = 0; i <= 4; i++) s6 += fabs(p6[i]);
        for (int i = 0; i <= 3; i++) s7 += fabs(p7[i]);
        for (int i = 0; i < nr; i++) {
            double gm = roots[i];
            if (!(fabs(gm) <= 1.0 + 1e-6)) continue;
            gm = fmax(-1.0, fmin(1.0, gm));
            double sg = sqrt((1.0 - gm) * (1.0 + gm));
            double v6 = cd_poly_eval(p6, 4, gm, NULL), v7 = cd_poly_eval(p7, 3, gm, NULL);
            if (fabs(v7) <= 1e-6 * s7 || fabs(v6) <= 1e-6 * s6) {
                cand_add(&c, side, atan2(sg, gm));
                if (sg > 0.0) cand_add(&c, side, atan2(-sg, gm));
            } else {
                cand_add(&c, side, atan2((v6 > 0.0) == (v7 > 0.0) ? -sg : sg, gm));
            }
        }
    }
    /* Safety samples: four angles of the moving circle (only polished when they beat every
     * root, i.e. if the solver missed the minimum's basin). */
    for (int i = 0; i < 4; i++) cand_add(&c, side, -0.75 * M_PI + 0.5 * M_PI * i);
    finish_candidates(&g, &c, b);
    return CDIST_OK;
}
