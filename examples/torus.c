/* SPDX-License-Identifier: MIT */
/* Torus-torus clearance: the distance between two tori is the distance between their core
 * circles minus the two tube radii (negative: they overlap). Build:
 *   cc torus.c $(pkg-config --cflags --libs circledist) -o torus */
#include <circledist.h>
#include <stdio.h>

typedef struct torus {
    cdist_circle core; /* centre, unit axis, major radius */
    double tube;       /* minor radius */
} torus;

int main(void)
{
    torus a = {{{0, 0, 0}, {0, 0, 1}, 2.0}, 0.25};
    torus b = {{{1.5, 0.2, 0.3}, {0, 1, 0}, 2.0}, 0.25}; /* linked with a */
    cdist_query *q = cdist_query_new();
    if (!q) return 1;
    cdist_result r;
    cdist_status st = cdist_circle_circle(q, &a.core, &b.core, &r);
    if (st != CDIST_OK) {
        fprintf(stderr, "query failed: %s: %s\n", cdist_status_name(st), cdist_query_last_error(q));
        cdist_query_free(q);
        return 1;
    }
    double clearance = r.distance - a.tube - b.tube;
    printf("core distance %.17g, clearance %.17g (%s)%s\n", r.distance, clearance,
           clearance < 0 ? "colliding" : "free", r.equidistant ? ", equidistant" : "");
    for (int i = 0; i < r.num_pairs; i++)
        printf("closest pair %d: (%g, %g, %g) - (%g, %g, %g)\n", i, r.pairs[i].point[0].x, r.pairs[i].point[0].y,
               r.pairs[i].point[0].z, r.pairs[i].point[1].x, r.pairs[i].point[1].y, r.pairs[i].point[1].z);
    cdist_query_free(q);
    return 0;
}
