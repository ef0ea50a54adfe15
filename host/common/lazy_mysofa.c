/* libmysofa for the fulgur program, opened on the first call
 * (lazy_library.h): a binaural layout's SOFA file. */
#include <mysofa.h>
#include <pthread.h>

#include "lazy_library.h"

static struct {
    __typeof__(mysofa_load) *load;
    __typeof__(mysofa_check) *check;
    __typeof__(mysofa_getAttribute) *get_attribute;
    __typeof__(mysofa_tocartesian) *tocartesian;
    __typeof__(mysofa_free) *free;
} api;

static pthread_once_t once = PTHREAD_ONCE_INIT;

static void load(void)
{
    const library_symbol symbols[] = {
        LIBRARY_SYMBOL(api.load, mysofa_load),
        LIBRARY_SYMBOL(api.check, mysofa_check),
        LIBRARY_SYMBOL(api.get_attribute, mysofa_getAttribute),
        LIBRARY_SYMBOL(api.tocartesian, mysofa_tocartesian),
        LIBRARY_SYMBOL(api.free, mysofa_free),
    };
    lazy_library_load(FULGUR_MYSOFA_SONAME, symbols, sizeof symbols / sizeof symbols[0]);
}

struct MYSOFA_HRTF *mysofa_load(const char *filename, int *err)
{
    pthread_once(&once, load);
    return api.load(filename, err);
}

int mysofa_check(struct MYSOFA_HRTF *hrtf)
{
    pthread_once(&once, load);
    return api.check(hrtf);
}

char *mysofa_getAttribute(struct MYSOFA_ATTRIBUTE *attr, char *name)
{
    pthread_once(&once, load);
    return api.get_attribute(attr, name);
}

void mysofa_tocartesian(struct MYSOFA_HRTF *hrtf)
{
    pthread_once(&once, load);
    api.tocartesian(hrtf);
}

void mysofa_free(struct MYSOFA_HRTF *hrtf)
{
    pthread_once(&once, load);
    api.free(hrtf);
}
