/* SPDX-License-Identifier: MIT */
/* Linking number of two circles and of two tori. The circle-circle distance d (the library's own
 * query) bounds every error the classification can afford: a crossing of one circle through the
 * other's disk lies at least d from that disk's rim, so a computation whose error is below d
 * counts the crossings exactly (link_core.h). It runs in double first and, when its error bound
 * does not settle a decision, in extended precision; pairs closer than CD_LINK_TOUCH_REL * L are
 * reported touching. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "internal.h"
#include "topology/topology-priv.h"

#define LK_UNDECIDED 2

#define LK_REAL double
#define LK_SQRT sqrt
#define LK_U 0x1p-53
#define LK_FN link_core_double
#include "link_core.h"

/* The extended type: binary128 where the compiler has it (software arithmetic from libgcc, no
 * libquadmath: its square root is two Newton steps from the double one), else long double. */
#if defined(__SIZEOF_FLOAT128__) && !defined(CD_NO_FLOAT128)
typedef __float128 link_xreal;
#define LINK_XREAL_U 0x1p-113
static link_xreal xsqrt(link_xreal x)
{
    if (!(x > 0)) return 0;
    link_xreal y = sqrt((double)x);
    y = 0.5 * (y + x / y);
    return 0.5 * (y + x / y);
}
#else
typedef long double link_xreal;
#define LINK_XREAL_U (LDBL_EPSILON / 2)
static link_xreal xsqrt(link_xreal x) { return x > 0 ? sqrtl(x) : 0; }
#endif

#define LK_REAL link_xreal
#define LK_SQRT xsqrt
#define LK_U ((double)LINK_XREAL_U)
#define LK_FN link_core_extended
#include "link_core.h"

size_t cdist_link_size(void) { return sizeof(cdist_link); }

static void link_set_error(void *link)
{
    cdist_link *out = memset(link, 0, sizeof(cdist_link));
    out->linking = out->core_linking = CDIST_LINK_ERROR;
    out->distance = out->core_distance = out->scale = NAN;
}

int cdist__link_count(const cdist__circle *a, const cdist__circle *b, double d, int extended)
{
    vec3 w = v_sub(b->c, a->c);
    double L = fmax(fmax(a->r, b->r), v_norm(w));
    /* Work at scale [1, 2): the power of two is exact. */
    double down = cdist__pow2(-cdist__scale_exponent(L));
    double ws[3] = {down * w.x, down * w.y, down * w.z};
    double na[3] = {a->n.x, a->n.y, a->n.z}, nb[3] = {b->n.x, b->n.y, b->n.z};
    double ra = down * a->r, rb = down * b->r;
    double d_low = down * d - CD_LINK_DIST_REL * (down * L);
    int v = extended ? link_core_extended(na, nb, ws, ra, rb, d_low) : link_core_double(na, nb, ws, ra, rb, d_low);
    return v == LK_UNDECIDED ? CDIST_LINK_TOUCHING : v;
}

/* The classification of two validated circles at certified distance d (caller's units). */
static void classify(const cdist__circle *a, const cdist__circle *b, double d, cdist_link *out)
{
    double L = fmax(fmax(a->r, b->r), v_dist(b->c, a->c));
    out->scale = L;
    out->distance = d;
    out->core_distance = d;
    int v = CDIST_LINK_TOUCHING;
    if (d > CD_LINK_TOUCH_REL * L) {
        v = cdist__link_count(a, b, d, 0);
        if (v == CDIST_LINK_TOUCHING) {
            out->flags |= CDIST_LINK_FLAG_EXTENDED;
            v = cdist__link_count(a, b, d, 1);
            if (v == CDIST_LINK_TOUCHING) out->flags |= CDIST_LINK_FLAG_UNRESOLVED;
        }
    }
    out->linking = out->core_linking = v;
}

/* Validation under the handle's flag, then the distance query (which takes the flag itself). */
static cdist_status link_circles(cdist_query *q, const cdist_circle *a, const cdist_circle *b, double ra_swept,
                                 double rb_swept, int tori, cdist_link *out)
{
    cdist_result r;
    if (out) link_set_error(out);
    cdist_status st = cdist__enter(q, &r);
    if (st) return st;
    cdist__circle ca, cb;
    if (!out) st = cdist__fail(q, CDIST_ERR_NULL_ARGUMENT, "link result pointer is NULL");
    else if (!(st = cdist__check_circle(q, a, tori ? "first torus's circle" : "first circle", &ca)))
        st = cdist__check_circle(q, b, tori ? "second torus's circle" : "second circle", &cb);
    if (!st && tori) {
        const double rs[2] = {ra_swept, rb_swept};
        for (int k = 0; k < 2 && !st; k++)
            st = cdist__check_radius(q, rs[k], k ? "second torus's tube radius" : "first torus's tube radius");
    }
    if (st) return cdist__leave(q, &r, st, CDIST_METHOD_AUTO);
    /* The certificate rests on the distance: AUTO, the library's certified choice, whatever
     * method the handle has (restored afterwards). */
    cdist_method method = q->method;
    q->method = CDIST_METHOD_AUTO;
    cdist__leave_setter(q);
    st = cdist_circle_circle(q, a, b, &r);
    if (!cdist__enter_setter(q)) {
        q->method = method;
        cdist__leave_setter(q);
    }
    if (st) return st;
    out->flags = 0;
    classify(&ca, &cb, r.distance, out);
    if (tori) {
        double rs = ra_swept + rb_swept;
        out->distance = r.distance - rs;
        if (rs > 0.0 && !(out->distance > 0.0)) out->linking = CDIST_LINK_OVERLAP;
    }
    return CDIST_OK;
}

cdist_status cdist_link_circles(cdist_query *q, const cdist_circle *a, const cdist_circle *b, cdist_link *out)
{
    return link_circles(q, a, b, 0.0, 0.0, 0, out);
}

cdist_status cdist_link_tori(cdist_query *q, const cdist_torus *a, const cdist_torus *b, cdist_link *out)
{
    return link_circles(q, a ? &a->circle : NULL, b ? &b->circle : NULL, a ? a->tube_radius : 0.0,
                        b ? b->tube_radius : 0.0, 1, out);
}

/* ---- batches: one entry at a time on the calling thread, the lowest failing entry reported ---- */

typedef struct link_job {
    int tori;
    const char *a, *b;
    ptrdiff_t a_stride, b_stride;
    cdist_link *out;
} link_job;

static cdist_status link_entry(cdist_query *q, const void *ctx, size_t i)
{
    const link_job *j = ctx;
    const void *a = j->a + (ptrdiff_t)i * j->a_stride, *b = j->b + (ptrdiff_t)i * j->b_stride;
    return j->tori ? cdist_link_tori(q, a, b, &j->out[i]) : cdist_link_circles(q, a, b, &j->out[i]);
}

static cdist_status link_batch(cdist_query *q, int tori, size_t n, const void *a, ptrdiff_t a_stride,
                               const void *b, ptrdiff_t b_stride, cdist_link *out, cdist_status *statuses)
{
    if (n == 0) return CDIST_OK;
    size_t size = tori ? sizeof(cdist_torus) : sizeof(cdist_circle);
    cdist__span in[2] = {cdist__span_of(a, n, a_stride, size, "first object array"),
                         cdist__span_of(b, n, b_stride, size, "second object array")};
    cdist_status st = cdist__topology_begin(q, n, q && a && b && out, out, sizeof *out, link_set_error, statuses,
                                            "a handle, object array or output array is NULL", in, 2);
    if (st) return st;
    link_job job = {tori, a, b, a_stride, b_stride, out};
    return cdist__topology_run(q, n, link_entry, &job, statuses);
}

cdist_status cdist__topology_begin(cdist_query *q, size_t n, int args_ok, void *out, size_t out_size,
                                   void (*set_error)(void *), cdist_status *statuses, const char *missing,
                                   const cdist__span *in, int n_in)
{
    if (!args_ok) {
        for (size_t i = 0; i < n; i++) {
            if (out) set_error((char *)out + i * out_size);
            if (statuses) statuses[i] = CDIST_ERR_NULL_ARGUMENT;
        }
        return cdist__topology_batch_report(q, SIZE_MAX, CDIST_ERR_NULL_ARGUMENT, missing);
    }
    cdist__span s[8];
    memcpy(s, in, (size_t)n_in * sizeof *s);
    s[n_in] = cdist__span_of(out, n, (ptrdiff_t)out_size, out_size, "results");
    s[n_in + 1] = cdist__span_of(statuses, n, sizeof *statuses, sizeof *statuses, statuses ? "statuses" : NULL);
    const char *x, *y;
    if (!cdist__spans_overlap(s, n_in + 2, n_in, &x, &y)) return CDIST_OK;
    char why[200];
    snprintf(why, sizeof why, CDIST__OVERLAP_MESSAGE, x, y);
    return cdist__topology_batch_report(q, SIZE_MAX, CDIST_ERR_OVERLAP, why);
}

cdist_status cdist__topology_run(cdist_query *q, size_t n, cdist_status (*entry)(cdist_query *, const void *, size_t),
                                 const void *ctx, cdist_status *statuses)
{
    size_t first = SIZE_MAX; /* the lowest failing entry, its status and message */
    cdist_status fail = CDIST_OK;
    char message[CD_MESSAGE_LEN] = "";
    for (size_t i = 0; i < n; i++) {
        cdist_status st = entry(q, ctx, i);
        if (statuses) statuses[i] = st;
        if (st && first == SIZE_MAX) {
            first = i;
            fail = st;
            if (st != CDIST_ERR_HANDLE_BUSY) memcpy(message, q->message, sizeof message);
        }
    }
    if (first == SIZE_MAX) return CDIST_OK;
    if (fail == CDIST_ERR_HANDLE_BUSY) return fail;
    return cdist__topology_batch_report(q, first, fail, message);
}

cdist_status cdist__topology_batch_report(cdist_query *q, size_t first, cdist_status st, const char *message)
{
    if (!q || cdist__enter_setter(q)) return st;
    if (first == SIZE_MAX) cdist__fail(q, st, "%s", message);
    else cdist__fail(q, st, "entry %zu: %s", first, message);
    cdist__leave_setter(q);
    return st;
}

cdist_status cdist_link_circles_batch(cdist_query *q, size_t n, const void *a, ptrdiff_t a_stride, const void *b,
                                      ptrdiff_t b_stride, cdist_link *out, cdist_status *statuses)
{
    return link_batch(q, 0, n, a, a_stride, b, b_stride, out, statuses);
}

cdist_status cdist_link_tori_batch(cdist_query *q, size_t n, const void *a, ptrdiff_t a_stride, const void *b,
                                   ptrdiff_t b_stride, cdist_link *out, cdist_status *statuses)
{
    return link_batch(q, 1, n, a, a_stride, b, b_stride, out, statuses);
}
