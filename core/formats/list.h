/* The registration list of field formats: one line each, in the order of
 * `noiselab formats` (core/format.h).  NL_FORMAT(id) names the descriptor
 * nl_format_<id> defined in core/formats/<id>.c.  Where two formats share
 * an extension, the first listed wins. */
NL_FORMAT(exr)
NL_FORMAT(tsv)
NL_FORMAT(npy)
NL_FORMAT(npz)
NL_FORMAT(png16)
NL_FORMAT(r16)
NL_FORMAT(f32)
NL_FORMAT(h5)
NL_FORMAT(geotiff)
NL_FORMAT(cog)
NL_FORMAT(netcdf)
NL_FORMAT(vdb)
