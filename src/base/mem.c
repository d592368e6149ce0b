/* SPDX-License-Identifier: MIT */
#include "base/mem.h"

#include <stdint.h>
#include <stdlib.h>
#if defined(__linux__)
#include <sys/mman.h>
#endif

/* Bytes: the x86-64 huge page, and the least array worth a system call (two huge pages, so that
 * at least one lies inside whatever the allocator's alignment). */
enum { HUGE_PAGE = 2 << 20, HUGE_MIN = 2 * HUGE_PAGE };

/* Advise the whole huge pages inside [p, p + bytes). */
static void *advise(void *p, size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if (p && bytes >= (size_t)HUGE_MIN) {
        const uintptr_t huge = (uintptr_t)HUGE_PAGE;
        uintptr_t lo = ((uintptr_t)p + huge - 1) & ~(huge - 1), hi = ((uintptr_t)p + bytes) & ~(huge - 1);
        if (hi > lo) (void)madvise((void *)lo, hi - lo, MADV_HUGEPAGE);
    }
#else
    (void)bytes;
#endif
    return p;
}

void *cdist__big_malloc(size_t bytes) { return advise(malloc(bytes), bytes); }
void *cdist__big_realloc(void *p, size_t bytes) { return advise(realloc(p, bytes), bytes); }
