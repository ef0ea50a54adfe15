/* A stable LSD radix sort of (key, index) pairs by a double key, so the
 * arrival sort of a voice's events costs O(n), not O(n log n). */
#ifndef FULGUR_SORT_INTERNAL_H
#define FULGUR_SORT_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

typedef struct fg_sort_pair {
    uint64_t key;    /* from fg_sort_key */
    uint32_t index;
} fg_sort_pair;

/* A key whose unsigned order is the order of the doubles (no NaN). */
uint64_t fg_sort_key(double value);

/* Sorts pairs[0..n) by key, equal keys keeping their order; tmp holds n
 * pairs of scratch. */
void fg_sort_pairs(fg_sort_pair *pairs, fg_sort_pair *tmp, size_t n);

#endif
