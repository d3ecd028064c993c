/* The slab byte estimates against what executing a slab takes: the peak
 * resident set while it runs (Linux: /proc/self/clear_refs resets VmHWM to
 * the current VmRSS; the peak afterwards less the resident set before).
 * The estimate must bound it (plus 3 MiB for the threads OpenMP starts and
 * page granularity) and not be loose by more than 2x: pages the allocator
 * reuses, or reserves but the execute never touches (the impulse arrays'
 * spare capacity), make the measured peak the smaller.  Skipped under
 * AddressSanitizer, whose quarantine keeps freed blocks resident, and where
 * clear_refs cannot be written. */
#include "../core/model.h"
#include "../core/nl_error.h"
#include "../synth/sparse.h"
#include "../synth/subdiv.h"
#include "util.h"

#include <criterion/criterion.h>
#include <stdio.h>
#include <string.h>

#if defined(__SANITIZE_ADDRESS__)
#define UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define UNDER_ASAN 1
#endif
#endif

/* A field of /proc/self/status in bytes (-1 when absent). */
static long status_kb(const char *key)
{
    char line[256];
    long v = -1;
    FILE *fp = fopen("/proc/self/status", "r");
    if (!fp)
        return -1;
    while (fgets(line, sizeof line, fp))
        if (!strncmp(line, key, strlen(key)) && sscanf(line + strlen(key), ":%ld", &v) == 1)
            break;
    fclose(fp);
    return v < 0 ? -1 : v * 1024;
}

/* Reset the peak; 0 when not possible here. */
static int reset_peak(void)
{
    FILE *fp = fopen("/proc/self/clear_refs", "w");
    int ok = fp && fputs("5", fp) >= 0;
    if (fp && fclose(fp))
        ok = 0;
    return ok;
}

static void skip_unless_measurable(void)
{
#ifdef UNDER_ASAN
    cr_skip_test("AddressSanitizer's quarantine keeps freed blocks resident");
#endif
    if (!reset_peak() || status_kb("VmHWM") < 0)
        cr_skip_test("the peak resident set cannot be reset here");
}

static void compare(const char *what, long before, size_t estimate)
{
    long peak = status_kb("VmHWM"), used = peak - before;
    cr_log_info("%s: estimate %zu bytes, measured peak %ld bytes", what, estimate, used);
    cr_assert_leq(used, (long)estimate + (3L << 20), "%s: measured %ld bytes, above the estimate %zu", what, used,
                  estimate);
    cr_assert_geq(2 * used, (long)estimate, "%s: the estimate %zu is over twice the measured %ld", what, estimate,
                  used);
}

Test(slabs, subdiv_bytes_measured)
{
    size_t n[2] = {2048, 2048}, ns[2] = {2048, 512};
    nl_subdiv_options o;
    nl_subdiv_plan *p;
    nl_model *m;
    nl_field *f;
    long before;
    skip_unless_measurable();
    m = test_model("markov:scale=9.1");
    nl_subdiv_options_default(&o);
    o.displacements = NL_SUBDIV_DISP_ERROR;
    cr_assert_eq(nl_subdiv_plan_alloc(m, 2, n, 1.0, &o, &p), NL_OK, "%s", nl_errmsg());
    f = nl_field_alloc(2, ns, NULL, NULL);
    cr_assert_not_null(f);
    memset(f->data, 0, f->count * sizeof *f->data); /* resident before the measurement */
    cr_assert_eq(nl_subdiv_plan_execute_slab(p, 3, 0, f), NL_OK, "%s", nl_errmsg()); /* threads started */
    reset_peak();
    before = status_kb("VmRSS");
    cr_assert_eq(nl_subdiv_plan_execute_slab(p, 3, 701, f), NL_OK, "%s", nl_errmsg());
    compare("subdivision 2048x2048, 512 rows, correlated", before, nl_subdiv_plan_slab_bytes(p, 512));
    nl_field_free(f);
    nl_subdiv_plan_free(p);
    nl_model_free(m);
}

Test(slabs_slow, sparse_bytes_measured)
{
    size_t n[2] = {2048, 2048}, ns[2] = {2048, 512};
    nl_synth_sparse_plan *p;
    nl_model *m;
    nl_field *f;
    long before;
    skip_unless_measurable();
    m = test_model("gauss:scale=3.3");
    cr_assert_eq(nl_synth_sparse_plan_model(m, 2, NULL, SPARSE_OPTS(0, 0, 24.0), &p), NL_OK, "%s", nl_errmsg());
    f = nl_field_alloc(2, ns, NULL, NULL);
    cr_assert_not_null(f);
    memset(f->data, 0, f->count * sizeof *f->data);
    /* no run before: a freed block raises glibc's mmap threshold, and the
     * next run's arrays then reuse resident heap pages, unmeasured */
    reset_peak();
    before = status_kb("VmRSS");
    cr_assert_eq(nl_synth_sparse_execute_slab(p, 3, NL_SYNTH_SPARSE_WRAP, n, 1536, f), NL_OK, "%s", nl_errmsg());
    compare("sparse 2048x2048, 512 rows, wrap", before, nl_synth_sparse_slab_bytes(p, NL_SYNTH_SPARSE_WRAP, n, 512));
    nl_field_free(f);
    nl_synth_sparse_plan_free(p);
    nl_model_free(m);
}
