/* SPDX-License-Identifier: MIT */
#include "query_io.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define ARC_COLS "Cx Cy Cz Nx Ny Nz r Ux Uy Uz start end"
#define CIRC_COLS "Cx Cy Cz Nx Ny Nz r"
/* swept kinds (src/swept) */
#define TORUS_COLS "Cx Cy Cz Nx Ny Nz R rt"
#define CAPS_COLS "P0x P0y P0z P1x P1y P1z rk"
#define SPH_COLS "Px Py Pz rs"
#define RDISK_COLS "Cx Cy Cz Nx Ny Nz R rr"

static cdist_vec3 vec_at(const double *v) { cdist_vec3 r = {v[0], v[1], v[2]}; return r; }

static cdist_circle circle_at(const double *v)
{
    cdist_circle c = {vec_at(v), vec_at(v + 3), v[6]};
    return c;
}

static cdist_arc arc_at(const double *v)
{
    cdist_arc a = {circle_at(v), vec_at(v + 7), v[10], v[11]};
    return a;
}

static cdist_helix helix_at(const double *v)
{
    cdist_helix h = {vec_at(v), vec_at(v + 3), vec_at(v + 6), v[9], v[10], v[11], v[12]};
    return h;
}

static cdist_bezier3 bezier_at(const double *v)
{
    cdist_bezier3 b;
    for (int i = 0; i < 4; i++) b.p[i] = vec_at(v + 3 * i);
    return b;
}

static cdist_line line_at(const double *v) { cdist_line l = {vec_at(v), vec_at(v + 3)}; return l; }
static cdist_ray ray_at(const double *v) { cdist_ray l = {vec_at(v), vec_at(v + 3)}; return l; }
static cdist_segment segment_at(const double *v) { cdist_segment l = {vec_at(v), vec_at(v + 3)}; return l; }

#ifndef CDQ_NO_SWEPT /* defined when building against a library without swept objects (scripts/bench-compare.sh) */
/* ---- swept kinds (src/swept) ----
 * A contact is written into the cdist_result the tool prints: distance = the signed distance,
 * sqr_distance = NaN (meaningless when negative), the points = the witness points on the
 * surfaces, params = the core parameters. */
static cdist_torus torus_at(const double *v) { cdist_torus t = {circle_at(v), v[7]}; return t; }
static cdist_capsule capsule_at(const double *v) { cdist_capsule c = {{vec_at(v), vec_at(v + 3)}, v[6]}; return c; }
static cdist_sphere sphere_at(const double *v) { cdist_sphere s = {vec_at(v), v[3]}; return s; }
static cdist_rounded_disk rdisk_at(const double *v) { cdist_rounded_disk d = {circle_at(v), v[7]}; return d; }

static cdist_status contact_to_result(cdist_status st, const cdist_contact *c, cdist_result *r)
{
    memset(r, 0, sizeof *r);
    r->distance = c->distance;
    r->sqr_distance = NAN;
    r->num_pairs = c->num_pairs;
    r->equidistant = c->equidistant;
    r->method = c->method;
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++) {
            r->pairs[i].point[j] = c->pairs[i].point[j];
            r->pairs[i].param[j] = c->pairs[i].param[j];
        }
    return st;
}

/* ---- end of swept kinds ---- */
#endif

/* Each object type as numbers on a line: CDQ_TYPE_<type> is (count, offset of its vector that
 * must be unit length (0: none), column names, reader). */
#define CDQ_TYPE_cdist_vec3 (3, 0, "Px Py Pz", vec_at)
#define CDQ_TYPE_cdist_line (6, 3, "Bx By Bz  Mx My Mz", line_at)
#define CDQ_TYPE_cdist_ray (6, 3, "Bx By Bz  Mx My Mz", ray_at)
#define CDQ_TYPE_cdist_segment (6, 0, "P0x P0y P0z  P1x P1y P1z", segment_at)
#define CDQ_TYPE_cdist_circle (7, 3, CIRC_COLS, circle_at)
#define CDQ_TYPE_cdist_arc (12, 3, ARC_COLS, arc_at)
#define CDQ_TYPE_cdist_helix (13, 3, "Cx Cy Cz Ax Ay Az Ux Uy Uz r pitch t0 t1", helix_at)
#define CDQ_TYPE_cdist_bezier3 (12, 0, "P0x P0y P0z P1x P1y P1z P2x P2y P2z P3x P3y P3z", bezier_at)
#define CDQ_TYPE_cdist_torus (8, 3, TORUS_COLS, torus_at)
#define CDQ_TYPE_cdist_capsule (7, 0, CAPS_COLS, capsule_at)
#define CDQ_TYPE_cdist_sphere (4, 0, SPH_COLS, sphere_at)
#define CDQ_TYPE_cdist_rounded_disk (8, 3, RDISK_COLS, rdisk_at)
#define CDQ_COUNT_(n, unit, cols, at) n
#define CDQ_UNIT_(n, unit, cols, at) unit
#define CDQ_COLS_(n, unit, cols, at) cols
#define CDQ_AT_(n, unit, cols, at) at
#define CDQ_COUNT(T) CDQ_COUNT_ T
#define CDQ_UNIT(T) CDQ_UNIT_ T
#define CDQ_COLS(T) CDQ_COLS_ T
#define CDQ_AT(T) CDQ_AT_ T

/* Per kind of the registry (src/api/kinds.def), once: where its two objects are in a line
 * (objects_NAME), the public call that answers them (run_NAME) and its row of the table. */
#define CDQ_OBJECTS(name, TA, TB)                                                                  \
    static void objects_##name(const double *v, void *a, void *b)                                 \
    {                                                                                              \
        *(TA *)a = CDQ_AT(CDQ_TYPE_##TA)(v);                                                       \
        *(TB *)b = CDQ_AT(CDQ_TYPE_##TB)(v + CDQ_COUNT(CDQ_TYPE_##TA));                            \
    }
#define CD_KIND(KIND, number, name, letters, TA, TB, ...)                                          \
    CDQ_OBJECTS(name, TA, TB)                                                                      \
    static cdist_status run_##name(cdist_query *q, const double *v, cdist_result *r)               \
    {                                                                                              \
        TA a;                                                                                      \
        TB b;                                                                                      \
        objects_##name(v, &a, &b);                                                                 \
        return cdist_##name(q, &a, &b, r);                                                         \
    }
/* A contact is written into the cdist_result the tool prints (contact_to_result). The tool
 * answers them one by one even with -j (objects NULL, no batch kind). */
#define CDQ_CONTACT_RUN(KIND, number, name, letters, TA, TB, ...)                                  \
    static cdist_status run_##name(cdist_query *q, const double *v, cdist_result *r)               \
    {                                                                                              \
        TA a = CDQ_AT(CDQ_TYPE_##TA)(v);                                                           \
        TB b = CDQ_AT(CDQ_TYPE_##TB)(v + CDQ_COUNT(CDQ_TYPE_##TA));                                \
        cdist_contact c;                                                                           \
        return contact_to_result(cdist_##name(q, &a, &b, &c), &c, r);                              \
    }
#ifndef CDQ_NO_SWEPT
#define CD_CONTACT_KIND CDQ_CONTACT_RUN
#endif
#include "../src/api/kinds.def"
#undef CDQ_CONTACT_RUN

/* The offsets of the unit vectors in a line of A then B: A's (when it has one), then B's. */
#define CDQ_UNIT_B(TA, TB) (CDQ_UNIT(CDQ_TYPE_##TB) ? CDQ_COUNT(CDQ_TYPE_##TA) + CDQ_UNIT(CDQ_TYPE_##TB) : 0)
#define CDQ_ROW(letters, name, TA, TB, objects, batch_kind, help)                                  \
    {#letters, CDQ_COUNT(CDQ_TYPE_##TA) + CDQ_COUNT(CDQ_TYPE_##TB), run_##name, objects, batch_kind, \
     {CDQ_UNIT(CDQ_TYPE_##TA) ? CDQ_UNIT(CDQ_TYPE_##TA) : CDQ_UNIT_B(TA, TB),                        \
      CDQ_UNIT(CDQ_TYPE_##TA) ? CDQ_UNIT_B(TA, TB) : 0},                                           \
     CDQ_COLS(CDQ_TYPE_##TA) "  " CDQ_COLS(CDQ_TYPE_##TB), help},
const cdq_kind cdq_kinds[] = {
#define CD_KIND(KIND, number, name, letters, TA, TB, grad, methods, auto_method, kernel, help)        \
    CDQ_ROW(letters, name, TA, TB, objects_##name, number, help)
#ifndef CDQ_NO_SWEPT
#define CD_CONTACT_KIND(KIND, number, name, letters, TA, TB, A, B, core, swap, help)                             \
    CDQ_ROW(letters, name, TA, TB, NULL, -1, help)
#endif
#include "../src/api/kinds.def"
    {NULL, 0, NULL, NULL, -1, {0, 0}, NULL, NULL},
};

/* Whether a decimal or hexadecimal literal has a non-zero digit in its mantissa. */
static int literal_nonzero(const char *s)
{
    int hex = 0;
    while (*s == '+' || *s == '-') s++;
    if (s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) {
        hex = 1;
        s += 2;
    }
    for (; *s; s++) {
        if (!hex && (*s == 'e' || *s == 'E')) break;
        if (hex && (*s == 'p' || *s == 'P')) break;
        if ((*s >= '1' && *s <= '9') || (hex && isxdigit((unsigned char)*s) && *s != '0')) return 1;
    }
    return 0;
}

int cdq_parse(const char *line, cdq_line *out, char *err, size_t errlen)
{
    const char *s = line;
    while (*s && isspace((unsigned char)*s)) s++;
    if (*s == '\0' || *s == '#') return 0;
    const char *k = s;
    while (*s && !isspace((unsigned char)*s) && *s != '#') s++;
    size_t klen = (size_t)(s - k);
    out->kind = NULL;
    for (const cdq_kind *kd = cdq_kinds; kd->name; kd++) {
        if (strlen(kd->name) == klen && strncmp(kd->name, k, klen) == 0) {
            out->kind = kd;
            break;
        }
    }
    if (!out->kind) {
        /* at most 20 bytes of it, never cut inside a UTF-8 sequence */
        size_t shown = klen;
        if (shown > 20) {
            shown = 20;
            while (shown > 0 && ((unsigned char)k[shown] & 0xC0) == 0x80) shown--;
        }
        snprintf(err, errlen, "unknown query kind '%.*s'%s", (int)shown, k, shown < klen ? "..." : "");
        return -1;
    }
    int n = 0;
    for (;;) {
        while (*s && isspace((unsigned char)*s)) s++;
        if (*s == '\0' || *s == '#') break;
        const char *tok = s;
        while (*s && !isspace((unsigned char)*s) && *s != '#') s++;
        if (n >= out->kind->nvalues) {
            snprintf(err, errlen, "'%s' takes %d numbers, got more", out->kind->name, out->kind->nvalues);
            return -1;
        }
        char buf[64];
        size_t tl = (size_t)(s - tok);
        if (tl >= sizeof buf) {
            snprintf(err, errlen, "number %d is too long", n + 1);
            return -1;
        }
        memcpy(buf, tok, tl);
        buf[tl] = '\0';
        char *end;
        errno = 0;
        double x = strtod(buf, &end);
        if (end == buf || *end != '\0') {
            snprintf(err, errlen, "number %d ('%s') is not a number", n + 1, buf);
            return -1;
        }
        /* Out of range: overflow to infinity, or a non-zero literal read as 0 (underflow). A
         * subnormal result is kept: it is the nearest double, only with fewer digits. */
        if (errno == ERANGE && isinf(x)) {
            snprintf(err, errlen, "number %d ('%s') is too large for a double", n + 1, buf);
            return -1;
        }
        if (x == 0 && literal_nonzero(buf)) {
            snprintf(err, errlen, "number %d ('%s') is too small for a double (it would be read as 0)", n + 1, buf);
            return -1;
        }
        out->v[n++] = x;
    }
    if (n != out->kind->nvalues) {
        snprintf(err, errlen, "'%s' takes %d numbers (%s), got %d", out->kind->name, out->kind->nvalues,
                 out->kind->columns, n);
        return -1;
    }
    out->nvalues = n;
    return 1;
}

void cdq_normalize(cdq_line *ql)
{
    for (int i = 0; i < 2; i++) {
        int at = ql->kind->unit_at[i];
        if (at == 0) continue;
        double *v = ql->v + at;
        double m = fmax(fabs(v[0]), fmax(fabs(v[1]), fabs(v[2])));
        if (!(m > 0) || !isfinite(m)) continue;
        double x = v[0] / m, y = v[1] / m, z = v[2] / m; /* scaled: no overflow or underflow */
        double n = sqrt(x * x + y * y + z * z);
        v[0] = x / n;
        v[1] = y / n;
        v[2] = z / n;
    }
}

int cdq_swapped(const cdq_line *ql, cdq_line *out)
{
    const char *k = ql->kind->name;
    int n = ql->kind->nvalues;
    if (k[0] != k[1] || k[2] != '\0' || n % 2) return 0;
    out->kind = ql->kind;
    out->nvalues = ql->nvalues;
    memcpy(out->v, ql->v + n / 2, (size_t)(n / 2) * sizeof(double));
    memcpy(out->v + n / 2, ql->v, (size_t)(n / 2) * sizeof(double));
    return 1;
}

cdist_status cdq_run(cdist_query *q, const cdq_line *ql, cdist_result *r)
{
    return ql->kind->run(q, ql->v, r);
}

static double dist3(const double *a, const double *b)
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

/* Point of the line B + t M nearest to C. */
static double line_center_dist(const double *B, const double *M, const double *C)
{
    double d[3] = {C[0] - B[0], C[1] - B[1], C[2] - B[2]};
    double mm = M[0] * M[0] + M[1] * M[1] + M[2] * M[2];
    double t = (d[0] * M[0] + d[1] * M[1] + d[2] * M[2]) / mm;
    double x[3] = {B[0] + t * M[0], B[1] + t * M[1], B[2] + t * M[2]};
    return dist3(x, C);
}

double cdq_scale(const cdq_line *ql, double expected)
{
    const double *v = ql->v;
    const char *k = ql->kind->name;
    double L = fabs(expected);
    if (ql->kind->batch_kind < 0) { /* swept kinds: every radius and coordinate */
        for (int i = 0; i < ql->nvalues; i++) L = fmax(L, fabs(v[i]));
        return L;
    }
    if (k[0] == 'p') {
        L = fmax(L, fmax(v[9], dist3(v, v + 3)));
    } else if (!strcmp(k, "lc") || !strcmp(k, "rc") || !strcmp(k, "ld") || !strcmp(k, "rd")) {
        L = fmax(L, fmax(v[12], line_center_dist(v, v + 3, v + 6)));
    } else if (!strcmp(k, "sc") || !strcmp(k, "sd")) {
        double M[3] = {v[3] - v[0], v[4] - v[1], v[5] - v[2]};
        double lc = (M[0] == 0 && M[1] == 0 && M[2] == 0) ? dist3(v, v + 6) : line_center_dist(v, M, v + 6);
        L = fmax(L, fmax(v[12], fmax(lc, dist3(v, v + 3))));
    } else if (!strcmp(k, "cc") || !strcmp(k, "cd") || !strcmp(k, "dd")) {
        L = fmax(L, fmax(fmax(v[6], v[13]), dist3(v, v + 7)));
    } else if (!strcmp(k, "ac") || !strcmp(k, "ad")) {
        L = fmax(L, fmax(fmax(v[6], v[18]), dist3(v, v + 12)));
    } else if (!strcmp(k, "aa")) {
        L = fmax(L, fmax(fmax(v[6], v[18]), dist3(v, v + 12)));
    } else if (!strcmp(k, "sa")) {
        L = fmax(L, fmax(v[12], fmax(dist3(v, v + 6), dist3(v + 3, v + 6))));
    } else if (k[0] == 'h') {
        double ext = fabs(v[10]) * fmax(fabs(v[11]), fabs(v[12])) / (2 * M_PI);
        L = fmax(L, fmax(fmax(v[9], v[19]), dist3(v, v + 13) + ext));
    } else if (k[0] == 'b') {
        for (int i = 0; i < 4; i++) L = fmax(L, dist3(v + 3 * i, v + 12));
        L = fmax(L, v[18]);
    }
    return L;
}
