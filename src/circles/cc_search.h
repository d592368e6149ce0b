/* SPDX-License-Identifier: MIT */
/* The circle-circle certified search (docs/circles.md): its sizes and the angle tables shared by
 * the single query's search (cc_search.c) and the batch kernel (src/batch/cc_kernel.c). The
 * arithmetic is in cc_search_body.h, written over lanes. */
#ifndef CDIST_CIRCLES_CC_SEARCH_H
#define CDIST_CIRCLES_CC_SEARCH_H

#include "circles/circles-priv.h"

#define CK_GRID 32     /* grid angles (97% of random pairs prune every interval outside the basin) */
#define CK_LEVELS 7    /* basin half-widths 2 pi / CK_GRID * 4^-l, l < 7: down to 5e-5 rad */
#define CK_NEWTON_MAX 8 /* from a certified basin Newton settles in 3 to 5 steps */
#define CK_FIRST_CONVEX 2 /* the level of the first convexity check (below it few basins pass) */
/* The single query's search gives up after this many levels (the scan then answers): nearly
 * every random pair certifies by level 4; basins that are not convex by then are mostly
 * near-touching circles, which the scan handles. */
#define CK_QUICK_LEVELS 5

/* Angles of the search, computed once (cdist__cc_search_tables). */
typedef struct cdist__cc_search_tab {
    double grid_c[CK_GRID], grid_s[CK_GRID]; /* cos, sin of 2 pi j / CK_GRID */
    double hull_c[CK_GRID], hull_s[CK_GRID]; /* the hull point of [t_j, t_j+1]: cos, sin of its middle / cos(pi / CK_GRID) */
    double grid_tan2;                        /* tan^2(pi / CK_GRID) */
    double grid_half_c, grid_half_s;         /* cos, sin of pi / CK_GRID */
    double half[CK_LEVELS];                  /* basin half-width h_l */
    double end_c[CK_LEVELS], end_s[CK_LEVELS]; /* cos, sin of h_l */
    double sub_c[CK_LEVELS][4], sub_s[CK_LEVELS][4]; /* cos, sin of k h_l / 4, k = 1..3 */
    double hull_sub_c[CK_LEVELS][4], hull_sub_s[CK_LEVELS][4]; /* of (2m + 1) h_l / 8, / cos(h_l / 8) */
    double sub_tan2[CK_LEVELS];              /* tan^2(h_l / 8) */
    /* the single query's zoom (cdist__cc_quick), lane k: cos, sin of (k - 4) h_l / 4 and of the
     * hull point of [(k - 4) h_l / 4, (k - 3) h_l / 4], (2 k - 7) h_l / 8, / cos(h_l / 8) */
    double zoom_c[CK_LEVELS][8], zoom_s[CK_LEVELS][8];
    double zoom_hull_c[CK_LEVELS][8], zoom_hull_s[CK_LEVELS][8];
    double lane_index[CK_GRID]; /* j at index j */
} cdist__cc_search_tab;
extern cdist__cc_search_tab cdist__cc_tab;

/* Fills cdist__cc_tab once (thread-safe); call before reading it. */
void cdist__cc_search_tables(void);

#endif
