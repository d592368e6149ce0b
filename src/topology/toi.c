/* SPDX-License-Identifier: MIT */
/* Time of impact of two rigidly moving swept objects by conservative advancement on the exact
 * signed distance (the swept contact queries). Every point of a body moves with speed at most
 * |T| + |omega| rho (rho: the largest distance of its core from the rotation centre), so the
 * distance between the bodies shrinks no faster than V = |T_a - T_b| + |omega_a| rho_a +
 * |omega_b| rho_b: from time t it cannot reach the target before t + (d(t) - target) / V. Steps
 * of that length never pass the first contact, however thin or fast the objects. */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "swept/swept-priv.h"
#include "topology/topology-priv.h"

size_t cdist_shape_size(void) { return sizeof(cdist_shape); }
size_t cdist_toi_result_size(void) { return sizeof(cdist_toi_result); }

/* R(angle about unit k) v, Rodrigues' formula. */
static vec3 rotate(vec3 k, double c, double s, vec3 v)
{
    return v_add(v_add(v_scale(c, v), v_scale(s, v_cross(k, v))), v_scale(v_dot(k, v) * (1.0 - c), k));
}

typedef struct pose {
    vec3 center, shift, k; /* rotation centre, displacement t T, unit axis */
    double c, s;           /* cos and sin of t |omega| */
} pose;

static pose pose_at(const cdist_motion *m, double t)
{
    pose p = {v3(0, 0, 0), v3(0, 0, 0), v3(0, 0, 1), 1.0, 0.0};
    if (!m) return p;
    p.center = m->center;
    p.shift = v_scale(t, m->translation);
    double w = v_norm(m->rotation);
    if (w > 0.0) {
        p.k = v_scale(1.0 / w, m->rotation);
        p.c = cos(t * w);
        p.s = sin(t * w);
    }
    return p;
}

static vec3 move_point(const pose *p, vec3 x) { return v_add(v_add(p->center, p->shift), rotate(p->k, p->c, p->s, v_sub(x, p->center))); }
static vec3 move_dir(const pose *p, vec3 n) { return rotate(p->k, p->c, p->s, n); }

static int shape_type_ok(int type) { return type >= CDIST_SHAPE_SPHERE && type <= CDIST_SHAPE_ROUNDED_DISK; }

static void shape_move(const cdist_shape *s, const pose *p, cdist_shape *out)
{
    *out = *s;
    switch (s->type) {
    case CDIST_SHAPE_SPHERE: out->u.sphere.center = move_point(p, s->u.sphere.center); break;
    case CDIST_SHAPE_CAPSULE:
        out->u.capsule.segment.p0 = move_point(p, s->u.capsule.segment.p0);
        out->u.capsule.segment.p1 = move_point(p, s->u.capsule.segment.p1);
        break;
    default: { /* the torus's circle, the rounded disk's disk */
        cdist_circle *k = s->type == CDIST_SHAPE_TORUS ? &out->u.torus.circle : &out->u.rounded_disk.disk;
        k->center = move_point(p, k->center);
        k->normal = move_dir(p, k->normal);
        break;
    }
    }
}

static int motion_finite(const cdist_motion *m)
{
    return !m || (cdist__in_range(m->center) && cdist__in_range(m->translation) && cdist__in_range(m->rotation));
}

cdist_status cdist_shape_at(const cdist_shape *s, const cdist_motion *m, double t, cdist_shape *out)
{
    if (!s || !out) return CDIST_ERR_NULL_ARGUMENT;
    if (!shape_type_ok(s->type)) return CDIST_ERR_BAD_OPTION;
    if (!isfinite(t) || !motion_finite(m)) return CDIST_ERR_NOT_FINITE;
    pose p = pose_at(m, t);
    shape_move(s, &p, out);
    return CDIST_OK;
}

static cdist__core_obj shape_core(const cdist_shape *s)
{
    switch (s->type) {
    case CDIST_SHAPE_CAPSULE: return CD_SWEPT_CAPSULE(&s->u.capsule);
    case CDIST_SHAPE_TORUS: return CD_SWEPT_TORUS(&s->u.torus);
    case CDIST_SHAPE_ROUNDED_DISK: return CD_SWEPT_RDISK(&s->u.rounded_disk);
    default: return CD_SWEPT_SPHERE(&s->u.sphere);
    }
}

/* The largest distance of the shape's core from point c (a disk's: its rim's). */
static double core_reach(const cdist_shape *s, vec3 c)
{
    switch (s->type) {
    case CDIST_SHAPE_SPHERE: return v_dist(s->u.sphere.center, c);
    case CDIST_SHAPE_CAPSULE: return fmax(v_dist(s->u.capsule.segment.p0, c), v_dist(s->u.capsule.segment.p1, c));
    default: {
        const cdist_circle *k = s->type == CDIST_SHAPE_TORUS ? &s->u.torus.circle : &s->u.rounded_disk.disk;
        vec3 n = v_unit_or_zero(k->normal), rel = v_sub(k->center, c);
        double h = v_dot(rel, n), q = v_norm(v_axpy(rel, -h, n));
        return sqrt(h * h + (q + k->radius) * (q + k->radius));
    }
    }
}

/* Largest magnitude of the coordinates the shape takes over the motion (for the rounding slack). */
static double motion_scale(const cdist_shape *s, const cdist_motion *m)
{
    vec3 c = m ? m->center : v3(0, 0, 0);
    double reach = core_reach(s, c);
    double extra = m ? v_norm(m->translation) : 0.0;
    return v_norm(c) + extra + reach;
}

static void toi_set_error(void *toi)
{
    cdist_toi_result *out = toi;
    memset(out, 0, sizeof *out);
    out->state = CDIST_TOI_NONE;
    out->t = NAN;
    out->distance = NAN;
    cdist__contact_set_error(&out->contact);
}

cdist_status cdist_toi(cdist_query *q, const cdist_shape *a, const cdist_motion *ma, const cdist_shape *b,
                       const cdist_motion *mb, double target, double tolerance, int max_iterations, cdist_toi_result *out)
{
    cdist_result r;
    if (out) toi_set_error(out);
    cdist_status st = cdist__enter(q, &r);
    if (st) return st;
    if (!out) st = cdist__fail(q, CDIST_ERR_NULL_ARGUMENT, "time-of-impact result pointer is NULL");
    else if (!a || !b) st = cdist__fail(q, CDIST_ERR_NULL_ARGUMENT, "%s shape pointer is NULL", a ? "second" : "first");
    else if (!shape_type_ok(a->type) || !shape_type_ok(b->type))
        st = cdist__fail(q, CDIST_ERR_BAD_OPTION, "%s shape's type %d is not a cdist_shape_type",
                         shape_type_ok(a->type) ? "second" : "first", shape_type_ok(a->type) ? b->type : a->type);
    else if (!motion_finite(ma) || !motion_finite(mb))
        st = cdist__fail(q, CDIST_ERR_NOT_FINITE, "%s motion has a NaN, infinite or out-of-range number",
                         motion_finite(ma) ? "second" : "first");
    else if (!isfinite(target) || fabs(target) > CD_MAX_ABS)
        st = cdist__fail(q, CDIST_ERR_NOT_FINITE, "target separation is not finite (%g)", target);
    else if (!(tolerance > 0.0) || !isfinite(tolerance))
        st = cdist__fail(q, CDIST_ERR_BAD_OPTION, "tolerance must be finite and > 0 (%g)", tolerance);
    else if (max_iterations < 1)
        st = cdist__fail(q, CDIST_ERR_BAD_OPTION, "max_iterations must be >= 1 (%d)", max_iterations);
    if (st) return cdist__leave(q, &r, st, CDIST_METHOD_AUTO);
    cdist__leave_setter(q);

    /* The bound on the shrinking speed, rounded up, and the slack for rounding of poses and
     * distances; the tolerance is at least twice the slack so that every step advances. The
     * signed distance core - (r_a + r_b) and its difference with the target round at the scale
     * of the swept radii and the target, which may exceed the motion's coordinates. */
    vec3 ta = ma ? ma->translation : v3(0, 0, 0), tb = mb ? mb->translation : v3(0, 0, 0);
    double wa = ma ? v_norm(ma->rotation) : 0.0, wb = mb ? v_norm(mb->rotation) : 0.0;
    double rho_a = core_reach(a, ma ? ma->center : v3(0, 0, 0)), rho_b = core_reach(b, mb ? mb->center : v3(0, 0, 0));
    double speed = (v_norm(v_sub(ta, tb)) + wa * rho_a + wb * rho_b) * (1.0 + CD_TOI_SPEED_ULPS * DBL_EPSILON);
    double radii = shape_core(a).radius + shape_core(b).radius;
    double slack = CD_TOI_POSE_ULPS * DBL_EPSILON *
                   fmax(fmax(motion_scale(a, ma), motion_scale(b, mb)), radii + fabs(target));
    double tol = fmax(tolerance, 2.0 * slack);

    double t = 0.0;
    for (int it = 1;; it++) {
        cdist_shape pa = *a, pb = *b;
        if (t > 0.0) {
            pose p = pose_at(ma, t);
            shape_move(a, &p, &pa);
            p = pose_at(mb, t);
            shape_move(b, &p, &pb);
        }
        cdist__core_obj oa = shape_core(&pa), ob = shape_core(&pb);
        if ((st = cdist__swept_query(q, &oa, &ob, &out->contact, NULL))) {
            toi_set_error(out);
            return st;
        }
        double d = out->contact.distance;
        out->t = t;
        out->distance = d;
        out->iterations = it;
        if (d <= target + tol) {
            out->state = CDIST_TOI_HIT;
            return CDIST_OK;
        }
        double step = (d - target - slack) / speed;
        if (!(t + step < 1.0)) { /* also speed == 0: the distance never changes */
            out->state = CDIST_TOI_NONE;
            return CDIST_OK;
        }
        if (it >= max_iterations) {
            out->state = CDIST_TOI_ITERATION_LIMIT;
            return CDIST_OK;
        }
        t += step;
    }
}

typedef struct toi_job {
    const char *a, *ma, *b, *mb;
    ptrdiff_t a_stride, ma_stride, b_stride, mb_stride;
    double target, tolerance;
    int max_iterations;
    cdist_toi_result *out;
} toi_job;

static cdist_status toi_entry(cdist_query *q, const void *ctx, size_t i)
{
    const toi_job *j = ctx;
    const void *mai = j->ma ? j->ma + (ptrdiff_t)i * j->ma_stride : NULL;
    const void *mbi = j->mb ? j->mb + (ptrdiff_t)i * j->mb_stride : NULL;
    return cdist_toi(q, (const void *)(j->a + (ptrdiff_t)i * j->a_stride), mai,
                     (const void *)(j->b + (ptrdiff_t)i * j->b_stride), mbi, j->target, j->tolerance,
                     j->max_iterations, &j->out[i]);
}

cdist_status cdist_toi_batch(cdist_query *q, size_t n, const cdist_shape *a, ptrdiff_t a_stride,
                             const cdist_motion *ma, ptrdiff_t ma_stride, const cdist_shape *b, ptrdiff_t b_stride,
                             const cdist_motion *mb, ptrdiff_t mb_stride, double target, double tolerance,
                             int max_iterations, cdist_toi_result *out, cdist_status *statuses)
{
    if (n == 0) return CDIST_OK;
    cdist__span in[4] = {cdist__span_of(a, n, a_stride, sizeof *a, "first shape array"),
                         cdist__span_of(ma, n, ma_stride, sizeof *ma, ma ? "first motion array" : NULL),
                         cdist__span_of(b, n, b_stride, sizeof *b, "second shape array"),
                         cdist__span_of(mb, n, mb_stride, sizeof *mb, mb ? "second motion array" : NULL)};
    cdist_status st = cdist__topology_begin(q, n, q && a && b && out, out, sizeof *out, toi_set_error, statuses,
                                            "a handle, shape array or output array is NULL", in, 4);
    if (st) return st;
    toi_job job = {(const char *)a, (const char *)ma, (const char *)b, (const char *)mb, a_stride, ma_stride,
                   b_stride, mb_stride, target, tolerance, max_iterations, out};
    return cdist__topology_run(q, n, toi_entry, &job, statuses);
}
