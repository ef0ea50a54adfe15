/* The GL module's one export (gl_module.h): what the program calls. Built
 * into fulgur-gl.so only. */
#include "common/commands.h"
#include "gl_module.h"
#include "render_picture.h"
#include "scene/generator_field_gpu.h"

__attribute__((visibility("default"))) extern const gl_module fulgur_gl_module;

const gl_module fulgur_gl_module = {
    .version = GL_MODULE_VERSION,
    .view_main = view_main,
    .render_picture = render_picture,
    .field_gpu_grow = gen_field_gpu_grow,
};
