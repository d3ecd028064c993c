/* Progress of long work on stderr: only when stderr is a terminal, and only
 * once the work has taken more than a second (quick runs stay quiet;
 * NOISELAB_PROGRESS_AFTER sets another number of seconds).
 * Fractions are printed by the caller's thread; phases of unknown length
 * by a helper thread that refreshes the elapsed time four times a second. */
#include "cli.h"

#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include <unistd.h>

static struct timespec t0;
static int started;
static volatile sig_atomic_t shown;

static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
static pthread_cond_t wake = PTHREAD_COND_INITIALIZER;
static pthread_t ticker;
static int ticking, stop;
static char line[160];

static double elapsed(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)(t.tv_sec - t0.tv_sec) + 1e-9 * (double)(t.tv_nsec - t0.tv_nsec);
}

/* Seconds of work before progress shows. */
static double after(void)
{
    const char *e = getenv("NOISELAB_PROGRESS_AFTER");
    char *end;
    double a = e ? strtod(e, &end) : 1;
    return e && end != e && a >= 0 ? a : 1;
}

static void start(void)
{
    if (!started)
        started = 1, clock_gettime(CLOCK_MONOTONIC, &t0);
}

void cli_progress(const char *what, double frac)
{
    int first = !started;
    start();
    if (!first && elapsed() > after() && isatty(2)) {
        fprintf(stderr, "\rnoiselab %s: %3.0f%% ", what, 100 * frac);
        shown = 1;
    }
}

static void *tick(void *arg)
{
    (void)arg;
    pthread_mutex_lock(&lock);
    while (!stop) {
        struct timespec t;
        double e = elapsed();
        if (e > after()) {
            fprintf(stderr, "\r%s (%.0f s)   ", line, e);
            shown = 1;
        }
        clock_gettime(CLOCK_REALTIME, &t);
        t.tv_nsec += 250000000L;
        if (t.tv_nsec >= 1000000000L)
            t.tv_sec++, t.tv_nsec -= 1000000000L;
        pthread_cond_timedwait(&wake, &lock, &t);
    }
    pthread_mutex_unlock(&lock);
    return NULL;
}

void cli_phase(const char *what, const char *phase)
{
    if (!isatty(2))
        return;
    start();
    pthread_mutex_lock(&lock);
    if (shown)
        fprintf(stderr, "\r%*s\r", (int)sizeof line, "");
    snprintf(line, sizeof line, "noiselab %s: %s", what, phase);
    pthread_mutex_unlock(&lock);
    if (!ticking) {
        stop = 0;
        ticking = pthread_create(&ticker, NULL, tick, NULL) == 0;
    }
}

void cli_progress_done(void)
{
    if (ticking) {
        pthread_mutex_lock(&lock);
        stop = 1;
        pthread_cond_signal(&wake);
        pthread_mutex_unlock(&lock);
        pthread_join(ticker, NULL);
        ticking = 0;
    }
    if (shown)
        fprintf(stderr, "\r%*s\r", (int)sizeof line, "");
    started = shown = 0;
}

void cli_progress_abandon(void)
{
    static const char blank[] = "                                                                                ";
    /* as cli_progress_done: a line of sizeof line blanks between two returns */
    if (shown && (write(2, "\r", 1) < 0 || write(2, blank, sizeof blank - 1) < 0 ||
                  write(2, blank, sizeof line - (sizeof blank - 1)) < 0 || write(2, "\r", 1) < 0))
        shown = 0;
}
