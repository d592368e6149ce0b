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
/* The checks of a batch of n > 0 entries before any entry is answered. Arguments missing
 * (!args_ok): every out[i] (out_size bytes each; none when out is NULL) in its error state by
 * set_error, every status CDIST_ERR_NULL_ARGUMENT, reported with `missing`. Else out or
 * statuses overlapping an input (the spans in[0 .. n_in)) or each other (cdist__spans_overlap):
 * CDIST_ERR_OVERLAP, nothing written. CDIST_OK to go on. */
cdist_status cdist__topology_begin(cdist_query *q, size_t n, int args_ok, void *out, size_t out_size,
                                   void (*set_error)(void *), cdist_status *statuses, const char *missing,
                                   const cdist__span *in, int n_in);
/* Entries 0 .. n-1 of a batch, one at a time on the calling thread: statuses[i] (when not NULL)
 * gets entry(q, ctx, i); returns CDIST_OK, else reports the lowest failing entry with its
 * message. */
cdist_status cdist__topology_run(cdist_query *q, size_t n, cdist_status (*entry)(cdist_query *, const void *, size_t),
                                 const void *ctx, cdist_status *statuses);

#endif
