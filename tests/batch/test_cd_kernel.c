/* SPDX-License-Identifier: MIT */
/* The circle-disk and disk-disk distance kernels, the rim searches in every lane width the
 * machine has (1, AVX2's 4, AVX-512's 8):
 *   test_cd_kernel DIR   (reads DIR/{cd,dd}_{random,hard}.txt)
 * on the reference files with bad entries mixed in (NaN, infinity, zero and non-unit normals,
 * negative radius, out of range), constructed special cases (coplanar, concentric, coaxial,
 * parallel planes, a circle through the disk, a circle touching the rim, zero radius, tiny
 * beside huge, far away) and random pairs (general, piercing, nearly coaxial, mixed scales):
 * - the kernel answers an entry only if the single query (method AUTO) accepts it, and then
 *   with the single query's distance bit for bit;
 * - the validation and the candidates over the face in every lane width are the one-lane body's
 *   (the single query's) bit for bit;
 * - the rim searches in every lane width certify the entries the single query's search of that
 *   width (cdist__cc_quick's variant for that instruction set) certifies, with its angle, cosine
 *   and sine bit for bit;
 * - it answers at least 80% of the valid entries of the random files (the rest: the single
 *   query's engine, parallel planes, zero radii);
 * - the public cdist_batch_distance equals the single queries bit for bit, statuses included,
 *   with 1 and 2 threads, and with the POLYNOMIAL method (which has no kernel). */
#include "../../src/batch/cd_kernel.c"
/* the single query's search in each width, to compare the lanes with */
#include "../../src/circles/cc_search.c"

#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "query_io.h"
#include "test_rand.h"
#include "circle_pairs.h"

enum { MAXN = 6000 };
static cdist_circle A[MAXN], B[MAXN];
static double D[MAXN];

static cdist_circle circ(double cx, double cy, double cz, double nx, double ny, double nz, double r)
{
    double l = sqrt(nx * nx + ny * ny + nz * nz);
    return (cdist_circle){{cx, cy, cz}, {nx / l, ny / l, nz / l}, r};
}

static size_t load(const char *dir, const char *kind, const char *set, size_t n)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s_%s.txt", dir, kind, set);
    return load_circle_pairs(path, A, B, n, MAXN - 2000);
}

static cdist_vec3 rvec(double s) { return (cdist_vec3){s * (2 * rnd01() - 1), s * (2 * rnd01() - 1), s * (2 * rnd01() - 1)}; }
static cdist_vec3 add3(cdist_vec3 a, cdist_vec3 b) { return (cdist_vec3){a.x + b.x, a.y + b.y, a.z + b.z}; }
static cdist_vec3 scale3(double k, cdist_vec3 a) { return (cdist_vec3){k * a.x, k * a.y, k * a.z}; }

/* Special and random pairs appended from n. */
static size_t extra(size_t n)
{
    cdist_circle s[][2] = {
        {circ(0, 0, 0, 0, 0, 1, 1), circ(0, 0, 0, 0, 0, 1, 2)},         /* concentric, coplanar */
        {circ(0, 0, 0, 0, 0, 1, 1), circ(0.3, 0.2, 0, 0, 0, 1, 0.7)},   /* coplanar */
        {circ(0, 0, 0, 0, 0, 1, 1), circ(0, 0, 2, 0, 0, 1, 0.5)},       /* coaxial */
        {circ(0, 0, 0, 0, 0, 1, 1), circ(0.3, 0.2, 1, 0, 0, 1, 0.7)},   /* parallel planes */
        {circ(0, 0, 0, 0, 0, 1, 1), circ(1, 0, 0, 0, 1, 0, 1)},         /* circle through the disk */
        {circ(0, 0, 0, 1, 0, 0, 1), circ(0, 0, 0, 0, 0, 1, 0.5)},       /* through the disk's centre */
        {circ(0, 0, 0, 0, 0, 1, 1), circ(2, 0, 0, 1, 0, 0, 1)},         /* touching the rim */
        {circ(0, 0, 0, 0, 0, 1, 1), circ(0, 0, 0.5, 0, 1, 0, 1e-8)},    /* tiny over the face */
        {circ(0, 0, 0, 0, 0, 1, 1e8), circ(0, 0, 1e-8, 0.6, 0, 0.8, 1e-8)}, /* huge disk, tiny circle */
        {circ(0, 0, 0, 0.6, 0, 0.8, 1e-8), circ(0, 0, 0, 0, 0, 1, 1e8)},
        {circ(0, 0, 0, 0, 0, 1, 1), circ(1e9, 0, 0, 0, 1, 0, 1)},       /* far away */
        {circ(0, 0, 0, 0, 0, 1, 0.0), circ(0.5, 0, 1, 0, 1, 0, 1)},     /* zero radius */
        {circ(0, 0, 0, 0, 0, 1, 2), circ(0, 0, 1, 1, 0, 0, 0.5)},       /* centre on the axis */
        {circ(1, 2, 3, 0.1, 0.2, 1, 1.5), circ(1, 2, 3.5, 0.1, 0.2, 1, 1.5)}, /* coaxial, equal */
    };
    for (size_t k = 0; k < sizeof s / sizeof s[0]; k++, n++) {
        A[n] = s[k][0];
        B[n] = s[k][1];
    }
    for (int k = 0; k < 2000; k++, n++) {
        cdist_vec3 na = rnd_unit_vec(), nb = rnd_unit_vec(), ca = rvec(3), cb;
        double ra = 0.1 + 2 * rnd01(), rb = 0.1 + 2 * rnd01();
        switch (k % 5) {
        case 4: /* the circle passes near the disk's axis (F's kink) */
            nb = (cdist_vec3){0, 0, 1};
            ca = (cdist_vec3){ra + pow(10, -1 - 8 * rnd01()), 0.3 * rnd01(), 0.2 + rnd01()};
            na = (cdist_vec3){0.3 * rnd01(), 1, 0.3 * rnd01()};
            cb = (cdist_vec3){0, 0, 0};
            break;
        case 0: cb = rvec(3); break;                                   /* general */
        case 1: cb = add3(ca, rvec(0.5 * ra)); break;                  /* near: often piercing */
        case 2:                                                        /* nearly coaxial */
            nb = (cdist_vec3){na.x + 1e-7 * rnd01(), na.y, na.z};
            cb = add3(ca, add3(scale3(2 * rnd01() - 1, na), rvec(1e-6)));
            break;
        default:                                                       /* mixed scales */
            cb = rvec(3);
            if (next_rand() & 1) ra *= 1e-6;
            else rb *= 1e6;
            break;
        }
        double l = sqrt(nb.x * nb.x + nb.y * nb.y + nb.z * nb.z), la = sqrt(na.x * na.x + na.y * na.y + na.z * na.z);
        A[n] = (cdist_circle){ca, scale3(1 / la, na), ra};
        B[n] = (cdist_circle){cb, scale3(1 / l, nb), rb};
    }
    return n;
}

/* The single query's distance and status of entry i. */
static cdist_status single(cdist_query *q, int disk, size_t i, double *d)
{
    cdist_result r;
    cdist_status st = disk ? cdist_disk_disk(q, &A[i], &B[i], &r) : cdist_circle_disk(q, &A[i], &B[i], &r);
    *d = r.distance;
    return st;
}

/* The kernel (its rim searches in the given lane width, 0: this CPU's, the single query's) over
 * entries [0, n): returns the number answered; the distances in D, NaN where left; checks them
 * against the single query bit for bit. */
static size_t run_width(cdist_query *q, int disk, int lanes, size_t n, const char *what, uint64_t *left_all)
{
    cdist__job job = {disk ? CDIST_KIND_DISK_DISK : CDIST_KIND_CIRCLE_DISK, n, (const char *)A, (const char *)B,
                      sizeof(cdist_circle), sizeof(cdist_circle), NULL, D, NULL, 64, CD_OUT_DISTANCE, 0, NULL, NULL};
    size_t answered = 0;
    int bad = 0;
    for (size_t lo = 0; lo < n; lo += 64) {
        size_t cnt = n - lo < 64 ? n - lo : 64;
        for (size_t k = 0; k < cnt; k++) D[lo + k] = NAN;
        uint64_t left = cd_kernel(&job, disk, 1e-6, lo, cnt, lanes);
        left_all[lo / 64] = left;
        for (size_t k = 0; k < cnt; k++) {
            if (left >> k & 1) continue;
            answered++;
            double ds;
            cdist_status st = single(q, disk, lo + k, &ds);
            if ((st != CDIST_OK || memcmp(&ds, &D[lo + k], sizeof ds)) && bad++ < 5)
                CHECK(0, "%s %s %d lanes entry %zu: kernel %.17g, single %.17g (status %d)", disk ? "dd" : "cd", what,
                      lanes, lo + k, D[lo + k], ds, (int)st);
        }
    }
    CHECK(bad == 0, "%s %s %d lanes: %d entries differ from the single query", disk ? "dd" : "cd", what, lanes, bad);
    return answered;
}

/* The rim searches in lanes of every width the machine has against the single query's search
 * of that width (cdist__cc_quick's variant, which another machine would run): the same entries
 * certified, the same angle, cosine and sine bit for bit. The widths' arithmetic differs (fma,
 * AVX-512's reciprocal square root), so their answers may differ in the last bits. */
static void check_widths(int disk, size_t n, const char *what)
{
    static cd_entry x[CD_SUB], xw[CD_SUB];
    const cdist__cc_frame *f[CD_SUB];
    double t[CD_SUB], c[CD_SUB], s[CD_SUB], d2[CD_SUB];
    int state[CD_SUB], statew[CD_SUB];
    int bad = 0, sbad = 0, searched = 0;
    typedef int (*quick_fn)(const cdist__cc_frame *, double *, double *, double *);
    quick_fn quick[3] = {ck_quick_1, NULL, NULL};
    int widths[3] = {1, 4, 8};
#ifdef CD_X86_KERNELS
    if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) quick[1] = ck_quick_4;
    if (__builtin_cpu_supports("avx512f")) quick[2] = ck_quick_8;
#endif
    cdist__cc_search_tables();
    cdist__job job = {disk ? CDIST_KIND_DISK_DISK : CDIST_KIND_CIRCLE_DISK, n, (const char *)A, (const char *)B,
                      sizeof(cdist_circle), sizeof(cdist_circle), NULL, D, NULL, 64, CD_OUT_DISTANCE, 0, NULL, NULL};
    for (size_t lo = 0; lo < n; lo += CD_SUB) {
        int cnt = n - lo < CD_SUB ? (int)(n - lo) : CD_SUB;
        cd_stages(cd_variant_of(1), &job, disk, 1e-6, lo, cnt, x, state);
        for (int k = 0; k < cnt; k++) {
            f[k] = state[k] == CD_SEARCH ? &x[k].st.f : NULL;
            searched += f[k] != NULL;
        }
        for (int w = 0; w < 3; w++) {
            if (!quick[w]) continue;
            /* the validation and framing in lanes: the single query's (the scalar check,
             * cdist__circles_frame) bit for bit; left: a rejected circle, a zero or subnormal
             * scale */
            cdist__circle aw[CD_SUB], ew[CD_SUB];
            double upw[CD_SUB], bsw[CD_SUB];
            uint64_t swap = (uint64_t)next_rand();
            uint64_t badf = cdist__circle_pairs_lanes(&job, 1e-6, lo, cnt, widths[w], swap, aw, ew, upw, bsw);
            int vbad = 0;
            for (int k = 0; k < cnt; k++) {
                cdist__circle as, es;
                const cdist_circle *in[2] = {&A[lo + (size_t)k], &B[lo + (size_t)k]};
                int sw = (int)(swap >> k & 1); /* exchanged */
                int ok = cdist__circle_fast_basis(1e-6, in[sw], &as) && cdist__circle_fast_basis(1e-6, in[1 - sw], &es);
                vec3 C = v_sub(es.c, as.c);
                ok = ok && fmax(fmax(as.r, es.r), fmax(fmax(fabs(C.x), fabs(C.y)), fabs(C.z))) >= 0x1p-1022;
                vbad |= ok == (int)(badf >> k & 1);
                if (!ok) continue;
                vec3 off;
                cdist__best best;
                int ex = cdist__circles_frame(&as, &es, &off, &best);
                vbad |= memcmp(&as, &aw[k], sizeof as) || memcmp(&es, &ew[k], sizeof es) || upw[k] != cdist__pow2(ex) ||
                        bsw[k] != best.scale;
            }
            CHECK(!vbad, "%s %s from %zu, %d lanes: the validation differs from the single query's", disk ? "dd" : "cd",
                  what, lo, widths[w]);
            /* the circle in the disk's frame in lanes: the one-lane body's (the single query's) */
            cd_stages(cd_variant_of(widths[w]), &job, disk, 1e-6, lo, cnt, xw, statew);
            for (int k = 0; k < cnt; k++) {
                int differ = statew[k] != state[k];
                if (!differ && state[k] != CD_SCALAR)
                    differ = memcmp(&x[k].st.scale, &xw[k].st.scale, 8) ||
                             memcmp(&x[k].st.k.g, &xw[k].st.k.g, offsetof(cdk_lanes_1, small));
                if (differ && sbad++ < 5)
                    CHECK(0, "%s %s entry %zu, %d lanes: the stages differ from one lane's (state %d vs %d)",
                          disk ? "dd" : "cd", what, lo + (size_t)k, widths[w], statew[k], state[k]);
            }
            /* the candidates over the faces in lanes: one lane's, from no start and from starts
             * below, at and above their answer (the far candidates dropped) */
            static cd_entry x1[CD_SUB];
            double start[CD_SUB];
            for (int pass = 0; pass < 2; pass++) {
                int s1[CD_SUB], sw[CD_SUB];
                memcpy(x1, x, sizeof x1);
                for (int k = 0; k < cnt; k++) {
                    s1[k] = sw[k] = state[k] == CD_SEARCH && statew[k] == CD_SEARCH ? CD_DONE : CD_SCALAR;
                    x1[k].st.d2 = xw[k].st.d2 = pass ? start[k] : INFINITY;
                }
                cd_faces(cd_variant_of(1), disk, cnt, x1, s1);
                cd_faces(cd_variant_of(widths[w]), disk, cnt, xw, sw);
                for (int k = 0; k < cnt; k++) {
                    if ((s1[k] != sw[k] || (s1[k] == CD_DONE && memcmp(&x1[k].st.d2, &xw[k].st.d2, 8))) && sbad++ < 5)
                        CHECK(0, "%s %s entry %zu, %d lanes, start %d: the faces' candidates differ from one lane's",
                              disk ? "dd" : "cd", what, lo + (size_t)k, widths[w], pass);
                    start[k] = x1[k].st.d2 * (k % 3 == 0 ? 0.25 : k % 3 == 1 ? 1.0 : 4.0);
                }
            }
            /* the rim search's frame in lanes: cdist__cc_quick_frame's (the decision and the fields
             * the search reads) */
            for (int k = 0; k < cnt; k++) {
                if (state[k] == CD_SCALAR) continue;
                const cdist__circle *pc = &x[k].st.c, *pd = &x[k].st.d;
                cdist__cc_frame fl, fs, *pf = &fl;
                double scl, scs;
                int engine = (int)(cd_variant_of(widths[w])->rim_frame(&pc, &pd, 1, &pf, &scl) & 1);
                int quick = cdist__cc_quick_frame(pc, pd, &fs, &scs);
                int differ = engine == quick;
                if (quick && !engine)
                    differ = memcmp(&fl.rg, &fs.rg, sizeof fs.rg) || memcmp(&scl, &scs, 8) || fl.R != fs.R ||
                             fl.s != fs.s || fl.W1 != fs.W1 || fl.Hh != fs.Hh || fl.Hc0 != fs.Hc0 || fl.Lw != fs.Lw;
                if (differ && sbad++ < 5)
                    CHECK(0, "%s %s entry %zu, %d lanes: the rim frame differs from the single query's", disk ? "dd" : "cd",
                          what, lo + (size_t)k, widths[w]);
            }
            uint64_t found = cdist__cc_quick_lanes(f, cnt, widths[w], t, c, s, d2);
            for (int k = 0; k < cnt; k++) {
                if (!f[k]) continue;
                double t1, c1, s1;
                int ok = quick[w](f[k], &t1, &c1, &s1);
                double d21 = ok ? cdist__cc_point_d2(&f[k]->rg, f[k]->s, c1, s1) : 0.0;
                if ((ok != (int)(found >> k & 1) || (ok && (memcmp(&t1, &t[k], 8) || memcmp(&c1, &c[k], 8) ||
                                                             memcmp(&s1, &s[k], 8) || memcmp(&d21, &d2[k], 8)))) &&
                    bad++ < 5)
                    CHECK(0, "%s %s entry %zu, %d lanes: certified %d, single query's search %d; angle %.17g vs %.17g",
                          disk ? "dd" : "cd", what, lo + (size_t)k, widths[w], (int)(found >> k & 1), ok, t[k], t1);
            }
        }
    }
    CHECK(bad == 0, "%s %s: %d rim searches differ from the single query's of their width", disk ? "dd" : "cd", what,
          bad);
    CHECK(sbad == 0, "%s %s: %d entries' stages differ between lane widths", disk ? "dd" : "cd", what, sbad);
    CHECK(searched > 0, "%s %s: no rim search ran", disk ? "dd" : "cd", what);
}

static void check_set(cdist_query *q, int disk, size_t n, size_t nvalid_random, const char *what)
{
    static uint64_t left[MAXN / 64 + 1];
    size_t answered = run_width(q, disk, 0, n, what, left);
    check_widths(disk, n, what);
    if (nvalid_random)
        CHECK(answered >= 0.8 * nvalid_random, "%s %s: the kernel answers %zu of %zu valid random entries",
              disk ? "dd" : "cd", what, answered, nvalid_random);
    printf("%s %s: %zu entries, %zu answered by the kernel\n", disk ? "dd" : "cd", what, n, answered);
}

/* The public batch against the single queries: statuses and distances bit for bit. */
static void check_public(cdist_query *q, int disk, size_t n)
{
    static double Dp[MAXN];
    static cdist_status S[MAXN];
    cdist_kind kind = disk ? CDIST_KIND_DISK_DISK : CDIST_KIND_CIRCLE_DISK;
    for (int threads = 1; threads <= 2; threads++)
        for (int poly = 0; poly < 2; poly++) {
            cdist_query_set_threads(q, threads);
            cdist_query_set_method(q, poly ? CDIST_METHOD_POLYNOMIAL : CDIST_METHOD_AUTO);
            cdist_batch_distance(q, kind, n, A, sizeof *A, B, sizeof *B, Dp, S);
            cdist_query_set_threads(q, 1);
            int bad = 0;
            for (size_t i = 0; i < n; i++) {
                double ds;
                cdist_status st = single(q, disk, i, &ds);
                if ((st != S[i] || (st == CDIST_OK && memcmp(&ds, &Dp[i], sizeof ds))) && bad++ < 3)
                    CHECK(0, "%s public batch (%d threads, %s) entry %zu: %.17g status %d, single %.17g status %d",
                          disk ? "dd" : "cd", threads, poly ? "POLYNOMIAL" : "AUTO", i, Dp[i], (int)S[i], ds, (int)st);
            }
            CHECK(bad == 0, "%s public batch: %d entries differ", disk ? "dd" : "cd", bad);
        }
    cdist_query_set_method(q, CDIST_METHOD_AUTO);
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: test_cd_kernel DIR\n");
        return 2;
    }
    cdist_query *q = cdist_query_new();
    const char *kinds[2] = {"cd", "dd"};
    for (int disk = 0; disk < 2; disk++) {
        size_t nr = load(argv[1], kinds[disk], "random", 0);
        check_set(q, disk, nr, nr, "random");
        size_t n = load(argv[1], kinds[disk], "hard", nr);
        n = extra(n);
        check_set(q, disk, n, 0, "files, special and random pairs");
        for (size_t i = 0; i < n; i += 37) corrupt_circle_pair(&A[i], &B[i]);
        check_set(q, disk, n, 0, "with bad entries");
        check_public(q, disk, n);
    }
    cdist_query_free(q);
    return check_summary("cd-kernel");
}
