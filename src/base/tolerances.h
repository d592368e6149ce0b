/* SPDX-License-Identifier: MIT */
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
/* The length rule of a vector: |d| is taken from d itself when its largest component is at
 * least this (length units), |d|^2 being then normal; below it |d|^2 may underflow, and d is
 * rescaled to its largest component first (the full check of a direction or normal, by a power
 * of two; a point's in-plane offset near a circle's axis before it is normalised). Not a
 * tolerance of the answer: only where exact rescaling is needed. */
#define CD_MIN_NORMAL_FAST 0x1p-500

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
/* Iteration caps: the safeguarded solver (cdist__root_halley_accel) halves the bracket at worst
 * every two steps, so 200 steps cover any bracket of doubles; Newton polishing from a good start
 * converges in a few steps. */
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
/* The point queries' fast path and the batch point kernel work unscaled when the problem scale
 * L = max(r, |p - c|) is at least this (length units): power-of-two scaling changes no rounding
 * unless a square underflows, and a term whose square underflows (below 2^-511) is then below
 * 2^-61 L, so the distance stays within an ulp of the scale; smaller problems are scaled to
 * [1, 2) first (a distance of 1e-170 came out 0 unscaled). */
#define CD_POINT_MIN_SCALE 0x1p-450
/* Gradients (src/swept/grad.c): a closest point X of a disk (centre C, radius r) counts as
 * inside the rim, where the radius does not move it, when its axis distance is below r by more
 * than CD_GRAD_RIM_REL * r (dimensionless: far above the rounding of a point placed on the rim,
 * a few eps r, so a rim point is never taken for an interior one) plus CD_GRAD_RIM_ULPS * eps *
 * (max|X_i| + max|C_i|) (the rounding of X - C and of the axis distance in the caller's units). */
#define CD_GRAD_RIM_REL 1e-9
#define CD_GRAD_RIM_ULPS 64.0

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
/* Line-circle, scaled units: the frame origin of the model is the canonical point x2 = 0 (where
 * F is exactly even in s for a symmetric configuration) when it lies within CD_LC_CANON_MAX of
 * B0 along the line; farther (nearly perpendicular lines) B0 itself, so that t does not cancel. */
#define CD_LC_CANON_MAX 4.0
/* Polynomial roots (src/base/poly.c): a nearly even (or odd) polynomial, whose roots pair up
 * as +-x of equal modulus (the hard case for shifted QR), is shifted by CD_POLY_SHIFT times its
 * root bound (dimensionless; an irrational-looking factor, so the shift does not land on another
 * symmetry); the QR iteration gets CD_POLY_QR_ITS sweeps per root or root pair found (a count:
 * clustered roots can need many) before it reports failure. */
#define CD_POLY_SHIFT 0.0377438833
#define CD_POLY_QR_ITS 120
/* Lines family scaling (src/lines/lines-priv.h): when the problem scale L is so far below the
 * coordinates that 2^-e times them would overflow, the exponent is raised so that the scaled
 * coordinates stay below 2^(CD_LINES_ABS_MAX_EXP + 1) (an exponent, dimensionless): headroom of
 * 2^23 for the sums taken on them (origin - centre, centre + offset), none of which is squared. */
#define CD_LINES_ABS_MAX_EXP 1000
/* Coordinates are at most CD_MAX_ABS = 1e150 < 2^499, so 2^-e times them cannot overflow for
 * e >= CD_LINES_OVERFLOW_EXP (an exponent): the check above is needed only below it. */
#define CD_LINES_OVERFLOW_EXP (-500)
/* Line kernels (src/batch/line_kernel_body.h), scaled units: a root that needed more than the
 * lanes' iterations counts as at an end of the range when within CD_LK_END_REL_ULPS * eps * |end|
 * + CD_LK_END_ABS of it (the bisection down to the end stops a few ulps short); any other slow
 * root is a nearly multiple one, left to the scalar path. */
#define CD_LK_END_REL_ULPS 8.0
#define CD_LK_END_ABS 0x1p-60

/* ---- curves family (src/curves: callback curves, helix, Bezier, arcs) ---- */

/* A zero_direction within this sine of the normal/axis cannot define angle 0 (dimensionless). */
#define CD_CURVE_PARALLEL_SIN 1e-10
/* A point is on a circle's axis (every circle point equally close, up to the tie tolerance)
 * when its axis distance is below CD_CURVE_AXIS_ULPS * eps * L. */
#define CD_CURVE_AXIS_ULPS 8.0
/* Rounding level of the sampled derivative g = F'/2: CD_CURVE_G_ULPS * eps * (|P - C| + r +
 * frame magnitude) * |P'| (a few roundings of each product in g); below it a sample counts as a
 * critical point. */
#define CD_CURVE_G_ULPS 32.0
/* Brackets of the scan's solvers stop at the resolution of t (CD_ROOT_REL_ULPS) plus
 * CD_CURVE_SPAN_ULPS * eps * (scanned span): t is not resolvable below an ulp of the span. */
#define CD_CURVE_SPAN_ULPS 0.25
#define CD_CURVE_ROOT_MAX_ITER 300
/* Golden sections (dip of g between samples, closest approach to the axis) stop at
 * CD_CURVE_GOLDEN_ULPS * eps * (|a| + |b|) plus the span term; at most this many steps
 * (0.618^60 ~ 3e-13 of a two-sample bracket, below which g's sign is noise anyway). */
#define CD_CURVE_GOLDEN_ULPS 4.0
#define CD_CURVE_GOLDEN_MAX_ITER 60
/* cdist__cs_polish's first step from a candidate, relative to max(span, |t|), growing by 4 at most
 * CD_CURVE_POLISH_STEPS times (4^40 covers any span). */
#define CD_CURVE_POLISH_STEP_REL 1e-10
#define CD_CURVE_POLISH_STEPS 40
/* Certification of the sampled curve queries (helix, Bezier, the sampled fallback of arc-circle
 * and arc-disk): the answer is within tau = CD_CURVE_CERT_ULPS * eps * L of the global minimum
 * (every excluded interval's lower bound is at least the answer minus tau; tau must exceed the
 * rounding of the bounds: CD_CURVE_CERT_EVAL_ULPS * eps * (2 L + r + frame magnitude) for a
 * sampled distance, the helix's and arcs' bound ranges). The certification's explicit stack
 * holds CD_CURVE_CERT_DEPTH nodes (deeper splits recurse); more than CD_CURVE_CERT_MAX_NODES
 * split nodes in one query is CDIST_ERR_COST_LIMIT. */
#define CD_CURVE_CERT_ULPS 512.0
#define CD_CURVE_CERT_EVAL_ULPS 16.0
#define CD_CURVE_CERT_DEPTH 80
#define CD_CURVE_CERT_MAX_NODES 200000L
/* Relative widening (dimensionless) of the certification's speed bounds and Lipschitz screen:
 * covers the rounding of an interval's width (sample parameters differ from equal spacing by
 * rounding only) and of the products that form the bound. */
#define CD_CURVE_CERT_WIDTH_REL 0x1p-40
/* Blocks of this many sample intervals are tried whole with a curve's own bound before their
 * intervals are bounded one by one (a cost choice, not a tolerance). */
#define CD_CURVE_CERT_BLOCK 16
/* Callback curves: positions sampled to choose the frame's power-of-two scale. */
#define CD_CURVE_SCALE_PROBES 8
/* Helix: at most 10^6 turns (a longer one is BAD_INTERVAL); the turn lower bound's ranges (and
 * the arcs' bound's) are widened by CD_CURVE_HELIX_BOUND_ULPS * eps times the magnitude of the
 * geometry (squares before their square roots: their rounding); a turn must be scanned when its
 * bound is below best - tau (the certification tolerance), and may hold a tie when its bound is
 * below best * (1 + CD_CURVE_HELIX_SKIP_REL) + CD_CURVE_HELIX_SKIP_ABS * L (far above the
 * rounding of both). */
#define CD_CURVE_HELIX_MAX_TURNS 1e6
#define CD_CURVE_HELIX_BOUND_ULPS 64.0
#define CD_CURVE_HELIX_SKIP_REL 1e-9
#define CD_CURVE_HELIX_SKIP_ABS 1e-12
/* Cost of one helix query (counts, not tolerances): at most CD_CURVE_HELIX_MAX_EVALS evaluations
 * of the curve (samples, refinements, certification), then CDIST_ERR_COST_LIMIT: a bound on the
 * query's time whatever the turns and the sample count. A turn is sampled at most
 * CD_CURVE_HELIX_TURN_SAMPLES times; the turns after the first at fewer when the turns that must
 * be scanned would not fit the budget at that count, each estimated at its samples plus
 * CD_CURVE_HELIX_PIECE_EVALS (refinement and certification), and never at fewer than
 * CD_CURVE_HELIX_MIN_SAMPLES (the API's minimum sample count): the query is refused then. */
#define CD_CURVE_HELIX_MAX_EVALS 12000L
#define CD_CURVE_HELIX_TURN_SAMPLES 4096
#define CD_CURVE_HELIX_PIECE_EVALS 128L
#define CD_CURVE_HELIX_MIN_SAMPLES 32L
/* Helix pieces that the certification does not need but whose bound is within the skip margin
 * above (a possible second closest pair, e.g. the next crossing of a disk) are scanned within
 * this many samples per query (6 pieces at the default 512 samples). */
#define CD_CURVE_HELIX_TIE_SAMPLES 3072.0
/* Arcs: the height over a disk's plane is constant (parallel planes) when its amplitude is
 * below CD_ARC_PARALLEL_ULPS * eps * r. Arc-arc whose circles' distance is constant (as the
 * circle-circle analysis decides it, within its 32 eps L) is answered in closed form as coaxial
 * when the normals' cross product is below CD_ARC_COAXIAL_ULPS * eps and the centres' offset
 * from the axis below CD_ARC_COAXIAL_ULPS * eps * L (rounding of generated coaxial inputs, far
 * below the other constant configuration, a circle through the other's centre, offset ~ r). */
#define CD_ARC_COAXIAL_ULPS 1024.0
#define CD_ARC_PARALLEL_ULPS 4.0
/* Segment-arc: the interior minima lie within r / |M| of the foot of the perpendicular; the
 * window is widened by CD_SEG_ARC_WINDOW_REL of itself and CD_SEG_ARC_WINDOW_ULPS * eps *
 * (|p0| / |M| + 1) (rounding of the foot). */
#define CD_SEG_ARC_WINDOW_REL 1e-9
#define CD_SEG_ARC_WINDOW_ULPS 4.0

/* ---- circles family (src/circles: circle-circle, circle-disk, disk-disk) ---- */

/* Circle-circle, scaled units (L in [1, 2)): the planes are parallel when the parameterised
 * circle's height over the other's plane varies by at most CD_CC_PARALLEL_ULPS * eps * L (the
 * rounding of a unit normal's components); the closed form (distance-to-circles-3d §5.2) then
 * errs by at most twice that in the distance. */
#define CD_CC_PARALLEL_ULPS 1.0

/* Circle-disk, scaled units: a candidate whose distance exceeds the best one already collected
 * by more than CD_CD_FAR_REL * L is not offered (nor are its points and angles formed). It can
 * never become the best or tie with it, nor merge with a pair that does: pairs merge only within
 * CD_DISTINCT_REL * L, where their distances differ by at most that much (the distance is
 * 1-Lipschitz in each point), and ties are within CD_TIE_ULPS * eps * L; four times the
 * distinctness radius covers both with a wide margin for the rounding of the comparison. */
#define CD_CD_FAR_REL (4 * CD_DISTINCT_REL)

/* Circle-circle: the robust method offers its candidates with the plain distance (rounding below
 * 8 eps (2 R + |C|) <= 24 eps L) and recomputes in double-double those within the tie tolerance
 * plus CD_CC_SETTLE_ULPS * eps * L of the best: every one that can be reported. */
#define CD_CC_SETTLE_ULPS 64.0

/* The certified search of circle-circle (src/circles/cc_search_body.h: the single query's and
 * the batch kernel's), in the robust method's scaled units (L in [0.5, 1), so F = squared
 * distance <= 4):
 *   - the answer F* is certified when the lower bound of F on every region outside the final
 *     basin exceeds it by CD_CCK_CERT_MARGIN: above the rounding of both (about 20 eps * 9 <
 *     1e-13) 25 times over, so no region can hold a smaller F; a near-tie of two minima goes
 *     to the scalar path instead;
 *   - F''/2 at a basin's ends carries CD_CCK_F2_ULPS * eps times the magnitude of its terms
 *     (as the bound of cdist__cc_convex, cc_certify.c);
 *   - Newton in the certified basin settles a lane after its first step below
 *     CD_CCK_NEWTON_STEP rad: its angle is then within about (F''' / F'') step^2 < 1e-19 rad
 *     of the minimum, and the angle's own rounding (1e-15 rad) dominates;
 *   - an answer below sqrt(CD_CCK_MIN_F) (1e-12, circles that touch or cross) goes to the
 *     scalar path: at a minimum d* the distance moves by about (R dt)^2 / (2 d*) for an angle
 *     error dt, an ulp of the scale only while d* >= 1e-12 (dt = 1e-15); below it the two
 *     searches' roundings of the angle would show. */
#define CD_CCK_CERT_MARGIN 1e-12
#define CD_CCK_F2_ULPS 64.0
#define CD_CCK_NEWTON_STEP 1e-10
#define CD_CCK_MIN_F 1e-24

/* Circle-circle engine (cc_scan.c refine): the bracketed Newton on F' stops after a step dx
 * (rad) once its quadratic-convergence error, about dx^2 / l for F's features of width
 * l = min(1, rho / W1) rad (rho: the axis distance of B, W1 >= |w'|; every derivative of
 * rho = |w| brings a factor W1 / rho), is below CD_CC_REFINE_QUAD rad: far below the angle's
 * own rounding (1e-16 rad), so the root is the true F''s to rounding. A fixed cut of dx would
 * not do: beside a tiny B (radius 4.7e-9 of A's) the minimum sits at rho ~ s, where dx <= 1e-9
 * leaves it 5e-12 rad off. */
#define CD_CC_REFINE_QUAD 1e-18
/* Circle-circle engine (cc_kink.c re-check, critical and minima modes): a root refined again
 * from a subdivision of a grid interval is the grid's own when the two refinements agree to
 * CD_CC_SAME_ROOT_ULPS ulps of the angle (rad; seen: 1 ulp apart). Critical points that close
 * are below the engine's resolution anyway (a min/max pair within CD_CC_MIN_WIDTH is only
 * sign-checked). */
#define CD_CC_SAME_ROOT_ULPS 64.0

/* Circle-circle, the single query: the certified search of the kernel (cdist__cc_quick) runs
 * first unless B's centre lies within CD_CC_QUICK_CENTRE_REL * s of A. There A crosses B's
 * axis at B's centre, F's kink (never certified convex) sits at or next to the minimum, and
 * the search would only add its cost to the scan's (the cc_linked_touch family). A routing
 * threshold, not an accuracy one: either path answers every configuration. */
#define CD_CC_QUICK_CENTRE_REL 1e-4
/* Nor when either centre lies within CD_CC_QUICK_AXIS_REL * L of the other circle's axis: F is
 * then a function of cos(t - phi), mirror-symmetric, and its minima come in tied pairs that the
 * search leaves to the scan anyway (the cc_center_on_axis family). Routing only. */
#define CD_CC_QUICK_AXIS_REL 1e-9
/* Circle-circle polynomial and iteration methods: a point P of one circle whose axis distance
 * rho to the other is below CD_CC_AXIS_NOISE_REL * |P - C| (max norm) has its closest point on
 * the other circle normalised from the in-plane vector w = (n x (P - C)) x n itself rather than
 * by rho: the cross product carries about eps |P - C| of rounding not orthogonal to n, which
 * shortens |w| below rho by a relative (eps |P - C| / rho)^2, beyond an ulp only below about
 * 2^-24 |P - C|; 2^-20 leaves a margin and changes no point farther from the axis. */
#define CD_CC_AXIS_NOISE_REL 0x1p-20

/* Circle-circle equidistance, scaled units (docs/circles.md): (a) F constant on a circle when
 * the distance varies by at most CD_CC_EQUI_ULPS eps L over it (the rounding of the distance at
 * 16 points, a few eps L each, with margin); (b) a closest point on the other circle's axis when
 * its axis distance is within CD_CC_AXIS_ULPS rounding units of the positions (eps (R + |C|)),
 * times min(1, s / L) (the other circle's closest point direction is lost to rounding there). */
#define CD_CC_EQUI_ULPS 32.0
#define CD_CC_AXIS_ULPS 8.0

/* Circle-circle engine, scaled units (L in [0.5, 1)):
 *   - intervals narrower than CD_CC_MIN_WIDTH rad (2^-30) stay uncertified and are only
 *     sign-checked: a further min/max pair hidden inside one would lie within 2^-30 rad;
 *   - a near-crossing of B's axis is a minimum of rho <= CD_CC_KINK_REL L: there H is below its
 *     rounding (relative eps L / rho) and cannot be certified, so the window is scanned on a
 *     geometric grid instead;
 *   - the bounds M1..M3 of H's derivatives are widened by CD_CC_BOUND_REL of themselves plus
 *     CD_CC_BOUND_ABS (the rounding of the coefficient arithmetic, a few eps relatively, and a
 *     floor for H = 0); the certified search widens its bound of |rho''| at the basin's ends
 *     the same way;
 *   - a certificate comparing a value with a bound times a width (monotone, convex) asks for a
 *     relative excess CD_CC_CERT_REL (dimensionless), above the rounding of the comparison. */
#define CD_CC_MIN_WIDTH (1.0 / 1073741824.0)
#define CD_CC_KINK_REL 1e-6
#define CD_CC_BOUND_REL 1e-9
#define CD_CC_BOUND_ABS 1e-300
#define CD_CC_CERT_REL 1e-12
/* The window around a near-crossing of B's axis (cc_kink.c), in rad of A's angle: half-width
 * CD_CC_KINK_CORE_GAIN sqrt(rho / L) + CD_CC_KINK_CORE_MIN to start (rho, and so the window
 * where H is below its rounding, grows with the distance from the crossing; the floor gives an
 * exact crossing a window), doubled while rho at both ends is below CD_CC_KINK_REL L, at most
 * CD_CC_KINK_CORE_MAX (half the geometric grid's widest offset, 0.1 rad). F is then minimised
 * on each side over at least CD_CC_KINK_POLISH_MIN rad, so that a minimum next to the crossing
 * is inside the minimisation's bracket whatever the window. Axis crossings are solved from a
 * 2x2 system that is singular below CD_CC_AXIS_DET_REL times the product of its columns' norms
 * (then on the segment its columns span), and a solution counts as a crossing when it is a unit
 * vector to CD_CC_AXIS_UNIT_REL (relative; the crossings only add points where F is not
 * smooth, the scan certifies around them). */
#define CD_CC_KINK_CORE_GAIN 1e3
#define CD_CC_KINK_CORE_MIN 1e-12
#define CD_CC_KINK_CORE_MAX 0.05
#define CD_CC_KINK_POLISH_MIN 1e-3
#define CD_CC_AXIS_DET_REL 1e-12
#define CD_CC_AXIS_UNIT_REL 1e-9

/* Circle-circle, polynomial and iteration methods (scale L in [1, 2)):
 *   - the planes are parallel below |n0 x n1| = CD_CC_POLY_PARALLEL (the rounding of unit
 *     normals, with margin): closed forms; closed-form candidates are added up to
 *     CD_CC_POLY_NEAR_PARALLEL (starting points only: the polish finds the true minima);
 *   - roots of the degree-8 polynomial count as real with imaginary parts up to
 *     CD_CC_POLY_IMAG_TOL (relative): near-symmetric configurations make roots near-double and
 *     rounding splits them into complex pairs (imaginary parts ~1e-4 with a centre 2e-6 off the
 *     other's axis); every candidate is polished and evaluated on the true distance;
 *   - the iteration stops when the point on the first circle moves by at most
 *     CD_CC_ITER_TOL L (it only seeds the polish on the true distance). */
#define CD_CC_POLY_PARALLEL 1e-13
#define CD_CC_POLY_NEAR_PARALLEL 1e-2
#define CD_CC_POLY_IMAG_TOL 1e-2
#define CD_CC_ITER_TOL 1e-6
/* Same methods, candidates (every one polished on the true distance, so these only decide which
 * are kept):
 *   - concentric when |C1 - C0| <= CD_CC_POLY_CONCENTRIC_REL max(r0, r1): closed-form critical
 *     points instead of the degree-8 polynomial, whose QR iteration can fail to converge there;
 *   - a root cos t of the polynomial is used when |cos t| <= 1 + CD_CC_POLY_COS_SLACK (rounding
 *     puts roots at t = 0 or pi slightly outside [-1, 1]; they are clamped);
 *   - the sign of sin t is -p6/p7 unless |p7| <= CD_CC_POLY_P7_REL of its coefficients' sum
 *     (p7 within rounding of 0): then both signs;
 *   - the polished candidates within CD_CC_KEEP_REL F_min + CD_CC_KEEP_ABS L^2 of the best are
 *     kept (a root near a double root is found to about sqrt(eps), F to about 1e-8 L^2 of its
 *     minimum); the iteration mirrors its fixed points within CD_CC_KEEP_REL F_min +
 *     CD_CC_ITER_KEEP_ABS L^2 of the best (they are polished minima already);
 *   - two polished fixed points of the iteration are the same when their angles differ by at
 *     most CD_CC_ITER_SAME rad (polished angles agree to far less; distinct minima lie farther
 *     apart);
 *   - the axes meet (a mirror plane through both centres, the paper's second pair) when the
 *     centre offset leaves the plane by at most CD_CC_MIRROR_REL L;
 *   - a circle may be at constant distance from the other when F'' at the best candidate is at
 *     most CD_CC_POLY_FLAT_REL r L (the samples then decide). */
#define CD_CC_POLY_CONCENTRIC_REL 1e-6
#define CD_CC_POLY_COS_SLACK 1e-3
#define CD_CC_POLY_P7_REL 1e-6
#define CD_CC_KEEP_REL 1e-3
#define CD_CC_KEEP_ABS 1e-4
#define CD_CC_ITER_KEEP_ABS 1e-6
#define CD_CC_ITER_SAME 1e-9
#define CD_CC_MIRROR_REL 1e-9
#define CD_CC_POLY_FLAT_REL 1e-9

/* Circle-disk, scaled units: the plane crossings are refined by two Newton steps on the height,
 * each at most CD_CD_Z_STEP rad of the circle's angle; an extremum of the rim distance whose
 * |F''| is at most CD_CD_FLAT_REL rho L (rho: the circle's radius) is flat enough to hide a
 * neighbouring one below the sampling, so its neighbourhood is scanned. */
#define CD_CD_Z_STEP 1e-3
/* Circle-disk batch kernel: the angle (rad) by which a plane crossing's start taken by the
 * angle sum (cos, sin of phi and of acos(cz) = sqrt(1 - cz^2), unit lengths to rounding) may
 * differ from the single query's sincos(phi +- acos(cz)): sqrt(1 - cz^2) near cz = +-1 loses
 * up to sqrt(2 eps) ~ 2e-8 and acos itself as much; 50 times that. */
#define CD_CD_CROSS_START 1e-6
/* Circle-disk batch kernel: relative bound (in eps) on sqrt(x^2 + y^2) against hypot(x, y) and
 * on the roundings of the squared distance formed from either; a candidate whose lower bound
 * so formed is above the far limit is dropped before hypot. A few ulps each; 16 covers them. */
#define CD_CD_HYPOT_ULPS 16
#define CD_CD_FLAT_REL 0.05
/* Circle-disk, polynomial method (circle_disk.c), scaled units:
 *   - roots of the rim polynomial count as real with imaginary parts up to CD_CD_POLY_IMAG_TOL
 *     (relative), as for line-circle: near-double roots split into complex pairs;
 *   - a root is a clean maximum, skipped, when |F'| <= CD_CD_MAX_SLOPE_REL |F''| there (within
 *     that many rad of its critical point; its neighbouring minima are roots of their own);
 *   - a root is extraneous (of the squared equation) when |F'| > CD_CD_ROOT_SLOPE_REL rho L there:
 *     F' is of the order rho L at those, ~1e-15 at a true root even in a cluster; unless its
 *     Newton step |F' / F''| is below CD_CD_ROOT_STEP rad (a disk much smaller than the circle:
 *     features of width R / rho, where F'' is huge);
 *   - walks downhill start with a step of CD_CD_SHELL rad, and a critical point's neighbourhood
 *     is scanned at offsets CD_CD_SHELL 2^j (j < 36): a neighbouring extremum closer than
 *     2 CD_CD_SHELL differs from it by ~1e-36 of scale^2, below any rounding. */
#define CD_CD_POLY_IMAG_TOL 1e-3
#define CD_CD_MAX_SLOPE_REL 1e-6
#define CD_CD_ROOT_SLOPE_REL 1e-6
#define CD_CD_ROOT_STEP 1e-3
#define CD_CD_SHELL 1e-9

/* ---- linking and time of impact (src/topology) ---- */

/* Linking: two circles are reported touching when their certified distance is at most
 * CD_LINK_TOUCH_REL * L (L = max(r_a, r_b, |C_b - C_a|)). Any lower value works for the proof
 * (the classification is certified against the distance, see link_core.h); this one sits below
 * the 1e-12 L promised in the header and well above the distance's own error. */
#define CD_LINK_TOUCH_REL 0x1p-40
/* Error allowed for the circle-circle distance and for the working copy of the circles (unit
 * normals, the centre difference), relative to L: the reference tolerance of the cc family
 * (1e-13 of scale), far above its rounding. d - CD_LINK_DIST_REL * L is a certified lower bound
 * of the working circles' distance. */
#define CD_LINK_DIST_REL 0x1p-43

/* Time of impact: slack for the rounding of a pose and of the distance at a pose, in eps times
 * the scale of the posed coordinates, or of the swept radii plus |target| when larger (the
 * Rodrigues rotation and the translation add a few ulps to each coordinate; the swept queries'
 * distance is exact to CD_TIE_ULPS, and core - (r_a + r_b) - target rounds at the radii's and
 * the target's scale). A conservative
 * step advances by (distance - target - slack) / bound. */
#define CD_TOI_POSE_ULPS 64.0
/* Time of impact: the bound on the shrinking speed (a sum of products of norms) is rounded up by
 * the factor 1 + CD_TOI_SPEED_ULPS * eps, above the few roundings of each term, so that it stays
 * an upper bound and a conservative step never passes the impact. */
#define CD_TOI_SPEED_ULPS 64.0
/* Scenes (src/scene): every bound of the broad phase (boxes, balls, circle-plane slabs) is
 * widened by CD_SCENE_BOUND_REL times the objects' coordinate scale S (largest |coordinate| plus
 * the radii). The bounds take a handful of roundings (about 10 eps S) and the exact queries
 * answer to a few ulps of their scale (<= S; the reference files hold them to 1e-13 S), so a
 * pair whose computed distance is <= delta always passes: 2^-36 (1.5e-11) is over 100 times
 * either and still far below any geometric gap that matters for pruning. */
#define CD_SCENE_BOUND_REL 0x1p-36
/* Scenes' motion bounds: a normal n with |n.n - 1| at most this (one normalised in double) is
 * taken as unit, the bound widened by |n.n - 1| instead of normalising it; 2^-40 keeps that
 * slack below the bound margin CD_SCENE_BOUND_REL. */
#define CD_SCENE_UNIT_SLACK 0x1p-40
/* Linked pairs of a scene: how far beyond touching (relative to the pair's L = max(r_a, r_b,
 * |C_b - C_a|)) two rings' bounding balls may be apart and still be answered. The linking query
 * reports touching up to CD_LINK_TOUCH_REL * L, and, in the one configuration its extended count
 * cannot settle, up to about 5e-11 L; 2^-30 (9.3e-10) covers both with room, so a pair left out
 * is one the linking query answers 0 (and whose true linking number is 0: see docs/scene.md). */
#define CD_SCENE_LINK_REACH_REL 0x1p-30
/* Time of impact of a scene: each object's reach (how far its solid moves over [0, 1]) is widened
 * by this relative amount before it screens pairs. The reach and the poses of cdist_toi() take a
 * few roundings each (CD_TOI_POSE_ULPS eps of the posed coordinates); 2^-30 is far above them. */
#define CD_SCENE_TOI_REACH_REL 0x1p-30
/* ---- swept objects' closed-form cores (src/swept/swept.c) ---- */

/* Two segments are parallel when sin^2 of their angle is below this (dimensionless): then the
 * interior critical point is ill-conditioned and an overlap is tested for a flat valley. */
#define CD_SEG_PARALLEL_SIN2 1e-24
/* Parallel segments' overlap along their direction is of positive length when it exceeds this
 * many eps times the magnitude of its end positions (measured from the shorter segment's
 * start): the rounding of those positions. */
#define CD_SEG_OVERLAP_ULPS 8.0
/* Contacts (CDIST_CONTACT_CORE_TOUCH, as circledist.h states it): the cores touch when their
 * distance is at most CD_CONTACT_TOUCH_ULPS * eps times the largest coordinate of the core
 * points, the rounding of a distance computed from those coordinates; then the touch normal
 * is t0 x t1 when the unit tangents' cross product exceeds CD_CONTACT_TANGENT_SIN
 * (dimensionless: the sine of their angle), far above its rounding (a few eps) so that the
 * normalised product has its direction to at least 8 digits. */
#define CD_CONTACT_TOUCH_ULPS 16.0
#define CD_CONTACT_TANGENT_SIN 1e-8
/* Gradients: a curve or a second disk crossing a disk inside its rim keeps the distance 0 on a
 * neighbourhood (CDIST_GRAD_NOT_DIFFERENTIABLE stays clear) when it leaves the disk's plane at
 * a sine above CD_GRAD_TRANSVERSAL_SIN (dimensionless), far above the rounding of the unit
 * vectors involved. */
#define CD_GRAD_TRANSVERSAL_SIN 1e-6

#endif
