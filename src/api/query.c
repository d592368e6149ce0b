/* SPDX-License-Identifier: MIT */
/* The query handle, options, status strings, version, status recording, circle frames. */
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "api/api-priv.h"

/* ---- version ---- */

const char *cdist_version_string(void) { return CDIST_VERSION_STRING; }
unsigned cdist_version_number(void) { return CDIST_VERSION_NUMBER; }
int cdist_version_major(void) { return CDIST_VERSION_MAJOR; }
int cdist_version_minor(void) { return CDIST_VERSION_MINOR; }
int cdist_version_patch(void) { return CDIST_VERSION_PATCH; }

/* ---- status ---- */

static const struct {
    const char *name, *text;
} status_table[] = {
    {"CDIST_OK", "success"},
    {"CDIST_ERR_NULL_ARGUMENT", "a required pointer was NULL"},
    {"CDIST_ERR_NOT_FINITE", "an input number was NaN or infinite"},
    {"CDIST_ERR_ZERO_VECTOR", "a normal, direction or axis had zero length"},
    {"CDIST_ERR_NOT_UNIT", "a normal or direction was not unit length"},
    {"CDIST_ERR_NEGATIVE_RADIUS", "a radius was negative"},
    {"CDIST_ERR_OUT_OF_RANGE", "a coordinate or radius exceeded 1e150 in magnitude"},
    {"CDIST_ERR_BAD_OPTION", "an option value or method was not valid"},
    {"CDIST_ERR_BAD_INTERVAL", "a parameter interval was empty, reversed or too long"},
    {"CDIST_ERR_CALLBACK_FAILED", "a curve callback returned an error"},
    {"CDIST_ERR_CALLBACK_NOT_FINITE", "a curve callback returned NaN or infinity"},
    {"CDIST_ERR_NO_MEMORY", "memory allocation failed"},
    {"CDIST_ERR_INTERNAL", "internal numerical failure"},
    {"CDIST_ERR_HANDLE_BUSY", "the query handle was in use by another call"},
    {"CDIST_ERR_COST_LIMIT", "the query would exceed the cost limit"},
    {"CDIST_ERR_THREAD", "a worker thread could not be started"},
    {"CDIST_ERR_BAD_KIND", "the query kind was not valid"},
    {"CDIST_ERR_CANCELLED", "the entry was not answered: the progress callback stopped the batch"},
    {"CDIST_ERR_OVERLAP", "an output array overlapped an input or another output array"},
};
#define STATUS_COUNT (sizeof status_table / sizeof status_table[0])

const char *cdist_status_string(cdist_status st)
{
    return ((unsigned)st < STATUS_COUNT) ? status_table[st].text : "unknown status";
}

const char *cdist_status_name(cdist_status st)
{
    return ((unsigned)st < STATUS_COUNT) ? status_table[st].name : "CDIST_UNKNOWN";
}

const char *cdist_method_name(cdist_method method)
{
    static const char *const names[] = {"auto", "polynomial", "robust", "iteration"};
    return ((unsigned)method < sizeof names / sizeof names[0]) ? names[method] : "unknown";
}

size_t cdist_result_size(void) { return sizeof(cdist_result); }
size_t cdist_pair_size(void) { return sizeof(cdist_pair); }

/* ---- handle ---- */

cdist_query *cdist_query_new(void)
{
    cdist_query *q = calloc(1, sizeof *q);
    if (!q) return NULL;
    q->method = CDIST_METHOD_AUTO;
    q->unit_tol = CD_DEFAULT_UNIT_TOL;
    q->curve_samples = CD_DEFAULT_CURVE_SAMPLES;
    q->max_iterations = CD_DEFAULT_MAX_ITERATIONS;
    q->last_status = CDIST_OK;
    q->poly = cdist__poly_ws_new();
    q->scratch_len = CD_CURVE_SCRATCH_ARRAYS * ((size_t)CD_DEFAULT_CURVE_SAMPLES + 1);
    q->scratch = malloc(q->scratch_len * sizeof(double));
    if (!q->poly || !q->scratch) {
        cdist_query_free(q);
        return NULL;
    }
    return q;
}

void cdist_query_free(cdist_query *q)
{
    if (!q) return;
    cdist__workers_free(q->workers);
    cdist__poly_ws_free(q->poly);
    free(q->scratch);
    free(q);
}

cdist_status cdist__enter_option_setter(cdist_query *q)
{
    cdist_status st = cdist__enter_setter(q);
    if (st) return st;
    if (atomic_load_explicit(&q->batch_busy, memory_order_acquire)) {
        cdist__leave_setter(q);
        return CDIST_ERR_HANDLE_BUSY;
    }
    return CDIST_OK;
}

static cdist_status setter_ok(cdist_query *q)
{
    cdist_status st = cdist__workers_sync(q);
    if (st) return st;
    q->last_status = CDIST_OK;
    q->message[0] = '\0';
    return CDIST_OK;
}

static cdist_status query_set_method_locked(cdist_query *q, cdist_method method)
{
    if ((unsigned)method > CDIST_METHOD_ITERATION)
        return cdist__fail(q, CDIST_ERR_BAD_OPTION, "method %d is not a cdist_method (0..3)", (int)method);
    q->method = method;
    return setter_ok(q);
}

CD_OPTION_SETTER(cdist_query_set_method, cdist_method, query_set_method_locked)

cdist_method cdist_query_get_method(const cdist_query *q) { return q ? q->method : CDIST_METHOD_AUTO; }

static cdist_status query_set_unit_tolerance_locked(cdist_query *q, double tol)
{
    if (!(tol >= 0.0)) return cdist__fail(q, CDIST_ERR_BAD_OPTION, "unit tolerance must be >= 0 (got %g)", tol);
    q->unit_tol = tol;
    return setter_ok(q);
}

CD_OPTION_SETTER(cdist_query_set_unit_tolerance, double, query_set_unit_tolerance_locked)

double cdist_query_get_unit_tolerance(const cdist_query *q) { return q ? q->unit_tol : CD_DEFAULT_UNIT_TOL; }

static cdist_status query_set_curve_samples_locked(cdist_query *q, int samples)
{
    if (samples < 8 || samples > CD_MAX_CURVE_SAMPLES)
        return cdist__fail(q, CDIST_ERR_BAD_OPTION, "curve samples must be in [8, %d] (got %d)", CD_MAX_CURVE_SAMPLES,
                       samples);
    size_t need = CD_CURVE_SCRATCH_ARRAYS * ((size_t)samples + 1);
    if (need > q->scratch_len) {
        double *s = realloc(q->scratch, need * sizeof(double));
        if (!s) return cdist__fail(q, CDIST_ERR_NO_MEMORY, "out of memory for %d curve samples", samples);
        q->scratch = s;
        q->scratch_len = need;
    }
    q->curve_samples = samples;
    return setter_ok(q);
}

CD_OPTION_SETTER(cdist_query_set_curve_samples, int, query_set_curve_samples_locked)

int cdist_query_get_curve_samples(const cdist_query *q) { return q ? q->curve_samples : CD_DEFAULT_CURVE_SAMPLES; }

static cdist_status query_set_max_iterations_locked(cdist_query *q, int max_iterations)
{
    if (max_iterations < 1)
        return cdist__fail(q, CDIST_ERR_BAD_OPTION, "max iterations must be >= 1 (got %d)", max_iterations);
    q->max_iterations = max_iterations;
    return setter_ok(q);
}

CD_OPTION_SETTER(cdist_query_set_max_iterations, int, query_set_max_iterations_locked)

int cdist_query_get_max_iterations(const cdist_query *q) { return q ? q->max_iterations : CD_DEFAULT_MAX_ITERATIONS; }

/* Entries between progress reports: rounded up to the batches' block of 64 entries. */
#define CD_PROGRESS_BLOCK 64

static cdist_status query_set_progress_locked(cdist_query *q, cdist_progress_fn fn, void *user, size_t every)
{
    if (fn && every == 0) return cdist__fail(q, CDIST_ERR_BAD_OPTION, "progress: every must be >= 1 with a callback");
    q->progress_fn = fn;
    q->progress_user = fn ? user : NULL;
    q->progress_every = 0;
    if (fn) {
        size_t blocks = every / CD_PROGRESS_BLOCK + (every % CD_PROGRESS_BLOCK != 0);
        q->progress_every = blocks <= SIZE_MAX / CD_PROGRESS_BLOCK ? blocks * CD_PROGRESS_BLOCK
                                                                    : SIZE_MAX / CD_PROGRESS_BLOCK * CD_PROGRESS_BLOCK;
    }
    q->last_status = CDIST_OK;
    q->message[0] = '\0';
    return CDIST_OK;
}

cdist_status cdist_query_set_progress(cdist_query *q, cdist_progress_fn fn, void *user, size_t every)
{
    cdist_status st = cdist__enter_option_setter(q);
    if (st) return st;
    st = query_set_progress_locked(q, fn, user, every);
    cdist__leave_setter(q);
    return st;
}

cdist_status cdist_query_last_status(const cdist_query *q) { return q ? q->last_status : CDIST_ERR_NULL_ARGUMENT; }

const char *cdist_query_last_error(const cdist_query *q)
{
    return q ? q->message : "query handle is NULL";
}

/* ---- status recording ---- */

cdist_status cdist__fail(cdist_query *q, cdist_status st, const char *fmt, ...)
{
    if (q) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(q->message, sizeof q->message, fmt, ap);
        va_end(ap);
        q->last_status = st;
    }
    return st;
}

void cdist__begin(cdist_query *q, cdist_result *r)
{
    if (r) cdist__result_set_error(r);
    if (q) {
        q->message[0] = '\0';
        q->last_status = CDIST_OK;
    }
}

/* ---- circle frames (public) ---- */

cdist_status cdist_circle_basis(const cdist_circle *c, cdist_vec3 *u, cdist_vec3 *v)
{
    if (!c) return CDIST_ERR_NULL_ARGUMENT;
    vec3 n;
    cdist_status st = cdist__check_direction(NULL, &c->normal, "normal", 0, &n, NULL);
    if (st) return st;
    vec3 uu, vv;
    v_basis(n, &uu, &vv);
    if (u) *u = uu;
    if (v) *v = vv;
    return CDIST_OK;
}

cdist_status cdist_circle_point(const cdist_circle *c, double angle, cdist_vec3 *point)
{
    if (!c || !point) return CDIST_ERR_NULL_ARGUMENT;
    if (!isfinite(angle) || !isfinite(c->radius) || !v_isfinite(c->center)) return CDIST_ERR_NOT_FINITE;
    if (c->radius < 0.0) return CDIST_ERR_NEGATIVE_RADIUS;
    vec3 u, v;
    cdist_status st = cdist_circle_basis(c, &u, &v);
    if (st) return st;
    *point = v_axpy(v_axpy(c->center, c->radius * cos(angle), u), c->radius * sin(angle), v);
    return CDIST_OK;
}
