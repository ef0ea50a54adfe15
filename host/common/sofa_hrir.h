/* A measured HRIR set from a SOFA file (AES69-2015, the
 * SimpleFreeFieldHRIR convention), read with libmysofa and handed to the
 * engine's binaural layout (fg_hrir_set, fulgur/engine.h): every
 * measurement's left and right impulse responses with the direction of
 * its source in the listener's frame (SOFA's: x ahead, y left, z up, the
 * engine's head frame), converted with libsamplerate's best sinc converter
 * when the file's rate is not the engine's (at load, never on the audio
 * thread). [main-thread] (it reads a file). */
#ifndef HOST_COMMON_SOFA_HRIR_H
#define HOST_COMMON_SOFA_HRIR_H

#include <stddef.h>

#include "fulgur/engine.h"

/* The measured MIT KEMAR set (normal pinna) that Debian's libmysofa1
 * installs: 710 directions, 512 taps at 44.1 kHz (Gardner & Martin 1995). */
#define SOFA_DEFAULT_FILE "/usr/share/libmysofa/MIT_KEMAR_normal_pinna.sofa"

typedef struct sofa_hrirs {
    fg_hrir_set set;     /* points into the arrays below */
    double *direction;
    float *left, *right;
    double file_rate_hz; /* the file's own rate */
} sofa_hrirs;

/* Reads path's responses at rate_hz into *out, diffuse-field equalized
 * with a flat low end (hrir_equalize.h). Returns 0, or -1 with a
 * message naming path and what is wrong in err: missing or unreadable, not
 * a SOFA file, not a valid SimpleFreeFieldHRIR set (libmysofa's check),
 * not two receivers (ears, dimension R), fewer than 16 measurements (M),
 * no taps (N) or more than FG_HRIR_MAX_LENGTH at rate_hz, Data.IR or
 * SourcePosition not of M x R x N and M x 3 values, Data.SamplingRate out
 * of 1 to 384 kHz, holding two rates or not in hertz, per-measurement
 * delays (Data.Delay other than 0), a non-finite tap, a failed conversion. On error *out is
 * zeroed and nothing is held. */
int sofa_hrirs_read(const char *path, double rate_hz, sofa_hrirs *out, char *err,
                    size_t err_size);

/* Frees the arrays and zeroes *h; a zeroed one is a no-op. */
void sofa_hrirs_free(sofa_hrirs *h);

#endif
