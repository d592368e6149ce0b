/* SPDX-License-Identifier: MIT */
/* The candidate collector: every family offers candidate pairs; the best (and, on a tie,
 * the second) become the result. */
#ifndef CDIST_BASE_BEST_H
#define CDIST_BASE_BEST_H

#include <math.h>

#include "circledist.h"
#include "base/numeric.h"
#include "base/tolerances.h"
#include "base/vec.h"

/* ---- candidate collection: every family offers candidate pairs; ties become two pairs ---- */

#define CD_BEST_KEEP 4

typedef struct cdist__cand {
    int equidistant; /* this candidate stands for infinitely many equally close pairs */
    double d2;
    vec3 p[2];
    double param[2];
} cdist__cand;

typedef struct cdist__best {
    double scale;    /* problem scale L, for the tie and distinctness tests */
    int n;           /* candidates kept, sorted by d2 */
    int equidistant; /* set by a family whose whole configuration has infinitely many closest pairs */
    cdist__cand c[CD_BEST_KEEP];
} cdist__best;

/* Two distances within CD_TIE_ULPS * eps * scale are a tie (both pairs are reported) when
 * their pairs are distinct: further apart than CD_DISTINCT_REL * scale (tolerances.h). */

CD_INLINE void cdist__best_init(cdist__best *b, double scale)
{
    b->scale = (scale > 0.0 && isfinite(scale)) ? scale : 1.0;
    b->n = 0;
    b->equidistant = 0;
}
/* The tie tolerance of b: two distances closer than this are a tie. */
CD_INLINE double cdist__best_tie_tol(const cdist__best *b) { return CD_TIE_ULPS * DBL_EPSILON * b->scale; }
/* Whether the result would be flagged equidistant (the whole configuration, or the best
 * candidate stands for infinitely many pairs). */
static inline int cdist__best_is_equidistant(const cdist__best *b)
{
    return b->equidistant || (b->n > 0 && b->c[0].equidistant);
}
/* Offer a candidate: p0 on the first object, p1 on the second, d2 = its squared distance
 * computed as accurately as the family can (usually from the true distance function). */
void cdist__best_offer(cdist__best *b, double d2, vec3 p0, vec3 p1, double param0, double param1);
/* Same with a flag: equidistant = 1 for a candidate that represents infinitely many equally
 * close pairs (e.g. a point on a circle's axis); the result is flagged equidistant only if that
 * candidate is the best. For moving candidates from one collector to another, pass the source
 * candidate's .equidistant. */
void cdist__best_offer_into(cdist__best *b, int equidistant, double d2, vec3 p0, vec3 p1, double param0, double param1);
/* Inline: the first candidate into an empty collector is kept as it is (most queries offer one
 * or two); the others go through the merging and sorting of cdist__best_offer_into. */
CD_INLINE void cdist__best_offer_flag(cdist__best *b, int equidistant, double d2, vec3 p0, vec3 p1, double param0,
                                      double param1)
{
    if (b->n == 0 && d2 >= 0.0) {
        cdist__cand *c = &b->c[0];
        c->equidistant = equidistant;
        c->d2 = d2;
        c->p[0] = p0;
        c->p[1] = p1;
        c->param[0] = param0;
        c->param[1] = param1;
        b->n = 1;
        return;
    }
    cdist__best_offer_into(b, equidistant, d2, p0, p1, param0, param1);
}
/* Write the result: the best pair and, on a tie, the second; points moved by `offset`
 * (the translation the family removed). swap exchanges the objects' roles (f(b,a) from f(a,b)). */
void cdist__best_to_result(const cdist__best *b, vec3 offset, int swap, cdist_result *r);

/* ---- combining collectors (families that split a query into sub-queries) ---- */

/* Copy the candidates of src into dst; points shifted by `shift`; swap exchanges the roles of
 * the two objects. Returns the squared distance of src's best (INFINITY when empty). */
double cdist__best_merge(cdist__best *dst, const cdist__best *src, vec3 shift, int swap);
/* An equidistant sub-result (squared distance eq_d2) makes the whole result equidistant only
 * when it attains the global minimum. */
void cdist__best_settle_equidistant(cdist__best *b, double eq_d2);
/* When the closest set is convex (line/segment/disk against a disk), two distinct closest pairs
 * at distance zero mean a whole segment of contact: flag it. */
void cdist__best_convex_contact(cdist__best *b);

#endif
