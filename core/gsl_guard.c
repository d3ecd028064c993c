/* The library's GSL error handler, installed around library calls. */
#include "gsl_guard_internal.h"

#include <gsl/gsl_errno.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>

static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
static atomic_long holders;               /* outermost brackets running, all threads */
static gsl_error_handler_t *saved;        /* the caller's handler, under lock */
static _Thread_local long depth;          /* brackets open in this thread */
static _Thread_local char reason[256];    /* GSL's last reason in this thread */

static void record(const char *why, const char *file, int line, int gsl_errno)
{
    snprintf(reason, sizeof reason, "%s (GSL %s:%d, code %d)", why, file, line, gsl_errno);
}

void nl_gsl_enter(void)
{
    long c;
    if (depth++ > 0)
        return;
    reason[0] = 0;
    /* someone holds the handler already: join without the lock */
    c = atomic_load(&holders);
    while (c > 0)
        if (atomic_compare_exchange_weak(&holders, &c, c + 1))
            return;
    pthread_mutex_lock(&lock);
    /* only a locked enter moves holders from 0, so the handler is in place
     * before anyone can join on the fast path */
    if (atomic_load(&holders) == 0)
        saved = gsl_set_error_handler(record);
    atomic_fetch_add(&holders, 1);
    pthread_mutex_unlock(&lock);
}

void nl_gsl_leave(void)
{
    long c;
    if (--depth > 0)
        return;
    /* not the last holder: leave without the lock */
    c = atomic_load(&holders);
    while (c > 1)
        if (atomic_compare_exchange_weak(&holders, &c, c - 1))
            return;
    pthread_mutex_lock(&lock);
    if (atomic_fetch_sub(&holders, 1) == 1)
        gsl_set_error_handler(saved);
    pthread_mutex_unlock(&lock);
}

const char *nl_gsl_reason(int gsl_status)
{
    return reason[0] ? reason : gsl_strerror(gsl_status);
}
