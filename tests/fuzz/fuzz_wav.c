/* libFuzzer target for fulgur analyze's WAV reader (host/common/wav_read.c):
 * the fuzz bytes are a sound file, opened by libsndfile from memory. A file
 * that opens is either read whole, with a rate inside the reader's range,
 * at least one channel, its calibration finite and positive and its
 * declared frames no fewer than those found; or refused with a message.
 * Corpus: corpus/fulgur_fuzz_wav/ (short float, PCM, RF64, calibrated and
 * truncated WAVs; tests/fuzz/write_seeds.py wrote them). The chunk walk
 * that guards libsndfile runs first, on the same bytes. */
#define _POSIX_C_SOURCE 200809L /* fmemopen */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "common/wav_read.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

typedef struct memory {
    const uint8_t *data;
    sf_count_t size, at;
} memory;

static sf_count_t mem_length(void *user)
{
    return ((memory *)user)->size;
}

static sf_count_t mem_seek(sf_count_t offset, int whence, void *user)
{
    memory *m = user;
    sf_count_t base = whence == SEEK_SET ? 0 : whence == SEEK_CUR ? m->at : m->size;
    /* 0 <= base + offset <= size, tested without forming a sum that can
     * overflow (a file's 64-bit chunk sizes ask for seeks near 2^63) */
    if (offset < -base || offset > m->size - base)
        return -1;
    return m->at = base + offset;
}

static sf_count_t mem_read(void *out, sf_count_t count, void *user)
{
    memory *m = user;
    sf_count_t n = count < m->size - m->at ? count : m->size - m->at;
    memcpy(out, m->data + m->at, (size_t)n);
    m->at += n;
    return n;
}

static sf_count_t mem_write(const void *in, sf_count_t count, void *user)
{
    (void)in, (void)count, (void)user;
    return 0;
}

static sf_count_t mem_tell(void *user)
{
    return ((memory *)user)->at;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char err[256] = "";
    FILE *in = size ? fmemopen((void *)data, size, "rb") : NULL;
    if (in) {
        int bad = wav_check_chunks(in, "fuzz.wav", err, sizeof err);
        fclose(in);
        if (bad) {
            if (strncmp(err, "fuzz.wav: ", 10) != 0)
                abort();
            return 0;
        }
    }
    SF_VIRTUAL_IO io = {mem_length, mem_seek, mem_read, mem_write, mem_tell};
    memory m = {data, (sf_count_t)size, 0};
    SF_INFO info = {0};
    SNDFILE *f = sf_open_virtual(&io, SFM_READ, &info, &m);
    if (!f)
        return 0;
    wav_audio w;
    if (wav_read(f, &info, "fuzz.wav", &w, err, sizeof err) == 0) {
        if (!w.samples || w.channels < 1 || w.rate_hz < 1 || w.rate_hz > WAV_READ_MAX_RATE_HZ ||
            w.declared_frames < w.frames || !isfinite(w.full_scale_pa) || w.full_scale_pa <= 0)
            abort();
        /* every sample read is there to be touched */
        volatile float sink = 0;
        for (size_t i = 0; i < w.frames * (size_t)w.channels; i++)
            sink += w.samples[i];
        (void)sink;
        free(w.samples);
    } else if (strncmp(err, "fuzz.wav: ", 10) != 0) {
        abort();
    }
    sf_close(f);
    return 0;
}
