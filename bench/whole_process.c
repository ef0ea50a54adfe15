/* bench_whole: fulgur render as a user runs it, whole process, against a
 * peer when one is given (issue 17). For 2 000 and 20 000 segments: the
 * CPU time (user + system) of `fulgur render` of an explicit-tree scene,
 * stereo 44.1 kHz, and of the peer's program on the same bolt for the same
 * sound length, in paired runs (one of each per round), medians; then
 * synthesis only: fulgur's post + render in this process (no parse, no
 * I/O) and the peer's own figure for its synthesis. Ratios are fulgur /
 * peer: below 1, fulgur costs less.
 *
 * The peer is a program run as `PEER SEGMENTS OUT.wav [NODES.txt]` that
 * prints "seconds=S synthesis_cpu_s=C" (bench/peer/: the driver of
 * cosinekitty/thunder, built outside this tree). Its bolt (written to
 * NODES.txt: the chain's points, top first, then the listener) is what
 * fulgur renders, from the same place, for S seconds. Without a peer the
 * bolt is synth_tree's, heard 50 m from its foot.
 *
 * usage: bench_whole FULGUR [PEER] [RUNS]   writes whole_process.csv
 *        bench_whole --scene SEGMENTS OUT.json   writes the scene only */
#define _DEFAULT_SOURCE /* mkdtemp */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "bench_util.h"
#include "fulgur/fulgur.h"
#include "synth_tree.h"

#define RATE_HZ 44100
#define BLOCK_FRAMES 512         /* fulgur render's own block (SCENE_RENDER_BLOCK_FRAMES) */
#define CHUNK_FRAMES 1024        /* and chunk (SCENE_RENDER_CHUNK_FRAMES) */
#define SPEED_OF_SOUND_M_S 343.0 /* the peer's */

typedef struct bolt {
    fg_node *nodes;
    size_t count;   /* nodes: segments + 1 */
    double ear[3];  /* the listener: between the ears */
    double seconds; /* the sound's length */
} bolt;

static void fail(const char *what)
{
    fprintf(stderr, "bench_whole: %s\n", what);
    exit(1);
}

/* The peer's bolt of n segments, its sound length and the listener. */
static bolt peer_bolt(const char *peer, size_t n, const char *dir)
{
    char count[32], wav[512], nodes[512], out[512];
    snprintf(count, sizeof count, "%zu", n);
    snprintf(wav, sizeof wav, "%s/peer.wav", dir);
    snprintf(nodes, sizeof nodes, "%s/nodes.txt", dir);
    snprintf(out, sizeof out, "%s/peer.out", dir);
    bench_run_child((char *[]){(char *)peer, count, wav, nodes, NULL}, out);
    bolt b = {.nodes = malloc((n + 1) * sizeof *b.nodes), .count = n + 1};
    FILE *f = fopen(nodes, "r"), *o = fopen(out, "r");
    double synth;
    if (!b.nodes || !f || !o || fscanf(o, "seconds=%lf synthesis_cpu_s=%lf", &b.seconds, &synth) != 2)
        fail("the peer's output is not \"seconds=S synthesis_cpu_s=C\"");
    for (size_t i = 0; i < b.count; i++) {
        double *p = &b.nodes[i].x;
        if (fscanf(f, "%lf %lf %lf", &p[0], &p[1], &p[2]) != 3)
            fail("the peer's NODES.txt holds fewer points than segments + 1");
        b.nodes[i].parent = (int32_t)i - 1;
        b.nodes[i].flags = FG_NODE_MAIN;
    }
    if (fscanf(f, "%lf %lf %lf", &b.ear[0], &b.ear[1], &b.ear[2]) != 3)
        fail("the peer's NODES.txt has no listener line");
    fclose(f);
    fclose(o);
    return b;
}

/* synth_tree's bolt of n segments heard 50 m from its lowest node, for the
 * time between the nearest and the farthest node's arrival. */
static bolt own_bolt(size_t n)
{
    bolt b = {.nodes = malloc((n + 1) * sizeof *b.nodes), .count = n + 1};
    if (!b.nodes)
        fail("out of memory");
    synth_tree(b.nodes, n, 3000.0, 3.0, 17);
    size_t low = 0;
    for (size_t i = 1; i < b.count; i++)
        if (b.nodes[i].z < b.nodes[low].z)
            low = i;
    b.ear[0] = b.nodes[low].x + 50, b.ear[1] = b.nodes[low].y, b.ear[2] = 1.7;
    double near = INFINITY, far = 0;
    for (size_t i = 0; i < b.count; i++) {
        double d = hypot(hypot(b.nodes[i].x - b.ear[0], b.nodes[i].y - b.ear[1]),
                         b.nodes[i].z - b.ear[2]);
        near = fmin(near, d), far = fmax(far, d);
    }
    b.seconds = (far - near) / SPEED_OF_SOUND_M_S;
    return b;
}

/* The scene fulgur renders: the bolt from the listener, facing -x (its
 * right ear at +y, as the peer's second), for the bolt's sound length. */
static void write_scene(const bolt *b, const char *path)
{
    FILE *f = fopen(path, "w");
    if (!f)
        fail("cannot write the scene");
    fprintf(f, "{\"sample_rate\": %d, \"channels\": 2, \"seed\": 1, \"duration\": %.9g,\n"
               " \"listener\": {\"position\": [%.17g, %.17g, %.17g], \"forward\": [-1, 0, 0], "
               "\"up\": [0, 0, 1]},\n"
               " \"discharges\": [{\"time\": 0, \"preset\": \"lightning\", \"strokes\": 1,\n"
               "  \"tree\": {\"nodes\": [\n",
            RATE_HZ, b->seconds, b->ear[0], b->ear[1], b->ear[2]);
    for (size_t i = 0; i < b->count; i++)
        fprintf(f, "   [%.17g, %.17g, %.17g, %d, %d]%s\n", b->nodes[i].x, b->nodes[i].y,
                b->nodes[i].z, (int)b->nodes[i].parent, (b->nodes[i].flags & FG_NODE_MAIN) != 0,
                i + 1 < b->count ? "," : "");
    fprintf(f, "]}}]}\n");
    if (fclose(f) != 0)
        fail("cannot write the scene");
}

static void check(fg_result r, const char *what)
{
    if (r != FG_OK) {
        fprintf(stderr, "bench_whole: %s: %s\n", what, fg_result_str(r));
        exit(1);
    }
}

/* fulgur's synthesis of the bolt: post + render of its frames, as the
 * scene's render does them (block 512, chunk 1024, stereo, 44.1 kHz), CPU
 * seconds. */
static double fulgur_synthesis_s(const bolt *b)
{
    fg_engine_config cfg = {.sample_rate_hz = RATE_HZ,
                            .channels = 2,
                            .max_block_frames = BLOCK_FRAMES,
                            .chunk_frames = CHUNK_FRAMES,
                            .segment_capacity = (uint32_t)b->count,
                            .max_voices = 1};
    fg_engine *e;
    check(fg_engine_create(&cfg, &e), "create");
    fg_listener pose = {.position = {b->ear[0], b->ear[1], b->ear[2]}, .forward = {-1, 0, 0},
                        .up = {0, 0, 1}};
    check(fg_engine_set_listener(e, &pose), "listener");
    fg_discharge d = {.nodes = b->nodes, .node_count = b->count, .strokes = 1, .seed = 1};
    check(fg_preset_sound(FG_PRESET_LIGHTNING, &d.sound), "preset");
    float *planes[2] = {malloc(BLOCK_FRAMES * sizeof(float)), malloc(BLOCK_FRAMES * sizeof(float))};
    if (!planes[0] || !planes[1])
        fail("out of memory");
    uint64_t frames = (uint64_t)llround(b->seconds * RATE_HZ);
    double t0 = bench_cpu_s();
    check(fg_engine_post(e, &d, NULL), "post");
    for (uint64_t done = 0; done < frames; done += BLOCK_FRAMES) {
        uint32_t n = frames - done < BLOCK_FRAMES ? (uint32_t)(frames - done) : BLOCK_FRAMES;
        check(fg_engine_render(e, planes, n), "render");
        fg_engine_collect(e);
    }
    double cpu = bench_cpu_s() - t0;
    free(planes[0]);
    free(planes[1]);
    fg_engine_destroy(e);
    return cpu;
}

int main(int argc, char **argv)
{
    if (argc == 4 && strcmp(argv[1], "--scene") == 0) {
        long n = atol(argv[2]);
        if (n < 1 || n > 10000000)
            fail("SEGMENTS must be 1..10000000");
        bolt b = own_bolt((size_t)n);
        write_scene(&b, argv[3]);
        free(b.nodes);
        return 0;
    }
    if (argc < 2 || argc > 4) {
        fprintf(stderr, "usage: bench_whole FULGUR [PEER] [RUNS]\n"
                        "       bench_whole --scene SEGMENTS OUT.json\n");
        return 2;
    }
    const char *fulgur = argv[1], *peer = argc > 2 && argv[2][0] ? argv[2] : NULL;
    int runs = argc > 3 ? atoi(argv[3]) : 21;
    if (runs < 1 || runs > 1000)
        fail("RUNS must be 1..1000");
    char dir[] = "/tmp/bench_whole_XXXXXX";
    if (!mkdtemp(dir))
        fail("cannot make a temporary directory");
    char scene[512], wav[512], peer_wav[512], peer_out[512];
    snprintf(scene, sizeof scene, "%s/scene.json", dir);
    snprintf(wav, sizeof wav, "%s/fulgur.wav", dir);
    snprintf(peer_wav, sizeof peer_wav, "%s/peer.wav", dir);
    snprintf(peer_out, sizeof peer_out, "%s/peer.out", dir);
    FILE *csv = bench_open_result("whole_process.csv");
    char machine[256];
    bench_machine(machine, sizeof machine);
    double load = -1;
    getloadavg(&load, 1);
    fprintf(csv, "# %s; load average %.1f; %d paired runs; CPU ms (user + system), medians; "
                 "peer: %s\nsegments,sound_s,fulgur_whole_ms,peer_whole_ms,whole_ratio,"
                 "fulgur_synthesis_ms,peer_synthesis_ms,synthesis_ratio\n",
            machine, load, runs, peer ? peer : "none");
    static const size_t counts[] = {2000, 20000};
    double *fw = malloc(runs * sizeof *fw), *pw = malloc(runs * sizeof *pw);
    double *fs = malloc(runs * sizeof *fs), *ps = malloc(runs * sizeof *ps);
    if (!fw || !pw || !fs || !ps)
        fail("out of memory");
    for (size_t c = 0; c < sizeof counts / sizeof counts[0]; c++) {
        size_t n = counts[c];
        bolt b = peer ? peer_bolt(peer, n, dir) : own_bolt(n);
        write_scene(&b, scene);
        char count[32];
        snprintf(count, sizeof count, "%zu", n);
        for (int r = 0; r < runs; r++) {
            fw[r] = bench_run_child((char *[]){(char *)fulgur, "render", scene, "-o", wav, NULL},
                                    NULL).cpu_s;
            fs[r] = fulgur_synthesis_s(&b);
            if (!peer)
                continue;
            pw[r] = bench_run_child((char *[]){(char *)peer, count, peer_wav, NULL}, peer_out).cpu_s;
            FILE *o = fopen(peer_out, "r");
            if (!o || fscanf(o, "seconds=%*f synthesis_cpu_s=%lf", &ps[r]) != 1)
                fail("the peer's output is not \"seconds=S synthesis_cpu_s=C\"");
            fclose(o);
        }
        double fwm = bench_median(fw, runs) * 1e3, fsm = bench_median(fs, runs) * 1e3;
        if (peer) {
            double pwm = bench_median(pw, runs) * 1e3, psm = bench_median(ps, runs) * 1e3;
            fprintf(csv, "%zu,%.3f,%.2f,%.2f,%.2f,%.2f,%.2f,%.2f\n", n, b.seconds, fwm, pwm,
                    fwm / pwm, fsm, psm, fsm / psm);
            printf("%6zu segments, %.2f s: whole process fulgur %.2f ms, peer %.2f ms (x%.2f); "
                   "synthesis %.2f ms, %.2f ms (x%.2f)\n",
                   n, b.seconds, fwm, pwm, fwm / pwm, fsm, psm, fsm / psm);
        } else {
            fprintf(csv, "%zu,%.3f,%.2f,,,%.2f,,\n", n, b.seconds, fwm, fsm);
            printf("%6zu segments, %.2f s: whole process %.2f ms; synthesis %.2f ms\n", n,
                   b.seconds, fwm, fsm);
        }
        free(b.nodes);
    }
    fclose(csv);
    unlink(scene), unlink(wav), unlink(peer_wav), unlink(peer_out);
    char nodes[512];
    snprintf(nodes, sizeof nodes, "%s/nodes.txt", dir);
    unlink(nodes);
    rmdir(dir);
    free(fw), free(pw), free(fs), free(ps);
    return 0;
}
