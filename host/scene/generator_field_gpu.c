/* Growing in a field solved on the GPU: a headless EGL context on the
 * generating thread (which is its [gpu-thread] for the call), the GPU
 * field, the solve, and the growth reading phi through the gather. */
#include <stdio.h>

#include "fulgur/gpu.h"
#include "generator_field_gpu.h"

fg_result gen_field_gpu_grow(fg_field *description, const fg_growth_config *growth, fg_tree *out,
                             double *residual, char *msg, size_t msg_size)
{
    fgg_context *ctx = NULL;
    fgg_field *field = NULL;
    fgg_solve_report rep = {0};
    fg_result r = fgg_context_create(NULL, &ctx);
    if (r == FG_OK)
        r = fgg_field_create(ctx, description, &field);
    if (r == FG_OK)
        r = fgg_field_solve(field, NULL, &rep);
    *residual = rep.residual;
    if (r != FG_OK)
        snprintf(msg, msg_size, "%s", fgg_error_message());
    if (r == FG_OK) {
        fg_field_source src;
        fgg_field_source_init(field, description, &src);
        r = fg_grow_matsuyama(&src, growth, out, NULL);
        if (r != FG_OK && r != FG_ERR_UNREACHABLE)
            snprintf(msg, msg_size, "%s", fgg_error_message());
    }
    fgg_field_destroy(field);
    fgg_context_destroy(ctx);
    return r;
}
