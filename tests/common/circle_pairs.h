/* SPDX-License-Identifier: MIT */
/* Pairs of circles for the circle kernels' tests: read from a reference file, and made bad in
 * one of the documented ways. Needs query_io.h, check.h and test_rand.h first. */
#ifndef CDIST_TEST_CIRCLE_PAIRS_H
#define CDIST_TEST_CIRCLE_PAIRS_H

#include <math.h>
#include <stdio.h>
#include <string.h>

/* The pairs of the file at path appended to A, B from n (up to max); returns the new count. */
static inline size_t load_circle_pairs(const char *path, cdist_circle *A, cdist_circle *B, size_t n, size_t max)
{
    char buf[2048], err[256];
    FILE *f = fopen(path, "r");
    CHECK(f != NULL, "cannot read %s", path);
    while (f && n < max && fgets(buf, sizeof buf, f)) {
        cdq_line ql;
        if (cdq_parse(buf, &ql, err, sizeof err) <= 0) continue;
        memcpy(&A[n], ql.v, sizeof A[n]);
        memcpy(&B[n], ql.v + 7, sizeof B[n]);
        n++;
    }
    if (f) fclose(f);
    return n;
}

/* One of the documented bad inputs, in a or b. */
static inline void corrupt_circle_pair(cdist_circle *a, cdist_circle *b)
{
    cdist_circle *c = (next_rand() & 1) ? a : b;
    switch (next_rand() % 7) {
    case 0: c->center.y = NAN; break;
    case 1: c->normal.z = INFINITY; break;
    case 2: c->normal = (cdist_vec3){0, 0, 0}; break;
    case 3: c->normal.x *= 1.01; break;
    case 4: c->radius = -1.0; break;
    case 5: c->center.x = 2e150; break;
    default: c->radius = NAN; break;
    }
}

#endif
