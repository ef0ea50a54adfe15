/* libFuzzer target for the WAV reader of fulgur analyze and a fire's
 * training clip (host/common/wav_file.c, wav_read.c): the fuzz bytes are
 * a file, opened from memory by wav_open, which walks its chunks and shows
 * libsndfile a header of its own. A file that opens is either read whole,
 * with a rate inside the reader's range, at least one channel, its
 * calibration finite and positive and its declared frames no fewer than
 * those found; or refused with a message naming it. Corpus:
 * corpus/fulgur_fuzz_wav/ (short float, PCM, RF64, calibrated and
 * truncated WAVs from tests/fuzz/write_seeds.py, and what the fuzzer found:
 * LIST chunks libsndfile's own parser loops on). A hang is a timeout. */
#define _POSIX_C_SOURCE 200809L /* fmemopen */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "common/wav_read.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* err names the file */
static void check_message(const char *err)
{
    if (strncmp(err, "fuzz.wav: ", 10) != 0)
        abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size == 0)
        return 0;
    FILE *in = fmemopen((void *)data, size, "rb");
    if (!in)
        abort();
    char err[512] = "";
    wav_file file;
    if (wav_open(&file, in, "fuzz.wav", err, sizeof err) != 0) {
        check_message(err);
        fclose(in);
        return 0;
    }
    if (file.held_bytes > file.declared_bytes)
        abort();
    wav_audio w;
    if (wav_read(&file, "fuzz.wav", &w, err, sizeof err) == 0) {
        if (!w.samples || w.channels < 1 || w.rate_hz < 1 || w.rate_hz > WAV_READ_MAX_RATE_HZ ||
            w.declared_frames < w.frames || !isfinite(w.full_scale_pa) || w.full_scale_pa <= 0)
            abort();
        /* every sample read is there to be touched */
        volatile float sink = 0;
        for (size_t i = 0; i < w.frames * (size_t)w.channels; i++)
            sink += w.samples[i];
        (void)sink;
        free(w.samples);
    } else {
        check_message(err);
    }
    wav_close(&file);
    fclose(in);
    return 0;
}
