/* Circle to circle. */
#include "stub.h"
CD_STUB(cdist_circle_circle, cdist_query *q, const cdist_circle *c0, const cdist_circle *c1, cdist_result *r)
CD_STUB(cdist_circle_circle_batch, cdist_query *q, size_t n, const cdist_circle *c0, const cdist_circle *c1,
        cdist_result *results, cdist_status *statuses)
cdist_status cd_circle_circle_core(cdist_query *q, cdist_method method, const cd_circle *c0, const cd_circle *c1,
                                   cd_best *b, int *iterations)
{
    (void)method; (void)c0; (void)c1; (void)b; (void)iterations;
    return cd_fail(q, CDIST_ERR_INTERNAL, "circle-circle is not implemented yet");
}
int cd_circle_circle_critical(cdist_query *q, const cd_circle *c0, const cd_circle *c1, double *theta0, int cap)
{
    (void)q; (void)c0; (void)c1; (void)theta0; (void)cap;
    return 0;
}
