/* Circle-circle by the degree-8 polynomial (distance-to-circles-3d §5). */
#include "stub.h"
cdist_status cd_cc_polynomial(cdist_query *q, const cd_circle *c0, const cd_circle *c1, cd_best *b)
{
    return cd_fail(q, CDIST_ERR_INTERNAL, "circle-circle polynomial method is not implemented yet");
}
