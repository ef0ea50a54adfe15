/* The pieces of the scene parser, one file each. Each returns 0, or -1 with
 * a path-bearing message in err (see json_read.h). */
#ifndef HOST_SCENE_SCENE_INTERNAL_H
#define HOST_SCENE_SCENE_INTERNAL_H

#include "json_read.h"
#include "scene.h"

/* The seeds a scene may give: integers below 2^53, each exact in JSON. */
#define SCENE_SEED_RANGE ((number_range){0, 9007199254740992.0, .integer = true})

/* "listener" (item may be NULL: the default pose) into s->poses. */
int scene_parse_listener(const cJSON *item, scene *s, char *err, size_t err_size);

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

/* "tree" at path: reads the nodes, adds offset_m and checks the tree into
 * *nodes (caller frees) and *count. */
int scene_parse_tree(const cJSON *item, const char *path, const double offset_m[3],
                     const fg_node **nodes, size_t *count, char *err, size_t err_size);

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

/* Frees s->fires, their paths and flux series. */
void scene_fire_free(scene *s);

#endif
