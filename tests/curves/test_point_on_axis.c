/* SPDX-License-Identifier: MIT */
/* An arc or a helix against a point-like circle or disk (radius 0 or 1e-30) on the curve's
 * axis: the distance is constant along an arc or a helix of pitch 0 (every point closest), and
 * least at the end nearest in height for a helix of tiny pitch. The certified scan could not end
 * on such a function (CDIST_ERR_COST_LIMIT). Expected values from the geometry:
 * |X - P|^2 = R^2 + (z(X) - zP)^2 for a point P on the axis, in long double. */
#include <float.h>

#include "check.h"

static cdist_query *q;

static void expect(const char *what, cdist_status st, const cdist_result *r, long double ref, int equi)
{
    CHECK(st == CDIST_OK, "%s: %s (%s)", what, cdist_status_name(st), cdist_query_last_error(q));
    if (st != CDIST_OK) return;
    CHECK(fabsl((long double)r->distance - ref) <= 8 * DBL_EPSILON * 1.2L, "%s: %.17g vs %.20Lg", what, r->distance,
          ref);
    CHECK(r->equidistant == equi, "%s: equidistant %d, expected %d", what, r->equidistant, equi);
}

int main(void)
{
    q = cdist_query_new();
    cdist_result r;
    const long double d05 = sqrtl(1.25L); /* radius 1, height 0.5 */
    cdist_arc a = {{tv(0, 0, 0), tv(0, 0, 1), 1.0}, tv(1, 0, 0), 0.065, 5.96};
    cdist_arc full = {{tv(0, 0, 0), tv(0, 0, 1), 1.0}, tv(1, 0, 0), 0.0, 6.283185307179586};
    cdist_circle p0 = {tv(0, 0, 0), tv(1, 0, 0), 0.0}, p05 = {tv(0, 0, 0.5), tv(1, 0, 0), 1e-30},
                 tilt = {tv(0, 0, 0), tv(0.70710678118654757, 0, 0.70710678118654757), 1e-30},
                 pt05 = {tv(0, 0, 0.5), tv(1, 0, 0), 0.0};
    expect("arc-disk, radius 0 at the centre", cdist_arc_disk(q, &a, &p0, &r), &r, 1.0L, 1);
    expect("arc-disk, radius 1e-30 above the centre", cdist_arc_disk(q, &a, &p05, &r), &r, d05, 1);
    expect("full arc-disk, tilted radius 1e-30", cdist_arc_disk(q, &full, &tilt, &r), &r, 1.0L, 1);
    expect("arc-circle, radius 0 above the centre", cdist_arc_circle(q, &a, &pt05, &r), &r, d05, 1);

    cdist_helix flat = {tv(0, 0, 0), tv(0, 0, 1), tv(1, 0, 0), 1.0, 0.0, 0.0, 6.283185307179586};
    cdist_helix fine = {tv(0, 0, 0), tv(0, 0, 1), tv(1, 0, 0), 1.0, 1e-12, 0.0, 62.83185307179586};
    expect("helix pitch 0 - circle radius 0", cdist_helix_circle(q, &flat, &pt05, &r), &r, d05, 1);
    expect("helix pitch 0 - disk radius 1e-30", cdist_helix_disk(q, &flat, &p05, &r), &r, d05, 1);
    /* pitch 1e-12 over ten turns: the top end, at height 1e-12 * t1 / (2 pi), is nearest */
    long double zt = 1e-12L * 62.83185307179586L / (2.0L * 3.14159265358979323846264338327950288L);
    expect("helix pitch 1e-12 - disk radius 0", cdist_helix_disk(q, &fine, &pt05, &r), &r,
           sqrtl(1.0L + (0.5L - zt) * (0.5L - zt)), 0);
    CHECK(r.num_pairs == 1 && r.pairs[0].param[0] == 62.83185307179586, "helix pitch 1e-12: at the end (%.17g)",
          r.pairs[0].param[0]);
    cdist_query_free(q);
    return check_summary("point on axis");
}
