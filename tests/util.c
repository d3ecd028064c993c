/* Running the CLI from tests and scratch space. */
#include "util.h"
#include "../core/nl_error.h"

#include <criterion/criterion.h>


#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

static void slurp(const char *path, char *buf, size_t len)
{
    FILE *fp = fopen(path, "r");
    size_t n = 0;
    if (fp) {
        n = fread(buf, 1, len - 1, fp);
        fclose(fp);
    }
    buf[n] = 0;
}

const char *scratch_dir(void)
{
    static char dir[256];
    if (!dir[0]) {
        snprintf(dir, sizeof dir, "/tmp/noiselab-test-%ld", (long)getpid());
        mkdir(dir, 0755);
    }
    return dir;
}

int run_noiselab(const char *args, char *out, size_t outlen, char *err, size_t errlen)
{
    const char *bin = getenv("NOISELAB");
    char cmd[4096], fo[300], fe[300];
    int rc;
    snprintf(fo, sizeof fo, "%s/stdout", scratch_dir());
    snprintf(fe, sizeof fe, "%s/stderr", scratch_dir());
    /* error exits leave their memory to exit(): no leak report from the CLI */
    snprintf(cmd, sizeof cmd, "cd %s && ASAN_OPTIONS=detect_leaks=0 %s %s >%s 2>%s", scratch_dir(),
             bin ? bin : "../bin/noiselab", args, fo, fe);
    rc = system(cmd);
    if (out)
        slurp(fo, out, outlen);
    if (err)
        slurp(fe, err, errlen);
    return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

json_t *run_noiselab_json(const char *args)
{
    static char out[1 << 20], err[4096];
    json_error_t je;
    json_t *j;
    cr_assert_eq(run_noiselab(args, out, sizeof out, err, sizeof err), 0, "%s: %s", args, err);
    j = json_loads(out, 0, &je);
    cr_assert(j, "%s: not JSON: %s", args, je.text);
    return j;
}

int file_exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

int count_lines(const char *s)
{
    int n = 0;
    for (; *s; s++)
        n += *s == '\n';
    return n;
}


nl_model *test_model(const char *spec)
{
    nl_model *m = NULL;
    cr_assert_eq(nl_model_parse(spec, &m), NL_OK, "%s: %s", spec, nl_errmsg());
    return m;
}

/* Write TEXT to NAME in the scratch folder; the path is valid until the
 * next call. */
const char *scratch_file(const char *name, const char *text)
{
    static char path[512];
    snprintf(path, sizeof path, "%s/%s", scratch_dir(), name);
    FILE *fp = fopen(path, "w");
    cr_assert_not_null(fp);
    fputs(text, fp);
    fclose(fp);
    return path;
}
