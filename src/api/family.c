/* SPDX-License-Identifier: MIT */
/* The family table (api-priv.h): methods per query family. Rows of families owned by other
 * subsystems state today's behaviour; their owners keep them current. */
#include "internal.h"

#define P CD_HAS(CDIST_METHOD_POLYNOMIAL)
#define R CD_HAS(CDIST_METHOD_ROBUST)
#define I CD_HAS(CDIST_METHOD_ITERATION)
#define A CD_HAS(CDIST_METHOD_AUTO)
/* The curve and arc rows: one method (root bounding and bisection), answered as ROBUST. */

const cdist__family cdist__family_table[CD_FAM_COUNT] = {
    [CD_FAM_POINT_CIRCLE] = {"point_circle", A, CDIST_METHOD_AUTO, 0}, /* closed form */
    [CD_FAM_POINT_DISK] = {"point_disk", A, CDIST_METHOD_AUTO, 0},
    [CD_FAM_LINE_CIRCLE] = {"line_circle", P | R, CDIST_METHOD_ROBUST, P},
    [CD_FAM_RAY_CIRCLE] = {"ray_circle", P | R, CDIST_METHOD_ROBUST, P},
    [CD_FAM_SEGMENT_CIRCLE] = {"segment_circle", P | R, CDIST_METHOD_ROBUST, P},
    [CD_FAM_CIRCLE_CIRCLE] = {"circle_circle", P | R | I, CDIST_METHOD_ROBUST, P},
    [CD_FAM_LINE_DISK] = {"line_disk", P | R, CDIST_METHOD_ROBUST, P},
    [CD_FAM_RAY_DISK] = {"ray_disk", P | R, CDIST_METHOD_ROBUST, P},
    [CD_FAM_SEGMENT_DISK] = {"segment_disk", P | R, CDIST_METHOD_ROBUST, P},
    [CD_FAM_CIRCLE_DISK] = {"circle_disk", P | R, CDIST_METHOD_ROBUST, P},
    [CD_FAM_DISK_DISK] = {"disk_disk", P | R, CDIST_METHOD_ROBUST, P},
    [CD_FAM_CURVE_CIRCLE] = {"curve_circle", R, CDIST_METHOD_ROBUST, 0},
    [CD_FAM_CURVE_DISK] = {"curve_disk", R, CDIST_METHOD_ROBUST, 0},
    [CD_FAM_ARC_CIRCLE] = {"arc_circle", R, CDIST_METHOD_ROBUST, 0},
    [CD_FAM_ARC_ARC] = {"arc_arc", R, CDIST_METHOD_ROBUST, 0},
    [CD_FAM_SEGMENT_ARC] = {"segment_arc", R, CDIST_METHOD_ROBUST, 0},
    [CD_FAM_ARC_DISK] = {"arc_disk", R, CDIST_METHOD_ROBUST, 0},
    [CD_FAM_HELIX_CIRCLE] = {"helix_circle", R, CDIST_METHOD_ROBUST, 0},
    [CD_FAM_HELIX_DISK] = {"helix_disk", R, CDIST_METHOD_ROBUST, 0},
    [CD_FAM_BEZIER3_CIRCLE] = {"bezier3_circle", R, CDIST_METHOD_ROBUST, 0},
    [CD_FAM_BEZIER3_DISK] = {"bezier3_disk", R, CDIST_METHOD_ROBUST, 0},
};
