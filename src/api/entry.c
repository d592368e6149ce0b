/* SPDX-License-Identifier: MIT */
/* The one entry path of the public queries (declarations and the protocol in api-priv.h). */
#include <math.h>
#include <string.h>

#include "api/api-priv.h"

cdist__span cdist__span_of(const void *p, size_t n, ptrdiff_t stride, size_t size, const char *what)
{
    uintptr_t base = (uintptr_t)p;
    uintptr_t last = base + (uintptr_t)((ptrdiff_t)(n - 1) * stride); /* wraps back for a negative stride */
    cdist__span s = {stride < 0 ? last : base, (stride < 0 ? base : last) + size, what};
    return s;
}

int cdist__spans_overlap(const cdist__span *s, int count, int n_inputs, const char **x, const char **y)
{
    for (int i = n_inputs; i < count; i++) {
        if (!s[i].what) continue;
        for (int j = 0; j < i; j++) {
            if (!s[j].what || !(s[i].lo < s[j].hi && s[j].lo < s[i].hi)) continue;
            *x = s[i].what;
            *y = s[j].what;
            return 1;
        }
    }
    return 0;
}

void cdist__result_swap(cdist_result *r)
{
    for (int i = 0; i < r->num_pairs; i++) {
        vec3 p = r->pairs[i].point[0];
        r->pairs[i].point[0] = r->pairs[i].point[1];
        r->pairs[i].point[1] = p;
        double t = r->pairs[i].param[0];
        r->pairs[i].param[0] = r->pairs[i].param[1];
        r->pairs[i].param[1] = t;
    }
}

void cdist__result_set_error(cdist_result *r)
{
    memset(r, 0, sizeof *r);
    r->distance = NAN;
    r->sqr_distance = NAN;
    for (int i = 0; i < 2; i++) {
        for (int k = 0; k < 2; k++) {
            r->pairs[i].point[k] = v3(NAN, NAN, NAN);
            r->pairs[i].param[k] = NAN;
        }
    }
}

cdist_status cdist__enter_slow(cdist_query *q, cdist_result *r)
{
    if (r) cdist__result_set_error(r);
    if (!q) return CDIST_ERR_NULL_ARGUMENT;
    if (r) return CDIST_ERR_HANDLE_BUSY; /* the fast path failed only on the flag */
    /* r is NULL: report it on the handle, if the handle is ours to write. */
    if (atomic_exchange_explicit(&q->busy, 1, memory_order_acquire)) return CDIST_ERR_HANDLE_BUSY;
    cdist_status st = cdist__fail(q, CDIST_ERR_NULL_ARGUMENT, "result pointer is NULL");
    atomic_store_explicit(&q->busy, 0, memory_order_release);
    return st;
}

cdist_status cdist__leave_slow(cdist_query *q, cdist_result *r, cdist_status st)
{
    if (st == CDIST_OK) {
        /* Final guard: a core that produced a non-finite distance is an internal failure. */
        st = cdist__fail(q, CDIST_ERR_INTERNAL, "internal failure: the distance came out %g", r->distance);
    }
    cdist__result_set_error(r);
    q->last_status = st;
    atomic_store_explicit(&q->busy, 0, memory_order_release);
    return st;
}

cdist_status cdist__enter_setter(cdist_query *q)
{
    if (!q) return CDIST_ERR_NULL_ARGUMENT;
    if (atomic_exchange_explicit(&q->busy, 1, memory_order_acquire)) return CDIST_ERR_HANDLE_BUSY;
    return CDIST_OK;
}

void cdist__leave_setter(cdist_query *q) { atomic_store_explicit(&q->busy, 0, memory_order_release); }
