/* The peers' keys that many aliases share (core/family.h,
 * nl_family_alias): gstat's vgm(psill, model, range, nugget) and GSTools'
 * CovModel(var, len_scale, nugget). */
#include "families_internal.h"

const nl_family_param nl_peer_gstat_params[3] = {NL_PEER_PSILL, NL_PEER_RANGE, NL_PARAM_NUGGET};
const nl_family_param nl_peer_gstools_params[3] = {NL_PARAM_VAR, NL_PEER_LEN_SCALE, NL_PARAM_NUGGET};

void nl_peer_shape_first(const double *q, double *p)
{
    p[0] = q[3];
    p[1] = q[1];
    p[2] = q[0];
    p[3] = q[2];
}
