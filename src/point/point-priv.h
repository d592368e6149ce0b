/* SPDX-License-Identifier: MIT */
/* Point family cores (src/point/point.c). */
#ifndef CDIST_POINT_PRIV_H
#define CDIST_POINT_PRIV_H

#include "base/best.h"
#include "base/vec.h"

/* The closest circle (disk) point k of p, both relative to the centre (c->c ignored):
 * squared distance, k, its circle angle (NaN at the centre or for r = 0), and whether every
 * circle point is as close (p on the axis). Only c->n and c->r are read. */
typedef struct cdist__point_pair {
    double d2;
    vec3 k;
    double angle;
    int equidistant;
} cdist__point_pair;
cdist__point_pair cdist__point_circle_pair(vec3 p, const cdist__circle *c);
cdist__point_pair cdist__point_disk_pair(vec3 p, const cdist__circle *c);

/* The same offered to a collector (swap: p is the second object); p relative to the centre. */
void cdist__point_circle_core(vec3 p, const cdist__circle *c, cdist__best *b, int swap);
void cdist__point_disk_core(vec3 p, const cdist__circle *c, cdist__best *b, int swap);

/* The whole point query (validated p and circle c, c's basis not needed): scaled by a power of
 * two, solved, and written to r (point[0] exactly p, param[0] NaN, method not set). */
void cdist__point_result(vec3 p, const cdist__circle *c, int disk, cdist_result *r);

#endif
