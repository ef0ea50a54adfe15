/* The output layout stage (fg_layout): the one place every source model's
 * waves meet the output channels.
 *
 * A model computes, per ear the layout asks for (fg_layout_ears: two for
 * stereo, one at the head's centre otherwise), each wave's geometry from
 * the listener's ears (core/trajectory_internal.h) and renders it with
 * fg_layout_gains into the bus set (core/bus_internal.h): a wave heard by
 * ear k goes to channel k with gain 1 in stereo (plus the head shadow's
 * twin, spatial/spherical_head_internal.h); a wave arriving from direction
 * dir in the head's frame goes to every ambisonic channel c with gain
 * gain[c]. The buses then filter each channel once per block: the cost of
 * the layout is one add per wave and output channel, and one pass of the
 * air's filters per bus and channel, never a filter per wave. */
#ifndef FULGUR_LAYOUT_INTERNAL_H
#define FULGUR_LAYOUT_INTERNAL_H

#include "ambisonics_internal.h"
#include "binaural_internal.h"
#include "fulgur/engine.h"

/* The most channels fg_layout_gains names: the binaural layout's
 * loudspeakers (a gain array of this size holds any layout's). */
#define FG_LAYOUT_CHANNELS_MAX FG_BINAURAL_SPEAKERS

/* The channels the buses carry: the output's, but for binaural the
 * virtual loudspeakers its HRIRs filter to the ears (binaural_internal.h). */
static inline unsigned fg_layout_bus_channels(const fg_engine_config *cfg)
{
    return cfg->layout == FG_LAYOUT_BINAURAL ? FG_BINAURAL_SPEAKERS : cfg->channels;
}

/* How many ears a model evaluates its geometry for. */
static inline unsigned fg_layout_ears(const fg_engine_config *cfg)
{
    return cfg->layout == FG_LAYOUT_STEREO ? cfg->channels : 1u;
}

/* The output channels a wave of ear ch from head-frame direction dir
 * reaches, and their gains: writes them to first[0..count) and gain[], and
 * returns count (at most FG_LAYOUT_CHANNELS_MAX). Stereo: channel ch alone,
 * gain 1. Ambisonics: every channel, the SN3D spherical harmonics of dir.
 * Binaural: every loudspeaker channel, the panning gains of dir (at most
 * four non-zero). [audio-thread] */
static inline unsigned fg_layout_gains(const fg_engine_config *cfg, unsigned ch,
                                       const double dir[3], unsigned *first, double *gain)
{
    if (cfg->layout == FG_LAYOUT_BINAURAL) {
        fg_binaural_gains(dir, gain);
        *first = 0;
        return FG_BINAURAL_SPEAKERS;
    }
    if (cfg->layout == FG_LAYOUT_AMBISONICS) {
        fg_ambisonic_gains(dir, cfg->ambisonic_order, gain);
        *first = 0;
        return fg_ambisonic_channels(cfg->ambisonic_order);
    }
    *first = ch;
    gain[0] = 1.0;
    return 1;
}

/* fg_layout_gains as a list, index[k] and gain[k] for k below the count
 * returned, the channels ascending (a gain may be 0: that channel gets
 * nothing). Binaural: the at most four loudspeakers fg_binaural_pan names,
 * not all fifty. [audio-thread] */
static inline unsigned fg_layout_reach(const fg_engine_config *cfg, unsigned ch,
                                       const double dir[3], unsigned *index, double *gain)
{
    if (cfg->layout == FG_LAYOUT_STEREO) {
        index[0] = ch;
        gain[0] = 1.0;
        return 1;
    }
    if (cfg->layout == FG_LAYOUT_BINAURAL)
        return fg_binaural_pan(dir, index, gain);
    unsigned first;
    const unsigned count = fg_layout_gains(cfg, ch, dir, &first, gain);
    for (unsigned c = 0; c < count; c++)
        index[c] = first + c;
    return count;
}

#endif
