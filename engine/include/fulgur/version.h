/* fulgur — the library's version.
 *
 * The macros are the version of the headers a program was compiled with;
 * fg_version_string() is the version of the library it runs with. They
 * differ when a program built against one release runs with another: the
 * shared library's SONAME (docs/linking.md) says which releases may be
 * swapped for one another. CMakeLists.txt reads its project version from
 * the three numbers below: this header is the one place they are written. */
#ifndef FULGUR_VERSION_H
#define FULGUR_VERSION_H

#include "fulgur/defs.h"

#ifdef __cplusplus
extern "C" {
#endif

#define FG_VERSION_MAJOR 0
#define FG_VERSION_MINOR 1
#define FG_VERSION_PATCH 0

/* One number that compares as the version does: FG_VERSION >=
 * FG_VERSION_ENCODE(0, 1, 0). */
#define FG_VERSION_ENCODE(major, minor, patch) ((major) * 1000000L + (minor) * 1000L + (patch))
#define FG_VERSION FG_VERSION_ENCODE(FG_VERSION_MAJOR, FG_VERSION_MINOR, FG_VERSION_PATCH)

#define FG_VERSION_STRINGIFY_(x) #x
#define FG_VERSION_STRINGIFY(x) FG_VERSION_STRINGIFY_(x)
/* "0.1.0" */
#define FG_VERSION_STRING                                                            \
    FG_VERSION_STRINGIFY(FG_VERSION_MAJOR) "." FG_VERSION_STRINGIFY(FG_VERSION_MINOR) "." \
    FG_VERSION_STRINGIFY(FG_VERSION_PATCH)

/* The library's name and version, "fulgur 0.1.0", as libsndfile's
 * sf_version_string() and Opus's opus_get_version_string() give theirs.
 * Never NULL; the string is static. [any-thread] */
FG_API const char *fg_version_string(void);

#ifdef __cplusplus
}
#endif

#endif
