/* A program outside the tree, built against an installed fulgur: one
 * spark rendered through the shared library. Exits 0 when the library's
 * version is the headers' and the spark is heard. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <fulgur/fulgur.h>

int main(void)
{
    if (strcmp(fg_version_string(), "fulgur " FG_VERSION_STRING) != 0) {
        fprintf(stderr, "library %s, headers %s\n", fg_version_string(), FG_VERSION_STRING);
        return 1;
    }
    fg_engine *engine;
    if (fg_engine_create(NULL, &engine) != FG_OK)
        return 1;
    /* a 1 cm spark 1 m ahead at ear height */
    fg_node nodes[2] = {{.x = 0, .y = 1, .z = 1.705, .parent = -1},
                        {.x = 0, .y = 1, .z = 1.695, .parent = 0}};
    fg_discharge spark = {.nodes = nodes, .node_count = 2, .emit_time_s = FG_EMIT_NOW, .strokes = 1};
    fg_listener head = {.position = {0, 0, 1.7}, .forward = {0, 1, 0}, .up = {0, 0, 1}};
    if (fg_engine_set_listener(engine, &head) != FG_OK ||
        fg_preset_sound(FG_PRESET_SPARK_BALLS, &spark.sound) != FG_OK ||
        fg_engine_post(engine, &spark, NULL) != FG_OK)
        return 1;
    float left[256], right[256], *out[2] = {left, right};
    double peak = 0;
    for (int block = 0; block < 100; block++) { /* 0.53 s at 48 kHz */
        if (fg_engine_render(engine, out, 256) != FG_OK)
            return 1;
        for (int i = 0; i < 256; i++)
            peak = fmax(peak, fabs(left[i]));
    }
    fg_engine_destroy(engine);
    printf("%s (C): spark peak %.3g Pa\n", fg_version_string(), peak);
    return peak > 1e-3 ? 0 : 1;
}
