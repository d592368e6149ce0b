/* SPDX-License-Identifier: MIT */
/* The large-array allocation (src/base/mem.c): the contents survive growth, and on Linux with
 * transparent huge pages on request ("madvise" or "always") the whole huge pages inside an
 * array of a few MiB carry the advice (VmFlags "hg" in /proc/self/smaps). Skipped (77) where the
 * system offers no such pages. Built against the internal library. */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "base/mem.h"

enum { HUGE = 2 << 20 };

/* 1: the mapping holding address p has VmFlags "hg"; 0: it has not; -1: smaps unreadable. */
static int advised(const void *p)
{
    FILE *f = fopen("/proc/self/smaps", "r");
    if (!f) return -1;
    char line[512];
    int in = 0, found = -1;
    uintptr_t x = (uintptr_t)p;
    while (fgets(line, sizeof line, f)) {
        unsigned long lo, hi;
        if (sscanf(line, "%lx-%lx ", &lo, &hi) == 2 && strchr(line, '-') < strchr(line, ' ')) {
            in = x >= lo && x < hi;
        } else if (in && !strncmp(line, "VmFlags:", 8)) {
            found = strstr(line, " hg") != NULL;
            break;
        }
    }
    fclose(f);
    return found;
}

static int thp_on_request(void)
{
    FILE *f = fopen("/sys/kernel/mm/transparent_hugepage/enabled", "r");
    if (!f) return 0;
    char mode[128] = "";
    int ok = fgets(mode, sizeof mode, f) && (strstr(mode, "[madvise]") || strstr(mode, "[always]"));
    fclose(f);
    return ok;
}

/* The first huge-page boundary inside [p, p + n), or NULL. */
static const char *inner(const char *p, size_t n)
{
    uintptr_t a = ((uintptr_t)p + HUGE - 1) & ~(uintptr_t)(HUGE - 1);
    return a + HUGE <= (uintptr_t)p + n ? (const char *)a : NULL;
}

int main(void)
{
    size_t n = 6 * (size_t)HUGE;
    unsigned char *p = cdist__big_malloc(n);
    CHECK(p != NULL, "big_malloc of %zu bytes", n);
    if (!p) return check_summary("mem");
    for (size_t i = 0; i < n; i++) p[i] = (unsigned char)(i * 7);
    unsigned char *q = cdist__big_realloc(p, 3 * n);
    CHECK(q != NULL, "big_realloc to %zu bytes", 3 * n);
    if (!q) {
        free(p);
        return check_summary("mem");
    }
    size_t bad = 0;
    for (size_t i = 0; i < n; i++) bad += q[i] != (unsigned char)(i * 7);
    CHECK(bad == 0, "%zu bytes changed by the growth", bad);
    memset(q + n, 1, 2 * n);
    /* small arrays are plain malloc: no system call, whatever their place */
    void *small = cdist__big_malloc(4096);
    CHECK(small != NULL, "a small array");
    free(small);
#if defined(__linux__)
    if (!thp_on_request()) {
        free(q);
        printf("mem: transparent huge pages not offered on request here; advice not checked\n");
        check_summary("mem");
        return 77;
    }
    const char *in = inner((const char *)q, 3 * n);
    int a = in ? advised(in) : -1;
    if (a < 0) {
        free(q);
        printf("mem: /proc/self/smaps not readable here; advice not checked\n");
        check_summary("mem");
        return 77;
    }
    CHECK(a == 1, "the huge pages inside a grown array of %zu bytes carry the advice (smaps: %d)", 3 * n, a);
    unsigned char *r = cdist__big_malloc(n);
    in = r ? inner((const char *)r, n) : NULL;
    a = in ? advised(in) : -1;
    CHECK(a == 1, "the huge pages inside a new array of %zu bytes carry the advice (smaps: %d)", n, a);
    free(r);
#endif
    free(q);
    return check_summary("mem");
}
