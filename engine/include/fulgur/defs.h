/* fulgur — common definitions: export macro, result attribute, thread tags,
 * and the rules every public call follows.
 *
 * Thread tags. Every public function names the one thread it may be called
 * from; the tags mean exactly this:
 *
 *   [main-thread]  creation, destruction and configuration. Never concurrent
 *                  with any other call on the same object.
 *   [sim-thread]   the single producer: the one thread that posts discharges
 *                  and collects finished voices. It may allocate and block.
 *   [audio-thread] the host's device callback. Wait-free and bounded: never
 *                  allocates, frees, locks, sleeps, prints or does I/O.
 *   [any-thread]   lock-free for the audio thread; callable from any thread.
 *                  Where calls from several threads must not overlap, the
 *                  function says so.
 *   [gpu-thread]   the thread that owns the GL context (gpu/ only).
 *
 * Names. A struct the caller fills to set up an object or a call ends in
 * _config; a struct a call fills to say what it did ends in _report. Pairs
 * of verbs: create/destroy, post/collect, set/get.
 *
 * Defaults. Zero in a field of a _config means the default given in its
 * comment. fg_X_config_resolve(in, out), where a struct has one, writes the
 * values a call will use (or returns the error it would); fg_X_get_config
 * returns those an object uses.
 *
 * NULL and programmer errors. A call that returns fg_result answers a NULL
 * argument it needs with FG_ERR_NULL and changes nothing. A call that
 * cannot report (a getter, a void function, a count) treats a NULL handle
 * or output pointer as a programmer error: an assert in Debug and test
 * builds; in a release build it returns without effect (0 or NULL for a
 * value). destroy(NULL) is a no-op.
 */
#ifndef FULGUR_DEFS_H
#define FULGUR_DEFS_H

#if defined(FULGUR_BUILDING_SHARED) && defined(__GNUC__)
#define FG_API __attribute__((visibility("default")))
#else
#define FG_API
#endif

#if defined(__GNUC__)
#define FG_NODISCARD __attribute__((warn_unused_result))
#else
#define FG_NODISCARD
#endif

#endif
