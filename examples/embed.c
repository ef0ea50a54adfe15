/* The smallest real-time host: a device thread pulls blocks through its
 * callback, paced like a sound card; the main thread is the application's
 * frame loop, turning the head each frame, posting a spark as its sim step,
 * and collecting. Build: cc embed.c -lfulgur -lm -lpthread.
 * Prints the peak pressure; fails when the spark is not heard. */
#define _POSIX_C_SOURCE 200809L /* nanosleep */
#include <math.h>
#include <stdatomic.h>
#include <stdbool.h>
#include <stdio.h>
#include <pthread.h>
#include <time.h>

#include "fulgur/fulgur.h"

#define BLOCK 256
#define BLOCKS 100 /* 0.53 s at 48 kHz */

static fg_engine *engine;
static atomic_bool device_done;
static float peak; /* the device thread's; read after the join */

/* audio thread: the device's callback, wait-free */
static void audio_callback(float *const *out, uint32_t frames)
{
    if (fg_engine_render(engine, out, frames) != FG_OK)
        return;
    for (uint32_t i = 0; i < frames; i++)
        peak = fmaxf(peak, fabsf(out[0][i]));
}

/* A stand-in for the sound card: one callback per block period. */
static void *device(void *arg)
{
    (void)arg;
    float left[BLOCK], right[BLOCK], *planes[2] = {left, right};
    struct timespec period = {.tv_nsec = 1000000000L / 48000 * BLOCK};
    for (int block = 0; block < BLOCKS; block++) {
        audio_callback(planes, BLOCK);
        nanosleep(&period, NULL);
    }
    atomic_store(&device_done, true);
    return NULL;
}

int main(void)
{
    if (fg_engine_create(NULL, &engine) != FG_OK) /* 48 kHz, two ears */
        return 1;
    pthread_t audio;
    if (pthread_create(&audio, NULL, device, NULL) != 0)
        return 1;
    /* sim thread's tree: a 2 cm spark one metre ahead, three nodes */
    fg_node tree[] = {{0, 1, 1.71, -1, 0}, {0.004, 1, 1.70, 0, 0}, {0, 1, 1.69, 1, 0}};
    int ok = 1;
    struct timespec frame_period = {.tv_nsec = 11111111}; /* 90 Hz */
    for (int frame = 0; !atomic_load(&device_done); frame++) {
        /* frame thread: where the head is, each frame */
        double yaw = 0.1 * sin(frame * 0.05);
        fg_listener head = {.position = {0, 0, 1.7}, .forward = {sin(yaw), cos(yaw), 0},
                            .up = {0, 0, 1}};
        ok &= fg_engine_set_listener(engine, &head) == FG_OK;
        /* sim thread: post a discharge to sound now, and reclaim finished ones */
        if (frame == 3) {
            fg_discharge spark = {.nodes = tree, .node_count = 3, .emit_time_s = FG_EMIT_NOW};
            ok &= fg_preset_sound(FG_PRESET_SPARK_BALLS, &spark.sound) == FG_OK &&
                  fg_engine_post(engine, &spark, NULL) == FG_OK;
        }
        fg_engine_collect(engine);
        nanosleep(&frame_period, NULL);
    }
    pthread_join(audio, NULL);
    fg_engine_destroy(engine);
    printf("peak %.3f Pa\n", peak);
    return ok && peak > 0 ? 0 : 1;
}
