/* Libraries the fulgur program opens the first time it calls into them.
 *
 * Linked to the program, libsndfile (and its FLAC, Vorbis, Opus, MPEG and
 * LAME codecs), FFTW (and its threads library), libmysofa, libsamplerate
 * and zlib were mapped and relocated in every process, though only
 * reading a WAV, an RF64 or calibrated output, a binaural render (a SOFA
 * file), an aerodynamic texture file or an analysis calls them: 5.8 ms of
 * CPU in each process (an empty program linked to them against one linked
 * to libcjson alone, medians of 60 alternating runs; 3.4 ms of it
 * libsndfile's). A plain WAV is written by audio_file.c itself.
 * lazy_sndfile.c, lazy_fftw.c, lazy_mysofa.c, lazy_samplerate.c and
 * lazy_zlib.c define, in the program only and hidden from what it
 * exports, each function of theirs the program calls: the first call
 * opens the library and every call goes on to the library's own. The
 * program is linked --as-needed, so the libraries leave its list of
 * needed objects. Tests, the LV2 plugin and libfulgur-scene link them as
 * before.
 *
 * Thread: any (each library is opened once, pthread_once). */
#ifndef HOST_COMMON_LAZY_LIBRARY_H
#define HOST_COMMON_LAZY_LIBRARY_H

#include "library_load.h"

/* library_load, or the end of the process as the dynamic loader's at
 * start: the message on stderr and exit status 127. */
void lazy_library_load(const char *library, const library_symbol *symbols, size_t count);

#endif
