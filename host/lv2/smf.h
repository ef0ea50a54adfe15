/* A Standard MIDI File (format 0 or 1) read into timed channel messages,
 * for rendering a MIDI file through fulgur.lv2 offline. */
#ifndef FULGUR_HOST_LV2_SMF_H
#define FULGUR_HOST_LV2_SMF_H

#include <stddef.h>
#include <stdint.h>

typedef struct smf_event {
    double time_s;    /* from the file's start, through its tempo map */
    uint8_t status, data1, data2;
} smf_event;

/* Reads path's note-on, note-off, aftertouch, control-change and
 * pitch-bend messages of every track, merged in time order (ties keep the
 * file's order). *events is owned by the caller (free). Returns 0, or -1
 * with a message in err naming the file and what is wrong (not "MThd", a
 * truncated chunk, a running status with none before, ...). */
int smf_read(const char *path, smf_event **events, size_t *count, char *err, size_t err_size);

#endif
