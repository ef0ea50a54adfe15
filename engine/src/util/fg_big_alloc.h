/* Zeroed storage for big arrays: the engine's events and prepare scratch
 * (segment_capacity of them), its bus set's planes, a scene file's text and
 * its trees' nodes. The first write to each
 * page of fresh memory takes a page fault in the kernel; on a virtual
 * machine one costs ~10 us, so the events of 20 000 segments (4.6 MB)
 * cost more in faults than in their computing. Arrays of 256 KiB and more
 * are therefore mapped on their own, whole 2 MiB aligned to 2 MiB, and
 * advised to take transparent huge pages (Linux, where the kernel's
 * setting allows them): one fault per 2 MiB. Elsewhere, and for smaller
 * arrays, this is calloc.
 *
 * MAP_ANONYMOUS and madvise are neither ISO C nor plain POSIX: a file that
 * includes this header defines _DEFAULT_SOURCE before its first include.
 * [any thread; the caller owns what it gets] */
#ifndef FG_BIG_ALLOC_H
#define FG_BIG_ALLOC_H

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fg_array.h"

#if defined(__linux__)
#if !defined(_DEFAULT_SOURCE) && !defined(_GNU_SOURCE)
#error "fg_big_alloc.h: define _DEFAULT_SOURCE before the first include"
#endif
#include <sys/mman.h>
#endif

/* Before the array, its mapping's length (0: calloc's); 64 bytes keep the
 * array aligned for any item. */
#define FG_BIG_HEADER_BYTES 64u

#if defined(MADV_HUGEPAGE)
#define FG_BIG_HUGE_PAGE_BYTES ((size_t)2 << 20)
/* Mapping a huge page (zeroing 2 MiB) costs about what 15 faults of 4 KiB
 * pages do on the (virtual) machine measured, 0.15 ms against 10 us each:
 * an array of 64 pages or more is mapped, at most 1.75 MiB more resident. */
#define FG_BIG_MAPPED_MIN_BYTES ((size_t)256 << 10)
#endif

/* count zeroed items of size bytes; NULL if out of memory or the size
 * overflows. Free with fg_big_free. */
static inline void *fg_big_calloc(size_t count, size_t size)
{
    if (size > 0 && count > (SIZE_MAX - 3 * FG_BIG_HEADER_BYTES) / size)
        return NULL;
    size_t bytes = FG_BIG_HEADER_BYTES + count * size;
    char *base;
#if defined(MADV_HUGEPAGE)
    if (bytes >= FG_BIG_MAPPED_MIN_BYTES && bytes <= SIZE_MAX - 2 * FG_BIG_HUGE_PAGE_BYTES) {
        const size_t huge = FG_BIG_HUGE_PAGE_BYTES;
        size_t length = (bytes + huge - 1) & ~(huge - 1);
        /* one huge page more than needed, then the ends cut off so that
         * the mapping starts on a huge page's boundary */
        char *m = mmap(NULL, length + huge, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS,
                       -1, 0);
        if (m == MAP_FAILED)
            return NULL;
        base = (char *)(((uintptr_t)m + huge - 1) & ~(uintptr_t)(huge - 1));
        if (base > m)
            munmap(m, (size_t)(base - m));
        munmap(base + length, (size_t)(m + huge - base));
        /* advice: without transparent huge pages the pages stay small */
        (void)madvise(base, length, MADV_HUGEPAGE);
        memcpy(base, &length, sizeof length);
        return base + FG_BIG_HEADER_BYTES;
    }
#endif
    base = calloc(1, bytes);
    return base ? base + FG_BIG_HEADER_BYTES : NULL;
}

/* Frees p from fg_big_calloc or fg_big_grow; NULL: nothing. */
static inline void fg_big_free(void *p)
{
    if (!p)
        return;
    char *base = (char *)p - FG_BIG_HEADER_BYTES;
    size_t length;
    memcpy(&length, base, sizeof length);
#if defined(MADV_HUGEPAGE)
    if (length > 0) {
        munmap(base, length);
        return;
    }
#endif
    free(base);
}

/* fg_array_grow for fg_big_calloc's arrays: items moved to a new array of
 * at least need (> 0) items of item_bytes, the rest zero; NULL (items and
 * *capacity untouched) when memory runs out or the size would overflow. */
static inline void *fg_big_grow(void *items, size_t *capacity, size_t need, size_t item_bytes,
                                size_t first_capacity)
{
    if (need <= *capacity)
        return items;
    size_t cap = fg_array_capacity(*capacity, need, item_bytes, first_capacity);
    char *grown = cap ? fg_big_calloc(cap, item_bytes) : NULL;
    if (!grown)
        return NULL;
    if (*capacity)
        memcpy(grown, items, *capacity * item_bytes);
    fg_big_free(items);
    *capacity = cap;
    return grown;
}

#endif
