/* The interposer behind rt_guard.h.
 *
 * Definitions here take precedence over the C library's for the whole
 * process (the executable is searched first), including calls made from
 * inside libc and from the statically linked engine.
 *
 * Where each call goes on:
 *  - a sanitizer runtime (TSan, ASan) defines its interceptors as weak
 *    aliases of the libc names plus strong __interceptor_<name> symbols
 *    (compiler-rt's naming up to LLVM 16); ours override the aliases, so we
 *    forward to __interceptor_<name> when it is linked in, keeping the
 *    sanitizer's view of memory and synchronisation intact;
 *  - otherwise malloc/calloc/realloc/free go to glibc's __libc_* entry
 *    points (dlsym itself calls calloc, so these cannot be looked up), and
 *    every other function to dlsym(RTLD_NEXT, name), resolved by a
 *    constructor before main, i.e. before any thread can be armed.
 * This file is compiled without sanitizers: its wrappers run before a
 * sanitizer runtime has started. The names with leading underscores are
 * the runtimes', not ours. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <execinfo.h>
#include <fcntl.h>
#include <link.h>
#include <malloc.h>
#include <pthread.h>
#include <sched.h>
#include <semaphore.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/uio.h>
#include <threads.h>
#include <time.h>
#include <unistd.h>

#include "rt_guard.h"

enum kind { KIND_ALLOC, KIND_LOCK, KIND_IO, KIND_SLEEP };

static _Thread_local bool armed;
static _Thread_local rt_guard_counts counted;
/* rt_guard_arm_within: the object's address range; [0, 0) for everything */
static _Thread_local uintptr_t scope_lo, scope_hi;
static _Thread_local bool walking; /* in backtrace(): its own calls are ours */

void rt_guard_arm(void)
{
    counted = (rt_guard_counts){0};
    scope_lo = scope_hi = 0;
    armed = true;
}

typedef struct object_range {
    uintptr_t code, lo, hi;
} object_range;

/* dl_iterate_phdr's callback: the span of the PT_LOAD segments of the
 * object holding range->code. */
static int find_object(struct dl_phdr_info *info, size_t size, void *data)
{
    (void)size;
    object_range *r = data;
    uintptr_t lo = UINTPTR_MAX, hi = 0;
    for (int i = 0; i < info->dlpi_phnum; i++) {
        const ElfW(Phdr) *ph = &info->dlpi_phdr[i];
        if (ph->p_type != PT_LOAD)
            continue;
        uintptr_t a = info->dlpi_addr + ph->p_vaddr, b = a + ph->p_memsz;
        lo = a < lo ? a : lo;
        hi = b > hi ? b : hi;
    }
    if (r->code < lo || r->code >= hi)
        return 0;
    r->lo = lo;
    r->hi = hi;
    return 1;
}

int rt_guard_arm_within(const void *code)
{
    object_range r = {(uintptr_t)code, 0, 0};
    dl_iterate_phdr(find_object, &r);
    if (r.hi == 0)
        return -1;
    /* backtrace() loads its unwinder at the first call: here, unarmed */
    void *warm[4];
    backtrace(warm, 4);
    rt_guard_arm();
    scope_lo = r.lo;
    scope_hi = r.hi;
    return 0;
}

/* Whether the calling stack passes through the scope's object. */
static bool from_scope(void)
{
    if (scope_hi == 0)
        return true;
    if (walking)
        return false;
    walking = true;
    void *frames[128];
    int n = backtrace(frames, 128);
    walking = false;
    for (int i = 0; i < n; i++)
        if ((uintptr_t)frames[i] >= scope_lo && (uintptr_t)frames[i] < scope_hi)
            return true;
    return false;
}

rt_guard_counts rt_guard_disarm(void)
{
    armed = false;
    return counted;
}

unsigned long rt_guard_total(const rt_guard_counts *c)
{
    return c->alloc + c->lock + c->io + c->sleep;
}

static void note(enum kind kind, const char *name)
{
    if (!armed || !from_scope())
        return;
    unsigned long *slot[] = {&counted.alloc, &counted.lock, &counted.io, &counted.sleep};
    ++*slot[kind];
    if (!counted.first)
        counted.first = name;
}

static void *find_next(const char *name)
{
    void *f = dlsym(RTLD_NEXT, name);
    if (!f)
        abort();
    return f;
}

/* Declares next_<name>(), returning the function a call to name goes on to;
 * a constructor resolves it before main. */
#define FORWARD(ret, name, params)                                                  \
    extern ret __interceptor_##name params __attribute__((weak));                 \
    static ret(*real_##name) params;                                               \
    static ret(*next_##name(void)) params                                          \
    {                                                                              \
        if (__interceptor_##name)                                                  \
            return __interceptor_##name;                                           \
        if (!real_##name)                                                          \
            real_##name = (ret(*) params)find_next(#name);                         \
        return real_##name;                                                        \
    }                                                                              \
    __attribute__((constructor)) static void resolve_##name(void)                  \
    {                                                                              \
        (void)next_##name();                                                       \
    }

/* The same for the allocator, whose fallback is glibc's __libc_<name>. */
#define FORWARD_LIBC(ret, name, params)                                             \
    extern ret __interceptor_##name params __attribute__((weak));                 \
    extern ret __libc_##name params;                                               \
    static ret(*next_##name(void)) params                                          \
    {                                                                              \
        return __interceptor_##name ? __interceptor_##name : __libc_##name;        \
    }

/* ---- allocation ---- */

FORWARD_LIBC(void *, malloc, (size_t))
FORWARD_LIBC(void *, calloc, (size_t, size_t))
FORWARD_LIBC(void *, realloc, (void *, size_t))
FORWARD_LIBC(void, free, (void *))
FORWARD(void *, aligned_alloc, (size_t, size_t))
FORWARD(int, posix_memalign, (void **, size_t, size_t))
FORWARD(void *, memalign, (size_t, size_t))

void *malloc(size_t size)
{
    note(KIND_ALLOC, "malloc");
    return next_malloc()(size);
}

void *calloc(size_t n, size_t size)
{
    note(KIND_ALLOC, "calloc");
    return next_calloc()(n, size);
}

void *realloc(void *p, size_t size)
{
    note(KIND_ALLOC, "realloc");
    return next_realloc()(p, size);
}

void free(void *p)
{
    note(KIND_ALLOC, "free");
    next_free()(p);
}

void *aligned_alloc(size_t alignment, size_t size)
{
    note(KIND_ALLOC, "aligned_alloc");
    return next_aligned_alloc()(alignment, size);
}

int posix_memalign(void **out, size_t alignment, size_t size)
{
    note(KIND_ALLOC, "posix_memalign");
    return next_posix_memalign()(out, alignment, size);
}

void *memalign(size_t alignment, size_t size)
{
    note(KIND_ALLOC, "memalign");
    return next_memalign()(alignment, size);
}

/* ---- locks and waits ---- */

/* A wrapper taking one pointer argument and returning int. */
#define WRAP_INT1(kind, name, type)         \
    FORWARD(int, name, (type))              \
    int name(type a)                        \
    {                                       \
        note(kind, #name);                  \
        return next_##name()(a);            \
    }

/* The same with two arguments. */
#define WRAP_INT2(kind, name, type1, type2) \
    FORWARD(int, name, (type1, type2))      \
    int name(type1 a, type2 b)              \
    {                                       \
        note(kind, #name);                  \
        return next_##name()(a, b);         \
    }

WRAP_INT1(KIND_LOCK, pthread_mutex_lock, pthread_mutex_t *)
WRAP_INT1(KIND_LOCK, pthread_mutex_trylock, pthread_mutex_t *)
WRAP_INT2(KIND_LOCK, pthread_mutex_timedlock, pthread_mutex_t *, const struct timespec *)
WRAP_INT1(KIND_LOCK, pthread_rwlock_rdlock, pthread_rwlock_t *)
WRAP_INT1(KIND_LOCK, pthread_rwlock_wrlock, pthread_rwlock_t *)
WRAP_INT1(KIND_LOCK, pthread_rwlock_tryrdlock, pthread_rwlock_t *)
WRAP_INT1(KIND_LOCK, pthread_rwlock_trywrlock, pthread_rwlock_t *)
WRAP_INT1(KIND_LOCK, pthread_spin_lock, pthread_spinlock_t *)
WRAP_INT1(KIND_LOCK, pthread_spin_trylock, pthread_spinlock_t *)
WRAP_INT2(KIND_LOCK, pthread_cond_wait, pthread_cond_t *, pthread_mutex_t *)
WRAP_INT1(KIND_LOCK, sem_wait, sem_t *)
WRAP_INT1(KIND_LOCK, sem_trywait, sem_t *)
WRAP_INT2(KIND_LOCK, sem_timedwait, sem_t *, const struct timespec *)
WRAP_INT1(KIND_LOCK, mtx_lock, mtx_t *)
WRAP_INT1(KIND_LOCK, mtx_trylock, mtx_t *)
WRAP_INT2(KIND_LOCK, mtx_timedlock, mtx_t *, const struct timespec *)
WRAP_INT2(KIND_LOCK, cnd_wait, cnd_t *, mtx_t *)

FORWARD(int, pthread_cond_timedwait, (pthread_cond_t *, pthread_mutex_t *, const struct timespec *))
int pthread_cond_timedwait(pthread_cond_t *c, pthread_mutex_t *m, const struct timespec *t)
{
    note(KIND_LOCK, "pthread_cond_timedwait");
    return next_pthread_cond_timedwait()(c, m, t);
}

FORWARD(int, cnd_timedwait, (cnd_t *, mtx_t *, const struct timespec *))
int cnd_timedwait(cnd_t *c, mtx_t *m, const struct timespec *t)
{
    note(KIND_LOCK, "cnd_timedwait");
    return next_cnd_timedwait()(c, m, t);
}

/* ---- sleeping ---- */

WRAP_INT2(KIND_SLEEP, nanosleep, const struct timespec *, struct timespec *)

FORWARD(int, clock_nanosleep, (clockid_t, int, const struct timespec *, struct timespec *))
int clock_nanosleep(clockid_t clock, int flags, const struct timespec *t, struct timespec *rem)
{
    note(KIND_SLEEP, "clock_nanosleep");
    return next_clock_nanosleep()(clock, flags, t, rem);
}

FORWARD(int, usleep, (useconds_t))
int usleep(useconds_t us)
{
    note(KIND_SLEEP, "usleep");
    return next_usleep()(us);
}

FORWARD(unsigned, sleep, (unsigned))
unsigned sleep(unsigned s)
{
    note(KIND_SLEEP, "sleep");
    return next_sleep()(s);
}

FORWARD(int, sched_yield, (void))
int sched_yield(void)
{
    note(KIND_SLEEP, "sched_yield");
    return next_sched_yield()();
}

/* ---- I/O ---- */

FORWARD(ssize_t, write, (int, const void *, size_t))
ssize_t write(int fd, const void *buf, size_t n)
{
    note(KIND_IO, "write");
    return next_write()(fd, buf, n);
}

FORWARD(ssize_t, read, (int, void *, size_t))
ssize_t read(int fd, void *buf, size_t n)
{
    note(KIND_IO, "read");
    return next_read()(fd, buf, n);
}

FORWARD(ssize_t, writev, (int, const struct iovec *, int))
ssize_t writev(int fd, const struct iovec *iov, int n)
{
    note(KIND_IO, "writev");
    return next_writev()(fd, iov, n);
}

FORWARD(int, open, (const char *, int, ...))
int open(const char *path, int flags, ...)
{
    note(KIND_IO, "open");
    mode_t mode = 0;
    if ((flags & O_CREAT) || (flags & O_TMPFILE) == O_TMPFILE) {
        va_list ap;
        va_start(ap, flags);
        mode = va_arg(ap, mode_t);
        va_end(ap);
    }
    return next_open()(path, flags, mode);
}

FORWARD(FILE *, fopen, (const char *, const char *))
FILE *fopen(const char *path, const char *mode)
{
    note(KIND_IO, "fopen");
    return next_fopen()(path, mode);
}

FORWARD(size_t, fwrite, (const void *, size_t, size_t, FILE *))
size_t fwrite(const void *p, size_t size, size_t n, FILE *f)
{
    note(KIND_IO, "fwrite");
    return next_fwrite()(p, size, n, f);
}

WRAP_INT2(KIND_IO, fputs, const char *, FILE *)
WRAP_INT2(KIND_IO, fputc, int, FILE *)
WRAP_INT1(KIND_IO, puts, const char *)
WRAP_INT1(KIND_IO, fflush, FILE *)
WRAP_INT2(KIND_IO, vprintf, const char *, va_list)

FORWARD(int, vfprintf, (FILE *, const char *, va_list))
int vfprintf(FILE *f, const char *format, va_list ap)
{
    note(KIND_IO, "vfprintf");
    return next_vfprintf()(f, format, ap);
}

int printf(const char *format, ...)
{
    note(KIND_IO, "printf");
    va_list ap;
    va_start(ap, format);
    int n = next_vprintf()(format, ap);
    va_end(ap);
    return n;
}

int fprintf(FILE *f, const char *format, ...)
{
    note(KIND_IO, "fprintf");
    va_list ap;
    va_start(ap, format);
    int n = next_vfprintf()(f, format, ap);
    va_end(ap);
    return n;
}
