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

/* Adds the surroundings and every discharge of the built scene as a flash
 * at its emit time with the engine's stroke offsets: the whole scene's
 * picture, as fulgur render --png draws it. Returns 0, or -1 with a
 * message naming the discharge. */
int picture_add_scene(fgg_picture *pic, const scene *s, char *err, size_t err_size);

/* The time of the scene's first return stroke (the earliest emit time):
 * a picture's default time. */
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

/* The camera gpu/ takes for a scene camera. */
void picture_camera(const scene_camera *sc, fgg_camera *out);

#endif
