#include <string.h>

#include "sort_internal.h"

#define DIGIT_BITS 11
#define BUCKETS (1u << DIGIT_BITS)
#define PASSES 6 /* 6 * 11 >= 64 */

uint64_t fg_sort_key(double value)
{
    uint64_t bits;
    memcpy(&bits, &value, sizeof bits);
    /* negatives: reverse their order; positives: above every negative */
    return bits >> 63 ? ~bits : bits | (UINT64_C(1) << 63);
}

void fg_sort_pairs(fg_sort_pair *pairs, fg_sort_pair *tmp, size_t n)
{
    size_t count[BUCKETS];
    fg_sort_pair *src = pairs, *dst = tmp;
    for (int pass = 0; pass < PASSES; pass++) {
        int shift = pass * DIGIT_BITS;
        memset(count, 0, sizeof count);
        for (size_t i = 0; i < n; i++)
            count[(src[i].key >> shift) & (BUCKETS - 1)]++;
        if (count[(src[0].key >> shift) & (BUCKETS - 1)] == n)
            continue; /* every key shares this digit */
        size_t sum = 0;
        for (size_t b = 0; b < BUCKETS; b++) {
            size_t c = count[b];
            count[b] = sum;
            sum += c;
        }
        for (size_t i = 0; i < n; i++)
            dst[count[(src[i].key >> shift) & (BUCKETS - 1)]++] = src[i];
        fg_sort_pair *t = src;
        src = dst;
        dst = t;
    }
    if (src != pairs)
        memcpy(pairs, src, n * sizeof *pairs);
}
