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

const cdq_kind cdq_kinds[] = {
    {"pc", 10, "Px Py Pz  " CIRC_COLS, "point to circle"},
    {"pd", 10, "Px Py Pz  " CIRC_COLS, "point to disk"},
    {"lc", 13, "Bx By Bz  Mx My Mz  " CIRC_COLS, "line B + t M to circle"},
    {"rc", 13, "Bx By Bz  Mx My Mz  " CIRC_COLS, "ray B + t M (t >= 0) to circle"},
    {"sc", 13, "P0x P0y P0z  P1x P1y P1z  " CIRC_COLS, "segment P0 P1 to circle"},
    {"cc", 14, "C0x C0y C0z N0x N0y N0z r0  C1x C1y C1z N1x N1y N1z r1", "circle to circle"},
    {"ld", 13, "Bx By Bz  Mx My Mz  " CIRC_COLS, "line to disk"},
    {"rd", 13, "Bx By Bz  Mx My Mz  " CIRC_COLS, "ray to disk"},
    {"sd", 13, "P0x P0y P0z  P1x P1y P1z  " CIRC_COLS, "segment to disk"},
    {"cd", 14, "C0x C0y C0z N0x N0y N0z r0  C1x C1y C1z N1x N1y N1z r1", "circle (first) to disk (second)"},
    {"dd", 14, "C0x C0y C0z N0x N0y N0z r0  C1x C1y C1z N1x N1y N1z r1", "disk to disk"},
    {"ac", 19, ARC_COLS "  " CIRC_COLS, "arc to circle"},
    {"aa", 24, ARC_COLS "  " ARC_COLS, "arc to arc"},
    {"sa", 18, "P0x P0y P0z  P1x P1y P1z  " ARC_COLS, "segment to arc"},
    {"ad", 19, ARC_COLS "  " CIRC_COLS, "arc to disk"},
    {"hc", 20, "Cx Cy Cz Ax Ay Az Ux Uy Uz r pitch t0 t1  " CIRC_COLS, "helix to circle"},
    {"hd", 20, "Cx Cy Cz Ax Ay Az Ux Uy Uz r pitch t0 t1  " CIRC_COLS, "helix to disk"},
    {"bc", 19, "P0x P0y P0z P1x P1y P1z P2x P2y P2z P3x P3y P3z  " CIRC_COLS, "cubic Bezier to circle"},
    {"bd", 19, "P0x P0y P0z P1x P1y P1z P2x P2y P2z P3x P3y P3z  " CIRC_COLS, "cubic Bezier to disk"},
    /* ---- swept kinds (src/swept): upper case T torus, K capsule, S sphere, R rounded disk,
     * lower case the plain object. distance is signed (negative: penetration depth), the
     * points are the witness points on the surfaces (cdist_contact). ---- */
    {"TT", 16, TORUS_COLS "  " TORUS_COLS, "torus to torus (signed)"},
    {"TK", 15, TORUS_COLS "  " CAPS_COLS, "torus to capsule (signed)"},
    {"TS", 12, TORUS_COLS "  " SPH_COLS, "torus to sphere (signed)"},
    {"TR", 16, TORUS_COLS "  " RDISK_COLS, "torus to rounded disk (signed)"},
    {"KK", 14, CAPS_COLS "  " CAPS_COLS, "capsule to capsule (signed)"},
    {"KS", 11, CAPS_COLS "  " SPH_COLS, "capsule to sphere (signed)"},
    {"KR", 15, CAPS_COLS "  " RDISK_COLS, "capsule to rounded disk (signed)"},
    {"SS", 8, SPH_COLS "  " SPH_COLS, "sphere to sphere (signed)"},
    {"SR", 12, SPH_COLS "  " RDISK_COLS, "sphere to rounded disk (signed)"},
    {"RR", 16, RDISK_COLS "  " RDISK_COLS, "rounded disk to rounded disk (signed)"},
    {"Tl", 14, TORUS_COLS "  Bx By Bz  Mx My Mz", "torus to line (signed)"},
    {"Tr", 14, TORUS_COLS "  Bx By Bz  Mx My Mz", "torus to ray (signed)"},
    {"Ts", 14, TORUS_COLS "  P0x P0y P0z  P1x P1y P1z", "torus to segment (signed)"},
    {"Kc", 14, CAPS_COLS "  " CIRC_COLS, "capsule to circle (signed)"},
    {"Kd", 14, CAPS_COLS "  " CIRC_COLS, "capsule to disk (signed)"},
    {"Sc", 11, SPH_COLS "  " CIRC_COLS, "sphere to circle (signed)"},
    {"Sd", 11, SPH_COLS "  " CIRC_COLS, "sphere to disk (signed)"},
    /* ---- end of swept kinds ---- */
    {NULL, 0, NULL, NULL},
};

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
        snprintf(err, errlen, "unknown query kind '%.*s'", (int)(klen > 20 ? 20 : klen), k);
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

/* ---- swept kinds (src/swept) ----
 * A contact is written into the cdist_result the tool prints: distance = the signed distance,
 * sqr_distance = NaN (meaningless when negative), the points = the witness points on the
 * surfaces, params = the core parameters. */
static cdist_torus torus_at(const double *v) { cdist_torus t = {circle_at(v), v[7]}; return t; }
static cdist_capsule capsule_at(const double *v) { cdist_capsule c = {{vec_at(v), vec_at(v + 3)}, v[6]}; return c; }
static cdist_sphere sphere_at(const double *v) { cdist_sphere s = {vec_at(v), v[3]}; return s; }
static cdist_rounded_disk rdisk_at(const double *v) { cdist_rounded_disk d = {circle_at(v), v[7]}; return d; }

static cdist_status swept_run(cdist_query *q, const char *k, const double *v, cdist_contact *c)
{
    cdist_torus t = torus_at(v);
    cdist_capsule kc = capsule_at(v);
    cdist_sphere sp = sphere_at(v);
    cdist_rounded_disk rd = rdisk_at(v);
    if (!strcmp(k, "TT")) { cdist_torus b = torus_at(v + 8); return cdist_torus_torus(q, &t, &b, c); }
    if (!strcmp(k, "TK")) { cdist_capsule b = capsule_at(v + 8); return cdist_torus_capsule(q, &t, &b, c); }
    if (!strcmp(k, "TS")) { cdist_sphere b = sphere_at(v + 8); return cdist_torus_sphere(q, &t, &b, c); }
    if (!strcmp(k, "TR")) { cdist_rounded_disk b = rdisk_at(v + 8); return cdist_torus_rounded_disk(q, &t, &b, c); }
    if (!strcmp(k, "KK")) { cdist_capsule b = capsule_at(v + 7); return cdist_capsule_capsule(q, &kc, &b, c); }
    if (!strcmp(k, "KS")) { cdist_sphere b = sphere_at(v + 7); return cdist_capsule_sphere(q, &kc, &b, c); }
    if (!strcmp(k, "KR")) { cdist_rounded_disk b = rdisk_at(v + 7); return cdist_capsule_rounded_disk(q, &kc, &b, c); }
    if (!strcmp(k, "SS")) { cdist_sphere b = sphere_at(v + 4); return cdist_sphere_sphere(q, &sp, &b, c); }
    if (!strcmp(k, "SR")) { cdist_rounded_disk b = rdisk_at(v + 4); return cdist_sphere_rounded_disk(q, &sp, &b, c); }
    if (!strcmp(k, "RR")) { cdist_rounded_disk b = rdisk_at(v + 8); return cdist_rounded_disk_rounded_disk(q, &rd, &b, c); }
    if (!strcmp(k, "Tl")) { cdist_line b = {vec_at(v + 8), vec_at(v + 11)}; return cdist_torus_line(q, &t, &b, c); }
    if (!strcmp(k, "Tr")) { cdist_ray b = {vec_at(v + 8), vec_at(v + 11)}; return cdist_torus_ray(q, &t, &b, c); }
    if (!strcmp(k, "Ts")) { cdist_segment b = {vec_at(v + 8), vec_at(v + 11)}; return cdist_torus_segment(q, &t, &b, c); }
    if (!strcmp(k, "Kc")) { cdist_circle b = circle_at(v + 7); return cdist_capsule_circle(q, &kc, &b, c); }
    if (!strcmp(k, "Kd")) { cdist_circle b = circle_at(v + 7); return cdist_capsule_disk(q, &kc, &b, c); }
    if (!strcmp(k, "Sc")) { cdist_circle b = circle_at(v + 4); return cdist_sphere_circle(q, &sp, &b, c); }
    if (!strcmp(k, "Sd")) { cdist_circle b = circle_at(v + 4); return cdist_sphere_disk(q, &sp, &b, c); }
    return CDIST_ERR_BAD_OPTION;
}

static int is_swept_kind(const char *k) { return k[0] == 'T' || k[0] == 'K' || k[0] == 'S' || k[0] == 'R'; }

static cdist_status swept_run_result(cdist_query *q, const char *k, const double *v, cdist_result *r)
{
    cdist_contact c;
    cdist_status st = swept_run(q, k, v, &c);
    memset(r, 0, sizeof *r);
    r->distance = c.distance;
    r->sqr_distance = NAN;
    r->num_pairs = c.num_pairs;
    r->equidistant = c.equidistant;
    r->method = c.method;
    for (int i = 0; i < 2; i++) {
        for (int j = 0; j < 2; j++) {
            r->pairs[i].point[j] = c.pairs[i].point[j];
            r->pairs[i].param[j] = c.pairs[i].param[j];
        }
    }
    return st;
}

/* Problem scale of a swept kind: radii, expected distance, reference point distance. */
static double swept_scale(const double *v, int nvalues, double expected)
{
    double L = fabs(expected);
    for (int i = 0; i < nvalues; i++) L = fmax(L, fabs(v[i]));
    return L;
}
/* ---- end of swept kinds ---- */

cdist_status cdq_run(cdist_query *q, const cdq_line *ql, cdist_result *r)
{
    if (is_swept_kind(ql->kind->name)) return swept_run_result(q, ql->kind->name, ql->v, r);
    const double *v = ql->v;
    const char *k = ql->kind->name;
    cdist_vec3 p = vec_at(v);
    cdist_line line = {vec_at(v), vec_at(v + 3)};
    cdist_ray ray = {vec_at(v), vec_at(v + 3)};
    cdist_segment seg = {vec_at(v), vec_at(v + 3)};
    if (!strcmp(k, "pc")) { cdist_circle c = circle_at(v + 3); return cdist_point_circle(q, &p, &c, r); }
    if (!strcmp(k, "pd")) { cdist_circle c = circle_at(v + 3); return cdist_point_disk(q, &p, &c, r); }
    if (!strcmp(k, "lc")) { cdist_circle c = circle_at(v + 6); return cdist_line_circle(q, &line, &c, r); }
    if (!strcmp(k, "rc")) { cdist_circle c = circle_at(v + 6); return cdist_ray_circle(q, &ray, &c, r); }
    if (!strcmp(k, "sc")) { cdist_circle c = circle_at(v + 6); return cdist_segment_circle(q, &seg, &c, r); }
    if (!strcmp(k, "ld")) { cdist_circle c = circle_at(v + 6); return cdist_line_disk(q, &line, &c, r); }
    if (!strcmp(k, "rd")) { cdist_circle c = circle_at(v + 6); return cdist_ray_disk(q, &ray, &c, r); }
    if (!strcmp(k, "sd")) { cdist_circle c = circle_at(v + 6); return cdist_segment_disk(q, &seg, &c, r); }
    if (!strcmp(k, "cc") || !strcmp(k, "cd") || !strcmp(k, "dd")) {
        cdist_circle c0 = circle_at(v), c1 = circle_at(v + 7);
        if (k[0] == 'c' && k[1] == 'c') return cdist_circle_circle(q, &c0, &c1, r);
        if (k[0] == 'c') return cdist_circle_disk(q, &c0, &c1, r);
        return cdist_disk_disk(q, &c0, &c1, r);
    }
    if (!strcmp(k, "ac")) { cdist_arc a = arc_at(v); cdist_circle c = circle_at(v + 12); return cdist_arc_circle(q, &a, &c, r); }
    if (!strcmp(k, "ad")) { cdist_arc a = arc_at(v); cdist_circle c = circle_at(v + 12); return cdist_arc_disk(q, &a, &c, r); }
    if (!strcmp(k, "aa")) { cdist_arc a = arc_at(v), b = arc_at(v + 12); return cdist_arc_arc(q, &a, &b, r); }
    if (!strcmp(k, "sa")) { cdist_arc a = arc_at(v + 6); return cdist_segment_arc(q, &seg, &a, r); }
    if (!strcmp(k, "hc")) { cdist_helix h = helix_at(v); cdist_circle c = circle_at(v + 13); return cdist_helix_circle(q, &h, &c, r); }
    if (!strcmp(k, "hd")) { cdist_helix h = helix_at(v); cdist_circle c = circle_at(v + 13); return cdist_helix_disk(q, &h, &c, r); }
    if (!strcmp(k, "bc")) { cdist_bezier3 b = bezier_at(v); cdist_circle c = circle_at(v + 12); return cdist_bezier3_circle(q, &b, &c, r); }
    if (!strcmp(k, "bd")) { cdist_bezier3 b = bezier_at(v); cdist_circle c = circle_at(v + 12); return cdist_bezier3_disk(q, &b, &c, r); }
    return CDIST_ERR_BAD_OPTION;
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
    if (is_swept_kind(k)) return swept_scale(v, ql->nvalues, expected);
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
