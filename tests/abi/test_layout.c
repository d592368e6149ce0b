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

SIZE(cdist_curve, 32);
OFF(cdist_curve, fn, 0);
OFF(cdist_curve, user, 8);
OFF(cdist_curve, t0, 16);
OFF(cdist_curve, t1, 24);

SIZE(cdist_sphere, 32);
OFF(cdist_sphere, center, 0);
OFF(cdist_sphere, radius, 24);

SIZE(cdist_capsule, 56);
OFF(cdist_capsule, segment, 0);
OFF(cdist_capsule, radius, 48);

SIZE(cdist_torus, 64);
OFF(cdist_torus, circle, 0);
OFF(cdist_torus, tube_radius, 56);

SIZE(cdist_rounded_disk, 64);
OFF(cdist_rounded_disk, disk, 0);
OFF(cdist_rounded_disk, radius, 56);

SIZE(cdist_contact_pair, 136);
OFF(cdist_contact_pair, point, 0);
OFF(cdist_contact_pair, core_point, 48);
OFF(cdist_contact_pair, normal, 96);
OFF(cdist_contact_pair, param, 120);

SIZE(cdist_contact, 368);
OFF(cdist_contact, distance, 0);
OFF(cdist_contact, core_distance, 8);
OFF(cdist_contact, num_pairs, 16);
OFF(cdist_contact, equidistant, 20);
OFF(cdist_contact, flags, 24);
OFF(cdist_contact, method, 28);
OFF(cdist_contact, pairs, 32);
OFF(cdist_contact, reserved, 304);

SIZE(cdist_grad_object, 264);
OFF(cdist_grad_object, d_center, 0);
OFF(cdist_grad_object, d_normal, 24);
OFF(cdist_grad_object, d_origin, 48);
OFF(cdist_grad_object, d_direction, 72);
OFF(cdist_grad_object, d_p0, 96);
OFF(cdist_grad_object, d_p1, 120);
OFF(cdist_grad_object, d_zero_direction, 144);
OFF(cdist_grad_object, d_radius, 168);
OFF(cdist_grad_object, d_radius_swept, 176);
OFF(cdist_grad_object, d_start, 184);
OFF(cdist_grad_object, d_end, 192);
OFF(cdist_grad_object, reserved, 200);

SIZE(cdist_grad, 600);
OFF(cdist_grad, obj, 0);
OFF(cdist_grad, flags, 528);
OFF(cdist_grad, reserved_int, 532);
OFF(cdist_grad, reserved, 536);

SIZE(cdist_status, 4);
SIZE(cdist_method, 4);
SIZE(cdist_curve_fn, 8);
SIZE(cdist_kind, 4);
SIZE(cdist_contact_flag, 4);
/* scenes (CDIST_1.1) */
SIZE(cdist_scene_pair, 136);
OFF(cdist_scene_pair, i, 0);
OFF(cdist_scene_pair, j, 8);
OFF(cdist_scene_pair, distance, 16);
OFF(cdist_scene_pair, status, 24);
OFF(cdist_scene_pair, num_pairs, 28);
OFF(cdist_scene_pair, flags, 32);
OFF(cdist_scene_pair, reserved, 36);
OFF(cdist_scene_pair, point, 40);
SIZE(cdist_scene_stats, 128);
OFF(cdist_scene_stats, objects, 0);
OFF(cdist_scene_stats, live, 8);
OFF(cdist_scene_stats, nodes, 16);
OFF(cdist_scene_stats, bytes, 24);
OFF(cdist_scene_stats, box_pairs, 32);
OFF(cdist_scene_stats, screened, 40);
OFF(cdist_scene_stats, candidates, 48);
OFF(cdist_scene_stats, reported, 56);
OFF(cdist_scene_stats, rebuilds, 64);
OFF(cdist_scene_stats, refits, 72);
OFF(cdist_scene_stats, reserved, 80);
SIZE(cdist_scene_link, 112);
OFF(cdist_scene_link, i, 0);
OFF(cdist_scene_link, j, 8);
OFF(cdist_scene_link, status, 16);
OFF(cdist_scene_link, reserved_int, 20);
OFF(cdist_scene_link, link, 24);
OFF(cdist_scene_link, reserved, 96);
OFF(cdist_scene_toi_result, i, 0);
OFF(cdist_scene_toi_result, j, 8);
OFF(cdist_scene_toi_result, candidates, 16);
OFF(cdist_scene_toi_result, toi, 24);
OFF(cdist_scene_toi_result, reserved, 448);
SIZE(cdist_scene_toi_result, 480);
SIZE(cdist_scene_kind, 4);
SIZE(cdist_scene_pair_flag, 4);
SIZE(cdist_grad_flag, 4);
SIZE(cdist_link, 72);
OFF(cdist_link, linking, 0);
OFF(cdist_link, core_linking, 4);
OFF(cdist_link, distance, 8);
OFF(cdist_link, core_distance, 16);
OFF(cdist_link, scale, 24);
OFF(cdist_link, flags, 32);
OFF(cdist_link, reserved_int, 36);
OFF(cdist_link, reserved, 40);

SIZE(cdist_shape_data, 80);
OFF(cdist_shape_data, sphere, 0);
OFF(cdist_shape_data, capsule, 0);
OFF(cdist_shape_data, torus, 0);
OFF(cdist_shape_data, rounded_disk, 0);
OFF(cdist_shape_data, reserved, 0);
SIZE(cdist_shape, 88);
OFF(cdist_shape, type, 0);
OFF(cdist_shape, reserved_int, 4);
OFF(cdist_shape, u, 8);

SIZE(cdist_motion, 72);
OFF(cdist_motion, center, 0);
OFF(cdist_motion, translation, 24);
OFF(cdist_motion, rotation, 48);

SIZE(cdist_toi_result, 424);
OFF(cdist_toi_result, state, 0);
OFF(cdist_toi_result, iterations, 4);
OFF(cdist_toi_result, t, 8);
OFF(cdist_toi_result, distance, 16);
OFF(cdist_toi_result, contact, 24);
OFF(cdist_toi_result, reserved, 392);
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
VALUE(CDIST_ERR_CANCELLED, 17);
VALUE(CDIST_ERR_OVERLAP, 18);

VALUE(CDIST_METHOD_AUTO, 0);
VALUE(CDIST_METHOD_POLYNOMIAL, 1);
VALUE(CDIST_METHOD_ROBUST, 2);
VALUE(CDIST_METHOD_ITERATION, 3);

VALUE(CDIST_KIND_POINT_CIRCLE, 0);
VALUE(CDIST_KIND_POINT_DISK, 1);
VALUE(CDIST_KIND_LINE_CIRCLE, 2);
VALUE(CDIST_KIND_RAY_CIRCLE, 3);
VALUE(CDIST_KIND_SEGMENT_CIRCLE, 4);
VALUE(CDIST_KIND_CIRCLE_CIRCLE, 5);
VALUE(CDIST_KIND_LINE_DISK, 6);
VALUE(CDIST_KIND_RAY_DISK, 7);
VALUE(CDIST_KIND_SEGMENT_DISK, 8);
VALUE(CDIST_KIND_CIRCLE_DISK, 9);
VALUE(CDIST_KIND_DISK_DISK, 10);
VALUE(CDIST_KIND_CURVE_CIRCLE, 11);
VALUE(CDIST_KIND_CURVE_DISK, 12);
VALUE(CDIST_KIND_ARC_CIRCLE, 13);
VALUE(CDIST_KIND_ARC_ARC, 14);
VALUE(CDIST_KIND_SEGMENT_ARC, 15);
VALUE(CDIST_KIND_ARC_DISK, 16);
VALUE(CDIST_KIND_HELIX_CIRCLE, 17);
VALUE(CDIST_KIND_HELIX_DISK, 18);
VALUE(CDIST_KIND_BEZIER3_CIRCLE, 19);
VALUE(CDIST_KIND_BEZIER3_DISK, 20);
VALUE(CDIST_KIND_TORUS_TORUS, 21);
VALUE(CDIST_KIND_TORUS_CAPSULE, 22);
VALUE(CDIST_KIND_TORUS_SPHERE, 23);
VALUE(CDIST_KIND_TORUS_ROUNDED_DISK, 24);
VALUE(CDIST_KIND_CAPSULE_CAPSULE, 25);
VALUE(CDIST_KIND_CAPSULE_SPHERE, 26);
VALUE(CDIST_KIND_CAPSULE_ROUNDED_DISK, 27);
VALUE(CDIST_KIND_SPHERE_SPHERE, 28);
VALUE(CDIST_KIND_SPHERE_ROUNDED_DISK, 29);
VALUE(CDIST_KIND_ROUNDED_DISK_ROUNDED_DISK, 30);
VALUE(CDIST_KIND_TORUS_LINE, 31);
VALUE(CDIST_KIND_TORUS_RAY, 32);
VALUE(CDIST_KIND_TORUS_SEGMENT, 33);
VALUE(CDIST_KIND_CAPSULE_CIRCLE, 34);
VALUE(CDIST_KIND_CAPSULE_DISK, 35);
VALUE(CDIST_KIND_SPHERE_CIRCLE, 36);
VALUE(CDIST_KIND_SPHERE_DISK, 37);

VALUE(CDIST_CONTACT_CORE_TOUCH, 1);
VALUE(CDIST_GRAD_NOT_DIFFERENTIABLE, 1);
SIZE(cdist_link_value, sizeof(int));
VALUE(CDIST_LINK_TOUCHING, 2);
VALUE(CDIST_LINK_OVERLAP, 3);
VALUE(CDIST_LINK_ERROR, 4);
SIZE(cdist_link_flag, sizeof(int));
VALUE(CDIST_LINK_FLAG_EXTENDED, 1);
VALUE(CDIST_LINK_FLAG_UNRESOLVED, 2);
SIZE(cdist_shape_type, sizeof(int));
VALUE(CDIST_SHAPE_SPHERE, 0);
VALUE(CDIST_SHAPE_CAPSULE, 1);
VALUE(CDIST_SHAPE_TORUS, 2);
VALUE(CDIST_SHAPE_ROUNDED_DISK, 3);
SIZE(cdist_toi_state, sizeof(int));
VALUE(CDIST_TOI_NONE, 0);
VALUE(CDIST_TOI_HIT, 1);
VALUE(CDIST_TOI_ITERATION_LIMIT, 2);

VALUE(CDIST_SCENE_POINT, 0);
VALUE(CDIST_SCENE_SEGMENT, 1);
VALUE(CDIST_SCENE_CIRCLE, 2);
VALUE(CDIST_SCENE_DISK, 3);
VALUE(CDIST_SCENE_ARC, 4);
VALUE(CDIST_SCENE_SPHERE, 5);
VALUE(CDIST_SCENE_CAPSULE, 6);
VALUE(CDIST_SCENE_TORUS, 7);
VALUE(CDIST_SCENE_ROUNDED_DISK, 8);
VALUE(CDIST_SCENE_PAIR_EQUIDISTANT, 1);
VALUE(CDIST_SCENE_PAIR_CORE_TOUCH, 2);

int main(void)
{
    /* The library was compiled from the same header: its own sizes agree. */
    int ok = cdist_result_size() == sizeof(cdist_result) && cdist_pair_size() == sizeof(cdist_pair)
             && cdist_contact_size() == sizeof(cdist_contact) && cdist_grad_size() == sizeof(cdist_grad)
             && cdist_swept_size(0) == sizeof(cdist_sphere) && cdist_swept_size(1) == sizeof(cdist_capsule)
             && cdist_swept_size(2) == sizeof(cdist_torus) && cdist_swept_size(3) == sizeof(cdist_rounded_disk)
             && cdist_kind_size_a(CDIST_KIND_CURVE_CIRCLE) == sizeof(cdist_curve)
             && cdist_contact_flag_core_touch() == CDIST_CONTACT_CORE_TOUCH
             && cdist_grad_flag_not_differentiable() == CDIST_GRAD_NOT_DIFFERENTIABLE
             && cdist_link_size() == sizeof(cdist_link) && cdist_shape_size() == sizeof(cdist_shape)
             && cdist_toi_result_size() == sizeof(cdist_toi_result)
             && cdist_scene_pair_size() == sizeof(cdist_scene_pair) && cdist_scene_stats_size() == sizeof(cdist_scene_stats)
             && cdist_scene_kind_size(CDIST_SCENE_ARC) == sizeof(cdist_arc)
             && cdist_scene_link_size() == sizeof(cdist_scene_link)
             && cdist_scene_toi_size() == sizeof(cdist_scene_toi_result);
#ifndef LAYOUT_CHECKED
    printf("test_layout: enumerator values checked; struct layout skipped (documented for x86-64 only)\n");
#endif
    printf("test_layout: %d passed, %d failed\n", ok, !ok);
    return ok ? 0 : 1;
}
