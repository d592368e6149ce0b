/* Lines, rays and segments to circles. */
#include "stub.h"
CD_STUB(cdist_line_circle, cdist_query *q, const cdist_line *l, const cdist_circle *c, cdist_result *r)
CD_STUB(cdist_ray_circle, cdist_query *q, const cdist_ray *l, const cdist_circle *c, cdist_result *r)
CD_STUB(cdist_segment_circle, cdist_query *q, const cdist_segment *s, const cdist_circle *c, cdist_result *r)
cdist_status cd_linear_circle(cdist_query *q, cdist_method method, vec3 B, vec3 M, double tmin, double tmax,
                              const cd_circle *c, cd_best *b)
{
    (void)method; (void)B; (void)M; (void)tmin; (void)tmax; (void)c; (void)b;
    return cd_fail(q, CDIST_ERR_INTERNAL, "line-circle is not implemented yet");
}
