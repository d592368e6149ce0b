/* Lines family cores (src/lines): lines, rays and segments to circles and disks. */
#ifndef CDIST_LINES_PRIV_H
#define CDIST_LINES_PRIV_H

#include "circledist.h"
#include "base/best.h"
#include "base/vec.h"

/* Points B + t M, t in [tmin, tmax] (infinite ends allowed), M unit, B relative to the centre
 * of c (c->c ignored), to circle c. param[0] of the candidates is t. Sets b->equidistant when
 * the whole line is the axis. Returns CDIST_OK or an internal failure. */
cdist_status cd_linear_circle(cdist_query *q, cdist_method method, vec3 B, vec3 M, double tmin, double tmax,
                              const cd_circle *c, cd_best *b);
/* The same against a disk. */
cdist_status cd_linear_disk(cdist_query *q, cdist_method method, vec3 B, vec3 M, double tmin, double tmax,
                            const cd_circle *d, cd_best *b);

/* ---- lines family (src/lines/line_circle.c) ----
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

#endif
