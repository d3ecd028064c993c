/* Option values shared by `noiselab synth` and `noiselab validate`. */
#include "synth.h"

#include <limits.h>
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
