/* The API layer: the query handle, status recording, input validation, method choice. */
#ifndef CDIST_API_PRIV_H
#define CDIST_API_PRIV_H

#include <stddef.h>

#include "circledist.h"
#include "base/poly.h"
#include "base/tolerances.h"
#include "base/vec.h"

#define CD_DEFAULT_CURVE_SAMPLES 512
#define CD_MAX_CURVE_SAMPLES (1 << 20)
#define CD_DEFAULT_MAX_ITERATIONS 200
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
};


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

#endif
