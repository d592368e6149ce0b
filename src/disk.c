/* Lines, rays, segments, circles and disks to disks. */
#include "stub.h"
CD_STUB(cdist_line_disk, cdist_query *q, const cdist_line *l, const cdist_circle *d, cdist_result *r)
CD_STUB(cdist_ray_disk, cdist_query *q, const cdist_ray *l, const cdist_circle *d, cdist_result *r)
CD_STUB(cdist_segment_disk, cdist_query *q, const cdist_segment *s, const cdist_circle *d, cdist_result *r)
CD_STUB(cdist_circle_disk, cdist_query *q, const cdist_circle *c, const cdist_circle *d, cdist_result *r)
CD_STUB(cdist_disk_disk, cdist_query *q, const cdist_circle *d0, const cdist_circle *d1, cdist_result *r)
cdist_status cd_linear_disk(cdist_query *q, cdist_method method, vec3 B, vec3 M, double tmin, double tmax,
                            const cd_circle *d, cd_best *b)
{
    (void)method; (void)B; (void)M; (void)tmin; (void)tmax; (void)d; (void)b;
    return cd_fail(q, CDIST_ERR_INTERNAL, "line-disk is not implemented yet");
}
cdist_status cd_circle_disk_core(cdist_query *q, cdist_method method, const cd_circle *c, const cd_circle *d,
                                 cd_best *b)
{
    (void)method; (void)c; (void)d; (void)b;
    return cd_fail(q, CDIST_ERR_INTERNAL, "circle-disk is not implemented yet");
}
