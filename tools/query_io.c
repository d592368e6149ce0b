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

/* Per kind, once: where its two objects are in a line (objects_KK) and the public call that
 * answers them (run_KK). */
#define KIND(kk, TA, A_AT, TB, B_AT, CALL)                                                         \
    static void objects_##kk(const double *v, void *a, void *b)                                   \
    {                                                                                              \
        *(TA *)a = A_AT;                                                                           \
        *(TB *)b = B_AT;                                                                           \
    }                                                                                              \
    static cdist_status run_##kk(cdist_query *q, const double *v, cdist_result *r)                 \
    {                                                                                              \
        TA a;                                                                                      \
        TB b;                                                                                      \
        objects_##kk(v, &a, &b);                                                                   \
        return CALL(q, &a, &b, r);                                                                 \
    }
KIND(pc, cdist_vec3, vec_at(v), cdist_circle, circle_at(v + 3), cdist_point_circle)
KIND(pd, cdist_vec3, vec_at(v), cdist_circle, circle_at(v + 3), cdist_point_disk)
KIND(lc, cdist_line, line_at(v), cdist_circle, circle_at(v + 6), cdist_line_circle)
KIND(rc, cdist_ray, ray_at(v), cdist_circle, circle_at(v + 6), cdist_ray_circle)
KIND(sc, cdist_segment, segment_at(v), cdist_circle, circle_at(v + 6), cdist_segment_circle)
KIND(ld, cdist_line, line_at(v), cdist_circle, circle_at(v + 6), cdist_line_disk)
KIND(rd, cdist_ray, ray_at(v), cdist_circle, circle_at(v + 6), cdist_ray_disk)
KIND(sd, cdist_segment, segment_at(v), cdist_circle, circle_at(v + 6), cdist_segment_disk)
KIND(cc, cdist_circle, circle_at(v), cdist_circle, circle_at(v + 7), cdist_circle_circle)
KIND(cd, cdist_circle, circle_at(v), cdist_circle, circle_at(v + 7), cdist_circle_disk)
KIND(dd, cdist_circle, circle_at(v), cdist_circle, circle_at(v + 7), cdist_disk_disk)
KIND(ac, cdist_arc, arc_at(v), cdist_circle, circle_at(v + 12), cdist_arc_circle)
KIND(aa, cdist_arc, arc_at(v), cdist_arc, arc_at(v + 12), cdist_arc_arc)
KIND(sa, cdist_segment, segment_at(v), cdist_arc, arc_at(v + 6), cdist_segment_arc)
KIND(ad, cdist_arc, arc_at(v), cdist_circle, circle_at(v + 12), cdist_arc_disk)
KIND(hc, cdist_helix, helix_at(v), cdist_circle, circle_at(v + 13), cdist_helix_circle)
KIND(hd, cdist_helix, helix_at(v), cdist_circle, circle_at(v + 13), cdist_helix_disk)
KIND(bc, cdist_bezier3, bezier_at(v), cdist_circle, circle_at(v + 12), cdist_bezier3_circle)
KIND(bd, cdist_bezier3, bezier_at(v), cdist_circle, circle_at(v + 12), cdist_bezier3_disk)
#undef KIND

#ifndef CDQ_NO_SWEPT /* defined when building against a library without swept objects (scripts/bench-compare.sh) */
/* ---- swept kinds (src/swept) ----
 * A contact is written into the cdist_result the tool prints: distance = the signed distance,
 * sqr_distance = NaN (meaningless when negative), the points = the witness points on the
 * surfaces, params = the core parameters. They have no batch kind (objects NULL). */
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

#define SWEPT(kk, TA, A_AT, TB, B_AT, CALL)                                                        \
    static cdist_status run_##kk(cdist_query *q, const double *v, cdist_result *r)                 \
    {                                                                                              \
        TA a = A_AT;                                                                               \
        TB b = B_AT;                                                                               \
        cdist_contact c;                                                                           \
        return contact_to_result(CALL(q, &a, &b, &c), &c, r);                                      \
    }
SWEPT(TT, cdist_torus, torus_at(v), cdist_torus, torus_at(v + 8), cdist_torus_torus)
SWEPT(TK, cdist_torus, torus_at(v), cdist_capsule, capsule_at(v + 8), cdist_torus_capsule)
SWEPT(TS, cdist_torus, torus_at(v), cdist_sphere, sphere_at(v + 8), cdist_torus_sphere)
SWEPT(TR, cdist_torus, torus_at(v), cdist_rounded_disk, rdisk_at(v + 8), cdist_torus_rounded_disk)
SWEPT(KK, cdist_capsule, capsule_at(v), cdist_capsule, capsule_at(v + 7), cdist_capsule_capsule)
SWEPT(KS, cdist_capsule, capsule_at(v), cdist_sphere, sphere_at(v + 7), cdist_capsule_sphere)
SWEPT(KR, cdist_capsule, capsule_at(v), cdist_rounded_disk, rdisk_at(v + 7), cdist_capsule_rounded_disk)
SWEPT(SS, cdist_sphere, sphere_at(v), cdist_sphere, sphere_at(v + 4), cdist_sphere_sphere)
SWEPT(SR, cdist_sphere, sphere_at(v), cdist_rounded_disk, rdisk_at(v + 4), cdist_sphere_rounded_disk)
SWEPT(RR, cdist_rounded_disk, rdisk_at(v), cdist_rounded_disk, rdisk_at(v + 8), cdist_rounded_disk_rounded_disk)
SWEPT(Tl, cdist_torus, torus_at(v), cdist_line, line_at(v + 8), cdist_torus_line)
SWEPT(Tr, cdist_torus, torus_at(v), cdist_ray, ray_at(v + 8), cdist_torus_ray)
SWEPT(Ts, cdist_torus, torus_at(v), cdist_segment, segment_at(v + 8), cdist_torus_segment)
SWEPT(Kc, cdist_capsule, capsule_at(v), cdist_circle, circle_at(v + 7), cdist_capsule_circle)
SWEPT(Kd, cdist_capsule, capsule_at(v), cdist_circle, circle_at(v + 7), cdist_capsule_disk)
SWEPT(Sc, cdist_sphere, sphere_at(v), cdist_circle, circle_at(v + 4), cdist_sphere_circle)
SWEPT(Sd, cdist_sphere, sphere_at(v), cdist_circle, circle_at(v + 4), cdist_sphere_disk)
#undef SWEPT
/* ---- end of swept kinds ---- */
#endif

const cdq_kind cdq_kinds[] = {
    {"pc", 10, run_pc, objects_pc, 0, {6, 0}, "Px Py Pz  " CIRC_COLS, "point to circle"},
    {"pd", 10, run_pd, objects_pd, 1, {6, 0}, "Px Py Pz  " CIRC_COLS, "point to disk"},
    {"lc", 13, run_lc, objects_lc, 2, {3, 9}, "Bx By Bz  Mx My Mz  " CIRC_COLS, "line B + t M to circle"},
    {"rc", 13, run_rc, objects_rc, 3, {3, 9}, "Bx By Bz  Mx My Mz  " CIRC_COLS, "ray B + t M (t >= 0) to circle"},
    {"sc", 13, run_sc, objects_sc, 4, {9, 0}, "P0x P0y P0z  P1x P1y P1z  " CIRC_COLS, "segment P0 P1 to circle"},
    {"cc", 14, run_cc, objects_cc, 5, {3, 10}, "C0x C0y C0z N0x N0y N0z r0  C1x C1y C1z N1x N1y N1z r1", "circle to circle"},
    {"ld", 13, run_ld, objects_ld, 6, {3, 9}, "Bx By Bz  Mx My Mz  " CIRC_COLS, "line to disk"},
    {"rd", 13, run_rd, objects_rd, 7, {3, 9}, "Bx By Bz  Mx My Mz  " CIRC_COLS, "ray to disk"},
    {"sd", 13, run_sd, objects_sd, 8, {9, 0}, "P0x P0y P0z  P1x P1y P1z  " CIRC_COLS, "segment to disk"},
    {"cd", 14, run_cd, objects_cd, 9, {3, 10}, "C0x C0y C0z N0x N0y N0z r0  C1x C1y C1z N1x N1y N1z r1", "circle (first) to disk (second)"},
    {"dd", 14, run_dd, objects_dd, 10, {3, 10}, "C0x C0y C0z N0x N0y N0z r0  C1x C1y C1z N1x N1y N1z r1", "disk to disk"},
    {"ac", 19, run_ac, objects_ac, 13, {3, 15}, ARC_COLS "  " CIRC_COLS, "arc to circle"},
    {"aa", 24, run_aa, objects_aa, 14, {3, 15}, ARC_COLS "  " ARC_COLS, "arc to arc"},
    {"sa", 18, run_sa, objects_sa, 15, {9, 0}, "P0x P0y P0z  P1x P1y P1z  " ARC_COLS, "segment to arc"},
    {"ad", 19, run_ad, objects_ad, 16, {3, 15}, ARC_COLS "  " CIRC_COLS, "arc to disk"},
    {"hc", 20, run_hc, objects_hc, 17, {3, 16}, "Cx Cy Cz Ax Ay Az Ux Uy Uz r pitch t0 t1  " CIRC_COLS, "helix to circle"},
    {"hd", 20, run_hd, objects_hd, 18, {3, 16}, "Cx Cy Cz Ax Ay Az Ux Uy Uz r pitch t0 t1  " CIRC_COLS, "helix to disk"},
    {"bc", 19, run_bc, objects_bc, 19, {15, 0}, "P0x P0y P0z P1x P1y P1z P2x P2y P2z P3x P3y P3z  " CIRC_COLS, "cubic Bezier to circle"},
    {"bd", 19, run_bd, objects_bd, 20, {15, 0}, "P0x P0y P0z P1x P1y P1z P2x P2y P2z P3x P3y P3z  " CIRC_COLS, "cubic Bezier to disk"},
#ifndef CDQ_NO_SWEPT
    /* ---- swept kinds (src/swept): upper case T torus, K capsule, S sphere, R rounded disk,
     * lower case the plain object. distance is signed (negative: penetration depth), the
     * points are the witness points on the surfaces (cdist_contact). ---- */
    {"TT", 16, run_TT, NULL, -1, {3, 11}, TORUS_COLS "  " TORUS_COLS, "torus to torus (signed)"},
    {"TK", 15, run_TK, NULL, -1, {3, 0}, TORUS_COLS "  " CAPS_COLS, "torus to capsule (signed)"},
    {"TS", 12, run_TS, NULL, -1, {3, 0}, TORUS_COLS "  " SPH_COLS, "torus to sphere (signed)"},
    {"TR", 16, run_TR, NULL, -1, {3, 11}, TORUS_COLS "  " RDISK_COLS, "torus to rounded disk (signed)"},
    {"KK", 14, run_KK, NULL, -1, {0, 0}, CAPS_COLS "  " CAPS_COLS, "capsule to capsule (signed)"},
    {"KS", 11, run_KS, NULL, -1, {0, 0}, CAPS_COLS "  " SPH_COLS, "capsule to sphere (signed)"},
    {"KR", 15, run_KR, NULL, -1, {10, 0}, CAPS_COLS "  " RDISK_COLS, "capsule to rounded disk (signed)"},
    {"SS", 8, run_SS, NULL, -1, {0, 0}, SPH_COLS "  " SPH_COLS, "sphere to sphere (signed)"},
    {"SR", 12, run_SR, NULL, -1, {7, 0}, SPH_COLS "  " RDISK_COLS, "sphere to rounded disk (signed)"},
    {"RR", 16, run_RR, NULL, -1, {3, 11}, RDISK_COLS "  " RDISK_COLS, "rounded disk to rounded disk (signed)"},
    {"Tl", 14, run_Tl, NULL, -1, {3, 11}, TORUS_COLS "  Bx By Bz  Mx My Mz", "torus to line (signed)"},
    {"Tr", 14, run_Tr, NULL, -1, {3, 11}, TORUS_COLS "  Bx By Bz  Mx My Mz", "torus to ray (signed)"},
    {"Ts", 14, run_Ts, NULL, -1, {3, 0}, TORUS_COLS "  P0x P0y P0z  P1x P1y P1z", "torus to segment (signed)"},
    {"Kc", 14, run_Kc, NULL, -1, {10, 0}, CAPS_COLS "  " CIRC_COLS, "capsule to circle (signed)"},
    {"Kd", 14, run_Kd, NULL, -1, {10, 0}, CAPS_COLS "  " CIRC_COLS, "capsule to disk (signed)"},
    {"Sc", 11, run_Sc, NULL, -1, {7, 0}, SPH_COLS "  " CIRC_COLS, "sphere to circle (signed)"},
    {"Sd", 11, run_Sd, NULL, -1, {7, 0}, SPH_COLS "  " CIRC_COLS, "sphere to disk (signed)"},
    /* ---- end of swept kinds ---- */
#endif
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
