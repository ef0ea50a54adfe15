/* What the picture tests share: reading PNGs, the camera's projection in
 * double (as picture_frame.c computes it), luminance, and comparing a
 * frame with its golden image (or writing it, with FULGUR_REGEN_GOLDEN). */
#ifndef TESTS_GPU_PICTURE_FIXTURE_H
#define TESTS_GPU_PICTURE_FIXTURE_H

#include <stdint.h>

#include "fulgur/gpu.h"

/* An 8-bit RGBA PNG (rows top first), malloc'd; NULL when it is not one. */
uint8_t *fixture_read_png(const char *path, int *w, int *h);

/* Where p lands on a w x h picture from camera c: pixel coordinates from
 * the top left (the centre of pixel i is i + 0.5); *depth_m the distance
 * along the view (negative: behind the eye). */
void fixture_project(const fgg_camera *c, int w, int h, const double p[3], double *px,
                     double *py, double *depth_m);

/* The focal length in pixels: how many pixels a view-space x / z of 1 is. */
double fixture_focal_px(const fgg_camera *c, int h);

/* Draws pic at t from c and reads the w x h frame back, malloc'd; fails
 * the test on an error. */
uint8_t *fixture_draw(fgg_picture *pic, const fgg_camera *c, int w, int h, double t);

/* R + G + B of the pixel (x, y) of a w-wide frame. */
int fixture_lum(const uint8_t *rgba, int w, int x, int y);

/* The mean of R + G + B over pixels whose centre lies at a distance in
 * [r0, r1) of (cx, cy), above it (y < cy) when upper; -1 when none. */
double fixture_ring_mean(const uint8_t *rgba, int w, int h, double cx, double cy, double r0,
                         double r1, int upper);

/* Compares the frame with golden_dir/name (mean absolute difference < 0.5,
 * max <= 48 over every byte), after writing it there when the environment
 * sets FULGUR_REGEN_GOLDEN (from pic's last frame). Fails the test on a
 * mismatch or an unreadable golden image. */
void fixture_golden(fgg_picture *pic, const uint8_t *rgba, int w, int h, const char *golden_dir,
                    const char *name);

#endif
