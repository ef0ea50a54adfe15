/* Zeroed storage for the engine's big arrays (the events and the prepare
 * scratch of segment_capacity). Its first write to each page takes a page
 * fault in the kernel; on a virtual machine one costs ~10 us, so the
 * events of 20 000 segments (4.6 MB) cost more in faults than in their
 * computing. Arrays of 256 KiB and more are therefore mapped on their
 * own, whole 2 MiB aligned to 2 MiB, and advised to take transparent huge
 * pages (Linux, where the kernel's setting allows them): one fault per
 * 2 MiB. Elsewhere, and for smaller arrays, this is calloc.
 * [main-thread] */
#ifndef FULGUR_CORE_BIG_ALLOC_INTERNAL_H
#define FULGUR_CORE_BIG_ALLOC_INTERNAL_H

#include <stddef.h>

/* count zeroed items of size bytes; NULL if out of memory or the size
 * overflows. Free with fg_big_free and the same count and size. */
void *fg_big_calloc(size_t count, size_t size);
/* Frees p (NULL: nothing) from fg_big_calloc(count, size). */
void fg_big_free(void *p, size_t count, size_t size);

#endif
