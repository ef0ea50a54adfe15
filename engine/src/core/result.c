#include "fulgur/result.h"

const char *fg_result_str(fg_result r)
{
    switch (r) {
    case FG_OK: return "ok";
    case FG_ERR_NULL: return "a required pointer is NULL";
    case FG_ERR_ARGUMENT: return "argument out of range";
    case FG_ERR_SAMPLE_RATE: return "sample rate outside 8000-384000 Hz";
    case FG_ERR_NOT_FINITE: return "value is not a finite number";
    case FG_ERR_TREE: return "discharge tree is invalid";
    case FG_ERR_CAPACITY: return "larger than the configured capacity";
    case FG_ERR_POOL_FULL: return "voice pool is full";
    case FG_ERR_QUEUE_FULL: return "queue to the audio thread is full";
    case FG_ERR_BLOCK_SIZE: return "block larger than the configured maximum";
    case FG_ERR_NOT_FOUND: return "no live voice has that id";
    case FG_ERR_NO_MEMORY: return "out of memory";
    case FG_ERR_UNREACHABLE: return "target cannot be reached";
    case FG_ERR_NOT_CONVERGED: return "solver did not converge";
    case FG_ERR_UNSUPPORTED: return "not supported here";
    case FG_ERR_GPU: return "the GPU driver failed";
    }
    return "unknown result code";
}
