/* Internal declarations shared by the query families. Nothing here is exported. */
#ifndef CDIST_INTERNAL_H
#define CDIST_INTERNAL_H

#include <float.h>
#include <stddef.h>

#include "circledist.h"
#include "poly.h"
#include "vec.h"

#define CD_DEFAULT_UNIT_TOL 1e-6
#define CD_DEFAULT_CURVE_SAMPLES 512
#define CD_MAX_CURVE_SAMPLES (1 << 20)
#define CD_DEFAULT_MAX_ITERATIONS 200
#define CD_MAX_ABS 1e150 /* largest accepted coordinate or radius: squares stay finite */
#define CD_MESSAGE_LEN 256

struct cdist_query {
    cdist_method method;
    double unit_tol;
    int curve_samples;
    int max_iterations;
    cdist_status last_status;
    char message[CD_MESSAGE_LEN];
    cd_poly_ws *poly;
    /* Scratch owned by the handle (sized by the setters) so that queries never allocate. */
    double *scratch;
    size_t scratch_len;
    struct cd_workers *workers; /* batch worker threads and their handles (src/batch); NULL = 1 thread */
};

/* Batch workers (src/batch/workers.c). cd_workers_free joins the threads and frees their handles
 * (NULL allowed). cd_workers_sync gives every worker handle the options of q, sizing their
 * workspaces (called by every option setter, so that a batch never allocates). */
void cd_workers_free(struct cd_workers *w);
cdist_status cd_workers_sync(cdist_query *q);

/* A validated circle: unit normal n, basis u, v (cdist_circle_basis rule), radius r. */
typedef struct cd_circle {
    vec3 c, n, u, v;
    double r;
} cd_circle;

/* ---- candidate collection: every family offers candidate pairs; ties become two pairs ---- */

#define CD_BEST_KEEP 4

typedef struct cd_cand {
    int equidistant; /* this candidate stands for infinitely many equally close pairs */
    double d2;
    vec3 p[2];
    double param[2];
} cd_cand;

typedef struct cd_best {
    double scale;    /* problem scale L, for the tie and distinctness tests */
    int n;           /* candidates kept, sorted by d2 */
    int equidistant; /* set by a family whose whole configuration has infinitely many closest pairs */
    cd_cand c[CD_BEST_KEEP];
} cd_best;

/* Two distances within CD_TIE_ULPS * eps * scale are a tie (both pairs are reported) when
 * their pairs are distinct: further apart than CD_DISTINCT_REL * scale. */
#define CD_TIE_ULPS 16.0
#define CD_DISTINCT_REL 1e-6

void cd_best_init(cd_best *b, double scale);
/* Whether the result would be flagged equidistant (the whole configuration, or the best
 * candidate stands for infinitely many pairs). */
static inline int cd_best_is_equidistant(const cd_best *b)
{
    return b->equidistant || (b->n > 0 && b->c[0].equidistant);
}
/* Offer a candidate: p0 on the first object, p1 on the second, d2 = its squared distance
 * computed as accurately as the family can (usually from the true distance function). */
void cd_best_offer(cd_best *b, double d2, vec3 p0, vec3 p1, double param0, double param1);
/* Same, for a candidate that represents infinitely many equally close pairs (e.g. a point on a
 * circle's axis): the result is flagged equidistant only if this candidate is the best. */
void cd_best_offer_equidistant(cd_best *b, double d2, vec3 p0, vec3 p1, double param0, double param1);
/* Either of the two above by a flag: for moving candidates from one collector to another
 * (pass the source candidate's .equidistant). */
void cd_best_offer_flag(cd_best *b, int equidistant, double d2, vec3 p0, vec3 p1, double param0, double param1);
/* Same, d2 computed as |p0 - p1|^2. */
void cd_best_offer_points(cd_best *b, vec3 p0, vec3 p1, double param0, double param1);
/* Write the result: the best pair and, on a tie, the second; points moved by `offset`
 * (the translation the family removed). swap exchanges the objects' roles (f(b,a) from f(a,b)). */
void cd_best_to_result(const cd_best *b, vec3 offset, int swap, cdist_result *r);

/* ---- validation and status ---- */

/* Start a query: sets the result to the error state (NaN, no pairs) and clears the message. */
void cd_begin(cdist_query *q, cdist_result *r);
/* Record a failure (message printf-style) and return the status. q may be NULL. */
cdist_status cd_fail(cdist_query *q, cdist_status st, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
/* Record success on the handle. */
cdist_status cd_ok(cdist_query *q, cdist_result *r, int method);

/* Check that q and r are non-NULL; on failure fills r (when it exists) and returns a status. */
cdist_status cd_check_handle(cdist_query *q, cdist_result *r);
cdist_status cd_check_ptr(cdist_query *q, const void *p, const char *what);
cdist_status cd_check_point(cdist_query *q, const cdist_vec3 *p, const char *what);
cdist_status cd_check_scalar(cdist_query *q, double x, const char *what);
/* A direction or normal: finite, non-zero, unit within the handle's tolerance (or any length
 * when unit_required is 0). Writes the unit vector and the original length. */
cdist_status cd_check_direction(cdist_query *q, const cdist_vec3 *d, const char *what, int unit_required,
                                vec3 *unit, double *length);
/* A circle or disk: writes the validated circle with its basis. */
cdist_status cd_check_circle(cdist_query *q, const cdist_circle *c, const char *what, cd_circle *out);

/* The method a family runs: AUTO (or a method the family lacks) becomes `fallback`. */
cdist_method cd_pick_method(const cdist_query *q, unsigned available_mask, cdist_method fallback);
#define CD_HAS(m) (1u << (m))

/* Angle of a point given relative to the circle centre, in (-pi, pi]; NaN when undefined. */
double cd_circle_angle(const cd_circle *c, vec3 rel);

/* ---- cores (inputs already translated so that the relevant centre is the origin) ---- */

/* Point p (relative to the circle centre) to circle/disk c (c->c ignored, taken as origin). */
void cd_point_circle_core(vec3 p, const cd_circle *c, cd_best *b, int swap);
void cd_point_disk_core(vec3 p, const cd_circle *c, cd_best *b, int swap);

/* Points B + t M, t in [tmin, tmax] (infinite ends allowed), M unit, B relative to the centre
 * of c (c->c ignored), to circle c. param[0] of the candidates is t. Sets b->equidistant when
 * the whole line is the axis. Returns CDIST_OK or an internal failure. */
cdist_status cd_linear_circle(cdist_query *q, cdist_method method, vec3 B, vec3 M, double tmin, double tmax,
                              const cd_circle *c, cd_best *b);
/* The same against a disk. */
cdist_status cd_linear_disk(cdist_query *q, cdist_method method, vec3 B, vec3 M, double tmin, double tmax,
                            const cd_circle *d, cd_best *b);

/* Circle c0 to circle c1 (c0->c at the origin, c1 relative to it). iterations may be NULL. */
cdist_status cd_circle_circle_core(cdist_query *q, cdist_method method, const cd_circle *c0, const cd_circle *c1,
                                   cd_best *b, int *iterations);
/* The non-robust circle-circle methods (src/cc_poly.c, src/cc_iteration.c), called by the
 * dispatcher in src/circle_circle.c with c0->c at the origin. Each handles every configuration
 * (setting b->equidistant where infinitely many pairs are closest) and offers its candidates to
 * b, or returns a non-OK status to make the dispatcher fall back to the robust method. */
cdist_status cd_cc_polynomial(cdist_query *q, const cd_circle *c0, const cd_circle *c1, cd_best *b);
cdist_status cd_cc_iteration(cdist_query *q, const cd_circle *c0, const cd_circle *c1, cd_best *b, int *iterations);

/* Every critical angle on c0 (in c0's basis) of theta -> dist^2(c0(theta), c1); returns the
 * count (at most cap), or -1 when the function is constant (every angle critical). */
int cd_circle_circle_critical(cdist_query *q, const cd_circle *c0, const cd_circle *c1, double *theta0, int cap);

/* Circle c to disk d (c->c at the origin, d relative to it). */
cdist_status cd_circle_disk_core(cdist_query *q, cdist_method method, const cd_circle *c, const cd_circle *d,
                                 cd_best *b);

/* ---- lines family (src/line_circle.c) ----
 * cd_linear_circle semantics: candidates are every local minimum of the squared distance inside
 * [tmin, tmax] plus the finite ends (point-circle), with param[1] the circle angle. method is
 * POLYNOMIAL or anything else (= ROBUST). b->equidistant is set when the closest point found is
 * on the circle's axis (the line is the axis, or a ray/segment end or clamped point lies on it)
 * and that candidate is then the best in b. cd_linear_circle_ex also reports the method that
 * answered (ROBUST when the polynomial module failed and the robust path took over). */
cdist_status cd_linear_circle_ex(cdist_query *q, cdist_method method, vec3 B, vec3 M, double tmin, double tmax,
                                 const cd_circle *c, cd_best *b, cdist_method *used);
/* Accuracy: the core is exact for the B it gets, so B should be near the centre. For a caller's
 * origin + t D, t in [tmin, tmax] (D as passed, any length), this returns B = (origin + t0 D) - C
 * for the point of the range nearest C, with origin - C kept exact (TwoSum) and one rounding at
 * the scale of B, and t0 (in units of D). Then call the core with M = D/|D| and the range
 * (tmin - t0)|D| .. (tmax - t0)|D|; a candidate's parameter in units of D is t0 + t/|D|. */
vec3 cd_line_near_centre(vec3 origin, vec3 D, vec3 C, double tmin, double tmax, double *t0);

/* ---- cc_methods block: helpers shared by cd_cc_polynomial and cd_cc_iteration (defined in
 * src/cc_poly.c). c0 is at the origin, c1 at D. "side" s moves a point on circle s and measures
 * its closed-form distance to the other circle: F_s(t) = dist^2(c_s(t), c_{1-s}). ---- */
typedef struct cd_cc {
    const cd_circle *c[2];
    vec3 D;   /* c1 centre relative to c0 centre */
    double L; /* problem scale */
} cd_cc;
/* F_s(t) with F' and F'' (either may be NULL); P, K (may be NULL): the moving point relative to
 * its own centre and the closest point of the other circle relative to that circle's centre. */
double cd_cc_eval(const cd_cc *g, int side, double t, double *f1, double *f2, vec3 *P, vec3 *K);
/* Safeguarded Newton on F_s' from t; returns the polished angle and writes F there. */
double cd_cc_polish(const cd_cc *g, int side, double t, double *F);
/* Offer the pair at angle t of side s (evaluated on the true distance). */
void cd_cc_offer(const cd_cc *g, int side, double t, cd_best *b);
/* Zero radius and coaxial circles, answered in closed form: returns 1 when b is complete. */
int cd_cc_closed_form(const cd_cc *g, cd_best *b);
/* Candidate angles on c0 for (nearly) parallel planes (Eberly 5.1-5.2, Li et al. 2.3);
 * returns the count (<= 4). */
int cd_cc_parallel_candidates(const cd_cc *g, double *t0);
/* When the axes meet (within a loose tolerance), the unit normal m of the mirror plane through
 * both axes; returns 0 otherwise. */
int cd_cc_mirror(const cd_cc *g, vec3 *m);
/* Offer polished minima (side, angle, F): the best, and the others unless they tie with it
 * without a barrier between them on c0 (one flat basin, not two symmetric minima). When F_s''
 * vanishes at the minimum, circle s may be at constant distance from the other (e.g. equal
 * perpendicular circles through each other's centre): tested by sampling, flagged equidistant. */
void cd_cc_offer_minima(const cd_cc *g, int n, const int *side, const double *t, const double *F, cd_best *b);
/* Both methods work on a copy scaled by a power of two (exact) so that the problem scale is
 * in [1, 2): squares neither overflow (coordinates up to 1e150) nor underflow (1e-300).
 * cd_cc_scale writes the scaled circles (c0 at the origin) and s; cd_cc_unscale offers the
 * scaled collector's candidates to b in the caller's units. */
void cd_cc_scale(const cd_circle *c0, const cd_circle *c1, double L, cd_circle *a, cd_circle *b, double *s);
void cd_cc_unscale(const cd_best *scaled, double s, cd_best *b);
/* ---- end of cc_methods block ---- */

#endif
