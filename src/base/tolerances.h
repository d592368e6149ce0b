/* Every tolerance of the library, named once, with its unit and the reason for its value.
 * One section per family; families append their own section (and use only these names).
 * "eps" is DBL_EPSILON = 2^-52; "L" is the problem scale (max of the radii and the centre
 * distances a family measures against, the scale of ../shared/cases/README.md). */
#ifndef CDIST_BASE_TOLERANCES_H
#define CDIST_BASE_TOLERANCES_H

#include <float.h>

/* ---- input validation (src/api) ---- */

/* |length - 1| allowed for a normal or a line direction (dimensionless). Default of
 * cdist_query_set_unit_tolerance: loose enough for normals computed in single precision. */
#define CD_DEFAULT_UNIT_TOL 1e-6
/* Largest accepted |coordinate| or radius (length units): squares of differences stay finite
 * (1e150^2 * 12 < DBL_MAX) even before a family rescales. */
#define CD_MAX_ABS 1e150

/* ---- candidate collector (src/base/best.c) ---- */

/* Two distances within CD_TIE_ULPS * eps * L are a tie (both pairs are reported): the spread
 * of a distance computed along two different paths of the same family. */
#define CD_TIE_ULPS 16.0
/* Two pairs are distinct when their points differ by more than CD_DISTINCT_REL * L in total:
 * well above the position error of a flat minimum (~sqrt(eps) L), well below any gap between
 * genuinely different closest pairs in the reference sets. */
#define CD_DISTINCT_REL 1e-6

/* ---- root and minimum module (src/base/roots.h) ---- */

/* A bracketed root is converged when the step is below CD_ROOT_REL_ULPS * eps * |x| (the
 * resolution of x) or below CD_ROOT_ABS (absolute, in the caller's scaled units: families call
 * the solvers on problems scaled to L in [1, 2), where 2^-62 is far below eps * L). */
#define CD_ROOT_REL_ULPS 2.0
#define CD_ROOT_ABS 0x1p-62
/* Iteration caps: safeguarded Newton halves the bracket at worst, so 200 steps cover any
 * bracket of doubles; Newton polishing from a good start converges in a few steps. */
#define CD_ROOT_MAX_ITER 200
#define CD_POLISH_MAX_ITER 60

/* ---- polynomial module (src/base/poly.c) ---- */

/* Leading coefficients below CD_POLY_LEAD_ULPS * eps (callers pass coefficients normalised
 * to max 1 at scale L ~ 1) are dropped: such a root is at |x| > 1/eps, outside any range. */
#define CD_POLY_LEAD_ULPS 4.0
/* A polynomial is "nearly even/odd" (solved shifted, see poly.c) when its odd (even) part is
 * below this fraction of the other (dimensionless). */
#define CD_POLY_EVEN_REL 1e-6

/* ---- point family (src/point) ---- */

/* A point is on the circle's axis when its axis distance |n x p| is below the rounding noise
 * of the cross product: CD_ON_AXIS_ULPS * eps * |p|. Then every circle point is closest. */
#define CD_ON_AXIS_ULPS 2.0

/* ---- lines family (src/lines) ---- */

/* Line-circle, scaled units (L in [1, 2)): the line is perpendicular to the plane when the
 * in-plane part of its unit direction is below CD_LC_PERP_ULPS * eps (rounding of a unit
 * vector's cross product); a candidate is on the axis when its axis distance is below
 * CD_LC_AXIS_ULPS * eps * max(1, |B|) (rounding of the frame origin B). */
#define CD_LC_PERP_ULPS 4.0
#define CD_LC_AXIS_ULPS 4.0
/* Imaginary-part tolerance for the quartic's roots (relative to 1 + |z|): generous, because a
 * tangent line gives a root of multiplicity 4 spread by ~eps^(1/4) ~ 1e-4; every root is then
 * polished on the true F' and kept only as a candidate. */
#define CD_LC_POLY_IMAG 1e-3
/* Line-disk: the line is parallel to the disk's plane when |n . M| (M unit) is below
 * CD_LD_PARALLEL_ULPS * eps (rounding of a unit dot product). */
#define CD_LD_PARALLEL_ULPS 4.0

/* ---- circles family (src/circles: circle-circle, circle-disk, disk-disk) ---- */

/* Circle-circle, scaled units (L in [1, 2)): the planes are parallel when the parameterised
 * circle's height over the other's plane varies by at most CD_CC_PARALLEL_ULPS * eps * L (the
 * rounding of a unit normal's components); the closed form (distance-to-circles-3d §5.2) then
 * errs by at most twice that in the distance. */
#define CD_CC_PARALLEL_ULPS 1.0

#endif
