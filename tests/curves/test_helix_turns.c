/* SPDX-License-Identifier: MIT */
/* Helices of many turns (issue 10 item 4): whole turns are skipped by a lower bound, so check
 * the answers against the long double brute force of brute.h over EVERY turn, on coils that
 * the target threads, surrounds, touches or misses; the slow probes (a million turns of
 * pitch 1e-6 coaxial with a circle and a disk) against their closed form; and the documented
 * cost limit (CDIST_ERR_COST_LIMIT with an error result) on a target threading 1e6 tight turns. */
#include "brute.h"

static cdist_query *q;
static double worst;


static void against_brute(int id, const cdist_helix *h, const cdist_circle *c, int disk)
{
    bf_helix x = bf_helix_of(h, c, disk);
    int ns = (int)(2048 * (1 + (h->t1 - h->t0) / (2 * M_PI)));
    ld ref = bf_min1d(bf_f_helix, &x, h->t0, h->t1, ns);
    cdist_result r;
    cdist_status st = (disk ? cdist_helix_disk : cdist_helix_circle)(q, h, c, &r);
    CHECK(st == CDIST_OK, "helix %d: %s", id, cdist_query_last_error(q));
    if (st) return;
    double ext = fabs(h->pitch) * fmax(fabs(h->t0), fabs(h->t1)) / (2 * M_PI);
    double L = fmax(fmax(fmax(h->radius, c->radius), tdist(h->center, c->center) + ext), (double)ref);
    double er = (double)(fabsl((ld)r.distance - ref) / L);
    if (er > worst) worst = er;
    CHECK(er <= 1e-12, "helix %d (%s): %.17g vs brute force %.20Lg (error %.3g)", id, disk ? "disk" : "circle",
          r.distance, ref, er);
}

static void random_coils(void)
{
    for (int id = 0; id < 160; id++) {
        int turns = 5 + (int)(40 * urand());
        double pitch = (id % 4 == 0 ? 0.02 : 0.3) * (urand() + 0.05) * (id % 3 == 0 ? -1 : 1);
        cdist_helix h = {tv(0, 0, 0), tv(0, 0, 1), tv(1, 0, 0), 0.5 + urand(), pitch, -0.5 * urand(), 0};
        h.t1 = h.t0 + 2 * M_PI * turns * (0.9 + 0.1 * urand());
        double zmid = pitch * turns / 2;
        cdist_circle c;
        switch (id % 5) {
        case 0: /* coaxial, inside or outside the coil */
            c = (cdist_circle){tv(0, 0, zmid * (2 * urand())), tv(0, 0, 1), 2 * urand()};
            break;
        case 1: /* threading: plane containing the axis */
            c = (cdist_circle){tv(0.3 * srand1(), 0.3 * srand1(), zmid * 2 * urand()), tv(1, 0, 0), 0.2 + 3 * urand()};
            break;
        case 2: /* tilted, near the coil */
            c = (cdist_circle){tv(srand1(), srand1(), zmid * 2 * urand()), rand_unit(), 2 * urand()};
            break;
        case 3: /* beyond an end of the coil */
            c = (cdist_circle){tv(srand1(), srand1(), (pitch > 0 ? 1 : -1) * (fabs(zmid) * 2.2 + urand())), rand_unit(), urand()};
            break;
        default: /* far to the side */
            c = (cdist_circle){tv(5 + 5 * urand(), srand1(), zmid * 2 * urand()), rand_unit(), 2 * urand()};
        }
        against_brute(id, &h, &c, id % 2);
    }
}

int main(void)
{
    q = cdist_query_new();
    random_coils();
    /* The probes: a million turns of pitch 1e-6 crossing the target's plane at radius 1
     * (closed form: the helix meets the plane at a point of radius 1, every point is >= 0.5
     * from the target). */
    cdist_helix h = {tv(0, 0, -0.5), tv(0, 0, 1), tv(1, 0, 0), 1.0, 1e-6, 0, 2 * M_PI * 1e6};
    cdist_circle c = {tv(0, 0, 0), tv(0, 0, 1), 1.5}, d = {tv(0, 0, 0), tv(0, 0, 1), 0.5};
    cdist_result r;
    CHECK(cdist_helix_circle(q, &h, &c, &r) == CDIST_OK && fabs(r.distance - 0.5) <= 1e-15,
          "coaxial 1e6 turns to circle: %.17g, expected 0.5", r.distance);
    CHECK(cdist_helix_disk(q, &h, &d, &r) == CDIST_OK && fabs(r.distance - 0.5) <= 1e-15,
          "coaxial 1e6 turns to disk: %.17g, expected 0.5", r.distance);
    /* A circle threading a million tight turns: documented cost limit. */
    cdist_helix t = {tv(0, 0, 0), tv(0, 0, 1), tv(1, 0, 0), 1.0, 1e-6, 0, 2 * M_PI * 1e6};
    cdist_circle th = {tv(0, 0, 0.5), tv(1, 0, 0), 2.0};
    cdist_status st = cdist_helix_circle(q, &t, &th, &r);
    CHECK(st == CDIST_ERR_COST_LIMIT && isnan(r.distance) && r.num_pairs == 0,
          "threaded coil: status %s, distance %g", cdist_status_name(st), r.distance);
    printf("helix turns: max error %.3g of scale\n", worst);
    cdist_query_free(q);
    return check_summary("helix-turns");
}
