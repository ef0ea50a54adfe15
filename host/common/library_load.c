/* Opening a library at run time (library_load.h). */
#include <dlfcn.h>
#include <stdio.h>

#include "library_load.h"

void *library_load(const char *library, const library_symbol *symbols, size_t count, char *err,
                   size_t err_size)
{
    void *lib = dlopen(library, RTLD_NOW | RTLD_LOCAL);
    if (!lib) {
        snprintf(err, err_size, "cannot load %s: %s", library, dlerror());
        return NULL;
    }
    for (size_t i = 0; i < count; i++)
        if (!(*symbols[i].slot = dlsym(lib, symbols[i].name))) {
            snprintf(err, err_size, "%s has no %s", library, symbols[i].name);
            dlclose(lib);
            return NULL;
        }
    return lib;
}
