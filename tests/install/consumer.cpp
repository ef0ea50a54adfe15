// A C++ program outside the tree, built against an installed fulgur and
// fulgur-gpu: the engine's and gpu/'s headers in C++, both libraries
// linked (gpu/ without a context: names and backends only).
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include <fulgur/fulgur.h>
#include <fulgur/gpu.h>

int main()
{
    if (std::strcmp(fg_version_string(), "fulgur " FG_VERSION_STRING) != 0)
        return 1;
    fg_engine_config config;
    if (fg_engine_config_resolve(nullptr, &config) != FG_OK)
        return 1;
    fg_engine *engine = nullptr;
    if (fg_engine_create(&config, &engine) != FG_OK)
        return 1;
    fg_node nodes[2] = {};
    nodes[0].y = 1, nodes[0].z = 1.705, nodes[0].parent = -1;
    nodes[1].y = 1, nodes[1].z = 1.695, nodes[1].parent = 0;
    fg_discharge spark = {};
    spark.nodes = nodes;
    spark.node_count = 2;
    spark.emit_time_s = FG_EMIT_NOW;
    spark.strokes = 1;
    fg_listener head = {};
    head.position[2] = 1.7, head.forward[1] = 1, head.up[2] = 1;
    if (fg_engine_set_listener(engine, &head) != FG_OK ||
        fg_preset_sound(FG_PRESET_SPARK_BALLS, &spark.sound) != FG_OK ||
        fg_engine_post(engine, &spark, nullptr) != FG_OK)
        return 1;
    std::vector<float> left(256), right(256);
    float *out[2] = {left.data(), right.data()};
    double peak = 0;
    for (int block = 0; block < 100; block++) {
        if (fg_engine_render(engine, out, 256) != FG_OK)
            return 1;
        for (float v : left)
            peak = std::fmax(peak, std::fabs(v));
    }
    fg_engine_destroy(engine);
    fgg_backend backend;
    if (fgg_backend_from_name("osmesa", &backend) != FG_OK || backend != FGG_BACKEND_OSMESA ||
        std::strcmp(fgg_backend_name(FGG_BACKEND_EGL), "egl") != 0)
        return 1;
    std::printf("%s (C++): spark peak %.3g Pa; gpu/ backends: egl %d, osmesa %d, window %d\n",
                fg_version_string(), peak, fgg_backend_built(FGG_BACKEND_EGL),
                fgg_backend_built(FGG_BACKEND_OSMESA), fgg_backend_built(FGG_BACKEND_WINDOW));
    return peak > 1e-3 ? 0 : 1;
}
