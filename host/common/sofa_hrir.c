#include <errno.h>
#include <math.h>
#include <mysofa.h>
#include <samplerate.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hrir_equalize.h"
#include "sofa_hrir.h"

void sofa_hrirs_free(sofa_hrirs *h)
{
    free(h->direction);
    free(h->left);
    free(h->right);
    memset(h, 0, sizeof *h);
}

static const char *mysofa_reason(int code)
{
    switch (code) {
    case MYSOFA_INVALID_FORMAT: return "not an HDF5/netCDF-4 SOFA file";
    case MYSOFA_UNSUPPORTED_FORMAT: return "an HDF5 layout libmysofa does not read";
    case MYSOFA_NO_MEMORY: return "out of memory";
    case MYSOFA_READ_ERROR: return "read error";
    case MYSOFA_INVALID_ATTRIBUTES: return "missing or wrong SOFA attributes (not SimpleFreeFieldHRIR)";
    case MYSOFA_INVALID_DIMENSIONS: return "wrong dimensions (M, R, N, C)";
    case MYSOFA_INVALID_DIMENSION_LIST: return "wrong dimension list of a variable";
    case MYSOFA_INVALID_COORDINATE_TYPE: return "an unknown coordinate type";
    case MYSOFA_ONLY_EMITTER_WITH_ECI_SUPPORTED: return "emitters other than one per measurement";
    case MYSOFA_ONLY_DELAYS_WITH_IR_OR_MR_SUPPORTED: return "delays of an unsupported shape";
    case MYSOFA_ONLY_THE_SAME_SAMPLING_RATE_SUPPORTED: return "more than one sampling rate";
    case MYSOFA_RECEIVERS_WITH_RCI_SUPPORTED: return "receivers of an unsupported shape";
    case MYSOFA_RECEIVERS_WITH_CARTESIAN_SUPPORTED: return "receivers not in cartesian coordinates";
    case MYSOFA_INVALID_RECEIVER_POSITIONS: return "receivers not to the left and right";
    case MYSOFA_ONLY_SOURCES_WITH_MC_SUPPORTED: return "source positions of an unsupported shape";
    default: return "libmysofa internal error";
    }
}

/* Every response of the set (m measurements x 2 ears of n taps at the
 * file's rate, as Data.IR holds them) to taps at ratio times that rate,
 * into left and right (m x taps each). One converter state serves them
 * all, reset between responses: a sinc converter's buffers are large to
 * make. 0, or -1 with why. */
static int convert(const float *ir, unsigned m, unsigned n, double ratio, size_t taps,
                   float *left, float *right, char *why, size_t why_size)
{
    int e = 0;
    SRC_STATE *state = ratio == 1.0 ? NULL : src_new(SRC_SINC_BEST_QUALITY, 1, &e);
    if (ratio != 1.0 && !state) {
        snprintf(why, why_size, "resampling failed: %s", src_strerror(e));
        return -1;
    }
    for (size_t r = 0; e == 0 && r < 2 * (size_t)m; r++) { /* response r = 2s + ear */
        float *to = (r % 2 == 0 ? left : right) + r / 2 * taps;
        memset(to, 0, taps * sizeof *to);
        if (!state) {
            memcpy(to, ir + r * n, n * sizeof *to);
            continue;
        }
        SRC_DATA src = {.data_in = ir + r * n, .input_frames = (long)n, .data_out = to,
                        .output_frames = (long)taps, .src_ratio = ratio, .end_of_input = 1};
        e = src_reset(state);
        if (e == 0)
            e = src_process(state, &src);
    }
    if (e != 0)
        snprintf(why, why_size, "resampling failed: %s", src_strerror(e));
    if (state)
        src_delete(state);
    return e == 0 ? 0 : -1;
}

/* The dimensions the engine needs, each named when wrong: 0, or -1 with
 * why. Run before libmysofa's own check too, whose answer for a wrong
 * dimension names none. */
static int check_dimensions(const struct MYSOFA_HRTF *hrtf, char *why, size_t why_size)
{
    const unsigned m = hrtf->M, r = hrtf->R, n = hrtf->N;
    if (r != 2) {
        snprintf(why, why_size, "%u receivers (dimension R): expected 2 (left and right ear)", r);
        return -1;
    }
    if (m < 16 || m > FG_HRIR_MAX_COUNT) {
        snprintf(why, why_size, "%u measurements (dimension M): expected 16 to %u", m,
                 FG_HRIR_MAX_COUNT);
        return -1;
    }
    if (n == 0) {
        snprintf(why, why_size, "Data.IR has no taps (dimension N is 0)");
        return -1;
    }
    if ((size_t)hrtf->DataIR.elements != (size_t)m * r * n) {
        snprintf(why, why_size, "Data.IR holds %u values: expected M x R x N = %u x %u x %u",
                 hrtf->DataIR.elements, m, r, n);
        return -1;
    }
    if ((size_t)hrtf->SourcePosition.elements != (size_t)m * 3) {
        snprintf(why, why_size, "SourcePosition holds %u values: expected M x 3 = %u",
                 hrtf->SourcePosition.elements, m * 3);
        return -1;
    }
    if (hrtf->DataSamplingRate.elements < 1) {
        snprintf(why, why_size, "Data.SamplingRate is empty");
        return -1;
    }
    for (unsigned k = 1; k < hrtf->DataSamplingRate.elements; k++) {
        if (hrtf->DataSamplingRate.values[k] != hrtf->DataSamplingRate.values[0]) {
            snprintf(why, why_size, "Data.SamplingRate holds %g and %g Hz: expected one rate",
                     hrtf->DataSamplingRate.values[0], hrtf->DataSamplingRate.values[k]);
            return -1;
        }
    }
    return 0;
}

/* Fills *out from the loaded, checked, cartesian hrtf; 0 or -1 with why. */
static int take(struct MYSOFA_HRTF *hrtf, double rate_hz, sofa_hrirs *out, char *why,
                size_t why_size)
{
    if (check_dimensions(hrtf, why, why_size) != 0)
        return -1;
    const unsigned m = hrtf->M, n = hrtf->N; /* R is 2: check_dimensions */
    const char *units = mysofa_getAttribute(hrtf->DataSamplingRate.attributes, "Units");
    if (units && strcmp(units, "hertz") != 0) {
        snprintf(why, why_size, "Data.SamplingRate in \"%s\": expected \"hertz\"", units);
        return -1;
    }
    for (unsigned k = 0; k < hrtf->DataDelay.elements; k++) {
        if (hrtf->DataDelay.values[k] != 0.0f) {
            snprintf(why, why_size, "per-measurement delays (Data.Delay) are not supported");
            return -1;
        }
    }
    double file_rate = hrtf->DataSamplingRate.values[0];
    if (!(file_rate >= 1000.0 && file_rate <= 384000.0)) {
        snprintf(why, why_size, "Data.SamplingRate %g Hz: expected 1000 to 384000", file_rate);
        return -1;
    }
    double ratio = rate_hz / file_rate;
    size_t taps = (size_t)ceil(n * ratio);
    if (taps == 0 || taps > FG_HRIR_MAX_LENGTH) {
        snprintf(why, why_size, "Data.IR of %u taps (dimension N) at %g Hz is %zu taps at %g Hz: "
                 "expected 1 to %u", n, file_rate, taps, rate_hz, FG_HRIR_MAX_LENGTH);
        return -1;
    }
    for (unsigned k = 0; k < hrtf->DataIR.elements; k++) {
        if (!isfinite(hrtf->DataIR.values[k])) {
            snprintf(why, why_size, "Data.IR value %u is not a finite number", k);
            return -1;
        }
    }
    out->direction = calloc((size_t)m * 3, sizeof *out->direction);
    out->left = calloc((size_t)m * taps, sizeof *out->left);
    out->right = calloc((size_t)m * taps, sizeof *out->right);
    if (!out->direction || !out->left || !out->right) {
        snprintf(why, why_size, "out of memory");
        return -1;
    }
    for (unsigned s = 0; s < m; s++) {
        const float *p = hrtf->SourcePosition.values + 3 * (size_t)s;
        if (!(isfinite(p[0]) && isfinite(p[1]) && isfinite(p[2])) ||
            (p[0] == 0.0f && p[1] == 0.0f && p[2] == 0.0f)) {
            snprintf(why, why_size, "SourcePosition %u is at the listener or not finite", s);
            return -1;
        }
        for (int j = 0; j < 3; j++)
            out->direction[3 * (size_t)s + j] = p[j];
    }
    if (convert(hrtf->DataIR.values, m, n, ratio, taps, out->left, out->right, why,
                why_size) != 0)
        return -1;
    out->file_rate_hz = file_rate;
    out->set = (fg_hrir_set){.sample_rate_hz = rate_hz, .count = m, .length = (uint32_t)taps,
                             .direction = out->direction, .left = out->left,
                             .right = out->right};
    return 0;
}

int sofa_hrirs_read(const char *path, double rate_hz, sofa_hrirs *out, char *err,
                    size_t err_size)
{
    memset(out, 0, sizeof *out);
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(err, err_size, "%s: cannot open the SOFA file: %s", path, strerror(errno));
        return -1;
    }
    fclose(f);
    int code = MYSOFA_OK;
    struct MYSOFA_HRTF *hrtf = mysofa_load(path, &code);
    if (!hrtf || code != MYSOFA_OK) {
        snprintf(err, err_size, "%s: not a SOFA file libmysofa reads (%s)", path,
                 mysofa_reason(code));
        mysofa_free(hrtf);
        return -1;
    }
    code = mysofa_check(hrtf);
    char why[160] = "";
    if ((code == MYSOFA_INVALID_DIMENSIONS ||
         code == MYSOFA_ONLY_THE_SAME_SAMPLING_RATE_SUPPORTED) &&
        check_dimensions(hrtf, why, sizeof why) != 0) {
        snprintf(err, err_size, "%s: %s", path, why);
        mysofa_free(hrtf);
        return -1;
    }
    if (code != MYSOFA_OK) {
        snprintf(err, err_size, "%s: not a SOFA SimpleFreeFieldHRIR set (%s)", path,
                 mysofa_reason(code));
        mysofa_free(hrtf);
        return -1;
    }
    mysofa_tocartesian(hrtf);
    int rc = take(hrtf, rate_hz, out, why, sizeof why);
    if (rc == 0)
        rc = hrir_equalize(&out->set, out->left, out->right, out->file_rate_hz, why, sizeof why);
    mysofa_free(hrtf);
    if (rc != 0) {
        snprintf(err, err_size, "%s: %s", path, why);
        sofa_hrirs_free(out);
    }
    return rc;
}
