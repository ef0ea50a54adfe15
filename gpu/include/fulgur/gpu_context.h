/* fulgur gpu/ — an OpenGL 4.3 core context to run the field solver and
 * draw the discharge picture in.
 *
 * Three backends behind one handle:
 *   - EGL, headless: EGL_EXT_platform_device first (a real GPU), falling back
 *     to EGL_MESA_platform_surfaceless (Mesa's llvmpipe, no display needed);
 *   - OSMesa, Mesa's software off-screen context;
 *   - a GLFW window, for the viewer.
 * GL entry points are resolved by libepoxy. Every fgg_ call that fails
 * leaves a message naming what went wrong in fgg_error_message().
 *
 * Threads: a context and everything made in it (fields, pictures) belong to
 * the one thread that created it, tagged [gpu-thread]. */
#ifndef FULGUR_GPU_CONTEXT_H
#define FULGUR_GPU_CONTEXT_H

#include <stddef.h>

#include "fulgur/defs.h"
#include "fulgur/result.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The GL version every backend must give: compute shaders and image load/store. */
#define FGG_GL_MAJOR 4
#define FGG_GL_MINOR 3

typedef struct fgg_context fgg_context;

typedef enum fgg_backend {
    FGG_BACKEND_EGL = 0, /* headless: a GPU device, else Mesa surfaceless */
    FGG_BACKEND_OSMESA,  /* headless software rendering */
    FGG_BACKEND_WINDOW   /* a GLFW window with a default framebuffer */
} fgg_backend;

typedef struct fgg_context_config {
    fgg_backend backend;
    int width, height;   /* window only, pixels; 0 means 1280 x 720 */
    const char *title;   /* window only; NULL means "fulgur" */
    int debug;           /* nonzero: a debug context, GL messages to stderr */
} fgg_context_config;

typedef struct fgg_context_info {
    fgg_backend backend;
    const char *platform; /* e.g. "EGL device", "EGL surfaceless", "OSMesa", "GLFW" */
    const char *renderer; /* GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)" */
    const char *version;  /* GL_VERSION */
    int gl_major, gl_minor;
} fgg_context_info;

/* The message of the last fgg_ call on this thread that failed, e.g. "the
 * OSMesa backend was not built: install libosmesa6-dev and reconfigure".
 * Never NULL; empty before any failure. Valid until the next failing call
 * on this thread. [any-thread] */
FG_API const char *fgg_error_message(void);

/* "egl", "osmesa" or "window". [any-thread] */
FG_API const char *fgg_backend_name(fgg_backend backend);

/* Parses a backend name as fgg_backend_name writes it. [any-thread]
 * Errors: FG_ERR_NULL; FG_ERR_ARGUMENT an unknown name (the message lists
 * the known ones). */
FG_API FG_NODISCARD fg_result fgg_backend_from_name(const char *name, fgg_backend *out);

/* Whether this build has the backend at all (its library was found when
 * fulgur was configured). Being built does not mean it can start here (no
 * display, no driver): fgg_context_create says. [any-thread] */
FG_API int fgg_backend_built(fgg_backend backend);

/* Creates a GL 4.3 core context with the chosen backend and makes it
 * current on the calling thread, which becomes its [gpu-thread]. config may
 * be NULL (EGL, defaults). *out is owned by the caller until
 * fgg_context_destroy. [gpu-thread]
 * Errors: FG_ERR_NULL out; FG_ERR_ARGUMENT an unknown backend or a negative
 * size; FG_ERR_UNSUPPORTED the backend was not built, cannot start here
 * (no EGL device or Mesa platform, no display for a window), or the driver
 * offers less than GL 4.3 core (the message names what it offers);
 * FG_ERR_NO_MEMORY. */
FG_API FG_NODISCARD fg_result fgg_context_create(const fgg_context_config *config,
                                                 fgg_context **out);

/* Releases the context and everything it owns on the GPU side; fields and
 * pictures made in it must be destroyed first. NULL is a no-op. [gpu-thread] */
FG_API void fgg_context_destroy(fgg_context *context);

/* Makes the context current on the calling thread again (after another GL
 * context was used there). [gpu-thread]
 * Errors: FG_ERR_NULL; FG_ERR_GPU the platform refused. */
FG_API FG_NODISCARD fg_result fgg_context_make_current(fgg_context *context);

/* What the context is. The strings are owned by the context and valid until
 * it is destroyed. [gpu-thread] */
FG_API void fgg_context_get_info(const fgg_context *context, fgg_context_info *out);

/* Window: shows the default framebuffer (swap buffers). Headless: a no-op.
 * [gpu-thread] */
FG_API void fgg_context_present(fgg_context *context);

/* Window: the framebuffer's size in pixels; headless: the size asked for
 * (or 0 x 0). [gpu-thread] */
FG_API void fgg_context_framebuffer_size(const fgg_context *context, int *width, int *height);

/* Window: the GLFWwindow pointer, for the host's input handling; headless:
 * NULL. Owned by the context. [gpu-thread] */
FG_API void *fgg_context_native_window(fgg_context *context);

#ifdef __cplusplus
}
#endif

#endif
