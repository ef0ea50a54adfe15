#define _DEFAULT_SOURCE /* fg_big_alloc.h */
#include <math.h>
#include <stddef.h>
#include <string.h>

#include "bus_internal.h"
#include "fg_big_alloc.h"
#include "fg_prefault.h"
#include "fg_simd.h"
#include "air/band_filters_internal.h"
#include "spatial/spherical_head_internal.h"

/* The band centres: 10 m to 30 km, log-spaced. */
#define BAND_NEAR_M 10.0
#define BAND_FAR_M 30000.0

static bool is_fir(unsigned b)
{
    return b % FG_BUS_PLAIN == FG_BUS_FIR;
}

static bool is_band(unsigned b)
{
    unsigned k = b % FG_BUS_PLAIN;
    return k >= FG_BUS_BAND0 && k < FG_BUS_FIR;
}

fg_result fg_bus_set_init(fg_bus_set *s, unsigned channels, uint32_t max_frames,
                          uint32_t chunk_frames, double fs_hz, double c_m_s, double head_radius_m,
                          const fg_air *air)
{
    /* the set up to the channels it has: the audio thread writes it */
    fg_prefault_zeroed(s, offsetof(fg_bus_set, chan) + channels * sizeof s->chan[0]);
    /* no head (one ear, or a spacing of 0) sends nothing to the twins:
     * they get no planes */
    s->count = head_radius_m > 0 ? FG_BUS_COUNT : FG_BUS_PLAIN;
    size_t planes = (size_t)s->count * channels;
    /* the longest power of two whose planes fit FG_BUS_PLANE_BYTES */
    const size_t fit = FG_BUS_PLANE_BYTES / (planes * (sizeof *s->d3 + sizeof *s->pre));
    uint32_t frames = 1;
    while (frames < max_frames && 2 * (size_t)frames <= fit)
        frames *= 2;
    max_frames = frames < max_frames ? frames : max_frames;
    /* the chunk: as long as the block, or the longer one asked, cut to
     * what fits beside the block's floats */
    const size_t chunk_fit =
        (FG_BUS_PLANE_BYTES / planes - max_frames * sizeof *s->pre) / sizeof *s->d3;
    uint32_t chunk = chunk_frames < chunk_fit ? chunk_frames : (uint32_t)chunk_fit;
    chunk = chunk > max_frames ? chunk : max_frames;
    /* the planes and the FIRs in one allocation (fg_big_alloc.h): stereo's
     * 0.6 MB at 256 frames took 190 page faults as three */
    const size_t samples = planes * max_frames, chunk_samples = planes * chunk;
    const size_t firs = (size_t)(s->count / FG_BUS_PLAIN) * channels;
    const size_t bytes =
        chunk_samples * sizeof *s->d3 + firs * sizeof *s->fir + samples * sizeof *s->pre;
    _Static_assert(sizeof(double) % _Alignof(fg_abe_fir) == 0 &&
                       sizeof(fg_abe_fir) % _Alignof(float) == 0,
                   "the FIRs follow the doubles, the floats the FIRs, each aligned");
    s->d3 = fg_big_calloc(bytes, 1);
    if (!s->d3)
        return FG_ERR_NO_MEMORY;
    s->fir = (fg_abe_fir *)(void *)(s->d3 + chunk_samples);
    s->pre = (float *)(void *)(s->fir + firs);
    fg_prefault_zeroed(s->d3, bytes);
    s->channels = channels;
    s->max_frames = max_frames;
    s->chunk_frames = chunk;
    s->accum_avx2 = fg_accum_avx2_available();
    s->fs_hz = fs_hz;
    s->air = *air;
    fg_result r = fg_band_plan_init(&s->plan, BAND_NEAR_M, BAND_FAR_M, FG_ABSORPTION_BANDS);
    for (unsigned i = 0; i < (s->count / FG_BUS_PLAIN) * channels && r == FG_OK; i++)
        r = fg_abe_fir_init(&s->fir[i], fs_hz);
    if (r != FG_OK) {
        fg_bus_set_deinit(s);
        return r;
    }
    fg_biquad hp = fg_head_highpass(head_radius_m > 0 ? head_radius_m : 1.0, fs_hz, c_m_s);
    for (unsigned b = 0; b < FG_BUS_PLAIN; b++) {
        for (unsigned ch = 0; ch < channels; ch++) {
            s->chan[ch].shadow[b] = (fg_iir){.sec = {hp}, .sections = 1};
            fg_iir_reset(&s->chan[ch].shadow[b]);
        }
    }
    for (unsigned b = 0; b < s->count; b++)
        for (unsigned ch = 0; ch < channels; ch++)
            s->chan[ch].quiet[b] = FG_ABE_FIR_HISTORY;
    return FG_OK;
}

void fg_bus_set_deinit(fg_bus_set *s)
{
    fg_big_free(s->d3);
    s->d3 = NULL;
    s->pre = NULL;
    s->fir = NULL;
}

void fg_bus_set_design_bands(fg_bus_set *s)
{
    if (s->bands_designed)
        return;
    fg_iir f[FG_ABSORPTION_BANDS];
    fg_band_filters_design(&s->air, s->plan.centre_m, FG_ABSORPTION_BANDS, s->fs_hz, f);
    for (unsigned k = 0; k < FG_ABSORPTION_BANDS; k++)
        for (unsigned twin = 0; twin < 2; twin++)
            for (unsigned ch = 0; ch < s->channels; ch++)
                s->chan[ch].band[twin][k] = f[k];
    s->bands_designed = true;
}

unsigned fg_bus_for_distance(const fg_bus_set *s, double r_m, double *w_next)
{
    unsigned lo;
    fg_band_locate(&s->plan, r_m, &lo, w_next);
    return FG_BUS_BAND0 + lo;
}

/* The lowest busy bus at or after b, or FG_BUS_COUNT: the busy buses in
 * ascending order, as the loops over all of them took them. */
static unsigned next_busy(const fg_bus_set *s, unsigned b)
{
    for (unsigned w = b / 64; w < sizeof s->busy / sizeof s->busy[0]; w++) {
        uint64_t m = s->busy[w] & (b > w * 64 ? ~(uint64_t)0 << (b - w * 64) : ~(uint64_t)0);
        if (m)
            return w * 64 + (unsigned)__builtin_ctzll(m);
    }
    return FG_BUS_COUNT;
}

/* The plane of bus b, channel ch, in pre. */
static float *pre_plane(const fg_bus_set *s, unsigned b, unsigned ch)
{
    return s->pre + ((size_t)b * s->channels + ch) * s->max_frames;
}

void fg_bus_set_begin(fg_bus_set *s, uint32_t n, fg_chunk_start start)
{
    const bool fresh = start != FG_CHUNK_CARRY || s->chunk_pos + n > s->chunk_len;
    for (unsigned b = next_busy(s, 0); b < FG_BUS_COUNT; b = next_busy(s, b + 1)) {
        if (fresh) {
            /* what the chunk's waves wrote beyond its blocks */
            for (fg_channel_mask m = s->opened[b]; m; m &= m - 1) {
                fg_accum *a = &s->chan[__builtin_ctzll(m)].accum[b];
                memset(a->d3, 0, a->n * sizeof *a->d3);
                fg_accum_restart(a, a->d3, 0);
            }
            s->opened[b] = 0;
        }
        for (fg_channel_mask m = s->pre_used[b]; m; m &= m - 1)
            memset(pre_plane(s, b, (unsigned)__builtin_ctzll(m)), 0, s->max_frames * sizeof(float));
        s->pre_used[b] = 0;
        if (!s->ringing[b] && !s->opened[b])
            s->busy[b / 64] &= ~((uint64_t)1 << (b % 64));
    }
    if (fresh) {
        s->chunk_follows = start != FG_CHUNK_NEW && s->chunk_pos == s->chunk_len;
        s->chunk_len = start == FG_CHUNK_BLOCK ? n : s->chunk_frames;
        s->chunk_pos = 0;
    }
    s->frames = n;
}

float *fg_bus_pre(fg_bus_set *s, unsigned b, unsigned ch)
{
    s->pre_used[b] |= (fg_channel_mask)1 << ch;
    fg_bus_busy(s, b);
    return pre_plane(s, b, ch);
}

/* The band filter of bus b (a band bus or its twin), ear ch. */
static fg_iir *band_filter(fg_bus_set *s, unsigned b, unsigned ch)
{
    return &s->chan[ch].band[b / FG_BUS_PLAIN][b % FG_BUS_PLAIN - FG_BUS_BAND0];
}

/* Whether f still rings; a tail ends (its states are zeroed) once every
 * state is below FG_BUS_TAIL_FLOOR_PA. */
static bool ringing(fg_iir *f)
{
    for (unsigned i = 0; i < f->sections; i++)
        if (fabs(f->z[i][0]) >= FG_BUS_TAIL_FLOOR_PA || fabs(f->z[i][1]) >= FG_BUS_TAIL_FLOOR_PA)
            return true;
    fg_iir_reset(f);
    return false;
}

/* Whether x[0..n) is all finite: x - x is 0 for a finite x, NaN otherwise,
 * and a sum of them 0 or NaN in any order; in two vectors of sums that do
 * not wait on each other. */
static bool all_finite(const float *x, uint32_t n)
{
    fg_vf lane[2] = {fg_vf_set(0.0f), fg_vf_set(0.0f)};
    uint32_t i = 0;
    for (; i + 2 * FG_VF_LANES <= n; i += 2 * FG_VF_LANES) {
        fg_vf a = fg_vf_load(x + i), b = fg_vf_load(x + i + FG_VF_LANES);
        lane[0] += a - a;
        lane[1] += b - b;
    }
    float sum = 0.0f, last[FG_VF_LANES];
    for (; i < n; i++)
        sum += x[i] - x[i];
    fg_vf_store(last, lane[0] + lane[1]);
    for (int k = 0; k < FG_VF_LANES; k++)
        sum += last[k];
    return sum == 0.0f;
}

/* Runs filter(b, ch) over the planes x[k] of channels ch[k], k < count,
 * FG_IIR_LANES at a time (the filters of one bus share their coefficients),
 * and notes in tail[k] whether it still rings. */
static void filter_planes(fg_iir *(*filter)(fg_bus_set *, unsigned, unsigned), fg_bus_set *s,
                          unsigned b, const unsigned *ch, float *const *x, unsigned count,
                          uint32_t n, bool *tail)
{
    for (unsigned k = 0; k < count; k += FG_IIR_LANES) {
        unsigned lanes = count - k < FG_IIR_LANES ? count - k : FG_IIR_LANES;
        fg_iir *f[FG_IIR_LANES];
        for (unsigned j = 0; j < lanes; j++)
            f[j] = filter(s, b, ch[k + j]);
        fg_iir_process_lanes(f, x + k, lanes, n);
        for (unsigned j = 0; j < lanes; j++)
            tail[k + j] = tail[k + j] || ringing(f[j]);
    }
}

/* The twin's head high-pass of bus b >= FG_BUS_PLAIN, ear ch. */
static fg_iir *shadow_filter(fg_bus_set *s, unsigned b, unsigned ch)
{
    return &s->chan[ch].shadow[b - FG_BUS_PLAIN];
}

_Static_assert(FG_BUS_MAX_CHANNELS <= 64, "fg_bus_set.written holds a bit per channel");

uint64_t fg_bus_set_end(fg_bus_set *s, float *const *out, uint32_t n)
{
    uint64_t dropped = 0;
    fg_channel_mask written = 0;
    for (unsigned b = next_busy(s, 0); b < FG_BUS_COUNT; b = next_busy(s, b + 1)) {
        /* the bus's channels to filter this block: their planes, whether
         * they had input, whether a filter still rings */
        unsigned ch[FG_BUS_MAX_CHANNELS], count = 0;
        float *x[FG_BUS_MAX_CHANNELS];
        bool input[FG_BUS_MAX_CHANNELS], tail[FG_BUS_MAX_CHANNELS];
        /* the accumulators whose waves still add to this block */
        fg_channel_mask fed = 0;
        for (fg_channel_mask m = s->opened[b]; m; m &= m - 1) {
            unsigned c = (unsigned)__builtin_ctzll(m);
            fed |= (fg_channel_mask)fg_accum_sounds(&s->chan[c].accum[b]) << c;
        }
        fg_channel_mask live = fed | s->pre_used[b] | s->ringing[b];
        fg_accum *acc[FG_BUS_MAX_CHANNELS];
        if (b == FG_BUS_DRY) {
            /* the first bus into out, which render zeroed, where nothing
             * was written into its planes */
            unsigned dry = 0;
            for (fg_channel_mask m = fed & ~s->pre_used[b]; m; m &= m - 1) {
                unsigned c = (unsigned)__builtin_ctzll(m);
                ch[dry] = c;
                acc[dry] = &s->chan[c].accum[b];
                x[dry++] = out[c];
                written |= (fg_channel_mask)1 << c;
            }
            fg_accum_end_all(acc, x, dry, n, s->accum_avx2);
            for (unsigned k = 0; k < dry; k++) {
                if (!all_finite(x[k], n)) {
                    memset(x[k], 0, n * sizeof(float));
                    dropped++;
                }
            }
            live = s->pre_used[b] | s->ringing[b];
        }
        unsigned planes = 0;
        for (fg_channel_mask m = live; m; m &= m - 1) {
            unsigned c = (unsigned)__builtin_ctzll(m);
            ch[planes] = c;
            acc[planes] = &s->chan[c].accum[b];
            x[planes] = pre_plane(s, b, c);
            input[planes++] = (fed | s->pre_used[b]) >> c & 1;
            s->pre_used[b] |= (fg_channel_mask)1 << c; /* zero it again next block */
        }
        fg_accum_end_all(acc, x, planes, n, s->accum_avx2);
        for (unsigned k = 0; k < planes; k++) {
            if (input[k] && !all_finite(x[k], n)) {
                memset(x[k], 0, n * sizeof(float));
                dropped++;
                continue;
            }
            ch[count] = ch[k];
            x[count] = x[k];
            input[count] = input[k];
            tail[count] = false;
            count++;
        }
        if (is_band(b))
            filter_planes(band_filter, s, b, ch, x, count, n, tail);
        if (is_fir(b)) {
            for (unsigned k = 0; k < count; k++) {
                fg_abe_fir_process(&s->fir[(b / FG_BUS_PLAIN) * s->channels + ch[k]], x[k], n);
                uint32_t *quiet = &s->chan[ch[k]].quiet[b];
                *quiet = input[k] ? 0 : *quiet + n;
                tail[k] = *quiet < FG_ABE_FIR_HISTORY;
            }
        }
        if (b >= FG_BUS_PLAIN)
            filter_planes(shadow_filter, s, b, ch, x, count, n, tail);
        for (unsigned k = 0; k < count; k++) {
            const fg_channel_mask bit = (fg_channel_mask)1 << ch[k];
            s->ringing[b] = tail[k] ? s->ringing[b] | bit : s->ringing[b] & ~bit;
            written |= bit;
            for (uint32_t i = 0; i < n; i++)
                out[ch[k]][i] += x[k][i];
        }
        /* one whose waves have ended, or that was handed out for none,
         * holds nothing: the chunk's next block starts it afresh */
        fg_channel_mask sounding = 0;
        for (fg_channel_mask m = fed; m; m &= m - 1) {
            unsigned c = (unsigned)__builtin_ctzll(m);
            sounding |= (fg_channel_mask)fg_accum_sounds(&s->chan[c].accum[b]) << c;
        }
        s->opened[b] = sounding;
    }
    s->written = written;
    s->chunk_pos += n;
    return dropped;
}
