/* Circle to circle: public entry points, method dispatch, and the robust method. */
#include <math.h>
#include <stdio.h>

#include "internal.h"

/* Robust method (distance-to-circles-3d §3 with the circle as the curve): bound the roots of
 * F'(theta), bisect each bracket, compare all minima. TODO(circle_circle branch). */
static cdist_status cc_robust(cdist_query *q, const cd_circle *c0, const cd_circle *c1, cd_best *b)
{
    (void)c0; (void)c1; (void)b;
    return cd_fail(q, CDIST_ERR_INTERNAL, "circle-circle robust method is not implemented yet");
}

cdist_status cd_circle_circle_core(cdist_query *q, cdist_method method, const cd_circle *c0, const cd_circle *c1,
                                   cd_best *b, int *iterations)
{
    if (iterations) *iterations = 0;
    cdist_status st = CDIST_ERR_INTERNAL;
    if (method == CDIST_METHOD_POLYNOMIAL) st = cd_cc_polynomial(q, c0, c1, b);
    else if (method == CDIST_METHOD_ITERATION) st = cd_cc_iteration(q, c0, c1, b, iterations);
    if (method == CDIST_METHOD_ROBUST || st != CDIST_OK) {
        /* The robust method answers every configuration; it is also the fallback. */
        cd_best_init(b, b->scale);
        st = cc_robust(q, c0, c1, b);
    }
    return st;
}

int cd_circle_circle_critical(cdist_query *q, const cd_circle *c0, const cd_circle *c1, double *theta0, int cap)
{
    (void)q; (void)c0; (void)c1; (void)theta0; (void)cap;
    return 0; /* TODO(circle_circle branch) */
}

cdist_status cdist_circle_circle(cdist_query *q, const cdist_circle *c0, const cdist_circle *c1, cdist_result *r)
{
    cdist_status st = cd_check_handle(q, r);
    if (st) return st;
    cd_circle a, b;
    if ((st = cd_check_circle(q, c0, "first circle", &a)) || (st = cd_check_circle(q, c1, "second circle", &b)))
        return st;
    /* Work relative to the first centre. */
    vec3 offset = a.c;
    a.c = v3(0, 0, 0);
    b.c = v_sub(b.c, offset);
    cd_best best;
    cd_best_init(&best, fmax(fmax(a.r, b.r), v_norm(b.c)));
    cdist_method m = cd_pick_method(q, CD_HAS(CDIST_METHOD_POLYNOMIAL) | CD_HAS(CDIST_METHOD_ROBUST) |
                                           CD_HAS(CDIST_METHOD_ITERATION),
                                    CDIST_METHOD_ROBUST);
    int iterations = 0;
    st = cd_circle_circle_core(q, m, &a, &b, &best, &iterations);
    if (st) return st;
    cd_best_to_result(&best, offset, 0, r);
    r->iterations = iterations;
    return cd_ok(q, r, m);
}

cdist_status cdist_circle_circle_batch(cdist_query *q, size_t n, const cdist_circle *c0, const cdist_circle *c1,
                                       cdist_result *results, cdist_status *statuses)
{
    if (!q) return CDIST_ERR_NULL_ARGUMENT;
    if (n == 0) return cd_ok(q, &(cdist_result){0}, q->method);
    if (!c0 || !c1 || !results)
        return cd_fail(q, CDIST_ERR_NULL_ARGUMENT, "batch: circles or results pointer is NULL");
    cdist_status first = CDIST_OK;
    char first_msg[CD_MESSAGE_LEN] = "";
    for (size_t i = 0; i < n; i++) {
        cdist_status st = cdist_circle_circle(q, &c0[i], &c1[i], &results[i]);
        if (statuses) statuses[i] = st;
        if (st != CDIST_OK && first == CDIST_OK) {
            first = st;
            snprintf(first_msg, sizeof first_msg, "batch entry %zu: %.200s", i, q->message);
        }
    }
    if (first != CDIST_OK) return cd_fail(q, first, "%s", first_msg);
    return first;
}
