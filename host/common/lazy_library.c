/* Opening the program's libraries on first use (lazy_library.h). */
#include <stdio.h>
#include <stdlib.h>

#include "lazy_library.h"

/* the shell's and the dynamic loader's status for what cannot be run */
#define LAZY_LIBRARY_MISSING 127

void lazy_library_load(const char *library, const library_symbol *symbols, size_t count)
{
    char err[512];
    if (!library_load(library, symbols, count, err, sizeof err)) {
        fprintf(stderr, "fulgur: %s\n", err);
        exit(LAZY_LIBRARY_MISSING);
    }
}
