/* SPDX-License-Identifier: MIT */
/* circledist: answers distance queries, one output line per query line, in order. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "circledist.h"
#include "query_io.h"

enum { FMT_TEXT, FMT_JSON, FMT_TABLE };
enum { MAX_LINE = 65536 }; /* longest query line kept; the rest of a longer line is skipped */
enum { CHUNK = 4096 };     /* queries answered together with -j N > 1 */
enum { EXIT_BAD_LINES = 1, EXIT_USAGE = 2, EXIT_WRITE = 3 };

static void usage(FILE *f)
{
    fprintf(f,
            "usage: circledist [OPTION...] [FILE...|-]\n"
            "\n"
            "Reads query lines (from the FILEs, or standard input when none or '-') and writes one\n"
            "answer per query, in order. Blank lines and '#' comments are skipped.\n"
            "\n"
            "Options:\n"
            "  --method=auto|polynomial|robust|iteration\n"
            "                   algorithm for the kinds that have several (default auto)\n"
            "  --format=text    distance num_pairs equidistant, then per pair the point on the first\n"
            "                   object and the point on the second (x y z each), all %%.17g (default)\n"
            "  --format=json    one JSON object per line with the same fields plus the parameters\n"
            "                   and the method's name (a NaN parameter as null; no sqr_distance for\n"
            "                   the swept kinds' signed distance; strings always valid UTF-8)\n"
            "  --format=table   aligned columns under a header row (distance %%.17g, coordinates\n"
            "                   to 6 digits); a second pair on its own row\n"
            "  --header, --no-header\n"
            "                   text format: a first '#' line naming the columns (default: only\n"
            "                   when standard output is a terminal)\n"
            "  --normalize      scale normals, line and ray directions and helix axes to unit length\n"
            "                   (for hand-typed values such as 0.7071 0.7071 0); without it they must\n"
            "                   be unit length within 1e-6\n"
            "  -j N, --jobs=N   answer with N threads through cdist_batch (1..256; output order and\n"
            "                   values unchanged)\n"
            "  --bench=N        read all input, answer it N times without printing answers, and\n"
            "                   print ns_per_query=<fastest of the N runs> (wall time per query;\n"
            "                   with several kinds also one 'kind=K queries=Q ns_per_query=T' line each)\n"
            "  -h, --help       this text          --version   tool and library versions\n"
            "\n"
            "Input: numbers as strtod reads them. A number too large for a double, or non-zero but\n"
            "too small to be anything but 0 (1e-999), is an error; subnormal values are kept.\n"
            "Lines longer than %d bytes are skipped and reported.\n"
            "\n"
            "A bad line prints 'error: line N: REASON' in its place (JSON: {\"line\":N,\"error\":...})\n"
            "and on stderr; the other lines are still answered.\n"
            "Exit status: 0 all answered; 1 some line was bad or a file could not be opened;\n"
            "2 usage error; 3 the output could not be written (e.g. disk full).\n"
            "\n"
            "Query kinds and their numbers:\n",
            MAX_LINE);
    for (const cdq_kind *k = cdq_kinds; k->name; k++) fprintf(f, "  %-3s %-32s %s\n", k->name, k->what, k->columns);
}

/* ---- output ---- */

static void json_num(FILE *f, double x)
{
    if (isfinite(x)) fprintf(f, "%.17g", x);
    else fputs("null", f);
}

/* Length of the valid UTF-8 sequence at s (1..4), or 0 when the bytes there are not one. */
static int utf8_len(const unsigned char *s)
{
    unsigned c = s[0];
    int n = c < 0x80 ? 1 : (c & 0xE0) == 0xC0 ? 2 : (c & 0xF0) == 0xE0 ? 3 : (c & 0xF8) == 0xF0 ? 4 : 0;
    if (n <= 1) return n;
    unsigned long cp = c & (0x7Fu >> n);
    for (int i = 1; i < n; i++) {
        if ((s[i] & 0xC0) != 0x80) return 0;
        cp = (cp << 6) | (s[i] & 0x3Fu);
    }
    static const unsigned long min_cp[5] = {0, 0, 0x80, 0x800, 0x10000}; /* no overlong forms */
    if (cp < min_cp[n] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return 0;
    return n;
}

/* A JSON string: quotes, backslashes and control characters escaped, invalid UTF-8 bytes
 * replaced by U+FFFD, so the output is always valid JSON whatever the input bytes were. */
static void json_string(FILE *f, const char *str)
{
    const unsigned char *s = (const unsigned char *)str;
    fputc('"', f);
    while (*s) {
        int n = utf8_len(s);
        if (n == 0) {
            fputs("\\ufffd", f);
            s++;
        } else if (*s == '"' || *s == '\\') {
            fprintf(f, "\\%c", *s++);
        } else if (*s < 0x20 || *s == 0x7F) {
            fprintf(f, "\\u%04x", *s++);
        } else {
            fwrite(s, 1, (size_t)n, f);
            s += n;
        }
    }
    fputc('"', f);
}

static void print_result(const cdist_result *r, int fmt, long lineno, const char *kind)
{
    if (fmt == FMT_TEXT) {
        printf("%.17g %d %d", r->distance, r->num_pairs, r->equidistant);
        for (int i = 0; i < r->num_pairs; i++)
            for (int k = 0; k < 2; k++)
                printf(" %.17g %.17g %.17g", r->pairs[i].point[k].x, r->pairs[i].point[k].y, r->pairs[i].point[k].z);
        putchar('\n');
        return;
    }
    if (fmt == FMT_TABLE) { /* the distance in full; coordinates to 6 digits, to fit ~110 columns */
        for (int i = 0; i < (r->num_pairs > 0 ? r->num_pairs : 1); i++) {
            if (i == 0)
                printf("%5ld %-4s %23.17g %1d %-3s", lineno, kind, r->distance, r->num_pairs,
                       r->equidistant ? "yes" : "no");
            else
                printf("%5s %-4s %23s %1s %-3s", "", "", "", "", "");
            for (int k = 0; k < 2 && i < r->num_pairs; k++)
                printf("  %10.6g %10.6g %10.6g", r->pairs[i].point[k].x, r->pairs[i].point[k].y,
                       r->pairs[i].point[k].z);
            putchar('\n');
        }
        return;
    }
    printf("{\"line\":%ld,\"kind\":\"%s\",\"distance\":", lineno, kind);
    json_num(stdout, r->distance);
    if (!isnan(r->sqr_distance) || isnan(r->distance)) { /* a contact's signed distance has no square */
        printf(",\"sqr_distance\":");
        json_num(stdout, r->sqr_distance);
    }
    printf(",\"num_pairs\":%d,\"equidistant\":%s,\"pairs\":[", r->num_pairs, r->equidistant ? "true" : "false");
    for (int i = 0; i < r->num_pairs; i++) {
        printf("%s{\"points\":[", i ? "," : "");
        for (int k = 0; k < 2; k++) {
            const cdist_vec3 *p = &r->pairs[i].point[k];
            printf("%s[", k ? "," : "");
            json_num(stdout, p->x);
            putchar(',');
            json_num(stdout, p->y);
            putchar(',');
            json_num(stdout, p->z);
            putchar(']');
        }
        printf("],\"params\":[");
        json_num(stdout, r->pairs[i].param[0]);
        putchar(',');
        json_num(stdout, r->pairs[i].param[1]);
        printf("]}");
    }
    printf("],\"method\":\"%s\"}\n", cdist_method_name(r->method));
}

static void print_header(int fmt, int header)
{
    if (fmt == FMT_TABLE) {
        printf("%5s %-4s %23s %1s %-3s  %10s %10s %10s  %10s %10s %10s\n", "line", "kind", "distance", "n", "eq",
               "x0", "y0", "z0", "x1", "y1", "z1");
    } else if (fmt == FMT_TEXT && header) {
        printf("# distance num_pairs equidistant then per pair: x0 y0 z0 (first object) x1 y1 z1 (second)\n");
    }
}

static void print_error(int fmt, const char *file, long lineno, const char *reason)
{
    if (fmt == FMT_JSON) {
        printf("{\"line\":%ld,\"error\":", lineno);
        json_string(stdout, reason);
        printf("}\n");
    } else if (fmt == FMT_TABLE) {
        printf("%6ld error: %s\n", lineno, reason);
    } else {
        printf("error: line %ld: %s\n", lineno, reason);
    }
    fprintf(stderr, "circledist: %s: error: line %ld: %s\n", file, lineno, reason);
}

/* ---- input ---- */

/* One input line in buf (NUL-terminated, at most MAX_LINE bytes kept). Returns 0 at end of
 * input. *too_long: the line was longer (the rest was read and dropped, never stored);
 * *has_nul: it contained a NUL byte. */
static int read_line(FILE *in, char *buf, int *too_long, int *has_nul)
{
    size_t n = 0;
    int c, any = 0;
    *too_long = *has_nul = 0;
    while ((c = getc_unlocked(in)) != EOF) { /* one thread reads: no per-byte lock */
        any = 1;
        if (c == '\n') break;
        if (c == '\0') *has_nul = 1;
        if (n < MAX_LINE) buf[n++] = (char)c;
        else *too_long = 1;
    }
    buf[n] = '\0';
    return any;
}

/* A query line read: a parsed query, or the reason it is bad. */
typedef struct item {
    long lineno;
    const char *file;
    int bad;
    char err[400];
    cdq_line ql;
} item;

/* Reads the next non-blank line of `in` into *it. Returns 0 at end of input. */
static int next_item(FILE *in, const char *file, long *lineno, char *buf, int normalize, item *it)
{
    int too_long, has_nul;
    while (read_line(in, buf, &too_long, &has_nul)) {
        ++*lineno;
        it->lineno = *lineno;
        it->file = file;
        it->bad = 1;
        if (too_long) {
            snprintf(it->err, sizeof it->err, "line is longer than %d bytes (skipped)", MAX_LINE);
            return 1;
        }
        if (has_nul) {
            snprintf(it->err, sizeof it->err, "line contains a NUL byte");
            return 1;
        }
        int k = cdq_parse(buf, &it->ql, it->err, sizeof it->err);
        if (k == 0) continue;
        it->bad = k < 0;
        if (!it->bad && normalize) cdq_normalize(&it->ql);
        return 1;
    }
    return 0;
}

/* ---- answering ---- */

typedef struct settings {
    cdist_method method;
    int fmt, header, normalize, jobs, bench;
} settings;

static cdist_query *new_handle(const settings *s)
{
    cdist_query *q = cdist_query_new();
    if (q) cdist_query_set_method(q, s->method);
    return q;
}

/* The reason for a failed query, with the CLI's way out for non-unit vectors. */
static void failure_reason(cdist_query *q, cdist_status st, char *err, size_t len)
{
    char msg[200];
    snprintf(msg, sizeof msg, "%.199s", cdist_query_last_error(q));
    if (st == CDIST_ERR_NOT_UNIT) {
        char *see = strstr(msg, "; see "); /* names a C function: not for the command line */
        if (see) snprintf(see, sizeof msg - (size_t)(see - msg), ")");
        snprintf(err, len, "%s (%s); run with --normalize to scale normals and directions to unit length", msg,
                 cdist_status_name(st));
    } else {
        snprintf(err, len, "%s (%s)", msg, cdist_status_name(st));
    }
}

/* Batch buffers for -j N > 1: the objects of one kind, gathered from a chunk. */
typedef struct batch_buf {
    char *a, *b;
    size_t *index;
    cdist_result *res;
    cdist_status *st;
} batch_buf;

static int batch_buf_init(batch_buf *bb, size_t n)
{
    size_t sa = 0, sb = 0;
    for (const cdq_kind *k = cdq_kinds; k->name; k++) {
        size_t x = cdist_kind_size_a((cdist_kind)k->batch_kind), y = cdist_kind_size_b((cdist_kind)k->batch_kind);
        sa = x > sa ? x : sa;
        sb = y > sb ? y : sb;
    }
    bb->a = malloc(n * sa);
    bb->b = malloc(n * sb);
    bb->index = malloc(n * sizeof *bb->index);
    bb->res = malloc(n * sizeof *bb->res);
    bb->st = malloc(n * sizeof *bb->st);
    return bb->a && bb->b && bb->index && bb->res && bb->st;
}

static void batch_buf_free(batch_buf *bb)
{
    free(bb->a);
    free(bb->b);
    free(bb->index);
    free(bb->res);
    free(bb->st);
}

/* Answers items[0..n) (bad items are skipped). One thread: single queries. Several: the
 * items of each kind go through cdist_batch(), which uses the handle's worker threads
 * (results do not depend on the thread count); the per-entry error messages of failed
 * entries come from answering them once more alone. */
static void answer(item *items, size_t n, cdist_result *res, cdist_status *st, cdist_query *q, int jobs,
                   batch_buf *bb)
{
    for (size_t i = 0; i < n; i++) { /* kinds without a batch kind (swept): single queries */
        if (items[i].bad || (jobs > 1 && items[i].ql.kind->objects)) continue;
        st[i] = cdq_run(q, &items[i].ql, &res[i]);
        if (st[i] != CDIST_OK) failure_reason(q, st[i], items[i].err, sizeof items[i].err);
    }
    if (jobs <= 1) return;
    for (const cdq_kind *k = cdq_kinds; k->name; k++) {
        if (!k->objects) continue;
        cdist_kind kind = (cdist_kind)k->batch_kind;
        size_t sa = cdist_kind_size_a(kind), sb = cdist_kind_size_b(kind), m = 0;
        for (size_t i = 0; i < n; i++) {
            if (items[i].bad || items[i].ql.kind != k) continue;
            k->objects(items[i].ql.v, bb->a + m * sa, bb->b + m * sb);
            bb->index[m++] = i;
        }
        if (m == 0) continue;
        cdist_batch(q, kind, m, bb->a, (ptrdiff_t)sa, bb->b, (ptrdiff_t)sb, bb->res, bb->st);
        for (size_t j = 0; j < m; j++) {
            size_t i = bb->index[j];
            res[i] = bb->res[j];
            st[i] = bb->st[j];
            if (st[i] != CDIST_OK) {
                cdist_result again;
                failure_reason(q, cdq_run(q, &items[i].ql, &again), items[i].err, sizeof items[i].err);
            }
        }
    }
}

static int stdout_failed(void) { return ferror(stdout) != 0; }

/* Answers and prints the items of one input. Returns the number of bad lines. */
static long process(FILE *in, const char *name, const settings *s, cdist_query *q, item *items,
                    cdist_result *res, cdist_status *st, batch_buf *bb, char *buf)
{
    long lineno = 0, bad = 0;
    size_t chunk = s->jobs > 1 ? CHUNK : 1; /* -j1 streams: each answer as soon as it is read */
    for (;;) {
        size_t n = 0;
        while (n < chunk && next_item(in, name, &lineno, buf, s->normalize, &items[n])) n++;
        if (n == 0) break;
        answer(items, n, res, st, q, s->jobs, bb);
        for (size_t i = 0; i < n; i++) {
            if (items[i].bad || st[i] != CDIST_OK) {
                print_error(s->fmt, name, items[i].lineno, items[i].err);
                bad++;
            } else {
                print_result(&res[i], s->fmt, items[i].lineno, items[i].ql.kind->name);
            }
        }
        if (stdout_failed()) break;
    }
    if (ferror(in)) {
        fprintf(stderr, "circledist: %s: read error: %s\n", name, strerror(errno));
        bad++;
    }
    return bad;
}

/* ---- --bench ---- */

static double wall(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Fastest of `runs` answers of items[0..n), in ns per query. */
static double time_items(item *items, size_t n, cdist_result *res, cdist_status *st, cdist_query *q, int jobs,
                         batch_buf *bb, int runs)
{
    double best = INFINITY;
    for (int r = 0; r < runs; r++) {
        double t0 = wall();
        answer(items, n, res, st, q, jobs, bb);
        best = fmin(best, wall() - t0);
    }
    return 1e9 * best / (double)n;
}

/* Allocation for the tool's own buffers: out of memory ends the tool with the usage status. */
static void *xrealloc(void *p, size_t size)
{
    void *r = realloc(p, size ? size : 1);
    if (!r) {
        fprintf(stderr, "circledist: out of memory\n");
        exit(EXIT_USAGE);
    }
    return r;
}

static int bench(const settings *s, const char **files, int nfiles, cdist_query *q, char *buf)
{
    size_t n = 0, cap = 1024;
    item *items = xrealloc(NULL, cap * sizeof *items);
    long bad = 0;
    int failed_open = 0;
    for (int i = 0; i < nfiles; i++) {
        const char *a = files[i];
        FILE *f = strcmp(a, "-") ? fopen(a, "r") : stdin;
        if (!f) {
            fprintf(stderr, "circledist: cannot open '%s': %s\n", a, strerror(errno));
            failed_open = 1;
            continue;
        }
        long lineno = 0;
        for (;;) {
            if (n == cap) items = xrealloc(items, (cap *= 2) * sizeof *items);
            if (!next_item(f, a, &lineno, buf, s->normalize, &items[n])) break;
            if (items[n].bad) {
                fprintf(stderr, "circledist: %s: error: line %ld: %s\n", a, items[n].lineno, items[n].err);
                bad++;
            } else {
                n++;
            }
        }
        if (f != stdin) fclose(f);
    }
    if (n == 0) {
        fprintf(stderr, "circledist: --bench: no queries\n");
        free(items);
        return EXIT_BAD_LINES;
    }
    cdist_result *res = xrealloc(NULL, n * sizeof *res);
    cdist_status *st = xrealloc(NULL, n * sizeof *st);
    batch_buf bb = {0};
    if (s->jobs > 1 && !batch_buf_init(&bb, n)) {
        fprintf(stderr, "circledist: out of memory\n");
        exit(EXIT_USAGE);
    }
    double t = time_items(items, n, res, st, q, s->jobs, &bb, s->bench);
    for (size_t i = 0; i < n; i++)
        if (st[i] != CDIST_OK) {
            fprintf(stderr, "circledist: %s: error: line %ld: %s\n", items[i].file, items[i].lineno, items[i].err);
            bad++;
        }
    printf("ns_per_query=%.1f queries=%zu runs=%d threads=%d\n", t, n, s->bench, s->jobs);
    /* per kind when mixed: each kind's queries gathered in input order and timed alone */
    int kinds = 0;
    for (const cdq_kind *k = cdq_kinds; k->name; k++) {
        size_t m = 0;
        for (size_t i = 0; i < n; i++) m += items[i].ql.kind == k;
        kinds += m > 0;
    }
    if (kinds > 1) {
        item *sub = xrealloc(NULL, n * sizeof *sub);
        for (const cdq_kind *k = cdq_kinds; k->name; k++) {
            size_t m = 0;
            for (size_t i = 0; i < n; i++)
                if (items[i].ql.kind == k) sub[m++] = items[i];
            if (m)
                printf("kind=%s queries=%zu ns_per_query=%.1f\n", k->name, m,
                       time_items(sub, m, res, st, q, s->jobs, &bb, s->bench));
        }
        free(sub);
    }
    batch_buf_free(&bb);
    free(items);
    free(res);
    free(st);
    return (bad || failed_open) ? EXIT_BAD_LINES : 0;
}

/* ---- main ---- */

/* A whole number in [1, max], else 0. */
static int parse_count(const char *v, long max)
{
    char *end;
    errno = 0;
    long j = strtol(v, &end, 10);
    return (errno || end == v || *end || j < 1 || j > max) ? 0 : (int)j;
}

static int parse_jobs(const char *v) { return parse_count(v, 256); }

/* Flushes and closes standard output; a write error (disk full, closed pipe) is reported. */
static int finish_output(void)
{
    int failed = stdout_failed();
    int e = errno;
    if (fflush(stdout) != 0) failed = 1, e = errno;
    if (fclose(stdout) != 0 && !failed) failed = 1, e = errno;
    if (failed) fprintf(stderr, "circledist: cannot write the output: %s\n", e ? strerror(e) : "write error");
    return failed;
}

int main(int argc, char **argv)
{
    settings s = {CDIST_METHOD_AUTO, FMT_TEXT, isatty(STDOUT_FILENO), 0, 1, 0};
    int nfiles = 0, opts_done = 0;
    const char **files = malloc((size_t)(argc + 1) * sizeof *files);
    if (!files) return EXIT_USAGE;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (opts_done || a[0] != '-' || !strcmp(a, "-")) {
            files[nfiles++] = a;
            continue;
        }
        if (!strcmp(a, "--")) opts_done = 1;
        else if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            free(files);
            usage(stdout);
            return finish_output() ? EXIT_WRITE : 0;
        } else if (!strcmp(a, "--version")) {
            free(files);
            printf("circledist %s (libcircledist %s)\n", CDIST_VERSION_STRING, cdist_version_string());
            return finish_output() ? EXIT_WRITE : 0;
        }
        else if (!strcmp(a, "--format=text")) s.fmt = FMT_TEXT;
        else if (!strcmp(a, "--format=json")) s.fmt = FMT_JSON;
        else if (!strcmp(a, "--format=table")) s.fmt = FMT_TABLE;
        else if (!strcmp(a, "--header")) s.header = 1;
        else if (!strcmp(a, "--no-header")) s.header = 0;
        else if (!strcmp(a, "--normalize")) s.normalize = 1;
        else if (!strcmp(a, "--method=auto")) s.method = CDIST_METHOD_AUTO;
        else if (!strcmp(a, "--method=polynomial")) s.method = CDIST_METHOD_POLYNOMIAL;
        else if (!strcmp(a, "--method=robust")) s.method = CDIST_METHOD_ROBUST;
        else if (!strcmp(a, "--method=iteration")) s.method = CDIST_METHOD_ITERATION;
        else if ((!strcmp(a, "-j") && i + 1 < argc && (s.jobs = parse_jobs(argv[++i]))) ||
                 (!strncmp(a, "-j", 2) && a[2] && (s.jobs = parse_jobs(a + 2))) ||
                 (!strncmp(a, "--jobs=", 7) && (s.jobs = parse_jobs(a + 7)))) {
        } else if (!strncmp(a, "--bench=", 8) && (s.bench = parse_count(a + 8, 1000000)) > 0) {
        } else {
            if (!strncmp(a, "-j", 2) || !strncmp(a, "--jobs", 6))
                fprintf(stderr, "circledist: bad value in '%s' (a number from 1 to 256 is needed)\n", a);
            else if (!strncmp(a, "--bench", 7))
                fprintf(stderr, "circledist: bad value in '%s' (a number of runs from 1 to 1000000 is needed)\n", a);
            else
                fprintf(stderr, "circledist: unknown option '%s'\n", a);
            free(files);
            usage(stderr);
            return EXIT_USAGE;
        }
    }
    if (nfiles == 0) files[nfiles++] = "-";
    cdist_query *q = new_handle(&s);
    if (!q || (s.jobs > 1 && cdist_query_set_threads(q, s.jobs) != CDIST_OK)) {
        fprintf(stderr, "circledist: cannot set up the query handle%s%s\n", q ? ": " : "",
                q ? cdist_query_last_error(q) : "");
        return EXIT_USAGE;
    }
    char *buf = malloc(MAX_LINE + 1);
    size_t chunk = s.jobs > 1 ? CHUNK : 1;
    item *items = malloc(chunk * sizeof *items);
    cdist_result *res = malloc(chunk * sizeof *res);
    cdist_status *st = malloc(chunk * sizeof *st);
    batch_buf bb = {0};
    if (!buf || !items || !res || !st || (s.jobs > 1 && !batch_buf_init(&bb, chunk))) {
        fprintf(stderr, "circledist: out of memory\n");
        return EXIT_USAGE;
    }
    int rc;
    if (s.bench) {
        rc = bench(&s, files, nfiles, q, buf);
    } else {
        long bad = 0;
        int open_failed = 0;
        print_header(s.fmt, s.header);
        for (int i = 0; i < nfiles && !stdout_failed(); i++) {
            FILE *f = strcmp(files[i], "-") ? fopen(files[i], "r") : stdin;
            if (!f) {
                fprintf(stderr, "circledist: cannot open '%s': %s\n", files[i], strerror(errno));
                open_failed = 1;
                continue;
            }
            bad += process(f, files[i], &s, q, items, res, st, &bb, buf);
            if (f != stdin) fclose(f);
        }
        rc = (bad || open_failed) ? EXIT_BAD_LINES : 0;
    }
    free(files);
    cdist_query_free(q);
    batch_buf_free(&bb);
    free(buf);
    free(items);
    free(res);
    free(st);
    if (finish_output()) rc = EXIT_WRITE;
    return rc;
}
