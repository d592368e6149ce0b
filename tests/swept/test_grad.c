/* SPDX-License-Identifier: MIT */
/* Gradients (cdist_*_grad) against finite differences of the distance.
 *  - Every line of the shared reference files (tests/data/{pc,pd,lc,ld,cc,cd}_{random,hard}.txt;
 *    lc/ld lines are also run as rays and segments, cd lines also as circle-circle and
 *    disk-disk) and random configurations: where the flag CDIST_GRAD_NOT_DIFFERENTIABLE is not
 *    set, every gradient component agrees with a central difference (Richardson-extrapolated,
 *    with a smaller plain step as second opinion) of the distance to 1e-7 relative. Normal and
 *    direction gradients are checked along two unit-preserving tangent perturbations and must
 *    be orthogonal to the vector.
 *  - Constructed non-differentiable configurations (two pairs, an equidistant set, zero
 *    distance) have the flag set, and their one-sided derivatives really differ.
 *  - Every clause of the header's gradient paragraph on a case where it applies (check_clauses):
 *    against differences of the distance (central, one-sided, forward) or a closed form.
 * The differences are taken of the distance the library computes, which the reference tests
 * hold to ~1e-15 of scale; the gradients come from a separate code path (the closest pair).
 * Where double differences cannot resolve the derivative (near-degenerate hard lines), the
 * point-circle, point-disk, circle-circle and line-circle hard sets are checked again against
 * differences of independent closed forms / minimisations in __float128. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "query_io.h"

/* Field types in a query line's numbers. */
enum { F_END, F_CENTER, F_NORMAL, F_RADIUS, F_ORIGIN, F_DIR, F_P0, F_P1, F_ZERO, F_START, F_ENDANG, F_RSWEPT };

typedef struct field {
    int type, offset, obj;
} field;

typedef cdist_status (*grad_fn)(cdist_query *, const double *, cdist_result *, cdist_grad *);

static cdist_vec3 V(const double *v) { return tv(v[0], v[1], v[2]); }
static cdist_circle Cc(const double *v) { cdist_circle c = {V(v), V(v + 3), v[6]}; return c; }

#define G2(name, ...)                                                                                              \
    static cdist_status name(cdist_query *q, const double *v, cdist_result *r, cdist_grad *g) { __VA_ARGS__; }
G2(g_pc, cdist_vec3 p = V(v); cdist_circle c = Cc(v + 3); return cdist_point_circle_grad(q, &p, &c, r, g))
G2(g_pd, cdist_vec3 p = V(v); cdist_circle c = Cc(v + 3); return cdist_point_disk_grad(q, &p, &c, r, g))
G2(g_lc, cdist_line l = {V(v), V(v + 3)}; cdist_circle c = Cc(v + 6); return cdist_line_circle_grad(q, &l, &c, r, g))
G2(g_rc, cdist_ray l = {V(v), V(v + 3)}; cdist_circle c = Cc(v + 6); return cdist_ray_circle_grad(q, &l, &c, r, g))
G2(g_sc, cdist_segment l = {V(v), V(v + 3)}; cdist_circle c = Cc(v + 6); return cdist_segment_circle_grad(q, &l, &c, r, g))
G2(g_ld, cdist_line l = {V(v), V(v + 3)}; cdist_circle c = Cc(v + 6); return cdist_line_disk_grad(q, &l, &c, r, g))
G2(g_rd, cdist_ray l = {V(v), V(v + 3)}; cdist_circle c = Cc(v + 6); return cdist_ray_disk_grad(q, &l, &c, r, g))
G2(g_sd, cdist_segment l = {V(v), V(v + 3)}; cdist_circle c = Cc(v + 6); return cdist_segment_disk_grad(q, &l, &c, r, g))
G2(g_cc, cdist_circle a = Cc(v); cdist_circle c = Cc(v + 7); return cdist_circle_circle_grad(q, &a, &c, r, g))
G2(g_cd, cdist_circle a = Cc(v); cdist_circle c = Cc(v + 7); return cdist_circle_disk_grad(q, &a, &c, r, g))
G2(g_dd, cdist_circle a = Cc(v); cdist_circle c = Cc(v + 7); return cdist_disk_disk_grad(q, &a, &c, r, g))

static cdist_arc Aa(const double *v) { cdist_arc a = {Cc(v), V(v + 7), v[10], v[11]}; return a; }
G2(g_ac, cdist_arc a = Aa(v); cdist_circle c = Cc(v + 12); return cdist_arc_circle_grad(q, &a, &c, r, g))
G2(g_ad, cdist_arc a = Aa(v); cdist_circle c = Cc(v + 12); return cdist_arc_disk_grad(q, &a, &c, r, g))
G2(g_aa, cdist_arc a = Aa(v); cdist_arc b = Aa(v + 12); return cdist_arc_arc_grad(q, &a, &b, r, g))
G2(g_sa, cdist_segment l = {V(v), V(v + 3)}; cdist_arc b = Aa(v + 6); return cdist_segment_arc_grad(q, &l, &b, r, g))

/* Swept kinds: the contact goes into the result (distance = signed distance, core points as
 * the pair, reserved[0] = the core distance) so the checks below apply unchanged. */
static void contact_to_result(const cdist_contact *c, cdist_result *r)
{
    memset(r, 0, sizeof *r);
    r->distance = c->distance;
    r->num_pairs = c->num_pairs;
    r->equidistant = c->equidistant;
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++) r->pairs[i].point[j] = c->pairs[i].core_point[j];
    r->reserved[0] = c->core_distance;
}
static cdist_torus Tt(const double *v) { cdist_torus t = {Cc(v), v[7]}; return t; }
static cdist_capsule Kk(const double *v) { cdist_capsule k = {{V(v), V(v + 3)}, v[6]}; return k; }
static cdist_sphere Ss(const double *v) { cdist_sphere x = {V(v), v[3]}; return x; }
static cdist_rounded_disk Rr(const double *v) { cdist_rounded_disk x = {Cc(v), v[7]}; return x; }
#define SG(name, call, ...)                                                                                        \
    static cdist_status name(cdist_query *q, const double *v, cdist_result *r, cdist_grad *g)                      \
    {                                                                                                              \
        cdist_contact c;                                                                                           \
        __VA_ARGS__;                                                                                               \
        cdist_status st = call;                                                                                    \
        contact_to_result(&c, r);                                                                                  \
        return st;                                                                                                 \
    }
SG(g_TT, cdist_torus_torus_grad(q, &a, &b, &c, g), cdist_torus a = Tt(v); cdist_torus b = Tt(v + 8))
SG(g_TK, cdist_torus_capsule_grad(q, &a, &b, &c, g), cdist_torus a = Tt(v); cdist_capsule b = Kk(v + 8))
SG(g_TS, cdist_torus_sphere_grad(q, &a, &b, &c, g), cdist_torus a = Tt(v); cdist_sphere b = Ss(v + 8))
SG(g_TR, cdist_torus_rounded_disk_grad(q, &a, &b, &c, g), cdist_torus a = Tt(v); cdist_rounded_disk b = Rr(v + 8))
SG(g_KK, cdist_capsule_capsule_grad(q, &a, &b, &c, g), cdist_capsule a = Kk(v); cdist_capsule b = Kk(v + 7))
SG(g_KS, cdist_capsule_sphere_grad(q, &a, &b, &c, g), cdist_capsule a = Kk(v); cdist_sphere b = Ss(v + 7))
SG(g_KR, cdist_capsule_rounded_disk_grad(q, &a, &b, &c, g), cdist_capsule a = Kk(v); cdist_rounded_disk b = Rr(v + 7))
SG(g_SS, cdist_sphere_sphere_grad(q, &a, &b, &c, g), cdist_sphere a = Ss(v); cdist_sphere b = Ss(v + 4))
SG(g_SR, cdist_sphere_rounded_disk_grad(q, &a, &b, &c, g), cdist_sphere a = Ss(v); cdist_rounded_disk b = Rr(v + 4))
SG(g_RR, cdist_rounded_disk_rounded_disk_grad(q, &a, &b, &c, g), cdist_rounded_disk a = Rr(v); cdist_rounded_disk b = Rr(v + 8))
SG(g_Tl, cdist_torus_line_grad(q, &a, &b, &c, g), cdist_torus a = Tt(v); cdist_line b = {V(v + 8), V(v + 11)})
SG(g_Tr, cdist_torus_ray_grad(q, &a, &b, &c, g), cdist_torus a = Tt(v); cdist_ray b = {V(v + 8), V(v + 11)})
SG(g_Ts, cdist_torus_segment_grad(q, &a, &b, &c, g), cdist_torus a = Tt(v); cdist_segment b = {V(v + 8), V(v + 11)})
SG(g_Kc, cdist_capsule_circle_grad(q, &a, &b, &c, g), cdist_capsule a = Kk(v); cdist_circle b = Cc(v + 7))
SG(g_Kd, cdist_capsule_disk_grad(q, &a, &b, &c, g), cdist_capsule a = Kk(v); cdist_circle b = Cc(v + 7))
SG(g_Sc, cdist_sphere_circle_grad(q, &a, &b, &c, g), cdist_sphere a = Ss(v); cdist_circle b = Cc(v + 4))
SG(g_Sd, cdist_sphere_disk_grad(q, &a, &b, &c, g), cdist_sphere a = Ss(v); cdist_circle b = Cc(v + 4))

#define CIRC(off, obj) {F_CENTER, off, obj}, {F_NORMAL, off + 3, obj}, {F_RADIUS, off + 6, obj}
#define ARC(off, obj) CIRC(off, obj), {F_ZERO, off + 7, obj}, {F_START, off + 10, obj}, {F_ENDANG, off + 11, obj}
#define TOR(off, obj) CIRC(off, obj), {F_RSWEPT, off + 7, obj}
#define CAP(off, obj) {F_P0, off, obj}, {F_P1, off + 3, obj}, {F_RSWEPT, off + 6, obj}
#define SPH(off, obj) {F_CENTER, off, obj}, {F_RSWEPT, off + 3, obj}
#define LIN(off, obj) {F_ORIGIN, off, obj}, {F_DIR, off + 3, obj}
#define SEG(off, obj) {F_P0, off, obj}, {F_P1, off + 3, obj}
typedef struct gkind {
    const char *name;
    grad_fn fn;
    field f[14];
} gkind;
static const gkind gkinds[] = {
    {"pc", g_pc, {{F_CENTER, 0, 0}, CIRC(3, 1), {F_END, 0, 0}}},
    {"pd", g_pd, {{F_CENTER, 0, 0}, CIRC(3, 1), {F_END, 0, 0}}},
    {"lc", g_lc, {{F_ORIGIN, 0, 0}, {F_DIR, 3, 0}, CIRC(6, 1), {F_END, 0, 0}}},
    {"rc", g_rc, {{F_ORIGIN, 0, 0}, {F_DIR, 3, 0}, CIRC(6, 1), {F_END, 0, 0}}},
    {"sc", g_sc, {{F_P0, 0, 0}, {F_P1, 3, 0}, CIRC(6, 1), {F_END, 0, 0}}},
    {"ld", g_ld, {{F_ORIGIN, 0, 0}, {F_DIR, 3, 0}, CIRC(6, 1), {F_END, 0, 0}}},
    {"rd", g_rd, {{F_ORIGIN, 0, 0}, {F_DIR, 3, 0}, CIRC(6, 1), {F_END, 0, 0}}},
    {"sd", g_sd, {{F_P0, 0, 0}, {F_P1, 3, 0}, CIRC(6, 1), {F_END, 0, 0}}},
    {"cc", g_cc, {CIRC(0, 0), CIRC(7, 1), {F_END, 0, 0}}},
    {"cd", g_cd, {CIRC(0, 0), CIRC(7, 1), {F_END, 0, 0}}},
    {"dd", g_dd, {CIRC(0, 0), CIRC(7, 1), {F_END, 0, 0}}},
    {"ac", g_ac, {ARC(0, 0), CIRC(12, 1), {F_END, 0, 0}}},
    {"ad", g_ad, {ARC(0, 0), CIRC(12, 1), {F_END, 0, 0}}},
    {"aa", g_aa, {ARC(0, 0), ARC(12, 1), {F_END, 0, 0}}},
    {"sa", g_sa, {SEG(0, 0), ARC(6, 1), {F_END, 0, 0}}},
    {"TT", g_TT, {TOR(0, 0), TOR(8, 1), {F_END, 0, 0}}},
    {"TK", g_TK, {TOR(0, 0), CAP(8, 1), {F_END, 0, 0}}},
    {"TS", g_TS, {TOR(0, 0), SPH(8, 1), {F_END, 0, 0}}},
    {"TR", g_TR, {TOR(0, 0), TOR(8, 1), {F_END, 0, 0}}},
    {"KK", g_KK, {CAP(0, 0), CAP(7, 1), {F_END, 0, 0}}},
    {"KS", g_KS, {CAP(0, 0), SPH(7, 1), {F_END, 0, 0}}},
    {"KR", g_KR, {CAP(0, 0), TOR(7, 1), {F_END, 0, 0}}},
    {"SS", g_SS, {SPH(0, 0), SPH(4, 1), {F_END, 0, 0}}},
    {"SR", g_SR, {SPH(0, 0), TOR(4, 1), {F_END, 0, 0}}},
    {"RR", g_RR, {TOR(0, 0), TOR(8, 1), {F_END, 0, 0}}},
    {"Tl", g_Tl, {TOR(0, 0), LIN(8, 1), {F_END, 0, 0}}},
    {"Tr", g_Tr, {TOR(0, 0), LIN(8, 1), {F_END, 0, 0}}},
    {"Ts", g_Ts, {TOR(0, 0), SEG(8, 1), {F_END, 0, 0}}},
    {"Kc", g_Kc, {CAP(0, 0), CIRC(7, 1), {F_END, 0, 0}}},
    {"Kd", g_Kd, {CAP(0, 0), CIRC(7, 1), {F_END, 0, 0}}},
    {"Sc", g_Sc, {SPH(0, 0), CIRC(4, 1), {F_END, 0, 0}}},
    {"Sd", g_Sd, {SPH(0, 0), CIRC(4, 1), {F_END, 0, 0}}},
};
static const gkind *find_kind(const char *name)
{
    for (size_t i = 0; i < sizeof gkinds / sizeof gkinds[0]; i++)
        if (!strcmp(gkinds[i].name, name)) return &gkinds[i];
    return NULL;
}

static cdist_query *q;

/* The distance at numbers v (NaN on failure). */
static double dist_at(const gkind *k, const double *v)
{
    cdist_result r;
    cdist_grad g;
    if (k->fn(q, v, &r, &g) != CDIST_OK) return NAN;
    return r.distance;
}

static double len3(const double *v) { return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

/* Directional derivative of the distance along perturbation dir (applied by `apply`). */
typedef void (*apply_fn)(const double *v0, double *v, int off, const double *e, double h);
static void apply_add(const double *v0, double *v, int off, const double *e, double h)
{
    for (int i = 0; i < 3; i++) v[off + i] = v0[off + i] + h * e[i];
}
static void apply_unit(const double *v0, double *v, int off, const double *e, double h)
{
    double w[3], n = len3(v0 + off);
    for (int i = 0; i < 3; i++) w[i] = v0[off + i] / n + h * e[i];
    double m = len3(w);
    for (int i = 0; i < 3; i++) v[off + i] = w[i] / m;
}
static void apply_scalar(const double *v0, double *v, int off, const double *e, double h)
{
    (void)e;
    v[off] = v0[off] + h;
}

static double central(const gkind *k, const double *v0, int n, apply_fn ap, int off, const double *e, double h)
{
    double v[CDQ_MAX_VALUES];
    memcpy(v, v0, n * sizeof(double));
    ap(v0, v, off, e, h);
    double fp = dist_at(k, v);
    memcpy(v, v0, n * sizeof(double));
    ap(v0, v, off, e, -h);
    double fm = dist_at(k, v);
    return (fp - fm) / (2 * h);
}

static int n_checked, n_flagged;
static double worst;

/* The analytic derivative along e of the field (type, obj) at numbers v (NaN if the query
 * fails; flagged queries included: their gradient is one-sided). */
static double analytic(const gkind *k, const double *v, int type, int obj, const double *e);

/* Compare the analytic derivative `g` along e against finite differences: Richardson at a
 * large step; then plain central differences at steps 1e-3 .. 1e-10 of the scale. A step only
 * counts where the distance is smooth at its scale: the analytic derivative at v +- h differs
 * from g by var <= 1e-5 (relative); there the difference must agree within its rounding
 * allowance plus var. Returns 1 (agrees), 0 (a smooth step disagrees: a definite error) or -1
 * (unresolved: no step is smooth — near-degenerate inputs within a few ulps of a
 * non-differentiable configuration, where double differences cannot see the derivative). */
static int agrees(const gkind *k, const double *v0, int n, apply_fn ap, int off, const double *e, double g, double L,
                  double scale_g, int type, int obj)
{
    double tol = 1e-7 * fmax(scale_g, 1e-3);
    double u = ap == apply_unit ? 1.0 : L; /* unit of the perturbed quantity */
    double h = 1e-3 * u;
    double d1 = central(k, v0, n, ap, off, e, h), d2 = central(k, v0, n, ap, off, e, h / 2);
    double rich = (4 * d2 - d1) / 3;
    if (fabs(rich - g) <= tol) return 1;
    int smooth_seen = 0;
    double last_fd = NAN, last_var = NAN;
    for (double hk = 1e-3 * u; hk >= 1e-10 * u; hk *= 0.1) {
        double w[CDQ_MAX_VALUES];
        memcpy(w, v0, n * sizeof(double));
        ap(v0, w, off, e, hk);
        double gp = analytic(k, w, type, obj, e);
        memcpy(w, v0, n * sizeof(double));
        ap(v0, w, off, e, -hk);
        double gm = analytic(k, w, type, obj, e);
        double var = fmax(fabs(gp - g), fabs(gm - g));
        if (!(var <= 1e-5 * fmax(scale_g, 1e-3))) continue;
        double fd = central(k, v0, n, ap, off, e, hk);
        if (isnan(fd)) continue; /* e.g. a radius 0 cannot go negative */
        smooth_seen = 1;
        double allow = tol + 8 * DBL_EPSILON * fmax(L, 1e-300) / hk + var;
        if (fabs(fd - g) <= allow) return 1;
        last_fd = fd, last_var = var;
    }
    if (getenv("GRAD_VERBOSE"))
        fprintf(stderr, "  field at %d dir (%g %g %g): grad %.17g fd %.17g / %.17g (var %.3g) %s\n", off, e[0], e[1],
                e[2], g, rich, last_fd, last_var, smooth_seen ? "DISAGREES" : "unresolved");
    return smooth_seen ? 0 : -1;
}

static double dot3(const double *a, cdist_vec3 b) { return a[0] * b.x + a[1] * b.y + a[2] * b.z; }
static const double *vfield(const cdist_grad_object *o, int type)
{
    switch (type) {
    case F_CENTER: return &o->d_center.x;
    case F_NORMAL: return &o->d_normal.x;
    case F_ORIGIN: return &o->d_origin.x;
    case F_DIR: return &o->d_direction.x;
    case F_P0: return &o->d_p0.x;
    case F_P1: return &o->d_p1.x;
    case F_ZERO: return &o->d_zero_direction.x;
    }
    return NULL;
}

static double analytic(const gkind *k, const double *v, int type, int obj, const double *e)
{
    cdist_result r;
    cdist_grad g;
    if (k->fn(q, v, &r, &g) != CDIST_OK) return NAN;
    const cdist_grad_object *o = &g.obj[obj];
    if (type == F_RADIUS) return o->d_radius;
    if (type == F_RSWEPT) return o->d_radius_swept;
    if (type == F_START) return o->d_start;
    if (type == F_ENDANG) return o->d_end;
    const double *gv = vfield(o, type);
    return gv[0] * e[0] + gv[1] * e[1] + gv[2] * e[2];
}

/* Check one query; returns 1 when every component agrees. */
static int check_line(const gkind *k, const double *v0, int n, const char *where)
{
    cdist_result r;
    cdist_grad g;
    cdist_status st = k->fn(q, v0, &r, &g);
    CHECK(st == CDIST_OK, "%s: status %d %s", where, st, cdist_query_last_error(q));
    if (st) return 0;
    if (g.flags & CDIST_GRAD_NOT_DIFFERENTIABLE) {
        n_flagged++;
        double Lp = 0;
        for (int i = 0; i < 3; i++)
            Lp = fmax(Lp, fmax(fabs((&r.pairs[0].point[0].x)[i]), fabs((&r.pairs[0].point[1].x)[i])));
        double dcore = k->name[0] >= 'A' && k->name[0] <= 'Z' ? r.reserved[0] : r.distance;
        CHECK(r.num_pairs == 2 || r.equidistant || dcore <= 16 * DBL_EPSILON * Lp, "%s: flag without a reason",
              where);
        return 1;
    }
    /* Unflagged with two pairs or an equidistant set only at distance 0 (a stable crossing of a
     * disk, where the zero gradient is exact: the differences below check it). */
    double dcore = k->name[0] >= 'A' && k->name[0] <= 'Z' ? r.reserved[0] : r.distance, Lq = 0;
    for (int i = 0; i < 3; i++)
        Lq = fmax(Lq, fmax(fabs((&r.pairs[0].point[0].x)[i]), fabs((&r.pairs[0].point[1].x)[i])));
    CHECK((r.num_pairs == 1 && !r.equidistant) || dcore <= 16 * DBL_EPSILON * Lq,
          "%s: not flagged but two pairs / equidistant", where);
    if (getenv("GRAD_VERBOSE")) fprintf(stderr, "%s: distance %.17g\n", where, r.distance);
    /* scale: the distance and the objects' extent */
    double L = fabs(r.distance);
    for (int i = 0; i < n; i++) L = fmax(L, fabs(v0[i]));
    int ok = 1;
#define ACC(x) do { int a_ = (x); if (a_ == 0) ok = 0; else if (a_ < 0 && ok == 1) ok = -1; } while (0)
    for (const field *f = k->f; f->type != F_END; f++) {
        const cdist_grad_object *o = &g.obj[f->obj];
        if (f->type == F_RADIUS || f->type == F_RSWEPT || f->type == F_START || f->type == F_ENDANG) {
            double e[3] = {0};
            double gs = analytic(k, v0, f->type, f->obj, e);
            /* angles: the unit is the radian, scaled to lengths by the scale */
            double Ls = (f->type == F_START || f->type == F_ENDANG) ? 1.0 : L;
            ACC(agrees(k, v0, n, apply_scalar, f->offset, e, gs, Ls, fmax(1.0, fabs(gs)), f->type, f->obj));
            continue;
        }
        const double *gv = vfield(o, f->type);
        double gn = len3(gv);
        if (f->type == F_NORMAL || f->type == F_DIR) {
            double u[3], m = len3(v0 + f->offset);
            for (int i = 0; i < 3; i++) u[i] = v0[f->offset + i] / m;
            CHECK(fabs(gv[0] * u[0] + gv[1] * u[1] + gv[2] * u[2]) <= 1e-12 * (1 + gn), "%s: tangent gradient", where);
            /* two tangent directions */
            cdist_vec3 U = tv(u[0], u[1], u[2]), a, b;
            cdist_circle tmp = {tv(0, 0, 0), U, 1};
            cdist_circle_basis(&tmp, &a, &b);
            double ea[3] = {a.x, a.y, a.z}, eb[3] = {b.x, b.y, b.z};
            ACC(agrees(k, v0, n, apply_unit, f->offset, ea, dot3(gv, a), L, fmax(gn, L), f->type, f->obj));
            ACC(agrees(k, v0, n, apply_unit, f->offset, eb, dot3(gv, b), L, fmax(gn, L), f->type, f->obj));
        } else {
            for (int i = 0; i < 3; i++) {
                double e[3] = {0};
                e[i] = 1;
                ACC(agrees(k, v0, n, apply_add, f->offset, e, gv[i], L, 1, f->type, f->obj));
            }
        }
    }
#undef ACC
    n_checked++;
    return ok;
}

static void run_file(const char *dir, const char *file, const char *as)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", dir, file);
    FILE *f = fopen(path, "r");
    CHECK(f != NULL, "cannot open %s", path);
    if (!f) return;
    char line[4096];
    int lineno = 0, bad = 0, total = 0, unresolved = 0;
    const gkind *k = find_kind(as);
    while (fgets(line, sizeof line, f)) {
        lineno++;
        cdq_line ql;
        char err[256];
        if (cdq_parse(line, &ql, err, sizeof err) != 1) continue;
        char where[1200];
        snprintf(where, sizeof where, "%s:%d as %s", file, lineno, as);
        total++;
        int ok = check_line(k, ql.v, ql.nvalues, where);
        if (ok < 0) unresolved++;
        if (ok == 0) {
            bad++;
            if (bad <= 5 || getenv("GRAD_ALL")) fprintf(stderr, "%s: gradient disagrees with finite differences (worst %.3g x tol)\n", where, worst);
        }
    }
    fclose(f);
    CHECK(bad == 0, "%s as %s: %d of %d lines disagree", file, as, bad, total);
    /* Unresolvable differences only on the near-degenerate (hard) sets. */
    CHECK(unresolved == 0 || strstr(file, "_hard"), "%s as %s: %d unresolved lines", file, as, unresolved);
    printf("%-16s as %s: %d lines, %d disagree, %d not resolvable by differences\n", file, as, total, bad, unresolved);
}

/* One-sided derivatives of a constructed non-differentiable case differ (the flag is real). */
static void check_kink(const char *what, const gkind *k, double *v, int n, apply_fn ap, int off, const double *e,
                       double h)
{
    cdist_result r;
    cdist_grad g;
    CHECK(k->fn(q, v, &r, &g) == CDIST_OK, "%s status", what);
    CHECK(g.flags & CDIST_GRAD_NOT_DIFFERENTIABLE, "%s: flagged", what);
    double f0 = dist_at(k, v), w[CDQ_MAX_VALUES];
    memcpy(w, v, n * sizeof(double));
    ap(v, w, off, e, h);
    double right = (dist_at(k, w) - f0) / h;
    memcpy(w, v, n * sizeof(double));
    ap(v, w, off, e, -h);
    double left = (f0 - dist_at(k, w)) / h;
    CHECK(fabs(right - left) > 1e-3, "%s: one-sided derivatives %.6g and %.6g differ", what, left, right);
}

static void check_kinks(void)
{
    double ex[3] = {1, 0, 0}, ey[3] = {0, 1, 0};
    /* point on a circle's axis: equidistant */
    double pc[] = {0, 0, 0.5, 0, 0, 0, 0, 0, 1, 1};
    check_kink("point on the axis", find_kind("pc"), pc, 10, apply_add, 0, ex, 1e-6);
    /* line over a circle's diameter: two pairs at t = +-1; tilting the circle about y lifts one */
    double lc[] = {0, 0, 0.5, 1, 0, 0, 0, 0, 0, 0, 0, 1, 1};
    check_kink("line over a diameter", find_kind("lc"), lc, 13, apply_unit, 9, ex, 1e-6);
    /* crossing circles (distance 0) */
    double cc[] = {0, 0, 0, 0, 0, 1, 1, 1, 0, 0, 0, 1, 0, 1};
    check_kink("linked circles", find_kind("cc"), cc, 14, apply_add, 7, ey, 1e-6);
    /* a point on a disk's face (distance 0): |h| */
    double ez[3] = {0, 0, 1};
    double pd[] = {0.2, 0.1, 0, 0, 0, 0, 0, 0, 1, 1};
    check_kink("point on a disk", find_kind("pd"), pd, 10, apply_add, 0, ez, 1e-6);
    /* A segment through a disk: distance 0 on a neighbourhood. Not flagged; the zero gradient
     * is exact and differences agree. */
    double sd[] = {0.2, 0.1, -1, 0.2, 0.1, 1, 0, 0, 0, 0, 0, 1, 1};
    cdist_result r;
    cdist_grad g;
    CHECK(g_sd(q, sd, &r, &g) == CDIST_OK && !(g.flags & CDIST_GRAD_NOT_DIFFERENTIABLE) && g.obj[0].d_p0.x == 0 &&
              g.obj[1].d_center.z == 0,
          "segment through a disk: not flagged, gradient 0");
    /* ... but a segment ending on the disk is flagged (moving it up lifts it off) */
    double sd_end[] = {0.2, 0.1, 0, 0.2, 0.1, 1, 0, 0, 0, 0, 0, 1, 1};
    double ez2[3] = {0, 0, 1};
    check_kink("segment ending on a disk", find_kind("sd"), sd_end, 13, apply_add, 0, ez2, 1e-6);
    for (int i = 0; i < 13; i++) {
        double e1[3] = {1, 0, 0};
        double fd = central(find_kind("sd"), sd, 13, apply_scalar, i, e1, 1e-4);
        if (i == 3 || i == 4 || i == 5 || i == 9 || i == 10 || i == 11) continue;
        CHECK(fabs(fd) < 1e-15, "segment through a disk: distance constant nearby (number %d: %g)", i, fd);
    }
}

/* ---- every clause of the header's gradient paragraph, on a case where it applies ---- */

/* The gradient's components, flattened in the order of the kind's fields (vectors: 3 numbers;
 * scalars: 1). */
static int grad_numbers(const gkind *k, const cdist_grad *g, double *out)
{
    int m = 0;
    for (const field *f = k->f; f->type != F_END; f++) {
        const cdist_grad_object *o = &g->obj[f->obj];
        switch (f->type) {
        case F_RADIUS: out[m++] = o->d_radius; break;
        case F_RSWEPT: out[m++] = o->d_radius_swept; break;
        case F_START: out[m++] = o->d_start; break;
        case F_ENDANG: out[m++] = o->d_end; break;
        default:
            for (int i = 0; i < 3; i++) out[m++] = vfield(o, f->type)[i];
        }
    }
    return m;
}

/* Flagged, distance > 0: the gradient is that of pairs[0] (or of the equidistant set's
 * representative pair), the distance being the minimum over the closest pairs: along every
 * coordinate direction e of a centre / origin / end point and every radius, g . e lies between
 * the right derivative along e and the left one (one-sided differences of the distance), and
 * with two isolated pairs (two_pairs) it equals one of them. */
/* Returns the largest gap between a number's one-sided derivatives (a kink shows one). */
static double check_one_sided(const char *what, const gkind *k, const double *v, int n, int two_pairs)
{
    cdist_result r;
    cdist_grad g;
    CHECK(k->fn(q, v, &r, &g) == CDIST_OK && (g.flags & CDIST_GRAD_NOT_DIFFERENTIABLE), "%s: flagged", what);
    double f0 = dist_at(k, v), w[CDQ_MAX_VALUES], gap = 0.0;
    const double h = 1e-7;
    for (const field *f = k->f; f->type != F_END; f++) {
        if (f->type == F_NORMAL || f->type == F_DIR || f->type == F_ZERO || f->type == F_START || f->type == F_ENDANG)
            continue;
        int scalar = f->type == F_RADIUS || f->type == F_RSWEPT;
        for (int i = 0; i < (scalar ? 1 : 3); i++) {
            double gi = f->type == F_RADIUS ? g.obj[f->obj].d_radius
                        : f->type == F_RSWEPT ? g.obj[f->obj].d_radius_swept
                                              : vfield(&g.obj[f->obj], f->type)[i];
            memcpy(w, v, n * sizeof(double));
            w[f->offset + i] += h;
            double right = (dist_at(k, w) - f0) / h;
            memcpy(w, v, n * sizeof(double));
            w[f->offset + i] -= h;
            double left = (f0 - dist_at(k, w)) / h;
            int ok = two_pairs ? fabs(gi - right) < 1e-5 || fabs(gi - left) < 1e-5
                               : gi >= right - 1e-5 && gi <= left + 1e-5;
            CHECK(ok, "%s: number %d: gradient %.9g against the one-sided derivatives (left %.9g, right %.9g)", what,
                  f->offset + i, gi, left, right);
            gap = fmax(gap, fabs(left - right));
        }
    }
    return gap;
}

/* Distance 0: the gradient is exactly 0; flagged unless the distance is 0 on a neighbourhood,
 * which central differences along every number (and tangent directions of the unit vectors)
 * then confirm through check_line; where flagged, a one-sided derivative along `kink_off` /
 * e is not 0 (the distance is |.|-like there). */
static void check_zero(const char *what, const gkind *k, double *v, int n, int stable, apply_fn ap, int kink_off,
                       const double *e)
{
    cdist_result r;
    cdist_grad g;
    CHECK(k->fn(q, v, &r, &g) == CDIST_OK, "%s: status", what);
    double x[64];
    int m = grad_numbers(k, &g, x), swept = k->name[0] >= 'A' && k->name[0] <= 'Z';
    int zero = 1;
    for (int i = 0; i < m; i++)
        if (x[i] != 0.0 && !(swept && x[i] == -1.0)) zero = 0; /* swept radii: -1 */
    CHECK(zero, "%s: gradient exactly 0", what);
    CHECK((!(g.flags & CDIST_GRAD_NOT_DIFFERENTIABLE)) == stable, "%s: flag %d, expected %d", what, g.flags, !stable);
    if (stable) {
        CHECK(check_line(k, v, n, what) == 1, "%s: differences of the distance agree with the zero gradient", what);
    } else {
        double w[CDQ_MAX_VALUES], up, down;
        memcpy(w, v, n * sizeof(double));
        ap(v, w, kink_off, e, 1e-6);
        up = dist_at(k, w);
        memcpy(w, v, n * sizeof(double));
        ap(v, w, kink_off, e, -1e-6);
        down = dist_at(k, w);
        CHECK(fmax(up, down) - dist_at(k, v) > 1e-8, "%s: the distance grows on a side (not differentiable)", what);
    }
}

static void check_clauses(void)
{
    cdist_result r;
    cdist_grad g;
    const double s2 = sqrt(0.5);
    double ex[3] = {1, 0, 0}, ez[3] = {0, 0, 1};
    /* point P: dP = dp. Point (2, 0, 1) to the unit circle: pair (1, 0, 0), w = (1, 0, 1)/sqrt 2. */
    double pc[] = {2, 0, 1, 0, 0, 0, 0, 0, 1, 1};
    CHECK(g_pc(q, pc, &r, &g) == CDIST_OK && fabs(g.obj[0].d_center.x - s2) < 1e-15 &&
              fabs(g.obj[0].d_center.z - s2) < 1e-15 && fabs(g.obj[1].d_radius + s2) < 1e-15,
          "point: d_center = w, circle d_radius = -w.e");
    CHECK(check_line(find_kind("pc"), pc, 10, "clause point") == 1, "clause point: differences");
    /* line o + t d (t fixed): a generic line; ray with its start closest: d_direction = 0 */
    double lc[] = {0.3, -2, 0.7, 2.0 / 3, 2.0 / 3, 1.0 / 3, 0, 0, 0, 0, 0, 1, 1};
    CHECK(check_line(find_kind("lc"), lc, 13, "clause line") == 1, "clause line: differences");
    double rc[] = {2, 0, 1, 1, 0, 0, 0, 0, 0, 0, 0, 1, 1};
    CHECK(g_rc(q, rc, &r, &g) == CDIST_OK && r.pairs[0].param[0] == 0.0 && g.obj[0].d_direction.x == 0.0 &&
              g.obj[0].d_direction.y == 0.0 && g.obj[0].d_direction.z == 0.0,
          "ray start closest: d_direction = 0");
    CHECK(check_line(find_kind("rc"), rc, 13, "clause ray start") == 1, "clause ray start: differences");
    /* segment p0 + s (p1 - p0), s fixed, end points included: p1 closest gives d_p0 = 0 */
    double sc[] = {4, 0, 1, 2, 0, 1, 0, 0, 0, 0, 0, 1, 1};
    CHECK(g_sc(q, sc, &r, &g) == CDIST_OK && r.pairs[0].param[0] == 1.0 && g.obj[0].d_p0.x == 0.0 &&
              fabs(g.obj[0].d_p1.x - s2) < 1e-15,
          "segment end p1 closest: d_p0 = 0, d_p1 = w");
    CHECK(check_line(find_kind("sc"), sc, 13, "clause segment end") == 1, "clause segment end: differences");
    /* circle C + r e, de = -(e . dN) N: two tilted circles apart */
    double cc[] = {0, 0, 0, 0, 0, 1, 1, 0.5, 2, 0.3, 0.6, 0, 0.8, 0.7};
    CHECK(check_line(find_kind("cc"), cc, 14, "clause circle") == 1, "clause circle: differences");
    /* disk interior (s < 1): d_radius = 0, d_normal = -(w . N)(P - C) */
    double pd[] = {0.2, 0.1, 0.5, 0, 0, 0, 0, 0, 1, 1};
    CHECK(g_pd(q, pd, &r, &g) == CDIST_OK && g.obj[1].d_radius == 0.0 && fabs(g.obj[1].d_normal.x - 0.2) < 1e-15 &&
              fabs(g.obj[1].d_normal.y - 0.1) < 1e-15 && g.obj[1].d_normal.z == 0.0,
          "disk interior: d_radius 0, d_normal = (w.N)(P - C) for the disk's w = -N");
    CHECK(check_line(find_kind("pd"), pd, 10, "clause disk interior") == 1, "clause disk interior: differences");
    /* disk rim (s = 1) */
    double pd_rim[] = {1.5, 0.5, 0.5, 0, 0, 0, 0, 0, 1, 1};
    CHECK(check_line(find_kind("pd"), pd_rim, 10, "clause disk rim") == 1, "clause disk rim: differences");
    /* disk interior: w is +-N, not from the rounded points (a point 1e-9 above a tilted disk at
     * 1e4: P - Q has lost half of its digits, N has not) */
    double pd_far[] = {1e4 + 0.8 * 0.25 + 0.6e-9, 0, -0.6 * 0.25 + 0.8e-9, 1e4, 0, 0, 0.6, 0, 0.8, 1};
    CHECK(g_pd(q, pd_far, &r, &g) == CDIST_OK && fabs(g.obj[0].d_center.x - 0.6) < 4e-16 &&
              g.obj[0].d_center.y == 0.0 && fabs(g.obj[0].d_center.z - 0.8) < 4e-16,
          "disk interior far out: w = N (got %.17g %.17g %.17g)", g.obj[0].d_center.x, g.obj[0].d_center.y,
          g.obj[0].d_center.z);
    /* arc: angle fixed; d_start active when the closest point is the start, d_end then 0 */
    double ac[] = {0, 0, 0, 0, 0, 1, 1, 1, 0, 0, 0, M_PI / 2, 0.5, -2, 0, 0, 0, 1, 0.1};
    CHECK(g_ac(q, ac, &r, &g) == CDIST_OK && r.pairs[0].param[0] == 0.0 && g.obj[0].d_start != 0.0 &&
              g.obj[0].d_end == 0.0,
          "arc start closest: d_start %g, d_end %g", g.obj[0].d_start, g.obj[0].d_end);
    CHECK(check_line(find_kind("ac"), ac, 19, "clause arc start") == 1, "clause arc start: differences");
    /* swept objects: the core gradient plus d_radius_swept = -1 (overlapping spheres: the
     * signed distance is negative, the cores apart, differentiable) */
    double ss[] = {0, 0, 0, 1, 1.5, 0.2, 0, 1};
    CHECK(g_SS(q, ss, &r, &g) == CDIST_OK && r.distance < 0 && g.obj[0].d_radius_swept == -1.0 &&
              g.obj[1].d_radius_swept == -1.0 && !(g.flags & CDIST_GRAD_NOT_DIFFERENTIABLE),
          "swept: d_radius_swept = -1, overlap differentiable");
    CHECK(check_line(find_kind("SS"), ss, 8, "clause swept") == 1, "clause swept: differences");
    /* two closest pairs: flagged, the gradient of pairs[0] is a one-sided derivative */
    double lc2[] = {0, 0, 0.5, 1, 0, 0, 0, 0, 0, 0, 0, 1, 1};
    CHECK(g_lc(q, lc2, &r, &g) == CDIST_OK && r.num_pairs == 2, "line over a diameter: two pairs");
    check_one_sided("two pairs", find_kind("lc"), lc2, 13, 1);
    /* an equidistant result: flagged, the representative pair's gradient is a one-sided derivative */
    double pc_axis[] = {0, 0, 0.5, 0, 0, 0, 0, 0, 1, 1};
    CHECK(g_pc(q, pc_axis, &r, &g) == CDIST_OK && r.equidistant, "point on the axis: equidistant");
    check_one_sided("equidistant", find_kind("pc"), pc_axis, 10, 0);
    /* a segment of length 0 (p0 == p1): moving p0 alone along w leaves p1 at the closest point
     * (derivative 0), against w the closest point moves with it (-1): flagged, and the gradient
     * (of the pair's s) lies between the one-sided derivatives */
    double sc_pt[] = {0.3, 0.2, 0.5, 0.3, 0.2, 0.5, 0, 0, 0, 0, 0, 1, 1};
    CHECK(check_one_sided("segment of length 0", find_kind("sc"), sc_pt, 13, 0) > 0.5, "segment of length 0: a kink");
    double ks_pt[] = {1, 1, 1, 1, 1, 1, 0.1, 0, 0, 0, 0.2};
    CHECK(check_one_sided("capsule of length 0", find_kind("KS"), ks_pt, 11, 0) > 0.5, "capsule of length 0: a kink");
    double kk_pt[] = {3, 0.2, 0.5, 3, 0.2, 0.5, 0.1, 0, 0, 0, 0, 0, 1, 0.1};
    CHECK(check_one_sided("capsule of length 0 and a capsule", find_kind("KK"), kk_pt, 14, 0) > 0.5,
          "capsule of length 0 and a capsule: a kink");
    /* distance 0 without a neighbourhood: flagged, gradient 0 */
    double pd0[] = {0.2, 0.1, 0, 0, 0, 0, 0, 0, 1, 1};
    check_zero("point on a disk", find_kind("pd"), pd0, 10, 0, apply_add, 0, ez);
    double cc0[] = {0, 0, 0, 0, 0, 1, 1, 1, 0, 0, 0, 1, 0, 2}; /* meet at (-1, 0, 0) */
    check_zero("crossing circles", find_kind("cc"), cc0, 14, 0, apply_add, 7, ex);
    /* swept: the rule reads the core distance (crossing capsule axes: core 0, flagged) */
    double kk0[] = {-1, 0, 0, 1, 0, 0, 0.2, 0, -1, 0, 0, 1, 0, 0.3};
    check_zero("crossing capsule axes", find_kind("KK"), kk0, 14, 0, apply_add, 7, ez);
    /* distance 0 on a whole neighbourhood: not flagged, gradient exactly 0 (two-sided) --
     * a segment, line, ray, circle and arc crossing a disk's plane inside its rim, and two
     * disks in transversal planes meeting inside both rims, whatever their pair count or
     * equidistant flag */
    double sd[] = {0.2, 0.1, -1, 0.3, 0.1, 1, 0, 0, 0, 0, 0, 1, 1};
    check_zero("segment through a disk", find_kind("sd"), sd, 13, 1, NULL, 0, NULL);
    double ld[] = {0.2, 0.1, -1, 0.6, 0, 0.8, 0, 0, 0, 0, 0, 1, 1};
    check_zero("line through a disk", find_kind("ld"), ld, 13, 1, NULL, 0, NULL);
    double rd[] = {0.2, 0.1, -1, 0.6, 0, 0.8, 0, 0, 0, 0, 0, 1, 1};
    check_zero("ray through a disk", find_kind("rd"), rd, 13, 1, NULL, 0, NULL);
    double cd[] = {0.2, 0, 0, 0, 1, 0, 0.3, 0, 0, 0, 0, 0, 1, 1}; /* two crossings: two pairs */
    CHECK(g_cd(q, cd, &r, &g) == CDIST_OK && r.num_pairs == 2, "circle through a disk: two pairs");
    check_zero("circle through a disk", find_kind("cd"), cd, 14, 1, NULL, 0, NULL);
    double ad[] = {0.2, 0, 0, 0, 1, 0, 0.3, 1, 0, 0, -2, 2, 0, 0, 0, 0, 0, 1, 1};
    check_zero("arc through a disk", find_kind("ad"), ad, 19, 1, NULL, 0, NULL);
    double dd[] = {0, 0, 0, 0, 0, 1, 1, 0.1, 0, 0, 0, 1, 0, 0.3}; /* meet along a segment: equidistant */
    CHECK(g_dd(q, dd, &r, &g) == CDIST_OK && r.equidistant, "crossing disks: equidistant");
    check_zero("disks crossing inside both rims", find_kind("dd"), dd, 14, 1, NULL, 0, NULL);
    double dd_sw[] = {0.1, 0, 0, 0, 1, 0, 0.3, 0, 0, 0, 0, 0, 1, 1};
    check_zero("disks crossing inside both rims, swapped", find_kind("dd"), dd_sw, 14, 1, NULL, 0, NULL);
    /* ... but not: a segment ending on the disk, a disk touching another's rim, a curve in the
     * disk's plane, a circle crossing the plane outside the rim at a point of the rim */
    double sd_end[] = {0.2, 0.1, 0, 0.2, 0.1, 1, 0, 0, 0, 0, 0, 1, 1};
    check_zero("segment ending on a disk", find_kind("sd"), sd_end, 13, 0, apply_add, 0, ez);
    double dd_rim[] = {0, 0, 0, 0, 0, 1, 1, 1.3, 0, 0, 0, 1, 0, 0.3};
    check_zero("disk touching a rim", find_kind("dd"), dd_rim, 14, 0, apply_add, 7, ex);
    double sd_flat[] = {-0.5, 0.1, 0, 0.5, 0.1, 0, 0, 0, 0, 0, 0, 1, 1};
    check_zero("segment in the disk's plane", find_kind("sd"), sd_flat, 13, 0, apply_add, 6, ez);
    /* a circle or disk of radius 0: differentiated from the right (forward difference) */
    double pc_r0[] = {3, 0, 4, 0, 0, 0, 0, 0, 1, 0};
    CHECK(g_pc(q, pc_r0, &r, &g) == CDIST_OK, "radius 0: status");
    double w0[10];
    memcpy(w0, pc_r0, sizeof w0);
    w0[9] = 1e-7;
    double fwd = (dist_at(find_kind("pc"), w0) - dist_at(find_kind("pc"), pc_r0)) / 1e-7;
    CHECK(fabs(g.obj[1].d_radius - fwd) < 1e-6, "radius 0: d_radius %.17g, forward difference %.17g",
          g.obj[1].d_radius, fwd);
    double pd_r0[] = {3, 0, 4, 0, 0, 0, 0, 0, 1, 0};
    CHECK(g_pd(q, pd_r0, &r, &g) == CDIST_OK, "disk radius 0: status");
    fwd = (dist_at(find_kind("pd"), w0) - dist_at(find_kind("pd"), pd_r0)) / 1e-7;
    CHECK(fabs(g.obj[1].d_radius - fwd) < 1e-6, "disk radius 0: d_radius %.17g, forward difference %.17g",
          g.obj[1].d_radius, fwd);
}

static void check_errors(void)
{
    cdist_result r;
    cdist_grad g;
    cdist_vec3 p = tv(0, 0, 0);
    cdist_circle c = {tv(0, 0, 0), tv(0, 0, 2), 1};
    CHECK(cdist_point_circle_grad(q, &p, &c, &r, &g) == CDIST_ERR_NOT_UNIT && isnan(g.obj[1].d_radius) &&
              isnan(r.distance),
          "bad input: NaN gradient");
    c.normal = tv(0, 0, 1);
    p = tv(0, 0, 2); /* a valid query (distance sqrt 5): a NULL gradient must not leave its result */
    r.distance = 1.0;
    r.num_pairs = 1;
    CHECK(cdist_point_circle_grad(q, &p, &c, &r, NULL) == CDIST_ERR_NULL_ARGUMENT && isnan(r.distance) &&
              r.num_pairs == 0 && cdist_query_last_status(q) == CDIST_ERR_NULL_ARGUMENT,
          "NULL gradient: result %.17g with %d pairs, status %d", r.distance, r.num_pairs,
          (int)cdist_query_last_status(q));
    cdist_sphere s0 = {tv(0, 0, 0), 0.5}, s1 = {tv(3, 0, 0), 0.5};
    cdist_contact ct;
    ct.distance = 1.0;
    ct.num_pairs = 1;
    CHECK(cdist_sphere_sphere_grad(q, &s0, &s1, &ct, NULL) == CDIST_ERR_NULL_ARGUMENT && isnan(ct.distance) &&
              ct.num_pairs == 0 && cdist_query_last_status(q) == CDIST_ERR_NULL_ARGUMENT,
          "swept NULL gradient: contact %.17g with %d pairs", ct.distance, ct.num_pairs);
    CHECK(cdist_sphere_sphere_grad(q, &s0, &s1, NULL, &g) == CDIST_ERR_NULL_ARGUMENT && isnan(g.obj[0].d_center.x),
          "swept NULL contact");
    CHECK(cdist_sphere_sphere_grad(q, &s0, &s1, &ct, &g) == CDIST_OK && ct.distance == 2.0 &&
              g.obj[0].d_center.x == -1.0,
          "swept gradient after the errors: %.17g", ct.distance);
    p = tv(0, 0, 0);
    CHECK(cdist_point_circle_grad(q, &p, &c, NULL, &g) == CDIST_ERR_NULL_ARGUMENT, "NULL result");
    CHECK(cdist_point_circle_grad(NULL, &p, &c, &r, &g) == CDIST_ERR_NULL_ARGUMENT, "NULL handle");
    CHECK(cdist_grad_size() == sizeof(cdist_grad), "grad size");
    CHECK(cdist_grad_flag_not_differentiable() == CDIST_GRAD_NOT_DIFFERENTIABLE, "flag function");
    /* a circle of radius 0 is differentiated from the right */
    cdist_vec3 p2 = tv(3, 0, 4);
    cdist_circle c0 = {tv(0, 0, 0), tv(0, 0, 1), 0};
    CHECK(cdist_point_circle_grad(q, &p2, &c0, &r, &g) == CDIST_OK && fabs(g.obj[1].d_radius + 0.6) < 1e-15,
          "radius 0: right derivative -0.6 (got %.17g)", g.obj[1].d_radius);
    /* an arc of radius 0 (the query's angle is NaN): finite, flagged one-sided gradient; the
     * radius derivative against a forward difference of the distance query */
    cdist_circle cy = {tv(0, 0, 4), tv(1, 0, 0), 1}; /* closest point (0, 0, 3) from the origin */
    const double spans[][2] = {{0, 2 * M_PI}, {0, M_PI / 4}, {M_PI, 1.5 * M_PI}, {-3, -1}};
    for (int k = 0; k < 4; k++) {
        cdist_arc a0 = {{tv(0, 0, 0), tv(1, 0, 0), 0}, tv(0, 1, 0), spans[k][0], spans[k][1]};
        CHECK(cdist_arc_circle_grad(q, &a0, &cy, &r, &g) == CDIST_OK, "arc radius 0: status");
        const cdist_grad_object *o = &g.obj[0];
        int finite = isfinite(o->d_radius) && isfinite(o->d_start) && isfinite(o->d_end) &&
                     isfinite(o->d_center.x + o->d_center.y + o->d_center.z) &&
                     isfinite(o->d_normal.x + o->d_normal.y + o->d_normal.z) &&
                     isfinite(o->d_zero_direction.x + o->d_zero_direction.y + o->d_zero_direction.z);
        CHECK(finite && (g.flags & CDIST_GRAD_NOT_DIFFERENTIABLE), "arc radius 0 span %d: finite, flagged", k);
        CHECK(fabs(o->d_center.z + 1) < 1e-15, "arc radius 0: d_center (%g %g %g)", o->d_center.x, o->d_center.y,
              o->d_center.z);
        cdist_result r0, r1;
        const double h = 1e-7;
        cdist_arc ah = a0;
        ah.circle.radius = h;
        CHECK(cdist_arc_circle(q, &a0, &cy, &r0) == CDIST_OK && cdist_arc_circle(q, &ah, &cy, &r1) == CDIST_OK,
              "arc radius 0: distances");
        double fd = (r1.distance - r0.distance) / h;
        CHECK(fabs(o->d_radius - fd) < 1e-6, "arc radius 0 span %d: d_radius %.17g vs forward difference %.17g", k,
              o->d_radius, fd);
    }
}

/* Random configurations of every kind (arcs with random spans: many closest points at an end;
 * swept objects often overlapping). */
static void run_random(void)
{
    for (size_t ki = 0; ki < sizeof gkinds / sizeof gkinds[0]; ki++) {
        const gkind *k = &gkinds[ki];
        int bad = 0, total = 0, endpoint = 0;
        for (int i = 0; i < 150; i++) {
            double v[CDQ_MAX_VALUES] = {0};
            int n = 0;
            for (const field *f = k->f; f->type != F_END; f++) {
                int w = 1;
                switch (f->type) {
                case F_RADIUS: v[f->offset] = 0.1 + urand(); break;
                case F_RSWEPT: v[f->offset] = 0.05 + 0.3 * urand(); break;
                case F_START: v[f->offset] = -M_PI + 2 * M_PI * urand(); break;
                case F_ENDANG: v[f->offset] = v[f->offset - 1] + 0.2 + 5.8 * urand(); break;
                default: {
                    w = 3;
                    int unit = f->type == F_NORMAL || f->type == F_DIR || f->type == F_ZERO;
                    cdist_vec3 u = unit ? rand_unit() : tv(1.5 * srand1(), 1.5 * srand1(), 1.5 * srand1());
                    v[f->offset] = u.x, v[f->offset + 1] = u.y, v[f->offset + 2] = u.z;
                }
                }
                if (f->offset + w > n) n = f->offset + w;
            }
            char where[64];
            snprintf(where, sizeof where, "random %d (%s)", i, k->name);
            cdist_result r;
            cdist_grad g;
            if (k->fn(q, v, &r, &g) == CDIST_OK)
                for (int o = 0; o < 2; o++) endpoint += g.obj[o].d_start != 0 || g.obj[o].d_end != 0;
            total++;
            if (check_line(k, v, n, where) != 1) {
                bad++;
                fprintf(stderr, "%s: disagrees or unresolved\n", where);
            }
        }
        CHECK(bad == 0, "random %s: %d of %d disagree", k->name, bad, total);
        if (k->name[0] == 'a' || k->name[1] == 'a')
            CHECK(endpoint > 10, "random %s: arc end points closest in %d cases", k->name, endpoint);
        printf("random %-3s: %d, %d disagree%s\n", k->name, total, bad, endpoint ? " (arc ends active: some)" : "");
    }
}

/* ---- point-circle / point-disk in quadruple precision ----
 * The near-degenerate reference lines (a point a few ulps from the axis, the face or the rim)
 * are differentiable but only on a neighbourhood far below double resolution. There the
 * distance is evaluated in closed form in __float128 (an independent formula, not the
 * library) at inputs perturbed below double resolution, with a step 1/100 of the distance to
 * the nearest non-differentiable set (axis, rim, face). The closest pair itself is
 * ill-conditioned there (its angle moves by O(1) under input perturbations of relative size
 * eps * L / kink), so the allowance is 1e-7 plus that condition number times 64 eps; away
 * from those sets (every random line) it is 1e-7. */
#if defined(__SIZEOF_FLOAT128__)
typedef __float128 qf;
static qf q_sqrt(qf x)
{
    if (x <= 0) return 0;
    qf y = sqrt((double)x);
    for (int i = 0; i < 3; i++) y = (y + x / y) / 2;
    return y;
}
/* numbers: P(3) C(3) N(3) r */
static qf q_dist(const qf *v, int disk, qf *kink)
{
    qf n[3] = {v[6], v[7], v[8]}, nn = q_sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int i = 0; i < 3; i++) n[i] /= nn;
    qf d[3] = {v[0] - v[3], v[1] - v[4], v[2] - v[5]};
    qf h = n[0] * d[0] + n[1] * d[1] + n[2] * d[2];
    qf c[3] = {n[1] * d[2] - n[2] * d[1], n[2] * d[0] - n[0] * d[2], n[0] * d[1] - n[1] * d[0]};
    qf rho = q_sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]), r = v[9];
    if (kink) {
        qf k = rho, a = rho - r < 0 ? r - rho : rho - r, b = h < 0 ? -h : h;
        if (disk && a < k) k = a;
        if (disk && b < k) k = b;
        *kink = k;
    }
    if (disk && rho <= r) return h < 0 ? -h : h;
    return q_sqrt((rho - r) * (rho - r) + h * h);
}

static void quad_check(const char *dir, const char *file, int disk)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", dir, file);
    FILE *f = fopen(path, "r");
    CHECK(f != NULL, "cannot open %s", path);
    if (!f) return;
    char line[4096];
    int lineno = 0, bad = 0, total = 0, loose = 0;
    const gkind *k = find_kind(disk ? "pd" : "pc");
    while (fgets(line, sizeof line, f)) {
        lineno++;
        cdq_line ql;
        char err[256];
        if (cdq_parse(line, &ql, err, sizeof err) != 1) continue;
        cdist_result r;
        cdist_grad g;
        if (k->fn(q, ql.v, &r, &g) != CDIST_OK || (g.flags & CDIST_GRAD_NOT_DIFFERENTIABLE)) continue;
        qf v[10], kink, L = 0;
        for (int i = 0; i < 10; i++) {
            v[i] = ql.v[i];
            if (fabs(ql.v[i]) > L) L = fabs(ql.v[i]);
        }
        q_dist(v, disk, &kink);
        qf step = kink / 100 < L * (qf)1e-20 ? kink / 100 : L * (qf)1e-20;
        double cond = 64 * DBL_EPSILON * (double)(L / kink);
        if (!(cond < 1e300)) cond = 1e300;
        int ok = 1, strict = 1;
        total++;
        /* positions and radius: plain coordinates */
        for (int i = 0; i < 10; i++) {
            if (i >= 6 && i < 9) continue;
            double an = i < 3 ? (&g.obj[0].d_center.x)[i] : (i < 6 ? (&g.obj[1].d_center.x)[i - 3] : g.obj[1].d_radius);
            qf w[10];
            memcpy(w, v, sizeof w);
            w[i] = v[i] + step;
            qf fp = q_dist(w, disk, NULL);
            w[i] = v[i] - step;
            qf fm = q_dist(w, disk, NULL);
            double fd = (double)((fp - fm) / (2 * step));
            if (!(fabs(fd - an) <= 1e-7 * fmax(1.0, fabs(an)))) strict = 0;
            if (!(fabs(fd - an) <= (1e-7 + cond) * fmax(1.0, fabs(an)))) {
                ok = 0;
                if (bad < 5) fprintf(stderr, "%s:%d number %d: grad %.17g, quad differences %.17g\n", file, lineno, i, an, fd);
            }
        }
        /* the normal along two tangent directions */
        cdist_vec3 nu = tv(ql.v[6], ql.v[7], ql.v[8]), a, b;
        cdist_circle tmp = {tv(0, 0, 0), nu, 1};
        cdist_query_set_unit_tolerance(q, INFINITY);
        cdist_circle_basis(&tmp, &a, &b);
        cdist_query_set_unit_tolerance(q, 1e-6);
        cdist_vec3 dirs[2] = {a, b};
        qf nstep = step / L;
        for (int t = 0; t < 2; t++) {
            double an = g.obj[1].d_normal.x * dirs[t].x + g.obj[1].d_normal.y * dirs[t].y + g.obj[1].d_normal.z * dirs[t].z;
            qf fpm[2];
            for (int sgn = 0; sgn < 2; sgn++) {
                qf w[10];
                memcpy(w, v, sizeof w);
                qf e = sgn ? -nstep : nstep;
                qf nn = q_sqrt(v[6] * v[6] + v[7] * v[7] + v[8] * v[8]);
                w[6] = v[6] / nn + e * dirs[t].x;
                w[7] = v[7] / nn + e * dirs[t].y;
                w[8] = v[8] / nn + e * dirs[t].z;
                fpm[sgn] = q_dist(w, disk, NULL); /* q_dist normalises */
            }
            double fd = (double)((fpm[0] - fpm[1]) / (2 * nstep));
            double gn = sqrt(g.obj[1].d_normal.x * g.obj[1].d_normal.x + g.obj[1].d_normal.y * g.obj[1].d_normal.y +
                             g.obj[1].d_normal.z * g.obj[1].d_normal.z);
            if (!(fabs(fd - an) <= 1e-7 * fmax(gn, (double)L))) strict = 0;
            if (!(fabs(fd - an) <= (1e-7 + cond) * fmax(gn, (double)L))) {
                ok = 0;
                if (bad < 5) fprintf(stderr, "%s:%d normal %d: grad %.17g, quad differences %.17g\n", file, lineno, t, an, fd);
            }
        }
        if (!ok) bad++;
        if (ok && !strict) loose++;
    }
    fclose(f);
    CHECK(loose == 0 || strstr(file, "_hard"), "%s: conditioning allowance used off the hard set", file);
    CHECK(bad == 0, "%s (quad precision): %d of %d lines disagree", file, bad, total);
    printf("%-16s quad-precision differences: %d lines, %d disagree (%d within 1e-7 only by the pair's conditioning)\n",
           file, total, bad, loose);
}

/* ---- circle-circle and line-circle in quadruple precision ----
 * D = min over the angle phi of the first circle (cc) / of the circle (lc) of the closed-form
 * distance from that circle point to the other object, minimised by golden section in
 * __float128 on a bracket around the library's closest point (independent of the library's
 * algorithm). Step 1e-22 of the scale. Allowance: 1e-7 plus the library gradient's own spread
 * under input perturbations of a few ulps (an empirical condition number of the closest pair). */
typedef struct { qf c[3], n[3], u[3], v[3], r; } qcirc;
static void q_circ(const qf *x, qcirc *o)
{
    qf nn = q_sqrt(x[3] * x[3] + x[4] * x[4] + x[5] * x[5]);
    for (int i = 0; i < 3; i++) o->c[i] = x[i], o->n[i] = x[3 + i] / nn;
    o->r = x[6];
    qf e[3] = {0, 0, 0};
    double an[3] = {fabs((double)o->n[0]), fabs((double)o->n[1]), fabs((double)o->n[2])};
    e[an[0] < 0.6 ? 0 : (an[1] < 0.6 ? 1 : 2)] = 1;
    qf d = e[0] * o->n[0] + e[1] * o->n[1] + e[2] * o->n[2];
    qf u[3] = {e[0] - d * o->n[0], e[1] - d * o->n[1], e[2] - d * o->n[2]};
    qf un = q_sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    for (int i = 0; i < 3; i++) o->u[i] = u[i] / un;
    o->v[0] = o->n[1] * o->u[2] - o->n[2] * o->u[1];
    o->v[1] = o->n[2] * o->u[0] - o->n[0] * o->u[2];
    o->v[2] = o->n[0] * o->u[1] - o->n[1] * o->u[0];
}
static qf q_cos(qf x) /* Taylor after reduction to |x| <= pi/4 is enough: |x| < 8 here */
{
    qf x2 = x * x, t = 1, s = 1;
    for (int k = 1; k < 40; k++) { t *= -x2 / ((2 * k - 1) * (2 * k)); s += t; }
    return s;
}
static qf q_sin(qf x)
{
    qf x2 = x * x, t = x, s = x;
    for (int k = 1; k < 40; k++) { t *= -x2 / ((2 * k) * (2 * k + 1)); s += t; }
    return s;
}
static void q_circle_point(const qcirc *c, qf phi, qf *p)
{
    qf co = q_cos(phi), si = q_sin(phi);
    for (int i = 0; i < 3; i++) p[i] = c->c[i] + c->r * (co * c->u[i] + si * c->v[i]);
}
static qf q_point_circle(const qf *p, const qcirc *c)
{
    qf d[3] = {p[0] - c->c[0], p[1] - c->c[1], p[2] - c->c[2]};
    qf h = c->n[0] * d[0] + c->n[1] * d[1] + c->n[2] * d[2];
    qf x[3] = {c->n[1] * d[2] - c->n[2] * d[1], c->n[2] * d[0] - c->n[0] * d[2], c->n[0] * d[1] - c->n[1] * d[0]};
    qf rho = q_sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    return q_sqrt((rho - c->r) * (rho - c->r) + h * h);
}
static qf q_point_line(const qf *p, const qf *o, const qf *dir)
{
    qf dd = dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2];
    qf w[3] = {p[0] - o[0], p[1] - o[1], p[2] - o[2]};
    qf t = (w[0] * dir[0] + w[1] * dir[1] + w[2] * dir[2]) / dd;
    qf e[3] = {w[0] - t * dir[0], w[1] - t * dir[1], w[2] - t * dir[2]};
    return q_sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
}
/* numbers as in the tool line (cc: circle circle; lc: line circle). */
static qf q_eval(int lc, const qf *x, qf phi)
{
    qcirc a;
    qf p[3];
    if (lc) {
        q_circ(x + 6, &a);
        q_circle_point(&a, phi, p);
        return q_point_line(p, x, x + 3);
    }
    qcirc b;
    q_circ(x, &a);
    q_circ(x + 7, &b);
    q_circle_point(&a, phi, p);
    return q_point_circle(p, &b);
}
static qf q_min_arg(int lc, const qf *x, double phi0, int *at_edge, qf *arg);
static qf q_min(int lc, const qf *x, double phi0, int *at_edge) { return q_min_arg(lc, x, phi0, at_edge, NULL); }
static qf q_min_arg(int lc, const qf *x, double phi0, int *at_edge, qf *arg)
{
    const qf gr = (q_sqrt(5) - 1) / 2;
    qf lo = phi0 - 0.05, hi = phi0 + 0.05;
    qf a = hi - gr * (hi - lo), b = lo + gr * (hi - lo);
    qf fa = q_eval(lc, x, a), fb = q_eval(lc, x, b);
    for (int it = 0; it < 120; it++) {
        if (fa < fb) { hi = b; b = a; fb = fa; a = hi - gr * (hi - lo); fa = q_eval(lc, x, a); }
        else { lo = a; a = b; fa = fb; b = lo + gr * (hi - lo); fb = q_eval(lc, x, b); }
    }
    qf m = (lo + hi) / 2;
    if (arg) *arg = m;
    *at_edge = (double)(m - (phi0 - 0.05)) < 1e-3 || (double)((phi0 + 0.05) - m) < 1e-3;
    return fa < fb ? fa : fb;
}

static void quad_check_curve(const char *dir, const char *file, int lc)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", dir, file);
    FILE *f = fopen(path, "r");
    CHECK(f != NULL, "cannot open %s", path);
    if (!f) return;
    char line[4096];
    int lineno = 0, bad = 0, total = 0, skipped = 0;
    const gkind *k = find_kind(lc ? "lc" : "cc");
    int nv = lc ? 13 : 14;
    while (fgets(line, sizeof line, f)) {
        lineno++;
        cdq_line ql;
        char err[256];
        if (cdq_parse(line, &ql, err, sizeof err) != 1) continue;
        cdist_result r;
        cdist_grad g;
        if (k->fn(q, ql.v, &r, &g) != CDIST_OK || (g.flags & CDIST_GRAD_NOT_DIFFERENTIABLE)) continue;
        qf x[14];
        double L = 0;
        for (int i = 0; i < nv; i++) x[i] = ql.v[i], L = fmax(L, fabs(ql.v[i]));
        /* the library's closest point on the parametrised circle, as an angle in our frame */
        qcirc a;
        q_circ(lc ? x + 6 : x, &a);
        cdist_vec3 P = r.pairs[0].point[lc ? 1 : 0];
        double rel[3] = {P.x - (double)a.c[0], P.y - (double)a.c[1], P.z - (double)a.c[2]};
        double cu = rel[0] * (double)a.u[0] + rel[1] * (double)a.u[1] + rel[2] * (double)a.u[2];
        double cv = rel[0] * (double)a.v[0] + rel[1] * (double)a.v[1] + rel[2] * (double)a.v[2];
        double phi0 = atan2(cv, cu);
        int edge = 0;
        qf phiq;
        qf d0 = q_min_arg(lc, x, phi0, &edge, &phiq);
        /* the library's pair is as good as double allows: at its angle the distance is within
         * rounding of the minimum */
        qf dlib = q_eval(lc, x, phi0);
        CHECK((double)(dlib - d0) <= 64 * DBL_EPSILON * fmax(L, 1), "%s:%d: the library's closest point is %.3g above the minimum",
              file, lineno, (double)(dlib - d0));
        if (edge || fabs((double)d0 - r.distance) > 1e-12 * fmax(L, 1)) { skipped++; continue; }
        /* empirical conditioning: the library gradient under a few-ulp input perturbations */
        double spread[14] = {0};
        for (int t = 0; t < 4; t++) {
            double w[14];
            for (int i = 0; i < nv; i++) w[i] = ql.v[i] * (1 + 4 * DBL_EPSILON * srand1());
            cdist_result r2;
            cdist_grad g2;
            if (k->fn(q, w, &r2, &g2) != CDIST_OK) continue;
            for (const field *fl = k->f; fl->type != F_END; fl++) {
                int wdt = fl->type == F_RADIUS ? 1 : 3;
                for (int c = 0; c < wdt; c++) {
                    double e[3] = {0};
                    e[c] = 1;
                    if (fl->type == F_NORMAL || fl->type == F_DIR) e[0] = e[1] = e[2] = 1;
                    double d1 = analytic(k, ql.v, fl->type, fl->obj, e), d2 = analytic(k, w, fl->type, fl->obj, e);
                    if (fabs(d1 - d2) > spread[fl->offset + c]) spread[fl->offset + c] = fabs(d1 - d2);
                }
            }
        }
        qf step = (qf)L * (qf)1e-22;
        int ok = 1;
        total++;
        for (const field *fl = k->f; fl->type != F_END; fl++) {
            int tangent = fl->type == F_NORMAL || fl->type == F_DIR;
            int cnt = fl->type == F_RADIUS ? 1 : (tangent ? 2 : 3);
            double sp = 0;
            for (int c = 0; c < (fl->type == F_RADIUS ? 1 : 3); c++) sp = fmax(sp, spread[fl->offset + c]);
            cdist_vec3 ta = tv(0, 0, 0), tb = ta;
            if (tangent) {
                cdist_circle tmp = {tv(0, 0, 0), tv(ql.v[fl->offset], ql.v[fl->offset + 1], ql.v[fl->offset + 2]), 1};
                cdist_query_set_unit_tolerance(q, INFINITY);
                cdist_circle_basis(&tmp, &ta, &tb);
                cdist_query_set_unit_tolerance(q, 1e-6);
            }
            for (int c = 0; c < cnt; c++) {
                double e[3] = {0};
                if (tangent) {
                    cdist_vec3 t = c ? tb : ta;
                    e[0] = t.x, e[1] = t.y, e[2] = t.z;
                } else if (fl->type != F_RADIUS) e[c] = 1;
                double an = analytic(k, ql.v, fl->type, fl->obj, e);
                qf fpm[2], fix[2][2];
                for (int sg = 0; sg < 2; sg++) {
                    qf w[14];
                    memcpy(w, x, sizeof w);
                    qf hs = sg ? -step : step;
                    if (tangent) {
                        hs /= (qf)L;
                        qf nn = q_sqrt(x[fl->offset] * x[fl->offset] + x[fl->offset + 1] * x[fl->offset + 1] +
                                       x[fl->offset + 2] * x[fl->offset + 2]);
                        for (int i = 0; i < 3; i++) w[fl->offset + i] = x[fl->offset + i] / nn + hs * e[i];
                    } else if (fl->type == F_RADIUS) {
                        w[fl->offset] += hs;
                    } else {
                        w[fl->offset + c] += hs;
                    }
                    int ed;
                    fpm[sg] = q_min(lc, w, phi0, &ed);
                    /* partial derivatives at fixed angle: at the library's and the exact one */
                    fix[0][sg] = q_eval(lc, w, phi0);
                    fix[1][sg] = q_eval(lc, w, phiq);
                }
                qf h = tangent ? step / (qf)L : step;
                double fd = (double)((fpm[0] - fpm[1]) / (2 * h));
                /* where the minimum is flat the angle is only determined to double's rounding of
                 * the distance; the gradient moves with it by the mixed derivative */
                double flat = fabs((double)((fix[0][0] - fix[0][1]) / (2 * h) - (fix[1][0] - fix[1][1]) / (2 * h)));
                double scale = tangent ? fmax(L, 1.0) : 1.0;
                if (!(fabs(fd - an) <= 1e-7 * fmax(scale, fabs(an)) + 4 * sp + 2 * flat)) {
                    ok = 0;
                    if (bad < 5)
                        fprintf(stderr, "%s:%d field %d/%d: grad %.17g, quad differences %.17g (spread %.3g, flat %.3g)\n",
                                file, lineno, fl->offset, c, an, fd, sp, flat);
                }
            }
        }
        if (!ok) bad++;
    }
    fclose(f);
    CHECK(bad == 0, "%s (quad precision): %d of %d lines disagree", file, bad, total);
    CHECK(skipped * 10 <= total, "%s: too many lines skipped (%d)", file, skipped);
    printf("%-16s quad-precision differences (%s): %d lines, %d disagree, %d skipped (bracket)\n", file,
           lc ? "lc" : "cc", total, bad, skipped);
}
#endif

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : "tests/data";
    q = cdist_query_new();
    static const char *files[][2] = {
        {"pc_random.txt", "pc"}, {"pc_hard.txt", "pc"}, {"pd_random.txt", "pd"}, {"pd_hard.txt", "pd"},
        {"lc_random.txt", "lc"}, {"lc_hard.txt", "lc"}, {"lc_random.txt", "rc"}, {"lc_random.txt", "sc"},
        {"ld_random.txt", "ld"}, {"ld_hard.txt", "ld"}, {"ld_random.txt", "rd"}, {"ld_random.txt", "sd"},
        {"cc_random.txt", "cc"}, {"cc_hard.txt", "cc"}, {"cd_random.txt", "cd"}, {"cd_hard.txt", "cd"},
        {"cd_random.txt", "dd"}, {"cd_hard.txt", "dd"},
    };
    for (size_t i = 0; i < sizeof files / sizeof files[0]; i++) run_file(dir, files[i][0], files[i][1]);
    run_random();
#if defined(__SIZEOF_FLOAT128__)
    quad_check(dir, "pc_hard.txt", 0);
    quad_check(dir, "pd_hard.txt", 1);
    quad_check(dir, "pc_random.txt", 0);
    quad_check(dir, "pd_random.txt", 1);
    quad_check_curve(dir, "cc_hard.txt", 0);
    quad_check_curve(dir, "lc_hard.txt", 1);
#else
    printf("no __float128: quad-precision checks skipped\n");
#endif
    check_kinks();
    check_clauses();
    check_errors();
    printf("checked %d differentiable queries, %d flagged\n", n_checked, n_flagged);
    cdist_query_free(q);
    return check_summary("grad");
}
