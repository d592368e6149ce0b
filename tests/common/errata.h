/* SPDX-License-Identifier: MIT */
/* Errata of the shared reference: lines "FILE_BASENAME LINE EXACT # why" in tests/data/errata.txt
 * for the few lines where the shared value is demonstrably off (exact mpmath values). */
#ifndef CDIST_TEST_ERRATA_H
#define CDIST_TEST_ERRATA_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The erratum for line `lineno` of the query file `queries`, if any. */
static inline int errata_lookup(const char *errata, const char *queries, long lineno, long double *value)
{
    if (!errata) return 0;
    FILE *f = fopen(errata, "r");
    if (!f) return 0;
    const char *base = strrchr(queries, '/');
    base = base ? base + 1 : queries;
    char line[512], name[256], num[128];
    long ln;
    int found = 0;
    while (!found && fgets(line, sizeof line, f)) {
        if (sscanf(line, "%255s %ld %127s", name, &ln, num) == 3 && !strcmp(name, base) && ln == lineno) {
            *value = strtold(num, NULL);
            found = 1;
        }
    }
    fclose(f);
    return found;
}

#endif
