/* What gpu/ files share: error reporting, the context's insides, the
 * backends' entry points and shader building. */
#ifndef FULGUR_GPU_INTERNAL_H
#define FULGUR_GPU_INTERNAL_H

#include <epoxy/gl.h>

#include "fulgur/gpu.h"

#if defined(__GNUC__)
#define FGG_PRINTF(a, b) __attribute__((format(printf, a, b)))
#else
#define FGG_PRINTF(a, b)
#endif

/* Sets fgg_error_message() and returns result. */
fg_result fgg_fail(fg_result result, const char *format, ...) FGG_PRINTF(2, 3);

/* One backend: create fills context->impl and makes the context current;
 * release makes it not current on the calling thread (context.c calls it
 * before another context is made current there, or this one destroyed). */
typedef struct fgg_backend_ops {
    const char *library; /* the Debian package that provides it, for messages */
    fg_result (*create)(fgg_context *context, const fgg_context_config *config);
    void (*destroy)(fgg_context *context);
    fg_result (*make_current)(fgg_context *context);
    void (*release)(fgg_context *context);
    void (*present)(fgg_context *context);
    void (*framebuffer_size)(const fgg_context *context, int *width, int *height);
} fgg_backend_ops;

/* NULL when the backend was not built. */
extern const fgg_backend_ops *const fgg_egl_backend;
extern const fgg_backend_ops *const fgg_osmesa_backend;
extern const fgg_backend_ops *const fgg_window_backend;

struct fgg_context {
    fgg_backend backend;
    const fgg_backend_ops *ops;
    void *impl;
    const char *platform;
    int width, height;
    int debug;
    fgg_context_info info;
};

/* After a backend made a context current: checks for GL 4.3 core and
 * fills the info; FG_ERR_UNSUPPORTED with the version found otherwise. */
fg_result fgg_context_check_version(fgg_context *context);

/* Compiles and links one compute shader; label names it in messages.
 * Errors: FG_ERR_GPU with the driver's log in the message. */
fg_result fgg_program_compute(const char *label, const char *source, GLuint *out);
/* Compiles and links a vertex + fragment program. */
fg_result fgg_program_graphics(const char *label, const char *vertex, const char *fragment,
                               GLuint *out);
/* FG_ERR_GPU naming what (and the GL error) if glGetError reports one. */
fg_result fgg_gl_check(const char *what);

#endif
