/* GL contexts on Mesa's llvmpipe: each backend gives GL 4.3 core and runs
 * a compute shader with exact results, EGL still works after OSMesa had
 * epoxy's dispatch, and every refusal says why.
 *
 * One executable, groups chosen by the first argument (CTest runs each):
 *   (none)  names, arguments, EGL, OSMesa, switching, shader errors, the
 *           window backend with no display;
 *   old-gl  run with MESA_GL_VERSION_OVERRIDE=3.3: 4.3 core is refused;
 *   window  run under xvfb-run: a GLFW window, switching to EGL and OSMesa. */
#define _POSIX_C_SOURCE 200809L /* unsetenv */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <threads.h>

#include <cmocka.h>

#include "context/gpu_internal.h"

#define SQUARES 1000 /* not a multiple of the work group size */

static const char square_source[] =
    "#version 430\n"
    "layout(local_size_x = 64) in;\n"
    "layout(std430, binding = 0) buffer Out { uint v[]; };\n"
    "void main() {\n"
    "    uint i = gl_GlobalInvocationID.x;\n"
    "    if (i < uint(v.length())) v[i] = i * i;\n"
    "}\n";

/* In the current context: writes i*i into an SSBO on the GPU, reads it back
 * and checks every value. */
static void assert_computes_squares(void)
{
    GLuint program = 0;
    assert_int_equal(fgg_program_compute("square", square_source, &program), FG_OK);
    static GLuint values[SQUARES];
    memset(values, 0xff, sizeof values);
    GLuint buffer;
    glGenBuffers(1, &buffer);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer);
    glBufferData(GL_SHADER_STORAGE_BUFFER, sizeof values, values, GL_DYNAMIC_READ);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffer);
    glUseProgram(program);
    glDispatchCompute((SQUARES + 63) / 64, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    memset(values, 0, sizeof values);
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof values, values);
    glDeleteBuffers(1, &buffer);
    glDeleteProgram(program);
    assert_int_equal(fgg_gl_check("squares"), FG_OK);
    for (GLuint i = 0; i < SQUARES; i++)
        assert_int_equal(values[i], i * i);
}

/* The current context is 4.3 core or newer, by the info and by GL itself. */
static void assert_core_43(const fgg_context *ctx, fgg_backend backend, const char *platform)
{
    fgg_context_info info;
    fgg_context_get_info(ctx, &info);
    assert_int_equal(info.backend, backend);
    assert_string_equal(info.platform, platform);
    assert_true(info.gl_major * 10 + info.gl_minor >= FGG_GL_MAJOR * 10 + FGG_GL_MINOR);
    assert_non_null(strstr(info.version, "Core Profile"));
    GLint major = 0, minor = 0, profile = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    assert_int_equal(major, info.gl_major);
    assert_int_equal(minor, info.gl_minor);
    assert_true(profile & GL_CONTEXT_CORE_PROFILE_BIT);
}

/* llvmpipe is listed as an EGL device too, but as a software one, which
 * the EGL backend passes over for the surfaceless platform. */
static const char *egl_platform(const fgg_context *ctx)
{
    fgg_context_info info;
    fgg_context_get_info(ctx, &info);
    return strstr(info.renderer, "llvmpipe") ? "EGL surfaceless" : "EGL device";
}

static fgg_context *create(fgg_backend backend)
{
    fgg_context *ctx = NULL;
    fg_result r = fgg_context_create(&(fgg_context_config){.backend = backend}, &ctx);
    if (r != FG_OK)
        fail_msg("%s: %s", fgg_backend_name(backend), fgg_error_message());
    return ctx;
}

static void test_backend_names(void **state)
{
    (void)state;
    for (int b = FGG_BACKEND_EGL; b <= FGG_BACKEND_WINDOW; b++) {
        fgg_backend parsed = (fgg_backend)-1;
        assert_int_equal(fgg_backend_from_name(fgg_backend_name((fgg_backend)b), &parsed), FG_OK);
        assert_int_equal(parsed, b);
    }
    assert_string_equal(fgg_backend_name(FGG_BACKEND_OSMESA), "osmesa");
    assert_string_equal(fgg_backend_name((fgg_backend)7), "unknown");

    fgg_backend out = FGG_BACKEND_WINDOW;
    assert_int_equal(fgg_backend_from_name("bogus", &out), FG_ERR_ARGUMENT);
    assert_int_equal(out, FGG_BACKEND_WINDOW);
    const char *m = fgg_error_message();
    assert_non_null(strstr(m, "\"bogus\""));
    assert_non_null(strstr(m, "egl"));
    assert_non_null(strstr(m, "osmesa"));
    assert_non_null(strstr(m, "window"));
    assert_int_equal(fgg_backend_from_name("EGL", &out), FG_ERR_ARGUMENT);
    assert_int_equal(fgg_backend_from_name("", &out), FG_ERR_ARGUMENT);
    assert_int_equal(fgg_backend_from_name(NULL, &out), FG_ERR_NULL);
    assert_int_equal(fgg_backend_from_name("egl", NULL), FG_ERR_NULL);
    assert_int_equal(out, FGG_BACKEND_WINDOW);
}

static void test_backends_built(void **state)
{
    (void)state;
    assert_true(fgg_backend_built(FGG_BACKEND_EGL));
#ifdef FGG_HAVE_OSMESA
    assert_true(fgg_backend_built(FGG_BACKEND_OSMESA));
#else
    assert_false(fgg_backend_built(FGG_BACKEND_OSMESA));
#endif
#ifdef FGG_HAVE_WINDOW
    assert_true(fgg_backend_built(FGG_BACKEND_WINDOW));
#else
    assert_false(fgg_backend_built(FGG_BACKEND_WINDOW));
#endif
    assert_false(fgg_backend_built((fgg_backend)3));
    assert_false(fgg_backend_built((fgg_backend)-1));
}

static void test_bad_arguments(void **state)
{
    (void)state;
    fgg_context *sentinel = (fgg_context *)&sentinel, *ctx = sentinel;
    static const struct {
        fgg_context_config config;
        fg_result expected;
    } cases[] = {
        {{.backend = (fgg_backend)3}, FG_ERR_ARGUMENT},
        {{.backend = (fgg_backend)-1}, FG_ERR_ARGUMENT},
        {{.backend = FGG_BACKEND_EGL, .width = -1}, FG_ERR_ARGUMENT},
        {{.backend = FGG_BACKEND_OSMESA, .height = -720}, FG_ERR_ARGUMENT},
        {{.backend = FGG_BACKEND_WINDOW, .width = 640, .height = -1}, FG_ERR_ARGUMENT},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        assert_int_equal(fgg_context_create(&cases[i].config, &ctx), cases[i].expected);
        assert_ptr_equal(ctx, sentinel);
        assert_true(fgg_error_message()[0] != '\0');
    }
    assert_int_equal(fgg_context_create(NULL, NULL), FG_ERR_NULL);
    assert_int_equal(fgg_context_make_current(NULL), FG_ERR_NULL);
    fgg_context_destroy(NULL);
}

static void test_egl(void **state)
{
    (void)state;
    fgg_context *ctx = NULL;
    assert_int_equal(fgg_context_create(NULL, &ctx), FG_OK);
    assert_core_43(ctx, FGG_BACKEND_EGL, egl_platform(ctx));
    int w = -1, h = -1;
    fgg_context_framebuffer_size(ctx, &w, &h);
    assert_int_equal(w, 0);
    assert_int_equal(h, 0);
    assert_null(fgg_context_native_window(ctx));
    fgg_context_present(ctx);
    assert_computes_squares();
    fgg_context_destroy(ctx);
}

/* Two EGL contexts share one display: destroying one leaves the other
 * working (the display is terminated with the last context). */
static void test_two_egl(void **state)
{
    (void)state;
    fgg_context *a = create(FGG_BACKEND_EGL);
    fgg_context *b = create(FGG_BACKEND_EGL);
    assert_computes_squares();
    fgg_context_destroy(b);
    assert_int_equal(fgg_context_make_current(a), FG_OK);
    assert_computes_squares();
    fgg_context_destroy(a);
    fgg_context *c = create(FGG_BACKEND_EGL);
    assert_computes_squares();
    fgg_context_destroy(c);
}

static void test_osmesa(void **state)
{
    (void)state;
    fgg_context *ctx = NULL;
    fgg_context_config config = {.backend = FGG_BACKEND_OSMESA, .width = 64, .height = 32};
    if (!fgg_backend_built(FGG_BACKEND_OSMESA)) {
        assert_int_equal(fgg_context_create(&config, &ctx), FG_ERR_UNSUPPORTED);
        assert_null(ctx);
        assert_non_null(strstr(fgg_error_message(), "install libosmesa6-dev"));
        return;
    }
    assert_int_equal(fgg_context_create(&config, &ctx), FG_OK);
    assert_core_43(ctx, FGG_BACKEND_OSMESA, "OSMesa");
    int w = -1, h = -1;
    fgg_context_framebuffer_size(ctx, &w, &h);
    assert_int_equal(w, 64);
    assert_int_equal(h, 32);
    assert_null(fgg_context_native_window(ctx));
    assert_computes_squares();
    assert_int_equal(fgg_context_make_current(ctx), FG_OK);
    assert_computes_squares();
    fgg_context_destroy(ctx);
}

/* OSMesa holds epoxy's dispatch while current; EGL must get it back. */
static void test_egl_after_osmesa(void **state)
{
    (void)state;
    if (!fgg_backend_built(FGG_BACKEND_OSMESA))
        skip();
    fgg_context *osmesa = create(FGG_BACKEND_OSMESA);
    assert_computes_squares();
    fgg_context_destroy(osmesa);
    fgg_context *egl = create(FGG_BACKEND_EGL);
    assert_core_43(egl, FGG_BACKEND_EGL, egl_platform(egl));
    assert_computes_squares();

    /* both alive, back and forth */
    osmesa = create(FGG_BACKEND_OSMESA);
    assert_computes_squares();
    assert_int_equal(fgg_context_make_current(egl), FG_OK);
    assert_computes_squares();
    assert_int_equal(fgg_context_make_current(osmesa), FG_OK);
    assert_computes_squares();
    /* destroying the current OSMesa context, then the EGL one again */
    fgg_context_destroy(osmesa);
    assert_int_equal(fgg_context_make_current(egl), FG_OK);
    assert_computes_squares();
    /* an OSMesa context destroyed while EGL is current */
    osmesa = create(FGG_BACKEND_OSMESA);
    assert_int_equal(fgg_context_make_current(egl), FG_OK);
    fgg_context_destroy(osmesa);
    assert_computes_squares();
    fgg_context_destroy(egl);
}

static int create_osmesa_elsewhere(void *message)
{
    fgg_context *ctx = NULL;
    fg_result r = fgg_context_create(&(fgg_context_config){.backend = FGG_BACKEND_OSMESA}, &ctx);
    strncpy(message, fgg_error_message(), 255);
    fgg_context_destroy(ctx);
    return r;
}

/* epoxy's pointers are the process's: one thread at a time has OSMesa. */
static void test_osmesa_one_thread(void **state)
{
    (void)state;
    if (!fgg_backend_built(FGG_BACKEND_OSMESA))
        skip();
    fgg_context *ctx = create(FGG_BACKEND_OSMESA);
    char message[256] = "";
    thrd_t other;
    int r = 0;
    assert_int_equal(thrd_create(&other, create_osmesa_elsewhere, message), thrd_success);
    assert_int_equal(thrd_join(other, &r), thrd_success);
    assert_int_equal(r, FG_ERR_UNSUPPORTED);
    assert_non_null(strstr(message, "current on another thread"));
    assert_computes_squares();
    fgg_context_destroy(ctx);
    /* once released here, the other thread may */
    assert_int_equal(thrd_create(&other, create_osmesa_elsewhere, message), thrd_success);
    assert_int_equal(thrd_join(other, &r), thrd_success);
    assert_int_equal(r, FG_OK);
}

/* The driver's log, naming the line, is in the message. */
static void test_shader_error(void **state)
{
    (void)state;
    static const char broken[] = "#version 430\n"
                                 "layout(local_size_x = 1) in;\n"
                                 "void main() { int x = ; }\n";
    for (int b = FGG_BACKEND_EGL; b <= FGG_BACKEND_OSMESA; b++) {
        if (!fgg_backend_built((fgg_backend)b))
            continue;
        fgg_context *ctx = create((fgg_backend)b);
        GLuint program = 12345;
        assert_int_equal(fgg_program_compute("broken", broken, &program), FG_ERR_GPU);
        assert_int_equal(program, 12345);
        const char *m = fgg_error_message();
        assert_non_null(strstr(m, "shader broken did not compile"));
        assert_non_null(strstr(m, "0:3(")); /* Mesa's "source:line(column)" */
        assert_non_null(strstr(m, "syntax error"));
        assert_int_equal(fgg_gl_check("after a failed compile"), FG_OK);
        fgg_context_destroy(ctx);
    }
}

static void test_window_without_display(void **state)
{
    (void)state;
    if (!fgg_backend_built(FGG_BACKEND_WINDOW))
        skip();
    unsetenv("DISPLAY");
    unsetenv("WAYLAND_DISPLAY");
    fgg_context *sentinel = (fgg_context *)&sentinel, *ctx = sentinel;
    fgg_context_config config = {.backend = FGG_BACKEND_WINDOW};
    assert_int_equal(fgg_context_create(&config, &ctx), FG_ERR_UNSUPPORTED);
    assert_ptr_equal(ctx, sentinel);
    assert_non_null(strstr(fgg_error_message(), "DISPLAY"));
    assert_non_null(strstr(fgg_error_message(), "--gl egl"));
    /* a failed create leaves the context that was current, current */
    for (int b = FGG_BACKEND_EGL; b <= FGG_BACKEND_OSMESA; b++) {
        if (!fgg_backend_built((fgg_backend)b))
            continue;
        fgg_context *previous = create((fgg_backend)b);
        assert_int_equal(fgg_context_create(&config, &ctx), FG_ERR_UNSUPPORTED);
        assert_computes_squares();
        fgg_context_destroy(previous);
    }
}

/* MESA_GL_VERSION_OVERRIDE=3.3: the refusal names 4.3 and what is offered. */
static void test_old_gl_refused(void **state)
{
    (void)state;
    static const struct {
        fgg_backend backend;
        const char *platform;
    } cases[] = {
        {FGG_BACKEND_EGL, "EGL surfaceless:"},
        {FGG_BACKEND_OSMESA, "OSMesa:"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        if (!fgg_backend_built(cases[i].backend))
            continue;
        fgg_context *sentinel = (fgg_context *)&sentinel, *ctx = sentinel;
        fgg_context_config config = {.backend = cases[i].backend};
        assert_int_equal(fgg_context_create(&config, &ctx), FG_ERR_UNSUPPORTED);
        assert_ptr_equal(ctx, sentinel);
        const char *m = fgg_error_message();
        assert_non_null(strstr(m, cases[i].platform));
        assert_non_null(strstr(m, "OpenGL 4.3 core is needed"));
        assert_non_null(strstr(m, "offers 3.3"));
    }
}

/* Under xvfb-run: a window, then EGL and OSMesa and back to it. */
static void test_window(void **state)
{
    (void)state;
    fgg_context *window = NULL;
    fgg_context_config config = {.backend = FGG_BACKEND_WINDOW, .width = 64, .height = 48};
    assert_int_equal(fgg_context_create(&config, &window), FG_OK);
    assert_core_43(window, FGG_BACKEND_WINDOW, "GLFW");
    int w = 0, h = 0;
    fgg_context_framebuffer_size(window, &w, &h);
    assert_int_equal(w, 64);
    assert_int_equal(h, 48);
    assert_non_null(fgg_context_native_window(window));
    assert_computes_squares();
    fgg_context_present(window);
    /* glvnd refuses EGL on a thread with GLX current: the window is released */
    fgg_context *egl = create(FGG_BACKEND_EGL);
    assert_computes_squares();
    assert_int_equal(fgg_context_make_current(window), FG_OK);
    assert_computes_squares();
    fgg_context_destroy(egl);
    if (fgg_backend_built(FGG_BACKEND_OSMESA)) {
        fgg_context *osmesa = create(FGG_BACKEND_OSMESA);
        assert_computes_squares();
        assert_int_equal(fgg_context_make_current(window), FG_OK);
        assert_computes_squares();
        fgg_context_destroy(osmesa);
    }
    fgg_context_destroy(window);
}

int main(int argc, char **argv)
{
    const char *group = argc > 1 ? argv[1] : "";
    if (strcmp(group, "old-gl") == 0) {
        const struct CMUnitTest cases[] = {cmocka_unit_test(test_old_gl_refused)};
        return cmocka_run_group_tests_name("old-gl", cases, NULL, NULL);
    }
    if (strcmp(group, "window") == 0) {
        const struct CMUnitTest cases[] = {cmocka_unit_test(test_window)};
        return cmocka_run_group_tests_name("window", cases, NULL, NULL);
    }
    const struct CMUnitTest cases[] = {
        cmocka_unit_test(test_backend_names),
        cmocka_unit_test(test_backends_built),
        cmocka_unit_test(test_bad_arguments),
        cmocka_unit_test(test_egl),
        cmocka_unit_test(test_two_egl),
        cmocka_unit_test(test_osmesa),
        cmocka_unit_test(test_egl_after_osmesa),
        cmocka_unit_test(test_osmesa_one_thread),
        cmocka_unit_test(test_shader_error),
        cmocka_unit_test(test_window_without_display),
    };
    return cmocka_run_group_tests_name("contexts", cases, NULL, NULL);
}
