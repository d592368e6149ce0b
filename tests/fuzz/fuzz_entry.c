/* Fuzz target for the parser and every public entry point.
 * - libFuzzer: clang -fsanitize=fuzzer,address (meson -Dfuzz=true... see README) uses
 *   LLVMFuzzerTestOneInput directly.
 * - Otherwise a main() drives it with deterministic pseudo-random inputs (a smoke test).
 * The input is read two ways: as query text for the tool's parser, and as raw doubles (any bit
 * pattern: NaN, Inf, subnormal, huge) for every query function. Invariants checked: no crash;
 * OK results have a finite distance >= 0 and 1-2 pairs; errors leave NaN and no pairs. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "circledist.h"
#include "query_io.h"

static cdist_query *q;

/* Swept kinds (upper-case tool names, src/swept) give signed distances (negative = overlap). */
static int signed_kind(const cdq_line *ql) { return ql && ql->kind->name[0] >= 'A' && ql->kind->name[0] <= 'Z'; }

static void check_result_kind(cdist_status st, const cdist_result *r, int is_signed)
{
    if (st == CDIST_OK) {
        if (!(is_signed || r->distance >= 0.0) || !isfinite(r->distance) || r->num_pairs < 1 || r->num_pairs > 2)
            abort();
    } else {
        if (!isnan(r->distance) || r->num_pairs != 0) abort();
        if (cdist_query_last_error(q)[0] == '\0') abort();
    }
}

static void check_result(cdist_status st, const cdist_result *r) { check_result_kind(st, r, 0); }

static int fuzz_curve(void *user, double t, cdist_vec3 *p, cdist_vec3 *d)
{
    const double *v = user;
    p->x = v[0] + t * v[3];
    p->y = v[1] + t * v[4];
    p->z = v[2] + t * v[5];
    *d = (cdist_vec3){v[3], v[4], v[5]};
    return v[6] > 1e300 ? 1 : 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (!q) q = cdist_query_new();
    if (size < 1) return 0;
    cdist_query_set_method(q, (cdist_method)(data[0] % 4));
    /* 1. As text. */
    char *text = malloc(size + 1);
    memcpy(text, data, size);
    text[size] = '\0';
    cdq_line ql;
    char err[256];
    char *save = NULL;
    for (char *line = strtok_r(text, "\n", &save); line; line = strtok_r(NULL, "\n", &save)) {
        if (cdq_parse(line, &ql, err, sizeof err) == 1) {
            cdist_result r;
            check_result_kind(cdq_run(q, &ql, &r), &r, signed_kind(&ql));
        }
    }
    free(text);
    /* 2. As raw doubles, for every query kind. */
    double v[CDQ_MAX_VALUES] = {0};
    size_t nd = (size - 1) / sizeof(double);
    if (nd > CDQ_MAX_VALUES) nd = CDQ_MAX_VALUES;
    memcpy(v, data + 1, nd * sizeof(double));
    for (const cdq_kind *k = cdq_kinds; k->name; k++) {
        ql.kind = k;
        ql.nvalues = k->nvalues;
        memcpy(ql.v, v, sizeof v);
        cdist_result r;
        check_result_kind(cdq_run(q, &ql, &r), &r, signed_kind(&ql));
    }
    cdist_result r;
    cdist_circle c = {{v[7], v[8], v[9]}, {v[10], v[11], v[12]}, v[13]};
    check_result(cdist_curve_circle(q, fuzz_curve, v, v[14], v[15], &c, &r), &r);
    check_result(cdist_curve_disk(q, fuzz_curve, v, v[14], v[15], &c, &r), &r);
    return 0;
}

#ifndef CDIST_LIBFUZZER
/* Smoke driver: mutated valid lines plus raw random doubles with special values. */
static uint64_t rng = 0x1234567887654321ull;
static uint64_t next(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return rng;
}

int main(int argc, char **argv)
{
    long iters = argc > 1 ? atol(argv[1]) : 3000;
    static const double special[] = {0.0, -0.0, 1.0, -1.0, 1e-300, 1e300, 1e151, 1e149, INFINITY, -INFINITY,
                                     NAN, 5e-324, 0.5, 2.0, 1e-8, 3.0};
    uint8_t buf[1 + CDQ_MAX_VALUES * sizeof(double)];
    for (long i = 0; i < iters; i++) {
        double v[CDQ_MAX_VALUES];
        for (int k = 0; k < CDQ_MAX_VALUES; k++) {
            uint64_t x = next();
            if (x % 4 == 0) v[k] = special[(x >> 8) % (sizeof special / sizeof special[0])];
            else if (x % 4 == 1) memcpy(&v[k], &x, sizeof x); /* any bit pattern */
            else v[k] = ((double)(x >> 11) / 9007199254740992.0) * 4 - 2;
        }
        /* Unit normals most of the time, so deep paths are reached. */
        if (i % 2) {
            for (int k = 0; k + 2 < CDQ_MAX_VALUES; k += 7) {
                double n = sqrt(v[k] * v[k] + v[k + 1] * v[k + 1] + v[k + 2] * v[k + 2]);
                if (n > 0 && isfinite(n)) v[k] /= n, v[k + 1] /= n, v[k + 2] /= n;
            }
        }
        buf[0] = (uint8_t)next();
        memcpy(buf + 1, v, sizeof v);
        LLVMFuzzerTestOneInput(buf, sizeof buf);
        char line[512];
        int n = snprintf(line, sizeof line, "%s %.17g %.3g %g nan 1e999 -- %c\n", cdq_kinds[next() % 19].name, v[0],
                         v[1], v[2], (char)(next() % 256));
        LLVMFuzzerTestOneInput((const uint8_t *)line, (size_t)n);
    }
    cdist_query_free(q);
    printf("fuzz_smoke: %ld passed, 0 failed\n", iters);
    return 0;
}
#endif
