// SPDX-License-Identifier: MIT
// The public header compiles as C++ and its declarations link from C++.
#include <circledist.h>

#include <cmath>
#include <cstdio>

static_assert(sizeof(cdist_vec3) == 3 * sizeof(double), "vec3 is three doubles");

int main()
{
    cdist_query *q = cdist_query_new();
    cdist_circle c = {{0, 0, 0}, {0, 0, 1}, 1};
    cdist_vec3 p = {2, 0, 0};
    cdist_result r;
    cdist_status st = cdist_point_circle(q, &p, &c, &r);
    cdist_query_free(q);
    int ok = st == CDIST_OK && r.distance == 1.0 && CDIST_VERSION_MAJOR == cdist_version_major();
    std::printf("test_cxx: %d passed, %d failed\n", ok, !ok);
    return ok ? 0 : 1;
}
