/* fulgur analyze: a WAV's level figures, and its waveform envelope and
 * spectrogram as gnuplot-ready text (scripts/plot.gp draws them). */
#include <errno.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "common/calibration.h"
#include "common/commands.h"
#include "common/options.h"
#include "common/temp_file.h"
#include "common/wav_read.h"
#include "envelope.h"
#include "spectrogram.h"

#define ENVELOPE_POINTS 2000
#define P_REF_PA 20e-6

static const char about[] =
    "Prints the peak and RMS pressure of a WAV. A WAV that fulgur render wrote at\n"
    "another level (--gain-db, --normalize) carries its calibration, which turns its\n"
    "samples back into pascals; one without is taken to be in pascals.\n";

static const char notes[] =
    "Exit: 0 done, 1 runtime error, 2 bad arguments or unreadable input.\n";

typedef struct audio {
    wav_audio wav;  /* its samples turned into pascals */
    double peak_fs; /* the largest |sample| as stored */
} audio;

static int read_wav(const char *path, audio *a)
{
    char err[512];
    FILE *in = fopen(path, "rb");
    if (!in) {
        fprintf(stderr, "fulgur: %s: cannot open it: %s\n", path, strerror(errno));
        return -1;
    }
    wav_file file;
    int rc = wav_open(&file, in, path, err, sizeof err);
    if (rc == 0)
        rc = wav_read(&file, path, &a->wav, err, sizeof err);
    wav_close(&file);
    fclose(in);
    if (rc != 0) {
        fprintf(stderr, "fulgur: %s\n", err);
        return -1;
    }
    const wav_audio *w = &a->wav;
    if (w->declared_frames > w->frames)
        fprintf(stderr,
                "fulgur: warning: %s is truncated: %zu frames found, %llu declared; "
                "analysing the %zu\n",
                path, w->frames, (unsigned long long)w->declared_frames, w->frames);
    /* everything below is in pascals */
    a->peak_fs = 0;
    for (size_t i = 0; i < w->frames * (size_t)w->channels; i++) {
        a->peak_fs = fmax(a->peak_fs, fabs(w->samples[i]));
        w->samples[i] = (float)(w->samples[i] * w->full_scale_pa);
    }
    return 0;
}

typedef int (*writer)(FILE *out, const audio *a);

static int write_envelope(FILE *out, const audio *a)
{
    const wav_audio *w = &a->wav;
    return envelope_write(out, w->samples, w->frames, w->channels, w->rate_hz, ENVELOPE_POINTS);
}

static int write_spectrogram(FILE *out, const audio *a)
{
    const wav_audio *w = &a->wav;
    return spectrogram_write(out, w->samples, w->frames, w->channels, 0, w->rate_hz);
}

static int write_output(const char *path, writer write, const audio *a)
{
    char err[512];
    temp_file t;
    if (temp_file_open(&t, path, err, sizeof err) != 0) {
        fprintf(stderr, "fulgur: %s\n", err);
        return -1;
    }
    FILE *out = temp_file_stream(&t);
    if (!out || write(out, a) != 0) {
        fprintf(stderr, "fulgur: %s: cannot write\n", path);
        temp_file_abort(&t);
        return -1;
    }
    if (temp_file_commit(&t, err, sizeof err) != 0) {
        fprintf(stderr, "fulgur: %s\n", err);
        return -1;
    }
    return 0;
}

static void print_levels(const char *path, const audio *a)
{
    const wav_audio *w = &a->wav;
    double peak = 0, sum = 0;
    size_t count = w->frames * (size_t)w->channels;
    for (size_t i = 0; i < count; i++) {
        peak = fmax(peak, fabs(w->samples[i]));
        sum += (double)w->samples[i] * w->samples[i];
    }
    double rms = count ? sqrt(sum / (double)count) : 0;
    printf("%s: %d ch, %.0f Hz, %.3f s, peak %.6g Pa (%.1f dB SPL), rms %.6g Pa; "
           "peak %+.1f dBFS, full scale = %.6g Pa (%s)\n",
           path, w->channels, w->rate_hz, (double)w->frames / w->rate_hz, peak,
           20 * log10(fmax(peak, 1e-12) / P_REF_PA), rms, calibration_dbfs(a->peak_fs),
           w->full_scale_pa, w->calibrated ? "the file's calibration" : "no calibration: pascals");
}

int analyze_main(int argc, char **argv)
{
    const char *in = NULL, *wave = NULL, *spec = NULL;
    const option table[] = {
        {"--waveform", OPTION_TEXT, &wave, "W.dat",
         .help = "write a min/max envelope: time_s, then min and max in Pa per\n"
                 "channel"},
        {"--spectrogram", OPTION_TEXT, &spec, "S.dat",
         .help = "write \"time_s freq_hz level_db\" rows (dB re 20 uPa, 1/24-octave\n"
                 "bands, channel 0), a blank line after each time slice"},
        {0},
    };
    const command_line cl = {"fulgur analyze", "IN.wav", 1, 1, about, notes, table};
    size_t operands;
    options_result parsed = options_parse(&cl, argc, argv, &in, &operands);
    if (parsed != OPTIONS_OK)
        return parsed == OPTIONS_HELP ? CLI_OK : CLI_USAGE;
    char err[512];
    if ((wave && temp_file_check_output(wave, in, err, sizeof err) != 0) ||
        (spec && temp_file_check_output(spec, in, err, sizeof err) != 0)) {
        fprintf(stderr, "fulgur: %s\n", err);
        return CLI_USAGE;
    }
    audio a;
    if (read_wav(in, &a) != 0)
        return CLI_USAGE;
    print_levels(in, &a);
    int rc = CLI_OK;
    if ((wave && write_output(wave, write_envelope, &a) != 0) ||
        (spec && write_output(spec, write_spectrogram, &a) != 0))
        rc = CLI_RUNTIME;
    free(a.wav.samples);
    return rc;
}
