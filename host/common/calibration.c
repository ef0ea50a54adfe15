/* The calibration comment of a WAV. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "calibration.h"

static const char prefix[] = "fulgur calibration: full scale = ";

int calibration_write(audio_wav *wav, double full_scale_pa, char *err, size_t err_size)
{
    char text[96], why[256];
    snprintf(text, sizeof text, "%s%.9g Pa", prefix, full_scale_pa);
    if (audio_wav_comment(wav, text, why, sizeof why) != 0) {
        snprintf(err, err_size, "writing the calibration into the WAV: %s", why);
        return -1;
    }
    return 0;
}

bool calibration_parse(const char *comment, double *full_scale_pa)
{
    const char *at = comment ? strstr(comment, prefix) : NULL;
    if (!at)
        return false;
    char *end;
    double v = strtod(at + sizeof prefix - 1, &end);
    if (end == at + sizeof prefix - 1 || strncmp(end, " Pa", 3) != 0 || !isfinite(v) || v <= 0)
        return false;
    *full_scale_pa = v;
    return true;
}

bool calibration_read(SNDFILE *wav, double *full_scale_pa)
{
    *full_scale_pa = CALIBRATION_DEFAULT_PA;
    return calibration_parse(sf_get_string(wav, SF_STR_COMMENT), full_scale_pa);
}

double calibration_dbfs(double peak)
{
    return peak > 0 ? 20 * log10(peak) : -INFINITY;
}
