/* SPDX-License-Identifier: MIT */
/* The candidate collector (best.h). */
#include "base/best.h"

#include <float.h>
#include <math.h>

static int cand_distinct(const cdist__best *b, const cdist__cand *x, const cdist__cand *y)
{
    vec3 d0 = v_sub(x->p[0], y->p[0]), d1 = v_sub(x->p[1], y->p[1]);
    double tol = CD_DISTINCT_REL * b->scale;
    /* |v| >= max |v_i|: most distinct pairs are decided without square roots */
    if (v_maxabs(d0) + v_maxabs(d1) > tol) return 1;
    return v_norm(d0) + v_norm(d1) > tol;
}

void cdist__best_offer_into(cdist__best *b, int equi, double d2, vec3 p0, vec3 p1, double param0, double param1)
{
    if (!(d2 >= 0.0)) return; /* NaN candidates are ignored */
    cdist__cand c = {equi, d2, {p0, p1}, {param0, param1}};
    /* Merge with a kept candidate describing the same pair: keep the smaller distance. */
    for (int i = 0; i < b->n; i++) {
        if (!cand_distinct(b, &c, &b->c[i])) {
            if (c.d2 >= b->c[i].d2) return;
            for (int j = i; j + 1 < b->n; j++) b->c[j] = b->c[j + 1];
            b->n--;
            break;
        }
    }
    int pos = b->n;
    while (pos > 0 && b->c[pos - 1].d2 > c.d2) pos--;
    if (pos >= CD_BEST_KEEP) return;
    int last = (b->n < CD_BEST_KEEP) ? b->n : CD_BEST_KEEP - 1;
    for (int j = last; j > pos; j--) b->c[j] = b->c[j - 1];
    b->c[pos] = c;
    if (b->n < CD_BEST_KEEP) b->n++;
}

void cdist__best_offer(cdist__best *b, double d2, vec3 p0, vec3 p1, double param0, double param1)
{
    cdist__best_offer_flag(b, 0, d2, p0, p1, param0, param1);
}

void cdist__best_to_result(const cdist__best *b, vec3 offset, int swap, cdist_result *r)
{
    if (b->n == 0) return;
    int a = swap ? 1 : 0;
    double d0 = sqrt(b->c[0].d2);
    r->distance = d0;
    r->sqr_distance = b->c[0].d2;
    r->equidistant = b->equidistant || b->c[0].equidistant;
    int np = 1;
    if (b->n > 1 && !r->equidistant) {
        double d1 = sqrt(b->c[1].d2);
        if (d1 - d0 <= cdist__best_tie_tol(b)) np = 2;
    }
    r->num_pairs = np;
    for (int i = 0; i < np; i++) {
        const cdist__cand *c = &b->c[i];
        r->pairs[i].point[a] = v_add(c->p[0], offset);
        r->pairs[i].point[1 - a] = v_add(c->p[1], offset);
        r->pairs[i].param[a] = c->param[0];
        r->pairs[i].param[1 - a] = c->param[1];
    }
}

double cdist__best_merge(cdist__best *dst, const cdist__best *src, vec3 shift, int swap)
{
    for (int i = 0; i < src->n; i++) {
        const cdist__cand *c = &src->c[i];
        vec3 p0 = v_add(c->p[0], shift), p1 = v_add(c->p[1], shift);
        if (swap) cdist__best_offer_flag(dst, c->equidistant, c->d2, p1, p0, c->param[1], c->param[0]);
        else cdist__best_offer_flag(dst, c->equidistant, c->d2, p0, p1, c->param[0], c->param[1]);
    }
    return src->n ? src->c[0].d2 : INFINITY;
}

/* Two squared distances tie when their distances agree within the tie tolerance of b. */
static int best_ties(const cdist__best *b, double d2a, double d2b)
{
    return fabs(sqrt(d2a) - sqrt(d2b)) <= cdist__best_tie_tol(b);
}

void cdist__best_settle_equidistant(cdist__best *b, double eq_d2)
{
    if (isfinite(eq_d2) && b->n > 0 && (eq_d2 <= b->c[0].d2 || best_ties(b, eq_d2, b->c[0].d2)))
        b->equidistant = 1;
}

void cdist__best_convex_contact(cdist__best *b)
{
    if (b->n >= 2 && best_ties(b, b->c[0].d2, b->c[1].d2) &&
        sqrt(b->c[1].d2) <= cdist__best_tie_tol(b))
        b->equidistant = 1;
}
