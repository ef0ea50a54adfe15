/* "random": discharges at seeded random times and places, expanded into
 * ordinary discharges after the listed ones when the scene is parsed.
 *
 * Why at parse time: the list is then fixed by the seed, so render and run
 * post exactly the same discharges, the run's sim thread builds each one's
 * tree lazily as it does for listed discharges (scene_build_discharge), and
 * the count can be checked before anything runs. Times are a Poisson
 * process of rate rate_hz over [start, end); places are uniform in the
 * region box, added to the template's offset. */
#define _DEFAULT_SOURCE /* fg_big_alloc.h */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fg_big_alloc.h"
#include "scene_internal.h"
#include "fg_rng.h"
#include "fg_array.h"

#define RANDOM_MAX_DISCHARGES 100000

/* The keys of "random" that are not a discharge's. */
static const char *const own_keys[] = {"rate_hz", "region", "start", "end", "seed", NULL};

static int parse_region(const cJSON *item, double lo[3], double hi[3], char *err,
                        size_t err_size)
{
    static const char *const keys[] = {"min", "max", NULL};
    if (!item)
        return 0;
    if (!cJSON_IsObject(item))
        return json_fail(err, err_size, "random.region", "expected {\"min\": [x, y, z], \"max\": [x, y, z]}");
    if (json_check_keys(item, "random.region", keys, err, err_size) ||
        json_vec3(item, "random.region", "min", lo, err, err_size) ||
        json_vec3(item, "random.region", "max", hi, err, err_size))
        return -1;
    for (int k = 0; k < 3; k++) {
        /* a shift beyond the engine's coordinates cannot hold a tree, and
         * max - min stays finite */
        if (fabs(lo[k]) > FG_TREE_MAX_COORDINATE_M || fabs(hi[k]) > FG_TREE_MAX_COORDINATE_M)
            return json_fail(err, err_size, fabs(lo[k]) > FG_TREE_MAX_COORDINATE_M
                                                ? "random.region.min"
                                                : "random.region.max",
                             "coordinate %d (%.16g) is beyond +-%g m", k,
                             fabs(lo[k]) > FG_TREE_MAX_COORDINATE_M ? lo[k] : hi[k],
                             FG_TREE_MAX_COORDINATE_M);
        if (lo[k] > hi[k])
            return json_fail(err, err_size, "random.region.min",
                             "above max in coordinate %d (%.16g > %.16g)", k, lo[k], hi[k]);
    }
    return 0;
}

/* The template: the discharge keys of "random" with "time" 0, parsed as a
 * discharge at path "random". The copy is kept in the scene's document
 * (freed with it) because the template's generator points into it. */
static int parse_template(cJSON *json, const cJSON *item, scene *s, scene_discharge *out,
                          char *err, size_t err_size)
{
    cJSON *copy = cJSON_Duplicate(item, 1);
    if (!copy)
        return json_fail(err, err_size, "random", "out of memory");
    for (const char *const *k = own_keys; *k; k++)
        cJSON_DeleteItemFromObjectCaseSensitive(copy, *k);
    if (cJSON_GetObjectItemCaseSensitive(copy, "time")) {
        cJSON_Delete(copy);
        return json_fail(err, err_size, "random.time", "not allowed: times are drawn at rate_hz");
    }
    if (!cJSON_AddNumberToObject(copy, "time", 0) ||
        !cJSON_AddItemToObject(json, "random (template)", copy)) {
        cJSON_Delete(copy);
        return json_fail(err, err_size, "random", "out of memory");
    }
    return scene_parse_discharge(copy, "random", 0, s, out, err, err_size);
}

/* One instance of the template at time t, moved by shift; its tree is
 * checked again where the shift put it (a generator's is checked when it
 * is built). Returns -1 with the message in err. */
static int instantiate(const scene_discharge *tpl, double t, const double shift[3], uint64_t seed,
                       scene_discharge *out, char *err, size_t err_size)
{
    *out = *tpl;
    out->post.emit_time_s = t;
    out->post.seed = seed;
    for (int k = 0; k < 3; k++)
        out->offset_m[k] += shift[k];
    out->post.nodes = NULL;
    out->post.node_count = 0;
    if (!tpl->post.nodes)
        return 0; /* a generator: scene_build applies the offset */
    size_t n = tpl->post.node_count;
    fg_node *nodes = fg_big_calloc(n, sizeof *nodes);
    if (!nodes)
        return json_fail(err, err_size, "random", "out of memory");
    memcpy(nodes, tpl->post.nodes, n * sizeof *nodes);
    fg_tree_translate(nodes, n, shift);
    char why[JSON_PATH_MAX + 128];
    if (scene_check_tree(nodes, n, "random.tree.nodes", why, sizeof why)) {
        fg_big_free(nodes);
        return json_fail(err, err_size, "random.region",
                         "a discharge shifted by [%.16g, %.16g, %.16g] is refused: %s", shift[0],
                         shift[1], shift[2], why);
    }
    out->post.nodes = nodes;
    out->post.node_count = n;
    return 0;
}

int scene_parse_random(cJSON *json, scene *s, char *err, size_t err_size)
{
    const cJSON *item = cJSON_GetObjectItemCaseSensitive(json, "random");
    if (!item)
        return 0;
    if (!cJSON_IsObject(item))
        return json_fail(err, err_size, "random", "expected an object");
    double rate = 0, start = 0, end = s->duration_s, seed = -1;
    double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    if (json_number(item, "random", "rate_hz", (number_range){0, 1000, .lo_open = true}, &rate, err,
                    err_size) ||
        json_number(item, "random", "start", (number_range){.lo = 0, .hi = SCENE_MAX_DURATION_S},
                    &start, err, err_size) ||
        json_number(item, "random", "end", (number_range){0, SCENE_MAX_DURATION_S, .lo_open = true},
                    &end, err, err_size) ||
        json_number(item, "random", "seed", SCENE_SEED_RANGE, &seed, err, err_size) ||
        parse_region(cJSON_GetObjectItemCaseSensitive(item, "region"), lo, hi, err, err_size))
        return -1;
    if (rate == 0)
        return json_fail(err, err_size, "random.rate_hz", "required (discharges per second)");
    if (end == 0)
        return json_fail(err, err_size, "random.end",
                         "required when the scene has no duration (when random discharges stop)");
    if (s->duration_s > 0 && end > s->duration_s)
        return json_fail(err, err_size, "random.end", "%.16g s is after the scene's end (%.16g s)",
                         end, s->duration_s);
    if (start >= end)
        return json_fail(err, err_size, "random.start", "%.16g s is not before end (%.16g s)",
                         start, end);
    if (rate * (end - start) > RANDOM_MAX_DISCHARGES / 2)
        return json_fail(err, err_size, "random.rate_hz",
                         "%.16g Hz over %.16g s is more than %d discharges on average", rate,
                         end - start, RANDOM_MAX_DISCHARGES / 2);
    scene_discharge tpl = {0};
    if (parse_template(json, item, s, &tpl, err, err_size))
        return -1;
    if (tpl.post.continuous && tpl.post.duration_s == 0) {
        scene_discharge_free_tree(&tpl);
        return json_fail(err, err_size, "random.continuous.duration",
                         "required: a random continuous discharge must end");
    }
    /* the process's own seed: the scene's index space cannot collide with it */
    uint64_t own = seed >= 0 ? (uint64_t)seed : scene_discharge_seed(s->seed, SIZE_MAX);
    uint64_t r = own;
    size_t base = s->discharge_count, n = 0, capacity = base;
    int rc = 0;
    for (double t = start - log1p(-fg_splitmix64_uniform(&r)) / rate; t < end && rc == 0;
         t -= log1p(-fg_splitmix64_uniform(&r)) / rate) {
        if (n == RANDOM_MAX_DISCHARGES) {
            rc = json_fail(err, err_size, "random.rate_hz", "more than %d discharges",
                           RANDOM_MAX_DISCHARGES);
            break;
        }
        scene_discharge *grown =
            fg_array_grow(s->discharges, &capacity, base + n + 1, sizeof *grown, 16);
        if (!grown) {
            rc = json_fail(err, err_size, "random", "out of memory");
            break;
        }
        s->discharges = grown;
        double shift[3];
        for (int k = 0; k < 3; k++)
            shift[k] = lo[k] + (hi[k] - lo[k]) * fg_splitmix64_uniform(&r);
        rc = instantiate(&tpl, t, shift, scene_discharge_seed(own, n), &s->discharges[base + n],
                         err, err_size);
        if (rc != 0)
            break;
        s->discharge_count = base + ++n;
    }
    scene_discharge_free_tree(&tpl);
    return rc;
}
