/* SPDX-License-Identifier: MIT */
/* Distance kernels of circle-disk and disk-disk for cdist_batch_distance: each entry runs the
 * single query's own steps (cdist__cd_stage_start, _finish: validation, framing, the candidates
 * over the disk's face, the bound that spares the rim), and the rims' certified searches of the
 * block run together in lanes (cdist__cc_quick_lanes, which certifies what the single query's
 * search certifies, with the same angle to the last bit). The distances are therefore the
 * single query's bit for bit; an entry whose query takes another path (a failed fast check, a
 * zero radius, parallel planes, the rim search's engine) is left to the scalar path. */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "batch-priv.h"
#include "api/api-priv.h"
#include "circles/circles-priv.h"

/* One entry: its stage, the frame's exponent and, for disk-disk, the second half's distance. */
typedef struct cd_entry {
    cdist__cd_stage st;
    int e;
    double d2_other;
} cd_entry;

/* Entry i, its circles a, e validated (cdist__circle_pairs_lanes), up to the rim search:
 * CD_STAGE_*. */
CD_INLINE int cd_start(const cdist__job *job, int disk, size_t i, cdist__circle a, cdist__circle e, cd_entry *x)
{
    if (disk && cdist__circle_less(cdist__job_b(job, i), cdist__job_a(job, i))) {
        cdist__circle t = a;
        a = e;
        e = t;
    }
    vec3 offset;
    cdist__best best;
    x->e = cdist__circles_frame(&a, &e, &offset, &best);
    x->d2_other = INFINITY;
    if (disk) {
        /* the rim of e over a's face, e's centre the origin (dd_query) */
        cdist__circle a1 = a, e1 = e;
        a1.c = v_neg(e.c);
        e1.c = v3(0, 0, 0);
        if (cdist__cd_stage_start(&x->st, &e1, &a1, best.scale, 0) != CD_STAGE_DONE) return CD_STAGE_SCALAR;
        x->d2_other = x->st.d2;
    }
    return cdist__cd_stage_start(&x->st, &a, &e, best.scale, 1);
}

/* The kernel with the rim searches in the given number of lanes (cdist__cc_quick_lanes), over
 * sub-blocks of CD_SUB entries (their stages stay in the first-level cache). An FMA clone, like
 * the single query's stages: the fma() of the validation and framing are instructions there. */
enum { CD_SUB = 16 };
CD_FMA_CLONES static uint64_t cd_kernel(const cdist__job *job, int disk, double unit_tol, size_t lo, size_t count,
                                        int lanes)
{
    cd_entry x[CD_SUB];
    cdist__circle a[CD_SUB], e[CD_SUB];
    const cdist__cc_frame *f[CD_SUB];
    double t[CD_SUB], c[CD_SUB], s[CD_SUB], d2r[CD_SUB];
    int state[CD_SUB], at[CD_SUB]; /* the searches packed: f[j] is entry at[j]'s */
    uint64_t left = 0;
    for (int b = 0; b < (int)count; b += CD_SUB) {
        int n = (int)count - b < CD_SUB ? (int)count - b : CD_SUB, m = 0;
        uint64_t bad = cdist__circle_pairs_lanes(job, unit_tol, lo + (size_t)b, n, lanes, a, e);
        for (int k = 0; k < n; k++) {
            state[k] = bad >> k & 1 ? CD_STAGE_SCALAR : cd_start(job, disk, lo + (size_t)(b + k), a[k], e[k], &x[k]);
            if (state[k] == CD_STAGE_SEARCH) {
                at[m] = k;
                f[m++] = &x[k].st.f;
            }
        }
        uint64_t found = m ? cdist__cc_quick_lanes(f, m, lanes, t, c, s, d2r) : 0;
        for (int j = 0; j < m; j++) {
            int k = at[j];
            if (!(found >> j & 1)) state[k] = CD_STAGE_SCALAR;
            else cdist__cd_stage_finish(&x[k].st, t[j], d2r[j]);
        }
        for (int k = 0; k < n; k++) {
            if (state[k] == CD_STAGE_SCALAR) {
                left |= (uint64_t)1 << (b + k);
                continue;
            }
            double d2 = x[k].st.d2 < x[k].d2_other ? x[k].st.d2 : x[k].d2_other;
            if (!(d2 < INFINITY)) {
                left |= (uint64_t)1 << (b + k);
                continue;
            }
            job->distances[lo + (size_t)(b + k)] = sqrt(d2) * cdist__pow2(x[k].e);
        }
    }
    return left;
}

uint64_t cdist__cd_distance_kernel(const cdist__job *job, int disk, double unit_tol, size_t lo, size_t count)
{
    return cd_kernel(job, disk, unit_tol, lo, count, 0);
}
