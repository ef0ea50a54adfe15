/* fulgur — common definitions: export macro, result attribute, thread tags.
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
