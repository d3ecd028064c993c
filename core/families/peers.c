/* The peers' keys that many aliases share (core/family.h,
 * nl_family_alias): gstat's vgm(psill, model, range, nugget) and GSTools'
 * CovModel(var, len_scale, nugget); gstat's anisotropy angle. */
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

/* gstat's vgm(..., anis = c(p, s)) in 2D (Pebesma 2004; gstat's ?vgm):
 * the range applies along the major axis, p degrees clockwise from +y
 * (north) towards +x, and s times it along the minor axis.  noiselab's
 * angle turns the major axis (where `scale` applies) from +x towards +y
 * (core/model_eval.c rotates the lag by -angle), ratio the minor's length
 * over the major's: angle = 90 - p, ratio = s.  So Sph:...,angle=30,ratio=0.5
 * is spherical:...,angle=60,ratio=0.5, and with ratio alone gstat's p = 0
 * (the major axis north) is angle=90.  gstat's 3D anis (five numbers) has
 * no counterpart: zratio stays noiselab's. */
void nl_peer_gstat_anis(nl_model *m)
{
    if (m->aniso_given)
        m->angle = M_PI / 2 - m->angle;
}
