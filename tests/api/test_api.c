/* SPDX-License-Identifier: MIT */
/* API contract: version, status names, handle options, NULL handling and bad input. */
#include <string.h>

#include "check.h"

static void version(void)
{
    CHECK(cdist_version_number() == CDIST_VERSION_NUMBER, "runtime and compile-time version agree");
    CHECK(strcmp(cdist_version_string(), CDIST_VERSION_STRING) == 0, "version string");
    CHECK(cdist_version_major() == CDIST_VERSION_MAJOR && cdist_version_minor() == CDIST_VERSION_MINOR &&
              cdist_version_patch() == CDIST_VERSION_PATCH,
          "version parts");
    CHECK(cdist_result_size() == sizeof(cdist_result), "result size");
    CHECK(cdist_pair_size() == sizeof(cdist_pair), "pair size");
    CHECK(strcmp(cdist_status_name(CDIST_OK), "CDIST_OK") == 0, "status name");
    CHECK(strcmp(cdist_status_name(CDIST_ERR_BAD_KIND), "CDIST_ERR_BAD_KIND") == 0, "last status name");
    CHECK(strcmp(cdist_status_name((cdist_status)999), "CDIST_UNKNOWN") == 0, "unknown name");
    CHECK(strcmp(cdist_status_string((cdist_status)-1), "unknown status") == 0, "unknown text");
    for (int s = 0; s <= CDIST_ERR_BAD_KIND; s++)
        CHECK(strlen(cdist_status_string((cdist_status)s)) > 5, "status %d has text", s);
}

static void handle(void)
{
    cdist_query_free(NULL);
    CHECK(cdist_query_set_method(NULL, CDIST_METHOD_ROBUST) == CDIST_ERR_NULL_ARGUMENT, "set_method NULL");
    CHECK(cdist_query_get_method(NULL) == CDIST_METHOD_AUTO, "get_method NULL");
    CHECK(strlen(cdist_query_last_error(NULL)) > 0, "last_error NULL");
    cdist_query *q = cdist_query_new();
    CHECK(cdist_query_get_method(q) == CDIST_METHOD_AUTO, "default method");
    CHECK(cdist_query_set_method(q, (cdist_method)7) == CDIST_ERR_BAD_OPTION, "bad method");
    CHECK(strstr(cdist_query_last_error(q), "method") != NULL, "message names the method");
    CHECK(cdist_query_last_status(q) == CDIST_ERR_BAD_OPTION, "last status");
    CHECK(cdist_query_set_method(q, CDIST_METHOD_ITERATION) == CDIST_OK, "set method");
    CHECK(cdist_query_get_method(q) == CDIST_METHOD_ITERATION, "get method");
    CHECK(cdist_query_last_error(q)[0] == '\0', "message cleared on success");
    CHECK(cdist_query_get_unit_tolerance(q) == 1e-6, "default unit tolerance");
    CHECK(cdist_query_set_unit_tolerance(q, -1) == CDIST_ERR_BAD_OPTION, "negative tolerance");
    CHECK(cdist_query_set_unit_tolerance(q, NAN) == CDIST_ERR_BAD_OPTION, "NaN tolerance");
    CHECK(cdist_query_get_curve_samples(q) == 512, "default samples");
    CHECK(cdist_query_set_curve_samples(q, 3) == CDIST_ERR_BAD_OPTION, "too few samples");
    CHECK(cdist_query_set_curve_samples(q, 4096) == CDIST_OK && cdist_query_get_curve_samples(q) == 4096,
          "more samples");
    CHECK(cdist_query_set_max_iterations(q, 0) == CDIST_ERR_BAD_OPTION, "zero iterations");
    CHECK(cdist_query_get_max_iterations(q) == 200, "default iterations");
    cdist_query_free(q);
}

static void bad_input(void)
{
    cdist_query *q = cdist_query_new();
    cdist_result r;
    cdist_circle c = {tv(0, 0, 0), tv(0, 0, 1), 1};
    cdist_vec3 p = tv(1, 2, 3);
    CHECK(cdist_point_circle(NULL, &p, &c, &r) == CDIST_ERR_NULL_ARGUMENT, "NULL handle");
    CHECK(isnan(r.distance) && r.num_pairs == 0, "error result is NaN with no pairs");
    CHECK(cdist_point_circle(q, NULL, &c, &r) == CDIST_ERR_NULL_ARGUMENT, "NULL point");
    CHECK(strstr(cdist_query_last_error(q), "point") != NULL, "message: %s", cdist_query_last_error(q));
    CHECK(cdist_point_circle(q, &p, NULL, &r) == CDIST_ERR_NULL_ARGUMENT, "NULL circle");
    CHECK(cdist_point_circle(q, &p, &c, NULL) == CDIST_ERR_NULL_ARGUMENT, "NULL result");
    cdist_vec3 bad = tv(NAN, 0, 0);
    CHECK(cdist_point_circle(q, &bad, &c, &r) == CDIST_ERR_NOT_FINITE, "NaN point");
    bad = tv(0, INFINITY, 0);
    CHECK(cdist_point_disk(q, &bad, &c, &r) == CDIST_ERR_NOT_FINITE, "Inf point");
    bad = tv(0, 0, 1e200);
    CHECK(cdist_point_disk(q, &bad, &c, &r) == CDIST_ERR_OUT_OF_RANGE, "huge point");
    cdist_circle b = c;
    b.normal = tv(0, 0, 0);
    CHECK(cdist_point_circle(q, &p, &b, &r) == CDIST_ERR_ZERO_VECTOR, "zero normal");
    CHECK(strstr(cdist_query_last_error(q), "normal") != NULL, "message: %s", cdist_query_last_error(q));
    b.normal = tv(0, 0.6, 0.6);
    CHECK(cdist_point_circle(q, &p, &b, &r) == CDIST_ERR_NOT_UNIT, "non-unit normal");
    b.normal = tv(0, NAN, 1);
    CHECK(cdist_point_circle(q, &p, &b, &r) == CDIST_ERR_NOT_FINITE, "NaN normal");
    b = c;
    b.radius = -1;
    CHECK(cdist_point_circle(q, &p, &b, &r) == CDIST_ERR_NEGATIVE_RADIUS, "negative radius");
    CHECK(strstr(cdist_query_last_error(q), "radius") != NULL, "message: %s", cdist_query_last_error(q));
    b.radius = NAN;
    CHECK(cdist_point_disk(q, &p, &b, &r) == CDIST_ERR_NOT_FINITE, "NaN radius");
    b.radius = INFINITY;
    CHECK(cdist_point_disk(q, &p, &b, &r) == CDIST_ERR_NOT_FINITE, "Inf radius");
    /* The handle recovers after an error. */
    CHECK(cdist_point_circle(q, &p, &c, &r) == CDIST_OK && cdist_query_last_error(q)[0] == '\0', "recovers");
    /* Circle frame helpers. */
    cdist_vec3 u, v;
    CHECK(cdist_circle_basis(NULL, &u, &v) == CDIST_ERR_NULL_ARGUMENT, "basis NULL");
    CHECK(cdist_circle_basis(&b, &u, &v) == CDIST_OK, "basis ignores radius");
    b.normal = tv(0, 0, 0);
    CHECK(cdist_circle_basis(&b, &u, &v) == CDIST_ERR_ZERO_VECTOR, "basis zero normal");
    CHECK(cdist_circle_point(&c, NAN, &u) == CDIST_ERR_NOT_FINITE, "circle_point NaN angle");
    cdist_query_free(q);
}

static void basis_rule(void)
{
    /* The documented rule: k = smallest |n_k| (first on ties), u = normalise(e_k - n_k n), v = n x u. */
    cdist_circle c = {tv(0, 0, 0), tv(0, 0, 1), 1};
    cdist_vec3 u, v;
    cdist_circle_basis(&c, &u, &v);
    CHECK(u.x == 1 && u.y == 0 && u.z == 0 && v.x == 0 && v.y == 1 && v.z == 0, "z normal basis");
    c.normal = tv(0.6, 0, 0.8);
    cdist_circle_basis(&c, &u, &v);
    CHECK(fabs(u.x) < 1e-16 && fabs(u.y - 1) < 1e-16, "k = y: u = e_y");
    for (int i = 0; i < 200; i++) {
        c.normal = rand_unit();
        cdist_circle_basis(&c, &u, &v);
        cdist_vec3 n = c.normal;
        double du = u.x * n.x + u.y * n.y + u.z * n.z, dv = v.x * n.x + v.y * n.y + v.z * n.z;
        double uv = u.x * v.x + u.y * v.y + u.z * v.z;
        /* right-handed: u x v = n */
        cdist_vec3 w = tv(u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x);
        CHECK(fabs(du) < 1e-15 && fabs(dv) < 1e-15 && fabs(uv) < 1e-15 && tdist(w, n) < 1e-15, "orthonormal");
    }
}

int main(void)
{
    version();
    handle();
    bad_input();
    basis_rule();
    return check_summary("test_api");
}
