/* Running R with gstat from the tests. */
#include "gstat.h"
#include "util.h"

#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

int gstat_available(const char *what)
{
    /* whether it is installed, without loading it (a second second of R per test) */
    if (system("Rscript -e 'quit(status = system.file(package = \"gstat\") == \"\")' >/dev/null 2>&1") == 0)
        return 1;
    fprintf(stderr, "skip: %s: Rscript with gstat is not installed (Debian: r-cran-gstat)\n", what);
    return 0;
}

long gstat_run(const char *script, double *v, size_t max)
{
    char path[512], cmd[1024];
    /* one script per process: tests running at once may share the directory */
    snprintf(path, sizeof path, "%s/gstat-%ld.R", scratch_dir(), (long)getpid());
    FILE *f = fopen(path, "w");
    if (!f)
        return -1;
    fputs(script, f);
    fclose(f);
    snprintf(cmd, sizeof cmd, "cd %s && Rscript %s 2>/dev/null", scratch_dir(), path);
    FILE *p = popen(cmd, "r");
    if (!p)
        return -1;
    size_t n = 0;
    while (n < max && fscanf(p, "%lf", &v[n]) == 1)
        n++;
    /* read to the end: R stopped by a closed pipe would fail the run */
    while (fgetc(p) != EOF)
        ;
    return pclose(p) == 0 ? (long)n : -1;
}

void gstat_write_points(const char *path, int dim, size_t n, const double *pts, const double *val)
{
    static const char *names[] = {"x", "y", "z"};
    FILE *f = fopen(path, "w");
    if (!f)
        return;
    for (int k = 0; k < dim; k++)
        fprintf(f, "%s\t", names[k]);
    fprintf(f, "value\n");
    for (size_t i = 0; i < n; i++) {
        for (int k = 0; k < dim; k++)
            fprintf(f, "%.17g\t", pts[i * dim + k]);
        fprintf(f, "%.17g\n", val[i]);
    }
    fclose(f);
}
