/* The OSMesa backend: Mesa's software off-screen GL, a 4.3 core context
 * made current on a 1 x 1 buffer (the picture renders into its own
 * framebuffer objects). OSMesa has no debug contexts: config->debug is not
 * used here.
 *
 * Why epoxy's dispatch is redirected while an OSMesa context is current.
 * Every GL call in gpu/ goes through libepoxy's public function pointers
 * (<epoxy/gl.h> turns glDispatchCompute into epoxy_glDispatchCompute). On
 * first use epoxy resolves a function from libGL.so.1 (GL 1.2 and older)
 * or through glXGetProcAddress / eglGetProcAddress, whichever of GLX and
 * EGL has a context current; with neither it aborts ("Couldn't find current
 * GLX or EGL context"). It does not know OSMesa, and libGL.so.1 is glvnd,
 * whose dispatch does not see OSMesa's context either (glGetString gives
 * NULL). epoxy_set_resolver_failure_handler does not help: the handler is
 * asked only when no provider fits the context's GL version, and with
 * glGetString giving NULL epoxy assumes every version fits and goes on to
 * the abort.
 *
 * libOSMesa exports every entry point and OSMesaGetProcAddress finds them;
 * the pointers it gives do not depend on the context. So while an OSMesa
 * context is current, the pointer of every GL function that gpu/ and its
 * tests call (FGG_GL_NAMES, read from their sources at build time by
 * cmake/GlNames.cmake) is set to OSMesa's, after keeping epoxy's own value;
 * the kept values go back when the context is released (context.c does
 * that before another context is made current or this one is destroyed).
 * A GL call gpu/ did not make when it was built is not redirected and hits
 * epoxy's abort: a new one is listed by the next build.
 *
 * The pointers are the process's, not the thread's: while an OSMesa context
 * is current on one thread, other threads must not call GL through epoxy.
 * A second thread's OSMesa context is refused; a second thread's EGL or
 * window context is not detected. */
#include <stdatomic.h>
#include <stdlib.h>

#include <epoxy/gl.h>
/* after epoxy, whose header stands in for the GL/gl.h that osmesa.h wants */
#include <GL/osmesa.h>

#include "gpu_gl_names.h"
#include "gpu_internal.h"

typedef struct osmesa_state {
    OSMesaContext context;
    unsigned char pixel[4]; /* the 1 x 1 RGBA colour buffer */
} osmesa_state;

/* Any function pointer: void (*)(void) converts to and from every other
 * without a warning (OSMESAproc, void (*)(), does not). */
typedef void (*gl_proc)(void);

#define COUNT_NAME(name) +1
enum { GL_NAME_COUNT = 0 FGG_GL_NAMES(COUNT_NAME) };

static gl_proc kept[GL_NAME_COUNT];
static atomic_int redirected; /* by some thread */
static _Thread_local int redirected_here;

/* Points epoxy at OSMesa for this thread, unless another thread has. */
static fg_result redirect(void)
{
    if (redirected_here)
        return FG_OK;
    int none = 0;
    if (!atomic_compare_exchange_strong(&redirected, &none, 1))
        return fgg_fail(FG_ERR_UNSUPPORTED, "OSMesa: a context is current on another thread; "
                                            "OSMesa contexts work on one thread at a time");
    redirected_here = 1;
    int i = 0;
    gl_proc proc;
    /* name is the epoxy_ pointer, #name the GL name */
#define REDIRECT(name)                                                   \
    kept[i] = (gl_proc)name;                                             \
    if ((proc = (gl_proc)OSMesaGetProcAddress(#name)) != NULL)           \
        name = (__typeof__(name))proc;                                   \
    i++;
    FGG_GL_NAMES(REDIRECT)
#undef REDIRECT
    return FG_OK;
}

static void restore(void)
{
    if (!redirected_here)
        return;
    int i = 0;
#define RESTORE(name) name = (__typeof__(name))kept[i++];
    FGG_GL_NAMES(RESTORE)
#undef RESTORE
    redirected_here = 0;
    atomic_store(&redirected, 0);
}

static OSMesaContext make_context(int profile, int major, int minor)
{
    const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA,
                              OSMESA_DEPTH_BITS, 0,
                              OSMESA_PROFILE, profile,
                              OSMESA_CONTEXT_MAJOR_VERSION, major,
                              OSMESA_CONTEXT_MINOR_VERSION, minor,
                              0};
    return OSMesaCreateContextAttribs(attributes, NULL);
}

/* The 4.3 core context was refused: find out what OSMesa does offer, for
 * the message. glGetString is called through OSMesa's own pointer, not
 * epoxy's. */
static fg_result refused(void)
{
    OSMesaContext c = make_context(OSMESA_COMPAT_PROFILE, 1, 0);
    unsigned char pixel[4];
    const char *version = NULL, *renderer = NULL;
    const GLubyte *(*get_string)(GLenum) =
        (const GLubyte *(*)(GLenum))(gl_proc)OSMesaGetProcAddress("glGetString");
    if (c && get_string && OSMesaMakeCurrent(c, pixel, GL_UNSIGNED_BYTE, 1, 1)) {
        version = (const char *)get_string(GL_VERSION);
        renderer = (const char *)get_string(GL_RENDERER);
    }
    fg_result r = fgg_fail(FG_ERR_UNSUPPORTED,
                           "OSMesa: OpenGL %d.%d core is needed (compute shaders), but %s offers %s",
                           FGG_GL_MAJOR, FGG_GL_MINOR, renderer ? renderer : "OSMesa",
                           version ? version : "no OpenGL context at all");
    if (c) {
        OSMesaMakeCurrent(NULL, NULL, GL_UNSIGNED_BYTE, 0, 0);
        OSMesaDestroyContext(c);
    }
    return r;
}

static fg_result osmesa_make_current(fgg_context *ctx)
{
    osmesa_state *s = ctx->impl;
    fg_result r = redirect();
    if (r != FG_OK)
        return r;
    if (!OSMesaMakeCurrent(s->context, s->pixel, GL_UNSIGNED_BYTE, 1, 1)) {
        restore();
        return fgg_fail(FG_ERR_GPU, "OSMesa: OSMesaMakeCurrent failed");
    }
    return FG_OK;
}

static fg_result osmesa_create(fgg_context *ctx, const fgg_context_config *config)
{
    (void)config;
    ctx->platform = "OSMesa";
    OSMesaContext c = make_context(OSMESA_CORE_PROFILE, FGG_GL_MAJOR, FGG_GL_MINOR);
    if (!c)
        return refused();
    osmesa_state *s = calloc(1, sizeof *s);
    if (!s) {
        OSMesaDestroyContext(c);
        return fgg_fail(FG_ERR_NO_MEMORY, "out of memory for an OSMesa context");
    }
    s->context = c;
    ctx->impl = s;
    fg_result r = osmesa_make_current(ctx);
    if (r != FG_OK) {
        OSMesaDestroyContext(c);
        free(s);
        ctx->impl = NULL;
    }
    return r;
}

static void osmesa_release(fgg_context *ctx)
{
    (void)ctx;
    restore();
    OSMesaMakeCurrent(NULL, NULL, GL_UNSIGNED_BYTE, 0, 0);
}

static void osmesa_destroy(fgg_context *ctx)
{
    osmesa_state *s = ctx->impl;
    OSMesaDestroyContext(s->context);
    free(s);
}

static const fgg_backend_ops osmesa_ops = {
    .library = "libosmesa6-dev",
    .create = osmesa_create,
    .destroy = osmesa_destroy,
    .make_current = osmesa_make_current,
    .release = osmesa_release,
};

const fgg_backend_ops *const fgg_osmesa_backend = &osmesa_ops;
