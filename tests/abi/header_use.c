/* SPDX-License-Identifier: MIT */
/* Uses every public type of circledist.h; compiled (not linked) as C89, C99, C11, C17, C++98,
 * C++11 and C++17 with -pedantic -Werror by check_header_std.py, so the header stays portable. */
#include <circledist.h>
#include <circledist.h> /* the include guard holds */

static int curve(void *user, double t, cdist_vec3 *position, cdist_vec3 *derivative)
{
    (void)user;
    position->x = t;
    position->y = 0;
    position->z = 0;
    derivative->x = 1;
    derivative->y = 0;
    derivative->z = 0;
    return 0;
}

int header_use(void);
int header_use(void)
{
    cdist_query *q = cdist_query_new();
    cdist_circle c = {{0, 0, 0}, {0, 0, 1}, 1};
    cdist_line l = {{0, 0, 0}, {1, 0, 0}};
    cdist_ray ray = {{0, 0, 0}, {1, 0, 0}};
    cdist_segment s = {{0, 0, 0}, {1, 0, 0}};
    cdist_arc a = {{{0, 0, 0}, {0, 0, 1}, 1}, {1, 0, 0}, 0, 1};
    cdist_helix h = {{0, 0, 0}, {0, 0, 1}, {1, 0, 0}, 1, 1, 0, 1};
    cdist_bezier3 b = {{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}}};
    cdist_result r;
    cdist_curve_fn f = curve;
    cdist_method m = CDIST_METHOD_ROBUST;
    cdist_status st = CDIST_OK;
    unsigned v = CDIST_VERSION_NUMBER;
    int bad = 0;

    bad |= cdist_query_set_method(q, m) != CDIST_OK;
    bad |= cdist_line_circle(q, &l, &c, &r) != st;
    bad |= cdist_ray_disk(q, &ray, &c, &r) != st;
    bad |= cdist_segment_arc(q, &s, &a, &r) != st;
    bad |= cdist_helix_circle(q, &h, &c, &r) != st;
    bad |= cdist_bezier3_disk(q, &b, &c, &r) != st;
    bad |= cdist_curve_circle(q, f, 0, 0.0, 1.0, &c, &r) != st;
    bad |= cdist_version_number() != v;
    bad |= r.pairs[0].param[0] != r.pairs[0].param[0];
    cdist_query_free(q);
    return bad;
}
