/* See lv2_fixture.h. */
#include <pthread.h>
#include <stdlib.h>

#include "lv2_fixture.h"

unsigned long lv2_run_guarded(lv2_host *host, uint32_t frames, float *left, float *right)
{
    rt_guard_arm();
    lv2_host_run(host, frames, left, right);
    rt_guard_counts c = rt_guard_disarm();
    return rt_guard_total(&c);
}

typedef struct work_job {
    lv2_host *host;
    unsigned ran;
    unsigned long allocs;
} work_job;

static void *worker_main(void *arg)
{
    work_job *job = arg;
    rt_guard_arm();
    job->ran = lv2_host_work(job->host);
    job->allocs = rt_guard_disarm().alloc;
    return NULL;
}

unsigned lv2_work_on_thread(lv2_host *host, unsigned long *allocs)
{
    work_job job = {host, 0, 0};
    pthread_t thread;
    if (pthread_create(&thread, NULL, worker_main, &job) != 0 || pthread_join(thread, NULL) != 0)
        abort();
    if (allocs)
        *allocs += job.allocs;
    return job.ran;
}
