/* Memory the audio thread will write, mapped before it does: a fresh
 * allocation (calloc's above all) is often only reserved, and its first
 * write to each page takes a page fault in the kernel, a stall the audio
 * thread must not take. Writing a zero to every page at creation maps it;
 * for zeroed memory the contents stay as they were. [main-thread] */
#ifndef FULGUR_UTIL_FG_PREFAULT_H
#define FULGUR_UTIL_FG_PREFAULT_H

#include <stddef.h>

/* 4096 bytes: the smallest page of the platforms fulgur runs on (larger
 * pages are touched more than once, which is harmless) */
#define FG_PREFAULT_STRIDE 4096u

/* Maps bytes at p (zeroed memory: the zeros it writes change nothing). */
static inline void fg_prefault_zeroed(void *p, size_t bytes)
{
    volatile unsigned char *b = p;
    for (size_t i = 0; i < bytes; i += FG_PREFAULT_STRIDE)
        b[i] = 0;
}

#endif
