/* An explicit tree: "nodes": [[x, y, z, parent] or [x, y, z, parent, main]]. */
#define _DEFAULT_SOURCE /* fg_big_alloc.h */
#include <stdint.h>
#include <stdlib.h>

#include "fg_big_alloc.h"
#include "scene_internal.h"

static const char *const tree_keys[] = {"nodes", NULL};

/* Node `index` of the list at list_path; the paths of the node and its
 * elements are made only for a message (a big tree has millions of
 * numbers). */
static int parse_node(const cJSON *item, const char *list_path, size_t index, fg_node *node,
                      char *err, size_t err_size)
{
    char path[JSON_PATH_MAX], elem[JSON_PATH_MAX];
    int n = cJSON_GetArraySize(item);
    if (!cJSON_IsArray(item) || n < 4 || n > 5) {
        json_path_index(path, sizeof path, list_path, index);
        return json_fail(err, err_size, path,
                         "expected [x, y, z, parent] or [x, y, z, parent, main]");
    }
    double v[5] = {0};
    int k = 0;
    for (const cJSON *c = item->child; c; c = c->next, k++) {
        number_range r = scene_node_element_range(k);
        if (cJSON_IsNumber(c) && number_range_holds(r, c->valuedouble)) {
            v[k] = c->valuedouble;
            continue;
        }
        json_path_index(path, sizeof path, list_path, index);
        json_path_index(elem, sizeof elem, path, (size_t)k);
        return json_number_value(c, elem, r, &v[k], err, err_size);
    }
    *node = scene_node_from(v);
    return 0;
}

int scene_check_tree(const fg_node *nodes, size_t count, const char *nodes_path, char *err,
                     size_t err_size)
{
    fg_tree_fault fault;
    if (fg_tree_check(nodes, count, &fault) == FG_OK)
        return 0;
    char what[128], path[JSON_PATH_MAX];
    fg_tree_fault_describe(&fault, what, sizeof what);
    /* a fault of the whole list (too few nodes) names the list */
    if (fault.node < count)
        json_path_index(path, sizeof path, nodes_path, fault.node);
    return json_fail(err, err_size, fault.node < count ? path : nodes_path, "%s", what);
}

int scene_parse_tree(const cJSON *item, const char *path, const double offset_m[3],
                     scene_node_lists *lists, const fg_node **nodes, size_t *count, char *err,
                     size_t err_size)
{
    char list_path[JSON_PATH_MAX];
    json_path_key(list_path, sizeof list_path, path, "nodes");
    if (json_check_keys(item, path, tree_keys, err, err_size))
        return -1;
    const cJSON *list = cJSON_GetObjectItemCaseSensitive(item, "nodes");
    if (!cJSON_IsArray(list))
        return json_fail(err, err_size, list_path, "required, an array of nodes");
    fg_node *out;
    size_t n;
    if (!scene_node_lists_take(lists, list, &out, &n)) {
        n = (size_t)cJSON_GetArraySize(list);
        out = fg_big_calloc(n ? n : 1, sizeof *out);
        if (!out)
            return json_fail(err, err_size, list_path, "out of memory");
        size_t i = 0;
        for (const cJSON *c = list->child; c; c = c->next, i++)
            if (parse_node(c, list_path, i, &out[i], err, err_size))
                goto fail;
    }
    fg_tree_translate(out, n, offset_m);
    if (scene_check_tree(out, n, list_path, err, err_size))
        goto fail;
    *nodes = out;
    *count = n;
    return 0;
fail:
    fg_big_free(out);
    return -1;
}
