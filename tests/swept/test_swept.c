/* SPDX-License-Identifier: MIT */
/* Swept objects (torus, capsule, sphere, rounded disk) against
 *  (1) the core query minus the radii (exact identity, bit for bit), plus the witness points
 *      and normals built from the core pairs;
 *  (2) an independent brute force: the core distance minimised over samples of the first core
 *      (closed-form long double distance to the second core, local pattern-search polish),
 *      minus the radii, for overlapping and separated configurations;
 *  (3) for separated configurations, the same minimum over the sampled first solid (core point
 *      plus a ball direction) of the distance to the second solid;
 *  (4) continuity of the signed distance through contact (a sweep of a translation);
 *  (5) the documented touch normal, errors and sizes. */
#include <float.h>
#include <math.h>
#include <string.h>

#include "check.h"

enum { K_SPHERE, K_CAPSULE, K_TORUS, K_RDISK, K_CIRCLE, K_DISK, K_LINE, K_RAY, K_SEGMENT };
static const char *kname[] = {"sphere", "capsule", "torus", "rounded_disk", "circle", "disk", "line", "ray", "segment"};

typedef struct tobj {
    int kind;
    cdist_vec3 p;      /* sphere centre */
    cdist_segment s;   /* capsule, segment */
    cdist_circle c;    /* torus, rounded disk, circle, disk */
    cdist_line l;      /* line, ray */
    double radius;     /* swept radius (0 for plain objects) */
} tobj;

/* ---- independent references (long double) ---- */

typedef long double ld;
typedef struct { ld x, y, z; } lv;
static lv lvv(cdist_vec3 a) { lv r = {a.x, a.y, a.z}; return r; }
static lv ladd(lv a, lv b) { lv r = {a.x + b.x, a.y + b.y, a.z + b.z}; return r; }
static lv lsub(lv a, lv b) { lv r = {a.x - b.x, a.y - b.y, a.z - b.z}; return r; }
static lv lsc(ld s, lv a) { lv r = {s * a.x, s * a.y, s * a.z}; return r; }
static ld ldot(lv a, lv b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static lv lcross(lv a, lv b) { lv r = {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; return r; }
static ld lnorm(lv a) { return sqrtl(ldot(a, a)); }
static lv lunit(lv a) { return lsc(1.0L / lnorm(a), a); }

/* An orthonormal frame of a circle (any frame: the references never use the library's). */
static void lframe(cdist_circle c, lv *n, lv *u, lv *v)
{
    *n = lunit(lvv(c.normal));
    lv e = fabsl(n->x) < 0.6L ? (lv){1, 0, 0} : (lv){0, 1, 0};
    *u = lunit(lsub(e, lsc(ldot(e, *n), *n)));
    *v = lcross(*n, *u);
}

/* Distance from point x to the core of o. */
static ld core_dist(lv x, const tobj *o)
{
    switch (o->kind) {
    case K_SPHERE: return lnorm(lsub(x, lvv(o->p)));
    case K_CAPSULE:
    case K_SEGMENT:
    case K_LINE:
    case K_RAY: {
        lv a, d;
        ld lo = 0, hi = 1;
        if (o->kind == K_CAPSULE || o->kind == K_SEGMENT) {
            a = lvv(o->s.p0);
            d = lsub(lvv(o->s.p1), a);
        } else {
            a = lvv(o->l.origin);
            d = lvv(o->l.direction);
            lo = o->kind == K_LINE ? -INFINITY : 0;
            hi = INFINITY;
        }
        ld dd = ldot(d, d), t = dd > 0 ? ldot(lsub(x, a), d) / dd : 0;
        if (t < lo) t = lo;
        if (t > hi) t = hi;
        return lnorm(lsub(x, ladd(a, lsc(t, d))));
    }
    default: {
        lv n, u, v;
        lframe(o->c, &n, &u, &v);
        lv rel = lsub(x, lvv(o->c.center));
        ld h = ldot(rel, n), rho = lnorm(lcross(n, rel)), r = o->c.radius;
        if ((o->kind == K_RDISK || o->kind == K_DISK) && rho <= r) return fabsl(h);
        return sqrtl((rho - r) * (rho - r) + h * h);
    }
    }
}

/* Core point of o at parameters t[] (dims: 0 point, 1 curve, 2 disk); per dim periodic or clamped. */
static int core_dims(const tobj *o)
{
    switch (o->kind) {
    case K_SPHERE: return 0;
    case K_RDISK:
    case K_DISK: return 2;
    default: return 1;
    }
}
static int core_periodic(const tobj *o, int k) { return (o->kind == K_TORUS || o->kind == K_CIRCLE) || ((o->kind == K_RDISK || o->kind == K_DISK) && k == 1); }
static ld line_span = 10;
static lv core_point(const tobj *o, const ld *t)
{
    switch (o->kind) {
    case K_SPHERE: return lvv(o->p);
    case K_CAPSULE:
    case K_SEGMENT: return ladd(lvv(o->s.p0), lsc(t[0], lsub(lvv(o->s.p1), lvv(o->s.p0))));
    case K_LINE: return ladd(lvv(o->l.origin), lsc((2 * t[0] - 1) * line_span, lvv(o->l.direction)));
    case K_RAY: return ladd(lvv(o->l.origin), lsc(t[0] * line_span, lvv(o->l.direction)));
    default: {
        lv n, u, v;
        lframe(o->c, &n, &u, &v);
        ld rr = o->c.radius, ang = 2 * M_PI * t[0];
        if (o->kind == K_RDISK || o->kind == K_DISK) rr *= t[0], ang = 2 * M_PI * t[1];
        return ladd(lvv(o->c.center), ladd(lsc(rr * cosl(ang), u), lsc(rr * sinl(ang), v)));
    }
    }
}

/* f over the box: dims of the first core (+2 for a ball direction when ball > 0). */
typedef struct bf {
    const tobj *a, *b;
    int with_ball;
} bf;
static int bf_dims(const bf *f) { return core_dims(f->a) + (f->with_ball ? 2 : 0); }
static int bf_periodic(const bf *f, int k)
{
    int cd = core_dims(f->a);
    return k < cd ? core_periodic(f->a, k) : 1;
}
static ld bf_eval(const bf *f, const ld *t)
{
    ld tt[4] = {0, 0, 0, 0};
    int d = bf_dims(f);
    for (int k = 0; k < d; k++) {
        tt[k] = t[k];
        if (!bf_periodic(f, k)) tt[k] = tt[k] < 0 ? 0 : (tt[k] > 1 ? 1 : tt[k]);
    }
    lv x = core_point(f->a, tt);
    if (f->with_ball) {
        int cd = core_dims(f->a);
        ld th = M_PI * tt[cd], ph = 2 * M_PI * tt[cd + 1];
        lv s = {sinl(th) * cosl(ph), sinl(th) * sinl(ph), cosl(th)};
        x = ladd(x, lsc(f->a->radius, s));
    }
    return core_dist(x, f->b);
}

/* Grid samples, then Hooke-Jeeves from the best few. */
static ld brute_min(const bf *f, int per_dim)
{
    int d = bf_dims(f);
    if (d == 0) return bf_eval(f, NULL);
    enum { KEEP = 6 };
    ld best[KEEP][5];
    for (int i = 0; i < KEEP; i++) best[i][4] = INFINITY;
    long total = 1;
    for (int k = 0; k < d; k++) total *= per_dim;
    for (long i = 0; i < total; i++) {
        ld t[4];
        long j = i;
        for (int k = 0; k < d; k++) {
            t[k] = (ld)(j % per_dim) / (per_dim - (bf_periodic(f, k) ? 0 : 1));
            j /= per_dim;
        }
        ld v = bf_eval(f, t);
        if (v < best[KEEP - 1][4]) {
            int m = KEEP - 1;
            while (m > 0 && best[m - 1][4] > v) {
                memcpy(best[m], best[m - 1], sizeof best[m]);
                m--;
            }
            for (int k = 0; k < d; k++) best[m][k] = t[k];
            best[m][4] = v;
        }
    }
    ld result = INFINITY;
    for (int i = 0; i < KEEP; i++) {
        if (!isfinite(best[i][4])) continue;
        ld t[4], v = best[i][4];
        for (int k = 0; k < d; k++) t[k] = best[i][k];
        for (ld step = 2.0L / per_dim; step > 1e-17L;) {
            int moved = 0;
            for (int k = 0; k < d; k++) {
                for (int sgn = -1; sgn <= 1; sgn += 2) {
                    ld save = t[k];
                    t[k] += sgn * step;
                    if (!bf_periodic(f, k)) t[k] = t[k] < 0 ? 0 : (t[k] > 1 ? 1 : t[k]);
                    ld w = bf_eval(f, t);
                    if (w < v) { v = w; moved = 1; } else t[k] = save;
                }
            }
            if (!moved) step *= 0.5L;
        }
        if (v < result) result = v;
    }
    return result;
}

/* ---- the library calls ---- */

static cdist_torus as_torus(const tobj *o) { cdist_torus t = {o->c, o->radius}; return t; }
static cdist_capsule as_capsule(const tobj *o) { cdist_capsule t = {o->s, o->radius}; return t; }
static cdist_sphere as_sphere(const tobj *o) { cdist_sphere t = {o->p, o->radius}; return t; }
static cdist_rounded_disk as_rdisk(const tobj *o) { cdist_rounded_disk t = {o->c, o->radius}; return t; }
static cdist_ray as_ray(const tobj *o) { cdist_ray r = {o->l.origin, o->l.direction}; return r; }

#define PK(a, b) ((a) * 16 + (b))
static cdist_status contact(cdist_query *q, const tobj *a, const tobj *b, cdist_contact *c)
{
    switch (PK(a->kind, b->kind)) {
    case PK(K_TORUS, K_TORUS): { cdist_torus x = as_torus(a), y = as_torus(b); return cdist_torus_torus(q, &x, &y, c); }
    case PK(K_TORUS, K_CAPSULE): { cdist_torus x = as_torus(a); cdist_capsule y = as_capsule(b); return cdist_torus_capsule(q, &x, &y, c); }
    case PK(K_TORUS, K_SPHERE): { cdist_torus x = as_torus(a); cdist_sphere y = as_sphere(b); return cdist_torus_sphere(q, &x, &y, c); }
    case PK(K_TORUS, K_RDISK): { cdist_torus x = as_torus(a); cdist_rounded_disk y = as_rdisk(b); return cdist_torus_rounded_disk(q, &x, &y, c); }
    case PK(K_CAPSULE, K_CAPSULE): { cdist_capsule x = as_capsule(a), y = as_capsule(b); return cdist_capsule_capsule(q, &x, &y, c); }
    case PK(K_CAPSULE, K_SPHERE): { cdist_capsule x = as_capsule(a); cdist_sphere y = as_sphere(b); return cdist_capsule_sphere(q, &x, &y, c); }
    case PK(K_CAPSULE, K_RDISK): { cdist_capsule x = as_capsule(a); cdist_rounded_disk y = as_rdisk(b); return cdist_capsule_rounded_disk(q, &x, &y, c); }
    case PK(K_SPHERE, K_SPHERE): { cdist_sphere x = as_sphere(a), y = as_sphere(b); return cdist_sphere_sphere(q, &x, &y, c); }
    case PK(K_SPHERE, K_RDISK): { cdist_sphere x = as_sphere(a); cdist_rounded_disk y = as_rdisk(b); return cdist_sphere_rounded_disk(q, &x, &y, c); }
    case PK(K_RDISK, K_RDISK): { cdist_rounded_disk x = as_rdisk(a), y = as_rdisk(b); return cdist_rounded_disk_rounded_disk(q, &x, &y, c); }
    case PK(K_TORUS, K_LINE): { cdist_torus x = as_torus(a); return cdist_torus_line(q, &x, &b->l, c); }
    case PK(K_TORUS, K_RAY): { cdist_torus x = as_torus(a); cdist_ray y = as_ray(b); return cdist_torus_ray(q, &x, &y, c); }
    case PK(K_TORUS, K_SEGMENT): { cdist_torus x = as_torus(a); return cdist_torus_segment(q, &x, &b->s, c); }
    case PK(K_CAPSULE, K_CIRCLE): { cdist_capsule x = as_capsule(a); return cdist_capsule_circle(q, &x, &b->c, c); }
    case PK(K_CAPSULE, K_DISK): { cdist_capsule x = as_capsule(a); return cdist_capsule_disk(q, &x, &b->c, c); }
    case PK(K_SPHERE, K_CIRCLE): { cdist_sphere x = as_sphere(a); return cdist_sphere_circle(q, &x, &b->c, c); }
    case PK(K_SPHERE, K_DISK): { cdist_sphere x = as_sphere(a); return cdist_sphere_disk(q, &x, &b->c, c); }
    }
    return CDIST_ERR_INTERNAL;
}

/* The public core query (when one exists; -1 otherwise): for the exact identity. swapped says
 * the library's order is (b, a). */
static int core_public(cdist_query *q, const tobj *a, const tobj *b, cdist_result *r, int *swapped)
{
    *swapped = 0;
    switch (PK(a->kind, b->kind)) {
    case PK(K_TORUS, K_TORUS): return cdist_circle_circle(q, &a->c, &b->c, r);
    case PK(K_TORUS, K_CAPSULE): *swapped = 1; return cdist_segment_circle(q, &b->s, &a->c, r);
    case PK(K_TORUS, K_SPHERE): *swapped = 1; return cdist_point_circle(q, &b->p, &a->c, r);
    case PK(K_TORUS, K_RDISK): return cdist_circle_disk(q, &a->c, &b->c, r);
    case PK(K_CAPSULE, K_RDISK): return cdist_segment_disk(q, &a->s, &b->c, r);
    case PK(K_SPHERE, K_RDISK): return cdist_point_disk(q, &a->p, &b->c, r);
    case PK(K_RDISK, K_RDISK): return cdist_disk_disk(q, &a->c, &b->c, r);
    case PK(K_TORUS, K_LINE): *swapped = 1; return cdist_line_circle(q, &b->l, &a->c, r);
    case PK(K_TORUS, K_RAY): { cdist_ray y = as_ray(b); *swapped = 1; return cdist_ray_circle(q, &y, &a->c, r); }
    case PK(K_TORUS, K_SEGMENT): *swapped = 1; return cdist_segment_circle(q, &b->s, &a->c, r);
    case PK(K_CAPSULE, K_CIRCLE): return cdist_segment_circle(q, &a->s, &b->c, r);
    case PK(K_CAPSULE, K_DISK): return cdist_segment_disk(q, &a->s, &b->c, r);
    case PK(K_SPHERE, K_CIRCLE): return cdist_point_circle(q, &a->p, &b->c, r);
    case PK(K_SPHERE, K_DISK): return cdist_point_disk(q, &a->p, &b->c, r);
    }
    return -1;
}

/* ---- random objects ---- */

static cdist_vec3 rpoint(double s) { return tv(s * srand1(), s * srand1(), s * srand1()); }
static tobj rand_obj(int kind)
{
    tobj o;
    memset(&o, 0, sizeof o);
    o.kind = kind;
    o.p = rpoint(1.0);
    o.s.p0 = rpoint(1.0);
    o.s.p1 = rpoint(1.0);
    o.c.center = rpoint(0.7);
    o.c.normal = rand_unit();
    o.c.radius = 0.2 + urand();
    o.l.origin = rpoint(1.0);
    o.l.direction = rand_unit();
    o.radius = (kind <= K_RDISK) ? 0.05 + 0.4 * urand() : 0.0;
    return o;
}

static void translate(tobj *o, cdist_vec3 d)
{
    o->p = tv(o->p.x + d.x, o->p.y + d.y, o->p.z + d.z);
    o->s.p0 = tv(o->s.p0.x + d.x, o->s.p0.y + d.y, o->s.p0.z + d.z);
    o->s.p1 = tv(o->s.p1.x + d.x, o->s.p1.y + d.y, o->s.p1.z + d.z);
    o->c.center = tv(o->c.center.x + d.x, o->c.center.y + d.y, o->c.center.z + d.z);
    o->l.origin = tv(o->l.origin.x + d.x, o->l.origin.y + d.y, o->l.origin.z + d.z);
}

static const int pairs[][2] = {
    {K_TORUS, K_TORUS},  {K_TORUS, K_CAPSULE}, {K_TORUS, K_SPHERE},   {K_TORUS, K_RDISK},   {K_CAPSULE, K_CAPSULE},
    {K_CAPSULE, K_SPHERE}, {K_CAPSULE, K_RDISK}, {K_SPHERE, K_SPHERE}, {K_SPHERE, K_RDISK}, {K_RDISK, K_RDISK},
    {K_TORUS, K_LINE},   {K_TORUS, K_RAY},     {K_TORUS, K_SEGMENT},  {K_CAPSULE, K_CIRCLE}, {K_CAPSULE, K_DISK},
    {K_SPHERE, K_CIRCLE}, {K_SPHERE, K_DISK},
};
#define NPAIRS ((int)(sizeof pairs / sizeof pairs[0]))

static double vdist(cdist_vec3 a, cdist_vec3 b) { return tdist(a, b); }
static double vnorm(cdist_vec3 a) { return sqrt(a.x * a.x + a.y * a.y + a.z * a.z); }

static int n_overlap[NPAIRS], n_apart[NPAIRS];

static void check_one(cdist_query *q, int pi, const tobj *a, const tobj *b, int surface)
{
    cdist_contact c;
    cdist_status st = contact(q, a, b, &c);
    CHECK(st == CDIST_OK, "%s-%s: status %d (%s)", kname[a->kind], kname[b->kind], st, cdist_query_last_error(q));
    if (st) return;
    const char *an = kname[a->kind], *bn = kname[b->kind];
    /* (1) exact identity with the public core query */
    cdist_result r;
    int sw;
    int cs = core_public(q, a, b, &r, &sw);
    if (cs >= 0) {
        CHECK(cs == CDIST_OK, "core status");
        CHECK(c.core_distance == r.distance, "%s-%s core distance %.17g vs %.17g", an, bn, c.core_distance, r.distance);
        CHECK(c.distance == r.distance - (a->radius + b->radius), "%s-%s: distance %.17g is not core - radii %.17g", an,
              bn, c.distance, r.distance - (a->radius + b->radius));
        CHECK(c.num_pairs == r.num_pairs && c.equidistant == r.equidistant, "%s-%s: pairs/equidistant carried", an, bn);
        for (int i = 0; i < r.num_pairs && i < c.num_pairs; i++) {
            CHECK(memcmp(&c.pairs[i].core_point[0], &r.pairs[i].point[sw], sizeof(cdist_vec3)) == 0 &&
                      memcmp(&c.pairs[i].core_point[1], &r.pairs[i].point[1 - sw], sizeof(cdist_vec3)) == 0,
                  "%s-%s: core points carried over", an, bn);
        }
    }
    /* witness points and normal */
    for (int i = 0; i < c.num_pairs; i++) {
        const cdist_contact_pair *p = &c.pairs[i];
        CHECK(fabs(vnorm(p->normal) - 1) < 1e-15, "unit normal");
        double cd = vdist(p->core_point[0], p->core_point[1]);
        CHECK(fabs(cd - c.core_distance) <= 1e-14 * (1 + cd), "%s-%s core pair distance %.17g vs %.17g", an, bn, cd,
              c.core_distance);
        if (!(c.flags & CDIST_CONTACT_CORE_TOUCH)) {
            cdist_vec3 d = tv(p->core_point[1].x - p->core_point[0].x, p->core_point[1].y - p->core_point[0].y,
                              p->core_point[1].z - p->core_point[0].z);
            double dn = d.x * p->normal.x + d.y * p->normal.y + d.z * p->normal.z;
            CHECK(fabs(dn - cd) <= 1e-14 * (1 + cd), "normal along the core pair");
        }
        cdist_vec3 w = tv(p->point[1].x - p->point[0].x, p->point[1].y - p->point[0].y, p->point[1].z - p->point[0].z);
        double sd = w.x * p->normal.x + w.y * p->normal.y + w.z * p->normal.z;
        CHECK(fabs(sd - c.distance) <= 1e-13, "%s-%s: witness points give the signed distance (%.17g vs %.17g)", an, bn,
              sd, c.distance);
        /* The witnesses are on the surfaces when the cores are apart (with touching cores the
         * documented normal need not be orthogonal to the cores). */
        if (!(c.flags & CDIST_CONTACT_CORE_TOUCH))
        CHECK(fabs((double)core_dist(lvv(p->point[0]), a) - a->radius) <= 1e-13 * (1 + a->radius) &&
              fabs((double)core_dist(lvv(p->point[1]), b) - b->radius) <= 1e-13 * (1 + b->radius),
              "%s-%s: witness 0 on surface (%.17g vs r %.17g)", an, bn, (double)core_dist(lvv(p->point[0]), a), a->radius);
    }
    /* (2) brute force over the first core, minus the radii */
    bf f = {a, b, 0};
    int dims = core_dims(a);
    ld bcore = brute_min(&f, dims == 2 ? 60 : 400);
    double bsigned = (double)(bcore - a->radius - b->radius);
    CHECK(fabs(bsigned - c.distance) <= 1e-9, "%s-%s: brute core %.17g vs library %.17g", an, bn, bsigned, c.distance);
    CHECK(c.distance <= bsigned + 1e-12, "%s-%s: library above brute force (%.17g > %.17g)", an, bn, c.distance, bsigned);
    if (c.distance < 0) n_overlap[pi]++;
    else n_apart[pi]++;
    /* (3) separated: the sampled first solid's distance to the second solid */
    if (surface && c.distance > 1e-3) {
        bf g = {a, b, a->radius > 0};
        int gd = bf_dims(&g);
        ld bs = brute_min(&g, gd >= 4 ? 12 : (gd == 3 ? 24 : 120)) - b->radius;
        CHECK(fabs((double)bs - c.distance) <= 1e-8, "%s-%s: surface brute %.17g vs library %.17g", an, bn, (double)bs,
              c.distance);
    }
}

/* (4) signed distance continuous through contact: slide b along the core pair's normal. */
static int check_continuity(cdist_query *q, const tobj *a0, const tobj *b0)
{
    tobj a = *a0, b = *b0;
    cdist_contact c;
    if (contact(q, &a, &b, &c) || c.num_pairs < 1) return 0;
    cdist_vec3 n = c.pairs[0].normal;
    /* move b so that the distance goes from about +0.3 to about -0.1 in small steps */
    double start = 0.3 - c.distance;
    translate(&b, tv(start * n.x, start * n.y, start * n.z));
    double prev = NAN;
    int crossed = 0;
    const double h = 1e-3;
    for (int k = 0; k < 3000 && !(prev < -0.05); k++) {
        if (contact(q, &a, &b, &c)) break;
        if (k > 0) {
            CHECK(fabs(c.distance - prev) <= h * (1 + 1e-9), "%s-%s continuity: jump %.3g at step %d", kname[a.kind],
                  kname[b.kind], fabs(c.distance - prev), k);
            if ((prev > 0) != (c.distance > 0)) crossed = 1;
        }
        prev = c.distance;
        translate(&b, tv(-h * n.x, -h * n.y, -h * n.z));
    }
    return crossed;
}

static void check_touch_and_errors(cdist_query *q)
{
    /* Two tori whose core circles cross at right angles at the origin: x-y circle and x-z
     * circle both through the origin, tangents (0,1,0) and (0,0,1): normal = +-(1,0,0),
     * oriented from centre a (-1,0,0)... towards centre b (-1,0,0)+... */
    cdist_torus ta = {{{1, 0, 0}, {0, 0, 1}, 1}, 0.1}, tb = {{{-1, 0, 0}, {0, 1, 0}, 1}, 0.2};
    cdist_contact c;
    CHECK(cdist_torus_torus(q, &ta, &tb, &c) == CDIST_OK, "touch status");
    CHECK(c.flags & CDIST_CONTACT_CORE_TOUCH, "touch flag");
    CHECK(c.core_distance == 0 && c.distance == -0.30000000000000004, "touch distance %.17g", c.distance);
    CHECK(fabs(c.pairs[0].normal.x + 1) < 1e-15, "touch normal (%g %g %g): tangents cross, oriented to b's centre",
          c.pairs[0].normal.x, c.pairs[0].normal.y, c.pairs[0].normal.z);
    /* concentric spheres: rule 4 */
    cdist_sphere s0 = {{1, 2, 3}, 1}, s1 = {{1, 2, 3}, 0.5};
    CHECK(cdist_sphere_sphere(q, &s0, &s1, &c) == CDIST_OK && c.distance == -1.5, "concentric spheres");
    CHECK(c.pairs[0].normal.z == 1 && (c.flags & CDIST_CONTACT_CORE_TOUCH), "concentric spheres normal +z");
    /* sphere centre on a disk: plane normal rule, oriented to the disk centre side: n.(C - p) = 0 -> first
     * non-zero component positive */
    cdist_sphere s2 = {{0.2, 0, 0}, 0.1};
    cdist_circle d = {{0, 0, 0}, {0, 0, -1}, 1};
    CHECK(cdist_sphere_disk(q, &s2, &d, &c) == CDIST_OK && c.distance == -0.1, "sphere in disk");
    CHECK(c.pairs[0].normal.z == 1, "sphere in disk normal (%g %g %g)", c.pairs[0].normal.x, c.pairs[0].normal.y,
          c.pairs[0].normal.z);
    /* errors */
    cdist_sphere bad = {{0, 0, 0}, -1};
    CHECK(cdist_sphere_sphere(q, &s0, &bad, &c) == CDIST_ERR_NEGATIVE_RADIUS && isnan(c.distance) && c.num_pairs == 0,
          "negative radius");
    CHECK(cdist_query_last_status(q) == CDIST_ERR_NEGATIVE_RADIUS, "status on handle");
    bad.radius = NAN;
    CHECK(cdist_sphere_sphere(q, &s0, &bad, &c) == CDIST_ERR_NOT_FINITE, "NaN radius");
    bad.radius = 1e151;
    CHECK(cdist_sphere_sphere(q, &s0, &bad, &c) == CDIST_ERR_OUT_OF_RANGE, "huge radius");
    CHECK(cdist_sphere_sphere(q, &s0, NULL, &c) == CDIST_ERR_NULL_ARGUMENT && isnan(c.distance), "NULL object");
    CHECK(cdist_sphere_sphere(q, &s0, &s1, NULL) == CDIST_ERR_NULL_ARGUMENT, "NULL contact");
    CHECK(cdist_sphere_sphere(NULL, &s0, &s1, &c) == CDIST_ERR_NULL_ARGUMENT && isnan(c.distance), "NULL handle");
    cdist_torus tn = ta;
    tn.circle.normal = tv(0, 0, 2);
    CHECK(cdist_torus_torus(q, &ta, &tn, &c) == CDIST_ERR_NOT_UNIT && isnan(c.distance), "core validation");
    cdist_capsule cp = {{{0, 0, 0}, {NAN, 0, 0}}, 1};
    CHECK(cdist_capsule_capsule(q, &cp, &cp, &c) == CDIST_ERR_NOT_FINITE, "segment validation");
    /* parallel overlapping capsules: equidistant */
    cdist_capsule c0 = {{{0, 0, 0}, {2, 0, 0}}, 0.1}, c1 = {{{1, 1, 0}, {3, 1, 0}}, 0.2};
    CHECK(cdist_capsule_capsule(q, &c0, &c1, &c) == CDIST_OK && c.equidistant && fabs(c.distance - 0.7) < 1e-15,
          "parallel capsules equidistant %.17g", c.distance);
    c1.segment.p0 = tv(3, 1, 0);
    c1.segment.p1 = tv(5, 1, 0);
    CHECK(cdist_capsule_capsule(q, &c0, &c1, &c) == CDIST_OK && !c.equidistant, "parallel, no overlap");
    CHECK(fabs(c.distance - (sqrt(2.0) - 0.3)) < 1e-15, "parallel, no overlap: %.17g", c.distance);
    /* two pairs carried over: a line over a torus core's diameter (closest at both ends) */
    cdist_torus tt = {{{0, 0, 0}, {0, 0, 1}, 1}, 0.25};
    cdist_line over = {{0, 0, 0.5}, {1, 0, 0}};
    CHECK(cdist_torus_line(q, &tt, &over, &c) == CDIST_OK && c.num_pairs == 2 && !c.equidistant,
          "two pairs: %d", c.num_pairs);
    CHECK(fabs(c.distance - 0.25) < 1e-15, "two pairs distance %.17g", c.distance);
    for (int i = 0; i < c.num_pairs; i++) {
        const cdist_contact_pair *p = &c.pairs[i];
        CHECK(fabs(p->normal.z - 1) < 1e-15 && fabs(fabs(p->core_point[0].x) - 1) < 1e-15,
              "pair %d: normal (%g %g %g) at core x %g", i, p->normal.x, p->normal.y, p->normal.z, p->core_point[0].x);
        CHECK(fabs(p->point[0].z - 0.25) < 1e-15 && fabs(p->point[1].z - 0.5) < 1e-15, "pair %d witnesses", i);
    }
    CHECK(c.num_pairs == 2 && c.pairs[0].core_point[0].x * c.pairs[1].core_point[0].x < 0, "two distinct pairs");
    /* sizes */
    CHECK(cdist_contact_size() == sizeof(cdist_contact) && sizeof(cdist_contact) == 368, "contact size");
    CHECK(cdist_swept_size(0) == 32 && cdist_swept_size(1) == 56 && cdist_swept_size(2) == 64 &&
              cdist_swept_size(3) == 64 && cdist_swept_size(4) == 0,
          "swept sizes");
    CHECK(cdist_contact_flag_core_touch() == CDIST_CONTACT_CORE_TOUCH, "flag function");
}

/* Segment-segment reference: f(s) = distance from a(s) to segment b (exact projection) is convex
 * in s; golden-section search in long double. Independent of the library's closed form. */
static ld ref_point_seg(lv p, lv b0, lv db)
{
    ld dd = ldot(db, db), t = dd > 0 ? ldot(lsub(p, b0), db) / dd : 0;
    if (t < 0) t = 0;
    if (t > 1) t = 1;
    return lnorm(lsub(p, ladd(b0, lsc(t, db))));
}
static ld ref_seg_seg(cdist_segment a, cdist_segment b)
{
    lv a0 = lvv(a.p0), da = lsub(lvv(a.p1), a0), b0 = lvv(b.p0), db = lsub(lvv(b.p1), b0);
    const ld g = (sqrtl(5.0L) - 1) / 2;
    ld lo = 0, hi = 1, x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
    ld f1 = ref_point_seg(ladd(a0, lsc(x1, da)), b0, db), f2 = ref_point_seg(ladd(a0, lsc(x2, da)), b0, db);
    for (int it = 0; it < 200; it++) {
        if (f1 <= f2) {
            hi = x2, x2 = x1, f2 = f1, x1 = hi - g * (hi - lo);
            f1 = ref_point_seg(ladd(a0, lsc(x1, da)), b0, db);
        } else {
            lo = x1, x1 = x2, f1 = f2, x2 = lo + g * (hi - lo);
            f2 = ref_point_seg(ladd(a0, lsc(x2, da)), b0, db);
        }
    }
    ld best = f1 < f2 ? f1 : f2;
    ld e0 = ref_point_seg(a0, b0, db), e1 = ref_point_seg(ladd(a0, da), b0, db);
    if (e0 < best) best = e0;
    if (e1 < best) best = e1;
    return best;
}

/* The scale of a pair of segments: the largest distance of an end from the origin. */
static double seg_scale(cdist_segment a, cdist_segment b)
{
    return fmax(fmax(vnorm(a.p0), vnorm(a.p1)), fmax(vnorm(b.p0), vnorm(b.p1)));
}

/* Capsule-capsule cores (radius 0): nearly parallel segments at angles e = 1e-3 .. 1e-12 (the
 * closed form used to cancel in A E - B^2) and random ones, against the long double reference;
 * the error bound is 4e-15 of the scale (largest coordinate). */
static void check_segment_segment(cdist_query *q)
{
    double worst = 0;
    for (int k = 3; k <= 12; k++) {
        double e = pow(10.0, -k);
        /* the reviewer's case: distance 1e-7 at s = t = 0.3 */
        cdist_capsule ca = {{{0, 0, 0}, {1, 0, 0}}, 0}, cb = {{{0, -0.3 * e, 1e-7}, {1, 0.7 * e, 1e-7}}, 0};
        for (int rep = 0; rep < 40; rep++) {
            if (rep > 0) {
                /* random nearly parallel pairs: a random direction, b tilted by e, offset apart */
                cdist_vec3 o = rpoint(2), d = rand_unit(), u = rand_unit();
                double len = 0.5 + urand(), h = pow(10.0, -1 - 8 * urand()), sh = urand() - 0.5;
                ca.segment.p0 = o;
                ca.segment.p1 = tv(o.x + len * d.x, o.y + len * d.y, o.z + len * d.z);
                cdist_vec3 b0 = tv(o.x + sh * d.x + h * u.x, o.y + sh * d.y + h * u.y, o.z + sh * d.z + h * u.z);
                double lb = len * (0.5 + urand());
                cdist_vec3 w = rand_unit();
                cb.segment.p0 = b0;
                cb.segment.p1 = tv(b0.x + lb * (d.x + e * w.x), b0.y + lb * (d.y + e * w.y), b0.z + lb * (d.z + e * w.z));
            }
            cdist_contact c;
            CHECK(cdist_capsule_capsule(q, &ca, &cb, &c) == CDIST_OK, "segment-segment status");
            double ref = (double)ref_seg_seg(ca.segment, cb.segment);
            double L = seg_scale(ca.segment, cb.segment);
            double err = fabs(c.core_distance - ref) / L;
            if (err > worst) worst = err;
            CHECK(err <= 4e-15, "nearly parallel e=%g rep %d: %.17g vs reference %.17g (%.3g of scale)", e, rep,
                  c.core_distance, ref, err);
            if (rep == 0 && k == 9)
                CHECK(fabs(c.core_distance - 1e-7) <= 4e-15, "reviewer's case %.17g", c.core_distance);
        }
    }
    for (int rep = 0; rep < 2000; rep++) {
        cdist_capsule ca = {{rpoint(3), rpoint(3)}, 0}, cb = {{rpoint(3), rpoint(3)}, 0};
        cdist_vec3 b0 = cb.segment.p0, a0 = ca.segment.p0, a1 = ca.segment.p1;
        if (rep % 4 == 0) cb.segment.p1 = tv(b0.x + (a1.x - a0.x), b0.y + (a1.y - a0.y), b0.z + (a1.z - a0.z)); /* parallel */
        cdist_contact c;
        CHECK(cdist_capsule_capsule(q, &ca, &cb, &c) == CDIST_OK, "random segment-segment status");
        double ref = (double)ref_seg_seg(ca.segment, cb.segment);
        double L = seg_scale(ca.segment, cb.segment);
        double err = fabs(c.core_distance - ref) / L;
        if (err > worst) worst = err;
        CHECK(err <= 4e-15, "random segments %d: %.17g vs reference %.17g (%.3g of scale)", rep, c.core_distance, ref,
              err);
    }
    printf("segment-segment: max error %.3g of scale\n", worst);
}

/* Tiny and subnormal coordinates in the closed-form cores (found by fuzzing): distances and
 * segment parameters must not lose their squares to underflow, and the touch normal of
 * subnormal objects is a finite unit vector. References: exact differences of the inputs. */
static void check_tiny(cdist_query *q)
{
    cdist_contact c;
    /* spheres of radius 0 at x = 8.09e-169 and x = 9.3e-320: distance their difference */
    cdist_sphere s0 = {tv(8.0947715414629835e-169, 0, 0), 0}, s1 = {tv(9.3462398223788609e-320, 0, 0), 0};
    double ref = 8.0947715414629835e-169 - 9.3462398223788609e-320;
    CHECK(cdist_sphere_sphere(q, &s0, &s1, &c) == CDIST_OK && fabs(c.distance - ref) <= 1e-15 * ref,
          "tiny spheres: distance %.17g, expected %.17g", c.distance, ref);
    /* a segment of length 5e-259 whose end p1 is 1e-300 from a point: p1 is the closest point */
    cdist_capsule k = {{tv(-5e-259, 0, 0), tv(0, 0, 0)}, 0};
    cdist_sphere p = {tv(0, 1e-300, 0), 0};
    CHECK(cdist_capsule_sphere(q, &k, &p, &c) == CDIST_OK && fabs(c.distance - 1e-300) <= 1e-15 * 1e-300 &&
              c.pairs[0].param[0] == 1.0,
          "tiny segment: distance %.17g at s = %.17g, expected 1e-300 at 1", c.distance, c.pairs[0].param[0]);
    /* capsules of subnormal size that touch: a finite unit normal */
    cdist_capsule a = {{tv(4.0414569829813967e-320, -0.0, -7.0137559083623359e-320),
                        tv(1.1052248497468685e-319, -8.0947715414629834e-320, -4.6797897974082873e-320)}, 0};
    cdist_capsule b = {{tv(5.9915340871167968e-320, 5.2118984979793098e-320, -1.5696465568376403e-320),
                        tv(0, 0, 4.0473857707314917e-320)}, 2.428431462438895e-319};
    cdist_status st = cdist_capsule_capsule(q, &a, &b, &c);
    cdist_vec3 n = c.pairs[0].normal;
    double nn = sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
    CHECK(st == CDIST_OK && fabs(nn - 1) < 1e-15, "subnormal capsules: normal (%g %g %g)", n.x, n.y, n.z);
}

int main(void)
{
    cdist_query *q = cdist_query_new();
    check_tiny(q);
    for (int pi = 0; pi < NPAIRS; pi++) {
        int crossed = 0;
        for (int k = 0; k < 24; k++) {
            tobj a = rand_obj(pairs[pi][0]), b = rand_obj(pairs[pi][1]);
            /* alternate between near (often overlapping) and far configurations */
            double off = (k % 3 == 0) ? 0.0 : (k % 3 == 1 ? 0.8 : 2.5);
            cdist_vec3 dir = rand_unit();
            translate(&b, tv(off * dir.x, off * dir.y, off * dir.z));
            if (k % 3 == 0) {
                /* near: b's reference point close to a's (mostly overlapping) */
                cdist_vec3 ra = a.kind == K_SPHERE ? a.p : (a.kind == K_CAPSULE ? a.s.p0 : a.c.center);
                cdist_vec3 rb = b.kind == K_SPHERE ? b.p : (b.kind == K_CAPSULE || b.kind == K_SEGMENT ? b.s.p0 :
                                (b.kind == K_LINE || b.kind == K_RAY ? b.l.origin : b.c.center));
                translate(&b, tv(ra.x - rb.x + 0.2 * srand1(), ra.y - rb.y + 0.2 * srand1(), ra.z - rb.z + 0.2 * srand1()));
            }
            check_one(q, pi, &a, &b, k < 9);
            if (k < 6) crossed += check_continuity(q, &a, &b);
        }
        CHECK(crossed >= 3, "%s-%s: continuity sweeps through contact: %d of 6", kname[pairs[pi][0]],
              kname[pairs[pi][1]], crossed);
        CHECK(n_overlap[pi] > 0 && n_apart[pi] > 0, "%s-%s: both overlapping (%d) and separated (%d) cases",
              kname[pairs[pi][0]], kname[pairs[pi][1]], n_overlap[pi], n_apart[pi]);
    }
    check_touch_and_errors(q);
    check_segment_segment(q);
    cdist_query_free(q);
    return check_summary("swept");
}
