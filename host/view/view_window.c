/* The viewer's window input: GLFW callbacks turn mouse and keys into
 * view_events and hand them to view_apply, the path the script takes. */
#include "view.h"

#ifdef FULGUR_HAVE_GLFW
#include <GLFW/glfw3.h>

typedef struct window_input {
    view *v;
    double last_x, last_y;
    bool orbiting;
} window_input;

static window_input input; /* one window per process */

static void send(view_event e)
{
    view_apply(input.v, &e);
}

static void on_key(GLFWwindow *w, int key, int scancode, int action, int mods)
{
    (void)w, (void)scancode, (void)mods;
    if (action != GLFW_PRESS)
        return;
    if (key == GLFW_KEY_SPACE)
        send((view_event){.kind = VIEW_EV_DISCHARGE});
    else if (key == GLFW_KEY_H)
        send((view_event){.kind = VIEW_EV_HOLD});
    else if (key == GLFW_KEY_C)
        send((view_event){.kind = VIEW_EV_CLEAR});
    else if (key == GLFW_KEY_R)
        send((view_event){.kind = VIEW_EV_REPLAY});
    else if (key == GLFW_KEY_F)
        send((view_event){.kind = VIEW_EV_FRAME});
    else if (key == GLFW_KEY_F1)
        send((view_event){.kind = VIEW_EV_OVERLAY});
    else if (key == GLFW_KEY_ESCAPE)
        send((view_event){.kind = VIEW_EV_QUIT});
}

static void on_button(GLFWwindow *w, int button, int action, int mods)
{
    double x, y;
    int width, height;
    glfwGetCursorPos(w, &x, &y);
    glfwGetWindowSize(w, &width, &height);
    bool orbit = button == GLFW_MOUSE_BUTTON_MIDDLE ||
                 (button == GLFW_MOUSE_BUTTON_LEFT && (mods & GLFW_MOD_ALT));
    if (orbit) {
        input.orbiting = action == GLFW_PRESS;
        input.last_x = x, input.last_y = y;
        return;
    }
    if (action != GLFW_PRESS || width <= 0 || height <= 0)
        return;
    int sign = button == GLFW_MOUSE_BUTTON_RIGHT || (mods & GLFW_MOD_SHIFT) ? -1 : 1;
    send((view_event){.kind = VIEW_EV_CLICK, .x = x / width, .y = y / height, .sign = sign});
}

static void on_cursor(GLFWwindow *w, double x, double y)
{
    int width, height;
    glfwGetWindowSize(w, &width, &height);
    if (input.orbiting && width > 0 && height > 0)
        send((view_event){.kind = VIEW_EV_ORBIT, .x = (x - input.last_x) / width,
                          .y = (y - input.last_y) / height});
    input.last_x = x, input.last_y = y;
}

static void on_scroll(GLFWwindow *w, double dx, double dy)
{
    (void)w, (void)dx;
    send((view_event){.kind = VIEW_EV_ZOOM, .y = dy});
}

int view_window_attach(view *v, fgg_context *ctx)
{
    GLFWwindow *w = fgg_context_native_window(ctx);
    if (!w)
        return -1;
    input = (window_input){.v = v};
    glfwSetKeyCallback(w, on_key);
    glfwSetMouseButtonCallback(w, on_button);
    glfwSetCursorPosCallback(w, on_cursor);
    glfwSetScrollCallback(w, on_scroll);
    return 0;
}

bool view_window_poll(view *v, fgg_context *ctx)
{
    (void)v;
    glfwPollEvents();
    return !glfwWindowShouldClose(fgg_context_native_window(ctx));
}

#else

int view_window_attach(view *v, fgg_context *ctx)
{
    (void)v, (void)ctx;
    return -1;
}

bool view_window_poll(view *v, fgg_context *ctx)
{
    (void)v, (void)ctx;
    return false;
}

#endif
