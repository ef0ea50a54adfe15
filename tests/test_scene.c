/* The scene parser: a table of bad scenes, each with its exact message;
 * defaults; the listener path; derived seeds. */
#define _POSIX_C_SOURCE 200809L /* mkdtemp, mkfifo, truncate */
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

#include "scene/generator.h"
#include "scene/scene.h"

#define SQRT_HALF 0.70710678118654752
#define TREE "\"tree\":{\"nodes\":[[0,0,0,-1],[0,0,0.01,0]]}"
#define SPARK "{\"time\":0,\"preset\":\"spark_balls\"," TREE "}"
#define WITH_SPARK(top) "{" top "\"discharges\":[" SPARK "]}"
#define ONE(fields) "{\"discharges\":[{\"time\":0,\"preset\":\"spark_balls\"," fields "}]}"
#define ONE_TREE(fields) ONE(fields "," TREE)

static int parse(const char *json, scene *s, char *err, size_t size)
{
    return scene_parse(json, strlen(json), s, err, size);
}

static const struct {
    const char *json;
    const char *message;
} bad[] = {
    {WITH_SPARK("\"sample_rate\":1000,"), "sample_rate: 1000 is outside 8000..384000"},
    {WITH_SPARK("\"camera\":{\"target\":[0,1,0]},"),
     "camera.eye: required (where the camera is, [x, y, z])"},
    {WITH_SPARK("\"camera\":{\"eye\":[0,1,0],\"target\":[0,1,0]},"),
     "camera.target: must differ from camera.eye"},
    {WITH_SPARK("\"camera\":{\"eye\":[0,0,0],\"target\":[0,0,5]},"),
     "camera.up: is parallel to the view (eye to target)"},
    {WITH_SPARK("\"camera\":{\"eye\":[0,0,0],\"target\":[0,1,0],\"fov\":180},"),
     "camera.fov: 180 is outside (0, 179)"},
    {WITH_SPARK("\"camera\":{\"eye\":[0,0,0],\"target\":[0,1,0],\"zoom\":2},"),
     "camera.zoom: unknown key (known: eye, target, up, fov)"},
    {WITH_SPARK("\"sample_rate\":1e999,"),
     "sample_rate: expected an integer in 8000..384000, not infinity"},
    {WITH_SPARK("\"channels\":3,"), "channels: 3 is outside 1..2"},
    {WITH_SPARK("\"channels\":\"2\","), "channels: expected an integer in 1..2"},
    {WITH_SPARK("\"block\":0.5,"), "block: 0.5 is not an integer"},
    {WITH_SPARK("\"duration\":0,"), "duration: 0 is outside (0, 3600]"},
    {WITH_SPARK("\"seed\":-1,"), "seed: -1 is outside 0..9007199254740992"},
    {WITH_SPARK("\"gain\":0,"), "gain: 0 is outside (0, 1000000000]"},
    {WITH_SPARK("\"speed_of_sound\":343,\"temperature_c\":20,"),
     "temperature_c: give speed_of_sound or temperature_c, not both"},
    {WITH_SPARK("\"channels\":1,\"channels\":2,"), "channels: given twice"},
    {WITH_SPARK("\"smaple_rate\":48000,"),
     "smaple_rate: unknown key (known: sample_rate, channels, block, duration, seed, gain, "
     "speed_of_sound, temperature_c, humidity, pressure, propagation, listener, discharges, "
     "random, camera, description, aero_objects, wind, fires, layout)"},
    {WITH_SPARK("\"humidity\":0,"), "humidity: 0 is outside (0, 100]"},
    {WITH_SPARK("\"propagation\":{\"refraction\":{\"radius\":5000}},"),
     "propagation.refraction.radius: 5000 is outside 20000..200000"},
    {WITH_SPARK("\"propagation\":{\"refraction\":1},"),
     "propagation.refraction: expected true, false or an object"},
    {WITH_SPARK("\"propagation\":{\"absorption\":\"iso\"},"),
     "propagation.absorption: expected \"off\", \"iso9613\" or \"abe_fir\""},
    {WITH_SPARK("\"propagation\":{\"absorption\":{\"distance\":10}},"),
     "propagation.absorption.model: required (\"off\", \"iso9613\" or \"abe_fir\")"},
    {WITH_SPARK("\"propagation\":{\"ground\":{\"reflection\":1.5}},"),
     "propagation.ground.reflection: 1.5 is outside (0, 1]"},
    {WITH_SPARK("\"propagation\":{\"turbulence\":{\"lenght\":5}},"),
     "propagation.turbulence.lenght: unknown key (known: amplitude, length)"},
    {WITH_SPARK("\"propagation\":{\"head_shadow\":\"yes\"},"),
     "propagation.head_shadow: expected true or false"},
    {WITH_SPARK("\"propagation\":{\"wind\":true},"),
     "propagation.wind: unknown key (known: refraction, turbulence, absorption, ground, "
     "head_shadow)"},
    {ONE_TREE("\"model\":\"glassner\""),
     "discharges[0].model: expected \"wm\" (Matsuyama) or \"abe\" (Abe et al.)"},
    {"[1, 2]", "scene: expected an object"},
    {"{\"discharges\": [}", "scene: JSON syntax error at line 1, column 17"},
    {"{\"discharges\":\n  [1,]}", "scene: JSON syntax error at line 2, column 6"},
    {WITH_SPARK("") " x", "scene: unexpected text after the JSON document at line 1, column 95"},
    {"{}", "discharges: required (an array of discharges), unless \"random\", "
           "\"aero_objects\" or \"fires\" is given"},
    {"{\"discharges\":[]}", "discharges: expected a non-empty array"},
    {"{\"discharges\":[3]}", "discharges[0]: expected an object"},
    {"{\"discharges\":[{\"preset\":\"spark_balls\"," TREE "}]}",
     "discharges[0].time: required (emit time, seconds)"},
    {ONE_TREE("\"tme\":1"),
     "discharges[0].tme: unknown key (known: time, preset, T0, r0, ps0, sigma0, t0_jitter, "
     "return_stroke_speed, ref_half_len, strokes, continuous, seed, offset, propagation, model, tree, "
     "generator, description)"},
    {"{\"discharges\":[{\"time\":0,\"preset\":\"sprak\"," TREE "}]}",
     "discharges[0].preset: unknown preset \"sprak\" "
     "(spark_balls, plasma_ball, lightning, lightning_table1)"},
    {"{\"discharges\":[{\"time\":0," TREE "}]}",
     "discharges[0].preset: required (spark_balls, plasma_ball, lightning, lightning_table1)"},
    {ONE_TREE("\"T0\":-1"), "discharges[0].T0: -1 is outside 1e-07..0.1"},
    {ONE_TREE("\"t0_jitter\":1"), "discharges[0].t0_jitter: 1 is outside [0, 1)"},
    {ONE_TREE("\"strokes\":33"), "discharges[0].strokes: 33 is outside 0..32"},
    {ONE_TREE("\"offset\":[1,2]"), "discharges[0].offset: expected an array [x, y, z]"},
    {ONE_TREE("\"strokes\":3,\"continuous\":{\"duration\":1}"),
     "discharges[0].strokes: a continuous discharge has one stroke, not 3"},
    {ONE_TREE("\"continuous\":{}"),
     "duration: required, since discharges[0] is continuous without a duration"},
    {ONE_TREE("\"continuous\":{\"min_interval\":0.06,\"duration\":1}"),
     "discharges[0].continuous.min_interval: 0.06 s is above max_interval (0.05 s)"},
    {ONE_TREE("\"continuous\":{\"every\":0.01}"),
     "discharges[0].continuous.every: unknown key (known: min_interval, max_interval, "
     "duration)"},
    {"{\"duration\":4,\"discharges\":[{\"time\":5,\"preset\":\"spark_balls\"," TREE "}]}",
     "discharges[0].time: 5 s is not before the scene's end (4 s)"},
    {ONE("\"generator\":{\"type\":\"spark_gap\"}," TREE),
     "discharges[0]: give exactly one of \"tree\" and \"generator\""},
    {ONE("\"seed\":1"), "discharges[0]: give exactly one of \"tree\" and \"generator\""},
    {ONE("\"generator\":{\"kind\":\"x\"}"),
     "discharges[0].generator.type: required, a string (known: %s)"},
    {ONE("\"generator\":{\"type\":\"sprak_gap\"}"),
     "discharges[0].generator.type: unknown generator \"sprak_gap\" (known: %s)"},
    {ONE("\"tree\":{\"nodes\":[[0,0,0,-1],[0,0,1,0],[0,0,2,5]]}"),
     "discharges[0].tree.nodes[2]: parent 5 is not before node 2"},
    {ONE("\"tree\":{\"nodes\":[[0,0,0,-1],[0,0,1,0],[0,0,2,2]]}"),
     "discharges[0].tree.nodes[2]: parent 2 is not before node 2"},
    {ONE("\"tree\":{\"nodes\":[[0,0,0,0],[0,0,1,0]]}"),
     "discharges[0].tree.nodes[0]: node 0 must be the root (parent -1), not have parent 0"},
    {ONE("\"tree\":{\"nodes\":[[0,0,0,-1],[0,0,1,-1]]}"),
     "discharges[0].tree.nodes[1]: node 1 has no parent; only node 0 may be the root"},
    {ONE("\"tree\":{\"nodes\":[[0,0,0,-1],[0,0,0,0]]}"),
     "discharges[0].tree.nodes[1]: node 1 lies on its parent 0 (zero-length segment)"},
    {ONE("\"tree\":{\"nodes\":[[0,0,0,-1]]}"),
     "discharges[0].tree.nodes: 1 node(s): a tree needs at least 2 (one segment)"},
    {ONE("\"tree\":{\"nodes\":[[0,0,0,-1],[0,0,1]]}"),
     "discharges[0].tree.nodes[1]: expected [x, y, z, parent] or [x, y, z, parent, main]"},
    {ONE("\"tree\":{\"nodes\":[[0,0,0,-1],[0,0,1,0,2]]}"),
     "discharges[0].tree.nodes[1][4]: 2 is outside 0..1"},
    {ONE("\"tree\":{\"nodes\":[[0,0,0,-1],[0,0,1,0.5]]}"),
     "discharges[0].tree.nodes[1][3]: 0.5 is not an integer"},
    {ONE("\"tree\":{\"nodes\":[[0,0,0,-1],[0,\"a\",1,0]]}"),
     "discharges[0].tree.nodes[1][1]: expected a number in -10000000..10000000"},
    {ONE("\"tree\":{\"node\":[]}"), "discharges[0].tree.node: unknown key (known: nodes)"},
    {WITH_SPARK("\"random\":{\"preset\":\"spark_balls\"," TREE "},"),
     "random.rate_hz: required (discharges per second)"},
    {WITH_SPARK("\"random\":{\"rate_hz\":1,\"preset\":\"spark_balls\"," TREE "},"),
     "random.end: required when the scene has no duration (when random discharges stop)"},
    {WITH_SPARK("\"duration\":2,\"random\":{\"rate_hz\":1,\"end\":3,\"preset\":\"spark_balls\"," TREE "},"),
     "random.end: 3 s is after the scene's end (2 s)"},
    {WITH_SPARK("\"random\":{\"rate_hz\":1,\"end\":3,\"time\":1,\"preset\":\"spark_balls\"," TREE "},"),
     "random.time: not allowed: times are drawn at rate_hz"},
    {WITH_SPARK("\"random\":{\"rate_hz\":1,\"end\":3,\"region\":{\"min\":[0,0,1],\"max\":[0,0,0]},\"preset\":\"spark_balls\"," TREE "},"),
     "random.region.min: above max in coordinate 2 (1 > 0)"},
    /* the region once shifted trees past the check: exit 1, no path */
    {WITH_SPARK("\"random\":{\"rate_hz\":1,\"end\":3,\"region\":{\"min\":[-1e308,0,0],\"max\":[1e308,0,0]},\"preset\":\"spark_balls\"," TREE "},"),
     "random.region.min: coordinate 0 (-1e+308) is beyond +-1e+07 m"},
    {WITH_SPARK("\"random\":{\"rate_hz\":1,\"end\":3,\"region\":{\"min\":[0,0,1e7],\"max\":[0,0,1e7]},\"preset\":\"spark_balls\"," TREE "},"),
     "random.region: a discharge shifted by [0, 0, 10000000] is refused: random.tree.nodes[1]: "
     "node 1 has a coordinate of 1e+07 m, beyond +-1e+07 m"},
    {WITH_SPARK("\"random\":{\"rate_hz\":1,\"end\":3,\"preset\":\"sprak\"," TREE "},"),
     "random.preset: unknown preset \"sprak\" "
     "(spark_balls, plasma_ball, lightning, lightning_table1)"},
    {WITH_SPARK("\"listener\":{\"position\":[0,0,0],\"up\":[0,2,0]},"),
     "listener.up: is parallel to forward"},
    /* 0.03 degrees apart: the engine refuses under 0.06 (the parser once
     * passed it, and the render failed at its first pose) */
    {WITH_SPARK("\"listener\":{\"up\":[0,1,0.0005]},"), "listener.up: is parallel to forward"},
    {WITH_SPARK("\"listener\":{\"forward\":[0,0,0]},"),
     "listener.forward: must have a finite, non-zero length"},
    {WITH_SPARK("\"listener\":{\"position\":[0,0,0],\"path\":[]},"),
     "listener: give either \"path\" or position/forward/up, not both"},
    {WITH_SPARK("\"listener\":{\"path\":[]},"),
     "listener.path: expected a non-empty array of poses"},
    {WITH_SPARK("\"listener\":{\"path\":[{\"position\":[0,0,0]}]},"),
     "listener.path[0].time: required (seconds)"},
    {WITH_SPARK("\"listener\":{\"path\":[{\"time\":0}]},"),
     "listener.path[0].position: required ([x, y, z] in metres)"},
    {WITH_SPARK("\"listener\":{\"path\":[{\"time\":2,\"position\":[0,0,0]},"
                "{\"time\":1,\"position\":[0,0,0]}]},"),
     "listener.path[1].time: 1 s is not after the previous pose's 2 s"},
    {WITH_SPARK("\"listener\":{\"path\":[{\"time\":0,\"position\":[0,0,0]},"
                "{\"time\":1,\"position\":[0,0,0],\"forward\":[0,-1,0]}]},"),
     "listener.path[1].forward: opposite to the previous pose's; add a pose in between"},
};

static void test_bad_scenes(void **state)
{
    (void)state;
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char expected[512], err[512] = "";
        snprintf(expected, sizeof expected, bad[i].message, gen_type_list());
        scene s;
        memset(&s, 0xab, sizeof s);
        int rc = parse(bad[i].json, &s, err, sizeof err);
        if (rc == 0 || strcmp(err, expected) != 0)
            print_message("case %zu: %s\n", i, bad[i].json);
        assert_int_equal(rc, -1);
        assert_string_equal(err, expected);
        /* nothing is left allocated or half-filled */
        assert_null(s.discharges);
        assert_null(s.poses);
        assert_null(s.json);
        assert_int_equal(s.discharge_count, 0);
    }
}

static void test_defaults(void **state)
{
    (void)state;
    scene s;
    char err[512];
    assert_int_equal(parse(WITH_SPARK(""), &s, err, sizeof err), 0);
    assert_true(s.sample_rate_hz == 48000);
    assert_int_equal(s.channels, 2);
    assert_int_equal(s.block_frames, 256);
    assert_true(s.duration_s == 0);
    assert_int_equal(s.seed, 1);
    assert_true(s.gain == 1);
    assert_true(s.speed_of_sound_m_s == 343);
    assert_int_equal(s.pose_count, 1);
    fg_listener pose;
    scene_listener_at(&s, 12.5, &pose);
    double expect_pos[3] = {0, 0, 1.7}, expect_fwd[3] = {0, 1, 0}, expect_up[3] = {0, 0, 1};
    assert_memory_equal(pose.position, expect_pos, sizeof expect_pos);
    assert_memory_equal(pose.forward, expect_fwd, sizeof expect_fwd);
    assert_memory_equal(pose.up, expect_up, sizeof expect_up);

    assert_int_equal(s.discharge_count, 1);
    const scene_discharge *d = &s.discharges[0];
    fg_sound_config preset;
    assert_int_equal(fg_preset_sound(FG_PRESET_SPARK_BALLS, &preset), FG_OK);
    assert_memory_equal(&d->post.sound, &preset, sizeof preset);
    assert_int_equal(d->preset, FG_PRESET_SPARK_BALLS);
    assert_int_equal(d->post.strokes, 0);
    assert_false(d->post.continuous);
    assert_int_equal(d->post.seed, scene_discharge_seed(1, 0));
    assert_null(d->generator);
    assert_int_equal(d->post.node_count, 2);
    const fg_node *end = &d->post.nodes[1];
    assert_true(end->z == 0.01 && end->parent == 0 && end->flags == 0);
    assert_int_equal(scene_build(&s, err, sizeof err), 0); /* no generator: nothing to do */
    assert_int_equal(s.discharges[0].post.node_count, 2);
    scene_deinit(&s);
    assert_null(s.discharges);
}

static void test_values(void **state)
{
    (void)state;
    const char *json =
        "{\"sample_rate\":44100,\"channels\":1,\"block\":64,\"duration\":2.5,\"seed\":77,"
        "\"gain\":0.5,\"temperature_c\":20,\"description\":\"values\",\"discharges\":["
        "{\"time\":0.25,\"preset\":\"lightning\",\"T0\":0.001,\"r0\":20,\"ps0\":100,"
        "\"sigma0\":0.3,\"t0_jitter\":0,\"return_stroke_speed\":2e8,\"strokes\":4,\"seed\":9,"
        "\"offset\":[10,20,30],\"tree\":{\"nodes\":[[0,0,0,-1,1],[1,2,3,0,1],[1,2,4,1]]}},"
        "{\"time\":0,\"preset\":\"plasma_ball\",\"continuous\":{}," TREE "},"
        "{\"time\":1,\"preset\":\"plasma_ball\",\"continuous\":{\"min_interval\":0.02,"
        "\"max_interval\":0.03,\"duration\":1.5}," TREE "}]}";
    scene s;
    char err[512];
    assert_int_equal(parse(json, &s, err, sizeof err), 0);
    assert_true(s.sample_rate_hz == 44100 && s.channels == 1 && s.block_frames == 64);
    assert_true(s.duration_s == 2.5 && s.seed == 77 && s.gain == 0.5);
    assert_true(fabs(s.speed_of_sound_m_s - 343.5) < 1e-12);
    const scene_discharge *d = s.discharges;
    assert_true(d[0].post.emit_time_s == 0.25 && d[0].preset == FG_PRESET_LIGHTNING);
    const fg_sound_config *sound = &d[0].post.sound;
    assert_true(sound->t0_s == 0.001 && sound->r0_m == 20 && sound->ps0_pa == 100);
    assert_true(sound->sigma0 == 0.3 && sound->t0_jitter == 0);
    assert_true(sound->return_stroke_speed_m_s == 2e8);
    assert_int_equal(d[0].post.strokes, 4);
    assert_int_equal(d[0].post.seed, 9);
    assert_int_equal(d[0].post.node_count, 3);
    const fg_node *nodes = d[0].post.nodes;
    assert_true(nodes[0].x == 10 && nodes[1].y == 22 && nodes[2].z == 34);
    assert_int_equal(nodes[1].flags, FG_NODE_MAIN);
    assert_int_equal(nodes[2].flags, 0);
    /* continuous: the default interval range; no duration: until the end */
    assert_true(d[1].post.continuous);
    assert_true(d[1].post.repeat_min_s == 0.01 && d[1].post.repeat_max_s == 0.05);
    assert_true(d[1].post.duration_s == 0);
    assert_true(d[2].post.repeat_min_s == 0.02 && d[2].post.repeat_max_s == 0.03);
    assert_true(d[2].post.duration_s == 1.5);
    assert_int_equal(d[1].post.seed, scene_discharge_seed(77, 1));
    assert_int_equal(d[2].post.seed, scene_discharge_seed(77, 2));
    scene_deinit(&s);
}

static void test_propagation(void **state)
{
    (void)state;
    scene s;
    char err[512];
    /* the scene's air and default effects, one discharge overriding two */
    const char *json =
        "{\"temperature_c\":10,\"humidity\":40,\"pressure\":95,"
        "\"propagation\":{\"refraction\":true,\"turbulence\":{\"amplitude\":0.001},"
        "\"absorption\":\"iso9613\",\"ground\":true,\"head_shadow\":true},"
        "\"discharges\":[" SPARK ",{\"time\":0,\"preset\":\"spark_balls\",\"model\":\"abe\","
        "\"propagation\":{\"refraction\":{\"radius\":80000},"
        "\"absorption\":{\"model\":\"abe_fir\",\"distance\":300},\"ground\":false}," TREE "}]}";
    assert_int_equal(parse(json, &s, err, sizeof err), 0);
    assert_true(s.temperature_c == 10 && s.humidity_pct == 40 && s.pressure_kpa == 95);
    assert_true(fabs(s.speed_of_sound_m_s - 337.5) < 1e-12);
    const fg_propagation_config *a = &s.discharges[0].post.propagation;
    const fg_propagation_config *b = &s.discharges[1].post.propagation;
    assert_true(a->refraction_radius_m == FG_REFRACTION_STORM_M);
    assert_true(a->turbulence_s == 0.001 && a->turbulence_length_m == FG_TURBULENCE_DEFAULT_LENGTH_M);
    assert_int_equal(a->absorption, FG_ABSORPTION_ISO9613);
    assert_true(a->ground_reflection == FG_GROUND_DEFAULT_REFLECTION);
    assert_int_equal(a->head_shadow, 1);
    assert_int_equal(s.discharges[0].post.model, FG_MODEL_WM);
    assert_true(b->refraction_radius_m == 80000);
    assert_true(b->turbulence_s == 0.001);
    assert_int_equal(b->absorption, FG_ABSORPTION_ABE_FIR);
    assert_true(b->abe_fir_distance_m == 300);
    assert_true(b->ground_reflection == 0);
    assert_int_equal(b->head_shadow, 1);
    assert_int_equal(s.discharges[1].post.model, FG_MODEL_ABE);
    fg_propagation_config used;
    assert_int_equal(fg_propagation_config_resolve(a, &used), FG_OK);
    assert_int_equal(fg_propagation_config_resolve(b, &used), FG_OK);
    scene_deinit(&s);
}

static void test_listener_path(void **state)
{
    (void)state;
    const char *json = WITH_SPARK(
        "\"listener\":{\"path\":["
        "{\"time\":1,\"position\":[0,0,0]},"
        "{\"time\":3,\"position\":[2,4,0],\"forward\":[2,0,0],\"up\":[0,0,5]},"
        "{\"time\":4,\"position\":[2,4,1],\"forward\":[1,0,0],\"up\":[0,1,1]}]},");
    scene s;
    char err[512];
    assert_int_equal(parse(json, &s, err, sizeof err), 0);
    assert_int_equal(s.pose_count, 3);
    static const struct {
        double t, pos[3], fwd[3], up[3], vel[3];
    } expect[] = {
        {0.0, {0, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, 0}},             /* held before */
        {1.0, {0, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, 0}},
        {2.0, {1, 2, 0}, {SQRT_HALF, SQRT_HALF, 0}, {0, 0, 1}, {1, 2, 0}}, /* halfway */
        {2.5, {1.5, 3, 0}, {0.94868329805051, 0.31622776601684, 0}, {0, 0, 1}, {1, 2, 0}},
        {3.5, {2, 4, 0.5}, {1, 0, 0}, {0, 0.38268343236509, 0.92387953251129}, {0, 0, 1}},
        {9.0, {2, 4, 1}, {1, 0, 0}, {0, SQRT_HALF, SQRT_HALF}, {0, 0, 0}}, /* held after */
    };
    for (size_t i = 0; i < sizeof expect / sizeof expect[0]; i++) {
        fg_listener p;
        scene_listener_at(&s, expect[i].t, &p);
        for (int k = 0; k < 3; k++) {
            assert_float_equal(p.position[k], expect[i].pos[k], 1e-12);
            assert_float_equal(p.forward[k], expect[i].fwd[k], 1e-12);
            assert_float_equal(p.up[k], expect[i].up[k], 1e-12);
            assert_float_equal(p.velocity[k], expect[i].vel[k], 1e-12);
        }
    }
    scene_deinit(&s);
}

static void test_derived_seeds(void **state)
{
    (void)state;
    /* a pure function of (scene seed, index) */
    assert_int_equal(scene_discharge_seed(1, 0), scene_discharge_seed(1, 0));
    uint64_t seen[16];
    for (size_t i = 0; i < 8; i++) {
        seen[i] = scene_discharge_seed(1, i);
        seen[8 + i] = scene_discharge_seed(2, i);
    }
    for (size_t i = 0; i < 16; i++)
        for (size_t k = 0; k < i; k++)
            assert_true(seen[i] != seen[k]);
    /* the parser uses it, the same way twice */
    const char *json = "{\"seed\":5,\"discharges\":[" SPARK "," SPARK "," SPARK "]}";
    scene a, b;
    char err[512];
    assert_int_equal(parse(json, &a, err, sizeof err), 0);
    assert_int_equal(parse(json, &b, err, sizeof err), 0);
    for (size_t i = 0; i < 3; i++) {
        assert_int_equal(a.discharges[i].post.seed, scene_discharge_seed(5, i));
        assert_int_equal(a.discharges[i].post.seed, b.discharges[i].post.seed);
    }
    scene_deinit(&a);
    scene_deinit(&b);
}

/* scene_load refuses what is no scene file before reading it: a FIFO (a
 * read would block), a directory, a device (the zero device once grew to
 * 5.9 GB), a file over the cap; a regular file within it loads. */
static void test_load_refuses(void **state)
{
    (void)state;
    char dir[] = "/tmp/fulgur-scene-XXXXXX", path[64], err[256];
    assert_non_null(mkdtemp(dir));
    scene s;
    snprintf(path, sizeof path, "%s/fifo.json", dir);
    assert_int_equal(mkfifo(path, 0600), 0);
    assert_int_equal(scene_load(path, &s, err, sizeof err), -1);
    assert_non_null(strstr(err, "not a regular file"));
    unlink(path);
    assert_int_equal(scene_load(dir, &s, err, sizeof err), -1);
    assert_non_null(strstr(err, "not a regular file"));
    assert_int_equal(scene_load("/dev/zero", &s, err, sizeof err), -1);
    assert_non_null(strstr(err, "not a regular file"));
    snprintf(path, sizeof path, "%s/big.json", dir);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(SPARK, f);
    fclose(f);
    assert_int_equal(truncate(path, (off_t)SCENE_MAX_FILE_BYTES + 1), 0); /* sparse */
    assert_int_equal(scene_load(path, &s, err, sizeof err), -1);
    assert_non_null(strstr(err, "more than a scene file may hold (256 MiB)"));
    f = fopen(path, "w");
    assert_non_null(f);
    fputs("{\"discharges\":[" SPARK "]}", f);
    fclose(f);
    assert_int_equal(scene_load(path, &s, err, sizeof err), 0);
    assert_int_equal(s.discharge_count, 1);
    scene_deinit(&s);
    unlink(path);
    rmdir(dir);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bad_scenes),
        cmocka_unit_test(test_defaults),
        cmocka_unit_test(test_values),
        cmocka_unit_test(test_propagation),
        cmocka_unit_test(test_listener_path),
        cmocka_unit_test(test_derived_seeds),
        cmocka_unit_test(test_load_refuses),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
