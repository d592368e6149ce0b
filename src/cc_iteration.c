/* Circle-circle by geometric iteration (Li, Wu, Wang, Zhang 2015). */
#include "stub.h"
cdist_status cd_cc_iteration(cdist_query *q, const cd_circle *c0, const cd_circle *c1, cd_best *b, int *iterations)
{
    return cd_fail(q, CDIST_ERR_INTERNAL, "circle-circle iteration method is not implemented yet");
}
