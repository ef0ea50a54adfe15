/* The headless gate between the viewer's frame thread and its audio
 * thread: the audio may render up to the frame thread's target, and the
 * frame thread may wait for the audio to get there; and stopping. The
 * paced (window) audio path never takes the lock. */
#include "view.h"

void view_stop(view *v)
{
    /* under the lock, so a waiter cannot miss it between check and wait */
    pthread_mutex_lock(&v->lock);
    atomic_store(&v->stop, true);
    pthread_cond_broadcast(&v->changed);
    pthread_mutex_unlock(&v->lock);
}

void view_release_audio(view *v, uint64_t target)
{
    pthread_mutex_lock(&v->lock);
    v->audio_target = target;
    pthread_cond_broadcast(&v->changed);
    pthread_mutex_unlock(&v->lock);
}

uint32_t view_wait_target(view *v, uint64_t frames, uint32_t block_frames)
{
    pthread_mutex_lock(&v->lock);
    while (v->audio_target <= frames && !atomic_load(&v->stop))
        pthread_cond_wait(&v->changed, &v->lock);
    uint64_t left = atomic_load(&v->stop) ? 0 : v->audio_target - frames;
    pthread_mutex_unlock(&v->lock);
    return left < block_frames ? (uint32_t)left : block_frames;
}

void view_announce_audio(view *v, uint64_t frames)
{
    pthread_mutex_lock(&v->lock);
    atomic_store(&v->audio_done, frames);
    pthread_cond_broadcast(&v->changed);
    pthread_mutex_unlock(&v->lock);
}

void view_wait_audio(view *v)
{
    pthread_mutex_lock(&v->lock);
    while (atomic_load(&v->audio_done) < v->audio_target && !atomic_load(&v->stop))
        pthread_cond_wait(&v->changed, &v->lock);
    pthread_mutex_unlock(&v->lock);
}
