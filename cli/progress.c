/* Progress of long work on stderr: only when stderr is a terminal, and only
 * once the work has taken more than a second (quick runs stay quiet). */
#include "cli.h"

#include <stdio.h>
#include <time.h>
#include <unistd.h>

static struct timespec t0;
static int started, shown;

void cli_progress(const char *what, double frac)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    if (!started) {
        started = 1, t0 = t;
        return;
    }
    if ((double)(t.tv_sec - t0.tv_sec) + 1e-9 * (double)(t.tv_nsec - t0.tv_nsec) > 1 && isatty(2)) {
        fprintf(stderr, "\rnoiselab %s: %3.0f%% ", what, 100 * frac);
        shown = 1;
    }
}

void cli_progress_done(void)
{
    if (shown)
        fprintf(stderr, "\r%60s\r", "");
    started = shown = 0;
}
