/* A scene as the engine takes it: its configuration and the order its
 * discharges are posted in. */
#include <stdlib.h>

#include "scene.h"

void scene_engine_config(const scene *s, fg_engine_config *out)
{
    *out = (fg_engine_config){
        .sample_rate_hz = s->sample_rate_hz,
        .max_block_frames = s->block_frames,
        .channels = s->channels,
        .layout = s->layout,
        .ambisonic_order = s->ambisonic_order,
        .hrirs = s->hrirs,
        .speed_of_sound_m_s = s->speed_of_sound_m_s,
        .air_temperature_k = s->temperature_c + 273.15,
        .air_humidity_pct = s->humidity_pct,
        .air_pressure_kpa = s->pressure_kpa,
    };
}

/* qsort has no context argument: the times travel with the indices. */
typedef struct post_slot {
    double time_s;
    size_t index;
} post_slot;

static int by_time(const void *a, const void *b)
{
    const post_slot *x = a, *y = b;
    if (x->time_s != y->time_s)
        return x->time_s < y->time_s ? -1 : 1;
    return (x->index > y->index) - (x->index < y->index);
}

size_t *scene_post_order(const scene *s)
{
    size_t n = s->discharge_count;
    post_slot *slots = malloc((n ? n : 1) * sizeof *slots);
    size_t *order = malloc((n ? n : 1) * sizeof *order);
    if (!slots || !order) {
        free(slots);
        free(order);
        return NULL;
    }
    for (size_t i = 0; i < n; i++)
        slots[i] = (post_slot){s->discharges[i].post.emit_time_s, i};
    qsort(slots, n, sizeof *slots, by_time);
    for (size_t i = 0; i < n; i++)
        order[i] = slots[i].index;
    free(slots);
    return order;
}
