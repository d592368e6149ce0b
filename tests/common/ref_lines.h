/* SPDX-License-Identifier: MIT */
/* Reading a reference pair of files: a query file in the tool's format and its expected
 * distances, one line each for the lines that parse. */
#ifndef CDIST_TEST_REF_LINES_H
#define CDIST_TEST_REF_LINES_H

#include <stdio.h>
#include <stdlib.h>

#include "query_io.h"

/* The next query of fq that parses, into *ql, and its expected distance (the next line of fe),
 * into *expected; *lineno counts the lines of fq read. 0 at the end of either file. */
static inline int ref_next(FILE *fq, FILE *fe, cdq_line *ql, long double *expected, long *lineno)
{
    char line[4096], eline[256], err[256];
    while (fgets(line, sizeof line, fq)) {
        ++*lineno;
        if (cdq_parse(line, ql, err, sizeof err) != 1) continue;
        if (!fgets(eline, sizeof eline, fe)) return 0;
        *expected = strtold(eline, NULL);
        return 1;
    }
    return 0;
}

#endif
