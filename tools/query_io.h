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
    /* the public call for the numbers of a line */
    cdist_status (*run)(cdist_query *q, const double *v, cdist_result *r);
    /* its two objects (the public structs, e.g. cdist_line and cdist_circle) written to a, b */
    void (*objects)(const double *v, void *a, void *b);
    int batch_kind; /* its cdist_kind number (a plain int: builds without the batch API too) */
    int unit_at[2];      /* offsets of the vectors that must be unit length (0: none) */
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

/* Scales the vectors that must be unit length (normals, line directions, helix axes) to unit
 * length, for hand-typed input. A zero vector is left as it is (the query reports it). */
void cdq_normalize(cdq_line *ql);

/* The same query with its two objects in the other order, for kinds whose two objects have the
 * same layout (names of one letter twice: cc, dd, aa, TT, KK, SS, RR). Returns 1 and writes
 * *out for those, 0 for every other kind. */
int cdq_swapped(const cdq_line *ql, cdq_line *out);

/* Run a parsed query. */
cdist_status cdq_run(cdist_query *q, const cdq_line *ql, cdist_result *r);

/* Problem scale of a query as ../shared/cases/README.md defines it, given the expected
 * distance: max(radii, expected, centre distance; for a line, its point nearest the centre). */
double cdq_scale(const cdq_line *ql, double expected);

#endif
