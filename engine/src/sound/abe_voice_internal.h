/* Abe et al.'s voice model (section 4.2, STEP1-5): each source point emits
 * an N-wave train built as the truncated harmonic series
 * (2/pi) sum_{n=1..N} (1/n) sin(n x), a sawtooth whose frequency and
 * amplitude fall with time.
 *
 * Decay laws (the paper tuned them by trial and error and gives none; these
 * are ours): instantaneous frequency f(t) = f0 exp(-t / freq_decay_s), so
 * the phase is x(t) = 2 pi f0 freq_decay_s (1 - exp(-t / freq_decay_s));
 * envelope exp(-t / amp_decay_s); the wave ends at -60 dB, t = amp_decay_s
 * ln 1000.
 *
 * Height (STEP3): sources higher above the ear sound lower. With the speed
 * of sound c = 331.5 + 0.6 t (t in C, eq. 4) and the standard-atmosphere
 * lapse rate of 6.5 K/km, t(h) = ground_temp_c - 0.0065 h, and
 * f0 = f_ground_hz c(h) / c(0): the source's wavelength scale is fixed, the
 * slower air aloft stretches it in time. The effect is mild: -5.6 % at
 * 5 km.
 *
 * Attenuation (STEP4): harmonic n, at frequency n f(t), loses
 * atten_db_m_hz2 (n f)^2 r decibels over distance r. The default 5e-9
 * dB/(m Hz^2) matches ISO 9613-1 at 1 kHz, 20 C, 70 % RH (5.0 dB/km).
 * Harmonics at or above 0.45 fs are left out (no aliasing).
 *
 * Loudness (STEP5): "inversely proportional to the distance squared" read
 * as intensity: energy ~ 1/r^2, so the peak is ref_peak_pa ref_distance_m
 * / r (r clamped to at least 1 m).
 *
 * Arrival: emit time + r / c. Each sample is the waveform at its time
 * (the series is band-limited by construction), computed from that time
 * alone, so rendering in any blocks gives identical samples. */
#ifndef FULGUR_ABE_VOICE_INTERNAL_H
#define FULGUR_ABE_VOICE_INTERNAL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "fulgur/result.h"

#define FG_ABE_MAX_HARMONICS 64
#define FG_ABE_LAPSE_K_PER_M 0.0065

typedef struct fg_abe_config {
    double f_ground_hz;      /* > 0: fundamental of a source at the ear's height; 80 */
    double ground_temp_c;    /* > -552.5 (c > 0): air temperature at the ear; 20 */
    double freq_decay_s;     /* > 0; 0.5 */
    double amp_decay_s;      /* > 0; 0.12: the wave lasts 0.83 s */
    unsigned harmonics;      /* N, 1..FG_ABE_MAX_HARMONICS; 16 */
    double atten_db_m_hz2;   /* >= 0; 5e-9 */
    double ref_distance_m;   /* > 0; 1000 */
    double ref_peak_pa;      /* > 0: peak at ref_distance_m; 1 */
} fg_abe_config;

/* The values in the comments above: what the engine plays. */
extern const fg_abe_config fg_abe_defaults;

/* The fundamental of a source height_m above the ear, Hz. */
double fg_abe_fundamental_hz(const fg_abe_config *p, double height_m);

/* One source as heard by one ear, prepared off the audio thread. */
typedef struct fg_abe_wave {
    double arrival_s;
    double f0_hz;
    double peak_pa;
    double gamma;        /* harmonic at f Hz has gain exp(-gamma f^2) */
    double freq_decay_s;
    double amp_decay_s;
    double duration_s;
    double rate;         /* Doppler: a moving ear hears the wave rate times as long; 1 */
    unsigned harmonics;
} fg_abe_wave;

/* Prepares w for a source at src and an ear at ear (metres, z up), emitted
 * at emit_s, travelling at c_m_s. p holds the ranges in the comments of
 * fg_abe_config (the tests vary fg_abe_defaults within them). */
void fg_abe_wave_init(fg_abe_wave *w, const fg_abe_config *p, const double src[3],
                      const double ear[3], double emit_s, double c_m_s);
/* Sets the parts of w that are p's alone, whatever the path: the decays,
 * the length and the harmonics (fg_abe_wave_init sets them too). */
void fg_abe_wave_set_decay(fg_abe_wave *w, const fg_abe_config *p);

/* Whether w's numbers are finite and its span's sample indices fit an
 * int64_t at fs_hz: what fg_abe_wave_span and fg_abe_wave_render need. */
bool fg_abe_wave_in_range(const fg_abe_wave *w, double fs_hz);

/* First and last sample (absolute index, sample k at time k / fs) that the
 * wave touches (w in range). */
void fg_abe_wave_span(const fg_abe_wave *w, double fs_hz, int64_t *first, int64_t *last);

/* Adds the wave's samples block_start .. block_start + n - 1 into out (w in
 * range). Returns false, having stopped before the first non-finite
 * sample, if one is not finite.
 * [audio-thread]: no allocation; cost per sample inside the span is one
 * sine, one cosine, three exponentials and a few operations per harmonic. */
bool fg_abe_wave_render(const fg_abe_wave *w, double fs_hz, int64_t block_start, float *out,
                        size_t n);

#endif
