/* A scene as gpu/'s picture shows it: the surroundings (the outdoors of a
 * lightning scene, or a dim room), every discharge's apparatus (its
 * electrodes and what holds them), and each discharge's flash: its
 * colour, its leader. fulgur render --png and fulgur view both draw a
 * scene through these, so the two show the same thing. [gpu-thread] */
#ifndef HOST_PICTURE_PICTURE_H
#define HOST_PICTURE_PICTURE_H

#include <stdbool.h>
#include <stddef.h>

#include "fulgur/gpu.h"
#include "scene/scene.h"

/* How long a leader is shown growing before its return stroke. */
#define PICTURE_LEADER_S 0.03

/* Whether the scene is outdoors: it has a lightning discharge. */
bool picture_outdoors(const scene *s);

/* The picture configuration for a scene at a size: indoors, a dim room's
 * ambient light so that the apparatus shows before the first spark. */
void picture_config(const scene *s, int width, int height, fgg_picture_config *out);

/* Adds the scene's surroundings and the apparatus of every discharge
 * (built), each different one once: for lightning the ground, the night
 * sky and a cloud deck just below the channels' tops; brass balls on
 * stems for a spark gap; a plasma ball's electrode, glass globe, base and
 * the table it stands on; a field generator's conductors (spheres, boxes,
 * planes; glass for those that enclose). Returns 0, or -1 with a message
 * naming the discharge. */
int picture_add_surroundings(fgg_picture *pic, const scene *s, char *err, size_t err_size);

/* Adds the surroundings, every discharge of the built scene as a flash
 * at its emit time with the engine's stroke offsets, and the fires and
 * aero objects where they are at t_s (picture_sources_add): the whole
 * scene's picture at t_s, as fulgur render --png draws it. Returns 0, or
 * -1 with a message naming the discharge, fire or object. */
int picture_add_scene(fgg_picture *pic, const scene *s, double t_s, char *err, size_t err_size);

/* The time of the scene's first return stroke (the earliest emit time),
 * 0 for a scene without discharges: a picture's default time. */
double picture_first_stroke_s(const scene *s);

/* When a discharge's leader starts showing (its emit time, less the
 * leader's time unless it is continuous). */
double picture_leader_start_s(const scene_discharge *d);

/* The discharge a picture at t_s is of: the latest whose leader has
 * started by then, or else the first to come. */
size_t picture_framed_discharge(const scene *s, double t_s);

/* The flash of a discharge of preset `preset` that the engine posts as
 * post (its tree, continuous repeat), starting at start_s on the
 * picture's clock, with the stroke offsets the engine will use. */
void picture_flash(const fg_discharge *post, fg_preset preset, double start_s,
                   const double *strokes_s, uint32_t stroke_count, fgg_flash *out);

/* A fire's flame in the picture (gpu/'s emissive volume): its base's
 * radius and its height, the same for every fire; it flickers by itself. */
#define PICTURE_FLAME_RADIUS_M 0.2
#define PICTURE_FLAME_HEIGHT_M 0.6

/* Adds the scene's fires (a flame each, where the fire is at t_s) and aero
 * objects (a stick a steel rod along its span, its D across; a compact
 * body a ball) at their poses at t_s; ids[fire_count + aero_count]
 * receives their ids, the fires first. Returns 0, or -1 with a message
 * naming the fire or object. */
int picture_sources_add(fgg_picture *pic, const scene *s, double t_s, uint32_t *ids, char *err,
                        size_t err_size);

/* Moves what picture_sources_add added to the poses at t_s (a fixed fire
 * stays). Returns 0, or -1 with a message naming the fire or object. */
int picture_sources_move(fgg_picture *pic, const scene *s, double t_s, const uint32_t *ids,
                         char *err, size_t err_size);

/* The camera gpu/ takes for a scene camera. */
void picture_camera(const scene_camera *sc, fgg_camera *out);

#endif
