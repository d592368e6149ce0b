/* SPDX-License-Identifier: MIT */
/* Torus-torus clearance with cdist_torus_torus(): the signed distance between two solid tori
 * (core distance minus the tube radii; negative: they overlap), the witness points on the two
 * surfaces and the contact normal. Then a batch: one torus against a row of tori in one
 * cdist_batch_contact() call. Build:
 *   cc torus.c $(pkg-config --cflags --libs circledist) -o torus */
#include <circledist.h>
#include <stdio.h>

static int report(cdist_query *q, cdist_status st)
{
    if (st == CDIST_OK) return 0;
    fprintf(stderr, "query failed: %s: %s\n", cdist_status_name(st), cdist_query_last_error(q));
    return 1;
}

int main(void)
{
    cdist_torus a = {{{0, 0, 0}, {0, 0, 1}, 2.0}, 0.25};   /* centre, unit axis, major radius; tube */
    cdist_torus b = {{{1.5, 0.2, 0.3}, {0, 1, 0}, 2.0}, 0.25}; /* linked with a */
    cdist_query *q = cdist_query_new();
    if (!q) return 1;
    cdist_contact c;
    if (report(q, cdist_torus_torus(q, &a, &b, &c))) {
        cdist_query_free(q);
        return 1;
    }
    printf("core distance %.17g, signed distance %.17g (%s)%s\n", c.core_distance, c.distance,
           c.distance < 0 ? "colliding" : "free", c.equidistant ? ", equidistant" : "");
    for (int i = 0; i < c.num_pairs; i++) {
        const cdist_contact_pair *p = &c.pairs[i];
        printf("pair %d: (%g, %g, %g) - (%g, %g, %g), normal (%g, %g, %g)\n", i, p->point[0].x, p->point[0].y,
               p->point[0].z, p->point[1].x, p->point[1].y, p->point[1].z, p->normal.x, p->normal.y, p->normal.z);
    }

    /* a row of tori slid along x against a, one call */
    enum { N = 5 };
    cdist_torus row[N];
    cdist_contact cs[N];
    cdist_status st[N];
    for (int i = 0; i < N; i++) {
        row[i] = b;
        row[i].circle.center.x = 1.5 + 1.0 * i;
    }
    if (report(q, cdist_batch_contact(q, CDIST_KIND_TORUS_TORUS, N, &a, 0, row, sizeof row[0], cs, st))) {
        cdist_query_free(q);
        return 1;
    }
    for (int i = 0; i < N; i++) printf("x = %g: signed distance %.6f\n", row[i].circle.center.x, cs[i].distance);
    cdist_query_free(q);
    return 0;
}
