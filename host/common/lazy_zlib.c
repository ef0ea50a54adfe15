/* zlib for the fulgur program, opened on the first call (lazy_library.h):
 * an aerodynamic texture file's CRC. */
#include <pthread.h>
#include <zlib.h>

#include "lazy_library.h"

static struct {
    __typeof__(crc32_z) *crc32_z;
} api;

static pthread_once_t once = PTHREAD_ONCE_INIT;

static void load(void)
{
    const library_symbol symbols[] = {LIBRARY_SYMBOL(api.crc32_z, crc32_z)};
    lazy_library_load(FULGUR_ZLIB_SONAME, symbols, 1);
}

uLong crc32_z(uLong crc, const Bytef *buf, z_size_t len)
{
    pthread_once(&once, load);
    return api.crc32_z(crc, buf, len);
}
