/* The build step: each generator object becomes a tree. */
#define _DEFAULT_SOURCE /* fg_big_alloc.h */
#include <stdlib.h>
#include <string.h>

#include "fg_big_alloc.h"
#include "generator.h"
#include "scene_internal.h"

/* Runs d's generator into a tree in the generator's own frame (the listener
 * given relative to the discharge's offset), then offsets and checks it. */
static int generate(const scene *s, size_t index, scene_discharge *d, char *err,
                    size_t err_size)
{
    char path[JSON_PATH_MAX], nodes_path[JSON_PATH_MAX];
    json_path_index(nodes_path, sizeof nodes_path, "discharges", index);
    json_path_key(path, sizeof path, nodes_path, "generator");
    json_path_key(nodes_path, sizeof nodes_path, path, "(generated nodes)");
    const cJSON *type = cJSON_GetObjectItemCaseSensitive(d->generator, "type");
    const gen_entry *g = gen_find(type->valuestring);
    fg_listener at;
    scene_listener_at(s, d->post.emit_time_s, &at);
    gen_context ctx = {.seed = d->post.seed, .speed_of_sound_m_s = s->speed_of_sound_m_s};
    for (int k = 0; k < 3; k++)
        ctx.listener_m[k] = at.position[k] - d->offset_m[k];
    fg_tree *tree;
    if (fg_tree_create(0, &tree) != FG_OK)
        return json_fail(err, err_size, path, "out of memory");
    int rc = -1;
    err[0] = '\0';
    if (g->generate(d->generator, path, &ctx, tree, err, err_size) != 0) {
        if (!err[0])
            json_fail(err, err_size, path, "generator \"%s\" failed", g->type);
        goto done;
    }
    size_t n = fg_tree_count(tree);
    fg_node *nodes = fg_big_calloc(n ? n : 1, sizeof *nodes);
    if (!nodes) {
        json_fail(err, err_size, path, "out of memory");
        goto done;
    }
    memcpy(nodes, fg_tree_nodes(tree), n * sizeof *nodes);
    fg_tree_translate(nodes, n, d->offset_m);
    if (scene_check_tree(nodes, n, nodes_path, err, err_size)) {
        fg_big_free(nodes);
        goto done;
    }
    d->post.nodes = nodes;
    d->post.node_count = n;
    rc = 0;
done:
    fg_tree_destroy(tree);
    return rc;
}

int scene_build_discharge(scene *s, size_t index, char *err, size_t err_size)
{
    scene_discharge *d = &s->discharges[index];
    if (!d->generator || d->post.nodes)
        return 0;
    return generate(s, index, d, err, err_size);
}

void scene_discharge_unbuild(scene_discharge *d)
{
    if (d->generator)
        scene_discharge_free_tree(d);
}

int scene_build(scene *s, char *err, size_t err_size)
{
    for (size_t i = 0; i < s->discharge_count; i++) {
        if (scene_build_discharge(s, i, err, err_size) == 0)
            continue;
        for (size_t k = 0; k < i; k++) /* back to the parsed state */
            scene_discharge_unbuild(&s->discharges[k]);
        return -1;
    }
    return 0;
}
