/* The discharge picture on Mesa llvmpipe (EGL surfaceless): a valid PNG,
 * the light where the segments project, a golden image, the timeline, a
 * marker where it projects, moved by a pose and changed by an update, and
 * bad input.
 *
 * The golden image: tests/gpu/golden/picture_tree.png. To regenerate it
 * after an intended change of the picture model, run
 *   FULGUR_REGEN_GOLDEN=1 BUILD/tests/gpu/test_gpu_picture tests/gpu/golden
 * from the source root, look at it, and commit it. */
#define _POSIX_C_SOURCE 200809L /* mkdtemp */
#include <dirent.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmocka.h>

#include "fulgur/gpu.h"
#include "fg_math.h"
#include "picture_fixture.h"

#define W 256
#define H 160
#define MAIN_NODES 11
#define NODES 19

static const char *golden_dir = "golden";

typedef struct fixture {
    fgg_context *ctx;
    fgg_picture *pic;
    fg_node nodes[NODES];
    fgg_camera cam;
    char dir[64];
} fixture;

/* A 10 m main channel zig-zagging down, a branch from node 3 going right
 * and down, and a branch of that branch. */
static void make_tree(fg_node *n)
{
    for (int i = 0; i < MAIN_NODES; i++)
        n[i] = (fg_node){0.6 * sin(1.7 * i), 0, 10.0 - i, i - 1, FG_NODE_MAIN};
    for (int k = 0; k < 5; k++) {
        int i = MAIN_NODES + k;
        int parent = k == 0 ? 3 : i - 1;
        n[i] = (fg_node){n[parent].x + 1.0, 0, n[parent].z - 0.7, parent, 0};
    }
    for (int k = 0; k < 3; k++) {
        int i = MAIN_NODES + 5 + k;
        int parent = k == 0 ? MAIN_NODES + 1 : i - 1;
        n[i] = (fg_node){n[parent].x - 0.5, 0, n[parent].z - 0.8, parent, 0};
    }
}

static int setup(void **state)
{
    fixture *f = calloc(1, sizeof *f);
    assert_non_null(f);
    fgg_context_config cc = {.backend = FGG_BACKEND_EGL};
    if (fgg_context_create(&cc, &f->ctx) != FG_OK) {
        fprintf(stderr, "no EGL context: %s\n", fgg_error_message());
        free(f);
        return -1;
    }
    fgg_picture_config pc = {.width = W, .height = H};
    if (fgg_picture_create(f->ctx, &pc, &f->pic) != FG_OK) {
        fprintf(stderr, "picture: %s\n", fgg_error_message());
        return -1;
    }
    make_tree(f->nodes);
    f->cam = (fgg_camera){.eye_m = {0.5, -30, 5}, .target_m = {0.5, 0, 5}, .up = {0, 0, 1},
                          .fov_y_deg = 30};
    strcpy(f->dir, "/tmp/fgg-picture-XXXXXX");
    assert_non_null(mkdtemp(f->dir));
    *state = f;
    return 0;
}

static int teardown(void **state)
{
    fixture *f = *state;
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", f->dir);
    if (system(cmd) != 0)
        fprintf(stderr, "could not remove %s\n", f->dir);
    fgg_picture_destroy(f->pic);
    fgg_context_destroy(f->ctx);
    free(f);
    return 0;
}

static void add_tree(fixture *f, double start_s, double leader_s, const double *strokes,
                     size_t stroke_count)
{
    fgg_picture_remove(f->pic, 0);
    fgg_flash fl = {.nodes = f->nodes, .node_count = NODES, .start_s = start_s,
                    .leader_s = leader_s, .stroke_offsets_s = strokes,
                    .stroke_count = stroke_count};
    assert_int_equal(fgg_picture_add(f->pic, &fl, NULL), FG_OK);
}

static uint8_t *draw_read(fixture *f, double t)
{
    return fixture_draw(f->pic, &f->cam, W, H, t);
}

static int lum(const uint8_t *px)
{
    return px[0] + px[1] + px[2];
}

static void project(const fgg_camera *c, const double p[3], double *px, double *py)
{
    fixture_project(c, W, H, p, px, py, NULL);
}

static double dist_to_segment(double x, double y, double ax, double ay, double bx, double by)
{
    double dx = bx - ax, dy = by - ay, l2 = dx * dx + dy * dy;
    double t = l2 > 0 ? ((x - ax) * dx + (y - ay) * dy) / l2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    return hypot(x - ax - t * dx, y - ay - t * dy);
}

/* Pixel distance from pixel (i, j)'s centre to the nearest segment among
 * those whose child node lies in [first, last]. */
static double dist_to_tree(const fixture *f, int i, int j, int first, int last)
{
    double best = 1e30;
    for (int n = first; n <= last; n++) {
        if (n == 0)
            continue;
        const fg_node *a = &f->nodes[f->nodes[n].parent], *b = &f->nodes[n];
        double pa[3] = {a->x, a->y, a->z}, pb[3] = {b->x, b->y, b->z}, ax, ay, bx, by;
        project(&f->cam, pa, &ax, &ay);
        project(&f->cam, pb, &bx, &by);
        best = fmin(best, dist_to_segment(i + 0.5, j + 0.5, ax, ay, bx, by));
    }
    return best;
}

/* --- Tests. --- */

static void png_is_valid_and_matches_the_frame(void **state)
{
    fixture *f = *state;
    add_tree(f, 1.0, 0.05, NULL, 0);
    uint8_t *rgba = draw_read(f, 1.0);
    char path[128];
    snprintf(path, sizeof path, "%s/frame.png", f->dir);
    assert_int_equal(fgg_picture_write_png(f->pic, path), FG_OK);
    int w = 0, h = 0;
    uint8_t *png = fixture_read_png(path, &w, &h);
    assert_non_null(png);
    assert_int_equal(w, W);
    assert_int_equal(h, H);
    assert_memory_equal(png, rgba, 4 * W * H);
    int lit = 0, peak = 0;
    for (int i = 0; i < W * H; i++) {
        lit += lum(&rgba[4 * i]) > 60;
        peak = lum(&rgba[4 * i]) > peak ? lum(&rgba[4 * i]) : peak;
        assert_int_equal(rgba[4 * i + 3], 255);
    }
    printf("lit pixels %d, peak %d\n", lit, peak);
    assert_true(lit > 300);
    assert_true(peak > 600);
    free(png);
    free(rgba);
}

static int by_lum_desc(const void *a, const void *b)
{
    const int *x = a, *y = b;
    return y[0] != x[0] ? y[0] - x[0] : x[1] - y[1];
}

static void brightest_pixels_lie_on_segments(void **state)
{
    fixture *f = *state;
    add_tree(f, 1.0, 0.05, NULL, 0);
    uint8_t *rgba = draw_read(f, 1.0);
    int(*order)[2] = malloc(sizeof(int[2]) * W * H);
    assert_non_null(order);
    for (int i = 0; i < W * H; i++) {
        order[i][0] = lum(&rgba[4 * i]);
        order[i][1] = i;
    }
    qsort(order, W * H, sizeof order[0], by_lum_desc);
    double worst = 0;
    for (int k = 0; k < 200; k++) {
        int i = order[k][1] % W, j = order[k][1] / W;
        worst = fmax(worst, dist_to_tree(f, i, j, 0, NODES - 1));
    }
    printf("200 brightest pixels: farthest %.2f px from a segment\n", worst);
    assert_true(worst <= 2.5);
    /* and the darkest of the frame is far from every segment */
    int i = order[W * H - 1][1] % W, j = order[W * H - 1][1] / W;
    assert_true(dist_to_tree(f, i, j, 0, NODES - 1) > 10);
    free(order);
    free(rgba);
}

static void matches_the_golden_image(void **state)
{
    fixture *f = *state;
    add_tree(f, 1.0, 0.05, NULL, 0);
    uint8_t *rgba = draw_read(f, 1.0);
    fixture_golden(f->pic, rgba, W, H, golden_dir, "picture_tree.png");
    free(rgba);
}

/* Summed luminance over pixels within 1.5 px of the nodes [first, last]'s
 * segments and more than 4 px from the others'. */
static double region_sum(const fixture *f, const uint8_t *rgba, int first, int last)
{
    double sum = 0;
    for (int j = 0; j < H; j++)
        for (int i = 0; i < W; i++) {
            if (dist_to_tree(f, i, j, first, last) > 1.5)
                continue;
            double other = fmin(first > 1 ? dist_to_tree(f, i, j, 1, first - 1) : 1e9,
                                last < NODES - 1 ? dist_to_tree(f, i, j, last + 1, NODES - 1)
                                                 : 1e9);
            if (other > 4)
                sum += lum(&rgba[4 * (j * W + i)]);
        }
    return sum;
}

/* Without bloom, so that the main channel's glow does not spill onto the
 * branches' pixels: the test is about what each segment emits. */
static void timeline(void **state)
{
    fixture *f = *state;
    fgg_picture *with_bloom = f->pic;
    fgg_picture_config pc = {.width = W, .height = H, .bloom = -1};
    assert_int_equal(fgg_picture_create(f->ctx, &pc, &f->pic), FG_OK);
    const double strokes[] = {0, 0.3};
    add_tree(f, 1.0, 0.1, strokes, 2);
    struct {
        double t, main, branch, total;
    } s[] = {{.t = 0.85}, {.t = 0.95}, {.t = 1.0}, {.t = 1.1}, {.t = 1.29}, {.t = 1.31}};
    enum { BEFORE, LEADER, STROKE, DECAYED, PRE_RESTRIKE, RESTRIKE };
    for (size_t k = 0; k < sizeof s / sizeof s[0]; k++) {
        uint8_t *rgba = draw_read(f, s[k].t);
        for (int i = 0; i < W * H; i++)
            s[k].total += lum(&rgba[4 * i]);
        s[k].main = region_sum(f, rgba, 1, MAIN_NODES - 1);
        s[k].branch = region_sum(f, rgba, MAIN_NODES, NODES - 1);
        printf("t %.2f s: main %.0f, branches %.0f, all %.0f\n", s[k].t, s[k].main,
               s[k].branch, s[k].total);
        free(rgba);
    }
    assert_true(s[BEFORE].total == 0);
    assert_true(s[LEADER].total > 0);
    assert_true(s[LEADER].main < 0.5 * s[STROKE].main);
    assert_true(s[DECAYED].main < 0.7 * s[STROKE].main);
    assert_true(s[PRE_RESTRIKE].main < s[DECAYED].main);
    assert_true(s[RESTRIKE].main > 1.5 * s[PRE_RESTRIKE].main);
    assert_true(s[RESTRIKE].branch <= s[PRE_RESTRIKE].branch * 1.01 + 1);
    assert_true(s[STROKE].branch > 2 * s[PRE_RESTRIKE].branch);
    fgg_picture_destroy(f->pic);
    f->pic = with_bloom;
}

/* Halfway through the leader the lower part of the main channel is dark. */
static void leader_grows_from_the_root(void **state)
{
    fixture *f = *state;
    add_tree(f, 1.0, 0.1, NULL, 0);
    uint8_t *rgba = draw_read(f, 0.93); /* 30 % of the way */
    double top = region_sum(f, rgba, 1, 2), bottom = region_sum(f, rgba, 8, MAIN_NODES - 1);
    printf("leader at 30 %%: top %.0f, bottom %.0f\n", top, bottom);
    assert_true(top > 0);
    assert_true(bottom == 0);
    free(rgba);
}

static int file_count(const char *dir)
{
    DIR *d = opendir(dir);
    assert_non_null(d);
    int n = 0;
    for (struct dirent *e; (e = readdir(d));)
        n += e->d_name[0] != '.';
    closedir(d);
    return n;
}

static void bad_input(void **state)
{
    fixture *f = *state;
    fgg_picture *none = NULL;
    fgg_picture_config pc = {.width = 8, .height = 8};
    assert_int_equal(fgg_picture_create(NULL, NULL, &none), FG_ERR_NULL);
    assert_int_equal(fgg_picture_create(f->ctx, NULL, NULL), FG_ERR_NULL);
    assert_int_equal(fgg_picture_create(f->ctx, &pc, &none), FG_ERR_ARGUMENT);
    pc = (fgg_picture_config){.width = 64, .height = 64, .exposure = NAN};
    assert_int_equal(fgg_picture_create(f->ctx, &pc, &none), FG_ERR_ARGUMENT);
    assert_null(none);
    fgg_picture_destroy(NULL);

    fgg_picture_remove(f->pic, 0);
    fgg_flash fl = {.nodes = f->nodes, .node_count = NODES, .start_s = 1};
    assert_int_equal(fgg_picture_add(NULL, &fl, NULL), FG_ERR_NULL);
    assert_int_equal(fgg_picture_add(f->pic, NULL, NULL), FG_ERR_NULL);
    fl.nodes = NULL;
    assert_int_equal(fgg_picture_add(f->pic, &fl, NULL), FG_ERR_NULL);
    fg_node bad[NODES];
    memcpy(bad, f->nodes, sizeof bad);
    bad[5].parent = 7; /* after the node: would allow a cycle */
    fl.nodes = bad;
    assert_int_equal(fgg_picture_add(f->pic, &fl, NULL), FG_ERR_TREE);
    memcpy(bad, f->nodes, sizeof bad);
    bad[4].z = NAN;
    assert_int_equal(fgg_picture_add(f->pic, &fl, NULL), FG_ERR_TREE);
    fl.nodes = f->nodes;
    fl.node_count = 1;
    assert_int_equal(fgg_picture_add(f->pic, &fl, NULL), FG_ERR_TREE);
    fl.node_count = NODES;
    fl.start_s = INFINITY;
    assert_int_equal(fgg_picture_add(f->pic, &fl, NULL), FG_ERR_NOT_FINITE);
    fl.start_s = 1;
    fl.leader_s = -1;
    assert_int_equal(fgg_picture_add(f->pic, &fl, NULL), FG_ERR_ARGUMENT);
    fl.leader_s = 0;
    const double neg[] = {0, -0.2};
    fl.stroke_offsets_s = neg;
    fl.stroke_count = 2;
    assert_int_equal(fgg_picture_add(f->pic, &fl, NULL), FG_ERR_ARGUMENT);
    /* nothing was added: the frame is black */
    uint8_t *rgba = draw_read(f, 1.0);
    for (int i = 0; i < W * H; i++)
        assert_int_equal(lum(&rgba[4 * i]), 0);
    free(rgba);

    fgg_camera cam = f->cam;
    assert_int_equal(fgg_picture_draw(NULL, &cam, 0), FG_ERR_NULL);
    assert_int_equal(fgg_picture_draw(f->pic, NULL, 0), FG_ERR_NULL);
    assert_int_equal(fgg_picture_draw(f->pic, &cam, NAN), FG_ERR_NOT_FINITE);
    memcpy(cam.eye_m, cam.target_m, sizeof cam.eye_m);
    assert_int_equal(fgg_picture_draw(f->pic, &cam, 0), FG_ERR_ARGUMENT);
    cam = f->cam;
    cam.up[0] = 0, cam.up[1] = 1, cam.up[2] = 0; /* along the view */
    assert_int_equal(fgg_picture_draw(f->pic, &cam, 0), FG_ERR_ARGUMENT);
    cam = f->cam;
    cam.eye_m[1] = NAN;
    assert_int_equal(fgg_picture_draw(f->pic, &cam, 0), FG_ERR_NOT_FINITE);
    cam = f->cam;
    cam.fov_y_deg = 180;
    assert_int_equal(fgg_picture_draw(f->pic, &cam, 0), FG_ERR_ARGUMENT);

    uint8_t px[4];
    assert_int_equal(fgg_picture_read_rgba8(NULL, px), FG_ERR_NULL);
    assert_int_equal(fgg_picture_read_rgba8(f->pic, NULL), FG_ERR_NULL);
    assert_int_equal(fgg_picture_write_png(NULL, "x.png"), FG_ERR_NULL);
    assert_int_equal(fgg_picture_write_png(f->pic, NULL), FG_ERR_NULL);

    /* unwritable: a missing directory, and a directory in the way */
    char path[160];
    snprintf(path, sizeof path, "%s/missing/frame.png", f->dir);
    int before = file_count(f->dir);
    assert_int_equal(fgg_picture_write_png(f->pic, path), FG_ERR_ARGUMENT);
    printf("%s\n", fgg_error_message());
    assert_non_null(strstr(fgg_error_message(), path));
    snprintf(path, sizeof path, "%s/in_the_way", f->dir);
    assert_int_equal(mkdir(path, 0700), 0);
    assert_int_equal(fgg_picture_write_png(f->pic, path), FG_ERR_ARGUMENT);
    printf("%s\n", fgg_error_message());
    assert_int_equal(file_count(f->dir), before + 1); /* the directory, no temporary */
    assert_int_equal(rmdir(path), 0);
}

/* The colour of the marker's disc near (x, y): a pixel 3 px right of and
 * below its centre, off the "+" and inside the rim. */
static const uint8_t *disc_px(const uint8_t *rgba, double x, double y)
{
    int i = (int)floor(x) + 3, j = (int)floor(y) + 3;
    assert_true(i >= 0 && i < W && j >= 0 && j < H);
    return &rgba[4 * (j * W + i)];
}

/* A marker is drawn where its point projects, red for +; a pose moves it,
 * an update turns it blue; bad drawables, poses and updates are refused
 * and change nothing. */
static void drawables_poses_and_bad_input(void **state)
{
    fixture *f = *state;
    fgg_picture_remove(f->pic, 0);
    const double at[3] = {f->nodes[5].x, f->nodes[5].y, f->nodes[5].z};
    fgg_drawable m = {.kind = FGG_DRAWABLE_MARKER,
                      .marker = {.position_m = {at[0], at[1], at[2]}, .sign = 1}};
    uint32_t id = 0;
    assert_int_equal(fgg_picture_add_drawable(f->pic, &m, &id), FG_OK);
    assert_true(id != 0);
    double x, y;
    project(&f->cam, at, &x, &y);
    uint8_t *rgba = draw_read(f, 0);
    const uint8_t *c = disc_px(rgba, x, y);
    printf("the + marker at (%.1f, %.1f): %d %d %d\n", x, y, c[0], c[1], c[2]);
    assert_true(c[0] > 150 && c[1] < 80 && c[2] < 80);
    free(rgba);

    /* moved 2 m along +x by a pose (rotated about z by 90 degrees: a point
     * at the body origin does not care), then turned negative */
    fgg_pose pose = {.position_m = {2, 0, 0}, .rotation = {0, -1, 0, 1, 0, 0, 0, 0, 1}};
    assert_int_equal(fgg_picture_set_pose(f->pic, id, &pose), FG_OK);
    const double moved[3] = {-at[1] + 2, at[0], at[2]};
    double mx, my;
    project(&f->cam, moved, &mx, &my);
    rgba = draw_read(f, 0);
    c = disc_px(rgba, mx, my);
    assert_true(c[0] > 150 && c[1] < 80 && c[2] < 80);
    assert_int_equal(lum(disc_px(rgba, x, y)), 0); /* not where it was */
    free(rgba);
    m.marker.sign = -1;
    assert_int_equal(fgg_picture_update(f->pic, id, &m), FG_OK);
    rgba = draw_read(f, 0);
    c = disc_px(rgba, mx, my);
    printf("the - marker moved to (%.1f, %.1f): %d %d %d\n", mx, my, c[0], c[1], c[2]);
    assert_true(c[2] > 150 && c[0] < 80);
    free(rgba);

    /* bad drawables: nothing is added */
    assert_int_equal(fgg_picture_add_drawable(NULL, &m, NULL), FG_ERR_NULL);
    assert_int_equal(fgg_picture_add_drawable(f->pic, NULL, NULL), FG_ERR_NULL);
    fgg_drawable d = {.kind = (fgg_drawable_kind)99};
    assert_int_equal(fgg_picture_add_drawable(f->pic, &d, NULL), FG_ERR_ARGUMENT);
    d = (fgg_drawable){.kind = FGG_DRAWABLE_SPHERE, .sphere = {.radius_m = 0}};
    assert_int_equal(fgg_picture_add_drawable(f->pic, &d, NULL), FG_ERR_ARGUMENT);
    d.sphere = (fgg_sphere){.centre_m = {0, NAN, 0}, .radius_m = 1};
    assert_int_equal(fgg_picture_add_drawable(f->pic, &d, NULL), FG_ERR_NOT_FINITE);
    d = (fgg_drawable){.kind = FGG_DRAWABLE_BOX, .box = {.min_m = {0, 0, 1}, .max_m = {1, 1, 0}}};
    assert_int_equal(fgg_picture_add_drawable(f->pic, &d, NULL), FG_ERR_ARGUMENT);
    d = (fgg_drawable){.kind = FGG_DRAWABLE_PLANE, .plane = {.half_size_m = 1}};
    assert_int_equal(fgg_picture_add_drawable(f->pic, &d, NULL), FG_ERR_ARGUMENT);
    d = (fgg_drawable){.kind = FGG_DRAWABLE_MARKER, .marker = {.sign = 2}};
    assert_int_equal(fgg_picture_add_drawable(f->pic, &d, NULL), FG_ERR_ARGUMENT);
    d = (fgg_drawable){.kind = FGG_DRAWABLE_VOLUME,
                       .volume = {.radius_m = 1, .height_m = 2, .temperature_k = 500}};
    assert_int_equal(fgg_picture_add_drawable(f->pic, &d, NULL), FG_ERR_ARGUMENT);
    d.volume.temperature_k = 1500, d.volume.intensity = -1;
    assert_int_equal(fgg_picture_add_drawable(f->pic, &d, NULL), FG_ERR_ARGUMENT);
    d = (fgg_drawable){.kind = FGG_DRAWABLE_GROUND, .ground = {.height_m = 10, .cloud_base_m = 5}};
    assert_int_equal(fgg_picture_add_drawable(f->pic, &d, NULL), FG_ERR_ARGUMENT);
    /* bad updates and poses: nothing changes */
    fgg_drawable sphere = {.kind = FGG_DRAWABLE_SPHERE, .sphere = {.radius_m = 1}};
    assert_int_equal(fgg_picture_update(f->pic, id, &sphere), FG_ERR_ARGUMENT);
    assert_int_equal(fgg_picture_update(f->pic, id + 1000, &m), FG_ERR_NOT_FOUND);
    fgg_drawable bad_m = m;
    bad_m.marker.position_m[0] = INFINITY;
    assert_int_equal(fgg_picture_update(f->pic, id, &bad_m), FG_ERR_NOT_FINITE);
    fgg_pose skew = {.rotation = {1, 0.1, 0, 0, 1, 0, 0, 0, 1}};
    assert_int_equal(fgg_picture_set_pose(f->pic, id, &skew), FG_ERR_ARGUMENT);
    fgg_pose mirror = {.rotation = {-1, 0, 0, 0, 1, 0, 0, 0, 1}};
    assert_int_equal(fgg_picture_set_pose(f->pic, id, &mirror), FG_ERR_ARGUMENT);
    fgg_pose far = {.position_m = {NAN, 0, 0}};
    assert_int_equal(fgg_picture_set_pose(f->pic, id, &far), FG_ERR_NOT_FINITE);
    assert_int_equal(fgg_picture_set_pose(f->pic, id + 1000, NULL), FG_ERR_NOT_FOUND);
    rgba = draw_read(f, 0);
    c = disc_px(rgba, mx, my);
    assert_true(c[2] > 150 && c[0] < 80); /* still the blue marker where the pose put it */
    free(rgba);
    /* a second ground is refused */
    d = (fgg_drawable){.kind = FGG_DRAWABLE_GROUND};
    assert_int_equal(fgg_picture_add_drawable(f->pic, &d, NULL), FG_OK);
    assert_int_equal(fgg_picture_add_drawable(f->pic, &d, NULL), FG_ERR_ARGUMENT);
    fgg_picture_remove(f->pic, 0);
}

/* The mean R, G, B over the 5 x 5 pixels around where p projects. */
static void mean_rgb_at(const fixture *f, const uint8_t *rgba, const double p[3], double rgb[3])
{
    double x, y;
    project(&f->cam, p, &x, &y);
    int i0 = (int)floor(x) - 2, j0 = (int)floor(y) - 2;
    assert_true(i0 >= 0 && i0 + 5 <= W && j0 >= 0 && j0 + 5 <= H);
    rgb[0] = rgb[1] = rgb[2] = 0;
    for (int j = j0; j < j0 + 5; j++)
        for (int i = i0; i < i0 + 5; i++)
            for (int c = 0; c < 3; c++)
                rgb[c] += rgba[4 * (j * W + i) + c] / 25.0;
}

/* A flame (a volume) with a matte wall behind it, no discharge, no
 * ambient: the flame glows warm (red over blue) where it stands and not
 * far above it, and it lights the wall beside it; at intensity 0 (an
 * update) both are dark. */
static void a_flame_glows_and_lights_the_wall(void **state)
{
    fixture *f = *state;
    fgg_picture_remove(f->pic, 0);
    fgg_drawable flame = {.kind = FGG_DRAWABLE_VOLUME,
                          .volume = {.base_m = {0.5, 0, 1}, .radius_m = 0.8, .height_m = 4,
                                     .intensity = 1, .seed = 7}};
    fgg_drawable wall = {.kind = FGG_DRAWABLE_BOX,
                         .box = {.min_m = {-6, 1, -1}, .max_m = {7, 1.2, 11},
                                 .surface = {.material = FGG_MATERIAL_MATTE}}};
    uint32_t id;
    assert_int_equal(fgg_picture_add_drawable(f->pic, &wall, NULL), FG_OK);
    assert_int_equal(fgg_picture_add_drawable(f->pic, &flame, &id), FG_OK);
    assert_int_equal(fgg_picture_lit_count(f->pic, 0), 1);
    const double in_flame[3] = {0.5, 0, 2.2}, above[3] = {0.5, 0, 9.5},
                 beside[3] = {3.5, 1, 2.5};
    double rgb_in[3], rgb_above[3], rgb_beside[3];
    uint8_t *rgba = draw_read(f, 0);
    mean_rgb_at(f, rgba, in_flame, rgb_in);
    mean_rgb_at(f, rgba, above, rgb_above);
    mean_rgb_at(f, rgba, beside, rgb_beside);
    free(rgba);
    printf("flame %.0f %.0f %.0f, above it %.0f %.0f %.0f, the wall beside it %.0f %.0f %.0f\n",
           rgb_in[0], rgb_in[1], rgb_in[2], rgb_above[0], rgb_above[1], rgb_above[2],
           rgb_beside[0], rgb_beside[1], rgb_beside[2]);
    assert_true(rgb_in[0] > 120 && rgb_in[0] > rgb_in[2] + 30);
    double lum_in = rgb_in[0] + rgb_in[1] + rgb_in[2];
    assert_true(rgb_above[0] + rgb_above[1] + rgb_above[2] < 0.25 * lum_in);
    assert_true(rgb_beside[0] > 8 && rgb_beside[0] >= rgb_beside[2]);

    flame.volume.intensity = 0;
    assert_int_equal(fgg_picture_update(f->pic, id, &flame), FG_OK);
    assert_int_equal(fgg_picture_lit_count(f->pic, 0), 0);
    rgba = draw_read(f, 0);
    mean_rgb_at(f, rgba, in_flame, rgb_in);
    mean_rgb_at(f, rgba, beside, rgb_beside);
    free(rgba);
    assert_true(rgb_in[0] + rgb_in[1] + rgb_in[2] < 3);
    assert_true(rgb_beside[0] + rgb_beside[1] + rgb_beside[2] < 3);
    fgg_picture_remove(f->pic, 0);
}

int main(int argc, char **argv)
{
    if (argc > 1)
        golden_dir = argv[1];
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(png_is_valid_and_matches_the_frame),
        cmocka_unit_test(brightest_pixels_lie_on_segments),
        cmocka_unit_test(matches_the_golden_image),
        cmocka_unit_test(timeline),
        cmocka_unit_test(leader_grows_from_the_root),
        cmocka_unit_test(bad_input),
        cmocka_unit_test(drawables_poses_and_bad_input),
        cmocka_unit_test(a_flame_glows_and_lights_the_wall),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
