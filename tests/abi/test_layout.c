/* SPDX-License-Identifier: MIT */
/* The documented x86-64 (LP64, System V) layout of every public struct and the number of every
 * public enumerator (docs/abi.md), asserted at compile time: a reordered field, a changed type
 * or a renumbered status fails the build of this test. check_layout_coverage.py checks that
 * every struct and enumerator of the header is listed here. */
#include <circledist.h>

#include <stddef.h>
#include <stdio.h>

#if defined(__x86_64__) && defined(__LP64__)
#define OFF(type, field, bytes) _Static_assert(offsetof(type, field) == (bytes), #type "." #field)
#define SIZE(type, bytes) _Static_assert(sizeof(type) == (bytes), "sizeof " #type)

SIZE(cdist_vec3, 24);
OFF(cdist_vec3, x, 0);
OFF(cdist_vec3, y, 8);
OFF(cdist_vec3, z, 16);

SIZE(cdist_circle, 56);
OFF(cdist_circle, center, 0);
OFF(cdist_circle, normal, 24);
OFF(cdist_circle, radius, 48);

SIZE(cdist_line, 48);
OFF(cdist_line, origin, 0);
OFF(cdist_line, direction, 24);

SIZE(cdist_ray, 48);
OFF(cdist_ray, origin, 0);
OFF(cdist_ray, direction, 24);

SIZE(cdist_segment, 48);
OFF(cdist_segment, p0, 0);
OFF(cdist_segment, p1, 24);

SIZE(cdist_arc, 96);
OFF(cdist_arc, circle, 0);
OFF(cdist_arc, zero_direction, 56);
OFF(cdist_arc, start, 80);
OFF(cdist_arc, end, 88);

SIZE(cdist_helix, 104);
OFF(cdist_helix, center, 0);
OFF(cdist_helix, axis, 24);
OFF(cdist_helix, zero_direction, 48);
OFF(cdist_helix, radius, 72);
OFF(cdist_helix, pitch, 80);
OFF(cdist_helix, t0, 88);
OFF(cdist_helix, t1, 96);

SIZE(cdist_bezier3, 96);
OFF(cdist_bezier3, p, 0);

SIZE(cdist_pair, 64);
OFF(cdist_pair, point, 0);
OFF(cdist_pair, param, 48);

SIZE(cdist_result, 224);
OFF(cdist_result, distance, 0);
OFF(cdist_result, sqr_distance, 8);
OFF(cdist_result, num_pairs, 16);
OFF(cdist_result, equidistant, 20);
OFF(cdist_result, pairs, 24);
OFF(cdist_result, method, 152);
OFF(cdist_result, iterations, 156);
OFF(cdist_result, reserved, 160);

SIZE(cdist_status, 4);
SIZE(cdist_method, 4);
SIZE(cdist_curve_fn, 8);
#define LAYOUT_CHECKED 1
#endif

#define VALUE(name, number) _Static_assert(name == (number), #name)

VALUE(CDIST_OK, 0);
VALUE(CDIST_ERR_NULL_ARGUMENT, 1);
VALUE(CDIST_ERR_NOT_FINITE, 2);
VALUE(CDIST_ERR_ZERO_VECTOR, 3);
VALUE(CDIST_ERR_NOT_UNIT, 4);
VALUE(CDIST_ERR_NEGATIVE_RADIUS, 5);
VALUE(CDIST_ERR_OUT_OF_RANGE, 6);
VALUE(CDIST_ERR_BAD_OPTION, 7);
VALUE(CDIST_ERR_BAD_INTERVAL, 8);
VALUE(CDIST_ERR_CALLBACK_FAILED, 9);
VALUE(CDIST_ERR_CALLBACK_NOT_FINITE, 10);
VALUE(CDIST_ERR_NO_MEMORY, 11);
VALUE(CDIST_ERR_INTERNAL, 12);
VALUE(CDIST_ERR_HANDLE_BUSY, 13);
VALUE(CDIST_ERR_COST_LIMIT, 14);
VALUE(CDIST_ERR_THREAD, 15);
VALUE(CDIST_ERR_BAD_KIND, 16);

VALUE(CDIST_METHOD_AUTO, 0);
VALUE(CDIST_METHOD_POLYNOMIAL, 1);
VALUE(CDIST_METHOD_ROBUST, 2);
VALUE(CDIST_METHOD_ITERATION, 3);

int main(void)
{
    /* The library was compiled from the same header: its own sizes agree. */
    int ok = cdist_result_size() == sizeof(cdist_result) && cdist_pair_size() == sizeof(cdist_pair);
#ifndef LAYOUT_CHECKED
    printf("test_layout: enumerator values checked; struct layout skipped (documented for x86-64 only)\n");
#endif
    printf("test_layout: %d passed, %d failed\n", ok, !ok);
    return ok ? 0 : 1;
}
