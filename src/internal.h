/* SPDX-License-Identifier: MIT */
/* Internal declarations shared by the query families. Nothing here is exported.
 * Umbrella header for the families from lines up: the base layer (src/base), the API layer
 * (src/api) and the point and lines families (src/point, src/lines) have their own headers,
 * included here. Below the lines family (src/base, src/api, src/point) files include only the
 * headers of their own and lower layers (tests/layers checks it). */
#ifndef CDIST_INTERNAL_H
#define CDIST_INTERNAL_H

#include <float.h>
#include <stddef.h>

#include "circledist.h"
#include "base/best.h"
#include "base/numeric.h"
#include "base/poly.h"
#include "base/roots.h"
#include "base/tolerances.h"
#include "base/vec.h"
#include "api/api-priv.h"
#include "lines/lines-priv.h"
#include "point/point-priv.h"

/* ---- cores (inputs already translated so that the relevant centre is the origin) ---- */

/* The non-robust circle-circle methods (src/circles/cc_poly.c, src/circles/cc_iteration.c), called by the
 * dispatcher in src/circles/circle_circle.c with c0->c at the origin. Each handles every configuration
 * (setting b->equidistant where infinitely many pairs are closest) and offers its candidates to
 * b, or returns a non-OK status to make the dispatcher fall back to the robust method. */
cdist_status cdist__cc_polynomial(cdist_query *q, const cdist__circle *c0, const cdist__circle *c1, cdist__best *b);
cdist_status cdist__cc_iteration(cdist_query *q, const cdist__circle *c0, const cdist__circle *c1, cdist__best *b, int *iterations);

/* Every critical angle on c0 (in c0's basis) of theta -> dist^2(c0(theta), c1) when dcap is
 * infinite. Else (minima mode) the local minima with distance up to min(dcap, the global
 * minimum) to the tie tolerance, the rest of the circle pruned by lower bounds (the closed form
 * of parallel planes still returns all its critical angles). Returns the count (at most cap), or
 * -1 when the function is constant (every angle critical). *sampled (when not NULL): 1 when some
 * of the circle was only sampled (a near-crossing of the other's axis, an exhausted budget,
 * H vanishing to rounding), so that an angle may be off by more than rounding. */
int cdist__circle_circle_critical(cdist_query *q, const cdist__circle *c0, const cdist__circle *c1, double dcap, double *theta0,
                                  int cap, int *sampled);

/* The circles family's one framing and scaling rule (src/base/numeric.h): a moved to the origin
 * and b with it (the translation is written to *offset), both scaled by the power of two 2^-e
 * that brings L = max(radii, |b centre|) into [1, 2), and best initialised at that scale.
 * Returns e. cdist__circles_result writes r from best (swap: the objects' roles exchanged) and
 * undoes the scaling and the translation: exact, so tiny and huge inputs (1e-300, 1e150) get
 * the answer of their unit-scale copy. */
int cdist__circles_frame(cdist__circle *a, cdist__circle *b, vec3 *offset, cdist__best *best);
void cdist__circles_result(const cdist__best *best, int swap, int e, vec3 offset, cdist_result *r);
/* Lexicographic order of two circles' numbers (centre, normal, radius): 1 when a comes first.
 * Families that swap their inputs into this order run the same computation for f(a, b) and
 * f(b, a). */
static inline int cdist__circle_less(const cdist_circle *a, const cdist_circle *b)
{
    const double va[7] = {a->center.x, a->center.y, a->center.z, a->normal.x, a->normal.y, a->normal.z, a->radius};
    const double vb[7] = {b->center.x, b->center.y, b->center.z, b->normal.x, b->normal.y, b->normal.z, b->radius};
    for (int i = 0; i < 7; i++) {
        if (va[i] < vb[i]) return 1;
        if (va[i] > vb[i]) return 0;
    }
    return 0;
}


/* ---- cc_methods block: helpers shared by cdist__cc_polynomial and cdist__cc_iteration (defined in
 * src/circles/cc_poly.c). c0 is at the origin, c1 at D. "side" s moves a point on circle s and measures
 * its closed-form distance to the other circle: F_s(t) = dist^2(c_s(t), c_{1-s}). ---- */
typedef struct cdist__cc {
    const cdist__circle *c[2];
    vec3 D;   /* c1 centre relative to c0 centre */
    double L; /* problem scale */
} cdist__cc;
/* F_s(t) with F' and F'' (either may be NULL); P, K (may be NULL): the moving point relative to
 * its own centre and the closest point of the other circle relative to that circle's centre. */
double cdist__cc_eval(const cdist__cc *g, int side, double t, double *f1, double *f2, vec3 *P, vec3 *K);
/* Safeguarded Newton on F_s' from t; returns the polished angle and writes F there. */
double cdist__cc_polish(const cdist__cc *g, int side, double t, double *F);
/* Offer the pair at angle t of side s (evaluated on the true distance). */
void cdist__cc_offer(const cdist__cc *g, int side, double t, cdist__best *b);
/* Zero radius and coaxial circles, answered in closed form: returns 1 when b is complete. */
int cdist__cc_closed_form(const cdist__cc *g, cdist__best *b);
/* Candidate angles on c0 for (nearly) parallel planes (Eberly 5.1-5.2, Li et al. 2.3);
 * returns the count (<= 4). */
int cdist__cc_parallel_candidates(const cdist__cc *g, double *t0);
/* When the axes meet (within a loose tolerance), the unit normal m of the mirror plane through
 * both axes; returns 0 otherwise. */
int cdist__cc_mirror(const cdist__cc *g, vec3 *m);
/* Offer polished minima (side, angle, F): the best, and the others unless they tie with it
 * without a barrier between them on c0 (one flat basin, not two symmetric minima). When F_s''
 * vanishes at the minimum, circle s may be at constant distance from the other (e.g. equal
 * perpendicular circles through each other's centre): tested by sampling, flagged equidistant. */
void cdist__cc_offer_minima(const cdist__cc *g, int n, const int *side, const double *t, const double *F, cdist__best *b);
/* Both methods work on a copy scaled by a power of two (exact) so that the problem scale is
 * in [1, 2): squares neither overflow (coordinates up to 1e150) nor underflow (1e-300).
 * cdist__cc_scale writes the scaled circles (c0 at the origin) and s; cdist__cc_unscale offers the
 * scaled collector's candidates to b in the caller's units. */
void cdist__cc_scale(const cdist__circle *c0, const cdist__circle *c1, double L, cdist__circle *a, cdist__circle *b, double *s);
void cdist__cc_unscale(const cdist__best *scaled, double s, cdist__best *b);
/* ---- end of cc_methods block ---- */

#endif
