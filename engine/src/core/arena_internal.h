/* First-fit allocation of contiguous segment ranges from the engine's
 * preallocated segment storage. Sim-thread only: the audio thread never
 * allocates or frees, it only uses the ranges it is handed. */
#ifndef FULGUR_ARENA_INTERNAL_H
#define FULGUR_ARENA_INTERNAL_H

#include <stdbool.h>
#include <stddef.h>

typedef struct fg_extent {
    size_t offset, length;
} fg_extent;

typedef struct fg_arena {
    fg_extent *free;    /* free ranges, sorted by offset, never adjacent */
    size_t count;       /* ranges in use of free[] */
    size_t max_ranges;  /* ranges free[] can hold */
} fg_arena;

/* capacity: units to manage; max_allocations: live allocations at most. */
bool fg_arena_init(fg_arena *arena, size_t capacity, size_t max_allocations);
void fg_arena_deinit(fg_arena *arena);
/* Returns false, changing nothing, if no free range is long enough. */
bool fg_arena_alloc(fg_arena *arena, size_t length, size_t *offset);
void fg_arena_free(fg_arena *arena, size_t offset, size_t length);

#endif
