/* Flushing denormals to zero for the duration of a render call, so a
 * decaying tail never takes the slow path. */
#ifndef FULGUR_FP_ENV_INTERNAL_H
#define FULGUR_FP_ENV_INTERNAL_H

typedef struct fg_fp_env {
    unsigned long saved;
} fg_fp_env;

fg_fp_env fg_fp_env_flush_denormals(void);
void fg_fp_env_restore(fg_fp_env env);

#endif
