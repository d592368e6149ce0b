/* SPDX-License-Identifier: MIT */
/* Disk to disk: the rim of each disk against the other disk (circle_disk.c); by the lemma of
 * circle_disk.c the closest pair has a rim point on at least one side, or the faces are
 * parallel and over each other (flagged equidistant). The rim-to-rim minima are searched once,
 * in the first half (see dd_query). */
#include <math.h>

#include "circles/circles-priv.h"

/* The validated problem, swapped into the canonical order: the core, then r written in full. */
static cdist_status dd_query(cdist_query *q, cdist__circle a, cdist__circle e, int swap, cdist_result *r, cdist_method *used)
{
    cdist_status st;
    if (swap) {
        cdist__circle t = a;
        a = e;
        e = t;
    }
    vec3 offset;
    cdist__best best;
    int ex = cdist__circles_frame(&a, &e, &offset, &best);
    cdist_method m = cdist__family_method(q, CD_FAM_DISK_DISK), used0, used1;
    /* Rim of a to disk e, and rim of e to disk a (computed with e's centre as origin). */
    cdist__best b0, b1;
    cdist__best_init(&b0, best.scale);
    cdist__best_init(&b1, best.scale);
    int rim_certified;
    if ((st = cdist__circle_disk_core_ex(q, m, &a, &e, INFINITY, 1, &b0, &used0, &rim_certified))) return st;
    cdist__circle a1 = a, e1 = e;
    a1.c = v_neg(e.c);
    e1.c = v3(0, 0, 0);
    /* the first answer caps the second search (its minima above it cannot win) */
    double cap0 = b0.n > 0 ? sqrt(b0.c[0].d2) : INFINITY;
    /* The second half needs no rim-to-rim minima when the first half's are certified
     * (rim_certified): it found them, ties included (docs/disk.md, "The rim-to-rim minima are
     * searched once"). */
    if ((st = cdist__circle_disk_core_ex(q, m, &e1, &a1, cap0, !rim_certified, &b1, &used1, NULL))) return st;
    double d0sq = cdist__best_merge(&best, &b0, v3(0, 0, 0), 0);
    double d1sq = cdist__best_merge(&best, &b1, e.c, 1);
    if (best.n == 0) return cdist__fail(q, CDIST_ERR_INTERNAL, "disk-disk found no candidate");
    /* Parallel faces over each other: the closest set is a region. A rim over the other face
     * (b0 or b1 equidistant) says so; a disk entirely over the other's face with its rim
     * beyond it is caught the other way round. */
    if (cdist__best_is_equidistant(&b0)) cdist__best_settle_equidistant(&best, d0sq);
    if (cdist__best_is_equidistant(&b1)) cdist__best_settle_equidistant(&best, d1sq);
    cdist__best_convex_contact(&best);
    cdist__circles_result(&best, swap, ex, offset, r);
    *used = used0 == CDIST_METHOD_ROBUST || used1 == CDIST_METHOD_ROBUST ? CDIST_METHOD_ROBUST : m;
    return CDIST_OK;
}

cdist_status cdist__circles_entry(cdist_query *q, const cdist_circle *c0, const char *what0, const cdist_circle *c1,
                                  const char *what1, int family, cdist__circles_query_fn query, cdist_result *r)
{
    cdist_status st = cdist__enter(q, r);
    if (st) return st;
    cdist__circle a, e;
    cdist_method used = cdist__family_method(q, family);
    if (!(st = cdist__check_circle(q, c0, what0, &a)) && !(st = cdist__check_circle(q, c1, what1, &e)))
        st = query(q, a, e, cdist__circle_less(c1, c0), r, &used);
    return cdist__leave(q, r, st, used);
}

cdist_status cdist_disk_disk(cdist_query *q, const cdist_circle *d0, const cdist_circle *d1, cdist_result *r)
{
    return cdist__circles_entry(q, d0, "first disk", d1, "second disk", CD_FAM_DISK_DISK, dd_query, r);
}
