/* The aerodynamic sound texture file (docs/aero-texture-format.md): a
 * little-endian header with a magic and a version, the shape, the sources,
 * the directions and their float32 samples, and a CRC-32 of it all. Files
 * are written under a temporary name and renamed when complete; reading
 * checks every size, value and the checksum, and says what is wrong with
 * the file by name. The engine takes textures from memory
 * (fg_aero_texture_create); this is the host's side. */
#ifndef HOST_AERO_TEXTURE_FILE_H
#define HOST_AERO_TEXTURE_FILE_H

#include <stddef.h>
#include <stdint.h>

#include "fulgur/aero.h"

#define AERO_TEXTURE_MAGIC "FGAEROTX"
#define AERO_TEXTURE_VERSION 1u

/* The bytes of a file holding t, in a new buffer the caller frees.
 * Returns 0, or -1 when out of memory. */
int aero_texture_encode(const fg_aero_texture *t, uint8_t **bytes, size_t *size);

/* A texture from the bytes of a file called name (for the messages).
 * Returns 0 and *out, or -1 with "NAME: what is wrong" in err (and *out
 * untouched). */
int aero_texture_decode(const uint8_t *bytes, size_t size, const char *name,
                        fg_aero_texture **out, char *err, size_t err_size);

/* Writes t to path: all of it, or nothing (an older file there is kept).
 * Returns 0, or -1 with a message naming path in err. */
int aero_texture_save(const fg_aero_texture *t, const char *path, char *err, size_t err_size);

/* Reads and decodes path. Returns 0, or -1 with a message in err. */
int aero_texture_load(const char *path, fg_aero_texture **out, char *err, size_t err_size);

#endif
