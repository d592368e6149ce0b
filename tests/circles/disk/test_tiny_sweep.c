/* SPDX-License-Identifier: MIT */
/* Brute-force sweep of a tiny circle or disk (radius 1e-12..1e-6 of the other) by a big circle
 * or disk: circle-circle, circle-disk both ways (AUTO and POLYNOMIAL) and disk-disk both ways,
 * against long double references, each the minimum of attained values (so an upper bound of
 * the true minimum) from independent searches: the rim of either object sampled, golden
 * sections on every sampled minimum and a geometric zoom to 1e-19 rad around the lowest (the
 * features are as narrow as the tiny radius), and a disk's face by nested golden sections.
 * Found the circle-circle engine's refinement stopping 5e-12 rad short beside a tiny circle
 * (circle-disk 1e-11 of scale off) and the parallel closed forms losing a tiny circle's
 * crossings (1.4e-8). usage: test_tiny_sweep [N [SEED]] */
#include <string.h>

#include "check.h"
#include "test_ld.h"


typedef struct { lv c, n, u, v; ld r; int disk; } obj;
static cdist_vec3 O;
static obj mk(cdist_circle c, int disk)
{
    obj d;
    lv_frame(c, O, &d.c, &d.n, &d.u, &d.v);
    d.r = c.radius;
    d.disk = disk;
    return d;
}
static ld pdist(const obj *d, lv p)
{
    lv D = lv_sub(p, d->c);
    ld h = lv_dot(d->n, D), rho = lv_norm(lv_cross(d->n, D));
    if (d->disk && rho <= d->r) return fabsl(h);
    return sqrtl((rho - d->r) * (rho - d->r) + h * h);
}
static lv rimpt(const obj *d, ld t) { return lv_add(d->c, lv_add(lv_scale(d->r * cosl(t), d->u), lv_scale(d->r * sinl(t), d->v))); }

typedef struct { const obj *x, *y; } rctx; /* x's rim parameterised, distance to y */
static ld rim_f(const rctx *c, ld t) { return pdist(c->y, rimpt(c->x, t)); }

static ld golden(const rctx *c, ld a, ld b)
{
    const ld g = 0.6180339887498948482045868L;
    ld cc = b - g * (b - a), dd = a + g * (b - a), fc = rim_f(c, cc), fd = rim_f(c, dd);
    ld best = fminl(fminl(rim_f(c, a), rim_f(c, b)), fminl(fc, fd));
    for (int it = 0; it < 200 && b - a > 1e-19L * (1 + fabsl(a)); it++) {
        if (fc <= fd) { b = dd; dd = cc; fd = fc; cc = b - g * (b - a); fc = rim_f(c, cc); }
        else { a = cc; cc = dd; fc = fd; dd = a + g * (b - a); fd = rim_f(c, dd); }
        best = fminl(best, fminl(fc, fd));
    }
    return best;
}

/* Minimum over x's rim of the distance to y: global samples, golden on each sampled local
 * minimum, and a geometric zoom around the best few (narrow features at the tiny scale). */
static ld rim_min(const obj *x, const obj *y)
{
    rctx c = {x, y};
    enum { NS = 4096, NZ = 256, KEEP = 3 };
    static ld v[NS + 1];
    const ld TWO_PI = 6.283185307179586476925286766559L, h = TWO_PI / NS;
    ld best = INFINITY;
    for (int i = 0; i < NS; i++) v[i] = rim_f(&c, i * h);
    /* centres for zoom: the KEEP lowest local minima */
    ld zc[KEEP], zv[KEEP];
    for (int k = 0; k < KEEP; k++) zc[k] = 0, zv[k] = INFINITY;
    for (int i = 0; i < NS; i++) {
        ld a = v[(i + NS - 1) % NS], b = v[(i + 1) % NS];
        best = fminl(best, v[i]);
        if (v[i] <= a && v[i] <= b) {
            best = fminl(best, golden(&c, (i - 1) * h, (i + 1) * h));
            /* insert */
            for (int k = 0; k < KEEP; k++)
                if (v[i] < zv[k]) {
                    for (int j = KEEP - 1; j > k; j--) zc[j] = zc[j - 1], zv[j] = zv[j - 1];
                    zc[k] = i * h, zv[k] = v[i];
                    break;
                }
        }
    }
    for (int k = 0; k < KEEP; k++) {
        if (!(zv[k] < INFINITY)) continue;
        ld t0 = zc[k], w = 2 * h;
        while (w > 1e-19L) {
            ld hz = 2 * w / NZ, bt = t0, bv = INFINITY, vz[NZ + 1];
            for (int j = 0; j <= NZ; j++) vz[j] = rim_f(&c, t0 - w + j * hz);
            for (int j = 0; j <= NZ; j++) {
                if (vz[j] < bv) bv = vz[j], bt = t0 - w + j * hz;
                if (j > 0 && j < NZ && vz[j] <= vz[j - 1] && vz[j] <= vz[j + 1])
                    best = fminl(best, golden(&c, t0 - w + (j - 1) * hz, t0 - w + (j + 1) * hz));
            }
            best = fminl(best, bv);
            t0 = bt;
            w = 4 * hz;
        }
    }
    return best;
}

/* Disk x's face (2D nested golden, x a disk) to y: the point-y distance; convex when y is a
 * disk, nearly so for a tiny x beside a big circle y. */
typedef struct { const obj *x, *y; ld xx; } fctx;
static ld face_in(const fctx *c, ld yy) { return pdist(c->y, lv_add(c->x->c, lv_add(lv_scale(c->xx, c->x->u), lv_scale(yy, c->x->v)))); }
static ld gold1(const fctx *c, ld a, ld b)
{
    const ld g = 0.6180339887498948482045868L;
    ld cc = b - g * (b - a), dd = a + g * (b - a), fc = face_in(c, cc), fd = face_in(c, dd);
    ld best = fminl(fminl(face_in(c, a), face_in(c, b)), fminl(fc, fd));
    for (int it = 0; it < 200 && b - a > 1e-19L * (fabsl(a) + fabsl(b)); it++) {
        if (fc <= fd) { b = dd; dd = cc; fd = fc; cc = b - g * (b - a); fc = face_in(c, cc); }
        else { a = cc; cc = dd; fc = fd; dd = a + g * (b - a); fd = face_in(c, dd); }
        best = fminl(best, fminl(fc, fd));
    }
    return best;
}
static ld face_out(fctx *c, ld xx)
{
    c->xx = xx;
    ld w = sqrtl(fmaxl(c->x->r * c->x->r - xx * xx, 0));
    if (w == 0) return face_in(c, 0);
    return gold1(c, -w, w);
}
static ld face_min(const obj *x, const obj *y)
{
    fctx c = {x, y, 0};
    const ld g = 0.6180339887498948482045868L;
    ld a = -x->r, b = x->r;
    ld cc = b - g * (b - a), dd = a + g * (b - a), fc = face_out(&c, cc), fd = face_out(&c, dd);
    ld best = fminl(fc, fd);
    for (int it = 0; it < 200 && b - a > 1e-19L * x->r; it++) {
        if (fc <= fd) { b = dd; dd = cc; fd = fc; cc = b - g * (b - a); fc = face_out(&c, cc); }
        else { a = cc; cc = dd; fc = fd; dd = a + g * (b - a); fd = face_out(&c, dd); }
        best = fminl(best, fminl(fc, fd));
    }
    return best;
}

/* Reference for kind 0 cc, 1 cd (a circle, b disk), 2 dd. */
static ld reference(int kind, cdist_circle a, cdist_circle b)
{
    O = b.radius >= a.radius ? b.center : a.center;
    obj A = mk(a, kind == 2), B = mk(b, kind >= 1);
    obj Ac = A, Bc = B;
    Ac.disk = 0;
    Bc.disk = 0;
    ld best = rim_min(&A, &B);               /* a's rim (a circle or the disk's rim) to b */
    if (kind == 0) best = fminl(best, rim_min(&B, &A));
    if (kind == 1) {
        best = fminl(best, rim_min(&Bc, &Ac)); /* b's rim to circle a (attained: an upper bound) */
        best = fminl(best, face_min(&B, &Ac)); /* b's face to circle a */
    }
    if (kind == 2) {
        best = fminl(best, rim_min(&B, &A));
        best = fminl(best, face_min(A.r <= B.r ? &A : &B, A.r <= B.r ? &B : &A));
    }
    return best;
}

static unsigned long long rng = 0x9E3779B97F4A7C15ull;
static double ur(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (double)(rng >> 11) * (1.0 / 9007199254740992.0);
}
static double sr(void) { return 2 * ur() - 1; }
static cdist_vec3 runit(void)
{
    for (;;) {
        double x = sr(), y = sr(), z = sr(), n = sqrt(x * x + y * y + z * z);
        if (n > 0.1 && n <= 1) return (cdist_vec3){x / n, y / n, z / n};
    }
}
static cdist_vec3 vcross(cdist_vec3 a, cdist_vec3 b) { return (cdist_vec3){a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
static cdist_vec3 vunit(cdist_vec3 a) { double n = sqrt(a.x * a.x + a.y * a.y + a.z * a.z); return (cdist_vec3){a.x / n, a.y / n, a.z / n}; }

/* big object and a tiny one near it: variant selects the placement */
static void config(cdist_circle *big, cdist_circle *tiny, int variant)
{
    double R = 0.5 + 1.5 * ur();
    big->center = (cdist_vec3){sr(), sr(), sr()};
    big->normal = runit();
    big->radius = R;
    cdist_vec3 n = big->normal, e = fabs(n.x) < 0.5 ? (cdist_vec3){1, 0, 0} : (cdist_vec3){0, 1, 0};
    cdist_vec3 u = vunit(vcross(n, e)), v = vcross(n, u);
    double th = 6.283185307179586 * ur();
    cdist_vec3 radial = {cos(th) * u.x + sin(th) * v.x, cos(th) * u.y + sin(th) * v.y, cos(th) * u.z + sin(th) * v.z};
    cdist_vec3 tang = vcross(n, radial);
    cdist_vec3 P0 = {big->center.x + R * radial.x, big->center.y + R * radial.y, big->center.z + R * radial.z};
    double r = R * pow(10.0, -6 - 6 * ur());
    cdist_vec3 off, tn = runit();
    double len;
    switch (variant % 6) {
    case 0: /* random offset of a few radii or less */
        len = r * pow(10.0, -3 + 4 * ur());
        off = runit();
        break;
    case 1: /* the big circle nearly touching the tiny rim: offset ~ r (1 +- tiny) in the tiny plane */
    {
        cdist_vec3 w = vunit(vcross(tn, runit()));
        len = r * (1 + (ur() < 0.5 ? -1 : 1) * pow(10.0, -6 * ur()));
        /* place the tiny centre so that P0 is at distance len from it, in its plane */
        off = w;
        break;
    }
    case 2: /* through the tiny disk near its centre (the big circle crosses the tiny axis) */
        len = r * pow(10.0, -4 * ur() - 1);
        off = runit();
        break;
    case 3: /* tiny plane containing the big circle's tangent (pierced edge-on) */
        tn = vunit(vcross(tang, runit()));
        len = r * pow(10.0, -2 + 3 * ur());
        off = runit();
        break;
    case 4: /* tiny plane perpendicular to the big circle's tangent (big circle pierces the face) */
        tn = ur() < 0.5 ? tang : vunit((cdist_vec3){tang.x + 1e-3 * sr(), tang.y + 1e-3 * sr(), tang.z + 1e-3 * sr()});
        len = r * pow(10.0, -3 + 3.5 * ur());
        off = runit();
        break;
    default: /* in the big plane, radially beside the rim (coplanar-ish) */
        tn = ur() < 0.5 ? n : runit();
        len = r * pow(10.0, -3 + 4 * ur());
        {
            double sg = ur() < 0.5 ? -1 : 1;
            off = (cdist_vec3){sg * radial.x, sg * radial.y, sg * radial.z};
        }
        break;
    }
    tiny->center = (cdist_vec3){P0.x + len * off.x, P0.y + len * off.y, P0.z + len * off.z};
    tiny->normal = tn;
    tiny->radius = r;
}

static double scale_of(cdist_circle a, cdist_circle b, double d)
{
    double dx = a.center.x - b.center.x, dy = a.center.y - b.center.y, dz = a.center.z - b.center.z;
    return fmax(fmax(a.radius, b.radius), fmax(sqrt(dx * dx + dy * dy + dz * dz), d));
}

int main(int argc, char **argv)
{
    int N = argc > 1 ? atoi(argv[1]) : 240;
    unsigned long long seed = argc > 2 ? strtoull(argv[2], 0, 0) : 1;
    rng ^= seed * 0x2545F4914F6CDD1Dull;
    cdist_query *q = cdist_query_new();
    const char *names[] = {"cc(big,tiny)", "cc(tiny,big)", "cd(bigC,tinyD)", "cd(tinyC,bigD)", "dd(big,tiny)", "dd(tiny,big)",
                           "cd-poly(bigC,tinyD)", "cd-poly(tinyC,bigD)"};
    enum { NK = 8 };
    double worst[NK] = {0};
    const double EPS = 2.220446049250313e-16;
    for (int i = 0; i < N; i++) {
        cdist_circle big, tiny;
        int variant = i % 6;
        config(&big, &tiny, variant);
        ld ref_cc = reference(0, big, tiny);
        ld ref_cd_bt = reference(1, big, tiny); /* big circle, tiny disk */
        ld ref_cd_tb = reference(1, tiny, big); /* tiny circle, big disk */
        ld ref_dd = reference(2, big, tiny);
        for (int k = 0; k < NK; k++) {
            cdist_result r;
            ld ref;
            cdist_query_set_method(q, k >= 6 ? CDIST_METHOD_POLYNOMIAL : CDIST_METHOD_AUTO);
            cdist_status st;
            cdist_circle a = (k % 2 == 0) ? big : tiny, b = (k % 2 == 0) ? tiny : big;
            switch (k) {
            case 0: case 1: st = cdist_circle_circle(q, &a, &b, &r); ref = ref_cc; break;
            case 2: case 6: st = cdist_circle_disk(q, &a, &b, &r); ref = ref_cd_bt; break;
            case 3: case 7: st = cdist_circle_disk(q, &a, &b, &r); ref = ref_cd_tb; break;
            default: st = cdist_disk_disk(q, &a, &b, &r); ref = ref_dd; break;
            }
            CHECK(st == CDIST_OK, "%s #%d: status %d", names[k], i, st);
            if (st != CDIST_OK) continue;
            double L = scale_of(a, b, r.distance);
            double e = fabs((double)((r.distance - ref) / L)) / EPS; /* eps of scale */
            if (e > worst[k]) worst[k] = e;
            /* The polynomial method of a big circle and a tiny disk is known to miss the lower
             * minimum of the tiny rim's cluster (below its roots' resolution): reported, not
             * checked. */
            if (k == 6) continue;
            CHECK(e <= 16, "%s #%d variant %d: %.17g vs brute force %.20Lg (%.3g eps of scale %.3g)\n"
                           "  big {{%a,%a,%a},{%a,%a,%a},%a}\n  tiny {{%a,%a,%a},{%a,%a,%a},%a}",
                  names[k], i, variant, r.distance, ref, e, L, big.center.x, big.center.y, big.center.z, big.normal.x,
                  big.normal.y, big.normal.z, big.radius, tiny.center.x, tiny.center.y, tiny.center.z, tiny.normal.x,
                  tiny.normal.y, tiny.normal.z, tiny.radius);
        }
    }
    printf("tiny sweep, %d configurations, max error in eps of scale:", N);
    for (int k = 0; k < NK; k++) printf(" %s %.3g", names[k], worst[k]);
    printf("\n");
    cdist_query_free(q);
    return check_summary("test_tiny_sweep");
}
