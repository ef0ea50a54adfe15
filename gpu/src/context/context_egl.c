/* The headless EGL backend: a GPU through EGL_EXT_platform_device when one
 * is there, else Mesa's EGL_MESA_platform_surfaceless (llvmpipe). No
 * surface: the picture renders into its own framebuffer objects. */
#include <stdlib.h>
#include <string.h>
#include <threads.h>

#include <epoxy/egl.h>

#include "gpu_internal.h"

typedef struct egl_state {
    EGLDisplay display;
    EGLContext context;
} egl_state;

/* EGL hands every context of a platform the same display, and
 * eglTerminate ends it for all of them: a display is terminated when the
 * last context on it goes. Contexts may live on several threads. */
#define MAX_DISPLAYS 8
static struct {
    EGLDisplay display;
    int contexts;
} displays[MAX_DISPLAYS];
static mtx_t displays_lock;
static once_flag displays_once = ONCE_FLAG_INIT;

static void displays_init(void)
{
    mtx_init(&displays_lock, mtx_plain);
}

static void display_hold(EGLDisplay d)
{
    call_once(&displays_once, displays_init);
    mtx_lock(&displays_lock);
    int free_slot = -1;
    for (int i = 0; i < MAX_DISPLAYS; i++) {
        if (displays[i].contexts > 0 && displays[i].display == d) {
            displays[i].contexts++;
            mtx_unlock(&displays_lock);
            return;
        }
        if (displays[i].contexts == 0 && free_slot < 0)
            free_slot = i;
    }
    /* more displays than slots: never terminated, which only leaks */
    if (free_slot >= 0)
        displays[free_slot].display = d, displays[free_slot].contexts = 1;
    mtx_unlock(&displays_lock);
}

static void display_drop(EGLDisplay d)
{
    call_once(&displays_once, displays_init);
    mtx_lock(&displays_lock);
    for (int i = 0; i < MAX_DISPLAYS; i++)
        if (displays[i].contexts > 0 && displays[i].display == d) {
            if (--displays[i].contexts == 0)
                eglTerminate(d);
            break;
        }
    mtx_unlock(&displays_lock);
}

static int has_extension(const char *list, const char *name)
{
    size_t n = strlen(name);
    for (const char *p = list; p && (p = strstr(p, name)) != NULL; p += n)
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0'))
            return 1;
    return 0;
}

/* A device that is a real GPU: Mesa lists its software rasteriser as a
 * device too, marked with EGL_MESA_device_software. */
static EGLDisplay device_display(const char *client)
{
    if (!has_extension(client, "EGL_EXT_platform_device") ||
        !has_extension(client, "EGL_EXT_device_enumeration"))
        return EGL_NO_DISPLAY;
    EGLDeviceEXT devices[16];
    EGLint count = 0;
    if (!eglQueryDevicesEXT(16, devices, &count))
        return EGL_NO_DISPLAY;
    for (EGLint i = 0; i < count; i++) {
        const char *ext = eglQueryDeviceStringEXT(devices[i], EGL_EXTENSIONS);
        if (has_extension(ext, "EGL_MESA_device_software"))
            continue;
        EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], NULL);
        EGLint major, minor;
        if (d != EGL_NO_DISPLAY && eglInitialize(d, &major, &minor))
            return d;
    }
    return EGL_NO_DISPLAY;
}

static EGLContext make_context(EGLDisplay d, int debug, int major, int minor)
{
    const EGLint attributes[] = {
        EGL_CONTEXT_MAJOR_VERSION, major,
        EGL_CONTEXT_MINOR_VERSION, minor,
        EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
        EGL_CONTEXT_OPENGL_DEBUG, debug ? EGL_TRUE : EGL_FALSE,
        EGL_NONE};
    return eglCreateContext(d, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
}

/* The 4.3 context was refused: find out what the driver does offer, for
 * the message. */
static fg_result refused(EGLDisplay d, const char *platform)
{
    EGLContext c = eglCreateContext(d, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, (EGLint[]){EGL_NONE});
    const char *version = NULL, *renderer = NULL;
    if (c != EGL_NO_CONTEXT && eglMakeCurrent(d, EGL_NO_SURFACE, EGL_NO_SURFACE, c)) {
        version = (const char *)glGetString(GL_VERSION);
        renderer = (const char *)glGetString(GL_RENDERER);
    }
    fg_result r = fgg_fail(FG_ERR_UNSUPPORTED,
                           "%s: OpenGL %d.%d core is needed (compute shaders), but %s offers %s",
                           platform, FGG_GL_MAJOR, FGG_GL_MINOR,
                           renderer ? renderer : "the driver",
                           version ? version : "no desktop GL context at all");
    if (c != EGL_NO_CONTEXT) {
        eglMakeCurrent(d, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(d, c);
    }
    return r;
}

static fg_result egl_create(fgg_context *ctx, const fgg_context_config *config)
{
    const char *client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!client || !has_extension(client, "EGL_EXT_platform_base"))
        return fgg_fail(FG_ERR_UNSUPPORTED,
                        "EGL: no EGL_EXT_platform_base here (is libegl1 with a driver, e.g. "
                        "libegl-mesa0, installed?)");
    EGLDisplay d = device_display(client);
    ctx->platform = "EGL device";
    if (d == EGL_NO_DISPLAY) {
        if (!has_extension(client, "EGL_MESA_platform_surfaceless"))
            return fgg_fail(FG_ERR_UNSUPPORTED,
                            "EGL: no GPU device and no EGL_MESA_platform_surfaceless "
                            "(install libegl-mesa0 for Mesa's llvmpipe)");
        d = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
        EGLint major, minor;
        if (d == EGL_NO_DISPLAY || !eglInitialize(d, &major, &minor))
            return fgg_fail(FG_ERR_UNSUPPORTED, "EGL: the surfaceless platform did not start "
                            "(EGL error 0x%x)", (unsigned)eglGetError());
        ctx->platform = "EGL surfaceless";
    }
    display_hold(d);
    if (!has_extension(eglQueryString(d, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context") ||
        !eglBindAPI(EGL_OPENGL_API)) {
        display_drop(d);
        return fgg_fail(FG_ERR_UNSUPPORTED, "%s: no surfaceless desktop OpenGL", ctx->platform);
    }
    EGLContext c = make_context(d, config->debug, FGG_GL_MAJOR, FGG_GL_MINOR);
    if (c == EGL_NO_CONTEXT) {
        fg_result r = refused(d, ctx->platform);
        display_drop(d);
        return r;
    }
    egl_state *s = malloc(sizeof *s);
    if (!s || !eglMakeCurrent(d, EGL_NO_SURFACE, EGL_NO_SURFACE, c)) {
        fg_result r = s ? FG_ERR_GPU : FG_ERR_NO_MEMORY;
        free(s);
        eglDestroyContext(d, c);
        display_drop(d);
        return fgg_fail(r, "%s: cannot make the context current", ctx->platform);
    }
    *s = (egl_state){d, c};
    ctx->impl = s;
    return FG_OK;
}

static void egl_release(fgg_context *ctx)
{
    egl_state *s = ctx->impl;
    eglMakeCurrent(s->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
}

static void egl_destroy(fgg_context *ctx)
{
    egl_state *s = ctx->impl;
    eglDestroyContext(s->display, s->context);
    display_drop(s->display);
    free(s);
}

static fg_result egl_make_current(fgg_context *ctx)
{
    egl_state *s = ctx->impl;
    if (!eglMakeCurrent(s->display, EGL_NO_SURFACE, EGL_NO_SURFACE, s->context))
        return fgg_fail(FG_ERR_GPU, "%s: eglMakeCurrent failed (0x%x)", ctx->platform,
                        (unsigned)eglGetError());
    return FG_OK;
}

static const fgg_backend_ops egl_ops = {
    .library = "libegl-dev",
    .create = egl_create,
    .destroy = egl_destroy,
    .make_current = egl_make_current,
    .release = egl_release,
};

const fgg_backend_ops *const fgg_egl_backend = &egl_ops;
