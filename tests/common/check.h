/* SPDX-License-Identifier: MIT */
/* Minimal test helpers: CHECK records a failure and goes on; check_summary() prints the
 * closing "N passed, N failed" line and gives the exit status. */
#ifndef CDIST_TEST_CHECK_H
#define CDIST_TEST_CHECK_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "circledist.h"

static int check_passed, check_failed;

#define CHECK(cond, ...)                                                                                       \
    do {                                                                                                       \
        if (cond) {                                                                                            \
            check_passed++;                                                                                    \
        } else {                                                                                               \
            check_failed++;                                                                                    \
            fprintf(stderr, "%s:%d: CHECK(%s) failed: ", __FILE__, __LINE__, #cond);                          \
            fprintf(stderr, __VA_ARGS__);                                                                      \
            fputc('\n', stderr);                                                                               \
        }                                                                                                      \
    } while (0)

#define CHECK_NEAR(a, b, tol, what)                                                                            \
    CHECK(fabs((double)(a) - (double)(b)) <= (tol), "%s: %.17g vs %.17g (diff %.3g > tol %.3g)", what,         \
          (double)(a), (double)(b), fabs((double)(a) - (double)(b)), (double)(tol))

static inline int check_summary(const char *name)
{
    printf("%s: %d passed, %d failed\n", name, check_passed, check_failed);
    return check_failed ? 1 : 0;
}

static inline cdist_vec3 tv(double x, double y, double z) { cdist_vec3 r = {x, y, z}; return r; }
static inline double tdist(cdist_vec3 a, cdist_vec3 b)
{
    return sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));
}

/* Deterministic xorshift random numbers for property tests. */
static unsigned long long check_rng_state = 0x9E3779B97F4A7C15ull;
static inline double urand(void)
{
    check_rng_state ^= check_rng_state << 13;
    check_rng_state ^= check_rng_state >> 7;
    check_rng_state ^= check_rng_state << 17;
    return (double)(check_rng_state >> 11) * (1.0 / 9007199254740992.0);
}
static inline double srand1(void) { return 2.0 * urand() - 1.0; }
static inline cdist_vec3 rand_unit(void)
{
    for (;;) {
        cdist_vec3 v = tv(srand1(), srand1(), srand1());
        double n = sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
        if (n > 0.1 && n <= 1.0) return tv(v.x / n, v.y / n, v.z / n);
    }
}

/* A random rotation (as a 3x3 row-major matrix) via Gram-Schmidt of random unit vectors. */
typedef struct { double m[3][3]; } trot;
static inline trot rand_rotation(void)
{
    cdist_vec3 a = rand_unit(), b = rand_unit();
    double d = a.x * b.x + a.y * b.y + a.z * b.z;
    b = tv(b.x - d * a.x, b.y - d * a.y, b.z - d * a.z);
    double n = sqrt(b.x * b.x + b.y * b.y + b.z * b.z);
    b = tv(b.x / n, b.y / n, b.z / n);
    cdist_vec3 c = tv(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
    trot r = {{{a.x, a.y, a.z}, {b.x, b.y, b.z}, {c.x, c.y, c.z}}};
    return r;
}
static inline cdist_vec3 rot_apply(const trot *r, cdist_vec3 v)
{
    return tv(r->m[0][0] * v.x + r->m[0][1] * v.y + r->m[0][2] * v.z,
              r->m[1][0] * v.x + r->m[1][1] * v.y + r->m[1][2] * v.z,
              r->m[2][0] * v.x + r->m[2][1] * v.y + r->m[2][2] * v.z);
}
/* x -> s R x + t */
static inline cdist_vec3 xform_point(const trot *r, double s, cdist_vec3 t, cdist_vec3 p)
{
    cdist_vec3 q = rot_apply(r, p);
    return tv(s * q.x + t.x, s * q.y + t.y, s * q.z + t.z);
}
static inline cdist_circle xform_circle(const trot *r, double s, cdist_vec3 t, cdist_circle c)
{
    cdist_circle o = {xform_point(r, s, t, c.center), rot_apply(r, c.normal), s * c.radius};
    return o;
}

/* Distance from p to circle c (independent closed form in long double, for checks). */
static inline long double ref_point_circle(cdist_vec3 p, cdist_circle c)
{
    long double nx = c.normal.x, ny = c.normal.y, nz = c.normal.z;
    long double nn = sqrtl(nx * nx + ny * ny + nz * nz);
    nx /= nn; ny /= nn; nz /= nn;
    long double dx = (long double)p.x - c.center.x, dy = (long double)p.y - c.center.y,
                dz = (long double)p.z - c.center.z;
    long double h = nx * dx + ny * dy + nz * dz;
    long double cx = ny * dz - nz * dy, cy = nz * dx - nx * dz, cz = nx * dy - ny * dx;
    long double rho = sqrtl(cx * cx + cy * cy + cz * cz);
    return sqrtl((rho - c.radius) * (rho - c.radius) + h * h);
}
static inline long double ref_point_disk(cdist_vec3 p, cdist_circle c)
{
    long double nx = c.normal.x, ny = c.normal.y, nz = c.normal.z;
    long double nn = sqrtl(nx * nx + ny * ny + nz * nz);
    nx /= nn; ny /= nn; nz /= nn;
    long double dx = (long double)p.x - c.center.x, dy = (long double)p.y - c.center.y,
                dz = (long double)p.z - c.center.z;
    long double h = nx * dx + ny * dy + nz * dz;
    long double cx = ny * dz - nz * dy, cy = nz * dx - nx * dz, cz = nx * dy - ny * dx;
    long double rho = sqrtl(cx * cx + cy * cy + cz * cz);
    if (rho <= c.radius) return fabsl(h);
    return sqrtl((rho - c.radius) * (rho - c.radius) + h * h);
}

#endif
