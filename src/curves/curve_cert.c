/* SPDX-License-Identifier: MIT */
/* Certification of a sampled scan: every sample interval gets a rigorous lower bound of the
 * distance over it (Lipschitz, second order along the chord, the components h and rho, the
 * curve's own bound); one below the answer minus tau is split, and a midpoint below it starts a
 * descent to its basin's minimum. The bounds and their proofs: docs/curves.md, "Certification".
 * So no sampling density can miss a basin by more than tau. */
#include <math.h>

#include "curve_scan.h"

typedef struct cert_node {
    double a, b, da, db, ha, hb; /* da, db: the sampled distances at a and b */
    double xa, ya, xb, yb; /* in-plane coordinates at a and b */
} cert_node;

/* Height over the circle's plane and in-plane coordinates (along the circle's u, v) of a point,
 * relative to the centre: the certification's component bounds (computed only there). */
static void plane_coords(const cdist__cs_scan *s, vec3 p, double *h, double *px, double *py)
{
    const cdist__circle *c = s->c;
    vec3 rel = v_sub(p, c->c);
    *h = c->n.x * rel.x + c->n.y * rel.y + c->n.z * rel.z;
    *px = c->u.x * rel.x + c->u.y * rel.y + c->u.z * rel.z;
    *py = c->v.x * rel.x + c->v.y * rel.y + c->v.z * rel.z;
}

/* Rounding of a sampled distance (positions, h, rho and F in plain arithmetic). */
static double cert_mu(const cdist__cs_scan *s)
{
    return CD_CURVE_CERT_EVAL_ULPS * DBL_EPSILON * (2.0 * s->k->b.scale + s->c->r + s->frame_mag);
}


/* The first- and second-order bounds of the distance over an interval of width w whose end
 * distances are at least da, db (rounding already subtracted) and whose end points are pab
 * apart (as computed; negative: not used): 1 when no point of it is below lim (> 0). The speed bound is the
 * curve's, or the local one: P' differs from its mean (P(b) - P(a)) / w by at most K w / 2
 * (|P''| <= K), the positions' rounding (mu each) included. */
static int chord_excluded(const cdist__cs_scan *s, double w, double da, double db, double pab, double mu, double best,
                          double lim)
{
    double K = s->accel_max, S = s->speed_max;
    if (pab >= 0.0) S = cdist__cs_min2(S, ((pab + 4.0 * mu) / w + 0.5 * K * w) * (1.0 + CD_CURVE_CERT_WIDTH_REL));
    if (0.5 * (da + db - S * w) >= lim) return 1;
    double dl = cdist__cs_min2(da, db), dh = cdist__cs_max2(da, db);
    if (!(dl > 0.0)) return 0;
    /* The chord from the lower end (fl) to the higher one (fh) minus M s (w - s) / 2, s from the
     * lower end: its minimum is at s = w/2 - (fh - fl) / (M w), clipped to [0, w/2]. */
    double fl = dl * dl, fh = dh * dh, M = 2.0 * (S * S + (best + S * w) * K), mw = M * w;
    double sm = mw > 0.0 ? 0.5 * w - (fh - fl) / mw : 0.5 * w;
    return (sm > 0.0 ? fl - 0.5 * M * sm * sm : fl) >= lim * lim;
}

/* The interval cannot hold a distance below lim (> 0); mu: cert_mu(s). */
static int cert_excluded(const cdist__cs_scan *s, const cert_node *nd, double best, double lim, double mu)
{
    double w = nd->b - nd->a, lim2 = lim * lim;
    double eh = nd->hb - nd->ha, ex = nd->xb - nd->xa, ey = nd->yb - nd->ya;
    double pab = s->speed_varies ? sqrt(eh * eh + ex * ex + ey * ey) : -1.0;
    if (chord_excluded(s, w, nd->da - mu, nd->db - mu, pab, mu, best, lim)) return 1;
    double hl = 0.0;
    if ((nd->ha > 0.0 && nd->hb > 0.0) || (nd->ha < 0.0 && nd->hb < 0.0))
        hl = cdist__cs_max2(0.0, cdist__cs_min2(fabs(nd->ha), fabs(nd->hb)) - mu - s->accel_normal_max * w * w * 0.125);
    /* (plain squares: the scan's frame is scaled to L ~ 1) */
    double dx = nd->xb - nd->xa, dy = nd->yb - nd->ya, ll = dx * dx + dy * dy;
    double u = ll > 0.0 ? -(nd->xa * dx + nd->ya * dy) / ll : 0.0;
    u = u < 0.0 ? 0.0 : (u > 1.0 ? 1.0 : u);
    double sag = s->accel_plane_max * w * w * 0.125 + 2.0 * mu, r = s->c->r;
    double cx = nd->xa + u * dx, cy = nd->ya + u * dy;
    double rl = cdist__cs_max2(0.0, sqrt(cx * cx + cy * cy) - sag - r);
    if (!s->disk) {
        double ra2 = nd->xa * nd->xa + nd->ya * nd->ya, rb2 = nd->xb * nd->xb + nd->yb * nd->yb;
        rl = cdist__cs_max2(rl, r - sqrt(cdist__cs_max2(ra2, rb2)) - sag);
    }
    if (hl * hl + rl * rl >= lim2) return 1;
    return s->lb && s->lb(s, nd->a, nd->b) >= lim;
}

static cdist_status certify(cdist__cs_scan *s, cert_node nd)
{
    cert_node stack[CD_CURVE_CERT_DEPTH];
    int top = 0;
    cdist_status st;
    double mu = cert_mu(s);
    for (;;) {
        double best = s->k->b.n ? sqrt(s->k->b.c[0].d2) : INFINITY;
        double lim = best - cdist__cs_cert_tol(s);
        double m = 0.5 * (nd.a + nd.b);
        if (lim > 0.0 && !cert_excluded(s, &nd, best, lim, mu) && m > nd.a && m < nd.b) {
            if (++s->cert_nodes > CD_CURVE_CERT_MAX_NODES)
                return cdist__fail(s->q, CDIST_ERR_COST_LIMIT,
                                   "curve: certifying the minimum needs more than %ld bound evaluations",
                                   (long)CD_CURVE_CERT_MAX_NODES);
            vec3 pm;
            double fm;
            if ((st = cdist__cs_eval_point(s, m, &pm, &fm))) return st;
            if (fm < lim * lim) {
                /* A point below the answer: descend to its basin's minimum. */
                double span = s->span;
                st = cdist__cs_polish(s, m, nd.a, nd.b);
                s->span = span;
                if (st) return st;
            }
            double dm = sqrt(fm), hm, px, py;
            plane_coords(s, pm, &hm, &px, &py);
            cert_node right = {m, nd.b, dm, nd.db, hm, nd.hb, px, py, nd.xb, nd.yb};
            nd.b = m;
            nd.db = dm;
            nd.hb = hm;
            nd.xb = px;
            nd.yb = py;
            if (top < CD_CURVE_CERT_DEPTH) {
                stack[top++] = right;
            } else if ((st = certify(s, right))) {
                return st;
            }
            continue;
        }
        if (top == 0) return CDIST_OK;
        nd = stack[--top];
    }
}

/* Certify the sample intervals of a scan (F: d^2, P: positions per sample), the bounds tried
 * cheapest first (docs/curves.md, "The bounds are tried cheapest first"); the Lipschitz screen
 * takes the longest interval of the scan (t_at's widths differ by rounding only, covered by
 * CD_CURVE_CERT_WIDTH_REL). */
cdist_status cdist__cs_certify_samples(cdist__cs_scan *s, double t0, double t1, int n, const double *F, const vec3 *P)
{
    double best = sqrt(s->k->b.c[0].d2);
    double lim = best - cdist__cs_cert_tol(s), mu = cert_mu(s);
    double screen = 2.0 * (lim + mu) + s->speed_max * ((t1 - t0) / n) * (1.0 + CD_CURVE_CERT_WIDTH_REL);
    double half2 = screen > 0.0 ? 0.25 * screen * screen * (1.0 + CD_CURVE_CERT_WIDTH_REL) : 0.0;
    int whole = 0;      /* the curve's bound was tried over the whole range */
    int block_end = -1; /* intervals below this index are settled by their block's bound */
    int block_tried = -1; /* start of the last block whose bound was tried */
    for (int e = 0; e <= n; e++) {
        if (F[e] >= half2) continue;
        for (int m = (e > 0 && F[e - 1] >= half2) ? e - 1 : e; m <= e && m < n; m++) {
            if (m < block_end) continue;
            double da = sqrt(F[m]), db = sqrt(F[m + 1]);
            if (da + db >= screen) continue;
            double a = cdist__cs_t_at(t0, t1, m, n), b = cdist__cs_t_at(t0, t1, m + 1, n);
            if (!(lim > 0.0)) return CDIST_OK;
            double pab = s->speed_varies ? v_dist(P[m], P[m + 1]) : -1.0;
            if (chord_excluded(s, b - a, da - mu, db - mu, pab, mu, best, lim)) continue;
            if (s->lb && n > 1) {
                if (!whole) {
                    whole = 1;
                    if (s->lb(s, t0, t1) >= lim) return CDIST_OK;
                }
                int b0 = m - m % CD_CURVE_CERT_BLOCK, b1 = b0 + CD_CURVE_CERT_BLOCK < n ? b0 + CD_CURVE_CERT_BLOCK : n;
                if (b0 != block_tried && b1 - b0 > 1) {
                    block_tried = b0;
                    if (s->lb(s, cdist__cs_t_at(t0, t1, b0, n), cdist__cs_t_at(t0, t1, b1, n)) >= lim) {
                        block_end = b1;
                        continue;
                    }
                }
            }
            cert_node nd;
            nd.a = a;
            nd.b = b;
            nd.da = da;
            nd.db = db;
            plane_coords(s, P[m], &nd.ha, &nd.xa, &nd.ya);
            plane_coords(s, P[m + 1], &nd.hb, &nd.xb, &nd.yb);
            cdist_status st = certify(s, nd);
            if (st) return st;
            best = sqrt(s->k->b.c[0].d2);
            lim = best - cdist__cs_cert_tol(s);
        }
    }
    return CDIST_OK;
}
