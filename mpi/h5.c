/* Fields in HDF5 files: one process (POSIX driver) or collective (MPI-IO). */
#include "h5.h"
#include "dist.h"
#include "../core/mem.h"
#include "../core/nl_error.h"
#include "../core/provenance.h"

#include <hdf5.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void quiet(void) { H5Eset_auto2(H5E_DEFAULT, NULL, NULL); }

/* File access: MPI-IO over comm, or the default driver. */
static hid_t fapl_for(MPI_Comm comm)
{
    hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
    if (fapl >= 0 && comm != MPI_COMM_NULL && H5Pset_fapl_mpio(fapl, comm, MPI_INFO_NULL) < 0) {
        H5Pclose(fapl);
        return -1;
    }
    return fapl;
}

static hid_t dxpl_for(MPI_Comm comm)
{
    hid_t dxpl = H5Pcreate(H5P_DATASET_XFER);
    if (dxpl >= 0 && comm != MPI_COMM_NULL && H5Pset_dxpl_mpio(dxpl, H5FD_MPIO_COLLECTIVE) < 0) {
        H5Pclose(dxpl);
        return -1;
    }
    return dxpl;
}

static int write_attrs(hid_t d, const nl_meta *meta, int processes)
{
    hid_t sp = H5Screate(H5S_SCALAR), a;
    int bad = sp < 0;
    for (int k = 0; meta && !bad && k < NL_META_NKEYS; k++) {
        const char *v = nl_meta_value(meta, k);
        hid_t t;
        if (!*v)
            continue;
        /* variable-length UTF-8: h5py reads them as str */
        t = H5Tcopy(H5T_C_S1);
        bad = t < 0 || H5Tset_size(t, H5T_VARIABLE) < 0 || H5Tset_cset(t, H5T_CSET_UTF8) < 0;
        if (!bad && (a = H5Acreate2(d, nl_meta_key(k), t, sp, H5P_DEFAULT, H5P_DEFAULT)) >= 0) {
            bad = H5Awrite(a, t, &v) < 0;
            H5Aclose(a);
        } else {
            bad = 1;
        }
        if (t >= 0)
            H5Tclose(t);
    }
    if (!bad && (a = H5Acreate2(d, "processes", H5T_STD_I32LE, sp, H5P_DEFAULT, H5P_DEFAULT)) >= 0) {
        bad = H5Awrite(a, H5T_NATIVE_INT, &processes) < 0;
        H5Aclose(a);
    } else {
        bad = 1;
    }
    if (sp >= 0)
        H5Sclose(sp);
    return bad;
}

/* HDF5 dims (slowest first) of a field's n; the slab's start and count. */
static void h5_dims(int dim, const size_t *n, size_t s0, size_t ns, hsize_t *dims, hsize_t *start, hsize_t *count)
{
    for (int a = 0; a < dim; a++) {
        dims[a] = n[dim - 1 - a];
        start[a] = 0;
        count[a] = dims[a];
    }
    start[0] = s0;
    count[0] = ns;
}

static int write_data(hid_t file, MPI_Comm comm, int dim, const size_t *n, size_t s0, size_t ns,
                      const double *slab, const nl_meta *meta, int dbl, int processes)
{
    hsize_t dims[3], start[3], count[3];
    hid_t fs, ms = -1, d = -1, x = -1;
    int bad;
    h5_dims(dim, n, s0, ns, dims, start, count);
    if ((fs = H5Screate_simple(dim, dims, NULL)) < 0)
        return 1;
    d = H5Dcreate2(file, "field", dbl ? H5T_IEEE_F64LE : H5T_IEEE_F32LE, fs, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    bad = d < 0 || write_attrs(d, meta, processes);
    if (!bad) {
        if (ns) {
            ms = H5Screate_simple(dim, count, NULL);
            bad = ms < 0 || H5Sselect_hyperslab(fs, H5S_SELECT_SET, start, NULL, count, NULL) < 0;
        } else {
            /* an empty share: nothing selected on either side (a null
             * dataspace here lets MPI-IO write a stray sample) */
            hsize_t one = 1;
            ms = H5Screate_simple(1, &one, NULL);
            bad = ms < 0 || H5Sselect_none(ms) < 0 || H5Sselect_none(fs) < 0;
        }
    }
    if (!bad) {
        double dummy = 0;
        bad = (x = dxpl_for(comm)) < 0 || H5Dwrite(d, H5T_NATIVE_DOUBLE, ms, fs, x, ns ? slab : &dummy) < 0;
    }
    if (x >= 0) H5Pclose(x);
    if (ms >= 0) H5Sclose(ms);
    if (d >= 0) H5Dclose(d);
    H5Sclose(fs);
    return bad;
}

int nl_mpi_h5_write(const char *path, MPI_Comm comm, int dim, const size_t *n, size_t s0, size_t ns,
                    const double *slab, const nl_meta *meta, int dbl, int processes)
{
    hid_t fapl, file = -1;
    int bad, st = NL_OK;
    quiet();
    if (dim < 1 || dim > 3 || s0 + ns > n[dim - 1] || (ns && !slab))
        st = NL_ERROR(NL_EINVAL, "HDF5: a slab %zu..%zu of a %dD field does not fit it", s0, s0 + ns, dim);
    if (comm != MPI_COMM_NULL && (st = nl_mpi_agree(comm, st)))
        return st;
    if (st)
        return st;
    /* a collective create of files that differ between processes hangs */
    if (comm != MPI_COMM_NULL && (st = nl_mpi_same_file(comm, path, 1)))
        return st;
    fapl = fapl_for(comm);
    /* creating is collective: every process gets the same answer */
    bad = fapl < 0 || (file = H5Fcreate(path, H5F_ACC_TRUNC, H5P_DEFAULT, fapl)) < 0;
    if (fapl >= 0)
        H5Pclose(fapl);
    if (bad)
        return NL_ERROR(NL_EIO, "%s: cannot create the HDF5 file", path);
    bad = write_data(file, comm, dim, n, s0, ns, slab, meta, dbl, processes);
    bad |= H5Fclose(file) < 0;
    st = bad ? NL_ERROR(NL_EIO, "%s: writing the HDF5 file failed", path) : NL_OK;
    return comm != MPI_COMM_NULL ? nl_mpi_agree(comm, st) : st;
}

int nl_mpi_h5_write_field(const char *path, const nl_field *f, const nl_meta *meta, int dbl)
{
    return nl_mpi_h5_write(path, MPI_COMM_NULL, f->dim, f->n, 0, f->n[f->dim - 1], f->data, meta, dbl, 1);
}

int nl_mpi_h5_is_hdf5(const char *path)
{
    static const unsigned char sig[8] = {0x89, 'H', 'D', 'F', '\r', '\n', 0x1a, '\n'};
    unsigned char b[8];
    FILE *fp = fopen(path, "rb");
    int yes = fp && fread(b, 1, 8, fp) == 8 && memcmp(b, sig, 8) == 0;
    if (fp)
        fclose(fp);
    return yes;
}

/* A string attribute's text: UTF-8 (ASCII when cset says so) without
 * control characters, as noiselab writes it. */
static int check_text(const char *path, const char *key, const char *s, size_t len, H5T_cset_t cset)
{
    for (size_t i = 0; i < len;) {
        unsigned char c = (unsigned char)s[i];
        size_t k = c < 0x80 ? 0 : (c & 0xe0) == 0xc0 && c >= 0xc2 ? 1 : (c & 0xf0) == 0xe0 ? 2
                 : (c & 0xf8) == 0xf0 && c <= 0xf4 ? 3 : 4;
        if (c < 0x20 || c == 0x7f)
            return NL_ERROR(NL_EINPUT, "%s: attribute %s: expected text without control characters, got byte "
                            "0x%02x at %zu", path, key, c, i);
        if (k && cset != H5T_CSET_UTF8)
            return NL_ERROR(NL_EINPUT, "%s: attribute %s: expected ASCII text (its encoding), got byte 0x%02x at "
                            "%zu", path, key, c, i);
        for (size_t j = 1; j <= k && k < 4; j++)
            if (i + j >= len || ((unsigned char)s[i + j] & 0xc0) != 0x80)
                k = 4;
        if (k == 4)
            return NL_ERROR(NL_EINPUT, "%s: attribute %s: expected UTF-8 text, got byte 0x%02x at %zu", path,
                            key, c, i);
        i += k + 1;
    }
    return NL_OK;
}

/* A variable-length string attribute into v (capacity cap). */
static int read_vlen(const char *path, const char *key, hid_t a, hid_t t, char *v, size_t cap)
{
    char *s = NULL;
    hid_t mt = H5Tcopy(H5T_C_S1);
    int st = NL_OK;
    if (mt < 0 || H5Tset_size(mt, H5T_VARIABLE) < 0 || H5Tset_cset(mt, H5Tget_cset(t)) < 0 ||
        H5Aread(a, mt, &s) < 0)
        st = NL_ERROR(NL_EINPUT, "%s: attribute %s cannot be read", path, key);
    else if (s && strlen(s) >= cap)
        st = NL_ERROR(NL_EINPUT, "%s: attribute %s: expected at most %zu bytes, got %zu", path, key, cap - 1,
                      strlen(s));
    else if (s && !(st = check_text(path, key, s, strlen(s), H5Tget_cset(t))))
        memcpy(v, s, strlen(s) + 1);
    if (s)
        H5free_memory(s);
    if (mt >= 0)
        H5Tclose(mt);
    return st;
}

/* A fixed-length string attribute into v: its bytes up to the first NUL,
 * and only NULs after it. */
static int read_fixed(const char *path, const char *key, hid_t a, hid_t t, char *v, size_t cap)
{
    size_t size = H5Tget_size(t), len;
    char raw[1024];
    if (size >= cap || size >= sizeof raw)
        return NL_ERROR(NL_EINPUT, "%s: attribute %s: expected at most %zu bytes, got a string of %zu", path, key,
                        cap - 1, size);
    if (H5Aread(a, t, raw) < 0)
        return NL_ERROR(NL_EINPUT, "%s: attribute %s cannot be read", path, key);
    len = strnlen(raw, size);
    for (size_t i = len; i < size; i++)
        if (raw[i])
            return NL_ERROR(NL_EINPUT, "%s: attribute %s: expected one string, got a NUL at byte %zu inside it",
                            path, key, len);
    raw[len] = 0;
    if (check_text(path, key, raw, len, H5Tget_cset(t)))
        return NL_EINPUT;
    memcpy(v, raw, len + 1);
    return NL_OK;
}

/* Whether attribute a holds one element (a scalar dataspace). */
static int is_scalar(hid_t a)
{
    hid_t sp = H5Aget_space(a);
    int yes = sp >= 0 && H5Sget_simple_extent_type(sp) == H5S_SCALAR;
    if (sp >= 0)
        H5Sclose(sp);
    return yes;
}

/* The string attribute key of d, when present, into v: a scalar string
 * (fixed or variable length) of at most cap - 1 bytes, or refused. */
static int read_string(const char *path, hid_t d, const char *key, char *v, size_t cap)
{
    hid_t a, t;
    int st;
    if (H5Aexists(d, key) <= 0)
        return NL_OK;
    if ((a = H5Aopen(d, key, H5P_DEFAULT)) < 0)
        return NL_ERROR(NL_EINPUT, "%s: attribute %s cannot be opened", path, key);
    t = H5Aget_type(a);
    if (t < 0 || H5Tget_class(t) != H5T_STRING || !is_scalar(a))
        st = NL_ERROR(NL_EINPUT, "%s: attribute %s: expected one string (a scalar, as noiselab writes), got %s",
                      path, key, t < 0 || H5Tget_class(t) != H5T_STRING ? "another type" : "several or none");
    else if (H5Tis_variable_str(t) > 0)
        st = read_vlen(path, key, a, t, v, cap);
    else
        st = read_fixed(path, key, a, t, v, cap);
    if (t >= 0)
        H5Tclose(t);
    H5Aclose(a);
    return st;
}

/* The "processes" attribute, when present: one integer >= 1. */
static int check_processes(const char *path, hid_t d)
{
    hid_t a, t;
    long long p = 0;
    int ok;
    if (H5Aexists(d, "processes") <= 0)
        return NL_OK;
    if ((a = H5Aopen(d, "processes", H5P_DEFAULT)) < 0)
        return NL_ERROR(NL_EINPUT, "%s: attribute processes cannot be opened", path);
    t = H5Aget_type(a);
    ok = t >= 0 && H5Tget_class(t) == H5T_INTEGER && is_scalar(a) && H5Aread(a, H5T_NATIVE_LLONG, &p) >= 0 &&
         p >= 1;
    if (t >= 0)
        H5Tclose(t);
    H5Aclose(a);
    return ok ? NL_OK : NL_ERROR(NL_EINPUT, "%s: attribute processes: expected one integer >= 1", path);
}

/* The provenance attributes of d into meta (zeroed first; left zeroed on
 * failure). */
static int read_attrs(const char *path, hid_t d, nl_meta *meta)
{
    int st = NL_OK;
    memset(meta, 0, sizeof *meta);
    for (int k = 0; k < NL_META_NKEYS && !st; k++)
        st = read_string(path, d, nl_meta_key(k), nl_meta_slot(meta, k), nl_meta_capacity(k));
    if (!st)
        st = check_processes(path, d);
    if (st)
        memset(meta, 0, sizeof *meta);
    return st;
}

/* Spacing "h0[,h1[,h2]]" (positive finite numbers); unit when absent. */
static int parse_spacing(const char *path, const char *s, int dim, double *h)
{
    for (int a = 0; a < 3; a++)
        h[a] = 1;
    if (!*s)
        return NL_OK;
    for (int a = 0; a < dim; a++) {
        char *end;
        h[a] = strtod(s, &end);
        if (end == s || !(h[a] > 0) || !isfinite(h[a]))
            return NL_ERROR(NL_EINPUT, "%s: attribute spacing \"%s\": expected positive numbers", path, s);
        s = end;
        if (*s == ',')
            s++;
        else if (a + 1 < dim)
            for (int b = a + 1; b < dim; b++)
                h[b] = h[a];
        if (*s != ',' && a + 1 < dim && *s == 0)
            break;
    }
    return NL_OK;
}

/* /field's samples: numbers (floating point, as noiselab writes, or
 * integers), converted to double by HDF5. */
static int check_type(const char *path, hid_t d)
{
    static const char *names[] = {"integer", "float", "time", "string", "bitfield", "opaque", "compound",
                                  "reference", "enum", "variable-length", "array"};
    hid_t t = H5Dget_type(d);
    H5T_class_t c = t < 0 ? H5T_NO_CLASS : H5Tget_class(t);
    if (t >= 0)
        H5Tclose(t);
    if (c == H5T_FLOAT || c == H5T_INTEGER)
        return NL_OK;
    return NL_ERROR(NL_EINPUT, "%s: /field holds %s samples; expected floating-point numbers (float32 or float64)",
                    path, c >= 0 && c < (H5T_class_t)(sizeof names / sizeof *names) ? names[c] : "unknown");
}

/* Open path's /field: its rank and size (x first). */
static int open_field(const char *path, MPI_Comm comm, hid_t *file, hid_t *d, int *dim, size_t *n)
{
    hid_t fapl = fapl_for(comm), sp;
    hsize_t dims[3];
    int r;
    *file = *d = -1;
    if (fapl < 0)
        return NL_ERROR(NL_EFAIL, "HDF5: cannot set up file access");
    *file = H5Fopen(path, H5F_ACC_RDONLY, fapl);
    H5Pclose(fapl);
    if (*file < 0)
        return NL_ERROR(NL_EINPUT, "%s: not a readable HDF5 file", path);
    if (H5Lexists(*file, "field", H5P_DEFAULT) <= 0 || (*d = H5Dopen2(*file, "field", H5P_DEFAULT)) < 0)
        return NL_ERROR(NL_EINPUT, "%s: no dataset /field; expected a field written by noiselab", path);
    if ((r = check_type(path, *d)))
        return r;
    sp = H5Dget_space(*d);
    r = sp < 0 ? -1 : H5Sget_simple_extent_ndims(sp);
    if (r < 1 || r > 3 || H5Sget_simple_extent_dims(sp, dims, NULL) < 0) {
        if (sp >= 0)
            H5Sclose(sp);
        return NL_ERROR(NL_EINPUT, "%s: /field has rank %d; expected 1, 2 or 3", path, r);
    }
    H5Sclose(sp);
    *dim = r;
    n[0] = n[1] = n[2] = 1;
    for (int a = 0; a < r; a++) {
        n[a] = (size_t)dims[r - 1 - a];
        if (n[a] < 1)
            return NL_ERROR(NL_EINPUT, "%s: /field is empty", path);
    }
    return NL_OK;
}

static int read_rows(const char *path, MPI_Comm comm, hid_t d, int dim, const size_t *n, size_t s0, size_t ns,
                     double *buf)
{
    hsize_t dims[3], start[3], count[3];
    hid_t fs = H5Dget_space(d), ms, x = dxpl_for(comm);
    int bad = fs < 0 || x < 0;
    h5_dims(dim, n, s0, ns, dims, start, count);
    if (ns) {
        ms = H5Screate_simple(dim, count, NULL);
        bad |= ms < 0 || H5Sselect_hyperslab(fs, H5S_SELECT_SET, start, NULL, count, NULL) < 0;
    } else {
        hsize_t one = 1;
        ms = H5Screate_simple(1, &one, NULL);
        bad |= ms < 0 || H5Sselect_none(ms) < 0 || H5Sselect_none(fs) < 0;
    }
    bad = bad || H5Dread(d, H5T_NATIVE_DOUBLE, ms, fs, x, buf) < 0;
    if (ms >= 0) H5Sclose(ms);
    if (fs >= 0) H5Sclose(fs);
    if (x >= 0) H5Pclose(x);
    return bad ? NL_ERROR(NL_EINPUT, "%s: reading /field failed", path) : NL_OK;
}

static int check_finite(const char *path, const double *v, size_t count, size_t offset)
{
    for (size_t i = 0; i < count; i++)
        if (!isfinite(v[i]))
            return NL_ERROR(NL_EINPUT, "%s: sample %zu is %g; expected finite values", path, offset + i, v[i]);
    return NL_OK;
}

int nl_mpi_h5_read(const char *path, nl_field **out, nl_meta *meta)
{
    hid_t file, d;
    nl_meta m;
    size_t n[3];
    double h[3];
    int dim, st;
    *out = NULL;
    quiet();
    st = open_field(path, MPI_COMM_NULL, &file, &d, &dim, n);
    if (!st && !(st = read_attrs(path, d, &m)))
        st = parse_spacing(path, m.spacing, dim, h);
    if (!st && (*out = nl_field_alloc(dim, n, h, &st)) != NULL &&
        !(st = read_rows(path, MPI_COMM_NULL, d, dim, n, 0, n[dim - 1], (*out)->data)))
        st = check_finite(path, (*out)->data, (*out)->count, 0);
    if (d >= 0) H5Dclose(d);
    if (file >= 0) H5Fclose(file);
    if (st) {
        nl_field_free(*out);
        *out = NULL;
    } else if (meta) {
        *meta = m;
    }
    return st;
}

int nl_mpi_h5_read_meta(const char *path, nl_meta *meta)
{
    hid_t file, d;
    size_t n[3];
    int dim, st;
    quiet();
    st = open_field(path, MPI_COMM_NULL, &file, &d, &dim, n);
    if (!st)
        st = read_attrs(path, d, meta);
    else
        memset(meta, 0, sizeof *meta);
    if (d >= 0) H5Dclose(d);
    if (file >= 0) H5Fclose(file);
    return st;
}

int nl_mpi_h5_read_slab(const char *path, MPI_Comm comm, int *dim, size_t *n, double *h, nl_meta *meta,
                        size_t *s0, size_t *ns, double **slab)
{
    hid_t file, d;
    nl_meta m;
    int st, P, r;
    *slab = NULL;
    quiet();
    MPI_Comm_size(comm, &P);
    MPI_Comm_rank(comm, &r);
    file = d = -1;
    /* a collective open of files that differ between processes hangs */
    if (!(st = nl_mpi_same_file(comm, path, 0)))
        st = open_field(path, comm, &file, &d, dim, n);
    if (!st && !(st = read_attrs(path, d, &m)))
        st = parse_spacing(path, m.spacing, *dim, h);
    if (!st) {
        size_t loc[3] = {n[0], n[1], n[2]};
        nl_mpi_block(n[*dim - 1], P, r, s0, ns);
        loc[*dim - 1] = *ns ? *ns : 1;
        if (!(st = nl_size_check(*dim, loc, sizeof(double), 1, NULL)) &&
            !(*slab = nl_alloc((*ns ? loc[0] * loc[1] * loc[2] : 1) * sizeof **slab)))
            st = NL_ERROR(NL_ENOMEM, "out of memory for a slab of %s", path);
    }
    /* the read is collective: every process must take part */
    st = nl_mpi_agree(comm, st);
    if (!st) {
        size_t row = 1, cnt;
        for (int a = 0; a + 1 < *dim; a++)
            row *= n[a];
        cnt = *ns * row;
        st = read_rows(path, comm, d, *dim, n, *s0, *ns, *slab);
        if (!st)
            st = check_finite(path, *slab, cnt, *s0 * row);
    }
    if (d >= 0) H5Dclose(d);
    if (file >= 0) H5Fclose(file);
    st = nl_mpi_agree(comm, st);
    if (st) {
        nl_free(*slab);
        *slab = NULL;
    } else if (meta) {
        *meta = m;
    }
    return st;
}
