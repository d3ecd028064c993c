/* Internals of conditional simulation shared by condsim.c (the plan, the
 * kriging of the residual) and condsim_draw.c (U at the sites given the
 * grid). */
#ifndef NL_CONDSIM_INTERNAL_H
#define NL_CONDSIM_INTERNAL_H

#include "condsim.h"

#include <stdint.h>

struct nl_condsim_plan {
    const nl_model *m;     /* borrowed */
    int dim;               /* grid dimension */
    size_t gn[3];          /* grid samples per axis */
    double h[3], lo[3];    /* grid spacing, lower corner of the extent */
    size_t n, np;          /* data, points */
    double *pts, *val;     /* n * dim coordinates, n values (copies) */
    double *at;            /* np * dim coordinates of the points (copy) */
    nl_condsim_options o;  /* as given, hood resolved */
    size_t *sample;        /* n + np: the grid sample of a datum or point on one, SIZE_MAX for a site */
    /* groups of sites drawn jointly (condsim_draw.c) */
    size_t ngroups;        /* groups */
    size_t *site_off;      /* ngroups + 1 offsets into site */
    size_t *site;          /* the sites of each group (data index; n + j for point j) */
    size_t *samp_off;      /* ngroups + 1 offsets into samp */
    size_t *samp;          /* the grid samples of each group, ascending */
    size_t *mat_off;       /* ngroups + 1 offsets into W (sites x samples each) */
    size_t *chol_off;      /* ngroups + 1 offsets into S (sites x sites each) */
    double *W;             /* C_TG C_GG^-1, row-major per group */
    double *S;             /* chol(C_TT - C_TG C_GG^-1 C_GT), lower, row-major per group */
    /* kriging weights (condsim.c): rows for the grid's cells, then the points */
    size_t width;          /* weights per row (0: none kept) */
    uint32_t *widx;        /* (count + np) * width data indices */
    double *w, *c;         /* (count + np) * width weights, count + np constants */
    nl_condsim_info info;  /* the figures */
};

/* The coordinates of site or datum s (data first, then the points). */
const double *nl_condsim_coords(const nl_condsim_plan *p, size_t s);
/* Group the sites and factor each group; fills the group arrays and the
 * info's sites, groups, largest, unlinked, screening and worst. */
int nl_condsim_groups(nl_condsim_plan *p);
/* U at every datum and point (n + np values into u): read from f on
 * samples, drawn given f at the sites with the numbers of `seed`. */
void nl_condsim_draw(const nl_condsim_plan *p, const nl_field *f, uint64_t seed, double *u);

#endif
