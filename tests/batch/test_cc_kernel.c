/* SPDX-License-Identifier: MIT */
/* The circle-circle distance kernel, each instruction set the machine has (scalar, AVX2,
 * AVX-512):
 *   test_cc_kernel DIR   (reads DIR/cc_{random,hard}.{txt,expected})
 * on the reference files with bad entries mixed in (NaN, infinity, zero and non-unit normals,
 * negative radius, out of range) and constructed special cases (coaxial, concentric, parallel
 * planes, linked and touching, a circle through the other's axis, symmetric pairs of minima,
 * zero radius, tiny, huge, far-away and subnormal-scale circles; random pairs that cross, touch
 * or nearly touch, and random pairs near an axis):
 * - the kernel answers an entry only if the single query accepts it, and then within 2 ulps of
 *   scale of the single query's distance (issue #11; scale as the reference files define it)
 *   and within 4e-15 of scale of the independent reference distance (the .expected files,
 *   computed in high precision by a separate method);
 * - it answers at least 95% of the valid entries of the random file (the rest is certified by
 *   the scalar path: near-ties of two minima, minima on an axis);
 * - the set-up in lanes gives the scalar set-up's ring bit for bit, and the final distance in
 *   lanes the scalar formula's (cdist__cc_point_d2) at any angle;
 * - every variant leaves nearly the same entries, and the public cdist_batch_distance agrees with the
 *   single queries (status, and distance to 2 ulps of scale) with 1 and 2 threads, and runs
 *   the single queries for a method that is not the kernel's (POLYNOMIAL). */
#include "../../src/batch/cc_kernel.c"

#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "test_rand.h"
#include "query_io.h"
#include "circle_pairs.h"

enum { MAXN = 2900 };
static cdist_circle A[MAXN], B[MAXN];
static double D[MAXN], REF[MAXN]; /* REF: NaN where there is no reference distance */
static size_t n_file;


/* One of the documented bad inputs, in either circle. */
static void corrupt(size_t i)
{
    corrupt_circle_pair(&A[i], &B[i]);
    REF[i] = NAN;
}

static cdist_circle circ(double cx, double cy, double cz, double nx, double ny, double nz, double r)
{
    double l = sqrt(nx * nx + ny * ny + nz * nz);
    return (cdist_circle){{cx, cy, cz}, {nx / l, ny / l, nz / l}, r};
}

static cdist_vec3 add3(cdist_vec3 a, cdist_vec3 b) { return (cdist_vec3){a.x + b.x, a.y + b.y, a.z + b.z}; }
static cdist_vec3 scale3(double k, cdist_vec3 a) { return (cdist_vec3){k * a.x, k * a.y, k * a.z}; }
/* an orthonormal basis u, v of the plane normal to the unit vector n */
static void basis_of(cdist_vec3 n, cdist_vec3 *u, cdist_vec3 *v)
{
    cdist_vec3 e = fabs(n.x) < 0.9 ? (cdist_vec3){1, 0, 0} : (cdist_vec3){0, 1, 0};
    cdist_vec3 w = {n.y * e.z - n.z * e.y, n.z * e.x - n.x * e.z, n.x * e.y - n.y * e.x};
    *u = scale3(1.0 / sqrt(w.x * w.x + w.y * w.y + w.z * w.z), w);
    *v = (cdist_vec3){n.y * u->z - n.z * u->y, n.z * u->x - n.x * u->z, n.x * u->y - n.y * u->x};
}

/* Valid special configurations appended after the file's entries. */
static size_t specials(size_t n)
{
    cdist_circle s[][2] = {
        {circ(0, 0, 0, 0, 0, 1, 1), circ(0, 0, 2, 0, 0, 1, 0.5)},       /* coaxial */
        {circ(0, 0, 0, 0, 0, 1, 1), circ(0, 0, 0, 0, 0, 1, 2)},         /* concentric, coplanar */
        {circ(0, 0, 0, 0, 0, 1, 1), circ(0.3, 0.2, 1, 0, 0, 1, 0.7)},   /* parallel planes */
        {circ(0, 0, 0, 0, 0, 1, 1), circ(1, 0, 0, 0, 1, 0, 1)},         /* linked, through each other's centre */
        {circ(0, 0, 0, 0, 0, 1, 1), circ(1 + 1e-9, 0, 0, 0, 1, 0, 1)},  /* linked, nearly touching */
        {circ(0, 0, 0, 0, 0, 1, 1), circ(0, 0, 0, 1, 0, 0, 1)},         /* orthogonal great circles */
        {circ(0, 0, 0, 0, 0, 1, 2), circ(0, 0, 1, 1, 0, 0, 0.5)},       /* centre on the axis: symmetric minima */
        {circ(0, 0, 0, 0, 0, 1, 1), circ(0.5, 0, 0, 0, 0, 1, 0.0)},     /* zero radius */
        {circ(1e-200, 0, 0, 0, 0, 1, 1e-200), circ(0, 2e-200, 1e-200, 0.3, 0.4, 0.5, 2e-200)}, /* tiny */
        {circ(1e140, 0, 0, 0, 0, 1, 1e140), circ(0, 2e140, 1e140, 0.3, 0.4, 0.5, 2e140)},     /* huge */
        {circ(1e9, 1e9, 0, 0.1, 0.2, 1, 1), circ(1e9 + 0.5, 1e9, 0.3, 0.3, 0.4, 0.5, 0.8)},   /* far away */
        {circ(0, 0, 0, 0, 0, 1, 1), circ(3, 0, 0, 0, 0, 1, 1)},         /* coplanar, apart */
    };
    for (size_t k = 0; k < sizeof s / sizeof s[0] && n < MAXN; k++, n++) {
        A[n] = s[k][0];
        B[n] = s[k][1];
        REF[n] = NAN;
    }
    /* random pairs that cross, touch or nearly touch (distance about delta, 0 to 1e-4) and
     * random pairs near the other circle's axis, none of them symmetric */
    static const double delta[] = {0.0, 1e-13, 1e-10, 1e-7, 1e-4};
    for (int k = 0; k < 500 && n < MAXN; k++, n++) {
        double r = 0.3 + rnd01(), rb = 0.3 + rnd01(), th = 2 * M_PI * rnd01();
        A[n] = circ(rnd01(), rnd01(), rnd01(), rnd01() - 0.5, rnd01() - 0.5, rnd01() - 0.5, r);
        cdist_vec3 u, v, nb = rnd_unit_vec(), ub;
        basis_of(A[n].normal, &u, &v);
        if (k % 6 == 5) { /* B's axis within 1e-7 of A's centre: B centred near A's centre on a line */
            cdist_vec3 o = scale3(1e-7 * rnd01(), rnd_unit_vec()), axis = rnd_unit_vec();
            double off = 2 * rnd01() - 1;
            B[n] = circ(A[n].center.x + o.x + off * axis.x, A[n].center.y + o.y + off * axis.y,
                        A[n].center.z + o.z + off * axis.z, axis.x, axis.y, axis.z, rb);
        } else { /* a point P of A, B through P, then B moved by delta */
            cdist_vec3 P = add3(A[n].center, add3(scale3(r * cos(th), u), scale3(r * sin(th), v)));
            cdist_vec3 tmp;
            basis_of(nb, &ub, &tmp);
            cdist_vec3 Cb = add3(add3(P, scale3(rb, ub)), scale3(delta[k % 6 % 5], rnd_unit_vec()));
            B[n] = circ(Cb.x, Cb.y, Cb.z, nb.x, nb.y, nb.z, rb);
        }
        REF[n] = NAN;
    }
    /* a pair at a subnormal scale (left to the scalar path by the kernel) */
    if (n < MAXN) {
        A[n] = circ(1e-310, 0, 0, 0.3, 0.4, 0.5, 2e-310);
        B[n] = circ(0, 3e-310, 1e-310, 0.5, -0.4, 0.3, 1e-310);
        REF[n++] = NAN;
    }
    return n;
}

static size_t load(const char *dir, const char *set)
{
    char path[1024], buf[2048], err[256];
    snprintf(path, sizeof path, "%s/cc_%s.txt", dir, set);
    FILE *f = fopen(path, "r");
    snprintf(path, sizeof path, "%s/cc_%s.expected", dir, set);
    FILE *e = fopen(path, "r");
    CHECK(f != NULL && e != NULL, "cannot read the cc_%s files", set);
    size_t n = 0;
    while (f && e && n < MAXN - 600 && fgets(buf, sizeof buf, f)) {
        cdq_line ql;
        if (cdq_parse(buf, &ql, err, sizeof err) <= 0) continue;
        memcpy(&A[n], ql.v, sizeof A[n]);
        memcpy(&B[n], ql.v + 7, sizeof B[n]);
        if (!fgets(buf, sizeof buf, e)) break;
        REF[n] = strtod(buf, NULL);
        n++;
    }
    if (f) fclose(f);
    if (e) fclose(e);
    return n;
}

/* The scale of entry i (cdq_scale of the reference files) for a distance d. */
static double scale_of(size_t i, double d)
{
    cdq_line ql;
    for (const cdq_kind *kd = cdq_kinds; kd->name; kd++)
        if (!strcmp(kd->name, "cc")) ql.kind = kd;
    ql.nvalues = 14;
    memcpy(ql.v, &A[i], sizeof A[i]);
    memcpy(ql.v + 7, &B[i], sizeof B[i]);
    return cdq_scale(&ql, d);
}

typedef uint64_t (*kfn)(const cdist__job *, int, double, size_t, size_t);

/* Returns the mask-count of valid entries the kernel left; *left_file: those of the file. */
static int check_kernel(const char *name, kfn k, cdist_query *q, size_t n, const char *what, int *left_file,
                        unsigned char *left_map)
{
    cdist__job job = {CDIST_KIND_CIRCLE_CIRCLE, n, (const char *)A, (const char *)B, sizeof A[0], sizeof B[0],
                      NULL, D, NULL, 64, CD_OUT_DISTANCE, 0, NULL, NULL};
    int bad = 0, badref = 0, wrong_left = 0, left_valid = 0, answered = 0, identical = 0;
    double worst = 0;
    *left_file = 0;
    for (size_t lo = 0; lo < n; lo += 64) {
        size_t cnt = n - lo < 64 ? n - lo : 64;
        for (size_t i = lo; i < lo + cnt; i++) D[i] = -1.0;
        uint64_t left = k(&job, 0, q->unit_tol, lo, cnt);
        for (size_t j = 0; j < cnt; j++) {
            size_t i = lo + j;
            cdist_result r;
            cdist_status st = cdist_circle_circle(q, &A[i], &B[i], &r);
            int l = (int)(left >> j & 1);
            left_map[i] = (unsigned char)l;
            if (l) {
                left_valid += st == CDIST_OK;
                *left_file += st == CDIST_OK && i < n_file;
                continue;
            }
            if (st != CDIST_OK) {
                if (wrong_left++ < 3)
                    CHECK(0, "%s %s entry %zu: kernel answered %.17g, single query %s", name, what, i, D[i],
                          cdist_status_name(st));
                continue;
            }
            answered++;
            identical += !memcmp(&D[i], &r.distance, sizeof(double));
            double L = scale_of(i, r.distance);
            if (!(fabs(D[i] - r.distance) <= 2.0 * ulp(L)) && bad++ < 3)
                CHECK(0, "%s %s entry %zu: %.17g vs single %.17g", name, what, i, D[i], r.distance);
            if (!isnan(REF[i])) {
                double err = fabs(D[i] - REF[i]) / L;
                worst = err > worst ? err : worst;
                if (!(err <= 4e-15) && badref++ < 3)
                    CHECK(0, "%s %s entry %zu: %.17g vs reference %.17g", name, what, i, D[i], REF[i]);
            }
        }
    }
    CHECK(bad == 0 && badref == 0 && wrong_left == 0,
          "%s %s: %d distances differ from the single query's by more than 2 ulps of scale, %d from the "
          "reference by more than 4e-15 of scale, %d rejected entries answered",
          name, what, bad, badref, wrong_left);
    printf("  %s %s: answered %d (%d bit-identical to the single query), worst error against the reference "
           "%.2g of scale\n",
           name, what, answered, identical, worst);
    return left_valid;
}

/* The public batch: status and distance of every entry as the single query's. */
static void check_batch(cdist_query *q, size_t n, const char *what)
{
    static cdist_status S[MAXN];
    cdist_batch_distance(q, CDIST_KIND_CIRCLE_CIRCLE, n, A, sizeof A[0], B, sizeof B[0], D, S);
    int bad = 0;
    for (size_t i = 0; i < n; i++) {
        cdist_result r;
        cdist_status st = cdist_circle_circle(q, &A[i], &B[i], &r);
        int same = S[i] == st && (st ? isnan(D[i]) : fabs(D[i] - r.distance) <= 2.0 * ulp(scale_of(i, r.distance)));
        if (!same && bad++ < 3)
            CHECK(0, "batch %s entry %zu: %.17g (%s) vs single %.17g (%s)", what, i, D[i], cdist_status_name(S[i]),
                  r.distance, cdist_status_name(st));
    }
    CHECK(bad == 0, "batch %s: %d entries differ from the single query", what, bad);
}

/* The scenes' screen (cdist__batch_screen) at cutoffs below, near and above each entry's
 * distance d (the single query's): a verdict -inf only when d <= cutoff (to rounding: 1e-13 of
 * scale), a finite answer either d (2 ulps of scale, as the kernel) or a lower bound of d above
 * the cutoff; a bad entry NaN. And the screen decides most entries from its grid when the cutoff
 * is far from d, which is what it is for. */
static void check_screen(cdist_query *q, size_t n, const char *what)
{
    static double cut[MAXN], out[MAXN], exact[MAXN];
    static cdist_status st[MAXN];
    for (size_t i = 0; i < n; i++) {
        cdist_result r;
        st[i] = cdist_circle_circle(q, &A[i], &B[i], &r);
        exact[i] = r.distance;
    }
    const double rel[] = {0.0, 0.5, 1.0 - 1e-3, 1.0 - 1e-9, 1.0, 1.0 + 1e-9, 1.0 + 1e-3, 2.0};
    int bad = 0, far = 0, far_decided = 0;
    for (size_t c = 0; c < sizeof rel / sizeof rel[0]; c++) {
        for (size_t i = 0; i < n; i++) cut[i] = st[i] ? 1.0 : exact[i] * rel[c];
        cdist_status ret = cdist__batch_screen(q, n, A, B, cut, out);
        CHECK(ret == CDIST_OK || ret == CDIST_ERR_NOT_FINITE || ret == CDIST_ERR_ZERO_VECTOR ||
                  ret == CDIST_ERR_NOT_UNIT || ret == CDIST_ERR_NEGATIVE_RADIUS || ret == CDIST_ERR_OUT_OF_RANGE,
              "screen %s: %s", what, cdist_status_name(ret));
        for (size_t i = 0; i < n; i++) {
            int ok;
            if (st[i]) ok = isnan(out[i]);
            else {
                double d = exact[i], L = scale_of(i, d);
                int same = fabs(out[i] - d) <= 2.0 * ulp(L);
                if (out[i] == -INFINITY) ok = d <= cut[i] + 1e-13 * L;
                else ok = same || (out[i] > cut[i] && out[i] <= d + 2.0 * ulp(L));
                if (rel[c] == 0.5 || rel[c] == 2.0) {
                    far += d > 1e-3 * L;
                    far_decided += d > 1e-3 * L && !same;
                }
            }
            if (!ok && bad++ < 3)
                CHECK(0, "screen %s entry %zu, cutoff %.17g: %.17g, distance %.17g (%s)", what, i, cut[i], out[i],
                      exact[i], cdist_status_name(st[i]));
        }
    }
    CHECK(bad == 0, "screen %s: %d verdicts wrong", what, bad);
    /* a count that leaves part of a lane group empty: nothing past the last entry is written
     * (nor answered: the empty lanes are no entries) */
    size_t m = n > 13 ? n - 13 : 1;
    for (size_t i = m; i < n; i++) out[i] = 12345.0;
    cdist__batch_screen(q, m, A, B, cut, out);
    int past = 0;
    for (size_t i = m; i < n; i++) past += out[i] != 12345.0;
    CHECK(past == 0, "screen %s: %d distances written past the %zu entries", what, past, m);
    CHECK(far_decided * 2 >= far, "screen %s: %d of %d entries with the cutoff at half or twice the distance decided "
          "by the grid", what, far_decided, far);
    printf("  %-6s screen: %d of %d entries decided by the grid at half or twice their distance\n", what, far_decided,
           far);
}

typedef unsigned (*sfn)(const cdist__job *, double, size_t, int, int, ck_block *);
typedef void (*ffn)(ck_block *, int);

/* The set-up in lanes against the scalar functions it repeats (cdist__circle_fast,
 * cdist__circles_frame, cdist__cc_prepare, cdist__check_circle's basis, cdist__cc_frame_ring): the same
 * acceptance (apart from equal radii, left by design) and bit-identical ring columns; and the
 * final distance in lanes at random angles against cdist__cc_point_d2, bit for bit. */
static void check_setup(const char *name, sfn setup, ffn final, int lanes, cdist_query *q, size_t n)
{
    cdist__job job = {CDIST_KIND_CIRCLE_CIRCLE, n, (const char *)A, (const char *)B, sizeof A[0], sizeof B[0],
                      NULL, D, NULL, 64, CD_OUT_DISTANCE, 0, NULL, NULL};
    static ck_block blk;
    int differ = 0, accept_bad = 0, checked = 0, dist_differ = 0;
    for (size_t lo = 0; lo < n; lo += 64) {
        int cnt = n - lo < 64 ? (int)(n - lo) : 64;
        for (int g = 0; g < cnt; g += lanes) {
            unsigned left = setup(&job, q->unit_tol, lo, g, cnt - g < lanes ? cnt - g : lanes, &blk);
            for (int l = 0; l < lanes; l++) {
                blk.t[g + l] = (2 * rnd01() - 1) * M_PI;
                sincos(blk.t[g + l], &blk.st[g + l], &blk.ct[g + l]);
            }
            final(&blk, g);
            for (int l = 0; l < lanes && g + l < cnt; l++) {
                int k = g + l;
                size_t i = lo + (size_t)k;
                /* accepted by the fast path (as the kernel), with the values (and basis) of the check */
                cdist__circle a, o;
                int ok = cdist__circle_fast(q->unit_tol, &A[i], &a) && cdist__circle_fast(q->unit_tol, &B[i], &o) &&
                         cdist__check_circle(q, &A[i], "first", &a) == CDIST_OK &&
                         cdist__check_circle(q, &B[i], "second", &o) == CDIST_OK;
                cdist__cc_problem p;
                vec3 off;
                cdist__best best;
                /* the kernel also leaves a subnormal frame scale and equal radii */
                double Lf = ok ? fmax(fmax(a.r, o.r), fmax(fmax(fabs(o.c.x - a.c.x), fabs(o.c.y - a.c.y)),
                                                          fabs(o.c.z - a.c.z)))
                               : 0.0;
                int e = ok ? cdist__circles_frame(&a, &o, &off, &best) : 0;
                ok = ok && Lf >= 0x1p-1022 && cdist__cc_prepare(&a, &o, &p) && a.r != o.r;
                if (!ok) {
                    accept_bad += !(left >> l & 1);
                    continue;
                }
                if (left >> l & 1) {
                    accept_bad++;
                    continue;
                }
                cdist__cc_frame f;
                cdist__cc_frame_ring(&f, &p.A, p.CB, &p.B);
                const cdist__ring rg = f.rg;
                const double want[] = {rg.al.x, rg.al.y, rg.al.z, rg.be.x, rg.be.y, rg.be.z, rg.ga.x,
                                       rg.ga.y, rg.ga.z, rg.ha,   rg.hb,   rg.hc,   p.B.r,   f.R * f.R,
                                       f.W1,    f.Hh,    f.Hc0,   f.Lw,    p.unscale, ldexp(1.0, e)};
                const int at[] = {CK_C_ALX, CK_C_ALY, CK_C_ALZ, CK_C_BEX, CK_C_BEY, CK_C_BEZ, CK_C_GAX,
                                  CK_C_GAY, CK_C_GAZ, CK_C_HA,  CK_C_HB,  CK_C_HC,  CK_C_S,   CK_C_R2,
                                  CK_C_W1,  CK_C_HH,  CK_C_HC0, CK_C_LW,  CK_C_UNSC, CK_C_UP};
                checked++;
                double c, sn;
                sincos(blk.t[k], &sn, &c);
                double d2 = cdist__cc_point_d2(&rg, p.B.r, c, sn);
                double d = sqrt(d2 * p.unscale * p.unscale) * ldexp(1.0, e);
                if (memcmp(&d, &blk.d[k], sizeof d) && dist_differ++ < 3)
                    CHECK(0, "%s final distance entry %zu at %.17g: %.17g vs scalar %.17g", name, i, blk.t[k], blk.d[k], d);
                for (int c = 0; c < (int)(sizeof at / sizeof at[0]); c++)
                    if (memcmp(&want[c], &blk.col[at[c]][k], sizeof(double))) {
                        if (differ++ < 3)
                            CHECK(0, "%s set-up entry %zu column %d: %.17g vs scalar %.17g", name, i, at[c],
                                  blk.col[at[c]][k], want[c]);
                    }
            }
        }
    }
    CHECK(differ == 0 && accept_bad == 0 && dist_differ == 0 && checked > 0,
          "%s set-up: %d columns differ from the scalar set-up, %d entries accepted or left wrongly, %d final "
          "distances differ (%d checked)",
          name, differ, accept_bad, dist_differ, checked);
}

int main(int argc, char **argv)
{
    test_rng = 0x9E3779B97F4A7C15ull;
    if (argc < 2) {
        fprintf(stderr, "usage: test_cc_kernel DIR\n");
        return 2;
    }
    cdist_query *q = cdist_query_new();
    const char *sets[] = {"random", "hard"};
    static unsigned char left1[MAXN], leftv[MAXN];
    for (int s = 0; s < 2; s++) {
        size_t n = load(argv[1], sets[s]), nf = n;
        for (size_t i = 0; i < nf; i++)
            if (next_rand() % 100 < 5) corrupt(i);
        n = specials(n);
        n_file = nf;
        int valid_file = 0, valid = 0;
        for (size_t i = 0; i < n; i++) {
            cdist_result r;
            int ok = cdist_circle_circle(q, &A[i], &B[i], &r) == CDIST_OK;
            valid += ok;
            valid_file += ok && i < nf;
        }
        int left_file, lf;
        check_setup("scalar", ck_setup_1, ck_final_1, 1, q, n);
        int left = check_kernel("scalar", kernel_scalar, q, n, sets[s], &left_file, left1);
        const char *best = "scalar";
#ifdef CD_X86_KERNELS
        __builtin_cpu_init();
        kfn wide[2] = {NULL, NULL};
        sfn wide_setup[2] = {ck_setup_4, ck_setup_8};
        ffn wide_final[2] = {ck_final_4, ck_final_8};
        int wide_lanes[2] = {4, 8};
        const char *wname[2] = {"avx2", "avx512"};
        if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) wide[0] = kernel_avx2;
        if (__builtin_cpu_supports("avx512f")) wide[1] = kernel_avx512;
        for (int v = 0; v < 2; v++) {
            if (!wide[v]) continue;
            check_setup(wname[v], wide_setup[v], wide_final[v], wide_lanes[v], q, n);
            int lv = check_kernel(wname[v], wide[v], q, n, sets[s], &lf, leftv);
            int differ = 0;
            for (size_t i = 0; i < n; i++) differ += leftv[i] != left1[i];
            /* the search's roundings differ between variants (fma); a certificate at its margin
             * may flip, but hardly ever */
            CHECK(differ * 200 <= (int)n, "%s left %d valid entries, scalar %d (%d differ)", wname[v], lv, left, differ);
            best = wname[v];
        }
#endif
        printf("  %-6s valid entries left to the scalar path (%s): %3d of %4d from the file, %3d of %3d special\n",
               sets[s], best, left_file, valid_file, left - left_file, valid - valid_file);
        if (s == 0)
            CHECK(left_file * 20 <= valid_file, "random: %d of %d valid entries left", left_file, valid_file);
        check_batch(q, n, sets[s]);
        check_screen(q, n, sets[s]);
        cdist_query_set_threads(q, 2);
        check_batch(q, n, sets[s]);
        cdist_query_set_threads(q, 1);
    }
    /* the POLYNOMIAL method is not the kernel's: the batch then runs the single queries */
    cdist_query_set_method(q, CDIST_METHOD_POLYNOMIAL);
    size_t n = specials(load(argv[1], "random"));
    check_batch(q, n, "random (polynomial)");
    cdist_query_free(q);
    return check_summary("cc-kernel");
}
