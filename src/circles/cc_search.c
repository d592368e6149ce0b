/* SPDX-License-Identifier: MIT */
/* The single circle-circle query's certified search (cdist__cc_quick; the method in
 * docs/circles.md): the bodies cc_search_body.h and cc_quick_body.h instantiated for 1, 4 and 8
 * lanes, the variant chosen at run time, and the angle tables shared with the batch kernel. */
#include <float.h>
#include <math.h>
#include <pthread.h>
#include <stdint.h>
#include <string.h>

#include "circles/cc_search.h"
#include "base/lanes/lanes.h"

cdist__cc_search_tab cdist__cc_tab;
static pthread_once_t cc_tab_once = PTHREAD_ONCE_INIT;

static void cc_tables_init(void)
{
    cdist__cc_search_tab *tb = &cdist__cc_tab;
    double step = 2.0 * M_PI / CK_GRID, sec = 1.0 / cos(0.5 * step);
    for (int j = 0; j < CK_GRID; j++) {
        tb->grid_c[j] = cos(j * step);
        tb->grid_s[j] = sin(j * step);
        tb->hull_c[j] = cos((j + 0.5) * step) * sec;
        tb->hull_s[j] = sin((j + 0.5) * step) * sec;
        tb->lane_index[j] = j;
    }
    tb->grid_tan2 = tan(0.5 * step) * tan(0.5 * step);
    tb->grid_half_c = cos(0.5 * step);
    tb->grid_half_s = sin(0.5 * step);
    double h = step;
    for (int l = 0; l < CK_LEVELS; l++, h *= 0.25) {
        tb->half[l] = h;
        tb->end_c[l] = cos(h);
        tb->end_s[l] = sin(h);
        double q = 0.125 * h, qsec = 1.0 / cos(q);
        for (int k = 0; k < 4; k++) {
            tb->sub_c[l][k] = cos(k * 0.25 * h);
            tb->sub_s[l][k] = sin(k * 0.25 * h);
            tb->hull_sub_c[l][k] = cos((2 * k + 1) * q) * qsec;
            tb->hull_sub_s[l][k] = sin((2 * k + 1) * q) * qsec;
        }
        tb->sub_tan2[l] = tan(q) * tan(q);
        for (int k = 0; k < 8; k++) {
            tb->zoom_c[l][k] = cos((k - 4) * 0.25 * h);
            tb->zoom_s[l][k] = sin((k - 4) * 0.25 * h);
            tb->zoom_hull_c[l][k] = cos((2 * k - 7) * q) * qsec;
            tb->zoom_hull_s[l][k] = sin((2 * k - 7) * q) * qsec;
        }
    }
}

void cdist__cc_search_tables(void) { pthread_once(&cc_tab_once, cc_tables_init); }

#define CC_LANES_BODY "circles/cc_quick_body.h"
#include "circles/cc_search_lanes.h"

CD_FMA_CLONES double cdist__cc_point_d2(const cdist__ring *rg, double s, double c, double sn)
{
    const ck_ring_1 r = {.alx = rg->al.x, .aly = rg->al.y, .alz = rg->al.z, .bex = rg->be.x, .bey = rg->be.y,
                         .bez = rg->be.z, .gax = rg->ga.x, .gay = rg->ga.y, .gaz = rg->ga.z, .ha = rg->ha,
                         .hb = rg->hb, .hc = rg->hc, .s = s};
    return cc_point_d2_1(&r, c, sn);
}

int cdist__cc_quick(const cdist__cc_frame *f, double *t, double *c, double *s)
{
    cdist__cc_search_tables();
#ifdef CD_X86_KERNELS
    int isa = cdist__lanes_isa();
    if (isa == CD_ISA_AVX512) return ck_quick_8(f, t, c, s);
    if (isa == CD_ISA_AVX2) return ck_quick_4(f, t, c, s);
#endif
    return ck_quick_1(f, t, c, s);
}
