/* XDMF 3 sidecars of HDF5 fields (xdmf.org/index.php/XDMF_Model_and_Format):
 * a uniform grid, CoRectMesh topology with ORIGIN_DXDY[DZ] geometry, and the
 * dataset /field as a node-centred scalar, so that ParaView and VisIt open
 * the .h5 through the .xmf. */
#include "format.h"
#include "nl_error.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

/* s with XML's five special characters escaped. */
static void put_escaped(FILE *fp, const char *s)
{
    for (; *s; s++)
        switch (*s) {
        case '&': fputs("&amp;", fp); break;
        case '<': fputs("&lt;", fp); break;
        case '>': fputs("&gt;", fp); break;
        case '"': fputs("&quot;", fp); break;
        case '\'': fputs("&apos;", fp); break;
        default: fputc(*s, fp);
        }
}

/* The k numbers v[k-1] .. v[0] (XDMF's slowest-first order), %.17g. */
static void put_reversed(FILE *fp, const double *v, int k)
{
    for (int a = k - 1; a >= 0; a--)
        fprintf(fp, "%.17g%s", v[a], a ? " " : "");
}

int nl_xdmf_write(const char *xmf_path, const char *h5_name, int dim, const size_t *n, const double *h,
                  const double *origin, int dbl)
{
    double hh[3] = {1, 1, 1}, o[3] = {0, 0, 0};
    size_t nn[3] = {1, 1, 1};
    int k = dim < 2 ? 2 : dim, st = NL_OK;
    FILE *fp;
    if (dim < 1 || dim > 3)
        return NL_ERROR(NL_EINVAL, "XDMF: expected 1 to 3 dimensions, got %d", dim);
    for (int a = 0; a < dim; a++) {
        nn[a] = n[a], hh[a] = h ? h[a] : 1, o[a] = origin ? origin[a] : 0;
        if (!nn[a] || !(hh[a] > 0) || !isfinite(hh[a]) || !isfinite(o[a]))
            return NL_ERROR(NL_EINVAL, "XDMF: axis %d: expected a size > 0, a spacing > 0 and a finite origin", a);
    }
    if (!(fp = fopen(xmf_path, "w")))
        return NL_ERROR(NL_EIO, "cannot create %s: %s", xmf_path, strerror(errno));
    fprintf(fp, "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n"
                "  <Grid Name=\"field\" GridType=\"Uniform\">\n"
                "   <Topology TopologyType=\"%dDCoRectMesh\" Dimensions=\"", k);
    for (int a = k - 1; a >= 0; a--)
        fprintf(fp, "%zu%s", nn[a], a ? " " : "");
    fprintf(fp, "\"/>\n   <Geometry GeometryType=\"%s\">\n"
                "    <DataItem Name=\"Origin\" Dimensions=\"%d\" NumberType=\"Float\" Precision=\"8\" "
                "Format=\"XML\">", k == 3 ? "ORIGIN_DXDYDZ" : "ORIGIN_DXDY", k);
    put_reversed(fp, o, k);
    fprintf(fp, "</DataItem>\n    <DataItem Name=\"Spacing\" Dimensions=\"%d\" NumberType=\"Float\" "
                "Precision=\"8\" Format=\"XML\">", k);
    put_reversed(fp, hh, k);
    fprintf(fp, "</DataItem>\n   </Geometry>\n"
                "   <Attribute Name=\"field\" AttributeType=\"Scalar\" Center=\"Node\">\n"
                "    <DataItem Dimensions=\"");
    for (int a = dim - 1; a >= 0; a--) /* the dataset's own shape */
        fprintf(fp, "%zu%s", nn[a], a ? " " : "");
    fprintf(fp, "\" NumberType=\"Float\" Precision=\"%d\" Format=\"HDF\">", dbl ? 8 : 4);
    put_escaped(fp, h5_name);
    fputs(":/field</DataItem>\n   </Attribute>\n  </Grid>\n </Domain>\n</Xdmf>\n", fp);
    if (ferror(fp))
        st = NL_ERROR(NL_EIO, "%s: write failed", xmf_path);
    if (fclose(fp) && !st)
        st = NL_ERROR(NL_EIO, "%s: write failed: %s", xmf_path, strerror(errno));
    return st;
}
