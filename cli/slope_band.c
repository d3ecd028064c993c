/* Refusing a slope band that reaches where the field's model has no power. */
#include "slope_band.h"
#include "cli.h"
#include "../core/family.h"
#include "../core/model.h"
#include "../core/nl_error.h"

#include <math.h>
#include <string.h>

void cli_slope_band_check(const char *cmd, const char *opt, double f1, double f2, const char *spec, int dim)
{
    const nl_family *fam;
    nl_model *m;
    double lo, hi;
    if (!spec)
        return;
    spec += strspn(spec, " \t");
    if (!*spec)
        return;
    fam = nl_family_find(spec, strcspn(spec, ": \t"));
    /* a recorded image:FILE is data: its file is not opened */
    if (fam && (fam->flags & NL_FAMILY_FILE))
        return;
    if (nl_model_parse(spec, &m))
        return;
    if (nl_model_band(m, dim, &lo, &hi)) {
        nl_model_free(m);
        return;
    }
    nl_model_free(m);
    if (f1 < lo)
        cli_die(2, "%s: %s %g:%g reaches below the field's band: %s has no power below fmin = %.10g; expected F1 >= %.10g",
                cmd, opt, f1, f2, spec, lo, lo);
    if (f2 > hi)
        cli_die(2, "%s: %s %g:%g reaches above the field's band: %s has no power above fmax = %.10g; expected F2 <= %.10g",
                cmd, opt, f1, f2, spec, hi, hi);
}
