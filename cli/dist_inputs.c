/* The analysis commands' distributed runs: the shared steps. */
#include "dist_inputs.h"
#include "../core/nl_error.h"

int cli_dist_wanted(const cli_inputs *in, const char *cmd)
{
    if (!cli_h5 || !cli_h5->launched || !cli_h5->read_slab)
        return 0;
    if (!in->K && in->count == 1 && cli_is_h5(in->files[0]))
        return 1;
    /* every process would read and analyse whole fields */
    if (cli_h5->size > 1)
        cli_die(2, "%s: %s is not distributed; under mpirun with %d processes expected one .h5 input, or run on one "
                "process", cmd, in->K ? "--realizations" : in->count > 1 ? "an ensemble of inputs" : "an input not .h5",
                cli_h5->size);
    return 0;
}

void cli_dist_refuse(const char *cmd, const char *opt)
{
    cli_die(2, "%s: %s is not available in a distributed run (mpirun with an .h5 input); expected a run without it, "
            "or one process", cmd, opt);
}

void cli_dist_read(const cli_inputs *in, cli_slab *s, nl_field *header)
{
    cli_check(cli_h5->read_slab(in->files[0], s));
    *header = (nl_field){.dim = s->dim, .n = {s->n[0], s->n[1], s->n[2]}, .h = {s->h[0], s->h[1], s->h[2]}};
    header->count = s->n[0] * s->n[1] * s->n[2];
}

void cli_dist_check(const cli_inputs *in, int st)
{
    if (st)
        cli_die(nl_error_is_input(st) ? 2 : 1, "%s: %s", in->files[0], nl_errmsg());
}

void cli_dist_free(cli_slab *s) { cli_h5->slab_free(s); }

int cli_dist_leader(void) { return cli_h5->rank == 0; }
