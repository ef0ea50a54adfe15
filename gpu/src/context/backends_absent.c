/* The backends this build was configured without. */
#include "gpu_internal.h"

#ifndef FGG_HAVE_OSMESA
const fgg_backend_ops *const fgg_osmesa_backend = NULL;
#endif
#ifndef FGG_HAVE_WINDOW
const fgg_backend_ops *const fgg_window_backend = NULL;
#endif
