/* SPDX-License-Identifier: MIT */
/* The line/ray/segment-circle distance kernels, each instruction set the machine has (scalar,
 * AVX2, AVX-512), against the single queries:
 *   test_line_kernel DIR   (reads DIR/{lc,rc,sc}_{random,hard}.txt)
 * on the reference files with bad entries mixed in (NaN, infinity, zero and non-unit vectors,
 * negative radius, out of range) and constructed special cases (lines along and across the
 * axis, perpendicular to the plane, zero radius, tangent lines, symmetric pairs of minima,
 * far-away origins, tiny and huge scales):
 * - the kernel answers an entry only if the single query accepts it (a rejected entry is always
 *   left to the scalar path), and then within 2 ulps of scale of the single query's distance
 *   (the bar of issue #11; scale as the reference files define it, tools/query_io.c); the
 *   kernel runs the single query's body (src/lines/line_circle_body.h, the solver of
 *   src/base/roots_halley.h) in lanes, so all of them are bit-identical (the count of those
 *   that are not is printed: 0 expected);
 * - it leaves few valid entries of the random files to the scalar path (counted and printed);
 * - the public cdist_batch_distance agrees with the single queries (status and distance). */
#include "../../src/batch/line_kernel.c"

#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "test_rand.h"
#include "query_io.h"

enum { MAXN = 4200 };
static cdist_line A[MAXN]; /* lines, rays and segments share the layout (two vec3) */
static cdist_circle C[MAXN];
static double D[MAXN];
static size_t n_file;


static const char *shape_name[] = {"line", "ray", "segment"};
static const char *file_kind[] = {"lc", "rc", "sc"};

static cdist_status single_query(cdist_query *q, int shape, size_t i, cdist_result *r)
{
    switch (shape) {
    case LK_LINE: return cdist_line_circle(q, &A[i], &C[i], r);
    case LK_RAY: return cdist_ray_circle(q, (const cdist_ray *)&A[i], &C[i], r);
    default: return cdist_segment_circle(q, (const cdist_segment *)&A[i], &C[i], r);
    }
}

/* One of the documented bad inputs. */
static void corrupt(size_t i)
{
    switch (next_rand() % 9) {
    case 0: A[i].origin.y = NAN; break;
    case 1: A[i].direction.z = INFINITY; break;
    case 2: A[i].direction = (cdist_vec3){0, 0, 0}; break; /* a zero segment is a point: valid */
    case 3: A[i].direction.x *= 1.01; break;               /* not unit (a segment: valid) */
    case 4: C[i].normal = (cdist_vec3){0, 0, 0}; break;
    case 5: C[i].normal.y *= 1.001; break;
    case 6: C[i].radius = -1.0; break;
    case 7: C[i].center.x = 2e150; break;
    default: C[i].radius = NAN; break;
    }
}

/* Valid special configurations appended after the file's entries. */
static size_t specials(size_t n, int shape)
{
    cdist_circle c0 = {{0, 0, 0}, {0, 0, 1}, 1.0};
    struct {
        cdist_vec3 o, d;
        cdist_circle c;
    } s[] = {
        {{0, 0, -2}, {0, 0, 1}, c0},                           /* the axis */
        {{0.5, 0.25, -2}, {0, 0, 1}, c0},                      /* perpendicular to the plane */
        {{-3, 1, 0}, {1, 0, 0}, c0},                           /* tangent in the plane */
        {{-3, 1, 0.5}, {1, 0, 0}, c0},                         /* tangent above the plane */
        {{-3, 0, 0.5}, {1, 0, 0}, c0},                         /* across the axis */
        {{-3, 0.5, 0}, {1, 0, 0}, c0},                         /* a secant: distance 0 */
        {{-3, 0, 2}, {0.6, 0, 0.8}, c0},                       /* crosses the axis obliquely */
        {{1e6, 0.3, 0.1}, {1, 0, 0}, c0},                      /* origin far along the line */
        {{-1e12, 1e12, 3}, {0.6, -0.8, 0}, c0},                /* farther */
        {{0.3, 0.2, 0.1}, {0.36, 0.48, 0.8}, {{0, 0, 0}, {0, 0, 1}, 0.0}}, /* zero radius */
        {{1e-200, 2e-200, 0}, {0, 0.6, 0.8}, {{0, 0, 0}, {0.6, 0, 0.8}, 3e-200}}, /* tiny */
        {{1e140, -2e140, 0}, {0, 0.6, 0.8}, {{1e140, 0, 0}, {0.6, 0, 0.8}, 3e140}}, /* huge */
        {{1e-310, 0, 0}, {0, 1, 0}, {{0, 0, 0}, {0, 0, 1}, 1e-310}},                /* subnormal */
        {{0, 0, 0.3}, {1, 0, 0}, {{0, 0, 0}, {0, 0, 1}, 5.0}}, /* two symmetric minima */
        {{-3, 1e-125, 0}, {1, 0, 0}, c0},                      /* within 2^-400 of the centre */
        {{-3, 1e-125, 2e-125}, {0.6, 0.8, 0}, {{0, 0, 0}, {0, 0.6, 0.8}, 1.0}}, /* the same, tilted */
    };
    for (size_t k = 0; k < sizeof s / sizeof s[0] && n < MAXN; k++, n++) {
        A[n].origin = s[k].o;
        A[n].direction = s[k].d;
        if (shape == LK_SEGMENT) /* a segment through the same points, 4 units long */
            A[n].direction = (cdist_vec3){s[k].o.x + 4 * s[k].d.x, s[k].o.y + 4 * s[k].d.y, s[k].o.z + 4 * s[k].d.z};
        C[n] = s[k].c;
    }
    /* random near-tangent and near-axis lines around random circles */
    for (int k = 0; k < 200 && n < MAXN; k++, n++) {
        double th = 2 * M_PI * rnd01(), r = 0.1 + 2 * rnd01();
        cdist_vec3 nn = {rnd01() - 0.5, rnd01() - 0.5, rnd01() - 0.5};
        double ln = sqrt(nn.x * nn.x + nn.y * nn.y + nn.z * nn.z);
        nn.x /= ln, nn.y /= ln, nn.z /= ln;
        C[n] = (cdist_circle){{rnd01(), rnd01(), rnd01()}, nn, r};
        cdist_circle *c = &C[n];
        /* a tangent direction in the plane: any vector orthogonal to n */
        cdist_vec3 t = {nn.y, -nn.x, 0};
        double lt = sqrt(t.x * t.x + t.y * t.y);
        t.x /= lt, t.y /= lt;
        cdist_vec3 w = {nn.y * t.z - nn.z * t.y, nn.z * t.x - nn.x * t.z, nn.x * t.y - nn.y * t.x};
        double off = (k % 2) ? r * (1 + 1e-9 * (rnd01() - 0.5)) : 1e-9 * rnd01(); /* tangent / near axis */
        double lift = (k % 4 < 2) ? 0.0 : 0.3 * rnd01();
        cdist_vec3 p = {c->center.x + off * w.x + lift * nn.x - 2 * cos(th) * t.x,
                        c->center.y + off * w.y + lift * nn.y - 2 * cos(th) * t.y,
                        c->center.z + off * w.z + lift * nn.z - 2 * cos(th) * t.z};
        A[n].origin = p;
        A[n].direction = shape == LK_SEGMENT ? (cdist_vec3){p.x + 4 * t.x, p.y + 4 * t.y, p.z + 4 * t.z} : t;
        if (k % 8 == 7) { /* across the plane through the axis */
            A[n].origin = (cdist_vec3){c->center.x - nn.x, c->center.y - nn.y, c->center.z - nn.z};
            cdist_vec3 d = {nn.x + 1e-7 * t.x, nn.y + 1e-7 * t.y, nn.z + 1e-7 * t.z};
            double ld = sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
            A[n].direction = (cdist_vec3){d.x / ld, d.y / ld, d.z / ld};
        }
    }
    return n;
}

static size_t load(const char *dir, int shape, const char *set)
{
    char path[1024], buf[2048], err[256];
    snprintf(path, sizeof path, "%s/%s_%s.txt", dir, file_kind[shape], set);
    FILE *f = fopen(path, "r");
    CHECK(f != NULL, "cannot read %s", path);
    if (!f) return 0;
    size_t n = 0;
    while (n < MAXN - 400 && fgets(buf, sizeof buf, f)) {
        cdq_line ql;
        if (cdq_parse(buf, &ql, err, sizeof err) <= 0) continue;
        memcpy(&A[n], ql.v, sizeof A[n]);
        memcpy(&C[n], ql.v + 6, sizeof C[n]);
        n++;
    }
    fclose(f);
    return n;
}

typedef uint64_t (*kfn)(const cdist__job *, int, double, size_t, size_t);

/* The scale of entry i (cdq_scale of the reference files) for a distance d. */
static double scale_of(int shape, size_t i, double d)
{
    cdq_line ql;
    for (const cdq_kind *kd = cdq_kinds; kd->name; kd++)
        if (!strcmp(kd->name, file_kind[shape])) ql.kind = kd;
    ql.nvalues = 13;
    memcpy(ql.v, &A[i], sizeof A[i]);
    memcpy(ql.v + 6, &C[i], sizeof C[i]);
    return cdq_scale(&ql, d);
}

/* Returns the number of valid entries the kernel left to the scalar path; *left_file gets those
 * among the file's entries (before the specials). */
static int check_kernel(const char *name, kfn k, cdist_query *q, int shape, size_t n, const char *what, int *left_file)
{
    cdist_kind kind = shape == LK_LINE ? CDIST_KIND_LINE_CIRCLE
                      : shape == LK_RAY ? CDIST_KIND_RAY_CIRCLE
                                        : CDIST_KIND_SEGMENT_CIRCLE;
    cdist__job job = {kind, n, (const char *)A, (const char *)C, sizeof A[0], sizeof C[0], NULL, D, NULL, 64, CD_OUT_DISTANCE, 0, NULL, NULL};
    int bad = 0, wrong_left = 0, left_valid = 0, answered = 0, identical = 0;
    *left_file = 0;
    double tol = q->unit_tol;
    for (size_t lo = 0; lo < n; lo += 64) {
        size_t cnt = n - lo < 64 ? n - lo : 64;
        for (size_t i = lo; i < lo + cnt; i++) D[i] = -1.0;
        uint64_t left = k(&job, shape, tol, lo, cnt);
        for (size_t j = 0; j < cnt; j++) {
            size_t i = lo + j;
            cdist_result r;
            cdist_status st = single_query(q, shape, i, &r);
            int l = (int)(left >> j & 1);
            if (l) {
                left_valid += st == CDIST_OK;
                *left_file += st == CDIST_OK && i < n_file;
                continue;
            }
            if (st != CDIST_OK) {
                if (wrong_left++ < 3)
                    CHECK(0, "%s %s %s entry %zu: kernel answered %.17g, single query %s", name, shape_name[shape],
                          what, i, D[i], cdist_status_name(st));
                continue;
            }
            answered++;
            identical += !memcmp(&D[i], &r.distance, sizeof(double));
            if (!(fabs(D[i] - r.distance) <= 2.0 * ulp(scale_of(shape, i, r.distance))) && bad++ < 3)
                CHECK(0, "%s %s %s entry %zu: %.17g vs single %.17g", name, shape_name[shape], what, i, D[i],
                      r.distance);
        }
    }
    CHECK(bad == 0 && wrong_left == 0,
          "%s %s %s: %d distances differ by more than 2 ulps of scale, %d rejected entries answered", name,
          shape_name[shape], what, bad, wrong_left);
    printf("  %s %s %s: %d of %d distances not bit-identical (within 2 ulps of scale)\n", name, shape_name[shape],
           what, answered - identical, answered);
    return left_valid;
}

/* The public batch: status and distance of every entry as the single query's. */
static void check_batch(cdist_query *q, int shape, size_t n, const char *what)
{
    cdist_kind kind = shape == LK_LINE ? CDIST_KIND_LINE_CIRCLE
                      : shape == LK_RAY ? CDIST_KIND_RAY_CIRCLE
                                        : CDIST_KIND_SEGMENT_CIRCLE;
    static cdist_status S[MAXN];
    cdist_batch_distance(q, kind, n, A, sizeof A[0], C, sizeof C[0], D, S);
    int bad = 0;
    for (size_t i = 0; i < n; i++) {
        cdist_result r;
        cdist_status st = single_query(q, shape, i, &r);
        int same = S[i] == st &&
                   (st ? isnan(D[i]) : fabs(D[i] - r.distance) <= 2.0 * ulp(scale_of(shape, i, r.distance)));
        if (!same && bad++ < 3)
            CHECK(0, "batch %s %s entry %zu: %.17g (%s) vs single %.17g (%s)", shape_name[shape], what, i, D[i],
                  cdist_status_name(S[i]), r.distance, cdist_status_name(st));
    }
    CHECK(bad == 0, "batch %s %s: %d entries differ from the single query", shape_name[shape], what, bad);
}

/* 2 ulps of the scale of a line-circle entry (cdq_scale: max(distance, radius, distance from the
 * centre to the line)). */
static double line_tol(const cdist_line *l, const cdist_circle *c, double d)
{
    cdq_line ql;
    for (const cdq_kind *kd = cdq_kinds; kd->name; kd++)
        if (!strcmp(kd->name, "lc")) ql.kind = kd;
    ql.nvalues = 13;
    memcpy(ql.v, l, sizeof *l);
    memcpy(ql.v + 6, c, sizeof *c);
    return 2.0 * ulp(cdq_scale(&ql, d));
}

/* Strides through the public batch: lines in user structs, one circle for all (stride 0), and
 * the arrays walked backwards; every distance within 2 ulps of scale of the single query's (the
 * kernel's loads). */
static void check_strides(cdist_query *q)
{
    enum { N = 150 };
    static struct {
        int tag;
        cdist_line line;
        char pad[5];
    } items[N];
    static double d[N];
    static cdist_status st[N];
    cdist_circle c = {{0.1, -0.2, 0.3}, {0.6, 0, 0.8}, 1.3};
    for (int i = 0; i < N; i++) {
        double t = 0.41 * i;
        items[i].tag = i;
        items[i].line = (cdist_line){{cos(t), sin(2 * t), 0.02 * i - 1}, {0, sin(t), cos(t)}};
    }
    CHECK(cdist_batch_distance(q, CDIST_KIND_LINE_CIRCLE, N, &items[0].line, sizeof items[0], &c, 0, d, st) ==
              CDIST_OK,
          "user structs, broadcast circle");
    int bad = 0;
    for (int i = 0; i < N; i++) {
        cdist_result r;
        cdist_line_circle(q, &items[i].line, &c, &r);
        bad += !(fabs(d[i] - r.distance) <= line_tol(&items[i].line, &c, r.distance)) || st[i] != CDIST_OK;
    }
    CHECK(bad == 0, "user structs, broadcast circle: %d entries differ", bad);
    CHECK(cdist_batch_distance(q, CDIST_KIND_LINE_CIRCLE, N, &items[N - 1].line, -(ptrdiff_t)sizeof items[0], &c, 0,
                               d, NULL) == CDIST_OK,
          "negative stride");
    bad = 0;
    for (int i = 0; i < N; i++) {
        cdist_result r;
        cdist_line_circle(q, &items[N - 1 - i].line, &c, &r);
        bad += !(fabs(d[i] - r.distance) <= line_tol(&items[N - 1 - i].line, &c, r.distance));
    }
    CHECK(bad == 0, "negative stride: %d entries differ", bad);
    /* each kernel variant on its own: user structs walked backwards, the circle broadcast */
    kfn ks[3] = {kernel_1, NULL, NULL};
    const char *kn[3] = {"scalar", "avx2", "avx512"};
#ifdef CD_X86_KERNELS
    __builtin_cpu_init();
    if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) ks[1] = kernel_4;
    if (__builtin_cpu_supports("avx512f")) ks[2] = kernel_8;
#endif
    for (int v = 0; v < 3; v++) {
        if (!ks[v]) continue;
        cdist__job job = {CDIST_KIND_LINE_CIRCLE, N, (const char *)&items[N - 1].line, (const char *)&c,
                          -(ptrdiff_t)sizeof items[0], 0, NULL, d, NULL, 64, CD_OUT_DISTANCE, 0, NULL, NULL};
        bad = 0;
        for (size_t lo = 0; lo < N; lo += 64) {
            size_t cnt = N - lo < 64 ? N - lo : 64;
            uint64_t left = ks[v](&job, LK_LINE, q->unit_tol, lo, cnt);
            for (size_t j = 0; j < cnt; j++) {
                cdist_result r;
                cdist_line_circle(q, &items[N - 1 - (lo + j)].line, &c, &r);
                const cdist_line *l = &items[N - 1 - (lo + j)].line;
                bad += (left >> j & 1) || !(fabs(d[lo + j] - r.distance) <= line_tol(l, &c, r.distance));
            }
        }
        CHECK(bad == 0, "%s kernel, negative stride and broadcast: %d entries differ or left", kn[v], bad);
    }
}

/* The vector kernels' cube root (cdist__cbrt's algorithm in lanes) against cdist__cbrt, bit for
 * bit, on 2^20 numbers of every binade, with zeros, subnormals, infinities and NaNs mixed in
 * (lanes the vector form does not take). The scalar kernel calls cdist__cbrt itself. */
static void check_cbrt(void)
{
    static double x[1 << 20], y[1 << 20];
    for (int i = 0; i < 1 << 20; i++) {
        uint64_t e = (uint64_t)(next_rand() % 2046 + 1), bits = e << 52 | (next_rand() >> 12);
        memcpy(&x[i], &bits, sizeof bits);
        if (i % 4099 == 0) x[i] = (i / 4099) % 4 == 0 ? 0.0 : (i / 4099) % 4 == 1 ? 0x1p-1070 : (i / 4099) % 4 == 2 ? INFINITY : NAN;
    }
#ifdef CD_X86_KERNELS
    __builtin_cpu_init();
#endif
    void (*lanes[])(const double *, double *, int) = {
#ifdef CD_X86_KERNELS
        __builtin_cpu_supports("avx512f") ? cbrt_lanes_8 : NULL,
        __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") ? cbrt_lanes_4 : NULL,
#endif
        NULL,
    };
    for (size_t v = 0; v < sizeof lanes / sizeof lanes[0]; v++) {
        if (!lanes[v]) continue;
        lanes[v](x, y, 1 << 20);
        int bad = 0;
        for (int i = 0; i < 1 << 20; i++) {
            double c = cdist__cbrt(x[i]);
            bad += memcmp(&c, &y[i], sizeof c) != 0 && !(isnan(c) && isnan(y[i]));
        }
        CHECK(bad == 0, "lane cube roots (variant %zu) differ from cdist__cbrt on %d of 2^20", v, bad);
    }
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: test_line_kernel DIR\n");
        return 2;
    }
    cdist_query *q = cdist_query_new();
    const char *sets[] = {"random", "hard"};
    for (int shape = 0; shape < 3; shape++) {
        for (int s = 0; s < 2; s++) {
            size_t n = load(argv[1], shape, sets[s]);
            size_t nf = n;
            for (size_t i = 0; i < nf; i++)
                if (next_rand() % 100 < 5) corrupt(i);
            n = specials(n, shape);
            n_file = nf;
            int valid = 0, valid_file = 0;
            for (size_t i = 0; i < n; i++) {
                cdist_result r;
                int ok = single_query(q, shape, i, &r) == CDIST_OK;
                valid += ok;
                valid_file += ok && i < nf;
            }
            int left_file, lf;
            int left = check_kernel("scalar", kernel_1, q, shape, n, sets[s], &left_file);
            const char *best = "scalar";
#ifdef CD_X86_KERNELS
            __builtin_cpu_init();
            if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) {
                int l2 = check_kernel("avx2", kernel_4, q, shape, n, sets[s], &lf);
                CHECK(l2 == left, "avx2 left %d valid entries, scalar %d", l2, left);
                best = "avx2";
            }
            if (__builtin_cpu_supports("avx512f")) {
                int l8 = check_kernel("avx512", kernel_8, q, shape, n, sets[s], &lf);
                CHECK(l8 == left, "avx512 left %d valid entries, scalar %d", l8, left);
                best = "avx512";
            }
#endif
            printf("  %-8s %-6s valid entries left to the scalar path (%s and the others): %3d of %4d from the "
                   "file, %3d of %3d special\n",
                   shape_name[shape], sets[s], best, left_file, valid_file, left - left_file, valid - valid_file);
            /* the random file: the kernel answers nearly everything valid */
            if (s == 0)
                CHECK(left_file * 50 <= valid_file, "%s random: %d of %d valid entries left", shape_name[shape],
                      left_file, valid_file);
            check_batch(q, shape, n, sets[s]);
            cdist_query_set_threads(q, 2);
            check_batch(q, shape, n, sets[s]);
            cdist_query_set_threads(q, 1);
        }
    }
    check_strides(q);
    check_cbrt();
    /* the POLYNOMIAL method is not the kernel's: the batch then runs the single queries */
    cdist_query_set_method(q, CDIST_METHOD_POLYNOMIAL);
    size_t n = specials(load(argv[1], LK_LINE, "random"), LK_LINE);
    check_batch(q, LK_LINE, n, "random (polynomial)");
    cdist_query_free(q);
    return check_summary("line-kernel");
}
