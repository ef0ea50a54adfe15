/* Reading a sound file whole for analysis (wav_read.h). */
#include "wav_read.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "calibration.h"
#include "text_escape.h"

/* Bytes per sample of the fixed-width encodings a WAV's data size can be
 * counted in; 0 for the others (compressed: the size says nothing simple). */
static unsigned sample_bytes(int format)
{
    switch (format & SF_FORMAT_SUBMASK) {
    case SF_FORMAT_PCM_S8:
    case SF_FORMAT_PCM_U8:
    case SF_FORMAT_ULAW:
    case SF_FORMAT_ALAW:
        return 1;
    case SF_FORMAT_PCM_16:
        return 2;
    case SF_FORMAT_PCM_24:
        return 3;
    case SF_FORMAT_PCM_32:
    case SF_FORMAT_FLOAT:
        return 4;
    case SF_FORMAT_DOUBLE:
        return 8;
    default:
        return 0;
    }
}

/* The frames a WAV's data chunk declares; frames when it cannot say. A
 * size of 0 or 0xFFFFFFFF is what streaming writers leave: "not known". */
static uint64_t declared_frames(SNDFILE *f, const SF_INFO *info, uint64_t frames)
{
    unsigned width = sample_bytes(info->format);
    if ((info->format & SF_FORMAT_TYPEMASK) != SF_FORMAT_WAV || width == 0)
        return frames;
    SF_CHUNK_INFO chunk = {.id = "data", .id_size = 4};
    SF_CHUNK_ITERATOR *it = sf_get_chunk_iterator(f, &chunk);
    if (!it || sf_get_chunk_size(it, &chunk) != SF_ERR_NO_ERROR || chunk.datalen == 0 ||
        chunk.datalen == UINT32_MAX)
        return frames;
    uint64_t declared = chunk.datalen / ((uint64_t)width * (uint64_t)info->channels);
    return declared > frames ? declared : frames;
}

static uint32_t chunk_size(const unsigned char *b, bool big_endian)
{
    return big_endian ? (uint32_t)b[0] << 24 | (uint32_t)b[1] << 16 | (uint32_t)b[2] << 8 | b[3]
                      : (uint32_t)b[3] << 24 | (uint32_t)b[2] << 16 | (uint32_t)b[1] << 8 | b[0];
}

/* The id of the chunk header at b, escaped for a message. */
static void chunk_id(const unsigned char *b, char *id, size_t id_size)
{
    char raw[5] = {0};
    memcpy(raw, b, 4);
    text_escape(id, id_size, raw);
}

/* Whether id (4 bytes) is one of ids[0 .. count). */
static bool id_in(const unsigned char *id, const char *const *ids, size_t count)
{
    for (size_t k = 0; k < count; k++)
        if (memcmp(id, ids[k], 4) == 0)
            return true;
    return false;
}

/* Walks the LIST chunk at byte at (bytes long, of which the file holds
 * avail) as libsndfile 1.2's LIST parser (wavlike_subchunk_parse) does, and
 * refuses it where that parser would loop forever or lose its place: from
 * the list type on it reads an id, and for ids other than INFO and adtl a
 * 32-bit size, rounded up to even; a size it does not know is skipped
 * after a bounds check in 32-bit arithmetic, so a size of 2^31 or more that
 * wraps the check past it is a seek backwards, and the parser reads the
 * same bytes again (a 98-byte file, found by fulgur_fuzz_wav). An 'exif'
 * list (parsed by rules of its own, which count bytes they do not read)
 * and a 'data' id inside a list (where the parser backs out into the file's
 * chunks, no longer on their boundaries) are refused as well, and so is a
 * list of 2 GiB or more. Ids it knows bound their own sizes; those that
 * end its walk end this one. */
static int check_list(FILE *in, const char *name, long at, uint32_t bytes, long avail,
                      bool big_endian, char *err, size_t err_size)
{
    static const char *const markers[] = {"INFO", "adtl"};
    static const char *const ends[] = {"DISP", "ltxt", "note", "\0\0\0\0"};
    static const char *const lost[] = {"exif", "data"};
    static const char *const strings[] = {"ISFT", "ICOP", "IARL", "IART", "ICMT", "ICRD", "IENG",
                                          "IGNR", "INAM", "IPRD", "ISBJ", "ISRC", "IAUT", "ITRK"};
    const uint32_t length = (long)bytes < avail ? bytes : (uint32_t)avail;
    if (length <= 8) /* read as one id and skipped */
        return 0;
    if (length >= UINT32_C(0x80000000)) { /* (where the parser's count of bytes read wraps) */
        snprintf(err, err_size, "%s: its 'LIST' chunk at byte %ld claims %u bytes, 2 GiB or more",
                 name, at, bytes);
        return -1;
    }
    /* each step moves on by at least 4 bytes, and read + size stays below
     * 2^32 (both below 2^31): the walk ends */
    for (uint32_t read = 0; read < length;) {
        unsigned char head[8];
        const long here = at + 8 + (long)read;
        if (fseek(in, here, SEEK_SET) != 0 || fread(head, 1, 4, in) != 4)
            return 0;
        read += 4;
        if (id_in(head, markers, 2))
            continue;
        if (id_in(head, lost, 2)) {
            snprintf(err, err_size,
                     "%s: its 'LIST' chunk at byte %ld holds '%.4s' at byte %ld, which "
                     "libsndfile's parser of lists cannot be trusted to read",
                     name, at, (const char *)head, here);
            return -1;
        }
        if (id_in(head, ends, sizeof ends / sizeof ends[0]) || fread(head + 4, 1, 4, in) != 4)
            return 0;
        read += 4;
        uint32_t size = chunk_size(head + 4, big_endian);
        size += size & 1u;
        if (memcmp(head, "labl", 4) == 0) {
            size -= 4;
            size += size & 1u;
            if (size < 1 || size >= 2048 || size >= length)
                return 0; /* it skips to the list's end */
            read += 4 + size;
            continue;
        }
        if (id_in(head, strings, sizeof strings / sizeof strings[0])) {
            if (size >= 2048 || size >= length)
                return 0;
            read += size;
            continue;
        }
        if (read + size > length) /* (it skips to the list's end) */
            return 0;
        if (size >= UINT32_C(0x80000000)) {
            char id[4 * 4 + 1];
            chunk_id(head, id, sizeof id);
            snprintf(err, err_size,
                     "%s: its 'LIST' chunk at byte %ld holds a '%s' at byte %ld claiming %u "
                     "bytes, which libsndfile reads as a step backwards, forever",
                     name, at, id, here, chunk_size(head + 4, big_endian));
            return -1;
        }
        read += size;
        if (size >= length)
            return 0;
    }
    return 0;
}

int wav_check_chunks(FILE *in, const char *name, char *err, size_t err_size)
{
    unsigned char head[12];
    if (fseek(in, 0, SEEK_END) != 0)
        return 0;
    const long size = ftell(in);
    if (size < 12 || fseek(in, 0, SEEK_SET) != 0 || fread(head, 1, 12, in) != 12)
        return 0;
    const bool rf64 = memcmp(head, "RF64", 4) == 0, big_endian = memcmp(head, "RIFX", 4) == 0;
    if ((!rf64 && !big_endian && memcmp(head, "RIFF", 4) != 0) || memcmp(head + 8, "WAVE", 4) != 0)
        return 0;
    /* each step moves on by at least 8 bytes: the walk ends */
    for (long at = 12; at + 8 <= size;) {
        unsigned char chunk[8];
        if (fseek(in, at, SEEK_SET) != 0 || fread(chunk, 1, 8, in) != 8)
            return 0;
        const uint32_t bytes = chunk_size(chunk + 4, big_endian);
        if (memcmp(chunk, "data", 4) == 0 || (rf64 && bytes == UINT32_MAX))
            return 0; /* the samples (cut short: wav_read says so), or ds64 sizes */
        if ((uint64_t)bytes > (uint64_t)(size - at - 8)) {
            char id[4 * 4 + 1];
            chunk_id(chunk, id, sizeof id);
            snprintf(err, err_size, "%s: its '%s' chunk at byte %ld claims %u bytes, past the "
                                    "file's end (%ld bytes)", name, id, at, bytes, size);
            return -1;
        }
        if (memcmp(chunk, "LIST", 4) == 0 &&
            check_list(in, name, at, bytes, size - at - 8, big_endian, err, err_size) != 0)
            return -1;
        at += 8 + (long)bytes + (long)(bytes & 1u);
    }
    return 0;
}

int wav_read(SNDFILE *f, const SF_INFO *info, const char *name, wav_audio *out, char *err,
             size_t err_size)
{
    memset(out, 0, sizeof *out);
    if (info->samplerate < 1 || info->samplerate > WAV_READ_MAX_RATE_HZ) {
        snprintf(err, err_size, "%s: a sample rate of %d Hz, outside 1..%d", name,
                 info->samplerate, WAV_READ_MAX_RATE_HZ);
        return -1;
    }
    if (info->channels < 1 || info->frames < 0) {
        snprintf(err, err_size, "%s: %d channels, %lld frames", name, info->channels,
                 (long long)info->frames);
        return -1;
    }
    size_t channels = (size_t)info->channels;
    if ((uint64_t)info->frames > SIZE_MAX / sizeof(float) / channels) {
        snprintf(err, err_size, "%s: %lld frames of %d channels do not fit in memory", name,
                 (long long)info->frames, info->channels);
        return -1;
    }
    size_t frames = (size_t)info->frames;
    float *samples = malloc((frames ? frames : 1) * channels * sizeof *samples);
    if (!samples) {
        snprintf(err, err_size, "%s: no memory for %zu frames", name, frames);
        return -1;
    }
    if (sf_readf_float(f, samples, info->frames) != info->frames) {
        snprintf(err, err_size, "%s: cannot read %zu frames", name, frames);
        free(samples);
        return -1;
    }
    out->samples = samples;
    out->frames = frames;
    out->declared_frames = declared_frames(f, info, frames);
    out->channels = info->channels;
    out->rate_hz = info->samplerate;
    out->calibrated = calibration_read(f, &out->full_scale_pa);
    return 0;
}
