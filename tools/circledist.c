/* SPDX-License-Identifier: MIT */
/* circledist: answers distance queries, one output line per query line, in order. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "circledist.h"
#include "query_io.h"

enum { FMT_TEXT, FMT_JSON };

static void usage(FILE *f)
{
    fprintf(f,
            "usage: circledist [--method=auto|polynomial|robust|iteration] [--format=text|json] [FILE...|-]\n"
            "\n"
            "Reads query lines (from the FILEs, or standard input when none or '-') and writes one\n"
            "line per query, in order. Blank lines and '#' comments are skipped.\n"
            "\n"
            "Text output: distance num_pairs equidistant, then for each pair the point on the first\n"
            "object and the point on the second (x y z each), all %%.17g.\n"
            "JSON output: one object per line with the same fields plus the parameters.\n"
            "A bad line prints 'error: line N: REASON' in its place (JSON: {\"line\":N,\"error\":...})\n"
            "and on stderr; the other lines are still answered and the exit status is 1.\n"
            "\n"
            "Query kinds and their numbers:\n");
    for (const cdq_kind *k = cdq_kinds; k->name; k++) fprintf(f, "  %-3s %-32s %s\n", k->name, k->what, k->columns);
    fprintf(f, "Normals and directions must be unit length (within 1e-6).\n");
}

static void json_num(FILE *f, double x)
{
    if (isfinite(x)) fprintf(f, "%.17g", x);
    else fputs("null", f);
}

static void json_string(FILE *f, const char *s)
{
    fputc('"', f);
    for (; *s; s++) {
        unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\') fprintf(f, "\\%c", c);
        else if (c < 0x20) fprintf(f, "\\u%04x", c);
        else fputc(c, f);
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
    printf("{\"line\":%ld,\"kind\":\"%s\",\"distance\":", lineno, kind);
    json_num(stdout, r->distance);
    printf(",\"sqr_distance\":");
    json_num(stdout, r->sqr_distance);
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
    printf("],\"method\":%d}\n", r->method);
}

static void print_error(int fmt, const char *file, long lineno, const char *reason)
{
    if (fmt == FMT_TEXT) {
        printf("error: line %ld: %s\n", lineno, reason);
    } else {
        printf("{\"line\":%ld,\"error\":", lineno);
        json_string(stdout, reason);
        printf("}\n");
    }
    fprintf(stderr, "circledist: %s: error: line %ld: %s\n", file, lineno, reason);
}

/* Returns the number of bad lines. */
static long process(FILE *in, const char *name, cdist_query *q, int fmt)
{
    char *line = NULL;
    size_t cap = 0;
    long lineno = 0, bad = 0;
    ssize_t len;
    while ((len = getline(&line, &cap, in)) >= 0) {
        lineno++;
        cdq_line ql;
        char err[256];
        int k;
        if (strlen(line) != (size_t)len) {
            snprintf(err, sizeof err, "line contains a NUL byte");
            k = -1;
        } else {
            k = cdq_parse(line, &ql, err, sizeof err);
        }
        if (k == 0) continue;
        if (k < 0) {
            print_error(fmt, name, lineno, err);
            bad++;
            continue;
        }
        cdist_result r;
        cdist_status st = cdq_run(q, &ql, &r);
        if (st != CDIST_OK) {
            snprintf(err, sizeof err, "%s (%s)", cdist_query_last_error(q), cdist_status_name(st));
            print_error(fmt, name, lineno, err);
            bad++;
            continue;
        }
        print_result(&r, fmt, lineno, ql.kind->name);
    }
    free(line);
    if (ferror(in)) {
        fprintf(stderr, "circledist: %s: read error\n", name);
        bad++;
    }
    return bad;
}

int main(int argc, char **argv)
{
    int fmt = FMT_TEXT;
    cdist_method method = CDIST_METHOD_AUTO;
    int nfiles = 0, opts_done = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (opts_done || a[0] != '-' || !strcmp(a, "-")) {
            nfiles++;
            continue;
        }
        if (!strcmp(a, "--")) opts_done = 1;
        else if (!strcmp(a, "--help") || !strcmp(a, "-h")) { usage(stdout); return 0; }
        else if (!strcmp(a, "--version")) {
            printf("circledist %s (libcircledist %s)\n", CDIST_VERSION_STRING, cdist_version_string());
            return 0;
        }
        else if (!strcmp(a, "--format=text")) fmt = FMT_TEXT;
        else if (!strcmp(a, "--format=json")) fmt = FMT_JSON;
        else if (!strcmp(a, "--method=auto")) method = CDIST_METHOD_AUTO;
        else if (!strcmp(a, "--method=polynomial")) method = CDIST_METHOD_POLYNOMIAL;
        else if (!strcmp(a, "--method=robust")) method = CDIST_METHOD_ROBUST;
        else if (!strcmp(a, "--method=iteration")) method = CDIST_METHOD_ITERATION;
        else {
            fprintf(stderr, "circledist: unknown option '%s'\n", a);
            usage(stderr);
            return 2;
        }
    }
    cdist_query *q = cdist_query_new();
    if (!q) {
        fprintf(stderr, "circledist: out of memory\n");
        return 2;
    }
    cdist_query_set_method(q, method);
    long bad = 0;
    int open_failed = 0;
    if (nfiles == 0) bad += process(stdin, "-", q, fmt);
    opts_done = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!opts_done && a[0] == '-' && strcmp(a, "-")) {
            if (!strcmp(a, "--")) opts_done = 1;
            continue;
        }
        if (!strcmp(a, "-")) {
            bad += process(stdin, "-", q, fmt);
            continue;
        }
        FILE *f = fopen(a, "r");
        if (!f) {
            fprintf(stderr, "circledist: cannot open '%s'\n", a);
            open_failed = 1;
            continue;
        }
        bad += process(f, a, q, fmt);
        fclose(f);
    }
    cdist_query_free(q);
    fflush(stdout);
    return (bad || open_failed) ? 1 : 0;
}
