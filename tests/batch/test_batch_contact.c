/* SPDX-License-Identifier: MIT */
/* Contact and gradient batches, progress and cancel, overlap detection:
 *   test_batch_contact DIR...   (reference files KIND_{random,hard}.txt looked up in each DIR)
 * - every contact kind: cdist_batch_contact() and cdist_batch_grad() are bit-identical to the
 *   single contact and _grad queries of every entry, with bad entries (NaN coordinate, NaN,
 *   negative or huge radius) mixed in at random positions; the swept objects are the reference
 *   files' objects (cc, sc, pc, cd, sd, pd, dd, lc, rc) with random radii; cdist_batch_distance()
 *   gives the single query's signed distance (bit for bit where the core's kernel repeats the
 *   single query's arithmetic, else within 4 ulps of scale), NaN and the status for a bad entry;
 * - every plain kind with a _grad query: cdist_batch_grad() against the single _grad query;
 * - threads 1 and 2 bit-identical;
 * - progress: called from the calling thread, done increasing, at the end done == total; a
 *   non-zero return cancels: the first entries keep their answers, the others get
 *   CDIST_ERR_CANCELLED and NaN; every thread count;
 * - overlapping outputs: CDIST_ERR_OVERLAP, nothing written (also the linking and time-of-impact
 *   batches). */
#include <math.h>
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "circledist.h"
#include "query_io.h"
#include "single.h"
#include "test_rand.h"

#define MAX_LINES 2100

static cdq_line lines[MAX_LINES];

static FILE *open_in(int ndirs, char **dirs, const char *name)
{
    char path[1024];
    for (int i = 0; i < ndirs; i++) {
        snprintf(path, sizeof path, "%s/%s", dirs[i], name);
        FILE *f = fopen(path, "r");
        if (f) return f;
    }
    return NULL;
}

/* The query lines of a reference file (0 if not found). */
static size_t read_file(int ndirs, char **dirs, const char *kname, const char *set)
{
    char name[64], buf[2048], err[256];
    snprintf(name, sizeof name, "%s_%s.txt", kname, set);
    FILE *f = open_in(ndirs, dirs, name);
    if (!f) return 0;
    size_t n = 0;
    while (n < MAX_LINES && fgets(buf, sizeof buf, f))
        if (cdq_parse(buf, &lines[n], err, sizeof err) > 0) n++;
    fclose(f);
    return n;
}

static const cdq_kind *find_kind(const char *name)
{
    for (const cdq_kind *k = cdq_kinds; k->name; k++)
        if (!strcmp(k->name, name)) return k;
    return NULL;
}

/* ---- contact kinds built from the reference objects ---- */

static const struct {
    cdist_kind kind;
    const char *file; /* the reference file whose objects are the cores */
} contact_kinds[] = {
    {CDIST_KIND_TORUS_TORUS, "cc"},     {CDIST_KIND_TORUS_CAPSULE, "sc"},   {CDIST_KIND_TORUS_SPHERE, "pc"},
    {CDIST_KIND_TORUS_ROUNDED_DISK, "cd"}, {CDIST_KIND_CAPSULE_CAPSULE, "sc"}, {CDIST_KIND_CAPSULE_SPHERE, "sc"},
    {CDIST_KIND_CAPSULE_ROUNDED_DISK, "sd"}, {CDIST_KIND_SPHERE_SPHERE, "pc"}, {CDIST_KIND_SPHERE_ROUNDED_DISK, "pd"},
    {CDIST_KIND_ROUNDED_DISK_ROUNDED_DISK, "dd"}, {CDIST_KIND_TORUS_LINE, "lc"}, {CDIST_KIND_TORUS_RAY, "rc"},
    {CDIST_KIND_TORUS_SEGMENT, "sc"},   {CDIST_KIND_CAPSULE_CIRCLE, "sc"},  {CDIST_KIND_CAPSULE_DISK, "sd"},
    {CDIST_KIND_SPHERE_CIRCLE, "pc"},   {CDIST_KIND_SPHERE_DISK, "pd"},
};

/* A radius for an object of size `scale`: 0 sometimes, else up to 1.5 scale (overlaps too). */
static double rnd_radius(double scale)
{
    unsigned k = (unsigned)(next_rand() % 8);
    return k == 0 ? 0.0 : rnd01() * 1.5 * (scale > 0 ? scale : 1.0);
}

/* The second object from a reference line's circle or disk cb: a sphere at its centre, a
 * rounded disk on it, or the circle or disk itself. */
static void second_from_circle(int sphere, int rounded_disk, const cdist_circle *cb, unsigned char *b)
{
    if (sphere) {
        cdist_sphere *s = (cdist_sphere *)b;
        s->center = cb->center;
        s->radius = rnd_radius(cb->radius);
    } else if (rounded_disk) {
        cdist_rounded_disk *r = (cdist_rounded_disk *)b;
        r->disk = *cb;
        r->radius = rnd_radius(cb->radius);
    } else {
        memcpy(b, cb, sizeof *cb);
    }
}

/* Objects of a contact kind from the two core objects of a reference line (xa, xb). */
static void build(cdist_kind kind, const unsigned char *xa, const unsigned char *xb, unsigned char *a, unsigned char *b)
{
    const cdist_circle *ca = (const cdist_circle *)xa, *cb = (const cdist_circle *)xb;
    const cdist_segment *sa = (const cdist_segment *)xa;
    const cdist_vec3 *pa = (const cdist_vec3 *)xa;
    double scale_b = cb->radius;
    switch (kind) {
    case CDIST_KIND_TORUS_TORUS:
    case CDIST_KIND_TORUS_ROUNDED_DISK:
    case CDIST_KIND_ROUNDED_DISK_ROUNDED_DISK: {
        cdist_torus *t = (cdist_torus *)a, *u = (cdist_torus *)b; /* same layout as the rounded disk */
        t->circle = *ca;
        t->tube_radius = rnd_radius(ca->radius);
        u->circle = *cb;
        u->tube_radius = rnd_radius(cb->radius);
        break;
    }
    case CDIST_KIND_TORUS_CAPSULE:
    case CDIST_KIND_TORUS_SEGMENT: { /* sc: segment, circle */
        cdist_torus *t = (cdist_torus *)a;
        t->circle = *cb;
        t->tube_radius = rnd_radius(cb->radius);
        if (kind == CDIST_KIND_TORUS_SEGMENT) {
            memcpy(b, sa, sizeof *sa);
        } else {
            cdist_capsule *k = (cdist_capsule *)b;
            k->segment = *sa;
            k->radius = rnd_radius(scale_b);
        }
        break;
    }
    case CDIST_KIND_TORUS_SPHERE: { /* pc: point, circle */
        cdist_torus *t = (cdist_torus *)a;
        cdist_sphere *s = (cdist_sphere *)b;
        t->circle = *cb;
        t->tube_radius = rnd_radius(cb->radius);
        s->center = *pa;
        s->radius = rnd_radius(scale_b);
        break;
    }
    case CDIST_KIND_CAPSULE_CAPSULE:
    case CDIST_KIND_CAPSULE_SPHERE:
    case CDIST_KIND_CAPSULE_ROUNDED_DISK:
    case CDIST_KIND_CAPSULE_CIRCLE:
    case CDIST_KIND_CAPSULE_DISK: { /* sc / sd: segment, circle or disk */
        cdist_capsule *k = (cdist_capsule *)a;
        k->segment = *sa;
        k->radius = rnd_radius(scale_b);
        if (kind == CDIST_KIND_CAPSULE_CAPSULE) {
            cdist_capsule *m = (cdist_capsule *)b;
            m->segment.p0 = cb->center;
            m->segment.p1 = (cdist_vec3){cb->center.x + cb->radius * cb->normal.x, cb->center.y + cb->radius * cb->normal.y,
                                         cb->center.z + cb->radius * cb->normal.z};
            m->radius = rnd_radius(scale_b);
        } else {
            second_from_circle(kind == CDIST_KIND_CAPSULE_SPHERE, kind == CDIST_KIND_CAPSULE_ROUNDED_DISK, cb, b);
        }
        break;
    }
    case CDIST_KIND_SPHERE_SPHERE:
    case CDIST_KIND_SPHERE_ROUNDED_DISK:
    case CDIST_KIND_SPHERE_CIRCLE:
    case CDIST_KIND_SPHERE_DISK: { /* pc / pd: point, circle or disk */
        cdist_sphere *s = (cdist_sphere *)a;
        s->center = *pa;
        s->radius = rnd_radius(scale_b);
        second_from_circle(kind == CDIST_KIND_SPHERE_SPHERE, kind == CDIST_KIND_SPHERE_ROUNDED_DISK, cb, b);
        break;
    }
    case CDIST_KIND_TORUS_LINE:
    case CDIST_KIND_TORUS_RAY: { /* lc / rc: line or ray, circle */
        cdist_torus *t = (cdist_torus *)a;
        t->circle = *cb;
        t->tube_radius = rnd_radius(cb->radius);
        memcpy(b, xa, sizeof(cdist_line));
        break;
    }
    default: break;
    }
}

/* Byte offset of the radius of a's or b's swept object (-1: a plain object). */
static long radius_offset(cdist_kind kind, int which)
{
    size_t size = which ? cdist_kind_size_b(kind) : cdist_kind_size_a(kind);
    int plain = which && kind >= CDIST_KIND_TORUS_LINE;
    return plain ? -1 : (long)size - (long)sizeof(double);
}

/* Corrupt one entry as the documented checks see it; the single query says which status. */
static void corrupt(cdist_kind kind, unsigned char *a, unsigned char *b)
{
    unsigned what = (unsigned)(next_rand() % 5);
    long off = radius_offset(kind, what & 1);
    unsigned char *obj = what & 1 ? b : a;
    double v = what < 2 ? NAN : what < 4 ? -1.0 : 1e200;
    if (what == 4 || off < 0) {
        ((double *)a)[0] = NAN; /* a coordinate of the first object */
        return;
    }
    memcpy(obj + off, &v, sizeof v);
}

static double contact_scale(const cdist_contact *c)
{
    double L = fabs(c->core_distance) + fabs(c->core_distance - c->distance);
    for (int k = 0; k < 2; k++) {
        const cdist_vec3 *p = &c->pairs[0].core_point[k];
        L = fmax(L, fmax(fabs(p->x), fmax(fabs(p->y), fabs(p->z))));
    }
    return L;
}

/* The core kernels whose distances repeat the single query's arithmetic (all but circle-circle). */
static int kernel_bit_identical(cdist_kind kind) { return kind != CDIST_KIND_TORUS_TORUS; }

static void run_contact(cdist_query *q, int ndirs, char **dirs, cdist_kind kind, const char *file, const char *set)
{
    size_t n = read_file(ndirs, dirs, file, set);
    if (n == 0) {
        printf("  %-26s %-6s (%s) not found, skipped\n", cdist_kind_name(kind), set, file);
        return;
    }
    const cdq_kind *fk = find_kind(file);
    size_t sa = cdist_kind_size_a(kind), sb = cdist_kind_size_b(kind);
    unsigned char *A = calloc(n, sa), *B = calloc(n, sb);
    int nbad = 0;
    for (size_t i = 0; i < n; i++) {
        unsigned char xa[256], xb[256];
        fk->objects(lines[i].v, xa, xb);
        build(kind, xa, xb, A + i * sa, B + i * sb);
        if (next_rand() % 100 < 4) {
            corrupt(kind, A + i * sa, B + i * sb);
            nbad++;
        }
    }
    cdist_contact *cs = malloc(n * sizeof *cs), *cb = malloc(n * sizeof *cb), *c1 = malloc(n * sizeof *c1);
    cdist_contact *cg = malloc(n * sizeof *cg);
    cdist_grad *gs = malloc(n * sizeof *gs), *gb = malloc(n * sizeof *gb), *gn = malloc(n * sizeof *gn);
    cdist_grad *g1 = malloc(n * sizeof *g1);
    cdist_status *ss = malloc(n * sizeof *ss), *st = malloc(n * sizeof *st), *s1 = malloc(n * sizeof *s1);
    double *d = malloc(n * sizeof *d), *d1 = malloc(n * sizeof *d1);
    size_t first_bad = SIZE_MAX;
    int singles_bad = 0;
    for (size_t i = 0; i < n; i++) {
        cdist_contact tmp;
        ss[i] = single_contact(q, kind, A + i * sa, B + i * sb, &cs[i]);
        cdist_status sg = single_grad(q, kind, A + i * sa, B + i * sb, &tmp, &gs[i]);
        CHECK(sg == ss[i] && !memcmp(&tmp, &cs[i], sizeof tmp), "%s: grad query differs from the contact query",
              cdist_kind_name(kind));
        if (ss[i]) {
            singles_bad++;
            if (first_bad == SIZE_MAX) first_bad = i;
        }
    }
    CHECK(singles_bad >= nbad / 2, "%s %s: only %d of %d corrupted entries failed", cdist_kind_name(kind), set,
          singles_bad, nbad);
    cdist_status want = first_bad == SIZE_MAX ? CDIST_OK : ss[first_bad];
    int identical = 0, answered = 0;
    for (int threads = 1; threads <= 2; threads++) {
        CHECK(cdist_query_set_threads(q, threads) == CDIST_OK, "threads %d", threads);
        cdist_status ret = cdist_batch_contact(q, kind, n, A, (ptrdiff_t)sa, B, (ptrdiff_t)sb, cb, st);
        CHECK(ret == want, "%s %s threads %d: contact batch returned %s, want %s", cdist_kind_name(kind), set, threads,
              cdist_status_name(ret), cdist_status_name(want));
        int mism = 0;
        for (size_t i = 0; i < n; i++) mism += memcmp(&cb[i], &cs[i], sizeof cb[i]) || st[i] != ss[i];
        CHECK(mism == 0, "%s %s threads %d: %d contacts differ from the single queries", cdist_kind_name(kind), set,
              threads, mism);
        ret = cdist_batch_grad(q, kind, n, A, (ptrdiff_t)sa, B, (ptrdiff_t)sb, cg, gb, st);
        CHECK(ret == want, "%s %s threads %d: grad batch returned %s", cdist_kind_name(kind), set, threads,
              cdist_status_name(ret));
        mism = 0;
        for (size_t i = 0; i < n; i++)
            mism += memcmp(&cg[i], &cs[i], sizeof cg[i]) || memcmp(&gb[i], &gs[i], sizeof gb[i]) || st[i] != ss[i];
        CHECK(mism == 0, "%s %s threads %d: %d gradients differ from the single queries", cdist_kind_name(kind), set,
              threads, mism);
        ret = cdist_batch_grad(q, kind, n, A, (ptrdiff_t)sa, B, (ptrdiff_t)sb, NULL, gn, NULL);
        CHECK(ret == want, "%s: grad batch without results returned %s", cdist_kind_name(kind), cdist_status_name(ret));
        mism = 0;
        for (size_t i = 0; i < n; i++) mism += memcmp(&gn[i], &gs[i], sizeof gn[i]) != 0;
        CHECK(mism == 0, "%s threads %d: %d gradients (no results) differ", cdist_kind_name(kind), threads, mism);
        ret = cdist_batch_distance(q, kind, n, A, (ptrdiff_t)sa, B, (ptrdiff_t)sb, d, st);
        CHECK(ret == want, "%s %s threads %d: distance batch returned %s", cdist_kind_name(kind), set, threads,
              cdist_status_name(ret));
        mism = 0;
        identical = answered = 0;
        for (size_t i = 0; i < n; i++) {
            int ok;
            if (ss[i]) {
                ok = isnan(d[i]) && st[i] == ss[i];
            } else {
                answered++;
                int same = !memcmp(&d[i], &cs[i].distance, sizeof d[i]);
                identical += same;
                ok = st[i] == CDIST_OK &&
                     (kernel_bit_identical(kind) ? same : fabs(d[i] - cs[i].distance) <= 4.0 * ulp(contact_scale(&cs[i])));
            }
            if (!ok && mism++ < 3)
                CHECK(0, "%s %s line %zu: distance %.17g (%s) vs single %.17g (%s)", cdist_kind_name(kind), set, i + 1,
                      d[i], cdist_status_name(st[i]), cs[i].distance, cdist_status_name(ss[i]));
        }
        CHECK(mism == 0, "%s %s threads %d: %d distances off", cdist_kind_name(kind), set, threads, mism);
        if (threads == 1) {
            memcpy(c1, cb, n * sizeof *c1);
            memcpy(g1, gb, n * sizeof *g1);
            memcpy(d1, d, n * sizeof *d1);
            memcpy(s1, st, n * sizeof *s1);
        } else {
            int diff = 0;
            for (size_t i = 0; i < n; i++)
                diff += memcmp(&cb[i], &c1[i], sizeof cb[i]) || memcmp(&gb[i], &g1[i], sizeof gb[i]) ||
                        memcmp(&d[i], &d1[i], sizeof d[i]) || st[i] != s1[i];
            CHECK(diff == 0, "%s %s: %d entries differ between 1 and 2 threads", cdist_kind_name(kind), set, diff);
        }
    }
    cdist_query_set_threads(q, 1);
    printf("  %-26s %-6s %4zu entries (%3d bad), distance-only bit-identical %d of %d\n", cdist_kind_name(kind), set, n,
           singles_bad, identical, answered);
    free(A);
    free(B);
    free(cs);
    free(cb);
    free(c1);
    free(cg);
    free(gs);
    free(gb);
    free(gn);
    free(g1);
    free(ss);
    free(st);
    free(s1);
    free(d);
    free(d1);
}

/* ---- gradients of the plain kinds ---- */

static void corrupt_plain(unsigned char *a, unsigned char *b)
{
    double *bd = (double *)b; /* every second object starts with a circle (arcs too) */
    switch (next_rand() % 3) {
    case 0: ((double *)a)[0] = NAN; break;
    case 1: bd[3] = bd[4] = bd[5] = 0.0; break;
    default: bd[6] = -1.0; break;
    }
}

static void run_plain_grad(cdist_query *q, int ndirs, char **dirs, const cdq_kind *fk, const char *set)
{
    cdist_kind kind = (cdist_kind)fk->batch_kind;
    size_t n = read_file(ndirs, dirs, fk->name, set);
    if (n == 0) return;
    size_t sa = cdist_kind_size_a(kind), sb = cdist_kind_size_b(kind);
    unsigned char *A = calloc(n, sa), *B = calloc(n, sb);
    for (size_t i = 0; i < n; i++) {
        fk->objects(lines[i].v, A + i * sa, B + i * sb);
        if (next_rand() % 100 < 4) corrupt_plain(A + i * sa, B + i * sb);
    }
    cdist_result *rs = malloc(n * sizeof *rs), *rb = malloc(n * sizeof *rb), *r1 = malloc(n * sizeof *r1);
    cdist_grad *gs = malloc(n * sizeof *gs), *gb = malloc(n * sizeof *gb), *g1 = malloc(n * sizeof *g1);
    cdist_status *ss = malloc(n * sizeof *ss), *st = malloc(n * sizeof *st);
    size_t first_bad = SIZE_MAX;
    int nbad = 0;
    for (size_t i = 0; i < n; i++) {
        ss[i] = single_grad(q, kind, A + i * sa, B + i * sb, &rs[i], &gs[i]);
        if (ss[i]) {
            nbad++;
            if (first_bad == SIZE_MAX) first_bad = i;
        }
    }
    cdist_status want = first_bad == SIZE_MAX ? CDIST_OK : ss[first_bad];
    for (int threads = 1; threads <= 2; threads++) {
        cdist_query_set_threads(q, threads);
        cdist_status ret = cdist_batch_grad(q, kind, n, A, (ptrdiff_t)sa, B, (ptrdiff_t)sb, rb, gb, st);
        CHECK(ret == want, "%s %s threads %d: grad batch returned %s, want %s", cdist_kind_name(kind), set, threads,
              cdist_status_name(ret), cdist_status_name(want));
        int mism = 0;
        for (size_t i = 0; i < n; i++)
            mism += memcmp(&rb[i], &rs[i], sizeof rb[i]) || memcmp(&gb[i], &gs[i], sizeof gb[i]) || st[i] != ss[i];
        CHECK(mism == 0, "%s %s threads %d: %d gradients differ from the single queries", cdist_kind_name(kind), set,
              threads, mism);
        if (threads == 1) {
            memcpy(r1, rb, n * sizeof *r1);
            memcpy(g1, gb, n * sizeof *g1);
        } else {
            int diff = 0;
            for (size_t i = 0; i < n; i++) diff += memcmp(&rb[i], &r1[i], sizeof rb[i]) || memcmp(&gb[i], &g1[i], sizeof gb[i]);
            CHECK(diff == 0, "%s %s: %d gradients differ between 1 and 2 threads", cdist_kind_name(kind), set, diff);
        }
    }
    cdist_query_set_threads(q, 1);
    printf("  %-26s %-6s %4zu gradients (%3d bad)\n", cdist_kind_name(kind), set, n, nbad);
    free(A);
    free(B);
    free(rs);
    free(rb);
    free(r1);
    free(gs);
    free(gb);
    free(g1);
    free(ss);
    free(st);
}

/* ---- progress and cancel ---- */

typedef struct progress_log {
    pthread_t caller;
    int calls, stop_at, wrong_thread, not_increasing;
    size_t last_done, total;
} progress_log;

static int on_progress(void *user, size_t done, size_t total)
{
    progress_log *p = user;
    p->calls++;
    p->wrong_thread += !pthread_equal(pthread_self(), p->caller);
    p->not_increasing += done <= p->last_done && p->calls > 1;
    p->last_done = done;
    p->total = total;
    return p->stop_at && p->calls >= p->stop_at;
}

static void random_torus(cdist_torus *t)
{
    t->circle.center = (cdist_vec3){4 * rnd01() - 2, 4 * rnd01() - 2, 4 * rnd01() - 2};
    t->circle.normal = rnd_unit_vec();
    t->circle.radius = 0.2 + rnd01();
    t->tube_radius = 0.1 * rnd01();
}

static void progress_cancel(cdist_query *q)
{
    enum { N = 20000, EVERY = 1000 };
    cdist_torus *ta = malloc(N * sizeof *ta), tb;
    for (int i = 0; i < N; i++) random_torus(&ta[i]);
    random_torus(&tb);
    ta[17].tube_radius = -1.0; /* one bad entry among the answered ones */
    cdist_contact *full = malloc(N * sizeof *full), *c = malloc(N * sizeof *c);
    cdist_status *sfull = malloc(N * sizeof *sfull), *st = malloc(N * sizeof *st);
    CHECK(cdist_batch_contact(q, CDIST_KIND_TORUS_TORUS, N, ta, sizeof *ta, &tb, 0, full, sfull) ==
              CDIST_ERR_NEGATIVE_RADIUS,
          "reference batch");

    CHECK(cdist_query_set_progress(q, on_progress, NULL, 0) == CDIST_ERR_BAD_OPTION, "every 0 refused");
    CHECK(cdist_query_set_progress(NULL, on_progress, NULL, 5) == CDIST_ERR_NULL_ARGUMENT, "NULL handle");
    for (int threads = 1; threads <= 2; threads++) {
        CHECK(cdist_query_set_threads(q, threads) == CDIST_OK, "threads %d", threads);
        /* to the end: reports about every EVERY entries, the last one with done == total */
        progress_log log = {pthread_self(), 0, 0, 0, 0, 0, 0};
        CHECK(cdist_query_set_progress(q, on_progress, &log, EVERY) == CDIST_OK, "set progress");
        cdist_status ret = cdist_batch_contact(q, CDIST_KIND_TORUS_TORUS, N, ta, sizeof *ta, &tb, 0, c, st);
        CHECK(ret == CDIST_ERR_NEGATIVE_RADIUS, "threads %d: full run returned %s", threads, cdist_status_name(ret));
        /* one thread: a report per 1024 entries (every rounded up to 64s) and the final one; two: the
         * calling thread reports between its own chunks (none if the other thread was faster) */
        int want_lo = threads == 1 ? N / 1024 + 1 : 1, want_hi = N / 1024 + 1;
        CHECK(log.calls >= want_lo && log.calls <= want_hi && log.last_done == N && log.total == N &&
                  !log.wrong_thread && !log.not_increasing,
              "threads %d: %d reports, last %zu of %zu, %d from another thread, %d not increasing", threads, log.calls,
              log.last_done, log.total, log.wrong_thread, log.not_increasing);
        int diff = 0;
        for (int i = 0; i < N; i++) diff += memcmp(&c[i], &full[i], sizeof c[i]) || st[i] != sfull[i];
        CHECK(diff == 0, "threads %d: progress changed %d answers", threads, diff);
        /* stopped by the third report (one thread: always; two threads: unless the other thread
         * answered nearly everything before the calling thread's third chunk, so a few tries) */
        progress_log stop = {pthread_self(), 0, 3, 0, 0, 0, 0};
        CHECK(cdist_query_set_progress(q, on_progress, &stop, EVERY) == CDIST_OK, "set progress");
        cdist_status ret_c = CDIST_OK;
        for (int attempt = 0; attempt < 20 && ret_c != CDIST_ERR_CANCELLED; attempt++) {
            stop.calls = 0;
            ret_c = cdist_batch_contact(q, CDIST_KIND_TORUS_TORUS, N, ta, sizeof *ta, &tb, 0, c, st);
            CHECK(ret_c == CDIST_ERR_CANCELLED || (threads > 1 && ret_c == CDIST_ERR_NEGATIVE_RADIUS),
                  "threads %d: a stopping callback gave %s", threads, cdist_status_name(ret_c));
        }
        CHECK(ret_c == CDIST_ERR_CANCELLED && stop.calls == 3 && !stop.wrong_thread,
              "threads %d: cancel returned %s after %d calls", threads, cdist_status_name(ret_c), stop.calls);
        CHECK(strstr(cdist_query_last_error(q), "cancelled") != NULL, "message '%s'", cdist_query_last_error(q));
        size_t k = 0;
        while (k < N && st[k] != CDIST_ERR_CANCELLED) k++;
        int bad = 0;
        for (size_t i = 0; i < k; i++) bad += memcmp(&c[i], &full[i], sizeof c[i]) || st[i] != sfull[i];
        for (size_t i = k; i < N; i++) bad += st[i] != CDIST_ERR_CANCELLED || !isnan(c[i].distance) || c[i].num_pairs != 0;
        CHECK(bad == 0 && k >= 3 * 1024 && k < N, "threads %d: %zu answered, %d wrong", threads, k, bad);
        /* the other batch calls honour it too: stopped at the first report */
        stop.stop_at = 1;
        double *d = malloc(N * sizeof *d);
        cdist_status ret_d = CDIST_OK;
        for (int attempt = 0; attempt < 20 && ret_d != CDIST_ERR_CANCELLED; attempt++) {
            stop.calls = 0;
            ret_d = cdist_batch_distance(q, CDIST_KIND_TORUS_TORUS, N, ta, sizeof *ta, &tb, 0, d, st);
        }
        CHECK(ret_d == CDIST_ERR_CANCELLED && st[N - 1] == CDIST_ERR_CANCELLED && isnan(d[N - 1]) && st[0] == CDIST_OK,
              "distance batch cancel: %s", cdist_status_name(ret_d));
        free(d);
        CHECK(cdist_query_set_progress(q, NULL, NULL, 0) == CDIST_OK, "progress off");
        int calls = stop.calls;
        ret = cdist_batch_contact(q, CDIST_KIND_TORUS_TORUS, N, ta, sizeof *ta, &tb, 0, c, st);
        CHECK(ret == CDIST_ERR_NEGATIVE_RADIUS && stop.calls == calls, "progress off: %s, %d calls",
              cdist_status_name(ret), stop.calls - calls);
    }
    CHECK(!strcmp(cdist_status_name(CDIST_ERR_CANCELLED), "CDIST_ERR_CANCELLED") &&
              !strcmp(cdist_status_name(CDIST_ERR_OVERLAP), "CDIST_ERR_OVERLAP"),
          "status names");
    cdist_query_set_threads(q, 1);
    free(ta);
    free(full);
    free(c);
    free(sfull);
    free(st);
}

/* ---- overlapping outputs ---- */

static void overlaps(cdist_query *q)
{
    enum { N = 100 };
    /* one buffer holding the inputs and, wrongly, the outputs */
    size_t bytes = N * sizeof(cdist_circle) * 2 + N * sizeof(cdist_result) + 4096;
    /* zeroed: the bytes past the inputs are compared too (an uninitialised tail is what
     * valgrind reported, not the library's structs, which have no padding) */
    unsigned char *buf = calloc(1, bytes), *copy = malloc(bytes);
    cdist_circle *a = (cdist_circle *)buf, *b = a + N;
    for (int i = 0; i < N; i++) {
        a[i] = (cdist_circle){{0.1 * i, 0, 0}, {0, 0, 1}, 1.0};
        b[i] = (cdist_circle){{0, 0.2 * i, 1}, {0, 1, 0}, 0.5};
    }
    memcpy(copy, buf, bytes);
    cdist_result *r_over_b = (cdist_result *)(void *)(b + N / 2);
    CHECK(cdist_batch(q, CDIST_KIND_CIRCLE_CIRCLE, N, a, sizeof *a, b, sizeof *b, r_over_b, NULL) == CDIST_ERR_OVERLAP,
          "results over b");
    CHECK(!memcmp(buf, copy, bytes), "an overlapping call wrote something");
    CHECK(strstr(cdist_query_last_error(q), "results") && strstr(cdist_query_last_error(q), "second object"),
          "message '%s'", cdist_query_last_error(q));
    /* negative stride: a walked backwards from its last element into the results */
    cdist_result *r_over_a = (cdist_result *)(void *)(a + 3);
    CHECK(cdist_batch(q, CDIST_KIND_CIRCLE_CIRCLE, 4, a + 3, -(ptrdiff_t)sizeof *a, b, 0, r_over_a + 0, NULL) ==
              CDIST_ERR_OVERLAP,
          "negative stride overlap");
    double *d = (double *)(void *)(b + N);
    cdist_status *st_over_d = (cdist_status *)(void *)(d + N / 2);
    CHECK(cdist_batch_distance(q, CDIST_KIND_CIRCLE_CIRCLE, N, a, sizeof *a, b, sizeof *b, d, st_over_d) ==
              CDIST_ERR_OVERLAP,
          "statuses over distances");
    cdist_grad *g = malloc(N * sizeof *g);
    CHECK(cdist_batch_grad(q, CDIST_KIND_CIRCLE_CIRCLE, N, a, sizeof *a, b, sizeof *b, (void *)g, g, NULL) ==
              CDIST_ERR_OVERLAP,
          "results over gradients");
    CHECK(!memcmp(buf, copy, bytes), "an overlapping call wrote something");
    /* right after the inputs, and inputs overlapping each other (broadcast): fine */
    cdist_result *r_after = (cdist_result *)(void *)(b + N);
    CHECK(cdist_batch(q, CDIST_KIND_CIRCLE_CIRCLE, N, a, sizeof *a, a, sizeof *a, r_after, NULL) == CDIST_OK,
          "adjacent outputs");
    CHECK(cdist_batch_grad(q, CDIST_KIND_CIRCLE_CIRCLE, N, a, sizeof *a, a + 1, 0, NULL, g, NULL) == CDIST_OK,
          "gradients only");
    /* the linking and time-of-impact batches: results or statuses over an input */
    memcpy(buf, copy, bytes);
    cdist_link *l_over_b = (cdist_link *)(void *)(b + N / 2);
    CHECK(cdist_link_circles_batch(q, N, a, sizeof *a, b, sizeof *b, l_over_b, NULL) == CDIST_ERR_OVERLAP &&
              strstr(cdist_query_last_error(q), "results"),
          "link results over b: '%s'", cdist_query_last_error(q));
    cdist_status *st_over_a = (cdist_status *)(void *)(a + 1);
    cdist_link *l_after = (cdist_link *)(void *)(b + N);
    CHECK(cdist_link_circles_batch(q, 4, a, sizeof *a, b, sizeof *b, l_after, st_over_a) == CDIST_ERR_OVERLAP &&
              strstr(cdist_query_last_error(q), "statuses"),
          "link statuses over a: '%s'", cdist_query_last_error(q));
    CHECK(!memcmp(buf, copy, bytes), "an overlapping link batch wrote something");
    CHECK(cdist_link_circles_batch(q, N, a, sizeof *a, b, sizeof *b, l_after, NULL) == CDIST_OK, "link adjacent");
    memcpy(buf, copy, bytes);
    cdist_shape *sh = (cdist_shape *)(void *)buf;
    cdist_motion *mo = (cdist_motion *)(void *)(sh + 4);
    for (int i = 0; i < 4; i++) {
        sh[i] = (cdist_shape){.type = CDIST_SHAPE_SPHERE};
        sh[i].u.sphere = (cdist_sphere){{3.0 * i, 0, 0}, 1.0};
        mo[i] = (cdist_motion){{3.0 * i, 0, 0}, {0, 1, 0}, {0, 0, 0}};
    }
    memcpy(copy, buf, bytes);
    cdist_toi_result *t_over_m = (cdist_toi_result *)(void *)(mo + 1);
    CHECK(cdist_toi_batch(q, 4, sh, sizeof *sh, mo, sizeof *mo, sh, 0, NULL, 0, 0.0, 1e-9, 100, t_over_m, NULL) ==
                  CDIST_ERR_OVERLAP &&
              strstr(cdist_query_last_error(q), "first motion"),
          "toi results over the motions: '%s'", cdist_query_last_error(q));
    CHECK(!memcmp(buf, copy, bytes), "an overlapping toi batch wrote something");
    cdist_toi_result *t_after = (cdist_toi_result *)(void *)(mo + 4);
    CHECK(cdist_toi_batch(q, 4, sh, sizeof *sh, mo, sizeof *mo, sh, 0, NULL, 0, 0.0, 1e-9, 100, t_after, NULL) ==
              CDIST_OK,
          "toi adjacent: '%s'", cdist_query_last_error(q));
    free(g);
    free(buf);
    free(copy);
}

/* ---- kinds ---- */

static void conventions(cdist_query *q)
{
    CHECK(cdist_kind_count() == 38, "kind count %d", cdist_kind_count());
    CHECK(!strcmp(cdist_kind_name(CDIST_KIND_TORUS_TORUS), "torus_torus") &&
              !strcmp(cdist_kind_name(CDIST_KIND_SPHERE_DISK), "sphere_disk") &&
              !strcmp(cdist_kind_name(CDIST_KIND_ROUNDED_DISK_ROUNDED_DISK), "rounded_disk_rounded_disk"),
          "contact kind names");
    CHECK(cdist_kind_name((cdist_kind)38) == NULL, "kind 38");
    CHECK(cdist_kind_size_a(CDIST_KIND_TORUS_CAPSULE) == sizeof(cdist_torus) &&
              cdist_kind_size_b(CDIST_KIND_TORUS_CAPSULE) == sizeof(cdist_capsule) &&
              cdist_kind_size_b(CDIST_KIND_SPHERE_DISK) == sizeof(cdist_circle),
          "contact kind sizes");
    CHECK(cdist_kind_result_size(CDIST_KIND_CIRCLE_CIRCLE) == sizeof(cdist_result) &&
              cdist_kind_result_size(CDIST_KIND_TORUS_TORUS) == sizeof(cdist_contact) &&
              cdist_kind_result_size((cdist_kind)99) == 0,
          "result sizes");
    int with_grad = 0;
    for (int k = 0; k < cdist_kind_count(); k++) with_grad += cdist_kind_has_grad((cdist_kind)k);
    CHECK(with_grad == 15 + 17 && !cdist_kind_has_grad(CDIST_KIND_HELIX_CIRCLE) && !cdist_kind_has_grad((cdist_kind)-1),
          "%d kinds with gradients", with_grad);
    /* an entry point refuses the kinds it does not answer, and says which to use */
    cdist_torus t = {{{0, 0, 0}, {0, 0, 1}, 1}, 0.1};
    cdist_result r[2];
    cdist_contact c[2];
    cdist_grad g[2];
    cdist_status st[2];
    CHECK(cdist_batch(q, CDIST_KIND_TORUS_TORUS, 2, &t, 0, &t, 0, r, st) == CDIST_ERR_BAD_KIND &&
              st[1] == CDIST_ERR_BAD_KIND && isnan(r[1].distance) && strstr(cdist_query_last_error(q), "cdist_batch_contact"),
          "cdist_batch on a contact kind: '%s'", cdist_query_last_error(q));
    CHECK(cdist_batch_contact(q, CDIST_KIND_CIRCLE_CIRCLE, 2, &t, 0, &t, 0, c, st) == CDIST_ERR_BAD_KIND &&
              isnan(c[0].distance) && c[0].num_pairs == 0,
          "cdist_batch_contact on a plain kind");
    CHECK(cdist_batch_grad(q, CDIST_KIND_HELIX_CIRCLE, 2, &t, 0, &t, 0, NULL, g, st) == CDIST_ERR_BAD_KIND &&
              isnan(g[0].obj[0].d_center.x),
          "cdist_batch_grad on a kind without gradient");
    CHECK(cdist_batch_grad(q, (cdist_kind)55, 2, &t, 0, &t, 0, r, g, st) == CDIST_ERR_BAD_KIND && st[0] == CDIST_ERR_BAD_KIND,
          "cdist_batch_grad on a bad kind");
    CHECK(cdist_batch_contact(q, CDIST_KIND_TORUS_TORUS, 2, &t, 0, &t, 0, NULL, st) == CDIST_ERR_NULL_ARGUMENT &&
              st[0] == CDIST_ERR_NULL_ARGUMENT,
          "NULL contacts");
    CHECK(cdist_batch_grad(NULL, CDIST_KIND_TORUS_TORUS, 2, &t, 0, &t, 0, c, g, st) == CDIST_ERR_NULL_ARGUMENT &&
              isnan(c[1].distance) && isnan(g[1].obj[1].d_radius),
          "NULL handle fills");
    /* the distance batch of a contact kind: the signed distance */
    cdist_torus u = {{{3, 0, 0}, {0, 0, 1}, 1}, 0.25};
    double d;
    CHECK(cdist_batch_distance(q, CDIST_KIND_TORUS_TORUS, 1, &t, 0, &u, 0, &d, NULL) == CDIST_OK &&
              fabs(d - 0.65) < 1e-15,
          "signed distance %.17g", d);
}

/* Every batch entry with each of its output arrays laid over the middle of each input array:
 * refused with CDIST_ERR_OVERLAP before anything is read or written (the inputs and every
 * output left as they were), the message naming the two arrays. */
enum { E_RESULT, E_DISTANCE, E_CONTACT, E_GRAD, E_COUNT };
static const char *const entry_name[E_COUNT] = {"cdist_batch", "cdist_batch_distance", "cdist_batch_contact",
                                                "cdist_batch_grad"};

static cdist_status call_entry(cdist_query *q, int entry, cdist_kind kind, size_t n, const void *a, ptrdiff_t sa,
                               const void *b, ptrdiff_t sb, void *out, cdist_grad *g, cdist_status *st)
{
    switch (entry) {
    case E_RESULT: return cdist_batch(q, kind, n, a, sa, b, sb, out, st);
    case E_DISTANCE: return cdist_batch_distance(q, kind, n, a, sa, b, sb, out, st);
    case E_CONTACT: return cdist_batch_contact(q, kind, n, a, sa, b, sb, out, st);
    default: return cdist_batch_grad(q, kind, n, a, sa, b, sb, out, g, st);
    }
}

static void overlaps_every_entry(cdist_query *q)
{
    enum { N = 64 };
    /* inputs first, then room for the outputs that are not under test */
    size_t in_bytes = 2 * N * sizeof(cdist_torus), out_bytes = N * (sizeof(cdist_contact) + sizeof(cdist_grad) + 64);
    unsigned char *buf = calloc(1, in_bytes + out_bytes), *copy = malloc(in_bytes + out_bytes);
    for (int entry = 0; entry < E_COUNT; entry++) {
        for (int contact = 0; contact < 2; contact++) {
            if ((entry == E_RESULT && contact) || (entry == E_CONTACT && !contact)) continue;
            cdist_kind kind = contact ? CDIST_KIND_TORUS_TORUS : CDIST_KIND_CIRCLE_CIRCLE;
            size_t so = contact ? sizeof(cdist_torus) : sizeof(cdist_circle);
            unsigned char *a = buf, *b = buf + N * so;
            for (int i = 0; i < N; i++) {
                cdist_torus ta = {{{0.1 * i, 0, 0}, {0, 0, 1}, 1.0}, 0.1}, tb = {{{0, 0.2 * i, 1}, {0, 1, 0}, 0.5}, 0.1};
                memcpy(a + i * so, &ta, so); /* a circle is a torus's first member */
                memcpy(b + i * so, &tb, so);
            }
            /* the outputs: 0 the entry's main array, 1 the gradients (cdist_batch_grad), 2 statuses */
            for (int which = 0; which < 3; which++) {
                if (which == 1 && entry != E_GRAD) continue;
                for (int over = 0; over < 2; over++) {
                    unsigned char *target = (over ? b : a) + (N / 2) * so;
                    unsigned char *free_area = buf + in_bytes;
                    void *out = which == 0 ? (void *)target : (void *)free_area;
                    cdist_grad *g = entry != E_GRAD ? NULL
                                    : which == 1    ? (cdist_grad *)(void *)target
                                                    : (cdist_grad *)(void *)(free_area + N * sizeof(cdist_contact));
                    cdist_status *st = which == 2 ? (cdist_status *)(void *)target
                                                  : (cdist_status *)(void *)(free_area + N * (sizeof(cdist_contact) +
                                                                                            sizeof(cdist_grad)));
                    memcpy(copy, buf, in_bytes + out_bytes);
                    cdist_status ret = call_entry(q, entry, kind, N, a, (ptrdiff_t)so, b, (ptrdiff_t)so, out, g, st);
                    const char *msg = cdist_query_last_error(q);
                    CHECK(ret == CDIST_ERR_OVERLAP && !memcmp(buf, copy, in_bytes + out_bytes) &&
                              strstr(msg, over ? "second object" : "first object") &&
                              strstr(msg, which == 0 ? (entry == E_DISTANCE ? "distances" : "results")
                                          : which == 1 ? "gradients"
                                                       : "statuses"),
                          "%s (%s) with output %d over the %s array: %s, '%s'", entry_name[entry],
                          cdist_kind_name(kind), which, over ? "second" : "first", cdist_status_name(ret), msg);
                }
            }
            /* the same call with every array apart is answered */
            unsigned char *free_area = buf + in_bytes;
            cdist_grad *g = entry == E_GRAD ? (cdist_grad *)(void *)(free_area + N * sizeof(cdist_contact)) : NULL;
            cdist_status *st =
                (cdist_status *)(void *)(free_area + N * (sizeof(cdist_contact) + sizeof(cdist_grad)));
            CHECK(call_entry(q, entry, kind, N, a, (ptrdiff_t)so, b, (ptrdiff_t)so, free_area, g, st) == CDIST_OK,
                  "%s (%s) with separate arrays", entry_name[entry], cdist_kind_name(kind));
        }
    }
    free(buf);
    free(copy);
}

int main(int argc, char **argv)
{
    test_rng = 0x9E3779B97F4A7C15ull;
    if (argc < 2) {
        fprintf(stderr, "usage: test_batch_contact DIR...\n");
        return 2;
    }
    cdist_query *q = cdist_query_new();
    conventions(q);
    overlaps(q);
    overlaps_every_entry(q);
    progress_cancel(q);
    const char *sets[] = {"random", "hard"};
    for (int s = 0; s < 2; s++) {
        for (size_t k = 0; k < sizeof contact_kinds / sizeof contact_kinds[0]; k++)
            run_contact(q, argc - 1, argv + 1, contact_kinds[k].kind, contact_kinds[k].file, sets[s]);
        for (const cdq_kind *fk = cdq_kinds; fk->name; fk++)
            if (fk->batch_kind >= 0 && cdist_kind_has_grad((cdist_kind)fk->batch_kind))
                run_plain_grad(q, argc - 1, argv + 1, fk, sets[s]);
    }
    cdist_query_free(q);
    return check_summary("batch-contact");
}
