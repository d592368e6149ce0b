/* SPDX-License-Identifier: MIT */
#ifndef CDIST_BASE_MEM_H
#define CDIST_BASE_MEM_H
/* Allocation of the large arrays (a scene's objects, tree, candidates and pair list): malloc or
 * realloc, then the kernel is asked to back them with transparent huge pages where it grants
 * them on request (Linux, THP mode "madvise"). A scene touches its ~200 bytes per object anew at
 * each build, and with 4 KiB pages the first-touch faults cost a large part of the build. The
 * advice may be refused or ignored; that is not an error. */
#include <stddef.h>

void *cdist__big_malloc(size_t bytes);
void *cdist__big_realloc(void *p, size_t bytes);

#endif
