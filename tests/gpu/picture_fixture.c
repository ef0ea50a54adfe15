/* The picture tests' shared pieces (picture_fixture.h). */
#include <math.h>
#include <png.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "fg_math.h"
#include "picture_fixture.h"

uint8_t *fixture_read_png(const char *path, int *w, int *h)
{
    png_image img;
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&img, path))
        return NULL;
    img.format = PNG_FORMAT_RGBA;
    uint8_t *buf = malloc(PNG_IMAGE_SIZE(img));
    if (!buf || !png_image_finish_read(&img, NULL, buf, 0, NULL)) {
        free(buf);
        png_image_free(&img);
        return NULL;
    }
    *w = (int)img.width;
    *h = (int)img.height;
    return buf;
}

double fixture_focal_px(const fgg_camera *c, int h)
{
    double fov = c->fov_y_deg == 0 ? 45 : c->fov_y_deg;
    return 0.5 * h / tan(fov * FG_PI / 360);
}

void fixture_project(const fgg_camera *c, int w, int h, const double p[3], double *px,
                     double *py, double *depth_m)
{
    double f[3], s[3], u[3], d[3], up[3] = {c->up[0], c->up[1], c->up[2]};
    if (up[0] == 0 && up[1] == 0 && up[2] == 0)
        up[2] = 1;
    for (int k = 0; k < 3; k++) {
        f[k] = c->target_m[k] - c->eye_m[k];
        d[k] = p[k] - c->eye_m[k];
    }
    double fl = sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (int k = 0; k < 3; k++)
        f[k] /= fl;
    s[0] = f[1] * up[2] - f[2] * up[1];
    s[1] = f[2] * up[0] - f[0] * up[2];
    s[2] = f[0] * up[1] - f[1] * up[0];
    double sl = sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    for (int k = 0; k < 3; k++)
        s[k] /= sl;
    u[0] = s[1] * f[2] - s[2] * f[1];
    u[1] = s[2] * f[0] - s[0] * f[2];
    u[2] = s[0] * f[1] - s[1] * f[0];
    double x = s[0] * d[0] + s[1] * d[1] + s[2] * d[2];
    double y = u[0] * d[0] + u[1] * d[1] + u[2] * d[2];
    double z = f[0] * d[0] + f[1] * d[1] + f[2] * d[2];
    double focal = fixture_focal_px(c, h);
    *px = 0.5 * w + focal * x / z;
    *py = 0.5 * h - focal * y / z;
    if (depth_m)
        *depth_m = z;
}

uint8_t *fixture_draw(fgg_picture *pic, const fgg_camera *c, int w, int h, double t)
{
    uint8_t *rgba = malloc(4 * (size_t)w * (size_t)h);
    assert_non_null(rgba);
    assert_int_equal(fgg_picture_draw(pic, c, t), FG_OK);
    assert_int_equal(fgg_picture_read_rgba8(pic, rgba), FG_OK);
    return rgba;
}

int fixture_lum(const uint8_t *rgba, int w, int x, int y)
{
    const uint8_t *p = &rgba[4 * ((size_t)y * (size_t)w + (size_t)x)];
    return p[0] + p[1] + p[2];
}

double fixture_ring_mean(const uint8_t *rgba, int w, int h, double cx, double cy, double r0,
                         double r1, int upper)
{
    double sum = 0;
    int n = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            double d = hypot(x + 0.5 - cx, y + 0.5 - cy);
            if (d < r0 || d >= r1 || (upper && y + 0.5 >= cy))
                continue;
            sum += fixture_lum(rgba, w, x, y);
            n++;
        }
    return n ? sum / n : -1;
}

void fixture_golden(fgg_picture *pic, const uint8_t *rgba, int w, int h, const char *golden_dir,
                    const char *name)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s", golden_dir, name);
    if (getenv("FULGUR_REGEN_GOLDEN")) {
        assert_int_equal(fgg_picture_write_png(pic, path), FG_OK);
        printf("wrote %s\n", path);
    }
    int gw = 0, gh = 0;
    uint8_t *golden = fixture_read_png(path, &gw, &gh);
    if (!golden)
        fail_msg("cannot read the golden image %s", path);
    assert_int_equal(gw, w);
    assert_int_equal(gh, h);
    double sum = 0;
    int max = 0;
    for (size_t i = 0; i < 4 * (size_t)w * (size_t)h; i++) {
        int d = abs((int)rgba[i] - (int)golden[i]);
        sum += d;
        max = d > max ? d : max;
    }
    double mean = sum / (4.0 * w * h);
    printf("%s: mean abs difference %.4f, max %d\n", name, mean, max);
    assert_true(mean < 0.5);
    assert_true(max <= 48);
    free(golden);
}
