/* SPDX-License-Identifier: MIT */
/* Point-circle and point-disk (Eberly, distance-to-circles-3d §2; point-curve-circle-to-disk §2).
 * Work relative to the centre; the distance to the axis is |N x D| (accurate near the axis, where
 * sqrt(|D|^2 - h^2) would cancel). */
#include <math.h>

#include "internal.h"

/* Split p (relative to the centre) into height h along n, in-plane part w and axis distance rho. */
static void split(vec3 p, const cd_circle *c, double *h, vec3 *w, double *rho)
{
    /* w = (n x p) x n is the in-plane part; built from the cross product it stays in the plane
     * and keeps its direction accurate even within a few ulps of the axis, where p - h n
     * would cancel. */
    vec3 np = v_cross(c->n, p);
    *h = v_dot(c->n, p);
    *w = v_cross(np, c->n);
    *rho = v_norm(np);
}

/* The point is on the axis when its axis distance is below the rounding noise of |N x D|. */
static int on_axis(vec3 p, double rho) { return rho <= 2.0 * DBL_EPSILON * v_norm(p); }

void cd_point_circle_core(vec3 p, const cd_circle *c, cd_best *b, int swap)
{
    double h, rho;
    vec3 w;
    split(p, c, &h, &w, &rho);
    vec3 k;
    double ang;
    int equi = 0;
    if (c->r == 0.0) {
        k = v3(0, 0, 0);
        ang = NAN;
    } else if (on_axis(p, rho)) {
        /* Every circle point is closest; angle 0 is the representative. */
        k = v_scale(c->r, c->u);
        ang = 0.0;
        equi = 1;
    } else {
        double wn = v_norm(w);
        k = v_scale(c->r / wn, w);
        ang = cd_circle_angle(c, w);
    }
    double dr = rho - c->r;
    double d2 = fma(dr, dr, h * h);
    if (swap) cd_best_offer_flag(b, equi, d2, k, p, ang, NAN);
    else cd_best_offer_flag(b, equi, d2, p, k, NAN, ang);
}

void cd_point_disk_core(vec3 p, const cd_circle *c, cd_best *b, int swap)
{
    double h, rho;
    vec3 w;
    split(p, c, &h, &w, &rho);
    if (rho > c->r) {
        cd_point_circle_core(p, c, b, swap);
        return;
    }
    double ang = on_axis(p, rho) ? NAN : cd_circle_angle(c, w);
    vec3 k = on_axis(p, rho) ? v3(0, 0, 0) : w;
    double d2 = h * h;
    if (swap) cd_best_offer(b, d2, k, p, ang, NAN);
    else cd_best_offer(b, d2, p, k, NAN, ang);
}

typedef void (*point_core_fn)(vec3, const cd_circle *, cd_best *, int);

static cdist_status point_query(cdist_query *q, const cdist_vec3 *p, const cdist_circle *c, cdist_result *r,
                                const char *what, point_core_fn core)
{
    cdist_status st = cd_check_handle(q, r);
    if (st) return st;
    cd_circle cc;
    if ((st = cd_check_point(q, p, "point")) || (st = cd_check_circle(q, c, what, &cc))) return st;
    vec3 rel = v_sub(*p, cc.c);
    cd_best b;
    cd_best_init(&b, fmax(cc.r, v_norm(rel)));
    core(rel, &cc, &b, 0);
    cd_best_to_result(&b, cc.c, 0, r);
    r->pairs[0].point[0] = *p; /* exactly the caller's point, not (p - C) + C */
    return cd_ok(q, r, CDIST_METHOD_AUTO);
}

cdist_status cdist_point_circle(cdist_query *q, const cdist_vec3 *p, const cdist_circle *c, cdist_result *r)
{
    return point_query(q, p, c, r, "circle", cd_point_circle_core);
}

cdist_status cdist_point_disk(cdist_query *q, const cdist_vec3 *p, const cdist_circle *d, cdist_result *r)
{
    return point_query(q, p, d, r, "disk", cd_point_disk_core);
}
