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
 * - The library never aborts, exits or prints. It never changes GSL's error handler.
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
 * V = N x U. Requires start <= end <= start + 2 pi.
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
    cdist_vec3 zero_direction; /**< direction of angle 0, not parallel to the axis */
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
    CDIST_ERR_BAD_KIND = 16            /**< a query kind number was not a ::cdist_kind */
} cdist_status;

/** Algorithms. A method that a query does not have is answered by ::CDIST_METHOD_AUTO;
 * cdist_result::method says which method answered.
 */
typedef enum cdist_method {
    CDIST_METHOD_AUTO = 0,       /**< the most exact and fastest for each query (default) */
    CDIST_METHOD_POLYNOMIAL = 1, /**< polynomial roots (GSL), polished on the true distance */
    CDIST_METHOD_ROBUST = 2,     /**< root bounding and bisection on the true derivative */
    CDIST_METHOD_ITERATION = 3   /**< geometric iteration (circle-circle) */
} cdist_method;

/** Curve callback: writes the position and derivative of the curve at parameter t and
 * returns 0; any other return value aborts the query with ::CDIST_ERR_CALLBACK_FAILED.
 */
typedef int (*cdist_curve_fn)(void *user, double t, cdist_vec3 *position, cdist_vec3 *derivative);

/** Opaque query handle: options plus every workspace a query needs, so queries never allocate. */
typedef struct cdist_query cdist_query;

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

/* ---- status, sizes ------------------------------------------------------------------ */

/** A one-sentence description of a status ("unknown status" for numbers not listed). */
CDIST_API const char *cdist_status_string(cdist_status status);
/** The enumerator's name, e.g. "CDIST_ERR_NOT_UNIT" ("CDIST_UNKNOWN" if not listed). */
CDIST_API const char *cdist_status_name(cdist_status status);
/** sizeof(cdist_result) as compiled into the library, for FFI users to check their layout. */
CDIST_API size_t cdist_result_size(void);
/** sizeof(cdist_pair) as compiled into the library. */
CDIST_API size_t cdist_pair_size(void);

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

/* ---- circle frames ------------------------------------------------------------------ */

/** The basis in which circle angles are measured. With N the normalised normal and k the
 * index of N's component of smallest magnitude (the first on ties), U = e_k - N_k N
 * normalised, V = N x U. Writes U and V (either may be NULL).
 */
CDIST_API cdist_status cdist_circle_basis(const cdist_circle *c, cdist_vec3 *u, cdist_vec3 *v);
/** The point of circle c at angle `angle` in the basis of cdist_circle_basis(). */
CDIST_API cdist_status cdist_circle_point(const cdist_circle *c, double angle, cdist_vec3 *point);

/* ---- point queries ------------------------------------------------------------------ */

/** Distance from point p to circle c. equidistant when p is on the circle's axis. */
CDIST_API cdist_status cdist_point_circle(cdist_query *q, const cdist_vec3 *p, const cdist_circle *c, cdist_result *r);
/** Distance from point p to disk d (circle plus interior). */
CDIST_API cdist_status cdist_point_disk(cdist_query *q, const cdist_vec3 *p, const cdist_circle *d, cdist_result *r);

/* ---- lines, rays, segments to circles ---------------------------------------------- */

/** Distance from a line to a circle (methods: POLYNOMIAL, ROBUST; AUTO = ROBUST). */
CDIST_API cdist_status cdist_line_circle(cdist_query *q, const cdist_line *l, const cdist_circle *c, cdist_result *r);
/** Distance from a ray (t >= 0) to a circle. */
CDIST_API cdist_status cdist_ray_circle(cdist_query *q, const cdist_ray *l, const cdist_circle *c, cdist_result *r);
/** Distance from a segment to a circle; param[0] is the segment parameter s in [0, 1]. */
CDIST_API cdist_status cdist_segment_circle(cdist_query *q, const cdist_segment *s, const cdist_circle *c, cdist_result *r);

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

/* ---- curves and arcs ---------------------------------------------------------------- */
/* These queries have one method (root bounding and bisection, answered as
 * ::CDIST_METHOD_ROBUST whatever the handle's method). Arcs are exact: their candidates are the
 * circle-circle critical points inside the range plus the end points. Callback curves, helices
 * and Bezier curves are sampled at cdist_query_get_curve_samples() intervals (per turn for a
 * helix) to bracket critical points, so two minima closer than the sample spacing may merge.
 * Cost limit: a helix's turns are skipped when a lower bound (from the axial and radial
 * geometry) shows they cannot beat the distance found; when more than
 * 2^21 / cdist_query_get_curve_samples() turns (4096 by default) cannot be skipped (a target
 * threading a long, tight coil), the helix queries return ::CDIST_ERR_COST_LIMIT. */

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
    CDIST_KIND_BEZIER3_DISK = 20    /**< a: cdist_bezier3,  b: cdist_circle as a disk */
    /* swept objects (torus, capsule, sphere, rounded disk) are appended from 21 on */
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

/** Full results for n queries of one kind. Object i of the first array is at
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
 *  cdist_batch(). */
CDIST_API cdist_status cdist_batch_distance(cdist_query *q, cdist_kind kind, size_t n, const void *a,
                                            ptrdiff_t a_stride, const void *b, ptrdiff_t b_stride,
                                            double *distances, cdist_status *statuses);

/** Worker threads used by the batch calls (default 1; 1..256; the calling thread is one of
 *  them). Workers and their workspaces are created here and live in the handle (they are
 *  joined by cdist_query_free()), so batches never allocate. Results are bit-identical for
 *  every thread count. Returns ::CDIST_ERR_BAD_OPTION outside 1..256, ::CDIST_ERR_THREAD or
 *  ::CDIST_ERR_NO_MEMORY when the workers cannot be created (the handle then has 1 thread). */
CDIST_API cdist_status cdist_query_set_threads(cdist_query *q, int threads);
/** The worker thread count (1 for a NULL handle). */
CDIST_API int cdist_query_get_threads(const cdist_query *q);

/* ---- swept objects and gradients (issue 14) ----------------------------------------- */
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
 * between the two one-sided derivatives) and an arc of radius 0 (a derivative from the right). At a disk's interior closest point the direction w is taken as +-N exactly (the
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

#ifdef __cplusplus
}
#endif

#endif /* CIRCLEDIST_H */
