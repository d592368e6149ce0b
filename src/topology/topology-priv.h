/* SPDX-License-Identifier: MIT */
/* Linking and time of impact (src/topology): internal entry points, for the tests. */
#ifndef CDIST_TOPOLOGY_PRIV_H
#define CDIST_TOPOLOGY_PRIV_H

#include "internal.h"

/* The crossing count of link_core.h for validated circles a, b whose certified distance is d
 * (caller's units, d > CD_LINK_TOUCH_REL * L): -1, 0, +1, or CDIST_LINK_TOUCHING when the error
 * bound of that precision (extended = 0: double, 1: the extended type) does not settle it. */
int cdist__link_count(const cdist__circle *a, const cdist__circle *b, double d, int extended);

/* The batches' closing report: records st with "entry <first>: <message>" (just the message when
 * first is SIZE_MAX) on q, under its in-use flag (a busy or NULL handle is left alone), and
 * returns st. */
cdist_status cdist__topology_batch_report(cdist_query *q, size_t first, cdist_status st, const char *message);
/* CDIST_ERR_OVERLAP, reported before anything is written, when an output span overlaps an earlier
 * span (cdist__spans_overlap); else CDIST_OK. */
cdist_status cdist__topology_overlap(cdist_query *q, const cdist__span *s, int count, int n_inputs);

/* The lowest failing entry of a batch and its message: cdist__topology_note records entry i's
 * status (the first failure only, copying the handle's message), cdist__topology_finish
 * returns CDIST_OK or reports that failure. */
typedef struct cdist__topology_failure {
    size_t first; /* SIZE_MAX: none */
    cdist_status status;
    char message[CD_MESSAGE_LEN];
} cdist__topology_failure;
void cdist__topology_note(const cdist_query *q, cdist__topology_failure *f, size_t i, cdist_status st);
cdist_status cdist__topology_finish(cdist_query *q, const cdist__topology_failure *f);

#endif
