/* SPDX-License-Identifier: MIT */
/* Swept and gradient queries respect the handle's in-use flag: with the flag set by hand (as if
 * another thread were inside) every call returns CDIST_ERR_HANDLE_BUSY, puts its outputs in the
 * error state and leaves the handle's status and message untouched; afterwards the flag is free
 * again after successes and failures. Built against the internal library. */
#include <math.h>
#include <stdatomic.h>
#include <string.h>

#include "check.h"
#include "internal.h"

static int contact_is_error(const cdist_contact *c) { return isnan(c->distance) && c->num_pairs == 0; }

int main(void)
{
    cdist_query *q = cdist_query_new();
    cdist_contact c;
    cdist_result r;
    cdist_grad g;
    cdist_sphere s0 = {{0, 0, 0}, 0.5}, s1 = {{3, 0, 0}, 0.5}, bad = {{0, 0, 0}, -1};
    cdist_capsule k0 = {{{0, 0, 0}, {1, 0, 0}}, 0.1}, k1 = {{{0, 1, 0}, {1, 1, 1}}, 0.1};
    cdist_torus t0 = {{{0, 0, 0}, {0, 0, 1}, 1}, 0.1}, t1 = {{{0, 0, 3}, {1, 0, 0}, 1}, 0.1};
    cdist_vec3 p = {0, 0, 2};
    cdist_circle ci = {{0, 0, 0}, {0, 0, 1}, 1};

    /* a known failure on the handle */
    CHECK(cdist_sphere_sphere(q, &s0, &bad, &c) == CDIST_ERR_NEGATIVE_RADIUS, "setup failure");
    char before[CD_MESSAGE_LEN];
    strcpy(before, cdist_query_last_error(q));

    atomic_store(&q->busy, 1); /* as if another thread were inside */
#define BUSY_CONTACT(call, what)                                                                               \
    do {                                                                                                       \
        c.distance = 1.0;                                                                                      \
        c.num_pairs = 1;                                                                                       \
        CHECK((call) == CDIST_ERR_HANDLE_BUSY && contact_is_error(&c), "busy %s", what);                    \
    } while (0)
    BUSY_CONTACT(cdist_sphere_sphere(q, &s0, &s1, &c), "sphere-sphere (point-point core)");
    BUSY_CONTACT(cdist_capsule_sphere(q, &k0, &s1, &c), "capsule-sphere (point-segment core)");
    BUSY_CONTACT(cdist_capsule_capsule(q, &k0, &k1, &c), "capsule-capsule (segment-segment core)");
    BUSY_CONTACT(cdist_torus_torus(q, &t0, &t1, &c), "torus-torus (public core)");
    BUSY_CONTACT(cdist_sphere_sphere(q, &s0, &bad, &c), "invalid radius");
    BUSY_CONTACT(cdist_sphere_sphere(q, &s0, NULL, &c), "NULL object");
    CHECK(cdist_sphere_sphere(q, &s0, &s1, NULL) == CDIST_ERR_HANDLE_BUSY, "busy NULL contact");
    BUSY_CONTACT(cdist_capsule_capsule_grad(q, &k0, &k1, &c, &g), "capsule-capsule gradient");
    CHECK(isnan(g.obj[0].d_p0.x), "busy gradient in the error state");
    BUSY_CONTACT(cdist_sphere_sphere_grad(q, &s0, &s1, &c, NULL), "NULL gradient");
    r.distance = 1.0;
    r.num_pairs = 1;
    CHECK(cdist_point_circle_grad(q, &p, &ci, &r, &g) == CDIST_ERR_HANDLE_BUSY && isnan(r.distance) &&
              r.num_pairs == 0,
          "busy point-circle gradient");
    CHECK(cdist_point_circle_grad(q, &p, &ci, NULL, &g) == CDIST_ERR_HANDLE_BUSY, "busy gradient, NULL result");
    CHECK(cdist_point_circle_grad(q, &p, &ci, &r, NULL) == CDIST_ERR_HANDLE_BUSY, "busy gradient, NULL gradient");
    CHECK(cdist_query_last_status(q) == CDIST_ERR_NEGATIVE_RADIUS && !strcmp(cdist_query_last_error(q), before),
          "the busy calls touched the handle: %d '%s'", (int)cdist_query_last_status(q), cdist_query_last_error(q));
    atomic_store(&q->busy, 0);

    /* free again: successes and failures release the flag */
    CHECK(cdist_sphere_sphere(q, &s0, &s1, &c) == CDIST_OK && c.distance == 2.0, "sphere-sphere %.17g", c.distance);
    CHECK(cdist_query_last_status(q) == CDIST_OK && atomic_load(&q->busy) == 0, "released after success");
    CHECK(cdist_capsule_capsule(q, &k0, &k1, &c) == CDIST_OK && fabs(c.distance - 0.8) < 1e-15,
          "capsule-capsule %.17g", c.distance);
    CHECK(cdist_capsule_sphere(q, &k0, &s1, &c) == CDIST_OK && c.distance == 1.4, "capsule-sphere %.17g", c.distance);
    CHECK(atomic_load(&q->busy) == 0, "released after the closed-form cores");
    CHECK(cdist_sphere_sphere(q, &s0, &bad, &c) == CDIST_ERR_NEGATIVE_RADIUS && atomic_load(&q->busy) == 0,
          "released after a radius failure");
    CHECK(cdist_capsule_capsule(q, &k0, &(cdist_capsule){{{NAN, 0, 0}, {1, 0, 0}}, 0}, &c) == CDIST_ERR_NOT_FINITE &&
              atomic_load(&q->busy) == 0 && contact_is_error(&c),
          "released after a core validation failure");
    CHECK(cdist_point_circle_grad(q, &p, &ci, NULL, &g) == CDIST_ERR_NULL_ARGUMENT && atomic_load(&q->busy) == 0 &&
              cdist_query_last_status(q) == CDIST_ERR_NULL_ARGUMENT,
          "NULL result reported and released");
    CHECK(cdist_torus_torus_grad(q, &t0, &t1, &c, &g) == CDIST_OK && atomic_load(&q->busy) == 0, "torus gradient");
    cdist_query_free(q);
    return check_summary("swept-busy");
}
