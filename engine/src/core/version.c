#include "fulgur/version.h"

const char *fg_version_string(void)
{
    return "fulgur " FG_VERSION_STRING;
}
