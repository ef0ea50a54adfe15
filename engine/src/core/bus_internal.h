/* Filter buses: where the audio thread sums each ear's waves before the
 * air's filters, so filtering costs per bus, never per segment.
 *
 * Bus FG_BUS_DRY has no filter; FG_BUS_BAND0 + k carries sources between
 * the (k-1)-th and (k+1)-th ISO 9613-1 band centres, each split between
 * its two nearest bands, through that band's fitted IIR;
 * FG_BUS_FIR carries Abe's 200 Hz FIR. With a head (two ears apart), each
 * has a head-shadowed twin at index + FG_BUS_PLAIN, which adds the
 * high-pass of Brown & Duda's head model (spatial/spherical_head_internal.h):
 * a wave sent whole to a bus and alpha - 1 of it to the twin is heard
 * through the head's one-pole, one-zero filter for its angle. The buses are shared by every voice: the
 * air's response depends only on the distance band. */
#ifndef FULGUR_BUS_INTERNAL_H
#define FULGUR_BUS_INTERNAL_H

#include <stdbool.h>
#include <stdint.h>

#include "air/abe_lowpass_internal.h"
#include "air/air_absorption_internal.h"
#include "air/distance_bands_internal.h"
#include "fulgur/propagation.h"
#include "air/iir_internal.h"
#include "accum_internal.h"

enum {
    FG_BUS_DRY = 0,
    FG_BUS_BAND0 = 1,
    FG_BUS_FIR = FG_BUS_BAND0 + FG_ABSORPTION_BANDS,
    FG_BUS_PLAIN = FG_BUS_FIR + 1,
    FG_BUS_COUNT = 2 * FG_BUS_PLAIN
};

/* Channels at most: the binaural layout's 50 virtual loudspeakers
 * (spatial/binaural_internal.h; a third-order ambisonic layout has 16). */
#define FG_BUS_MAX_CHANNELS 50

/* A filter's tail ends once every state of it is below this, in pascals:
 * its states are zeroed and the bus stops filtering that channel until its
 * next input, soon after its input stops rather than once the states
 * underflow (iir.c snaps them at 1e-30; the band filters' slowest poles,
 * radius 0.960 at 3 km and 0.989 at 30 km, take 1 700 and 6 200 samples
 * to fall from 1 Pa to that, 560 and 2 070 to this). The free response
 * dropped, from states below 1e-12 Pa through these poles, stays under
 * 1e-10 Pa, 106 dB below the threshold of hearing (20 uPa):
 * tests/test_buses.c. */
#define FG_BUS_TAIL_FLOOR_PA 1e-12

/* The most bytes the planes (a double a frame of the chunk and a float a
 * frame of the block, per bus and channel) take: a longer max_frames is cut
 * to the longest power of two that fits (stereo with the twins keeps 4096
 * frames, third-order ambisonics 1024, binaural 512), and the engine
 * renders a longer call as blocks of that length (core/render.c). */
#define FG_BUS_PLANE_BYTES (16u << 20)

/* The accumulators' planes are a chunk of blocks long
 * (fg_engine_config.chunk_frames): a still listener's block adds to the
 * chunk's accumulators each wave that joins it, to the chunk's end, and no
 * wave already written: a wave is visited once a chunk, not once a block.
 * How a block's accumulators begin (fg_bus_set_begin): */
typedef enum fg_chunk_start {
    FG_CHUNK_CARRY, /* in the chunk under way, or a new one where the block does not fit it */
    FG_CHUNK_NEW,   /* in a new chunk: what was written ahead is dropped */
    FG_CHUNK_BLOCK  /* in a new chunk of this block alone (a moving listener's) */
} fg_chunk_start;

/* A bit per channel (FG_BUS_MAX_CHANNELS <= 64): a block's work on a bus
 * visits only the channels whose bits are set, so a bus costs per channel
 * that sounds, not per channel of the layout. */
typedef uint64_t fg_channel_mask;

/* One channel of every bus: its input and its filters' state. */
typedef struct fg_bus_channel {
    fg_accum accum[FG_BUS_COUNT];  /* difference-domain input (the WM-waves), per bus */
    uint32_t quiet[FG_BUS_COUNT];  /* frames since the FIR last had input */
    fg_iir band[2][FG_ABSORPTION_BANDS]; /* [plain, twin][band] */
    fg_iir shadow[FG_BUS_PLAIN];   /* the twins' head high-pass */
} fg_bus_channel;

typedef struct fg_bus_set {
    unsigned count;      /* buses with planes: FG_BUS_COUNT with a head, else
                          * FG_BUS_PLAIN (no twins) */
    unsigned channels;
    uint32_t max_frames; /* the longest block: the max_frames asked, or fewer to fit
                          * FG_BUS_PLANE_BYTES */
    uint32_t chunk_frames; /* the longest chunk: max_frames, or the chunk_frames asked
                            * where it is longer and the planes fit */
    /* audio thread: the block under way, and the chunk it lies in: its
     * length and the frames of it before the block; whether it follows
     * the chunk before whole (that one's every frame was ended, none of
     * what it wrote dropped) */
    uint32_t frames, chunk_len, chunk_pos;
    bool chunk_follows;
    double *d3; /* count * channels * chunk_frames, bus by bus, a chunk long
                 * each (fg_bus_accum); the allocation (fg_big_alloc.h) that
                 * fir and pre lie in, after it */
    float *pre; /* count * channels * max_frames floats, bus by bus: the
                 * buses' signal before the filters (fg_bus_pre) */
    /* filters: shared coefficients, state per ear */
    fg_band_plan plan;
    bool bands_designed; /* sim thread only: the audio thread touches a band's
                          * filter after adopting a voice that needed it, so
                          * the inbox ring orders the design before */
    fg_abe_fir *fir;     /* [count / FG_BUS_PLAIN (plain, shadowed)][channels] */
    fg_air air;
    double fs_hz;
    bool accum_avx2;     /* the CPU ends the accumulators four at a time in AVX2 */
    /* audio thread, a bit per channel of each bus: */
    fg_channel_mask opened[FG_BUS_COUNT];   /* accumulators handed out in this chunk, at
                                             * the block: the others are zero, unused */
    fg_channel_mask pre_used[FG_BUS_COUNT]; /* something was written into pre this block */
    fg_channel_mask ringing[FG_BUS_COUNT];  /* the filters still hold a tail: an IIR's
                                             * state, or the FIR's history of input */
    fg_channel_mask written; /* fg_bus_set_end's last call wrote out[ch] */
    /* a bit per bus with a bit in opened, pre_used or ringing: a block
     * visits only those of the 94 buses (fg_bus_busy) */
    uint64_t busy[(FG_BUS_COUNT + 63) / 64];
    /* last, by channel: a layout of few channels uses only the first few
     * of these 1.9 MB (mapped all at once where the engine's allocation
     * takes a huge page, core/engine.c) */
    fg_bus_channel chan[FG_BUS_MAX_CHANNELS];
} fg_bus_set;

/* Allocates the buses for blocks of max_frames frames or of fewer, to fit
 * FG_BUS_PLANE_BYTES (s->max_frames says), and for chunks of chunk_frames
 * or of fewer, to fit it (s->chunk_frames), with the twins and their filter
 * for a head of radius head_radius_m (0: none, no twins). s is zeroed
 * memory (the engine's allocation); the part the channels use is mapped,
 * the channels beyond them are never written. [main-thread] */
fg_result fg_bus_set_init(fg_bus_set *s, unsigned channels, uint32_t max_frames,
                          uint32_t chunk_frames, double fs_hz, double c_m_s, double head_radius_m,
                          const fg_air *air);
void fg_bus_set_deinit(fg_bus_set *s);

/* Designs the ISO 9613-1 band filters the first time a voice needs them
 * (0.15-0.3 s of CPU for the first engine of a process with this rate
 * and air, a copy for the others: air/band_filters_internal.h).
 * [sim-thread] */
void fg_bus_set_design_bands(fg_bus_set *s);

/* The band buses for a source r_m away: the nearer one is returned, and
 * *w_next is the share of the next (distance_bands_internal.h; 0 when the
 * source takes the returned bus alone). [audio-thread] safe. */
unsigned fg_bus_for_distance(const fg_bus_set *s, double r_m, double *w_next);

/* Starts a block of n frames on every bus, in the chunk start says.
 * [audio-thread] */
void fg_bus_set_begin(fg_bus_set *s, uint32_t n, fg_chunk_start start);

/* The float buffer of bus b, channel ch, for waves rendered sample by
 * sample. */
float *fg_bus_pre(fg_bus_set *s, unsigned b, unsigned ch);

/* Notes bus b as busy this block. */
static inline void fg_bus_busy(fg_bus_set *s, unsigned b)
{
    s->busy[b / 64] |= (uint64_t)1 << (b % 64);
}

/* The difference-domain accumulator of bus b, channel ch, for waves added
 * per breakpoint, from the block's start to the chunk's end; the first
 * call of a chunk starts it there. [audio-thread] */
static inline fg_accum *fg_bus_accum(fg_bus_set *s, unsigned b, unsigned ch)
{
    fg_accum *a = &s->chan[ch].accum[b];
    const fg_channel_mask bit = (fg_channel_mask)1 << ch;
    if (!(s->opened[b] & bit)) {
        s->opened[b] |= bit;
        fg_bus_busy(s, b);
        double *plane = s->d3 + ((size_t)b * s->channels + ch) * s->chunk_frames;
        fg_accum_restart(a, plane + s->chunk_pos, s->chunk_len - s->chunk_pos);
    }
    return a;
}

/* Ends the block of n: integrates its frames of the accumulators, filters
 * every bus with input or a ringing tail and adds it to out,
 * noting in s->written the output planes it wrote (the others it leaves
 * as they were). The
 * last guard of a finite output: a bus whose block holds a non-finite
 * sample before its filters is dropped for the block (its filters keep
 * their state; its accumulator's sums may stay non-finite: the caller
 * starts the next block in a new chunk), and an output plane that would
 * hold one is zeroed. Returns how many blocks of a bus and ear were
 * dropped (0 whenever the models kept their waves finite). [audio-thread] */
uint64_t fg_bus_set_end(fg_bus_set *s, float *const *out, uint32_t n);

#endif
