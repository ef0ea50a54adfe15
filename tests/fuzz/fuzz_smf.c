/* libFuzzer target for fulgur-lv2-render's MIDI file reader: any bytes
 * either parse into time-ordered, finite, well-formed channel messages or
 * are refused with a message that names the file, leaving the outputs
 * untouched. Corpus: corpus/fulgur_fuzz_smf/ (small .mid files). */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "smf.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    smf_event *events = NULL;
    size_t count = 12345;
    char err[256] = "";
    if (smf_parse(data, size, "fuzz.mid", &events, &count, err, sizeof err) != 0) {
        if (events || count != 12345 || strncmp(err, "fuzz.mid: ", 10) != 0)
            abort();
        return 0;
    }
    for (size_t i = 0; i < count; i++) {
        const smf_event *e = &events[i];
        uint8_t kind = e->status & 0xf0;
        if (!isfinite(e->time_s) || e->time_s < 0 || (i && e->time_s < events[i - 1].time_s) ||
            kind < 0x80 || kind == 0xc0 || kind == 0xd0 || kind == 0xf0 ||
            ((e->data1 | e->data2) & 0x80))
            abort();
    }
    free(events);
    return 0;
}
