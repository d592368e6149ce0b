/* SPDX-License-Identifier: MIT */
/* Every public query family (point, lines/rays/segments to circles and disks, circle-circle,
 * circle-disk, disk-disk, arcs, helix, Bezier, callback curve) under every method on random and
 * degenerate inputs: the process stays alive, every OK result is finite and >= 0 (signed for
 * the swept kinds) and every error leaves NaN and no pairs. */
#include <string.h>

#include "check.h"
#include "circle_curve.h"
#include "query_io.h"

static cdist_query *q;
static long n_ok;

static void check_ok(cdist_status st, const cdist_result *r, const char *what, int id)
{
    n_ok += st == CDIST_OK;
    if (st == CDIST_OK)
        /* swept kinds (upper-case tool names) have signed distances */
        CHECK(isfinite(r->distance) && (r->distance >= 0.0 || (what[0] >= 'A' && what[0] <= 'Z')),
              "%s %d: OK with distance %g", what, id, r->distance);
    else
        CHECK(isnan(r->distance) && r->num_pairs == 0, "%s %d: error %s without the error result", what, id,
              cdist_status_name(st));
}

/* A value for slot k: random in [-2, 2], or (degenerate mode) from a small set, so that
 * coaxial, concentric, coplanar, on-axis, zero-radius and touching configurations are common. */
static double value(int degenerate)
{
    static const double set[] = {0.0, 0.0, 1.0, -1.0, 0.5, 2.0, 1e-9};
    if (degenerate) return set[(int)(urand() * 7.0) % 7];
    return 4.0 * urand() - 2.0;
}

int main(void)
{
    q = cdist_query_new();
    /* Any non-zero normal or direction is accepted and normalised. */
    cdist_query_set_unit_tolerance(q, INFINITY);
    cdist_query_set_curve_samples(q, 32);
    const cdist_method methods[4] = {CDIST_METHOD_AUTO, CDIST_METHOD_ROBUST, CDIST_METHOD_POLYNOMIAL,
                                     CDIST_METHOD_ITERATION};
    long runs = 0;
    for (int m = 0; m < 4; m++) {
        cdist_query_set_method(q, methods[m]);
        for (int id = 0; id < 400; id++) {
            int degenerate = id % 2;
            double v[CDQ_MAX_VALUES];
            for (int k = 0; k < CDQ_MAX_VALUES; k++) v[k] = value(degenerate);
            for (const cdq_kind *kd = cdq_kinds; kd->name; kd++) {
                cdq_line ql;
                ql.kind = kd;
                ql.nvalues = kd->nvalues;
                memcpy(ql.v, v, sizeof v);
                /* Mostly valid: positive radii and ordered intervals (arcs within 2 pi). */
                if (id % 5 != 0) {
                    if (kd->name[0] == 'a' || kd->name[1] == 'a') {
                        int off = kd->name[0] == 's' ? 6 : 0;
                        ql.v[off + 6] = fabs(ql.v[off + 6]);
                        ql.v[off + 11] = ql.v[off + 10] + fabs(ql.v[off + 11]);
                        if (!strcmp(kd->name, "aa")) {
                            ql.v[18] = fabs(ql.v[18]);
                            ql.v[23] = ql.v[22] + fabs(ql.v[23]);
                        }
                    }
                    if (kd->name[0] == 'h') {
                        ql.v[9] = fabs(ql.v[9]);
                        ql.v[12] = ql.v[11] + 3.0 * fabs(ql.v[12]);
                    }
                    ql.v[kd->nvalues - 1] = fabs(ql.v[kd->nvalues - 1]);
                    if (kd->name[0] == 'c' || (kd->name[0] == 'd' && kd->name[1] == 'd')) ql.v[6] = fabs(ql.v[6]);
                }
                cdist_result r;
                { cdist_status st = cdq_run(q, &ql, &r); check_ok(st, &r, kd->name, id); }
                runs++;
            }
            /* A callback curve (a circle) against a circle and a disk. */
            cdist_circle c0 = {tv(v[0], v[1], v[2]), tv(v[3], v[4], v[5]), fabs(v[6])};
            cdist_circle c1 = {tv(v[7], v[8], v[9]), tv(v[10], v[11], v[12]), fabs(v[13])};
            if (cdist_circle_basis(&c0, NULL, NULL) == CDIST_OK) {
                circ_curve k = circ_curve_of(&c0);
                cdist_result r;
                check_ok(cdist_curve_circle(q, circ_fn, &k, 0.0, 6.283185307179586, &c1, &r), &r, "curve-circle", id);
                check_ok(cdist_curve_disk(q, circ_fn, &k, 0.0, 6.283185307179586, &c1, &r), &r, "curve-disk", id);
                runs += 2;
            }
        }
    }
    printf("method-sweep: %ld queries under the four methods (%ld answered)\n", runs, n_ok);
    /* Most inputs must reach the algorithms, not the validation. */
    CHECK(n_ok > runs / 2, "only %ld of %ld queries answered", n_ok, runs);
    cdist_query_free(q);
    return check_summary("method-sweep");
}
