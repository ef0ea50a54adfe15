/* libFuzzer target for what fulgur reads from outside.
 *   first byte even: the rest is scene JSON, through scene_parse (no
 *     generators, no rendering); a parsed scene must hold only valid trees
 *     and a usable listener, a refused one must say why.
 *   first byte odd: the rest is an array of fg_node, through fg_tree_check
 *     and fg_tree_fault_describe; the fault must agree with the result.
 * Corpus (corpus/): json_* are '0' + a scene; nodes_* are '1' + fg_node
 * structs packed by Python's struct.pack("<dddiI", x, y, z, parent, flags). */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "scene/scene.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void fuzz_scene(const char *text, size_t size)
{
    scene s;
    char err[512] = "";
    if (scene_parse(text, size, &s, err, sizeof err) != 0) {
        if (err[0] == '\0' || s.discharges || s.poses || s.json)
            abort();
        return;
    }
    for (size_t i = 0; i < s.discharge_count; i++) {
        const scene_discharge *d = &s.discharges[i];
        if (!d->generator && fg_tree_check(d->post.nodes, d->post.node_count, NULL) != FG_OK)
            abort();
        if (fg_sound_config_check(&d->post.sound) != FG_OK)
            abort();
    }
    fg_listener pose;
    scene_listener_at(&s, s.poses[s.pose_count - 1].time_s * 0.5, &pose);
    if (pose.forward[0] != pose.forward[0] || pose.up[2] != pose.up[2]) /* NaN */
        abort();
    scene_deinit(&s);
}

static void fuzz_nodes(const uint8_t *bytes, size_t size)
{
    size_t count = size / sizeof(fg_node);
    /* exactly count nodes on the heap, so reading past them is caught */
    fg_node *nodes = malloc(count ? count * sizeof *nodes : 1);
    if (!nodes)
        return;
    memcpy(nodes, bytes, count * sizeof *nodes);
    fg_tree_fault fault;
    fg_result r = fg_tree_check(nodes, count, &fault);
    if ((r == FG_OK) != (fault.kind == FG_TREE_FAULT_NONE) || (r != FG_OK && r != FG_ERR_TREE) ||
        fault.node > count)
        abort();
    char text[128], tiny[8];
    fg_tree_fault_describe(&fault, text, sizeof text);
    fg_tree_fault_describe(&fault, tiny, sizeof tiny);
    if (strlen(text) == 0 || strlen(tiny) >= sizeof tiny)
        abort();
    free(nodes);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size == 0)
        return 0;
    if (data[0] % 2 == 0)
        fuzz_scene((const char *)data + 1, size - 1);
    else
        fuzz_nodes(data + 1, size - 1);
    return 0;
}
