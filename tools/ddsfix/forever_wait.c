/* LD_PRELOAD shim: a "wait forever" that overflowed waits forever again.
 *
 * Why: the PyPI wheels' Fast DDS was built against glibc 2.28, which has no
 * pthread_cond_clockwait, so its inlined libstdc++ condition_variable turns a
 * wait_until(steady_clock::time_point::max()) into a system_clock deadline.
 * That sum overflows to a negative timespec; glibc's pthread_cond_timedwait
 * then returns EINVAL at once *without releasing the mutex*, and the caller
 * loops.  DomainParticipant::set_listener(nullptr) (rmw_fastrtps's
 * destroy_participant, at every node's shutdown) waits like that for a
 * discovery callback that needs the mutex it holds: the node spins forever
 * and ignores SIGINT/SIGTERM (tools/bench/soak_shutdown.py, "What it found").
 *
 * What: a deadline with tv_sec < 0 or tv_nsec outside [0, 1e9) never comes
 * from a real deadline (all are after 1970); only such an overflow makes one.
 * Wait without a deadline then, as the caller meant; pass every other call to
 * glibc unchanged.  Built by tools/setup_env.sh into the venv (only where the
 * wheels are used) and preloaded by textbook.isolation for every ROS run;
 * tests/tools/test_ddsfix.py checks it.
 *
 * Symbol versions: glibc has two pthread_cond_timedwait, the default
 * GLIBC_2.3.2 (what the wheels and everything newer link to) and the old
 * GLIBC_2.2.5 one with another pthread_cond_t layout.  This unversioned
 * definition takes the place of the default; the real one is looked up by
 * that exact version.
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <pthread.h>
#include <time.h>

typedef int (*timedwait_fn)(pthread_cond_t *, pthread_mutex_t *, const struct timespec *);

static timedwait_fn real_timedwait;

__attribute__((constructor)) static void find_real_timedwait(void)
{
    real_timedwait = (timedwait_fn)dlvsym(RTLD_NEXT, "pthread_cond_timedwait", "GLIBC_2.3.2");
    if (!real_timedwait)
        real_timedwait = (timedwait_fn)dlsym(RTLD_NEXT, "pthread_cond_timedwait");
}

int pthread_cond_timedwait(pthread_cond_t *cond, pthread_mutex_t *mutex,
                           const struct timespec *deadline)
{
    if (deadline->tv_sec < 0 || deadline->tv_nsec < 0 || deadline->tv_nsec >= 1000000000L)
        return pthread_cond_wait(cond, mutex);  /* the overflowed "forever" */
    if (!real_timedwait)
        find_real_timedwait();
    return real_timedwait ? real_timedwait(cond, mutex, deadline) : EINVAL;
}
