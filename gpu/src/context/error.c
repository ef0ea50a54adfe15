/* The message of the last failing fgg_ call, one per thread. */
#include <stdarg.h>
#include <stdio.h>

#include "gpu_internal.h"

static _Thread_local char message[512];

const char *fgg_error_message(void)
{
    return message;
}

fg_result fgg_fail(fg_result result, const char *format, ...)
{
    va_list args;
    va_start(args, format);
    vsnprintf(message, sizeof message, format, args);
    va_end(args);
    return result;
}
