/* The pieces of the scene parser, one file each. Each returns 0, or -1 with
 * a path-bearing message in err (see json_read.h). */
#ifndef HOST_SCENE_SCENE_INTERNAL_H
#define HOST_SCENE_SCENE_INTERNAL_H

#include "json_read.h"
#include "scene.h"

/* The seeds a scene may give: integers below 2^53, each exact in JSON. */
#define SCENE_SEED_RANGE ((number_range){0, 9007199254740992.0, .integer = true})

/* One explicit tree's "nodes" read by the streaming reader: discharge
 * index, the array's bytes [start, end) in the text (from its '[' to
 * past its ']'), its nodes (as
 * written, offset not applied) and its item in the parsed document. */
typedef struct scene_node_list {
    size_t discharge;
    size_t start, end;
    fg_node *nodes;
    size_t count;
    const cJSON *json;
} scene_node_list;

struct scene_node_lists {
    const char *text;  /* while reading */
    scene_node_list *list;
    size_t count;
    size_t next;       /* the next to take */
};

/* "listener" (item may be NULL: the default pose) into s->poses. */
int scene_parse_listener(const cJSON *item, scene *s, char *err, size_t err_size);

/* "layout" of the document json (may be absent: stereo) into s's layout,
 * order, channels and sofa_file (relative to dir). */
int scene_parse_layout(const cJSON *json, const char *dir, scene *s, char *err, size_t err_size);

/* "camera" (item may be NULL: none given) into s->camera. */
int scene_parse_camera(const cJSON *item, scene *s, char *err, size_t err_size);

/* One element of "discharges", at path, into *out (zeroed on entry; owns
 * out->nodes on success). Reads s's seed for the default seed. */
int scene_parse_discharge(const cJSON *item, const char *path, size_t index, const scene *s,
                          scene_discharge *out, char *err, size_t err_size);

/* Frees d's tree (the scene owns it; fg_discharge's pointer is const only
 * towards the engine) and sets it to none. */
void scene_discharge_free_tree(scene_discharge *d);

/* "propagation" at path (an object) over *p, which holds the defaults:
 * the keys present replace their effect's settings. */
int scene_parse_propagation(const cJSON *item, const char *path, fg_propagation_config *p, char *err,
                            size_t err_size);

/* "tree" at path: reads the nodes (those lists took from the text, or
 * the JSON's; lists may be NULL), adds offset_m and checks the tree into
 * *nodes (caller frees) and *count. */
int scene_parse_tree(const cJSON *item, const char *path, const double offset_m[3],
                     scene_node_lists *lists, const fg_node **nodes, size_t *count, char *err,
                     size_t err_size);

/* scene_node.c. Whether v[0..n) is a node the scene accepts ([x, y, z, parent] or
 * [x, y, z, parent, main], each within its range), and that node (v[4]
 * read only when n is 5: v must hold 0 there otherwise). */
int scene_node_values(const double *v, int n);
fg_node scene_node_from(const double v[5]);

/* The range of element k (0..4) of a node: coordinates, parent, main. */
number_range scene_node_element_range(int k);

/* The streaming reader (scene_nodes_stream.c): reads the explicit trees'
 * "nodes" arrays it can take from text into *lists and returns the rest
 * of the text (malloc'ed, *rest_size bytes), each taken array written
 * "[]"; NULL (and *lists empty) when it takes none or memory runs out. */
char *scene_nodes_stream(const char *text, size_t size, scene_node_lists *lists,
                         size_t *rest_size);

/* Points each list at its "nodes" item in json, the document parsed from
 * the rest of the text (before anything changes it). */
void scene_node_lists_bind(scene_node_lists *lists, const cJSON *json);

/* If nodes_json is the item of the next list (trees are read in document
 * order), moves that list's nodes to *nodes and *count and returns 1;
 * else 0. lists may be NULL. */
int scene_node_lists_take(scene_node_lists *lists, const cJSON *nodes_json, fg_node **nodes,
                          size_t *count);

/* Frees what the lists still hold and empties them. */
void scene_node_lists_free(scene_node_lists *lists);

/* fg_tree_check with the fault described at nodes_path ("...nodes[7]: ..."). */
int scene_check_tree(const fg_node *nodes, size_t count, const char *nodes_path, char *err,
                     size_t err_size);

/* "random" (absent: nothing to do): its discharges, drawn from its seed,
 * appended to s->discharges. The template is kept inside json. */
int scene_parse_random(cJSON *json, scene *s, char *err, size_t err_size);

/* "wind" and "aero_objects" (absent: nothing to do) into s->aeros, their
 * texture files read relative to dir (NULL: the working directory). */
int scene_parse_aero(const cJSON *json, const char *dir, scene *s, char *err, size_t err_size);

/* Frees s->aeros and their textures. */
void scene_aero_free(scene *s);

/* "fires" (absent: nothing to do) into s->fires, their flux files read
 * relative to dir. */
int scene_parse_fires(const cJSON *json, const char *dir, scene *s, char *err, size_t err_size);

/* Runs item's "simulation" (the flame simulation, offline, at sim_rate_hz)
 * into f's flux series (scene_fire_sim.c). */
int scene_fire_simulate(const cJSON *item, const char *path, double sim_rate_hz,
                        scene_fire *f, char *err, size_t err_size);

/* Frees s->fires, their paths and flux series. */
void scene_fire_free(scene *s);

#endif
