/* The query handle, options, status strings, version, validation and result assembly. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "internal.h"

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
    q->poly = cd_poly_ws_new();
    q->scratch_len = 4 * ((size_t)CD_DEFAULT_CURVE_SAMPLES + 1);
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
    cd_workers_free(q->workers);
    cd_poly_ws_free(q->poly);
    free(q->scratch);
    free(q);
}

static cdist_status setter_ok(cdist_query *q)
{
    cdist_status st = cd_workers_sync(q);
    if (st) return st;
    q->last_status = CDIST_OK;
    q->message[0] = '\0';
    return CDIST_OK;
}

cdist_status cdist_query_set_method(cdist_query *q, cdist_method method)
{
    if (!q) return CDIST_ERR_NULL_ARGUMENT;
    if ((unsigned)method > CDIST_METHOD_ITERATION)
        return cd_fail(q, CDIST_ERR_BAD_OPTION, "method %d is not a cdist_method (0..3)", (int)method);
    q->method = method;
    return setter_ok(q);
}

cdist_method cdist_query_get_method(const cdist_query *q) { return q ? q->method : CDIST_METHOD_AUTO; }

cdist_status cdist_query_set_unit_tolerance(cdist_query *q, double tol)
{
    if (!q) return CDIST_ERR_NULL_ARGUMENT;
    if (!(tol >= 0.0)) return cd_fail(q, CDIST_ERR_BAD_OPTION, "unit tolerance must be >= 0 (got %g)", tol);
    q->unit_tol = tol;
    return setter_ok(q);
}

double cdist_query_get_unit_tolerance(const cdist_query *q) { return q ? q->unit_tol : CD_DEFAULT_UNIT_TOL; }

cdist_status cdist_query_set_curve_samples(cdist_query *q, int samples)
{
    if (!q) return CDIST_ERR_NULL_ARGUMENT;
    if (samples < 8 || samples > CD_MAX_CURVE_SAMPLES)
        return cd_fail(q, CDIST_ERR_BAD_OPTION, "curve samples must be in [8, %d] (got %d)", CD_MAX_CURVE_SAMPLES,
                       samples);
    size_t need = 4 * ((size_t)samples + 1);
    if (need > q->scratch_len) {
        double *s = realloc(q->scratch, need * sizeof(double));
        if (!s) return cd_fail(q, CDIST_ERR_NO_MEMORY, "out of memory for %d curve samples", samples);
        q->scratch = s;
        q->scratch_len = need;
    }
    q->curve_samples = samples;
    return setter_ok(q);
}

int cdist_query_get_curve_samples(const cdist_query *q) { return q ? q->curve_samples : CD_DEFAULT_CURVE_SAMPLES; }

cdist_status cdist_query_set_max_iterations(cdist_query *q, int max_iterations)
{
    if (!q) return CDIST_ERR_NULL_ARGUMENT;
    if (max_iterations < 1)
        return cd_fail(q, CDIST_ERR_BAD_OPTION, "max iterations must be >= 1 (got %d)", max_iterations);
    q->max_iterations = max_iterations;
    return setter_ok(q);
}

int cdist_query_get_max_iterations(const cdist_query *q) { return q ? q->max_iterations : CD_DEFAULT_MAX_ITERATIONS; }

cdist_status cdist_query_last_status(const cdist_query *q) { return q ? q->last_status : CDIST_ERR_NULL_ARGUMENT; }

const char *cdist_query_last_error(const cdist_query *q)
{
    return q ? q->message : "query handle is NULL";
}

/* ---- status recording ---- */

cdist_status cd_fail(cdist_query *q, cdist_status st, const char *fmt, ...)
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

static void result_set_error(cdist_result *r)
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

void cd_begin(cdist_query *q, cdist_result *r)
{
    if (r) result_set_error(r);
    if (q) {
        q->message[0] = '\0';
        q->last_status = CDIST_OK;
    }
}

cdist_status cd_ok(cdist_query *q, cdist_result *r, int method)
{
    r->method = method;
    q->last_status = CDIST_OK;
    q->message[0] = '\0';
    return CDIST_OK;
}

/* ---- validation ---- */

cdist_status cd_check_handle(cdist_query *q, cdist_result *r)
{
    cd_begin(q, r);
    if (!q) return CDIST_ERR_NULL_ARGUMENT;
    if (!r) return cd_fail(q, CDIST_ERR_NULL_ARGUMENT, "result pointer is NULL");
    return CDIST_OK;
}

cdist_status cd_check_ptr(cdist_query *q, const void *p, const char *what)
{
    return p ? CDIST_OK : cd_fail(q, CDIST_ERR_NULL_ARGUMENT, "%s pointer is NULL", what);
}

cdist_status cd_check_scalar(cdist_query *q, double x, const char *what)
{
    if (!isfinite(x)) return cd_fail(q, CDIST_ERR_NOT_FINITE, "%s is not finite (%g)", what, x);
    if (fabs(x) > CD_MAX_ABS) return cd_fail(q, CDIST_ERR_OUT_OF_RANGE, "%s exceeds 1e150 in magnitude (%g)", what, x);
    return CDIST_OK;
}

cdist_status cd_check_point(cdist_query *q, const cdist_vec3 *p, const char *what)
{
    if (!p) return cd_fail(q, CDIST_ERR_NULL_ARGUMENT, "%s pointer is NULL", what);
    if (!v_isfinite(*p))
        return cd_fail(q, CDIST_ERR_NOT_FINITE, "%s is not finite (%g, %g, %g)", what, p->x, p->y, p->z);
    if (v_maxabs(*p) > CD_MAX_ABS)
        return cd_fail(q, CDIST_ERR_OUT_OF_RANGE, "%s exceeds 1e150 in magnitude (%g, %g, %g)", what, p->x, p->y,
                       p->z);
    return CDIST_OK;
}

cdist_status cd_check_direction(cdist_query *q, const cdist_vec3 *d, const char *what, int unit_required, vec3 *unit,
                                double *length)
{
    cdist_status st = cd_check_point(q, d, what);
    if (st) return st;
    /* Scale first so the length neither overflows nor underflows. */
    double m = v_maxabs(*d);
    if (m == 0.0) return cd_fail(q, CDIST_ERR_ZERO_VECTOR, "%s has zero length", what);
    vec3 s = v_scale(1.0 / m, *d);
    double ns = v_norm(s);
    double len = m * ns;
    if (unit_required && q && !(fabs(len - 1.0) <= q->unit_tol))
        return cd_fail(q, CDIST_ERR_NOT_UNIT,
                       "%s has length %.17g, not 1 (tolerance %g; see cdist_query_set_unit_tolerance)", what, len,
                       q->unit_tol);
    if (unit) *unit = v_scale(1.0 / ns, s);
    if (length) *length = len;
    return CDIST_OK;
}

/* Validation without message formatting: a valid circle formats no strings (that was a fifth
 * of a random circle-circle query). Returns 0 on any doubt; cd_check_circle then finds and
 * reports the problem. */
static int circle_fast(const cdist_query *q, const cdist_circle *c, cd_circle *out)
{
    vec3 p = c->center, d = c->normal;
    double r = c->radius;
    if (!v_isfinite(p) || !v_isfinite(d) || !isfinite(r)) return 0;
    if (v_maxabs(p) > CD_MAX_ABS || v_maxabs(d) > CD_MAX_ABS || fabs(r) > CD_MAX_ABS || r < 0.0) return 0;
    double m = v_maxabs(d);
    if (m == 0.0) return 0;
    vec3 sd = v_scale(1.0 / m, d); /* same arithmetic as cd_check_direction */
    double ns = v_norm(sd), len = m * ns;
    if (!(fabs(len - 1.0) <= q->unit_tol)) return 0;
    out->n = v_scale(1.0 / ns, sd);
    out->c = p;
    out->r = r;
    v_basis(out->n, &out->u, &out->v);
    return 1;
}

cdist_status cd_check_circle(cdist_query *q, const cdist_circle *c, const char *what, cd_circle *out)
{
    if (!c) return cd_fail(q, CDIST_ERR_NULL_ARGUMENT, "%s pointer is NULL", what);
    if (q && circle_fast(q, c, out)) return CDIST_OK;
    char buf[64];
    snprintf(buf, sizeof buf, "%s centre", what);
    cdist_status st = cd_check_point(q, &c->center, buf);
    if (st) return st;
    snprintf(buf, sizeof buf, "%s normal", what);
    st = cd_check_direction(q, &c->normal, buf, 1, &out->n, NULL);
    if (st) return st;
    snprintf(buf, sizeof buf, "%s radius", what);
    st = cd_check_scalar(q, c->radius, buf);
    if (st) return st;
    if (c->radius < 0.0) return cd_fail(q, CDIST_ERR_NEGATIVE_RADIUS, "%s radius is negative (%g)", what, c->radius);
    out->c = c->center;
    out->r = c->radius;
    v_basis(out->n, &out->u, &out->v);
    return CDIST_OK;
}

cdist_method cd_pick_method(const cdist_query *q, unsigned available_mask, cdist_method fallback)
{
    cdist_method m = q->method;
    if (m == CDIST_METHOD_AUTO || !(available_mask & CD_HAS(m))) return fallback;
    return m;
}

double cd_circle_angle(const cd_circle *c, vec3 rel)
{
    double x = v_dot(c->u, rel), y = v_dot(c->v, rel);
    if (x == 0.0 && y == 0.0) return NAN;
    double a = atan2(y, x);
    return (a == -M_PI) ? M_PI : a;
}

/* ---- circle frames (public) ---- */

cdist_status cdist_circle_basis(const cdist_circle *c, cdist_vec3 *u, cdist_vec3 *v)
{
    if (!c) return CDIST_ERR_NULL_ARGUMENT;
    vec3 n;
    cdist_status st = cd_check_direction(NULL, &c->normal, "normal", 0, &n, NULL);
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

/* ---- candidate collection ---- */

void cd_best_init(cd_best *b, double scale)
{
    b->scale = (scale > 0.0 && isfinite(scale)) ? scale : 1.0;
    b->n = 0;
    b->equidistant = 0;
}

static int cand_distinct(const cd_best *b, const cd_cand *x, const cd_cand *y)
{
    double sep = v_dist(x->p[0], y->p[0]) + v_dist(x->p[1], y->p[1]);
    return sep > CD_DISTINCT_REL * b->scale;
}

void cd_best_offer_flag(cd_best *b, int equi, double d2, vec3 p0, vec3 p1, double param0, double param1)
{
    if (!(d2 >= 0.0)) return; /* NaN candidates are ignored */
    cd_cand c = {equi, d2, {p0, p1}, {param0, param1}};
    /* Merge with a kept candidate describing the same pair: keep the smaller distance. */
    for (int i = 0; i < b->n; i++) {
        if (!cand_distinct(b, &c, &b->c[i])) {
            if (c.d2 >= b->c[i].d2) return;
            for (int j = i; j + 1 < b->n; j++) b->c[j] = b->c[j + 1];
            b->n--;
            break;
        }
    }
    int pos = b->n;
    while (pos > 0 && b->c[pos - 1].d2 > c.d2) pos--;
    if (pos >= CD_BEST_KEEP) return;
    int last = (b->n < CD_BEST_KEEP) ? b->n : CD_BEST_KEEP - 1;
    for (int j = last; j > pos; j--) b->c[j] = b->c[j - 1];
    b->c[pos] = c;
    if (b->n < CD_BEST_KEEP) b->n++;
}

void cd_best_offer(cd_best *b, double d2, vec3 p0, vec3 p1, double param0, double param1)
{
    cd_best_offer_flag(b, 0, d2, p0, p1, param0, param1);
}

void cd_best_offer_equidistant(cd_best *b, double d2, vec3 p0, vec3 p1, double param0, double param1)
{
    cd_best_offer_flag(b, 1, d2, p0, p1, param0, param1);
}

void cd_best_offer_points(cd_best *b, vec3 p0, vec3 p1, double param0, double param1)
{
    cd_best_offer(b, v_sqr(v_sub(p0, p1)), p0, p1, param0, param1);
}

void cd_best_to_result(const cd_best *b, vec3 offset, int swap, cdist_result *r)
{
    if (b->n == 0) return;
    int a = swap ? 1 : 0;
    double d0 = sqrt(b->c[0].d2);
    r->distance = d0;
    r->sqr_distance = b->c[0].d2;
    r->equidistant = b->equidistant || b->c[0].equidistant;
    int np = 1;
    if (b->n > 1 && !r->equidistant) {
        double d1 = sqrt(b->c[1].d2);
        if (d1 - d0 <= CD_TIE_ULPS * DBL_EPSILON * b->scale) np = 2;
    }
    r->num_pairs = np;
    for (int i = 0; i < np; i++) {
        const cd_cand *c = &b->c[i];
        r->pairs[i].point[a] = v_add(c->p[0], offset);
        r->pairs[i].point[1 - a] = v_add(c->p[1], offset);
        r->pairs[i].param[a] = c->param[0];
        r->pairs[i].param[1 - a] = c->param[1];
    }
}
