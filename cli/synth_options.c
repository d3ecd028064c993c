/* Option values shared by `noiselab synth` and `noiselab validate`. */
#include "synth.h"
#include "../synth/subdiv.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

int cli_synth_parse_int(const char *opt, const char *s, int min, int max)
{
    size_t v = cli_parse_count(opt, s, (size_t)min);
    if (v > (size_t)max)
        cli_die(2, "%s: expected %d to %d, got \"%s\"", opt, min, max, s);
    return (int)v;
}

int cli_synth_parse_neighborhood(const char *s)
{
    return strcmp(s, "auto") == 0 ? 0 : cli_synth_parse_int("--neighborhood", s, 1, INT_MAX);
}

double cli_synth_parse_tol(const char *opt, const char *s, int *rule)
{
    static const struct {
        const char *prefix;
        int rule;
    } rules[] = {{"variance:", NL_SUBDIV_STOP_VARIANCE}, {"improvement:", NL_SUBDIV_STOP_IMPROVEMENT}};
    char *end;
    double v;
    const char *num = s;
    *rule = NL_SUBDIV_STOP_IMPROVEMENT;
    for (size_t i = 0; i < sizeof rules / sizeof *rules; i++)
        if (strncmp(s, rules[i].prefix, strlen(rules[i].prefix)) == 0) {
            *rule = rules[i].rule;
            num = s + strlen(rules[i].prefix);
            break;
        }
    errno = 0;
    v = strtod(num, &end);
    if (end == num || *end || errno || !isfinite(v) || !(v > 0))
        cli_die(2, "%s: expected a positive number, variance:NUMBER or improvement:NUMBER, got \"%s\"", opt, s);
    return v;
}
