/* A shared library opened at run time (dlopen) and the functions taken
 * from it: the live devices' libraries (live_audio.h) and the libraries
 * the program opens on first use (lazy_library.h). */
#ifndef HOST_COMMON_LIBRARY_LOAD_H
#define HOST_COMMON_LIBRARY_LOAD_H

#include <stddef.h>

/* One function taken from a library: its name, and where its address goes
 * (POSIX lets dlsym's object pointer stand for a function). */
typedef struct library_symbol {
    const char *name;
    void **slot;
} library_symbol;
#define LIBRARY_SYMBOL(field, function)                                                            \
    {                                                                                              \
#function, (void **)&(field)                                                               \
    }

/* dlopens library (RTLD_NOW | RTLD_LOCAL) and resolves the count symbols.
 * Returns its handle, or NULL with a message naming library in err
 * ("cannot load", with dlerror's reason, or the symbol it lacks), nothing
 * left open. [any-thread] */
void *library_load(const char *library, const library_symbol *symbols, size_t count, char *err,
                   size_t err_size);

#endif
