/* A Standard MIDI File (format 0 or 1) read into timed channel messages,
 * for rendering a MIDI file through fulgur.lv2 offline. */
#ifndef HOST_LV2_SMF_H
#define HOST_LV2_SMF_H

#include <stddef.h>
#include <stdint.h>

typedef struct smf_event {
    double time_s;    /* from the file's start, through its tempo map */
    uint8_t status, data1, data2;
} smf_event;

/* Parses the file's bytes data[0..size): its note-on, note-off,
 * aftertouch, control-change and pitch-bend messages of every track, merged
 * in time order (ties keep the file's order). *events is owned by the
 * caller (free). Returns 0, or -1 with a message in err that starts with
 * name and says what is wrong (not "MThd", a truncated chunk, a running
 * status with none before, ...); *events and *count are then untouched. */
int smf_parse(const uint8_t *data, size_t size, const char *name, smf_event **events,
              size_t *count, char *err, size_t err_size);

/* Reads the file at path (at most 64 MiB) and parses it as smf_parse does,
 * with path for name. */
int smf_read(const char *path, smf_event **events, size_t *count, char *err, size_t err_size);

#endif
