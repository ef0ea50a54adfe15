/* The window backend: a GLFW window with a GL 4.3 core context, for the
 * viewer. */
#include <epoxy/gl.h>
#include <GLFW/glfw3.h>

#include "gpu_internal.h"

static int windows_open;

static fg_result glfw_error(fg_result result, const char *what)
{
    const char *why = NULL;
    int code = glfwGetError(&why);
    return fgg_fail(result, "GLFW: %s: %s (GLFW error 0x%x)", what,
                    why ? why : "no reason given", (unsigned)code);
}

static fg_result window_create(fgg_context *ctx, const fgg_context_config *config)
{
    ctx->platform = "GLFW";
    if (windows_open == 0 && !glfwInit())
        return glfw_error(FG_ERR_UNSUPPORTED,
                          "cannot start (no display? set DISPLAY, or use --gl egl)");
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, FGG_GL_MAJOR);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, FGG_GL_MINOR);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, config->debug ? GLFW_TRUE : GLFW_FALSE);
    int w = config->width ? config->width : 1280, h = config->height ? config->height : 720;
    GLFWwindow *window =
        glfwCreateWindow(w, h, config->title ? config->title : "fulgur", NULL, NULL);
    if (!window) {
        fg_result r = glfw_error(FG_ERR_UNSUPPORTED, "no window with an OpenGL 4.3 core context");
        if (windows_open == 0)
            glfwTerminate();
        return r;
    }
    windows_open++;
    glfwMakeContextCurrent(window);
    glfwSwapInterval(1);
    ctx->width = w;
    ctx->height = h;
    ctx->impl = window;
    return FG_OK;
}

static void window_destroy(fgg_context *ctx)
{
    glfwDestroyWindow(ctx->impl);
    if (--windows_open == 0)
        glfwTerminate();
}

static fg_result window_make_current(fgg_context *ctx)
{
    glfwMakeContextCurrent(ctx->impl);
    return FG_OK;
}

static void window_release(fgg_context *ctx)
{
    (void)ctx;
    glfwMakeContextCurrent(NULL);
}

static void window_present(fgg_context *ctx)
{
    glfwSwapBuffers(ctx->impl);
}

static void window_framebuffer_size(const fgg_context *ctx, int *width, int *height)
{
    glfwGetFramebufferSize(ctx->impl, width, height);
}

static const fgg_backend_ops window_ops = {
    .library = "libglfw3-dev",
    .create = window_create,
    .destroy = window_destroy,
    .make_current = window_make_current,
    .release = window_release,
    .present = window_present,
    .framebuffer_size = window_framebuffer_size,
};

const fgg_backend_ops *const fgg_window_backend = &window_ops;
