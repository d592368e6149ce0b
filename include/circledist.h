/// @file circledist.h
/// libcircledist: exact minimum distance and every closest pair between 3D circles, disks,
/// points, lines, rays, segments, arcs and parametric curves.
///
/// Conventions used throughout:
/// - Every query takes a query handle, its objects by pointer, and a caller-provided result,
///   and returns a ::cdist_status. On success the result holds the global minimum distance
///   and up to two closest pairs; on error the result holds distance NaN and no pairs, and
///   cdist_query_last_error() explains what was wrong.
/// - Normals and directions must be non-zero and finite. By default their length must be 1
///   within a relative tolerance of 1e-6 (see cdist_query_set_unit_tolerance()); accepted
///   vectors are normalised before use. A line's parameter t always refers to the direction
///   exactly as the caller passed it.
/// - A radius must be finite and >= 0. Radius 0 is allowed: the circle (or disk) is its centre.
/// - Coordinates and radii must not exceed 1e150 in magnitude (their squares must not
///   overflow); larger values give ::CDIST_ERR_OUT_OF_RANGE.
/// - Circle angles (the `param` of a point on a circle or disk) are measured in the basis
///   {U, V, N} returned by cdist_circle_basis(): a point at angle a is
///   C + r (cos a U + sin a V), with a in (-pi, pi].
/// - Thread safety: a ::cdist_query handle must be used by one thread at a time. Use one
///   handle per thread; distinct handles share nothing. Functions without a handle argument
///   are thread-safe. A call that finds its handle in use by another thread's call returns
///   ::CDIST_ERR_HANDLE_BUSY at once, without touching the handle (its result, when given,
///   is set to NaN with no pairs); the calls of the point and lines families and the option
///   setters detect this (an atomic flag per handle, taken on entry and released on exit).
/// - The library never aborts, exits or prints. It never changes GSL's error handler.
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
/// Marks a symbol exported from libcircledist (everything else is hidden).
#define CDIST_API __attribute__((visibility("default")))
#endif

/// A point or vector in 3D.
typedef struct cdist_vec3 {
    double x; ///< x coordinate
    double y; ///< y coordinate
    double z; ///< z coordinate
} cdist_vec3;

/// A circle: the points at distance `radius` from `center` in the plane through `center`
/// orthogonal to `normal`. The same struct describes a disk (the circle plus its interior).
typedef struct cdist_circle {
    cdist_vec3 center; ///< centre of the circle
    cdist_vec3 normal; ///< unit normal of the circle's plane
    double radius;     ///< radius, >= 0
} cdist_circle;

/// A line: origin + t * direction for every real t.
typedef struct cdist_line {
    cdist_vec3 origin;    ///< a point of the line
    cdist_vec3 direction; ///< unit direction
} cdist_line;

/// A ray: origin + t * direction for t >= 0.
typedef struct cdist_ray {
    cdist_vec3 origin;    ///< the ray's start point
    cdist_vec3 direction; ///< unit direction
} cdist_ray;

/// A segment: p0 + s * (p1 - p0) for s in [0, 1]. p0 == p1 is allowed (a point).
typedef struct cdist_segment {
    cdist_vec3 p0; ///< start point (s = 0)
    cdist_vec3 p1; ///< end point (s = 1)
} cdist_segment;

/// A circular arc: the points C + r (cos a U + sin a V) of `circle` for a in [start, end],
/// where U = `zero_direction` (projected onto the circle's plane and normalised) and
/// V = N x U. Requires start <= end <= start + 2 pi.
typedef struct cdist_arc {
    cdist_circle circle;       ///< the supporting circle
    cdist_vec3 zero_direction; ///< direction of angle 0, must not be parallel to the normal
    double start;              ///< first angle of the arc, radians
    double end;                ///< last angle of the arc, radians
} cdist_arc;

/// A circular helix: C + r (cos t U + sin t V) + (pitch t / (2 pi)) N for t in [t0, t1],
/// with N = `axis` (unit), U = `zero_direction` projected orthogonal to N, V = N x U.
typedef struct cdist_helix {
    cdist_vec3 center;         ///< point on the axis at t = 0
    cdist_vec3 axis;           ///< unit axis direction
    cdist_vec3 zero_direction; ///< direction of angle 0, not parallel to the axis
    double radius;             ///< radius, >= 0
    double pitch;              ///< axial advance per full turn (may be 0 or negative)
    double t0;                 ///< first angle, radians
    double t1;                 ///< last angle, radians, >= t0
} cdist_helix;

/// A cubic Bezier curve with control points p[0..3], parameter t in [0, 1].
typedef struct cdist_bezier3 {
    cdist_vec3 p[4]; ///< control points
} cdist_bezier3;

/// One closest pair.
typedef struct cdist_pair {
    /// point[0] lies on the first object of the query, point[1] on the second.
    cdist_vec3 point[2];
    /// Parameter of each point on its object: line/ray parameter t (for the direction as
    /// passed), segment parameter s in [0, 1], circle/arc angle in (-pi, pi] (arcs: in the
    /// arc's own frame, within [start, end]), disk: polar angle of the point (NaN at the
    /// centre), curve parameter t; NaN for a point and wherever the value is meaningless
    /// (e.g. a circle of radius 0).
    double param[2];
} cdist_pair;

/// Query result. Output only: the library writes every field.
///
/// Growth policy: fields are never moved or removed. Fields added in later 1.x releases take
/// their place inside `reserved` (which 1.0 sets to zero), so sizeof(cdist_result) and every
/// offset stay the same for the whole of ABI version 1 (see cdist_result_size()).
typedef struct cdist_result {
    double distance;     ///< minimum distance (NaN on error)
    double sqr_distance; ///< distance squared
    int num_pairs;       ///< number of pairs given: 0 (error), 1 or 2
    /// Non-zero when infinitely many closest pairs exist (a point on a circle's axis, coaxial
    /// circles, a line in a disk's plane over the disk, ...). One representative pair is given.
    int equidistant;
    cdist_pair pairs[2]; ///< the closest pairs; pairs[i] valid for i < num_pairs
    int method;          ///< the ::cdist_method that actually answered
    int iterations;      ///< iterations used by ::CDIST_METHOD_ITERATION (else 0)
    double reserved[8];  ///< reserved for future fields; set to zero
} cdist_result;

/// Status codes. The numbers are fixed forever; new codes are only appended.
typedef enum cdist_status {
    CDIST_OK = 0,                      ///< success
    CDIST_ERR_NULL_ARGUMENT = 1,       ///< a required pointer was NULL
    CDIST_ERR_NOT_FINITE = 2,          ///< an input number was NaN or infinite
    CDIST_ERR_ZERO_VECTOR = 3,         ///< a normal, direction or axis had zero length
    CDIST_ERR_NOT_UNIT = 4,            ///< a normal or direction was not unit length
    CDIST_ERR_NEGATIVE_RADIUS = 5,     ///< a radius was negative
    CDIST_ERR_OUT_OF_RANGE = 6,        ///< a coordinate or radius exceeded 1e150
    CDIST_ERR_BAD_OPTION = 7,          ///< an option value or method was not valid
    CDIST_ERR_BAD_INTERVAL = 8,        ///< a parameter interval was empty or too long
    CDIST_ERR_CALLBACK_FAILED = 9,     ///< a curve callback returned non-zero
    CDIST_ERR_CALLBACK_NOT_FINITE = 10, ///< a curve callback returned NaN or infinity
    CDIST_ERR_NO_MEMORY = 11,          ///< memory allocation failed
    CDIST_ERR_INTERNAL = 12,           ///< an internal numerical failure (please report)
    CDIST_ERR_HANDLE_BUSY = 13,        ///< the handle was already in use by another call (one thread per handle)
    CDIST_ERR_COST_LIMIT = 14,         ///< the query would exceed the documented cost limit
    CDIST_ERR_THREAD = 15,             ///< a worker thread could not be started
    CDIST_ERR_BAD_KIND = 16            ///< a query kind number was not a ::cdist_kind
} cdist_status;

/// Algorithms. A method that a query does not have is answered by ::CDIST_METHOD_AUTO;
/// cdist_result::method says which method answered.
typedef enum cdist_method {
    CDIST_METHOD_AUTO = 0,       ///< the most exact and fastest for each query (default)
    CDIST_METHOD_POLYNOMIAL = 1, ///< polynomial roots (GSL), polished on the true distance
    CDIST_METHOD_ROBUST = 2,     ///< root bounding and bisection on the true derivative
    CDIST_METHOD_ITERATION = 3   ///< geometric iteration (circle-circle)
} cdist_method;

/// Curve callback: writes the position and derivative of the curve at parameter t and
/// returns 0; any other return value aborts the query with ::CDIST_ERR_CALLBACK_FAILED.
typedef int (*cdist_curve_fn)(void *user, double t, cdist_vec3 *position, cdist_vec3 *derivative);

/// Opaque query handle: options plus every workspace a query needs, so queries never allocate.
typedef struct cdist_query cdist_query;

/* ---- version ------------------------------------------------------------------------ */

/// Library version as "MAJOR.MINOR.PATCH" of the library actually loaded.
CDIST_API const char *cdist_version_string(void);
/// Library version as MAJOR*10000 + MINOR*100 + PATCH of the library actually loaded.
CDIST_API unsigned cdist_version_number(void);
/// Major version of the library actually loaded.
CDIST_API int cdist_version_major(void);
/// Minor version of the library actually loaded.
CDIST_API int cdist_version_minor(void);
/// Patch version of the library actually loaded.
CDIST_API int cdist_version_patch(void);

/* ---- status, sizes ------------------------------------------------------------------ */

/// A one-sentence description of a status ("unknown status" for numbers not listed).
CDIST_API const char *cdist_status_string(cdist_status status);
/// The enumerator's name, e.g. "CDIST_ERR_NOT_UNIT" ("CDIST_UNKNOWN" if not listed).
CDIST_API const char *cdist_status_name(cdist_status status);
/// sizeof(cdist_result) as compiled into the library, for FFI users to check their layout.
CDIST_API size_t cdist_result_size(void);
/// sizeof(cdist_pair) as compiled into the library.
CDIST_API size_t cdist_pair_size(void);

/* ---- query handle ------------------------------------------------------------------- */

/// Creates a query handle with default options. Returns NULL if memory runs out.
CDIST_API cdist_query *cdist_query_new(void);
/// Frees a handle and its workspaces. NULL is allowed and does nothing.
CDIST_API void cdist_query_free(cdist_query *q);
/// Selects the algorithm for later queries (default ::CDIST_METHOD_AUTO).
/// Returns ::CDIST_ERR_BAD_OPTION for a number that is not a ::cdist_method.
CDIST_API cdist_status cdist_query_set_method(cdist_query *q, cdist_method method);
/// The selected algorithm (::CDIST_METHOD_AUTO for a NULL handle).
CDIST_API cdist_method cdist_query_get_method(const cdist_query *q);
/// Sets the relative tolerance for unit normals and directions: a vector is accepted when
/// | |v| - 1 | <= tol and is then normalised. Pass INFINITY to accept (and normalise) any
/// non-zero length, 0 to demand |v| == 1 as computed in double. Default 1e-6.
CDIST_API cdist_status cdist_query_set_unit_tolerance(cdist_query *q, double tol);
/// The unit-length tolerance (see cdist_query_set_unit_tolerance()).
CDIST_API double cdist_query_get_unit_tolerance(const cdist_query *q);
/// Sets how many subintervals curve queries sample to bracket the critical points before
/// refining them (minimum 8, default 512). More samples catch closer pairs of extrema.
CDIST_API cdist_status cdist_query_set_curve_samples(cdist_query *q, int samples);
/// The curve sample count.
CDIST_API int cdist_query_get_curve_samples(const cdist_query *q);
/// Sets the iteration cap of ::CDIST_METHOD_ITERATION per start (minimum 1, default 200).
CDIST_API cdist_status cdist_query_set_max_iterations(cdist_query *q, int max_iterations);
/// The iteration cap.
CDIST_API int cdist_query_get_max_iterations(const cdist_query *q);
/// Status of the last query or setter called on this handle.
CDIST_API cdist_status cdist_query_last_status(const cdist_query *q);
/// Message describing the last error on this handle ("" after success). The string is owned
/// by the handle and valid until the next call with it.
CDIST_API const char *cdist_query_last_error(const cdist_query *q);

/* ---- circle frames ------------------------------------------------------------------ */

/// The basis in which circle angles are measured. With N the normalised normal and k the
/// index of N's component of smallest magnitude (the first on ties), U = e_k - N_k N
/// normalised, V = N x U. Writes U and V (either may be NULL).
CDIST_API cdist_status cdist_circle_basis(const cdist_circle *c, cdist_vec3 *u, cdist_vec3 *v);
/// The point of circle c at angle `angle` in the basis of cdist_circle_basis().
CDIST_API cdist_status cdist_circle_point(const cdist_circle *c, double angle, cdist_vec3 *point);

/* ---- point queries ------------------------------------------------------------------ */

/// Distance from point p to circle c. equidistant when p is on the circle's axis.
CDIST_API cdist_status cdist_point_circle(cdist_query *q, const cdist_vec3 *p, const cdist_circle *c, cdist_result *r);
/// Distance from point p to disk d (circle plus interior).
CDIST_API cdist_status cdist_point_disk(cdist_query *q, const cdist_vec3 *p, const cdist_circle *d, cdist_result *r);

/* ---- lines, rays, segments to circles ---------------------------------------------- */

/// Distance from a line to a circle (methods: POLYNOMIAL, ROBUST; AUTO = ROBUST).
CDIST_API cdist_status cdist_line_circle(cdist_query *q, const cdist_line *l, const cdist_circle *c, cdist_result *r);
/// Distance from a ray (t >= 0) to a circle.
CDIST_API cdist_status cdist_ray_circle(cdist_query *q, const cdist_ray *l, const cdist_circle *c, cdist_result *r);
/// Distance from a segment to a circle; param[0] is the segment parameter s in [0, 1].
CDIST_API cdist_status cdist_segment_circle(cdist_query *q, const cdist_segment *s, const cdist_circle *c, cdist_result *r);

/* ---- circle to circle --------------------------------------------------------------- */

/// Distance between two circles (methods: POLYNOMIAL, ROBUST, ITERATION; AUTO picks).
/// Swapping c0 and c1 gives the same distance with the pairs' points swapped.
CDIST_API cdist_status cdist_circle_circle(cdist_query *q, const cdist_circle *c0, const cdist_circle *c1, cdist_result *r);
/// Answers n circle-circle queries: results[i] and statuses[i] for (c0[i], c1[i]). A bad
/// entry gets its own status and a NaN result; the others are still answered. Returns
/// ::CDIST_OK when every entry succeeded, else the status of the first failing entry
/// (whose message cdist_query_last_error() then gives). statuses may be NULL.
CDIST_API cdist_status cdist_circle_circle_batch(cdist_query *q, size_t n, const cdist_circle *c0,
                                                 const cdist_circle *c1, cdist_result *results,
                                                 cdist_status *statuses);

/* ---- disks -------------------------------------------------------------------------- */

/// Distance from a line to a disk.
CDIST_API cdist_status cdist_line_disk(cdist_query *q, const cdist_line *l, const cdist_circle *d, cdist_result *r);
/// Distance from a ray to a disk.
CDIST_API cdist_status cdist_ray_disk(cdist_query *q, const cdist_ray *l, const cdist_circle *d, cdist_result *r);
/// Distance from a segment to a disk.
CDIST_API cdist_status cdist_segment_disk(cdist_query *q, const cdist_segment *s, const cdist_circle *d, cdist_result *r);
/// Distance from a circle (first) to a disk (second).
CDIST_API cdist_status cdist_circle_disk(cdist_query *q, const cdist_circle *c, const cdist_circle *d, cdist_result *r);
/// Distance between two disks.
CDIST_API cdist_status cdist_disk_disk(cdist_query *q, const cdist_circle *d0, const cdist_circle *d1, cdist_result *r);

/* ---- curves and arcs ---------------------------------------------------------------- */
/* These queries have one method (root bounding and bisection, answered as
 * ::CDIST_METHOD_ROBUST whatever the handle's method). Arcs are exact: their candidates are the
 * circle-circle critical points inside the range plus the end points. Callback curves, helices
 * and Bezier curves are sampled at cdist_query_get_curve_samples() intervals (per turn for a
 * helix) to bracket critical points, so two minima closer than the sample spacing may merge. */

/// Distance from the curve f(t), t in [t0, t1], to a circle; param[0] is the curve parameter.
/// The curve must be continuously differentiable and f must give its exact derivative.
CDIST_API cdist_status cdist_curve_circle(cdist_query *q, cdist_curve_fn f, void *user, double t0, double t1,
                                          const cdist_circle *c, cdist_result *r);
/// Distance from the curve f(t), t in [t0, t1], to a disk.
CDIST_API cdist_status cdist_curve_disk(cdist_query *q, cdist_curve_fn f, void *user, double t0, double t1,
                                        const cdist_circle *d, cdist_result *r);
/// Distance from an arc to a circle; param[0] is the arc angle.
CDIST_API cdist_status cdist_arc_circle(cdist_query *q, const cdist_arc *a, const cdist_circle *c, cdist_result *r);
/// Distance between two arcs.
CDIST_API cdist_status cdist_arc_arc(cdist_query *q, const cdist_arc *a0, const cdist_arc *a1, cdist_result *r);
/// Distance from a segment (first) to an arc (second).
CDIST_API cdist_status cdist_segment_arc(cdist_query *q, const cdist_segment *s, const cdist_arc *a, cdist_result *r);
/// Distance from an arc to a disk.
CDIST_API cdist_status cdist_arc_disk(cdist_query *q, const cdist_arc *a, const cdist_circle *d, cdist_result *r);
/// Distance from a helix to a circle; param[0] is the helix parameter t.
CDIST_API cdist_status cdist_helix_circle(cdist_query *q, const cdist_helix *h, const cdist_circle *c, cdist_result *r);
/// Distance from a helix to a disk.
CDIST_API cdist_status cdist_helix_disk(cdist_query *q, const cdist_helix *h, const cdist_circle *d, cdist_result *r);
/// Distance from a cubic Bezier curve to a circle; param[0] is the Bezier parameter.
CDIST_API cdist_status cdist_bezier3_circle(cdist_query *q, const cdist_bezier3 *b, const cdist_circle *c, cdist_result *r);
/// Distance from a cubic Bezier curve to a disk.
CDIST_API cdist_status cdist_bezier3_disk(cdist_query *q, const cdist_bezier3 *b, const cdist_circle *d, cdist_result *r);

#ifdef __cplusplus
}
#endif

#endif /* CIRCLEDIST_H */
