/* FFTW planner flags, threads and the wisdom cache (see fftw_plan.h). */
#include "fftw_plan.h"

#include <fftw3.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static int ready, measured;
static char cache[4096];

/* $XDG_CACHE_HOME/noiselab (or $HOME/.cache/noiselab); "" when neither is set. */
static void cache_path(void)
{
    const char *x = getenv("XDG_CACHE_HOME"), *h = getenv("HOME");
    char dir[3072];
    cache[0] = 0;
    if (x && *x)
        snprintf(dir, sizeof dir, "%s/noiselab", x);
    else if (h && *h)
        snprintf(dir, sizeof dir, "%s/.cache/noiselab", h);
    else
        return;
    snprintf(cache, sizeof cache, "%s/fftw-wisdom", dir);
}

#ifndef NL_WISDOM_FILE
#define NL_WISDOM_FILE "/usr/local/share/noiselab/fftw-wisdom"
#endif

/* Measured wisdom, later sources adding to earlier ones: FFTW's system
 * wisdom (/etc/fftw/wisdom, from fftw-wisdom), the wisdom installed with
 * noiselab (make wisdom), $NOISELAB_WISDOM, the user's cache.  A missing or
 * foreign file (another FFTW) is skipped.  None under NOISELAB_FFTW=estimate. */
static void setup(void)
{
    const char *extra = getenv("NOISELAB_WISDOM"), *e = getenv("NOISELAB_FFTW");
    ready = 1;
    fftw_init_threads();
    fftw_make_planner_thread_safe();
    cache_path();
    if (e && strcmp(e, "estimate") == 0)
        return;
    fftw_import_system_wisdom();
    fftw_import_wisdom_from_filename(NL_WISDOM_FILE);
    if (extra && *extra)
        fftw_import_wisdom_from_filename(extra);
    if (cache[0])
        fftw_import_wisdom_from_filename(cache);
}

int nl_threads_max(void)
{
    long cpus = sysconf(_SC_NPROCESSORS_ONLN);
    int cap = cpus > 0 && cpus < 1024 ? (int)cpus * NL_THREADS_PER_CPU : 1024 * NL_THREADS_PER_CPU;
    int want = omp_get_max_threads();
    return want < 1 ? 1 : want < cap ? want : cap;
}

/* FFTW_ESTIMATE takes a measured plan from wisdom when there is one (the
 * planner accepts wisdom of equal or greater rigour), so the default costs
 * no planning time and still runs measured plans wherever they exist. */
unsigned nl_fftw_flags(size_t count)
{
    const char *e = getenv("NOISELAB_FFTW");
    int measure = e && strcmp(e, "measure") == 0;
    if (!ready)
        setup();
    /* threads pay off only on large transforms; on small ones their start-up
     * and, when processes share the cores, their spinning cost more */
    fftw_plan_with_nthreads(count >= NL_FFTW_THREADS_MIN ? nl_threads_max() : 1);
    measured |= measure;
    return measure ? FFTW_MEASURE : FFTW_ESTIMATE;
}

void nl_fftw_save(void)
{
    char dir[4096], tmp[4200], *slash;
    if (!measured || !cache[0])
        return;
    snprintf(dir, sizeof dir, "%s", cache);
    if ((slash = strrchr(dir, '/')))
        *slash = 0;
    /* create $XDG_CACHE_HOME and its noiselab folder if missing */
    for (char *p = dir + 1; *p; p++)
        if (*p == '/') {
            *p = 0;
            mkdir(dir, 0755);
            *p = '/';
        }
    mkdir(dir, 0755);
    snprintf(tmp, sizeof tmp, "%s.%ld", cache, (long)getpid());
    if (fftw_export_wisdom_to_filename(tmp))
        rename(tmp, cache);
    else
        unlink(tmp);
    measured = 0;
}
