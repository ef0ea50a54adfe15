/* The two rules every public call of the project follows, written once.
 *
 * Defaults: in a settings struct, zero in a field means the default given
 * in its comment; the one function that resolves the struct fills each
 * field with FG_DEF (after sokol's _saudio_def).
 *
 * Programmer errors: a call that returns a result code answers a NULL
 * argument with FG_ERR_NULL; a call that cannot report (a getter, a void
 * function) treats a NULL handle or output pointer as a programmer error
 * with FG_REQUIRE: an assert in Debug and test builds; in a release build
 * it returns without effect (FG_REQUIRE_OR: with the value given).
 * destroy(NULL) is a no-op and needs neither. */
#ifndef FG_RULES_H
#define FG_RULES_H

#include <assert.h>

/* val, or def where val is zero (def is evaluated only then). */
#define FG_DEF(val, def) ((val) == 0 ? (def) : (val))

/* In a void function: returns at once if cond is false. */
#define FG_REQUIRE(cond)   \
    do {                   \
        assert(cond);      \
        if (!(cond))       \
            return;        \
    } while (0)

/* In a function returning a value: returns value at once if cond is false. */
#define FG_REQUIRE_OR(cond, value) \
    do {                           \
        assert(cond);              \
        if (!(cond))               \
            return (value);        \
    } while (0)

#endif
