/* SPDX-License-Identifier: MIT */
/* Distance kernels of circle-disk and disk-disk for cdist_batch_distance: the single query's
 * steps for many entries at once, in lanes where its arithmetic is written over lanes (cd_body.h,
 * the rim search), one by one elsewhere (cdist__cd_stage_finish); why the distances are the
 * single query's bit for bit: docs/architecture.md, "One source". An entry whose query takes
 * another path (a failed fast check, a zero radius, parallel planes, the rim search's engine) is
 * left to the scalar path. */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "batch-priv.h"
#include "api/api-priv.h"
#include "base/lanes/lanes.h"
#include "circles/circles-priv.h"

#define CDK_OFFER_PAIR(...) ((void)0) /* distances only: no pairs */
#define CD_LANES 1
#include "cd_kernel_body.h"
#ifdef CD_X86_KERNELS
#define CD_LANES 8
#include "cd_kernel_body.h"
#define CD_LANES 4
#include "cd_kernel_body.h"
#endif

/* The stages in one instruction set's lanes. */
typedef struct cd_variant {
    int lanes;
    unsigned (*face)(const cdist__circle *const *c, const cdist__circle *const *d, int neg, const double *bscale, int n,
                     cdk_lanes_1 *const *g, double *scale, double *min);
    unsigned (*rim_frame)(const cdist__circle *const *c, const cdist__circle *const *d, int n, cdist__cc_frame *const *f,
                          double *sc);
} cd_variant;

static const cd_variant *cd_variant_of(int lanes)
{
    static const cd_variant v1 = {1, cd_face_1, cd_rim_frame_1};
#ifdef CD_X86_KERNELS
    static const cd_variant v4 = {4, cd_face_4, cd_rim_frame_4}, v8 = {8, cd_face_8, cd_rim_frame_8};
    lanes = cdist__lanes_width(lanes);
    if (lanes == 8) return &v8;
    if (lanes == 4) return &v4;
#endif
    return &v1;
}

/* One entry: its stage and the frame's scale 2^e. */
typedef struct cd_entry {
    cdist__cd_stage st;
    double up;
} cd_entry;

enum { CD_SUB = 16 };
enum { CD_DONE, CD_SEARCH, CD_SCALAR };

/* Entries [lo, lo + n), n <= CD_SUB, up to the rim search: state[k] CD_SEARCH (the search is to
 * run on x[k].st.f, the circle in the disk's frame is in x[k].st.k) or CD_SCALAR. The rim search
 * runs first, with no cap: its minimum is a candidate like the others (the single query may
 * leave it out where it is far above the face's candidates; it cannot be the answer there), and
 * its distance, usually the answer, drops the face's candidates far above it before their
 * library calls. */
static void cd_stages(const cd_variant *v, const cdist__job *job, int disk, double unit_tol, size_t lo, int n,
                      cd_entry *x, int *state)
{
    cdist__circle a[CD_SUB], e[CD_SUB];
    const cdist__circle *pa[CD_SUB], *pe[CD_SUB];
    cdk_lanes_1 *g[CD_SUB];
    cdist__cc_frame *f[CD_SUB];
    double bscale[CD_SUB], up[CD_SUB], scale[CD_SUB], sc[CD_SUB];
    uint64_t swap = 0;
    for (int k = 0; disk && k < n; k++)
        if (cdist__circle_less(cdist__job_b(job, lo + (size_t)k), cdist__job_a(job, lo + (size_t)k)))
            swap |= (uint64_t)1 << k;
    uint64_t bad = cdist__circle_pairs_lanes(job, unit_tol, lo, n, v->lanes, swap, a, e, up, bscale);
    for (int k = 0; k < n; k++) {
        pa[k] = &x[k].st.c;
        pe[k] = &x[k].st.d;
        f[k] = &x[k].st.f;
        g[k] = &x[k].st.k.g;
        state[k] = bad >> k & 1 ? CD_SCALAR : CD_SEARCH;
        if (state[k] == CD_SCALAR) {
            x[k].st.c = x[k].st.d = (cdist__circle){v3(0, 0, 0), v3(0, 0, 1), v3(1, 0, 0), v3(0, 1, 0), 1.0};
            bscale[k] = 1.0;
            continue;
        }
        x[k].up = up[k];
        x[k].st.c = a[k];
        x[k].st.d = e[k];
        x[k].st.bscale = bscale[k];
        x[k].st.d2 = x[k].st.dcap = INFINITY;
    }
    for (int k0 = 0; k0 < n; k0 += v->lanes) {
        int m = n - k0 < v->lanes ? n - k0 : v->lanes;
        unsigned out = v->face(pa + k0, pe + k0, 0, bscale + k0, m, g + k0, scale + k0, NULL);
        out |= v->rim_frame(pa + k0, pe + k0, m, f + k0, sc + k0);
        for (int k = k0; k < k0 + m; k++) {
            if (out >> (k - k0) & 1) state[k] = CD_SCALAR;
            if (state[k] == CD_SCALAR) continue;
            x[k].st.scale = scale[k];
            x[k].st.sc = sc[k];
            cdist__cd_stage_ring(&x[k].st);
        }
    }
}

/* The candidates over the faces of the entries answered so far, from their rim minimum on: the
 * circle's over the disk's face, and for disk-disk the other half of dd_query (the rim of e over
 * a's face, e's centre the origin; no rim minima of its own: see dd_query). */
static void cd_faces(const cd_variant *v, int disk, int n, cd_entry *x, int *state)
{
    const cdist__circle *pa[CD_SUB], *pe[CD_SUB];
    double bscale[CD_SUB], min[CD_SUB];
    int at[CD_SUB], m = 0;
    for (int k = 0; k < n; k++)
        if (state[k] == CD_DONE) {
            at[m] = k;
            pa[m] = &x[k].st.c;
            pe[m] = &x[k].st.d;
            bscale[m] = x[k].st.bscale;
            min[m++] = x[k].st.d2;
        }
    for (int j0 = 0; j0 < m; j0 += v->lanes) {
        int w = m - j0 < v->lanes ? m - j0 : v->lanes;
        unsigned out = v->face(pa + j0, pe + j0, 0, bscale + j0, w, NULL, NULL, min + j0);
        if (disk) out |= v->face(pe + j0, pa + j0, 1, bscale + j0, w, NULL, NULL, min + j0);
        for (int j = j0; j < j0 + w; j++) {
            if (out >> (j - j0) & 1) state[at[j]] = CD_SCALAR;
            x[at[j]].st.d2 = min[j];
        }
    }
}

/* The kernel with the stages and rim searches in the given number of lanes (0: this CPU's
 * widest), over sub-blocks of CD_SUB entries (their stages stay in the first-level cache). */
CD_FMA_CLONES static uint64_t cd_kernel(const cdist__job *job, int disk, double unit_tol, size_t lo, size_t count,
                                        int lanes)
{
    const cd_variant *v = cd_variant_of(lanes);
    cd_entry x[CD_SUB];
    const cdist__cc_frame *f[CD_SUB];
    double t[CD_SUB], c[CD_SUB], s[CD_SUB], d2r[CD_SUB];
    int state[CD_SUB], at[CD_SUB]; /* the searches packed: f[j] is entry at[j]'s */
    uint64_t left = 0;
    for (int b = 0; b < (int)count; b += CD_SUB) {
        int n = (int)count - b < CD_SUB ? (int)count - b : CD_SUB, m = 0;
        cd_stages(v, job, disk, unit_tol, lo + (size_t)b, n, x, state);
        for (int k = 0; k < n; k++)
            if (state[k] == CD_SEARCH) {
                at[m] = k;
                f[m++] = &x[k].st.f;
            }
        uint64_t found = m ? cdist__cc_quick_lanes(f, m, lanes, t, c, s, d2r) : 0;
        for (int j = 0; j < m; j++) {
            int k = at[j];
            if (!(found >> j & 1)) {
                state[k] = CD_SCALAR;
            } else {
                cdist__cd_stage_finish(&x[k].st, t[j], d2r[j]);
                state[k] = CD_DONE;
            }
        }
        cd_faces(v, disk, n, x, state);
        for (int k = 0; k < n; k++) {
            double d2 = x[k].st.d2;
            if (state[k] == CD_SCALAR || !(d2 < INFINITY)) {
                left |= (uint64_t)1 << (b + k);
                continue;
            }
            job->distances[lo + (size_t)(b + k)] = sqrt(d2) * x[k].up;
        }
    }
    return left;
}

uint64_t cdist__cd_distance_kernel(const cdist__job *job, int disk, double unit_tol, size_t lo, size_t count)
{
    return cd_kernel(job, disk, unit_tol, lo, count, 0);
}
