/* libFuzzer target for the aero texture file reader: any bytes either
 * decode into a texture that encodes back to the same bytes, or are
 * refused with a message naming the file, leaving the output untouched.
 * Each input is also tried with its CRC-32 recomputed, so that the checks
 * behind the checksum see mutated files too. Corpus:
 * corpus/fulgur_fuzz_aerotex/ (a small real texture). */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#include "common/aero_texture_file.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void one(const uint8_t *data, size_t size)
{
    fg_aero_texture *t = (fg_aero_texture *)&size;
    char err[512] = "";
    if (aero_texture_decode(data, size, "fuzz.aerotex", &t, err, sizeof err) != 0) {
        if (t != (fg_aero_texture *)&size || strncmp(err, "fuzz.aerotex: ", 14) != 0)
            abort();
        return;
    }
    uint8_t *again;
    size_t n;
    if (aero_texture_encode(t, &again, &n) != 0)
        abort();
    if (n != size || memcmp(again, data, size) != 0)
        abort();
    free(again);
    fg_aero_texture_destroy(t);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    one(data, size);
    if (size < 4)
        return 0;
    uint8_t *sealed = malloc(size);
    if (!sealed)
        return 0;
    memcpy(sealed, data, size);
    uint32_t crc = (uint32_t)crc32_z(0L, sealed, size - 4);
    for (int i = 0; i < 4; i++)
        sealed[size - 4 + i] = (uint8_t)(crc >> (8 * i));
    one(sealed, size);
    free(sealed);
    return 0;
}
