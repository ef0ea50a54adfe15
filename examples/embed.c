/* The smallest host: one spark, rendered the way a device callback would
 * pull it. Build: cc embed.c -lfulgur -lm. Prints the peak pressure. */
#include <math.h>
#include <stdio.h>

#include "fulgur/fulgur.h"

int main(void)
{
    fg_engine *engine;
    if (fg_engine_create(NULL, &engine) != FG_OK) /* 48 kHz, two ears */
        return 1;

    /* frame thread: where the head is */
    fg_listener head = {.position = {0, 0, 1.7}, .forward = {0, 1, 0}, .up = {0, 0, 1}};
    if (fg_engine_set_listener(engine, &head) != FG_OK)
        return 1;

    /* sim thread: a 2 cm spark one metre ahead, as a three-node tree */
    fg_node tree[] = {{0, 1, 1.71, -1, 0}, {0.004, 1, 1.70, 0, 0}, {0, 1, 1.69, 1, 0}};
    fg_discharge spark = {.nodes = tree, .node_count = 3, .emit_time_s = FG_EMIT_NOW};
    if (fg_preset_sound(FG_PRESET_SPARK_BALLS, &spark.sound) != FG_OK ||
        fg_engine_post(engine, &spark, NULL) != FG_OK)
        return 1;

    /* audio thread: pull blocks; sim thread: collect finished voices */
    float left[256], right[256], *planes[2] = {left, right};
    float peak = 0;
    for (int block = 0; block < 40; block++) {
        if (fg_engine_render(engine, planes, 256) != FG_OK)
            return 1;
        for (int i = 0; i < 256; i++)
            peak = fmaxf(peak, fabsf(left[i]));
        fg_engine_collect(engine);
    }
    printf("peak %.3f Pa\n", peak);
    fg_engine_destroy(engine);
    return peak > 0 ? 0 : 1;
}
