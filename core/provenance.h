/* Provenance of a field: how it was made, as a typed record, and its text
 * form, the key/value pairs of nl_meta (core/io.h) that files hold: EXR
 * attributes "noiselab.KEY", HDF5 attributes "KEY" of the dataset, TSV
 * comment lines "# KEY: value".
 *
 * The keys, in the order files record them: model, method, seed, spacing,
 * size, version, flags, origin.  The method string is the synthesis
 * method's own text (its name and options); it is carried here unread.
 *
 * Formatting writes exactly what the writers have always recorded (seed in
 * decimal, size "N[xM[xK]]", spacing "h0[,h1[,h2]]" with %.17g, so that
 * it reads back to the same double, origin "X[,Y[,Z]]" the same way), so parse(format(p))
 * gives p back.  Parsing refuses a value that is not what its key holds
 * with NL_EINPUT and one line naming the key and the value (a file's
 * attributes are input: they may be damaged or hostile).
 *
 * Thread safety: every function is reentrant (no shared state); the
 * caller owns every record. */
#ifndef NL_PROVENANCE_H
#define NL_PROVENANCE_H

#include "io.h"

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The number of keys; key i of nl_meta is nl_meta_key(i), i < this. */
enum { NL_META_NKEYS = 8 };

/* Which keys nl_provenance_parse reads (a bit per key, or'ed). */
enum {
    NL_PROV_MODEL = 1 << 0,   /* model: a spec nl_model_parse accepts (image:FILE unread) */
    NL_PROV_METHOD = 1 << 1,  /* method: any text */
    NL_PROV_SEED = 1 << 2,    /* seed: decimal 0 .. 2^64 - 1 */
    NL_PROV_SPACING = 1 << 3, /* spacing: one positive finite number per axis */
    NL_PROV_SIZE = 1 << 4,    /* size: 1 to 3 counts >= 1, "x" between */
    NL_PROV_VERSION = 1 << 5, /* version: any text */
    NL_PROV_FLAGS = 1 << 6,   /* flags: any text */
    NL_PROV_ORIGIN = 1 << 7,  /* origin: 1 to 3 numbers within +-2^53, "," between */
    NL_PROV_ALL = (1 << 8) - 1
};

/* How a field was made.  Text members are NUL-terminated; "" when not
 * recorded.  Numbers are valid where their has_ or count member says so. */
typedef struct {
    char model[1024];  /* model spec (core/model.h) */
    char method[256];  /* synthesis method and its options: the method's text */
    char flags[256];   /* comma-separated detector flags */
    char version[32];  /* version of the library that made it */
    uint64_t seed;     /* the seed, when has_seed */
    int has_seed;      /* 1: seed recorded */
    int dim;           /* size recorded for 1, 2 or 3 axes; 0: no size */
    size_t n[3];       /* samples per axis, x first (n[dim..2] are 1) */
    int nspacing;      /* spacing values recorded (0: none; else 1 to 3) */
    double h[3];       /* spacing per axis, x first (h[nspacing..2] are 0) */
    int norigin;       /* origin numbers recorded (0: none; else 1 to 3) */
    double origin[3];  /* where sample 0 sits, in samples (times h: length units), x first;
                          integers for a window of a larger field (nl_meta_origin) */
} nl_provenance;

/* "model", "method", ... for i < NL_META_NKEYS, in the files' order; NULL
 * otherwise. */
const char *nl_meta_key(int i);

/* The value of key i in m (a string inside m; NULL for a bad i), and its
 * capacity in bytes, the NUL included (0 for a bad i). */
const char *nl_meta_value(const nl_meta *m, int i);
size_t nl_meta_capacity(int i);

/* The same string, writable (NULL for a bad i): the readers fill it with at
 * most nl_meta_capacity(i) - 1 bytes and a NUL. */
char *nl_meta_slot(nl_meta *m, int i);

/* An empty record: no key recorded (all zero). */
void nl_provenance_init(nl_provenance *p);

/* The key/value pairs of p into kv (zeroed first; keys not recorded stay
 * "").  NL_EINVAL (kv zeroed) when dim, nspacing or norigin is out of
 * range, a spacing is not positive and finite, a count is 0, or a text
 * member is not NUL-terminated; NL_ETOOBIG when a value does not fit its
 * key's capacity. */
int nl_provenance_format(const nl_provenance *p, nl_meta *kv);

/* The keys of kv selected by `keys` (NL_PROV_* or'ed) into p, which is
 * first emptied; keys not selected or empty ("") are not recorded.  Checks,
 * in the order seed, model, size, spacing, origin, then the text keys:
 * each value must be NUL-terminated within its capacity, hold no control
 * character and be what its key holds (see the NL_PROV_* list; a model is
 * parsed and released, except that a model naming a file, image:FILE, is
 * checked for its family and its text only: a record is data, and the
 * file it names is not opened).  Returns
 * NL_OK, or NL_EINPUT (p emptied) with a message of one line naming the
 * key "noiselab.KEY" and quoting the value, or what nl_model_parse returns
 * for a bad model, with its message. */
int nl_provenance_parse(const nl_meta *kv, unsigned keys, nl_provenance *p);

/* Where a field's grid sits, as its record m says: for a dim-D field of
 * n[0..dim-1] samples (x first) whose spacing is h (in: the field's, e.g.
 * nl_field.h), the coordinate of sample 0 per axis into origin (x first,
 * length units), so that sample i of axis a sits at origin[a] + i h[a].
 * From noiselab.origin, in samples: origin[a] = value a times h[a] (axes
 * it does not give: 0).  Files written before maps made on an extent
 * recorded it (krige, synth --condition) say "extent=a:b,..." in
 * noiselab.method instead: their samples are the cell centres, h[a] =
 * (b - a) / n[a] (written back to h) and origin[a] = a + h[a] / 2; so
 * do georeferenced files without noiselab.origin, whose m->extent holds
 * the cell edges "x0:x1,y0:y1" (the GDAL formats).  None recorded: 0.
 * h and origin hold 3 entries (origin's past dim set to 0).  NL_OK, or
 * NL_EINPUT with one line quoting a malformed value. */
int nl_meta_origin(const nl_meta *m, int dim, const size_t *n, double *h, double *origin);

/* Record the grid of a dim-D field in m: noiselab.spacing h and
 * noiselab.origin origin[a] / h[a] (origin x first, in length units, as
 * nl_meta_origin gives it back; a value within 1e-9 of an integer number of
 * samples is written as that integer), both with %.17g.  NL_EINVAL (m
 * unchanged) for dim outside 1..3, a spacing that is not positive and
 * finite or an origin that is not finite; NL_ETOOBIG when they do not fit. */
int nl_meta_set_origin(nl_meta *m, int dim, const double *h, const double *origin);

#ifdef __cplusplus
}
#endif

#endif
