/* SPDX-License-Identifier: MIT */
/* The helix queries' cost bound: at every sample count the API allows, a helix query spends at
 * most CD_CURVE_HELIX_MAX_EVALS evaluations of the curve (read from the library's counter, not
 * timed: speed is measured in bench/), and answers either the true distance (closed form or the
 * long double brute force of brute.h over every turn) or CDIST_ERR_COST_LIMIT with the error
 * result. The coils: long coaxial coils of pitch 1e-9 (every turn within rounding of the answer),
 * a circle threading 4000 and 240000 tight turns, a circle threading a coil of 45 turns, a
 * narrow basin on every turn. */
#include "brute.h"
#include "curves/curve_scan.h"

static cdist_query *q;

/* ref: the distance (NAN: the brute force over every turn, computed once per case). expect_ok:
 * the query must answer (a coil the bound settles in a few turns). */
static void check_case(const char *name, const cdist_helix *h, const cdist_circle *c, int disk, ld *ref,
                       int expect_ok, int samples)
{
    cdist_result r;
    cdist_status st = (disk ? cdist_helix_disk : cdist_helix_circle)(q, h, c, &r);
    long spent = cdist__helix_last_evals();
    CHECK(spent <= CD_CURVE_HELIX_MAX_EVALS + 1, "%s at %d samples: %ld evaluations (budget %ld)", name, samples, spent,
          CD_CURVE_HELIX_MAX_EVALS);
    if (st == CDIST_ERR_COST_LIMIT && !expect_ok) {
        CHECK(isnan(r.distance) && r.num_pairs == 0, "%s at %d samples: refused without the error result", name,
              samples);
        return;
    }
    CHECK(st == CDIST_OK, "%s at %d samples: %s (%s)", name, samples, cdist_status_name(st),
          cdist_query_last_error(q));
    if (st) return;
    if (isnan((double)*ref)) {
        bf_helix x = bf_helix_of(h, c, disk);
        int ns = (int)(1024 * (1 + (h->t1 - h->t0) / (2 * M_PI)));
        *ref = bf_min1d(bf_f_helix, &x, h->t0, h->t1, ns);
    }
    double ext = fabs(h->pitch) * fmax(fabs(h->t0), fabs(h->t1)) / (2 * M_PI);
    double L = fmax(fmax(h->radius, c->radius), tdist(h->center, c->center) + ext);
    double er = (double)(fabsl((ld)r.distance - *ref) / L);
    CHECK(er <= 1e-12, "%s at %d samples: %.17g vs %.20Lg (error %.3g of scale)", name, samples, r.distance, *ref, er);
}

int main(void)
{
    q = cdist_query_new();
    static const int samples[] = {8, 9, 64, 512, 4096, 65536, 1 << 20};
    cdist_helix coil4k = {tv(0, 0, 0), tv(0, 0, 1), tv(1, 0, 0), 1.0, 1e-9, 0, 25000};
    cdist_helix coil240k = {tv(0, 0, 0), tv(0, 0, 1), tv(1, 0, 0), 1.0, 1e-9, 0, 1.5e6};
    cdist_helix coil45 = {tv(0, 0, 0), tv(0, 0, 1), tv(1, 0, 0), 1.0, 0.05, 0, 282};
    cdist_helix basin = {tv(0, 0, 0), tv(0.12713528112406569, 0.72235514668474465, 0.67973499420845329),
                         tv(0.88764416518506173, 0.22295885816590461, -0.4029605235978716), 1,
                         8.1110380473151297e-06, -2.6739032527197715, 38.002800815063324};
    /* Coaxial with the coil, radius 0.5: every helix point is sqrt(0.25 + z^2) from it, at
     * least 0.5, equal at t = 0. */
    cdist_circle coax = {tv(0, 0, 0), tv(0, 0, 1), 0.5};
    cdist_circle through = {tv(0, 0, 0), tv(1, 0, 0), 3.0}; /* in a plane holding the axis */
    cdist_circle thread45 = {tv(0.1, 0, 0.7), tv(1, 0, 0), 2.0};
    cdist_circle basin_c = {tv(0.88764416518461076, 0.22295885816674854, -0.40296052359735768),
                            tv(-0.39536083285874024, 0.62633915544033258, -0.67185495027091557),
                            0.060415434432673422};
    ld half = 0.5L, r_through = NAN, r_thread = NAN, r_basin = NAN, r_through240 = NAN;
    for (size_t i = 0; i < sizeof samples / sizeof samples[0]; i++) {
        int n = samples[i];
        CHECK(cdist_query_set_curve_samples(q, n) == CDIST_OK, "set %d samples", n);
        check_case("coaxial circle, 4000 turns", &coil4k, &coax, 0, &half, 1, n);
        check_case("coaxial disk, 4000 turns", &coil4k, &coax, 1, &half, 1, n);
        check_case("coaxial circle, 240000 turns", &coil240k, &coax, 0, &half, 1, n);
        check_case("coaxial disk, 240000 turns", &coil240k, &coax, 1, &half, 1, n);
        check_case("threading circle, 4000 turns", &coil4k, &through, 0, &r_through, 0, n);
        check_case("threading circle, 240000 turns", &coil240k, &through, 0, &r_through240, 0, n);
        check_case("threading circle, 45 turns", &coil45, &thread45, 0, &r_thread, 1, n);
        check_case("narrow basin on every turn", &basin, &basin_c, 0, &r_basin, 1, n);
    }
    cdist_query_free(q);
    return check_summary("helix-cost");
}
