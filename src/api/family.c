/* SPDX-License-Identifier: MIT */
/* The family table (api-priv.h) from the registry of kinds, and the registry's checks against
 * the public enum: every row has the number of its cdist_kind, rows are in that order without
 * gaps, and the families come before the contact kinds. */
#include "api/api-priv.h"

#define P CD_HAS(CDIST_METHOD_POLYNOMIAL)
#define R CD_HAS(CDIST_METHOD_ROBUST)
#define I CD_HAS(CDIST_METHOD_ITERATION)
#define A CD_HAS(CDIST_METHOD_AUTO)

const cdist__family cdist__family_table[CD_FAM_COUNT] = {
#define CD_KIND(KIND, number, name, letters, TA, TB, grad, methods, auto_method, ...)                    \
    [CD_FAM_##KIND] = {methods, CDIST_METHOD_##auto_method},
#define CD_CURVE_KIND(KIND, number, name, TB, methods, auto_method)                                      \
    [CD_FAM_##KIND] = {methods, CDIST_METHOD_##auto_method},
#include "api/kinds.def"
};

/* The registry's row positions, to check that numbers are dense and in order. */
enum {
#define CD_KIND(KIND, ...) ROW_##KIND,
#define CD_CURVE_KIND(KIND, ...) ROW_##KIND,
#define CD_CONTACT_KIND(KIND, ...) ROW_##KIND,
#include "api/kinds.def"
    ROW_COUNT
};
#define CHECK_ROW(KIND, number)                                                                                     \
    _Static_assert((int)CDIST_KIND_##KIND == (number), "registry number of " #KIND " is its cdist_kind's");         \
    _Static_assert(ROW_##KIND == (number), "registry row " #KIND " in the order of its number");
#define CHECK_FAMILY(KIND, number) CHECK_ROW(KIND, number) _Static_assert((number) < CD_FAM_COUNT, #KIND);
#define CD_KIND(KIND, number, ...) CHECK_FAMILY(KIND, number)
#define CD_CURVE_KIND(KIND, number, ...) CHECK_FAMILY(KIND, number)
#define CD_CONTACT_KIND(KIND, number, ...)                                                                          \
    CHECK_ROW(KIND, number) _Static_assert((number) >= CD_FAM_COUNT, "contact kind " #KIND " after the families");
#include "api/kinds.def"
_Static_assert((int)CDIST_KIND_SPHERE_DISK + 1 == ROW_COUNT, "one registry row per cdist_kind");
