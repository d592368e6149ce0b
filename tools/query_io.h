/* SPDX-License-Identifier: MIT */
/* Query-line parsing and dispatch shared by the circledist tool and the tests.
 * Line format: KIND then whitespace-separated numbers; '#' starts a comment. */
#ifndef CDIST_QUERY_IO_H
#define CDIST_QUERY_IO_H

#include <stddef.h>

#include "circledist.h"

#define CDQ_MAX_VALUES 24

typedef struct cdq_kind {
    const char *name;    /* e.g. "cc" */
    int nvalues;         /* numbers after the kind */
    const char *columns; /* human-readable column list */
    const char *what;    /* human-readable description */
} cdq_kind;

typedef struct cdq_line {
    const cdq_kind *kind;
    int nvalues;
    double v[CDQ_MAX_VALUES];
} cdq_line;

/* The table of kinds, terminated by an entry with name NULL. */
extern const cdq_kind cdq_kinds[];

/* Parse one line. Returns 1 for a query, 0 for a blank or comment line, -1 for a bad line
 * (reason written to err). */
int cdq_parse(const char *line, cdq_line *out, char *err, size_t errlen);

/* Run a parsed query. */
cdist_status cdq_run(cdist_query *q, const cdq_line *ql, cdist_result *r);

/* Problem scale of a query as ../shared/cases/README.md defines it, given the expected
 * distance: max(radii, expected, centre distance; for a line, its point nearest the centre). */
double cdq_scale(const cdq_line *ql, double expected);

#endif
