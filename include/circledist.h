/* SPDX-License-Identifier: MIT */
/** @file circledist.h
 * libcircledist: exact minimum distance and every closest pair between 3D circles, disks,
 * points, lines, rays, segments, arcs and parametric curves.
 *
 * Conventions used throughout:
 * - Every query takes a query handle, its objects by pointer, and a caller-provided result,
 *   and returns a ::cdist_status. On success the result holds the global minimum distance
 *   and up to two closest pairs; on error the result holds distance NaN and no pairs, and
 *   cdist_query_last_error() explains what was wrong.
 * - Normals and directions must be non-zero and finite. By default their length must be 1
 *   within a relative tolerance of 1e-6 (see cdist_query_set_unit_tolerance()); accepted
 *   vectors are normalised before use. A line's parameter t always refers to the direction
 *   exactly as the caller passed it.
 * - A radius must be finite and >= 0. Radius 0 is allowed: the circle (or disk) is its centre.
 * - Coordinates and radii must not exceed 1e150 in magnitude (their squares must not
 *   overflow); larger values give ::CDIST_ERR_OUT_OF_RANGE.
 * - Circle angles (the `param` of a point on a circle or disk) are measured in the basis
 *   {U, V, N} returned by cdist_circle_basis(): a point at angle a is
 *   C + r (cos a U + sin a V), with a in (-pi, pi].
 * - Thread safety: a ::cdist_query handle must be used by one thread at a time. Use one
 *   handle per thread; distinct handles share nothing. Functions without a handle argument
 *   are thread-safe. A call that finds its handle in use by another thread's call returns
 *   ::CDIST_ERR_HANDLE_BUSY at once, without touching the handle (its result, when given,
 *   is set to NaN with no pairs): an atomic flag per handle, taken on entry and released on
 *   exit, detects the misuse cheaply (it is a diagnostic, not a lock: the rule stands).
 * - The library never aborts, exits or prints.
 */
#ifndef CIRCLEDIST_H
#define CIRCLEDIST_H

#include <stddef.h>

#include "circledist_version.h"

#ifdef __cplusplus
extern "C" {
#endif

#if defined(_WIN32) && !defined(__GNUC__)
#define CDIST_API
#else
/** Marks a symbol exported from libcircledist (everything else is hidden). */
#define CDIST_API __attribute__((visibility("default")))
#endif

/** @defgroup objects Objects, results and enumerations
 *  @{ */

/** A point or vector in 3D. */
typedef struct cdist_vec3 {
    double x; /**< x coordinate */
    double y; /**< y coordinate */
    double z; /**< z coordinate */
} cdist_vec3;

/** A circle: the points at distance `radius` from `center` in the plane through `center`
 * orthogonal to `normal`. The same struct describes a disk (the circle plus its interior).
 */
typedef struct cdist_circle {
    cdist_vec3 center; /**< centre of the circle */
    cdist_vec3 normal; /**< unit normal of the circle's plane */
    double radius;     /**< radius, >= 0 */
} cdist_circle;

/** A line: origin + t * direction for every real t. */
typedef struct cdist_line {
    cdist_vec3 origin;    /**< a point of the line */
    cdist_vec3 direction; /**< unit direction */
} cdist_line;

/** A ray: origin + t * direction for t >= 0. */
typedef struct cdist_ray {
    cdist_vec3 origin;    /**< the ray's start point */
    cdist_vec3 direction; /**< unit direction */
} cdist_ray;

/** A segment: p0 + s * (p1 - p0) for s in [0, 1]. p0 == p1 is allowed (a point). */
typedef struct cdist_segment {
    cdist_vec3 p0; /**< start point (s = 0) */
    cdist_vec3 p1; /**< end point (s = 1) */
} cdist_segment;

/** A circular arc: the points C + r (cos a U + sin a V) of `circle` for a in [start, end],
 * where U = `zero_direction` (projected onto the circle's plane and normalised) and
 * V = N x U. Requires start <= end <= start + 2 pi, checked exactly: end must not exceed the
 * exact sum start + 2 pi rounded up to a double (so an end computed in double as
 * start + 2 * M_PI is accepted, and nothing longer whatever |start|), else
 * ::CDIST_ERR_BAD_INTERVAL.
 */
typedef struct cdist_arc {
    cdist_circle circle;       /**< the supporting circle */
    cdist_vec3 zero_direction; /**< direction of angle 0, must not be parallel to the normal */
    double start;              /**< first angle of the arc, radians */
    double end;                /**< last angle of the arc, radians */
} cdist_arc;

/** A circular helix: C + r (cos t U + sin t V) + (pitch t / (2 pi)) N for t in [t0, t1],
 * with N = `axis` (unit), U = `zero_direction` projected orthogonal to N, V = N x U.
 */
typedef struct cdist_helix {
    cdist_vec3 center;         /**< point on the axis at t = 0 */
    cdist_vec3 axis;           /**< unit axis direction */
    cdist_vec3 zero_direction; /**< direction of angle 0 (any length), not parallel to the axis:
                                     ::CDIST_ERR_ZERO_VECTOR when zero or within sin 1e-10 of
                                     it; at an angle theta from the axis, angle 0 is known to
                                     about 1.1e-16 / sin theta radians (docs/curves.md) */
    double radius;             /**< radius, >= 0 */
    double pitch;              /**< axial advance per full turn (may be 0 or negative) */
    double t0;                 /**< first angle, radians */
    double t1;                 /**< last angle, radians, >= t0 */
} cdist_helix;

/** A cubic Bezier curve with control points p[0..3], parameter t in [0, 1]. */
typedef struct cdist_bezier3 {
    cdist_vec3 p[4]; /**< control points */
} cdist_bezier3;

/** One closest pair. */
typedef struct cdist_pair {
    /** point[0] lies on the first object of the query, point[1] on the second. */
    cdist_vec3 point[2];
    /** Parameter of each point on its object: line/ray parameter t (for the direction as
     * passed), segment parameter s in [0, 1], circle/arc angle in (-pi, pi] (arcs: in the
     * arc's own frame, within [start, end]), disk: polar angle of the point (NaN at the
     * centre), curve parameter t; NaN for a point and wherever the value is meaningless
     * (e.g. a circle of radius 0).
     */
    double param[2];
} cdist_pair;

/** Query result. Output only: the library writes every field.
 *
 * Growth policy: fields are never moved or removed. Fields added in later 1.x releases take
 * their place inside `reserved` (which 1.0 sets to zero), so sizeof(cdist_result) and every
 * offset stay the same for the whole of ABI version 1 (see cdist_result_size()).
 */
typedef struct cdist_result {
    double distance;     /**< minimum distance (NaN on error) */
    double sqr_distance; /**< distance squared */
    int num_pairs;       /**< number of pairs given: 0 (error), 1 or 2 */
    /** Non-zero when infinitely many closest pairs exist (a point on a circle's axis, coaxial
     * circles, a line in a disk's plane over the disk, ...). One representative pair is given.
     */
    int equidistant;
    cdist_pair pairs[2]; /**< the closest pairs; pairs[i] valid for i < num_pairs */
    int method;          /**< the ::cdist_method that actually answered */
    int iterations;      /**< iterations used by ::CDIST_METHOD_ITERATION (else 0) */
    double reserved[8];  /**< reserved for future fields; set to zero */
} cdist_result;

/** Status codes. The numbers are fixed forever; new codes are only appended. */
typedef enum cdist_status {
    CDIST_OK = 0,                      /**< success */
    CDIST_ERR_NULL_ARGUMENT = 1,       /**< a required pointer was NULL */
    CDIST_ERR_NOT_FINITE = 2,          /**< an input number was NaN or infinite */
    CDIST_ERR_ZERO_VECTOR = 3,         /**< a normal, direction or axis had zero length */
    CDIST_ERR_NOT_UNIT = 4,            /**< a normal or direction was not unit length */
    CDIST_ERR_NEGATIVE_RADIUS = 5,     /**< a radius was negative */
    CDIST_ERR_OUT_OF_RANGE = 6,        /**< a coordinate or radius exceeded 1e150 */
    CDIST_ERR_BAD_OPTION = 7,          /**< an option value or method was not valid */
    CDIST_ERR_BAD_INTERVAL = 8,        /**< a parameter interval was empty or too long */
    CDIST_ERR_CALLBACK_FAILED = 9,     /**< a curve callback returned non-zero */
    CDIST_ERR_CALLBACK_NOT_FINITE = 10, /**< a curve callback returned NaN or infinity */
    CDIST_ERR_NO_MEMORY = 11,          /**< memory allocation failed */
    CDIST_ERR_INTERNAL = 12,           /**< an internal numerical failure (please report) */
    CDIST_ERR_HANDLE_BUSY = 13,        /**< the handle was already in use by another call (one thread per handle) */
    CDIST_ERR_COST_LIMIT = 14,         /**< the query would exceed the documented cost limit */
    CDIST_ERR_THREAD = 15,             /**< a worker thread could not be started */
    CDIST_ERR_BAD_KIND = 16,           /**< a query kind number was not a ::cdist_kind (or not one the call answers) */
    CDIST_ERR_CANCELLED = 17,          /**< a batch entry was not answered: the progress callback stopped the batch (1.1) */
    CDIST_ERR_OVERLAP = 18             /**< a batch output array overlapped an input or another output array (1.1) */
} cdist_status;

/** Algorithms. A method that a query does not have is answered by ::CDIST_METHOD_AUTO;
 * cdist_result::method says which method answered.
 */
typedef enum cdist_method {
    CDIST_METHOD_AUTO = 0,       /**< the most exact and fastest for each query (default) */
    CDIST_METHOD_POLYNOMIAL = 1, /**< polynomial roots (companion-matrix QR), polished on the true distance */
    CDIST_METHOD_ROBUST = 2,     /**< root bounding and bisection on the true derivative */
    CDIST_METHOD_ITERATION = 3   /**< geometric iteration (circle-circle) */
} cdist_method;

/** Curve callback: writes the position and derivative of the curve at parameter t and
 * returns 0; any other return value aborts the query with ::CDIST_ERR_CALLBACK_FAILED.
 */
typedef int (*cdist_curve_fn)(void *user, double t, cdist_vec3 *position, cdist_vec3 *derivative);

/** Opaque query handle: options plus every workspace a query needs, so queries never allocate. */
typedef struct cdist_query cdist_query;

/** @} */

/** @defgroup version Version
 *  @{ */
/* ---- version ------------------------------------------------------------------------ */

/** Library version as "MAJOR.MINOR.PATCH" of the library actually loaded. */
CDIST_API const char *cdist_version_string(void);
/** Library version as MAJOR*10000 + MINOR*100 + PATCH of the library actually loaded. */
CDIST_API unsigned cdist_version_number(void);
/** Major version of the library actually loaded. */
CDIST_API int cdist_version_major(void);
/** Minor version of the library actually loaded. */
CDIST_API int cdist_version_minor(void);
/** Patch version of the library actually loaded. */
CDIST_API int cdist_version_patch(void);

/** @} */

/** @defgroup status Status names and struct sizes
 *  @{ */
/* ---- status, sizes ------------------------------------------------------------------ */

/** A one-sentence description of a status ("unknown status" for numbers not listed). */
CDIST_API const char *cdist_status_string(cdist_status status);
/** The enumerator's name, e.g. "CDIST_ERR_NOT_UNIT" ("CDIST_UNKNOWN" if not listed). */
CDIST_API const char *cdist_status_name(cdist_status status);
/** The method's short name as the circledist tool's --method option spells it: "auto",
 * "polynomial", "robust", "iteration" ("unknown" for numbers not listed). Since 1.1. */
CDIST_API const char *cdist_method_name(cdist_method method);
/** sizeof(cdist_result) as compiled into the library, for FFI users to check their layout. */
CDIST_API size_t cdist_result_size(void);
/** sizeof(cdist_pair) as compiled into the library. */
CDIST_API size_t cdist_pair_size(void);

/** @} */

/** @defgroup handle Query handle and options
 *  @{ */
/* ---- query handle ------------------------------------------------------------------- */

/** Creates a query handle with default options. Returns NULL if memory runs out. */
CDIST_API cdist_query *cdist_query_new(void);
/** Frees a handle and its workspaces. NULL is allowed and does nothing. */
CDIST_API void cdist_query_free(cdist_query *q);
/** Selects the algorithm for later queries (default ::CDIST_METHOD_AUTO).
 * Returns ::CDIST_ERR_BAD_OPTION for a number that is not a ::cdist_method.
 */
CDIST_API cdist_status cdist_query_set_method(cdist_query *q, cdist_method method);
/** The selected algorithm (::CDIST_METHOD_AUTO for a NULL handle). */
CDIST_API cdist_method cdist_query_get_method(const cdist_query *q);
/** Sets the relative tolerance for unit normals and directions: a vector is accepted when
 * | |v| - 1 | <= tol and is then normalised. Pass INFINITY to accept (and normalise) any
 * non-zero length, 0 to demand |v| == 1 as computed in double. Default 1e-6.
 */
CDIST_API cdist_status cdist_query_set_unit_tolerance(cdist_query *q, double tol);
/** The unit-length tolerance (see cdist_query_set_unit_tolerance()). */
CDIST_API double cdist_query_get_unit_tolerance(const cdist_query *q);
/** Sets how many subintervals curve queries sample to bracket the critical points before
 * refining them (minimum 8, default 512). More samples catch closer pairs of extrema.
 */
CDIST_API cdist_status cdist_query_set_curve_samples(cdist_query *q, int samples);
/** The curve sample count. */
CDIST_API int cdist_query_get_curve_samples(const cdist_query *q);
/** Sets the iteration cap of ::CDIST_METHOD_ITERATION per start (minimum 1, default 200). */
CDIST_API cdist_status cdist_query_set_max_iterations(cdist_query *q, int max_iterations);
/** The iteration cap. */
CDIST_API int cdist_query_get_max_iterations(const cdist_query *q);
/** Status of the last query or setter called on this handle. */
CDIST_API cdist_status cdist_query_last_status(const cdist_query *q);
/** Message describing the last error on this handle ("" after success). The string is owned
 * by the handle and valid until the next call with it.
 */
CDIST_API const char *cdist_query_last_error(const cdist_query *q);

/** @} */

/** @defgroup frames Circle frames (angles of points on circles)
 *  @{ */
/* ---- circle frames ------------------------------------------------------------------ */

/** The basis in which circle angles are measured. With N the normalised normal and k the
 * index of N's component of smallest magnitude (the first on ties), U = e_k - N_k N
 * normalised, V = N x U. Writes U and V (either may be NULL).
 */
CDIST_API cdist_status cdist_circle_basis(const cdist_circle *c, cdist_vec3 *u, cdist_vec3 *v);
/** The point of circle c at angle `angle` in the basis of cdist_circle_basis(). */
CDIST_API cdist_status cdist_circle_point(const cdist_circle *c, double angle, cdist_vec3 *point);

/** @} */

/** @defgroup points Point queries
 *  @{ */
/* ---- point queries ------------------------------------------------------------------ */

/** Distance from point p to circle c. equidistant when p is on the circle's axis. */
CDIST_API cdist_status cdist_point_circle(cdist_query *q, const cdist_vec3 *p, const cdist_circle *c, cdist_result *r);
/** Distance from point p to disk d (circle plus interior). */
CDIST_API cdist_status cdist_point_disk(cdist_query *q, const cdist_vec3 *p, const cdist_circle *d, cdist_result *r);

/** @} */

/** @defgroup lines Lines, rays and segments to circles
 *  @{ */
/* ---- lines, rays, segments to circles ---------------------------------------------- */

/** Distance from a line to a circle (methods: POLYNOMIAL, ROBUST; AUTO = ROBUST). */
CDIST_API cdist_status cdist_line_circle(cdist_query *q, const cdist_line *l, const cdist_circle *c, cdist_result *r);
/** Distance from a ray (t >= 0) to a circle. */
CDIST_API cdist_status cdist_ray_circle(cdist_query *q, const cdist_ray *l, const cdist_circle *c, cdist_result *r);
/** Distance from a segment to a circle; param[0] is the segment parameter s in [0, 1]. */
CDIST_API cdist_status cdist_segment_circle(cdist_query *q, const cdist_segment *s, const cdist_circle *c, cdist_result *r);

/** @} */

/** @defgroup circles Circle to circle
 *  @{ */
/* ---- circle to circle --------------------------------------------------------------- */

/** Distance between two circles (methods: POLYNOMIAL, ROBUST, ITERATION; AUTO picks).
 * Swapping c0 and c1 gives the same distance, pair count and equidistant flag, with the pairs'
 * points swapped, under every method. The normals are used as unit vectors (scaled to length 1
 * when accepted within the unit tolerance).
 * Equidistant configurations (coaxial circles, identical circles, a meridian or Villarceau
 * circle of the other's torus, a closest point on the other circle's axis) are decided with a
 * tolerance, not exactly on the doubles: with L = max(r0, r1, |C1 - C0|), equidistant is set
 * when the distance from the points of one circle to the other varies by at most 32 eps L
 * (eps = DBL_EPSILON), or a closest point lies within 8 eps (r0 + r1 + |C1 - C0|) min(1, r / L)
 * of the other circle's axis (r that circle's radius); one representative pair is given. So
 * two circles that differ only by a few ulps of L (e.g. equal coplanar circles of radius 100
 * whose centres are 1.1e-14 apart, which meet at exactly two points) are reported as one
 * equidistant pair: their distance varies by less than the accuracy of the answer (a few
 * eps L), which cannot resolve two separate minima.
 */
CDIST_API cdist_status cdist_circle_circle(cdist_query *q, const cdist_circle *c0, const cdist_circle *c1, cdist_result *r);
/** Answers n circle-circle queries: results[i] and statuses[i] for (c0[i], c1[i]); the same as
 *  cdist_batch() with ::CDIST_KIND_CIRCLE_CIRCLE and strides sizeof(cdist_circle). A bad entry
 *  gets its own status and a NaN result; the others are still answered. Returns ::CDIST_OK
 *  when every entry succeeded, else the status of the first failing entry (whose index and
 *  message cdist_query_last_error() then gives). statuses may be NULL. */
CDIST_API cdist_status cdist_circle_circle_batch(cdist_query *q, size_t n, const cdist_circle *c0,
                                                 const cdist_circle *c1, cdist_result *results,
                                                 cdist_status *statuses);

/** @} */

/** @defgroup disks Disks
 *  @{ */
/* ---- disks -------------------------------------------------------------------------- */

/** Distance from a line to a disk. */
CDIST_API cdist_status cdist_line_disk(cdist_query *q, const cdist_line *l, const cdist_circle *d, cdist_result *r);
/** Distance from a ray to a disk. */
CDIST_API cdist_status cdist_ray_disk(cdist_query *q, const cdist_ray *l, const cdist_circle *d, cdist_result *r);
/** Distance from a segment to a disk. */
CDIST_API cdist_status cdist_segment_disk(cdist_query *q, const cdist_segment *s, const cdist_circle *d, cdist_result *r);
/** Distance from a circle (first) to a disk (second). */
CDIST_API cdist_status cdist_circle_disk(cdist_query *q, const cdist_circle *c, const cdist_circle *d, cdist_result *r);
/** Distance between two disks. */
CDIST_API cdist_status cdist_disk_disk(cdist_query *q, const cdist_circle *d0, const cdist_circle *d1, cdist_result *r);

/** @} */

/** @defgroup curves Curves, arcs, helices and Bezier curves
 *  @{ */
/* ---- curves and arcs ---------------------------------------------------------------- */
/* These queries have one method (root bounding and bisection, answered as
 * ::CDIST_METHOD_ROBUST whatever the handle's method). Arcs are exact: their candidates are the
 * circle-circle critical points inside the range plus the end points (closed form for arcs on
 * coaxial circles). Helices and Bezier curves are sampled at cdist_query_get_curve_samples()
 * intervals (per turn for a helix, at most 4096 per turn) to bracket critical points, and the
 * answer is then certified: every interval is bounded below (from bounds of the curve's first
 * and second derivatives, and for a helix its cylinder and slab), and one whose bound is below
 * the answer minus tau = 512 eps L (about 1.1e-13 of the problem scale L, rounding included) is split and
 * searched; so the distance is within tau of the global minimum at every sample count (the
 * count trades speed only). A second closest pair less than tau from the answer may go
 * unreported when the bound excluded its region. The sampled fallback of arc-circle and
 * arc-disk (parallel configurations) is certified the same way; the other fallbacks sample a
 * function known to be constant, or (segment-arc, when the lines core fails) are not certified.
 * Callback curves (cdist_curve_circle, cdist_curve_disk) are NOT certified: no bound of the
 * callback's derivatives is known. A minimum is found when g = F'/2 changes sign between two
 * samples, or dips to zero between samples of one sign where the golden-section search finds
 * it; a basin narrower than the sample spacing can be missed, and the answer is then the
 * distance of another local minimum or an end point (a true distance, above the minimum).
 * Raise the sample count for curves with fine detail.
 * Cost limits (::CDIST_ERR_COST_LIMIT): a helix query spends at most 12000 evaluations of the
 * curve (samples, refinement and certification, whatever the turns and the sample count) and
 * refuses when it would need more. Turns are skipped when a lower bound (from the axial and
 * radial geometry) shows they cannot beat the distance found by more than tau; when the turns
 * that cannot be skipped do not fit the budget (more than about 70 about equally close: a target
 * threading a long, tight coil) the query refuses before scanning them. A certification that
 * needs more than 200000 interval splits stops. */

/** Distance from the curve f(t), t in [t0, t1], to a circle; param[0] is the curve parameter.
 * The curve must be continuously differentiable and f must give its exact derivative.
 */
CDIST_API cdist_status cdist_curve_circle(cdist_query *q, cdist_curve_fn f, void *user, double t0, double t1,
                                          const cdist_circle *c, cdist_result *r);
/** Distance from the curve f(t), t in [t0, t1], to a disk. */
CDIST_API cdist_status cdist_curve_disk(cdist_query *q, cdist_curve_fn f, void *user, double t0, double t1,
                                        const cdist_circle *d, cdist_result *r);
/** Distance from an arc to a circle; param[0] is the arc angle. */
CDIST_API cdist_status cdist_arc_circle(cdist_query *q, const cdist_arc *a, const cdist_circle *c, cdist_result *r);
/** Distance between two arcs. */
CDIST_API cdist_status cdist_arc_arc(cdist_query *q, const cdist_arc *a0, const cdist_arc *a1, cdist_result *r);
/** Distance from a segment (first) to an arc (second). */
CDIST_API cdist_status cdist_segment_arc(cdist_query *q, const cdist_segment *s, const cdist_arc *a, cdist_result *r);
/** Distance from an arc to a disk. */
CDIST_API cdist_status cdist_arc_disk(cdist_query *q, const cdist_arc *a, const cdist_circle *d, cdist_result *r);
/** Distance from a helix to a circle; param[0] is the helix parameter t. */
CDIST_API cdist_status cdist_helix_circle(cdist_query *q, const cdist_helix *h, const cdist_circle *c, cdist_result *r);
/** Distance from a helix to a disk. */
CDIST_API cdist_status cdist_helix_disk(cdist_query *q, const cdist_helix *h, const cdist_circle *d, cdist_result *r);
/** Distance from a cubic Bezier curve to a circle; param[0] is the Bezier parameter. */
CDIST_API cdist_status cdist_bezier3_circle(cdist_query *q, const cdist_bezier3 *b, const cdist_circle *c, cdist_result *r);
/** Distance from a cubic Bezier curve to a disk. */
CDIST_API cdist_status cdist_bezier3_disk(cdist_query *q, const cdist_bezier3 *b, const cdist_circle *d, cdist_result *r);

/** @} */

/** @defgroup batches Batches
 *  @{ */
/* ---- batches ------------------------------------------------------------------------ */

/** Query kinds for the batch entry points. Numbers are fixed; new kinds are appended. The
 *  comment of each kind names the types of its first (a) and second (b) objects; a kind
 *  without a comment has the types its name says (a ray is a ::cdist_ray, a disk a
 *  ::cdist_circle, ...). cdist_kind_size_a() and cdist_kind_size_b() give their sizes. */
typedef enum cdist_kind {
    CDIST_KIND_POINT_CIRCLE = 0,    /**< a: cdist_vec3,     b: cdist_circle */
    CDIST_KIND_POINT_DISK = 1,      /**< a: cdist_vec3,     b: cdist_circle as a disk */
    CDIST_KIND_LINE_CIRCLE = 2,     /**< a: cdist_line,     b: cdist_circle */
    CDIST_KIND_RAY_CIRCLE = 3,      /**< a: cdist_ray,      b: cdist_circle */
    CDIST_KIND_SEGMENT_CIRCLE = 4,  /**< a: cdist_segment,  b: cdist_circle */
    CDIST_KIND_CIRCLE_CIRCLE = 5,   /**< a: cdist_circle,   b: cdist_circle */
    CDIST_KIND_LINE_DISK = 6,       /**< a: cdist_line,     b: cdist_circle as a disk */
    CDIST_KIND_RAY_DISK = 7,        /**< a: cdist_ray,      b: cdist_circle as a disk */
    CDIST_KIND_SEGMENT_DISK = 8,    /**< a: cdist_segment,  b: cdist_circle as a disk */
    CDIST_KIND_CIRCLE_DISK = 9,     /**< a: cdist_circle,   b: cdist_circle as a disk */
    CDIST_KIND_DISK_DISK = 10,      /**< a: cdist_circle as a disk, b: cdist_circle as a disk */
    CDIST_KIND_CURVE_CIRCLE = 11,   /**< a: cdist_curve: callback and interval, b: cdist_circle */
    CDIST_KIND_CURVE_DISK = 12,     /**< a: cdist_curve,    b: cdist_circle as a disk */
    CDIST_KIND_ARC_CIRCLE = 13,     /**< a: cdist_arc,      b: cdist_circle */
    CDIST_KIND_ARC_ARC = 14,        /**< a: cdist_arc,      b: cdist_arc */
    CDIST_KIND_SEGMENT_ARC = 15,    /**< a: cdist_segment,  b: cdist_arc */
    CDIST_KIND_ARC_DISK = 16,       /**< a: cdist_arc,      b: cdist_circle as a disk */
    CDIST_KIND_HELIX_CIRCLE = 17,   /**< a: cdist_helix,    b: cdist_circle */
    CDIST_KIND_HELIX_DISK = 18,     /**< a: cdist_helix,    b: cdist_circle as a disk */
    CDIST_KIND_BEZIER3_CIRCLE = 19, /**< a: cdist_bezier3,  b: cdist_circle */
    CDIST_KIND_BEZIER3_DISK = 20,   /**< a: cdist_bezier3,  b: cdist_circle as a disk */
    /* Contact kinds (1.1): the swept-object queries, results in ::cdist_contact
     * (cdist_batch_contact(), cdist_batch_grad(); cdist_batch_distance() gives the signed
     * distance). A torus is a ::cdist_torus, a capsule a ::cdist_capsule, ... */
    CDIST_KIND_TORUS_TORUS = 21,               /**< cdist_torus_torus() */
    CDIST_KIND_TORUS_CAPSULE = 22,             /**< cdist_torus_capsule() */
    CDIST_KIND_TORUS_SPHERE = 23,              /**< cdist_torus_sphere() */
    CDIST_KIND_TORUS_ROUNDED_DISK = 24,        /**< cdist_torus_rounded_disk() */
    CDIST_KIND_CAPSULE_CAPSULE = 25,           /**< cdist_capsule_capsule() */
    CDIST_KIND_CAPSULE_SPHERE = 26,            /**< cdist_capsule_sphere() */
    CDIST_KIND_CAPSULE_ROUNDED_DISK = 27,      /**< cdist_capsule_rounded_disk() */
    CDIST_KIND_SPHERE_SPHERE = 28,             /**< cdist_sphere_sphere() */
    CDIST_KIND_SPHERE_ROUNDED_DISK = 29,       /**< cdist_sphere_rounded_disk() */
    CDIST_KIND_ROUNDED_DISK_ROUNDED_DISK = 30, /**< cdist_rounded_disk_rounded_disk() */
    CDIST_KIND_TORUS_LINE = 31,                /**< cdist_torus_line() */
    CDIST_KIND_TORUS_RAY = 32,                 /**< cdist_torus_ray() */
    CDIST_KIND_TORUS_SEGMENT = 33,             /**< cdist_torus_segment() */
    CDIST_KIND_CAPSULE_CIRCLE = 34,            /**< cdist_capsule_circle() */
    CDIST_KIND_CAPSULE_DISK = 35,              /**< cdist_capsule_disk(), b: cdist_circle as a disk */
    CDIST_KIND_SPHERE_CIRCLE = 36,             /**< cdist_sphere_circle() */
    CDIST_KIND_SPHERE_DISK = 37                /**< cdist_sphere_disk(), b: cdist_circle as a disk */
} cdist_kind;

/** A callback curve as one value, for batches: fn(user, t, ...) for t in [t0, t1], the
 *  arguments of cdist_curve_circle(). A NULL fn is a bad entry (::CDIST_ERR_NULL_ARGUMENT). */
typedef struct cdist_curve {
    cdist_curve_fn fn; /**< the curve callback */
    void *user;        /**< passed to fn unchanged */
    double t0;         /**< first parameter */
    double t1;         /**< last parameter, >= t0 */
} cdist_curve;

/** Number of kinds (one past the largest ::cdist_kind). */
CDIST_API int cdist_kind_count(void);
/** The kind's name in lower case without prefix ("point_circle", "circle_circle", ...); NULL for
 *  a number that is not a kind. */
CDIST_API const char *cdist_kind_name(cdist_kind kind);
/** sizeof the first object type of a kind (0 for a number that is not a kind), for FFI users. */
CDIST_API size_t cdist_kind_size_a(cdist_kind kind);
/** sizeof the second object type of a kind (0 for a number that is not a kind). */
CDIST_API size_t cdist_kind_size_b(cdist_kind kind);

/** Full results for n queries of one kind (not a contact kind: ::CDIST_ERR_BAD_KIND, use
 *  cdist_batch_contact()). Object i of the first array is at
 *  (const char *)a + i * a_stride (bytes; 0 repeats one object = broadcast, negative allowed),
 *  likewise b. results[i] (contiguous, n entries) and statuses[i] (may be NULL) are written for
 *  every i; a bad entry gets its status and a NaN result with no pairs, the others are answered,
 *  each exactly as the single query (e.g. cdist_point_circle()) answers it. Uses the handle's
 *  method and options and its worker threads (cdist_query_set_threads()); never allocates.
 *  Returns ::CDIST_OK when every entry succeeded, else the status of the lowest-index failing
 *  entry (cdist_query_last_error() names the index and gives that entry's message). A NULL
 *  handle or array (for n > 0): ::CDIST_ERR_NULL_ARGUMENT; a number that is not a kind:
 *  ::CDIST_ERR_BAD_KIND; in both cases results and statuses are still filled (NaN / that
 *  status) whenever they are writable. n = 0 does nothing and returns ::CDIST_OK. */
CDIST_API cdist_status cdist_batch(cdist_query *q, cdist_kind kind, size_t n, const void *a, ptrdiff_t a_stride,
                                   const void *b, ptrdiff_t b_stride, cdist_result *results,
                                   cdist_status *statuses);

/** Distance only (no pairs, params or flags), for screening: distances[i] equals the full
 *  query's distance to <= 2 ulps of the problem scale; NaN for a bad entry. May use SIMD kernels
 *  with a certified screen (uncertain entries go to the scalar path). Same conventions as
 *  cdist_batch(). Every kind, contact kinds included (1.1): their signed distance, the core's
 *  distance (from the core kind's kernel where it has one) minus the radii. */
CDIST_API cdist_status cdist_batch_distance(cdist_query *q, cdist_kind kind, size_t n, const void *a,
                                            ptrdiff_t a_stride, const void *b, ptrdiff_t b_stride,
                                            double *distances, cdist_status *statuses);

/* Batch conventions shared by every batch entry (cdist_batch(), cdist_batch_distance(),
 * cdist_batch_contact(), cdist_batch_grad()):
 * - The output arrays (results, contacts, gradients, distances, statuses) must not overlap the
 *   input objects (the n strided entries of a and of b) nor each other: an entry's outputs are
 *   written while later entries are still to be read. From 1.1 such a call is refused before
 *   anything is read or written: ::CDIST_ERR_OVERLAP (the message names the arrays), outputs
 *   untouched. (The check compares address ranges; a callback curve's user data is not checked.)
 * - Progress and cancel (1.1): see cdist_query_set_progress(). A cancelled batch returns
 *   ::CDIST_ERR_CANCELLED; every entry answered before the stop keeps its answer and status,
 *   every other entry gets status ::CDIST_ERR_CANCELLED and the error state (NaN). */

/** Worker threads used by the batch calls (default 1; 1..256; the calling thread is one of
 *  them). Workers and their workspaces are created here and live in the handle (they are
 *  joined by cdist_query_free()), so batches never allocate. Results are bit-identical for
 *  every thread count. Returns ::CDIST_ERR_BAD_OPTION outside 1..256, ::CDIST_ERR_THREAD or
 *  ::CDIST_ERR_NO_MEMORY when the workers cannot be created (the handle then has 1 thread). */
CDIST_API cdist_status cdist_query_set_threads(cdist_query *q, int threads);
/** The worker thread count (1 for a NULL handle). */
CDIST_API int cdist_query_get_threads(const cdist_query *q);

/** @} */

/** @defgroup swept Swept objects: spheres, capsules, tori, rounded disks
 *  @{ */
/* ---- swept objects and gradients ---------------------------------------------------- */
/* A swept object is a core (point, segment, circle, disk) swept by a ball of radius
 * `radius`: the set of points within `radius` of the core. The signed distance between two
 * swept objects (or a swept object and a plain object, radius 0) is
 *     distance = core_distance - (radius_a + radius_b)
 * (evaluated exactly in that order), negative when the solids overlap: then -distance is the
 * penetration depth along the closest pair of the cores. */

/** A sphere: a point swept by a ball. sizeof = 32 bytes (4 doubles). */
typedef struct cdist_sphere {
    cdist_vec3 center; /**< centre */
    double radius;     /**< radius, >= 0 (0: a point) */
} cdist_sphere;

/** A capsule: a segment swept by a ball. sizeof = 56 bytes (7 doubles). */
typedef struct cdist_capsule {
    cdist_segment segment; /**< the core segment (p0 == p1 allowed: a sphere) */
    double radius;         /**< radius of the ball, >= 0 */
} cdist_capsule;

/** A torus: a circle swept by a ball (the solid torus; a spindle torus when
 *  tube_radius > circle.radius). sizeof = 64 bytes (8 doubles). */
typedef struct cdist_torus {
    cdist_circle circle; /**< the core circle (centre line of the tube) */
    double tube_radius;  /**< tube radius, >= 0 */
} cdist_torus;

/** A rounded disk: a disk swept by a ball (a coin with rounded rim). sizeof = 64 bytes. */
typedef struct cdist_rounded_disk {
    cdist_circle disk; /**< the core disk */
    double radius;     /**< radius of the ball, >= 0 */
} cdist_rounded_disk;

/** One closest pair of a contact query. */
typedef struct cdist_contact_pair {
    /** Witness points on the two surfaces: point[0] = core_point[0] + r0 * normal,
     *  point[1] = core_point[1] - r1 * normal (so distance = (point[1] - point[0]) . normal;
     *  when the solids overlap point[0] lies inside the second solid and vice versa). */
    cdist_vec3 point[2];
    /** The closest pair of the cores, exactly as the core query returned it. */
    cdist_vec3 core_point[2];
    /** Unit contact normal pointing from the first object to the second:
     *  (core_point[1] - core_point[0]) / core_distance when the cores are apart, otherwise
     *  chosen by the rule of ::CDIST_CONTACT_CORE_TOUCH. */
    cdist_vec3 normal;
    /** Parameters of the core points as in ::cdist_pair; NaN for a point core. */
    double param[2];
} cdist_contact_pair;

/** Contact result flags (bits of cdist_contact::flags). Values are fixed. */
typedef enum cdist_contact_flag {
    /** The cores touch or cross (core_distance <= 16 eps times the largest coordinate of the
     *  core points): no closest-pair direction exists and the normal is chosen
     *  deterministically, first rule that gives a non-zero vector: (1) both cores are curves
     *  (segment/line/ray direction, circle tangent N x (P - C)) and their tangents at the core
     *  points are not parallel: normal = t0 x t1; (2) a core is a circle or disk (first object
     *  first): its plane normal; (3) a core is a segment/line/ray (first first): the U vector
     *  of cdist_circle_basis() for a circle with that direction as normal; (4) (0, 0, 1).
     *  The sign is then chosen so that normal . (m1 - m0) > 0, m = the core's reference point
     *  (centre, segment midpoint, line/ray origin), or if that is 0 so that the first
     *  non-zero component is positive. */
    CDIST_CONTACT_CORE_TOUCH = 1
} cdist_contact_flag;

/** Result of a swept-object (contact) query. Output only: the library writes every field.
 *  Growth policy as for ::cdist_result: new fields take their place in `reserved` (zero in
 *  1.0), sizeof (368 bytes on LP64, see cdist_contact_size()) never changes in ABI 1. */
typedef struct cdist_contact {
    double distance;      /**< signed distance = core_distance - (r0 + r1) (NaN on error) */
    double core_distance; /**< distance between the cores, from the core query */
    int num_pairs;        /**< 0 (error), 1 or 2, carried over from the core query */
    int equidistant;      /**< carried over from the core query (infinitely many pairs) */
    int flags;            /**< bits of ::cdist_contact_flag */
    int method;           /**< the ::cdist_method that answered the core query */
    cdist_contact_pair pairs[2]; /**< pairs[i] valid for i < num_pairs */
    double reserved[8];   /**< reserved for future fields; set to zero */
} cdist_contact;

/** sizeof(cdist_contact) as compiled into the library. */
CDIST_API size_t cdist_contact_size(void);
/** sizeof(cdist_sphere), sizeof(cdist_capsule), sizeof(cdist_torus), sizeof(cdist_rounded_disk)
 *  for which = 0, 1, 2, 3 (0 otherwise), for FFI users to check their layout. */
CDIST_API size_t cdist_swept_size(int which);
/** The value of ::CDIST_CONTACT_CORE_TOUCH (for bindings without the header). */
CDIST_API int cdist_contact_flag_core_touch(void);

/* Contact queries. Every one validates its objects like the core queries (radii: finite,
 * >= 0, <= 1e150; else ::CDIST_ERR_NOT_FINITE / ::CDIST_ERR_NEGATIVE_RADIUS /
 * ::CDIST_ERR_OUT_OF_RANGE), answers the core query with the handle's method and options,
 * and fills the contact; on error: distance NaN, no pairs. Object order in the name is the
 * order of point[0] / point[1]. */

/** Torus to torus (core: cdist_circle_circle()). */
CDIST_API cdist_status cdist_torus_torus(cdist_query *q, const cdist_torus *a, const cdist_torus *b, cdist_contact *c);
/** Torus to capsule (core: cdist_segment_circle(), objects swapped back). */
CDIST_API cdist_status cdist_torus_capsule(cdist_query *q, const cdist_torus *a, const cdist_capsule *b, cdist_contact *c);
/** Torus to sphere (core: cdist_point_circle(), swapped back). */
CDIST_API cdist_status cdist_torus_sphere(cdist_query *q, const cdist_torus *a, const cdist_sphere *b, cdist_contact *c);
/** Torus to rounded disk (core: cdist_circle_disk()). */
CDIST_API cdist_status cdist_torus_rounded_disk(cdist_query *q, const cdist_torus *a, const cdist_rounded_disk *b, cdist_contact *c);
/** Capsule to capsule (core: segment-segment, answered in closed form; equidistant when the
 *  segments are parallel with overlapping projections). */
CDIST_API cdist_status cdist_capsule_capsule(cdist_query *q, const cdist_capsule *a, const cdist_capsule *b, cdist_contact *c);
/** Capsule to sphere (core: point-segment, closed form). */
CDIST_API cdist_status cdist_capsule_sphere(cdist_query *q, const cdist_capsule *a, const cdist_sphere *b, cdist_contact *c);
/** Capsule to rounded disk (core: cdist_segment_disk()). */
CDIST_API cdist_status cdist_capsule_rounded_disk(cdist_query *q, const cdist_capsule *a, const cdist_rounded_disk *b, cdist_contact *c);
/** Sphere to sphere (core: point-point). */
CDIST_API cdist_status cdist_sphere_sphere(cdist_query *q, const cdist_sphere *a, const cdist_sphere *b, cdist_contact *c);
/** Sphere to rounded disk (core: cdist_point_disk()). */
CDIST_API cdist_status cdist_sphere_rounded_disk(cdist_query *q, const cdist_sphere *a, const cdist_rounded_disk *b, cdist_contact *c);
/** Rounded disk to rounded disk (core: cdist_disk_disk()). */
CDIST_API cdist_status cdist_rounded_disk_rounded_disk(cdist_query *q, const cdist_rounded_disk *a, const cdist_rounded_disk *b, cdist_contact *c);
/** Torus to line (core: cdist_line_circle(), swapped back). */
CDIST_API cdist_status cdist_torus_line(cdist_query *q, const cdist_torus *a, const cdist_line *b, cdist_contact *c);
/** Torus to ray (core: cdist_ray_circle(), swapped back). */
CDIST_API cdist_status cdist_torus_ray(cdist_query *q, const cdist_torus *a, const cdist_ray *b, cdist_contact *c);
/** Torus to segment (core: cdist_segment_circle(), swapped back). */
CDIST_API cdist_status cdist_torus_segment(cdist_query *q, const cdist_torus *a, const cdist_segment *b, cdist_contact *c);
/** Capsule to circle (core: cdist_segment_circle()). */
CDIST_API cdist_status cdist_capsule_circle(cdist_query *q, const cdist_capsule *a, const cdist_circle *b, cdist_contact *c);
/** Capsule to disk (core: cdist_segment_disk()). */
CDIST_API cdist_status cdist_capsule_disk(cdist_query *q, const cdist_capsule *a, const cdist_circle *b, cdist_contact *c);
/** Sphere to circle (core: cdist_point_circle()). */
CDIST_API cdist_status cdist_sphere_circle(cdist_query *q, const cdist_sphere *a, const cdist_circle *b, cdist_contact *c);
/** Sphere to disk (core: cdist_point_disk()). */
CDIST_API cdist_status cdist_sphere_disk(cdist_query *q, const cdist_sphere *a, const cdist_circle *b, cdist_contact *c);

/** @} */

/** @defgroup gradients Gradients
 *  @{ */
/* ---- gradients ----
 * A `_grad` query answers the query and writes the derivative of the distance with respect to
 * every input parameter of both objects, from the closest pair (envelope theorem): with P on
 * the first object, Q on the second and w = (P - Q) / |P - Q|, dD/dtheta = w . dP/dtheta for
 * the first object's parameters and -w . dQ/dtheta for the second's, the points' own
 * parameters held fixed in a parametrisation whose range does not depend on theta:
 *   point P:               dP = dp;
 *   line/ray o + t d:      dP = do + t dd (t fixed; for a ray t >= 0 fixed, so a ray start
 *                          point closest gives d_direction = 0 since t = 0);
 *   segment p0 + s(p1-p0): dP = (1-s) dp0 + s dp1 (s in [0,1] fixed: end points included);
 *   circle C + r e:        e the unit radial direction, moved by the smallest rotation
 *                          taking N to N + dN: de = -(e . dN) N;
 *   disk C + r s e:        s in [0,1] fixed (rim s = 1, interior s < 1; the interior gives
 *                          d_radius = 0 because w is along N there, and d_normal =
 *                          -(w . N)(P - C): tilting the disk moves the point);
 *   arc:                   angle a fixed inside [start, end]; d_start / d_end are
 *                          r w . T(a) when the closest point is that end of the arc, else 0;
 *                          d_normal / d_zero_direction through the arc frame U, V.
 * Normal and direction gradients are tangent to the unit sphere (g . N = 0, dD = g . dN for
 * unit-preserving dN). Swept objects: the core gradient plus d_radius_swept = -1 each.
 * The flag ::CDIST_GRAD_NOT_DIFFERENTIABLE is one decision. At distance (core distance for
 * swept objects) 0, within the rounding of the closest points' coordinates, the gradient is 0;
 * the flag is not set where the distance is 0 on a whole neighbourhood -- at some closest pair
 * a curve crosses a disk's plane transversally (sine of the angle > 1e-6) at a point clearly
 * inside the rim and away from the curve's ends, or two disks in transversal planes meet in a
 * segment that reaches inside both rims -- whatever the number of pairs or the equidistant flag
 * (the zero gradient is then exact), and set otherwise (0 is an element of the Clarke
 * subdifferential). At a distance above 0 the flag is set for two closest pairs (the gradient
 * is that of pairs[0], the one-sided derivative along directions that keep it closest), an
 * equidistant result (the gradient of the representative pair: along any direction it lies
 * between the two one-sided derivatives), an arc of radius 0 (a derivative from the right) and
 * a segment or capsule core of length 0 (p0 == p1 exactly: the gradient of the pair's s, one
 * of the one-sided derivatives; moving p0 or p1 alone along w does not change the distance).
 * At a disk's interior closest point the direction w is taken as +-N exactly (the
 * optimality condition) rather than from the rounded points. A circle or disk of radius 0 is
 * differentiated from the right (r -> 0+). Accuracy: the gradient is that of the computed
 * closest pair; at relative distance delta from a non-differentiable configuration (e.g. a
 * point delta * L from a circle's axis) the pair is ill-conditioned and the gradient is
 * accurate to about eps / delta (relative), not to rounding; at a flat (degenerate) minimum
 * the pair's parameter is only determined to the rounding of the distance, and the gradient
 * moves with it by the mixed second derivative (tests/swept/test_grad.c checks both against
 * quad-precision differences). */

/** Gradient of the distance with respect to one object's parameters. Fields that do not
 *  apply to the object's kind are 0. */
typedef struct cdist_grad_object {
    cdist_vec3 d_center;    /**< point, sphere centre, circle/disk/arc/torus/rounded-disk centre */
    cdist_vec3 d_normal;    /**< circle/disk/arc/torus/rounded-disk normal (tangent space) */
    cdist_vec3 d_origin;    /**< line/ray origin */
    cdist_vec3 d_direction; /**< line/ray direction (tangent space) */
    cdist_vec3 d_p0;        /**< segment/capsule p0 */
    cdist_vec3 d_p1;        /**< segment/capsule p1 */
    cdist_vec3 d_zero_direction; /**< arc zero_direction (full 3-vector, the arc frame only
                                      depends on its direction, so it is orthogonal to it) */
    double d_radius;        /**< circle/disk/arc radius (the core radius of a torus/rounded disk) */
    double d_radius_swept;  /**< sphere/capsule radius, torus tube radius, rounded-disk radius: -1 */
    double d_start;         /**< arc start angle */
    double d_end;           /**< arc end angle */
    double reserved[8];     /**< reserved for future fields; set to zero */
} cdist_grad_object;

/** Gradient flags (bits of cdist_grad::flags). Values are fixed. */
typedef enum cdist_grad_flag {
    /** The distance is not differentiable here (see the rules above). */
    CDIST_GRAD_NOT_DIFFERENTIABLE = 1
} cdist_grad_flag;

/** Gradient of one query: obj[0] for the first object, obj[1] for the second. */
typedef struct cdist_grad {
    cdist_grad_object obj[2]; /**< per-object gradients */
    int flags;                /**< bits of ::cdist_grad_flag */
    int reserved_int;         /**< reserved; 0 */
    double reserved[8];       /**< reserved for future fields; set to zero */
} cdist_grad;

/** sizeof(cdist_grad) as compiled into the library. */
CDIST_API size_t cdist_grad_size(void);
/** The value of ::CDIST_GRAD_NOT_DIFFERENTIABLE. */
CDIST_API int cdist_grad_flag_not_differentiable(void);

/** cdist_point_circle() with the gradient. On error the gradient is all NaN. */
CDIST_API cdist_status cdist_point_circle_grad(cdist_query *q, const cdist_vec3 *p, const cdist_circle *c, cdist_result *r, cdist_grad *g);
/** cdist_point_disk() with the gradient. */
CDIST_API cdist_status cdist_point_disk_grad(cdist_query *q, const cdist_vec3 *p, const cdist_circle *d, cdist_result *r, cdist_grad *g);
/** cdist_line_circle() with the gradient. */
CDIST_API cdist_status cdist_line_circle_grad(cdist_query *q, const cdist_line *l, const cdist_circle *c, cdist_result *r, cdist_grad *g);
/** cdist_ray_circle() with the gradient. */
CDIST_API cdist_status cdist_ray_circle_grad(cdist_query *q, const cdist_ray *l, const cdist_circle *c, cdist_result *r, cdist_grad *g);
/** cdist_segment_circle() with the gradient. */
CDIST_API cdist_status cdist_segment_circle_grad(cdist_query *q, const cdist_segment *s, const cdist_circle *c, cdist_result *r, cdist_grad *g);
/** cdist_circle_circle() with the gradient. */
CDIST_API cdist_status cdist_circle_circle_grad(cdist_query *q, const cdist_circle *c0, const cdist_circle *c1, cdist_result *r, cdist_grad *g);
/** cdist_line_disk() with the gradient. */
CDIST_API cdist_status cdist_line_disk_grad(cdist_query *q, const cdist_line *l, const cdist_circle *d, cdist_result *r, cdist_grad *g);
/** cdist_ray_disk() with the gradient. */
CDIST_API cdist_status cdist_ray_disk_grad(cdist_query *q, const cdist_ray *l, const cdist_circle *d, cdist_result *r, cdist_grad *g);
/** cdist_segment_disk() with the gradient. */
CDIST_API cdist_status cdist_segment_disk_grad(cdist_query *q, const cdist_segment *s, const cdist_circle *d, cdist_result *r, cdist_grad *g);
/** cdist_circle_disk() with the gradient. */
CDIST_API cdist_status cdist_circle_disk_grad(cdist_query *q, const cdist_circle *c, const cdist_circle *d, cdist_result *r, cdist_grad *g);
/** cdist_disk_disk() with the gradient. */
CDIST_API cdist_status cdist_disk_disk_grad(cdist_query *q, const cdist_circle *d0, const cdist_circle *d1, cdist_result *r, cdist_grad *g);
/** cdist_arc_circle() with the gradient (arc fields: d_center, d_normal, d_radius,
 *  d_zero_direction, d_start, d_end). */
CDIST_API cdist_status cdist_arc_circle_grad(cdist_query *q, const cdist_arc *a, const cdist_circle *c, cdist_result *r, cdist_grad *g);
/** cdist_arc_arc() with the gradient. */
CDIST_API cdist_status cdist_arc_arc_grad(cdist_query *q, const cdist_arc *a0, const cdist_arc *a1, cdist_result *r, cdist_grad *g);
/** cdist_segment_arc() with the gradient. */
CDIST_API cdist_status cdist_segment_arc_grad(cdist_query *q, const cdist_segment *s, const cdist_arc *a, cdist_result *r, cdist_grad *g);
/** cdist_arc_disk() with the gradient. */
CDIST_API cdist_status cdist_arc_disk_grad(cdist_query *q, const cdist_arc *a, const cdist_circle *d, cdist_result *r, cdist_grad *g);

/* Swept-object gradients: the contact query plus the gradient of the signed distance (torus:
 * the circle's fields and d_radius_swept for the tube radius; capsule: d_p0, d_p1,
 * d_radius_swept; sphere: d_center, d_radius_swept; rounded disk: the disk's fields and
 * d_radius_swept). The flag follows the core result (cores touching: gradient 0 except
 * d_radius_swept = -1). On error the gradient is all NaN. */

/** cdist_torus_torus() with the gradient. */
CDIST_API cdist_status cdist_torus_torus_grad(cdist_query *q, const cdist_torus *a, const cdist_torus *b, cdist_contact *c, cdist_grad *g);
/** cdist_torus_capsule() with the gradient. */
CDIST_API cdist_status cdist_torus_capsule_grad(cdist_query *q, const cdist_torus *a, const cdist_capsule *b, cdist_contact *c, cdist_grad *g);
/** cdist_torus_sphere() with the gradient. */
CDIST_API cdist_status cdist_torus_sphere_grad(cdist_query *q, const cdist_torus *a, const cdist_sphere *b, cdist_contact *c, cdist_grad *g);
/** cdist_torus_rounded_disk() with the gradient. */
CDIST_API cdist_status cdist_torus_rounded_disk_grad(cdist_query *q, const cdist_torus *a, const cdist_rounded_disk *b, cdist_contact *c, cdist_grad *g);
/** cdist_capsule_capsule() with the gradient. */
CDIST_API cdist_status cdist_capsule_capsule_grad(cdist_query *q, const cdist_capsule *a, const cdist_capsule *b, cdist_contact *c, cdist_grad *g);
/** cdist_capsule_sphere() with the gradient. */
CDIST_API cdist_status cdist_capsule_sphere_grad(cdist_query *q, const cdist_capsule *a, const cdist_sphere *b, cdist_contact *c, cdist_grad *g);
/** cdist_capsule_rounded_disk() with the gradient. */
CDIST_API cdist_status cdist_capsule_rounded_disk_grad(cdist_query *q, const cdist_capsule *a, const cdist_rounded_disk *b, cdist_contact *c, cdist_grad *g);
/** cdist_sphere_sphere() with the gradient. */
CDIST_API cdist_status cdist_sphere_sphere_grad(cdist_query *q, const cdist_sphere *a, const cdist_sphere *b, cdist_contact *c, cdist_grad *g);
/** cdist_sphere_rounded_disk() with the gradient. */
CDIST_API cdist_status cdist_sphere_rounded_disk_grad(cdist_query *q, const cdist_sphere *a, const cdist_rounded_disk *b, cdist_contact *c, cdist_grad *g);
/** cdist_rounded_disk_rounded_disk() with the gradient. */
CDIST_API cdist_status cdist_rounded_disk_rounded_disk_grad(cdist_query *q, const cdist_rounded_disk *a, const cdist_rounded_disk *b, cdist_contact *c, cdist_grad *g);
/** cdist_torus_line() with the gradient. */
CDIST_API cdist_status cdist_torus_line_grad(cdist_query *q, const cdist_torus *a, const cdist_line *b, cdist_contact *c, cdist_grad *g);
/** cdist_torus_ray() with the gradient. */
CDIST_API cdist_status cdist_torus_ray_grad(cdist_query *q, const cdist_torus *a, const cdist_ray *b, cdist_contact *c, cdist_grad *g);
/** cdist_torus_segment() with the gradient. */
CDIST_API cdist_status cdist_torus_segment_grad(cdist_query *q, const cdist_torus *a, const cdist_segment *b, cdist_contact *c, cdist_grad *g);
/** cdist_capsule_circle() with the gradient. */
CDIST_API cdist_status cdist_capsule_circle_grad(cdist_query *q, const cdist_capsule *a, const cdist_circle *b, cdist_contact *c, cdist_grad *g);
/** cdist_capsule_disk() with the gradient. */
CDIST_API cdist_status cdist_capsule_disk_grad(cdist_query *q, const cdist_capsule *a, const cdist_circle *b, cdist_contact *c, cdist_grad *g);
/** cdist_sphere_circle() with the gradient. */
CDIST_API cdist_status cdist_sphere_circle_grad(cdist_query *q, const cdist_sphere *a, const cdist_circle *b, cdist_contact *c, cdist_grad *g);
/** cdist_sphere_disk() with the gradient. */
CDIST_API cdist_status cdist_sphere_disk_grad(cdist_query *q, const cdist_sphere *a, const cdist_circle *b, cdist_contact *c, cdist_grad *g);

/** @} */

/** @defgroup topology Linking numbers and time of impact
 *  @{ */
/* ---- linking and time of impact ------------------------------------------------------ */

/* Linking. The linking number of two oriented circles a and b (each oriented counterclockwise
 * about its normal: the tangent at a point p is N x (p - C)) is the signed number of times b
 * crosses the open disk of a, a crossing counting +1 when b passes through the disk in the
 * direction of a's normal and -1 against it. It is symmetric (lk(a, b) = lk(b, a)), equals the
 * Gauss linking integral, changes sign when either normal is reversed, and is -1, 0 or +1 for
 * two circles. It is defined only when the circles do not meet.
 *
 * Guarantee: with L = max(r_a, r_b, |C_b - C_a|) and d the certified circle-circle distance
 * (cdist_circle_circle()), pairs with d <= 2^-40 L (9.1e-13 L) are reported
 * ::CDIST_LINK_TOUCHING; every other pair gets its exact linking number, never a wrong -1, 0 or
 * +1: the crossings are counted in double with a running error bound, and again in extended
 * precision (binary128, or long double where the compiler has no binary128) when the bound is
 * not below d. One configuration can exhaust even the extended bound: planes within about 1e-8
 * rad of parallel, one circle nearly tangent to the other's plane, and d below about 5e-11 L;
 * it is then reported ::CDIST_LINK_TOUCHING with ::CDIST_LINK_FLAG_UNRESOLVED (never a wrong
 * number). A circle of radius 0 (a point) is unlinked from everything it does not touch.
 *
 * Tori (solid, cdist_torus): linked when their core circles are linked and the solids are
 * disjoint, i.e. core distance > r_a + r_b (tube radii). When the solids overlap or touch
 * (core distance <= r_a + r_b, with r_a + r_b > 0) the result is ::CDIST_LINK_OVERLAP and
 * core_linking still gives the cores' value (their linking number, or ::CDIST_LINK_TOUCHING).
 */

/** Values of cdist_link::linking besides -1, 0 and +1. Numbers are fixed. */
typedef enum cdist_link_value {
    CDIST_LINK_TOUCHING = 2, /**< the circles meet (distance <= 2^-40 L): linking is undefined */
    CDIST_LINK_OVERLAP = 3,  /**< tori only: the solid tori overlap or touch */
    CDIST_LINK_ERROR = 4     /**< the query failed (see its status) */
} cdist_link_value;

/** Flags (bits of cdist_link::flags). Values are fixed. */
typedef enum cdist_link_flag {
    /** The double-precision count was not certain; extended precision decided. */
    CDIST_LINK_FLAG_EXTENDED = 1,
    /** Even extended precision could not decide: reported ::CDIST_LINK_TOUCHING (see above). */
    CDIST_LINK_FLAG_UNRESOLVED = 2
} cdist_link_flag;

/** Result of a linking query. Output only; growth policy as for ::cdist_result (new fields
 *  take their place in `reserved`). */
typedef struct cdist_link {
    int linking;          /**< -1, 0, +1, or a ::cdist_link_value */
    int core_linking;     /**< the core circles' value (equal to linking for circles) */
    double distance;      /**< circles: their distance; tori: signed distance (core - tube radii) */
    double core_distance; /**< distance between the (core) circles, from cdist_circle_circle() */
    double scale;         /**< L = max(r_a, r_b, |C_b - C_a|) of the (core) circles */
    int flags;            /**< bits of ::cdist_link_flag */
    int reserved_int;     /**< reserved; 0 */
    double reserved[4];   /**< reserved for future fields; set to zero */
} cdist_link;

/** sizeof(cdist_link) as compiled into the library. */
CDIST_API size_t cdist_link_size(void);
/** Linking number of circles a and b (the rule above). Validates like cdist_circle_circle()
 *  and runs it with ::CDIST_METHOD_AUTO whatever the handle's method; on error out->linking is ::CDIST_LINK_ERROR and the
 *  distances NaN. */
CDIST_API cdist_status cdist_link_circles(cdist_query *q, const cdist_circle *a, const cdist_circle *b, cdist_link *out);
/** Linking of two solid tori (the rule above); tube radii must be finite and >= 0. */
CDIST_API cdist_status cdist_link_tori(cdist_query *q, const cdist_torus *a, const cdist_torus *b, cdist_link *out);
/** n linking queries: object i of a at (const char *)a + i * a_stride bytes (0 broadcasts one
 *  object, negative allowed), likewise b, both ::cdist_circle; out[i] and statuses[i] (may be
 *  NULL) written for every i; a bad entry gets its status and ::CDIST_LINK_ERROR, the others
 *  are answered exactly as cdist_link_circles() answers them. Runs on the calling thread and
 *  never allocates. Returns ::CDIST_OK, else the status of the lowest failing entry
 *  (cdist_query_last_error() names it); NULL handle or arrays (n > 0):
 *  ::CDIST_ERR_NULL_ARGUMENT for every entry; out or statuses overlapping an input or each
 *  other: ::CDIST_ERR_OVERLAP before anything is read or written. */
CDIST_API cdist_status cdist_link_circles_batch(cdist_query *q, size_t n, const void *a, ptrdiff_t a_stride,
                                                const void *b, ptrdiff_t b_stride, cdist_link *out,
                                                cdist_status *statuses);
/** cdist_link_circles_batch() for ::cdist_torus objects (cdist_link_tori()). */
CDIST_API cdist_status cdist_link_tori_batch(cdist_query *q, size_t n, const void *a, ptrdiff_t a_stride,
                                             const void *b, ptrdiff_t b_stride, cdist_link *out,
                                             cdist_status *statuses);

/* Time of impact. Two swept objects (cdist_shape) each move rigidly over t in [0, 1]. The
 * motion model (cdist_motion): a point x of the object at t = 0 is at
 *     x(t) = c + t T + R(t omega) (x - c),
 * where c is the rotation centre (any point, fixed in the body), T is the translation of c over
 * the interval, and R(t omega) is the rotation by angle t |omega| about the axis omega / |omega|
 * (Rodrigues). So c moves linearly while the body turns about c at a constant angular velocity
 * omega. Two poses (R0, p0) and (R1, p1) of a body with reference point c0 give
 * omega = log(R1 R0^T) (axis times angle, angle in [0, pi], or more for several turns) and
 * T = p1 - p0. The object's normals turn with it. A NULL motion keeps the object still.
 *
 * cdist_toi() finds the first t at which the signed distance (cdist_torus_torus() etc.) reaches
 * the target separation, by conservative advancement on the exact distance d(t). No point of a
 * body moves faster than |T| + |omega| rho, where rho is the largest distance of its core from
 * c. So d shrinks no faster than V = |T_a - T_b| + |omega_a| rho_a + |omega_b| rho_b, and the
 * step from t to t + (d(t) - target - slack) / V cannot pass a contact. The result never
 * tunnels: a ring that passes through another's hole is no hit, and one that clips the rim is.
 * Guarantee: on ::CDIST_TOI_HIT, d(s) > target for every s in [0, t) and
 * d(t) <= target + tolerance. On ::CDIST_TOI_NONE, d(s) > target on all of [0, 1]. On
 * ::CDIST_TOI_ITERATION_LIMIT, d(s) > target on [0, t] and the search stopped. slack covers
 * the rounding of poses and distances: 64 eps times the largest coordinate of the motion, or
 * times r_a + r_b + |target| (the swept radii) when that is larger. The
 * tolerance used is max(tolerance, 2 slack). The distance tolerance does not bound the time: a
 * grazing approach (d' near 0) can sit within the tolerance for a long time. Each step costs one
 * contact query. The count is about log(gap / tolerance) / (|d'| / V) near a transversal contact,
 * so it is larger when the approach speed |d'| is small compared with V (fast spin, slow
 * approach). */

/** Shape types of ::cdist_shape. Numbers are fixed. Circles (a torus with tube radius 0),
 *  segments (a capsule with radius 0), points and disks are the zero-radius cases. */
typedef enum cdist_shape_type {
    CDIST_SHAPE_SPHERE = 0,      /**< u.sphere */
    CDIST_SHAPE_CAPSULE = 1,     /**< u.capsule */
    CDIST_SHAPE_TORUS = 2,       /**< u.torus */
    CDIST_SHAPE_ROUNDED_DISK = 3 /**< u.rounded_disk */
} cdist_shape_type;

/** The object of a ::cdist_shape, by its type. sizeof = 80 bytes. */
typedef union cdist_shape_data {
    cdist_sphere sphere;             /**< ::CDIST_SHAPE_SPHERE */
    cdist_capsule capsule;           /**< ::CDIST_SHAPE_CAPSULE */
    cdist_torus torus;               /**< ::CDIST_SHAPE_TORUS */
    cdist_rounded_disk rounded_disk; /**< ::CDIST_SHAPE_ROUNDED_DISK */
    double reserved[10];             /**< room for larger types; keeps the size fixed */
} cdist_shape_data;

/** A swept object of any type. sizeof = 88 bytes on LP64 (cdist_shape_size()). */
typedef struct cdist_shape {
    int type;           /**< a ::cdist_shape_type */
    int reserved_int;   /**< reserved; 0 */
    cdist_shape_data u; /**< the object (the member named by type) */
} cdist_shape;

/** A rigid motion over t in [0, 1] (the model above). */
typedef struct cdist_motion {
    cdist_vec3 center;      /**< rotation centre c at t = 0 (a point fixed in the body) */
    cdist_vec3 translation; /**< T: the displacement of c from t = 0 to t = 1 */
    cdist_vec3 rotation;    /**< omega: rotation axis times total angle (radians) over [0, 1] */
} cdist_motion;

/** Outcome of a time-of-impact query. Numbers are fixed. */
typedef enum cdist_toi_state {
    CDIST_TOI_NONE = 0,           /**< no contact in [0, 1] */
    CDIST_TOI_HIT = 1,            /**< contact at t */
    CDIST_TOI_ITERATION_LIMIT = 2 /**< max_iterations steps used; no contact in [0, t] */
} cdist_toi_state;

/** Result of cdist_toi(). Output only; growth policy as for ::cdist_result. */
typedef struct cdist_toi_result {
    int state;             /**< a ::cdist_toi_state */
    int iterations;        /**< distance queries used */
    double t;              /**< HIT: the time of impact; otherwise the last time evaluated */
    double distance;       /**< signed distance at t */
    cdist_contact contact; /**< the contact of the objects posed at t (cdist_shape_at()) */
    double reserved[4];    /**< reserved for future fields; set to zero */
} cdist_toi_result;

/** sizeof(cdist_shape) as compiled into the library. */
CDIST_API size_t cdist_shape_size(void);
/** sizeof(cdist_toi_result) as compiled into the library. */
CDIST_API size_t cdist_toi_result_size(void);
/** The shape s moved by m to time t (any real t), as cdist_toi() poses it. Thread-safe, no
 *  handle. Returns ::CDIST_ERR_NULL_ARGUMENT, ::CDIST_ERR_BAD_OPTION (unknown type) or
 *  ::CDIST_ERR_NOT_FINITE (t or the motion); the shape itself is not validated. */
CDIST_API cdist_status cdist_shape_at(const cdist_shape *s, const cdist_motion *m, double t, cdist_shape *out);
/** First time of impact of a moving with ma and b moving with mb (either motion may be NULL):
 *  the first t in [0, 1] with signed distance <= target (+ tolerance, see above). target is any
 *  finite separation (0: touching; negative: that penetration depth). tolerance > 0 is in
 *  length units. max_iterations >= 1 caps the distance queries. The shapes are validated by the
 *  contact query at t = 0 (its status and message); a bad type, a non-finite motion or target,
 *  or a bad tolerance or cap gives ::CDIST_ERR_BAD_OPTION / ::CDIST_ERR_NOT_FINITE. Reaching the
 *  cap is not an error (state ::CDIST_TOI_ITERATION_LIMIT). On error out->t and distance are NaN. */
CDIST_API cdist_status cdist_toi(cdist_query *q, const cdist_shape *a, const cdist_motion *ma, const cdist_shape *b,
                                 const cdist_motion *mb, double target, double tolerance, int max_iterations,
                                 cdist_toi_result *out);
/** n time-of-impact queries with the batch conventions of cdist_link_circles_batch(): entry i
 *  uses the objects and motions at byte offsets i * stride of a, ma, b, mb (stride 0
 *  broadcasts; ma or mb NULL: that side does not move). It writes out[i] and statuses[i] (may
 *  be NULL) for every i, runs on the calling thread and never allocates. */
CDIST_API cdist_status cdist_toi_batch(cdist_query *q, size_t n, const cdist_shape *a, ptrdiff_t a_stride,
                                       const cdist_motion *ma, ptrdiff_t ma_stride, const cdist_shape *b,
                                       ptrdiff_t b_stride, const cdist_motion *mb, ptrdiff_t mb_stride, double target,
                                       double tolerance, int max_iterations, cdist_toi_result *out,
                                       cdist_status *statuses);
/** @} */

/** @defgroup scenes Scenes: many objects at once
 *  @{ */
/* ---- scenes: many objects at once --------------------------------------------------- */
/* A scene holds N objects of any of the kinds below; object ids are the indices at which
 * cdist_scene_add() put them (0, 1, 2, ... in order of addition; an id is never reused).
 * Every object is a core (point, segment, circle, disk, arc) plus a ball radius (0 for the
 * plain kinds), and the distance of a pair is the signed distance of the swept queries:
 *     distance = core_distance - (radius_a + radius_b),
 * with the core distance from the library's own query for the two cores (swapping the
 * arguments where only the other order exists, and the result back), so a scene's answer for
 * a pair (i, j), i first, is bit for bit that of the corresponding single query. The one core
 * pair without an exact query, point-arc (sphere or point against an arc), is reported with
 * status ::CDIST_ERR_BAD_KIND and distance NaN whenever the bounds cannot exclude it: never
 * approximated, never dropped.
 *
 * The broad phase is certified: every bound (boxes, balls, slabs of circle planes, a sampled
 * ring bound) is a lower bound of the signed distance widened by a relative margin of 2^-36 of
 * the objects' coordinate scale, far above the rounding of the bounds and of the queries, and
 * pairs of two circle cores are screened by the distance of cdist_batch_distance() (within 2
 * ulps of the scale of the full query's) against the same margin, so no pair whose computed
 * distance is <= delta is ever left out (docs/scene.md gives the argument).
 * Pairs are skipped (never tested, never reported) when both objects have the same non-zero
 * group, or when they are consecutive ids i, i + 1 with the same non-zero chain (the links of
 * a chain touch by design): see cdist_scene_set_groups().
 *
 * Threads: the queries share their work among the query handle's threads
 * (cdist_query_set_threads()); results are bit-identical for every thread count. A scene
 * must be used by one call at a time (it holds the workspaces); a call that finds it in use
 * returns ::CDIST_ERR_HANDLE_BUSY. Object ids and counts must stay below 2^32 - 1. */

/** Opaque scene: objects, their bounds and the bounding-volume tree. */
typedef struct cdist_scene cdist_scene;

/** Object kinds of a scene, with the C type of one object. Numbers are fixed. */
typedef enum cdist_scene_kind {
    CDIST_SCENE_POINT = 0,        /**< cdist_vec3 */
    CDIST_SCENE_SEGMENT = 1,      /**< cdist_segment */
    CDIST_SCENE_CIRCLE = 2,       /**< cdist_circle */
    CDIST_SCENE_DISK = 3,         /**< cdist_circle as a disk */
    CDIST_SCENE_ARC = 4,          /**< cdist_arc */
    CDIST_SCENE_SPHERE = 5,       /**< cdist_sphere */
    CDIST_SCENE_CAPSULE = 6,      /**< cdist_capsule */
    CDIST_SCENE_TORUS = 7,        /**< cdist_torus */
    CDIST_SCENE_ROUNDED_DISK = 8  /**< cdist_rounded_disk */
} cdist_scene_kind;

/** Bits of cdist_scene_pair::flags. Values are fixed. */
typedef enum cdist_scene_pair_flag {
    CDIST_SCENE_PAIR_EQUIDISTANT = 1, /**< infinitely many closest pairs (the core query's flag) */
    CDIST_SCENE_PAIR_CORE_TOUCH = 2   /**< the cores touch (::CDIST_CONTACT_CORE_TOUCH) */
} cdist_scene_pair_flag;

/** One answered pair of a scene query. For a pair of one scene i < j; for two scenes i is an
 *  id of the first and j of the second; for a query object i is the scene's id and j is
 *  SIZE_MAX (the query object is the second object). sizeof = 136 bytes on LP64. */
typedef struct cdist_scene_pair {
    size_t i;        /**< id of the first object */
    size_t j;        /**< id of the second object */
    double distance; /**< signed distance (NaN when status is not ::CDIST_OK) */
    int status;      /**< ::CDIST_OK, or why the pair could not be answered */
    int num_pairs;   /**< closest pairs given: 1 or 2 (0 on error) */
    int flags;       /**< bits of ::cdist_scene_pair_flag */
    int reserved;    /**< 0 */
    /** point[k][0] on object i's surface, point[k][1] on object j's (the witness points of
     *  the contact query, cdist_contact_pair::point), for k < num_pairs. */
    cdist_vec3 point[2][2];
} cdist_scene_pair;

/** Counters of a scene and of its last query (cdist_scene_get_stats()). */
typedef struct cdist_scene_stats {
    size_t objects;     /**< ids given out (live, invalid and removed objects) */
    size_t live;        /**< objects that take part in queries */
    size_t nodes;       /**< nodes of the tree */
    size_t bytes;       /**< memory held by the scene (objects, bounds, tree, workspaces) */
    size_t box_pairs;   /**< last query: object pairs whose boxes passed */
    size_t screened;    /**< last query: pairs passed by the bounds, before the distance screen */
    size_t candidates;  /**< last query: pairs answered by the exact query */
    size_t reported;    /**< last query: pairs reported */
    size_t rebuilds;    /**< tree builds since the scene was created */
    size_t refits;      /**< refits (pose updates answered without a rebuild) */
    size_t reserved[6]; /**< reserved for future counters; 0 */
} cdist_scene_stats;

/** Receives answered pairs in order (sorted by i, then j), n at a time; return 0 to go on,
 *  anything else to stop the query (it then returns ::CDIST_ERR_CALLBACK_FAILED). */
typedef int (*cdist_scene_pair_fn)(void *user, const cdist_scene_pair *pairs, size_t n);

/** sizeof(cdist_scene_pair) as compiled into the library. */
CDIST_API size_t cdist_scene_pair_size(void);
/** sizeof(cdist_scene_stats) as compiled into the library. */
CDIST_API size_t cdist_scene_stats_size(void);
/** sizeof the C type of one object of a scene kind (0 for a number that is not a kind). */
CDIST_API size_t cdist_scene_kind_size(cdist_scene_kind kind);

/** Creates an empty scene (NULL if memory runs out). */
CDIST_API cdist_scene *cdist_scene_new(void);
/** Frees a scene. NULL is allowed. */
CDIST_API void cdist_scene_free(cdist_scene *s);

/** Adds n objects of one kind; object k is at (const char *)objects + k * stride (stride 0
 *  repeats one object). They get the ids first .. first + n - 1 (*first_id, may be NULL).
 *  Each object is validated as the single queries validate it, with q's unit tolerance; an
 *  invalid one gets its status in statuses[k] (may be NULL), keeps its id and takes part in
 *  no query; the others are added. Returns ::CDIST_OK when all were valid, else the status of
 *  the first invalid one (cdist_query_last_error() names its index). A bad kind:
 *  ::CDIST_ERR_BAD_KIND and nothing is added. The queries answer pairs with the options of
 *  their own handle: under a stricter unit tolerance than at add, a pair that the bounds let
 *  through fails with ::CDIST_ERR_NOT_UNIT (reported as any failing pair). */
CDIST_API cdist_status cdist_scene_add(cdist_query *q, cdist_scene *s, cdist_scene_kind kind, size_t n,
                                       const void *objects, ptrdiff_t stride, size_t *first_id,
                                       cdist_status *statuses);
/** Moves (or reshapes) objects: object k replaces the object with id ids[k] (ids NULL: ids 0 ..
 *  n - 1); its kind may change. A valid object keeps its place in the tree, whose boxes are
 *  refitted before the next query (no rebuild; see docs/scene.md); an invalid one gets its status in statuses[k]
 *  and the old object stays. An id out of range or removed: ::CDIST_ERR_OUT_OF_RANGE at its
 *  index. An invalid object previously added becomes live when updated with a valid one.
 *  Returns the first failing status as cdist_scene_add(). */
CDIST_API cdist_status cdist_scene_update(cdist_query *q, cdist_scene *s, size_t n, const size_t *ids,
                                          cdist_scene_kind kind, const void *objects, ptrdiff_t stride,
                                          cdist_status *statuses);
/** Removes objects (their ids are not reused). Ids out of range: ::CDIST_ERR_OUT_OF_RANGE (the
 *  valid ids of the call are still removed); removing twice is allowed. */
CDIST_API cdist_status cdist_scene_remove(cdist_query *q, cdist_scene *s, size_t n, const size_t *ids);
/** Sets the skip filter of objects ids[k] (ids NULL: 0 .. n - 1): group[k] (0: none; a pair of
 *  the same non-zero group is skipped) and chain[k] (0: none; ids i and i + 1 of the same
 *  non-zero chain are skipped). Either array may be NULL (left unchanged). New objects have 0. */
CDIST_API cdist_status cdist_scene_set_groups(cdist_query *q, cdist_scene *s, size_t n, const size_t *ids,
                                              const unsigned *group, const unsigned *chain);
/** Number of ids given out (removed and invalid objects included); 0 for NULL. */
CDIST_API size_t cdist_scene_count(const cdist_scene *s);
/** Status of object id: ::CDIST_OK when live, its validation status when invalid,
 *  ::CDIST_ERR_OUT_OF_RANGE when out of range or removed. */
CDIST_API cdist_status cdist_scene_object_status(const cdist_scene *s, size_t id);
/** Rebuilds the tree from the current poses (queries rebuild by themselves when objects were
 *  added, or when moves have doubled the leaves' boxes; see docs/scene.md). */
CDIST_API cdist_status cdist_scene_rebuild(cdist_query *q, cdist_scene *s);
/** Counters of the scene and of its last query. */
CDIST_API cdist_status cdist_scene_get_stats(const cdist_scene *s, cdist_scene_stats *stats);

/** Every pair i < j (not skipped) with distance <= delta, sorted by (i, j), with its
 *  distance and closest points. The first min(count, capacity) pairs go to out, *count gets
 *  the number of pairs found (all of them: when it exceeds capacity, call again with a larger
 *  array; nothing is dropped silently). Pairs that could not be answered (status != OK) are
 *  always included and the call returns the first such status. delta may be negative
 *  (overlapping swept objects); NaN: ::CDIST_ERR_NOT_FINITE. out NULL with capacity > 0:
 *  ::CDIST_ERR_NULL_ARGUMENT. */
CDIST_API cdist_status cdist_scene_pairs_within(cdist_query *q, cdist_scene *s, double delta, cdist_scene_pair *out,
                                                size_t capacity, size_t *count);
/** cdist_scene_pairs_within() delivering the pairs to fn in order instead (*count, may be
 *  NULL, gets the number delivered). */
CDIST_API cdist_status cdist_scene_pairs_within_fn(cdist_query *q, cdist_scene *s, double delta,
                                                   cdist_scene_pair_fn fn, void *user, size_t *count);
/** Every pair (i in a, j in b) with distance <= delta, sorted by (i, j); groups and chains do
 *  not apply between scenes. Same conventions as cdist_scene_pairs_within(). a == b is allowed
 *  (every ordered pair i != j then appears once as (i, j), i < j, as in the one-scene query). */
CDIST_API cdist_status cdist_scene_pairs_between(cdist_query *q, cdist_scene *a, cdist_scene *b, double delta,
                                                 cdist_scene_pair *out, size_t capacity, size_t *count);
/** The closest pair of the scene (the smallest distance; ties: smallest (i, j)); skipped pairs
 *  do not count. Fewer than two live objects: ::CDIST_ERR_BAD_INTERVAL, out->distance NaN. A
 *  pair without an exact query (point or sphere against an arc) that the bounds cannot put
 *  farther than the answer: its status (::CDIST_ERR_BAD_KIND) and that pair in out, the one with
 *  the smallest (i, j) when there are several (the same for every tree order). */
CDIST_API cdist_status cdist_scene_closest_pair(cdist_query *q, cdist_scene *s, cdist_scene_pair *out);
/** The closest pair between scenes a and b (i in a, j in b). */
CDIST_API cdist_status cdist_scene_closest_pair_between(cdist_query *q, cdist_scene *a, cdist_scene *b,
                                                        cdist_scene_pair *out);
/** The k objects nearest to a query object (kind, object), sorted by distance then id: out[m].i
 *  the id, out[m].j = SIZE_MAX, point[.][1] on the query object. *count = min(k, live objects)
 *  answered objects. An object without an exact query against the query object that the bounds
 *  cannot put beyond the k-th distance: its status, the message naming the smallest such id. */
CDIST_API cdist_status cdist_scene_nearest(cdist_query *q, cdist_scene *s, cdist_scene_kind kind, const void *object,
                                           size_t k, cdist_scene_pair *out, size_t *count);
/** Every object within delta of a query object, sorted by id (conventions of
 *  cdist_scene_nearest() and of cdist_scene_pairs_within() for capacity and count). */
CDIST_API cdist_status cdist_scene_within(cdist_query *q, cdist_scene *s, cdist_scene_kind kind, const void *object,
                                          double delta, cdist_scene_pair *out, size_t capacity, size_t *count);
/** @} */

/** @addtogroup batches
 *  @{ */
/* ---- batches of contacts and gradients, progress (1.1) ---------------------------------- */

/** sizeof the result type of a kind: sizeof(cdist_result), or sizeof(cdist_contact) for a
 *  contact kind (::CDIST_KIND_TORUS_TORUS and after); 0 for a number that is not a kind. */
CDIST_API size_t cdist_kind_result_size(cdist_kind kind);
/** 1 when the kind has a `_grad` query (so cdist_batch_grad() answers it), else 0. The kinds
 *  without one: callback curves, helices and Bezier curves. */
CDIST_API int cdist_kind_has_grad(cdist_kind kind);

/** Contact results for n queries of a contact kind: contacts[i] and statuses[i] for the
 *  single query (e.g. cdist_torus_torus()) on the strided entries, bit for bit. Conventions of
 *  cdist_batch() (strides, broadcast, statuses, return value, threads, no allocation); a kind
 *  that is not a contact kind gives ::CDIST_ERR_BAD_KIND. */
CDIST_API cdist_status cdist_batch_contact(cdist_query *q, cdist_kind kind, size_t n, const void *a,
                                           ptrdiff_t a_stride, const void *b, ptrdiff_t b_stride,
                                           cdist_contact *contacts, cdist_status *statuses);

/** Gradients for n queries of any kind with a `_grad` query (cdist_kind_has_grad()): grads[i],
 *  results[i] and statuses[i] exactly as the single `_grad` query (e.g. cdist_circle_circle_grad(),
 *  cdist_torus_torus_grad()) gives them. results: n ::cdist_result for the kinds of cdist_batch(),
 *  n ::cdist_contact for a contact kind (cdist_kind_result_size() bytes each), or NULL when only
 *  the gradients are wanted. A bad entry gets its status and an all-NaN gradient. Conventions of
 *  cdist_batch(); a kind without a `_grad` query gives ::CDIST_ERR_BAD_KIND (for a number that
 *  is not a kind the results, whose type is then unknown, are not written). */
CDIST_API cdist_status cdist_batch_grad(cdist_query *q, cdist_kind kind, size_t n, const void *a, ptrdiff_t a_stride,
                                        const void *b, ptrdiff_t b_stride, void *results, cdist_grad *grads,
                                        cdist_status *statuses);

/** Progress callback of long calls: `done` of `total` entries are answered. Return 0 to go on,
 *  non-zero to stop. */
typedef int (*cdist_progress_fn)(void *user, size_t done, size_t total);

/** Asks batch calls on this handle (cdist_batch(), cdist_batch_distance(), cdist_batch_contact(),
 *  cdist_batch_grad(); not the link and time-of-impact batches nor the scene queries, which
 *  neither report nor stop) to report progress: fn(user, done, total) is called after about
 *  every `every` answered entries (never more often than once per `every` entries, rounded up to a
 *  multiple of 64; `done` counts the entries of every thread, and increases from call to call) and,
 *  unless stopped, once at the end (done == total). It is called from the thread that called the
 *  batch only, never from a worker thread, while the batch owns the handle: fn must not call the
 *  library with this handle (its option setters return ::CDIST_ERR_HANDLE_BUSY; its queries would
 *  change the handle's status and message under the batch). A non-zero return stops the batch: the
 *  worker threads finish the entries they are answering and take no more; the call returns
 *  ::CDIST_ERR_CANCELLED, the entries answered keep their answers (identical for every thread
 *  count) and statuses, the others get ::CDIST_ERR_CANCELLED and the error state (NaN). The
 *  entries answered are the first k for some k (the message gives k), which depends on timing
 *  and the thread count. fn = NULL switches
 *  progress off (the default; `every` is then ignored); with fn, every must be >= 1 (else
 *  ::CDIST_ERR_BAD_OPTION). The option does not change any answer. */
CDIST_API cdist_status cdist_query_set_progress(cdist_query *q, cdist_progress_fn fn, void *user, size_t every);

/** One pair of cdist_scene_linked_pairs(). Output only; new fields take their place in
 *  `reserved`. */
typedef struct cdist_scene_link {
    size_t i;          /**< id of the first ring (i < j) */
    size_t j;          /**< id of the second ring */
    int status;        /**< ::CDIST_OK, or why the pair could not be answered */
    int reserved_int;  /**< 0 */
    cdist_link link;   /**< cdist_link_tori() of the two rings, i first (bit for bit) */
    double reserved[2]; /**< reserved for future fields; 0 */
} cdist_scene_link;

/** sizeof(cdist_scene_link) as compiled into the library. */
CDIST_API size_t cdist_scene_link_size(void);
/** Every pair of rings i < j of the scene that is not certified unlinked and apart: the
 *  objects of kinds ::CDIST_SCENE_CIRCLE and ::CDIST_SCENE_TORUS (a circle is a torus of tube
 *  radius 0; other kinds take no part) are answered with cdist_link_tori() semantics, and a
 *  pair is reported when its linking or core_linking is not 0: linked cores (+-1), touching
 *  cores (::CDIST_LINK_TOUCHING) and overlapping tori (::CDIST_LINK_OVERLAP, whatever the
 *  cores). Sorted by (i, j); groups and chains do not apply (linked neighbours are the point).
 *  The broad phase is exact for this question: two linked circles each cross the other's open
 *  disk, so their bounding balls (centre C, radius r) intersect and so do their boxes; pairs
 *  whose solids' bounding balls are apart by more than 2^-30 L (L = max(r_a, r_b,
 *  |C_b - C_a|)) plus the scene's bound margin are never answered, and the linking query gives
 *  0 for all of them (docs/scene.md). Conventions of cdist_scene_pairs_within() for out,
 *  capacity and *count; a pair that could not be answered is included with its status and
 *  the call returns the first such status. */
CDIST_API cdist_status cdist_scene_linked_pairs(cdist_query *q, cdist_scene *s, cdist_scene_link *out,
                                                size_t capacity, size_t *count);

/** Result of cdist_scene_toi(). Output only; new fields take their place in `reserved`. */
typedef struct cdist_scene_toi_result {
    size_t i;              /**< the pair of the earliest time (i < j); SIZE_MAX when no pair hits */
    size_t j;              /**< its second object */
    size_t candidates;     /**< pairs within reach that got a time-of-impact query */
    cdist_toi_result toi;  /**< cdist_toi() of the pair, i first (state ::CDIST_TOI_NONE and t = 1
                                when no pair hits) */
    double reserved[4];    /**< reserved for future fields; 0 */
} cdist_scene_toi_result;

/** sizeof(cdist_scene_toi_result) as compiled into the library. */
CDIST_API size_t cdist_scene_toi_size(void);
/** Time of impact of a moving scene: every live object id moves rigidly over [0, 1] with the
 *  motion at (const char *)motions + id * stride (the model of cdist_toi(); stride 0 means
 *  sizeof(cdist_motion); motions NULL: nothing moves; one entry per id given out, removed and
 *  invalid ids included and ignored). Returns the earliest t over the pairs (not skipped by
 *  groups and chains) at which one reaches signed distance target, as cdist_toi() answers each
 *  pair (points as spheres, segments as capsules, circles as tori and disks as rounded disks
 *  of radius 0; an arc in reach: ::CDIST_ERR_BAD_KIND): out->toi is that pair's result (state
 *  ::CDIST_TOI_HIT, or ::CDIST_TOI_ITERATION_LIMIT when a capped search stopped first: no pair
 *  reaches the target before its t). Ties: the smallest (i, j). Only pairs within reach are
 *  queried: a pair whose distance at 0 exceeds target + tolerance + the two objects' reaches
 *  (|T| + |omega| times the solid's largest distance from the rotation centre: no point moves
 *  farther) cannot hit, and the scene's certified bounds exclude it. Bad target, tolerance or
 *  cap as cdist_toi(); a non-finite motion: ::CDIST_ERR_NOT_FINITE. */
CDIST_API cdist_status cdist_scene_toi(cdist_query *q, cdist_scene *s, const cdist_motion *motions, ptrdiff_t stride,
                                       double target, double tolerance, int max_iterations,
                                       cdist_scene_toi_result *out);

/** @} */

#ifdef __cplusplus
}
#endif

#endif /* CIRCLEDIST_H */
