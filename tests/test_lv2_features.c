/* fulgur.lv2's instantiate and extension_data as hosts really call them:
 * the module opened with dlopen and its descriptor called directly (liblilv
 * cleans up what it passes; other hosts do not). A feature whose URI is NULL
 * (lv2file passes one) is skipped, a NULL feature list or one without
 * urid:map or worker:schedule is refused with NULL, and a NULL extension
 * URI gives NULL: none of them crashes. usage: test_lv2_features MODULE */
#include <dlfcn.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>
#include <lv2/core/lv2.h>
#include <lv2/urid/urid.h>
#include <lv2/worker/worker.h>

static const char *module_path;

static LV2_URID map_uri(LV2_URID_Map_Handle handle, const char *uri)
{
    (void)handle;
    return (LV2_URID)(strlen(uri) + 1); /* any non-zero id will do here */
}

static LV2_Worker_Status schedule_work(LV2_Worker_Schedule_Handle handle, uint32_t size,
                                       const void *data)
{
    (void)handle, (void)size, (void)data;
    return LV2_WORKER_SUCCESS;
}

static const LV2_Descriptor *descriptor(void **lib)
{
    *lib = dlopen(module_path, RTLD_NOW | RTLD_LOCAL);
    assert_non_null(*lib);
    const LV2_Descriptor *(*entry)(uint32_t);
    *(void **)&entry = dlsym(*lib, "lv2_descriptor");
    assert_non_null(entry);
    const LV2_Descriptor *d = entry(0);
    assert_non_null(d);
    assert_string_equal(d->URI, FULGUR_LV2_URI);
    /* one plugin per output layout, then none */
    static const char *const others[] = {FULGUR_LV2_URI "-binaural", FULGUR_LV2_URI "-ambisonics1",
                                         FULGUR_LV2_URI "-ambisonics2",
                                         FULGUR_LV2_URI "-ambisonics3"};
    for (uint32_t i = 0; i < 4; i++) {
        assert_non_null(entry(i + 1));
        assert_string_equal(entry(i + 1)->URI, others[i]);
    }
    assert_null(entry(5));
    return d;
}

static void test_null_uri_skipped(void **state)
{
    (void)state;
    void *lib;
    const LV2_Descriptor *d = descriptor(&lib);
    LV2_URID_Map map = {NULL, map_uri};
    LV2_Worker_Schedule schedule = {NULL, schedule_work};
    LV2_Feature nameless = {NULL, NULL}, map_f = {LV2_URID__map, &map},
                schedule_f = {LV2_WORKER__schedule, &schedule};
    const LV2_Feature *features[] = {&nameless, &map_f, &nameless, &schedule_f, NULL};
    LV2_Handle h = d->instantiate(d, 48000, "/nonexistent", features);
    assert_non_null(h);
    assert_null(d->extension_data(NULL));
    assert_non_null(d->extension_data(LV2_WORKER__interface));
    d->cleanup(h);
    dlclose(lib);
}

static void test_refused_without_required(void **state)
{
    (void)state;
    void *lib;
    const LV2_Descriptor *d = descriptor(&lib);
    LV2_URID_Map map = {NULL, map_uri};
    LV2_Feature nameless = {NULL, NULL}, map_f = {LV2_URID__map, &map};
    const LV2_Feature *only_nameless[] = {&nameless, NULL};
    const LV2_Feature *no_schedule[] = {&map_f, &nameless, NULL};
    const LV2_Feature *none[] = {NULL};
    assert_null(d->instantiate(d, 48000, "/nonexistent", NULL));
    assert_null(d->instantiate(d, 48000, "/nonexistent", none));
    assert_null(d->instantiate(d, 48000, "/nonexistent", only_nameless));
    assert_null(d->instantiate(d, 48000, "/nonexistent", no_schedule));
    dlclose(lib);
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: test_lv2_features MODULE\n");
        return 2;
    }
    module_path = argv[1];
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_null_uri_skipped),
        cmocka_unit_test(test_refused_without_required),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
