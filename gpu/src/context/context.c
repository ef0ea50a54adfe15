/* The context handle over its backends, and the GL version check. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gpu_internal.h"

static const char *const names[] = {"egl", "osmesa", "window"};

const char *fgg_backend_name(fgg_backend backend)
{
    return (unsigned)backend < 3 ? names[backend] : "unknown";
}

fg_result fgg_backend_from_name(const char *name, fgg_backend *out)
{
    if (!name || !out)
        return fgg_fail(FG_ERR_NULL, "no backend name given");
    for (unsigned b = 0; b < 3; b++)
        if (strcmp(name, names[b]) == 0) {
            *out = (fgg_backend)b;
            return FG_OK;
        }
    return fgg_fail(FG_ERR_ARGUMENT, "unknown GL backend \"%s\": use egl, osmesa or window", name);
}

static const fgg_backend_ops *ops_of(fgg_backend backend)
{
    switch (backend) {
    case FGG_BACKEND_EGL: return fgg_egl_backend;
    case FGG_BACKEND_OSMESA: return fgg_osmesa_backend;
    case FGG_BACKEND_WINDOW: return fgg_window_backend;
    }
    return NULL;
}

int fgg_backend_built(fgg_backend backend)
{
    return ops_of(backend) != NULL;
}

static const char *const packages[] = {"libegl-dev", "libosmesa6-dev", "libglfw3-dev"};

/* The fgg context current on this thread. Making another one current first
 * releases this one through its own platform: EGL, GLX and OSMesa do not
 * know of each other's contexts (glvnd refuses an EGL context on a thread
 * where a GLX one is current; an OSMesa context holds epoxy's dispatch,
 * see context_osmesa.c). */
static _Thread_local fgg_context *current;

static void release_current(void)
{
    if (current)
        current->ops->release(current);
    current = NULL;
}

fg_result fgg_context_create(const fgg_context_config *config, fgg_context **out)
{
    if (!out)
        return fgg_fail(FG_ERR_NULL, "fgg_context_create: out is NULL");
    fgg_context_config c = {0};
    if (config)
        c = *config;
    if ((unsigned)c.backend > FGG_BACKEND_WINDOW)
        return fgg_fail(FG_ERR_ARGUMENT, "unknown GL backend %d", (int)c.backend);
    if (c.width < 0 || c.height < 0)
        return fgg_fail(FG_ERR_ARGUMENT, "window size %d x %d is negative", c.width, c.height);
    const fgg_backend_ops *ops = ops_of(c.backend);
    if (!ops)
        return fgg_fail(FG_ERR_UNSUPPORTED,
                        "the %s GL backend was not built: install %s and reconfigure fulgur",
                        names[c.backend], packages[c.backend]);
    fgg_context *ctx = calloc(1, sizeof *ctx);
    if (!ctx)
        return fgg_fail(FG_ERR_NO_MEMORY, "out of memory for a GL context");
    ctx->backend = c.backend;
    ctx->ops = ops;
    ctx->width = c.width;
    ctx->height = c.height;
    ctx->debug = c.debug;
    fgg_context *previous = current;
    release_current();
    fg_result r = ops->create(ctx, &c);
    if (r == FG_OK) {
        current = ctx;
        r = fgg_context_check_version(ctx);
    }
    if (r != FG_OK) {
        fgg_context_destroy(ctx);
        /* a failed create leaves the thread as it was; previous made itself
         * current once, so this is not expected to fail */
        if (previous && previous->ops->make_current(previous) == FG_OK)
            current = previous;
        return r;
    }
    *out = ctx;
    return FG_OK;
}

void fgg_context_destroy(fgg_context *ctx)
{
    if (!ctx)
        return;
    if (ctx == current)
        release_current();
    if (ctx->impl)
        ctx->ops->destroy(ctx);
    free(ctx);
}

fg_result fgg_context_make_current(fgg_context *ctx)
{
    if (!ctx)
        return fgg_fail(FG_ERR_NULL, "fgg_context_make_current: context is NULL");
    if (ctx != current)
        release_current();
    fg_result r = ctx->ops->make_current(ctx);
    current = r == FG_OK ? ctx : NULL;
    return r;
}

void fgg_context_get_info(const fgg_context *ctx, fgg_context_info *out)
{
    *out = ctx->info;
}

void fgg_context_present(fgg_context *ctx)
{
    if (ctx->ops->present)
        ctx->ops->present(ctx);
}

void fgg_context_framebuffer_size(const fgg_context *ctx, int *width, int *height)
{
    if (ctx->ops->framebuffer_size) {
        ctx->ops->framebuffer_size(ctx, width, height);
        return;
    }
    *width = ctx->width;
    *height = ctx->height;
}

void *fgg_context_native_window(fgg_context *ctx)
{
    return ctx->backend == FGG_BACKEND_WINDOW ? ctx->impl : NULL;
}

fg_result fgg_context_check_version(fgg_context *ctx)
{
    const char *version = (const char *)glGetString(GL_VERSION);
    const char *renderer = (const char *)glGetString(GL_RENDERER);
    int major = 0, minor = 0;
    if (!version || sscanf(version, "%d.%d", &major, &minor) != 2)
        return fgg_fail(FG_ERR_UNSUPPORTED, "%s: the GL context gives no version",
                        ctx->platform);
    ctx->info = (fgg_context_info){.backend = ctx->backend, .platform = ctx->platform,
                                   .renderer = renderer ? renderer : "unknown",
                                   .version = version, .gl_major = major, .gl_minor = minor};
    if (major < FGG_GL_MAJOR || (major == FGG_GL_MAJOR && minor < FGG_GL_MINOR))
        return fgg_fail(FG_ERR_UNSUPPORTED,
                        "%s: OpenGL %d.%d core is needed (compute shaders), but %s offers %s",
                        ctx->platform, FGG_GL_MAJOR, FGG_GL_MINOR, ctx->info.renderer, version);
    return FG_OK;
}
