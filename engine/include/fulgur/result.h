/* fulgur — result codes shared by every engine call. */
#ifndef FULGUR_RESULT_H
#define FULGUR_RESULT_H

#include "fulgur/defs.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum fg_result {
    FG_OK = 0,
    FG_ERR_NULL = -1,          /* a required pointer argument was NULL */
    FG_ERR_ARGUMENT = -2,      /* a value is out of its documented range */
    FG_ERR_SAMPLE_RATE = -3,   /* sample rate outside 8 kHz – 384 kHz */
    FG_ERR_NOT_FINITE = -4,    /* a NaN or infinite value where a number was due */
    FG_ERR_TREE = -5,          /* a discharge tree breaks its rules (see fg_tree_check) */
    FG_ERR_CAPACITY = -6,      /* larger than the engine or generator was configured to hold */
    FG_ERR_POOL_FULL = -7,     /* no free voice or segment storage now; collect and retry */
    FG_ERR_QUEUE_FULL = -8,    /* the ring to the audio thread is full; retry later */
    FG_ERR_BLOCK_SIZE = -9,    /* nframes larger than the configured maximum block */
    FG_ERR_NOT_FOUND = -10,    /* no live voice has that id */
    FG_ERR_NO_MEMORY = -11,    /* allocation failed (never on the audio thread) */
    FG_ERR_UNREACHABLE = -12,  /* a growth target cannot be reached */
    FG_ERR_NOT_CONVERGED = -13,/* an iterative solve stopped short of its tolerance */
    FG_ERR_UNSUPPORTED = -14,  /* not available here: a backend not built or not usable, GL too old */
    FG_ERR_GPU = -15,          /* the GPU driver failed: a shader did not compile, a GL error */
    FG_ERR_IO = -16            /* a file could not be read or written (libfulgur-scene; the
                                * engine itself does no I/O) */
} fg_result;

/* A short English description of r, e.g. "tree is invalid". Never NULL; the
 * string is static. [any-thread] */
FG_API const char *fg_result_str(fg_result r);

#ifdef __cplusplus
}
#endif

#endif
