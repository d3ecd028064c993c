"""The public nl_ declarations the package calls, copied from the headers
named beside each group (cffi cdef syntax).  Struct layouts must match the
headers exactly: python/tests/test_layout.py compiles these declarations
against the headers and compares sizes and offsets."""

CDEF = r"""
/* core/version.h, core/nl_error.h */
const char *nl_version(void);
const char *nl_errmsg(void);

/* core/field.h */
typedef struct {
    int dim;
    size_t n[3];
    double h[3];
    size_t count;
    double *data;
} nl_field;
int nl_size_check(int dim, const size_t *n, size_t elem, size_t copies, size_t *count);
nl_field *nl_field_alloc(int dim, const size_t *n, const double *h, int *status);
void nl_field_free(nl_field *f);
int nl_field_check_finite(const nl_field *f, double limit, size_t *first);

/* core/mem.h */
void *nl_alloc(size_t bytes);
void nl_free(void *p);

/* core/io.h */
typedef struct {
    char model[1024];
    char method[256];
    char seed[32];
    char spacing[128];
    char size[64];
    char version[32];
    char flags[256];
    char origin[64];
    char crs[1024];
    char extent[192];
} nl_meta;
int nl_exr_write(const char *path, const nl_field *f, const nl_meta *meta);
int nl_tsv_write_field(const char *path, const nl_field *f, const nl_meta *meta, const char *coord,
                       const double *t);
int nl_field_read(const char *path, nl_field **out, nl_meta *meta);

/* core/format.h */
typedef ... FILE;
typedef struct {
    const char *format;
    int precision;
    double lo, hi;
    const char *sidecar;
} nl_write_options;
typedef struct {
    const char *format;
    int dim;
    size_t n[3];
    double lo, hi;
} nl_read_options;
typedef struct nl_format {
    const char *name;
    const char *extensions;
    const char *summary;
    unsigned dims;
    unsigned types;
    int precision;
    unsigned meta;
    unsigned flags;
    const char *magic;
    size_t magic_len;
    int (*read)(const char *path, const unsigned char *buf, size_t len, const nl_read_options *o,
                nl_field **out, nl_meta *meta);
    int (*read_stream)(FILE *fp, const char *path, nl_field **out, nl_meta *meta);
    int (*write)(const char *path, const nl_field *f, const nl_meta *meta, const nl_write_options *o);
} nl_format;
size_t nl_format_count(void);
const nl_format *nl_format_get(size_t i);
const nl_format *nl_format_find(const char *name);
int nl_format_resolve(const char *path, const char *format, const nl_format **out);
int nl_field_write(const char *path, const nl_field *f, const nl_meta *meta, const nl_write_options *o);
int nl_field_read_opts(const char *path, const nl_read_options *o, nl_field **out, nl_meta *meta);
int nl_format_crs_check(const char *crs);
int nl_xdmf_write(const char *xmf_path, const char *h5_name, int dim, const size_t *n, const double *h,
                  const double *origin, int dbl);

/* core/provenance.h */
enum { NL_META_NKEYS = 8 };
typedef struct {
    char model[1024];
    char method[256];
    char flags[256];
    char version[32];
    uint64_t seed;
    int has_seed;
    int dim;
    size_t n[3];
    int nspacing;
    double h[3];
    int norigin;
    double origin[3];
} nl_provenance;
const char *nl_meta_key(int i);
void nl_provenance_init(nl_provenance *p);
int nl_provenance_format(const nl_provenance *p, nl_meta *kv);
int nl_provenance_parse(const nl_meta *kv, unsigned keys, nl_provenance *p);

/* core/model.h */
typedef struct nl_model nl_model;
int nl_model_parse(const char *spec, nl_model **out);
void nl_model_free(nl_model *m);
const char *nl_model_spec(const nl_model *m);
int nl_model_is_spectral(const nl_model *m);
int nl_model_is_intrinsic(const nl_model *m);
double nl_model_variogram(const nl_model *m, int dim, const double *lag);
double nl_model_acf(const nl_model *m, int dim, const double *lag);
int nl_model_check_dim(const nl_model *m, int dim);
int nl_model_is_reentrant(const nl_model *m);
int nl_model_has_acf(const nl_model *m);
int nl_model_is_isotropic(const nl_model *m);
double nl_model_nugget(const nl_model *m);
double nl_model_spectrum(const nl_model *m, int dim, const double *f);
double nl_model_spectral_density(const nl_model *m, int dim, const double *f);
typedef struct {
    const char *name;
    const char *params;
    const char *formula;
} nl_model_info;
const nl_model_info *nl_model_catalogue(size_t *count);

/* core/family.h */
typedef enum { NL_ROLE_SHAPE = 0, NL_ROLE_VARIANCE, NL_ROLE_SCALE, NL_ROLE_NUGGET, NL_ROLE_BAND } nl_param_role;
typedef enum { NL_RANGE_ANY = 0, NL_RANGE_POSITIVE, NL_RANGE_NONNEG, NL_RANGE_UPTO } nl_param_range;
enum { NL_FAMILY_SPECTRAL = 1, NL_FAMILY_FIT = 2, NL_FAMILY_EXPRESSION = 4, NL_FAMILY_ARGUMENT = 8,
       NL_FAMILY_INTRINSIC = 32 };
typedef struct {
    const char *name;
    nl_param_role role;
    double def;
    const char *def_text;
    const char *placeholder;
    const char *example;
    nl_param_range range;
    double hi;
    const char *why;
    double start;
    int start_per_scale;
    double fit_lo, fit_hi;
} nl_family_param;
typedef struct {
    const char *name;
    const char *peer;
    const char *formula;
    size_t nparams;
    const nl_family_param *params;
    void (*convert)(const double *q, double *p);
} nl_family_alias;
typedef struct nl_family {
    const char *name;
    const char *aliases;
    const char *argument;
    const char *usage;
    const char *formula;
    unsigned flags;
    int max_dim;
    const char *validity;
    size_t nparams;
    const nl_family_param *params;
    int (*parse_argument)(nl_model *m, const char *arg);
    int (*check)(const nl_model *m);
    double (*profile)(const nl_model *m, double t);
    double (*acf)(const nl_model *m, int dim, const double *lag);
    double (*acf_stretched)(const nl_model *m, double u, double v, double w, double r);
    double (*spectrum)(const nl_model *m, int dim, const double *f);
    int (*isotropic)(const nl_model *m);
    int (*check_dim)(const nl_model *m, int dim);
    double (*acf_d2)(const nl_model *m, double t);
    size_t npeers;
    const nl_family_alias *peers;
} nl_family;
size_t nl_family_count(void);
const nl_family *nl_family_get(size_t i);

/* core/dist.h */
typedef struct nl_dist nl_dist;
int nl_dist_parse(const char *spec, nl_dist **out);
void nl_dist_free(nl_dist *d);
const char *nl_dist_spec(const nl_dist *d);
double nl_dist_cdf(const nl_dist *d, double y);
double nl_dist_pdf(const nl_dist *d, double y);
double nl_dist_quantile(const nl_dist *d, double u);
double nl_dist_transform(const nl_dist *d, double x);
int nl_dist_is_function(const nl_dist *d);
double nl_dist_mean(const nl_dist *d);
double nl_dist_variance(const nl_dist *d);

/* analysis/bands.h */
int nl_band_chisq(double nu, double *lo, double *hi);
int nl_welch_edf(int dim, const size_t *n, size_t S, double *nu);

/* synth/fft.h */
typedef struct nl_synth_fft_plan nl_synth_fft_plan;
typedef struct {
    double variance;
    double min_lambda;
    double max_lambda;
    size_t negatives;
    double clamp_error;
} nl_synth_fft_info;
int nl_synth_fft_plan_alloc(const nl_model *m, int dim, const size_t *n, const double *h, unsigned flags,
                            nl_synth_fft_plan **out);
void nl_synth_fft_plan_info(const nl_synth_fft_plan *p, nl_synth_fft_info *info);
int nl_synth_fft_execute(const nl_synth_fft_plan *p, uint64_t seed, nl_field *out);
void nl_synth_fft_plan_free(nl_synth_fft_plan *p);

/* synth/circulant.h */
typedef struct {
    size_t m[3];
    double min_eigenvalue;
    double max_eigenvalue;
    double clamp_error;
    int doublings;
    double variance_loss;
} nl_synth_circulant_info;
typedef struct nl_synth_circulant_plan nl_synth_circulant_plan;
int nl_synth_circulant_plan_alloc(const nl_model *m, int dim, const size_t *n, const double *h, unsigned flags,
                                  int max_factor, nl_synth_circulant_plan **out);
void nl_synth_circulant_plan_info(const nl_synth_circulant_plan *p, nl_synth_circulant_info *info);
int nl_synth_circulant_execute(const nl_synth_circulant_plan *p, uint64_t seed, nl_field *out);
void nl_synth_circulant_plan_free(nl_synth_circulant_plan *p);

/* synth/cholesky.h */
typedef struct nl_synth_cholesky_plan nl_synth_cholesky_plan;
int nl_synth_cholesky_plan_alloc(const nl_model *m, int dim, const size_t *n, const double *h,
                                 nl_synth_cholesky_plan **out);
int nl_synth_cholesky_execute(nl_synth_cholesky_plan *p, uint64_t seed, nl_field *out);
void nl_synth_cholesky_plan_free(nl_synth_cholesky_plan *p);

/* synth/subdiv.h */
typedef struct {
    int cls;
    size_t n;
    double *a;
    double variance;
    double raw_variance;
    double condition;
    double min_eigenvalue;
    unsigned flags;
    int nalt;
    int *offx, *offy;
    double *alt_a;
    double *alt_var;
} nl_subdiv_class;
typedef struct {
    int level;
    double spacing;
    int N;
    int reach;
    int nclass;
    nl_subdiv_class cls[3];
    int taps;
    double *filt;
    double filt_error;
} nl_subdiv_level;
typedef struct {
    int dim;
    int levels;
    double spacing0;
    double r0;
    unsigned flags;
    nl_subdiv_level *level;
} nl_subdiv_coeffs;
const char *nl_subdiv_flag_name(unsigned bit);
const char *nl_subdiv_class_name(int cls);
int nl_subdiv_coeffs_alloc_rule(const nl_model *m, int dim, int levels, double spacing0, int N, int rule, double tol,
                                int nmax, nl_subdiv_coeffs **out);
void nl_subdiv_coeffs_free(nl_subdiv_coeffs *c);
int nl_subdiv_coeffs_correlate(nl_subdiv_coeffs *c, const nl_model *m, int taps, int target);
typedef struct nl_subdiv_plan nl_subdiv_plan;
typedef struct {
    int levels;
    int N;
    double tol;
    int nmax;
    int nonperiodic;
    int allow_not_pd;
    int image;
    int random_nb;
    uint64_t random_seed;
    int displacements;
    int taps;
    int stop;
} nl_subdiv_options;
typedef struct {
    int levels;
    double spacing0;
    double variance;
    double coarse_correlation;
} nl_subdiv_info;
void nl_subdiv_options_default(nl_subdiv_options *o);
int nl_subdiv_plan_alloc(const nl_model *m, int dim, const size_t *n, double h, const nl_subdiv_options *o,
                         nl_subdiv_plan **out);
int nl_subdiv_plan_alloc_midpoint(int dim, const size_t *n, double h, int levels, double H, double sigma2,
                                  double vscale, nl_subdiv_plan **out);
int nl_subdiv_midpoint_hurst(const nl_model *m, int dim, double *H);
const nl_subdiv_coeffs *nl_subdiv_plan_coeffs(const nl_subdiv_plan *p);
void nl_subdiv_plan_info(const nl_subdiv_plan *p, nl_subdiv_info *info);
int nl_subdiv_plan_execute(const nl_subdiv_plan *p, uint64_t seed, nl_field *f);
int nl_subdiv_plan_execute_window(const nl_subdiv_plan *p, uint64_t seed, const long *origin, nl_field *f);
void nl_subdiv_plan_free(nl_subdiv_plan *p);

/* synth/midpoint.h, synth/faulting.h */
int nl_synth_midpoint_miller_default_levels(int dim, const size_t *n);
int nl_synth_midpoint_miller(int levels, double H, double sigma2, double vscale, uint64_t seed, nl_field *out);
int nl_synth_faulting(uint64_t seed, double density, nl_field *f, size_t *count);

/* synth/sparse.h */
typedef struct nl_synth_sparse_plan nl_synth_sparse_plan;
typedef struct {
    int radius;
    int cell;
    double density;
    double kernel_energy;
    double truncated;
    double kurtosis;
    double variance;
    double mean;
    double clamp_error;
    size_t negatives;
} nl_synth_sparse_info;
typedef struct {
    int radius;
    int cell;
    double density;
    unsigned flags;
} nl_synth_sparse_options;
void nl_synth_sparse_options_default(nl_synth_sparse_options *o);
int nl_synth_sparse_plan_model(const nl_model *m, int dim, const double *h, const nl_synth_sparse_options *o,
                               nl_synth_sparse_plan **out);
int nl_synth_sparse_plan_expr(const char *expr, int dim, const nl_synth_sparse_options *o,
                              nl_synth_sparse_plan **out);
void nl_synth_sparse_plan_info(const nl_synth_sparse_plan *p, nl_synth_sparse_info *info);
int nl_synth_sparse_execute(const nl_synth_sparse_plan *p, uint64_t seed, unsigned flags, const long *origin,
                            nl_field *out);
int nl_synth_sparse_check_work(int dim, const size_t *n, int radius, int cell, double density, unsigned flags);
void nl_synth_sparse_plan_free(nl_synth_sparse_plan *p);

/* synth/lattice.h */
typedef struct {
    int octaves;
    double cell[16];
    double weight[16];
    double peak[16];
    double leakage[16];
    size_t negatives;
    double clamp_error;
} nl_synth_lattice_plan;
int nl_synth_lattice_plan_init(const nl_model *m, int dim, double cell0, int octaves, unsigned flags,
                               nl_synth_lattice_plan *p);
int nl_synth_lattice_execute(const nl_synth_lattice_plan *p, uint64_t seed, nl_field *out);
double nl_synth_lattice_default_cell(const size_t *n);
int nl_synth_lattice_default_octaves(double cell0);
int nl_synth_lattice_check_grid(const nl_model *m, int dim, const size_t *n, unsigned flags, double *clamp_error);

typedef struct nl_synth_lattice_wiener_plan nl_synth_lattice_wiener_plan;
typedef struct {
    int cell;
    size_t nodes[2];
    double variance;
    double mean_error;
    double max_error;
    int rank;
    size_t negatives;
} nl_synth_lattice_wiener_info;
int nl_synth_lattice_wiener_plan_alloc(const nl_model *m, int dim, const size_t *n, int cell, unsigned flags,
                                       nl_synth_lattice_wiener_plan **out);
void nl_synth_lattice_wiener_plan_info(const nl_synth_lattice_wiener_plan *p, nl_synth_lattice_wiener_info *info);
int nl_synth_lattice_wiener_execute(const nl_synth_lattice_wiener_plan *p, uint64_t seed, nl_field *out,
                                    double **lattice);
void nl_synth_lattice_wiener_plan_free(nl_synth_lattice_wiener_plan *p);

/* synth/method.h */
enum {
    NL_METHOD_MODEL = 1, NL_METHOD_NO_MODEL = 2, NL_METHOD_PERIODIC = 4, NL_METHOD_WINDOW = 8,
    NL_METHOD_DISTRIBUTED = 16, NL_METHOD_CONDITIONABLE = 32, NL_METHOD_EXACT = 64, NL_METHOD_CLAMP = 128,
    NL_METHOD_SERIAL = 256, NL_METHOD_TORUS = 512, NL_METHOD_EMBEDDING = 1024,
    NL_METHOD_VALIDATED = 2048, NL_METHOD_SUBDIVISION = 4096, NL_METHOD_NUGGET = 8192,
    NL_METHOD_INTRINSIC = 16384
};
enum {
    NL_METHOD_OPEN = 1, NL_METHOD_REPLACES_MODEL = 2, NL_METHOD_FILE = 4, NL_METHOD_SUFFIX = 8,
    NL_METHOD_MAKES_WINDOW = 16, NL_METHOD_NO_WINDOW = 32, NL_METHOD_EXPRESSION = 64
};
enum { NL_METHOD_OPT_CLAMP = 1, NL_METHOD_OPT_RECORDED = 2 };
typedef enum {
    NL_METHOD_INT, NL_METHOD_DOUBLE, NL_METHOD_CHOICE, NL_METHOD_FLAG, NL_METHOD_STRING
} nl_method_opt_type;
typedef struct {
    const char *name;
    nl_method_opt_type type;
    unsigned flags;
    double min, max;
    const char *words;
    const char *expect;
    const char *def;
    const char *help;
} nl_method_option;
typedef struct {
    int set;
    long i;
    double d;
    const char *s;
    const nl_field *field;
} nl_method_value;
typedef struct nl_method_type nl_method_type;
typedef struct {
    const nl_method_type *type;
    unsigned flags;
    nl_method_value v[12];
} nl_method_options;
typedef struct {
    int dim;
    size_t n[3];
    double h[3];
    long origin[2];
} nl_method_grid;
typedef struct nl_method_plan nl_method_plan;
typedef struct {
    char method[4096];
    char flags[256];
    double sd;
    double offset;
    char json[8192];
} nl_method_report;
struct nl_method_type {
    const char *name;
    const char *summary;
    const char *noun;
    const char *help;
    unsigned dims;
    unsigned caps;
    const nl_method_option *options;
    int noptions;
    const char *model_conflict;
    const char *model_missing;
    int (*plan)(const nl_model *m, const nl_method_grid *g, const nl_method_options *o, nl_method_plan **out);
    int (*execute)(nl_method_plan *p, uint64_t seed, nl_field *f);
    int (*execute_slab)(nl_method_plan *p, uint64_t seed, size_t s0, nl_field *f);
    int (*describe)(const nl_method_plan *p, char *buf, size_t size);
    int (*report)(const nl_method_plan *p, const nl_model *m, uint64_t seed, const nl_field *f,
                  nl_method_report *r);
    void (*free)(nl_method_plan *p);
};
int nl_method_count(void);
const nl_method_type *nl_method_at(int i);
const nl_method_type *nl_method_find(const char *name);
int nl_method_option_index(const nl_method_type *t, const char *name);
void nl_method_options_default(const nl_method_type *t, nl_method_options *o);
int nl_method_options_set(nl_method_options *o, const char *name, const char *text, const char *label);
int nl_method_plan_alloc(const nl_method_type *t, const nl_model *m, const nl_method_grid *g,
                         const nl_method_options *o, nl_method_plan **out);
int nl_method_execute(nl_method_plan *p, uint64_t seed, nl_field *f);
int nl_method_describe(const nl_method_plan *p, char *buf, size_t size);
int nl_method_report_of(const nl_method_plan *p, const nl_model *m, uint64_t seed, const nl_field *f,
                        nl_method_report *r);
void *nl_method_plan_impl(const nl_method_plan *p);
void nl_method_plan_free(nl_method_plan *p);
typedef struct {
    double H;
    int levels;
    int miller;
    double vscale;
    struct nl_subdiv_plan *plan;
} nl_midpoint_method_plan;
typedef struct {
    int wiener;
    double cell0;
    int octaves;
    double grid_clamp_error;
    nl_synth_lattice_plan perlin;
    nl_synth_lattice_wiener_plan *plan;
} nl_lattice_method_plan;

/* synth/shape.h */
int nl_synth_shape(nl_field *f, const nl_dist *to, int empirical);

/* analysis/acf.h, analysis/psd.h, analysis/welch.h, analysis/radial.h */
int nl_acf_full(const nl_field *x, double mean, int unbiased, nl_field **out);
int nl_acf_radial(const nl_field *full, size_t nbins, double *lag, double *val, size_t *cnt);
int nl_acf_model_values(const nl_model *m, int dim, const size_t *n, const double *h, int axis, const double *lag,
                        size_t nl, double *out);
int nl_psd_periodogram(const nl_field *x, double mean, nl_field **out);
int nl_psd_welch(const nl_field *x, size_t S, double mean, nl_field **out, size_t *segments);
int nl_radial(const nl_field *g, int kind, double step, size_t nbins, double *r, double *v, size_t *cnt);
int nl_acf_axis(const nl_field *full, int axis, size_t maxlag, double *lag, double *val);
size_t nl_psd_profile_size(const nl_field *P);
int nl_psd_profile(const nl_field *P, double *freq, double *val, size_t *cnt, size_t *nf);
int nl_fftshift_alloc(const nl_field *P, nl_field **out);
int nl_acf_centred_alloc(const nl_field *full, nl_field **out);
int nl_acf_bartlett_band(const nl_field *full, size_t N, size_t maxlag, const double *val, double *lo, double *hi);
int nl_acf_model_band(const nl_model *m, int dim, const size_t *n, const double *h, int axis, size_t maxlag,
                      double *mean, double *lo, double *hi);
int nl_psd_model_profile(const nl_model *m, int dim, const size_t *n, const double *h, double *val, size_t *nf);

/* core/wk.h */
int nl_wk_sample_acf(const nl_model *m, nl_field *R);
int nl_wk_sample_spectrum(const nl_model *m, nl_field *S);
int nl_wk_acf_to_spectrum(const nl_field *R, nl_field *S);

/* analysis/hist.h */
typedef struct {
    size_t n;
    double mean;
    double variance;
    double skewness;
    double kurtosis;
    double min, max;
} nl_moments;
int nl_moments_compute(const nl_field *x, nl_moments *m);
int nl_hist(const nl_field *x, size_t bins, double *edges, double *counts);

/* analysis/gof_boot.h */
typedef struct {
    int tested;
    double value;
    double expected;
    double null_mean;
    double null_sd;
    double p;
    double p_rank;
} nl_gof_boot_stat;
typedef struct {
    size_t n;
    size_t fields;
    size_t draws;
    size_t bins;
    size_t tests;
    nl_gof_boot_stat stat[6];
    double ks_n_eff, ks_shift;
    double moment_dof;
    double chi2_scale, chi2_dof;
    double p;
    int p_from;
    double var_ratio_lo, var_ratio_hi;
    double ks_q95;
    double ks_detectable;
    double radius_min, radius_max;
} nl_gof_boot;
int nl_gof_boot_test(const nl_field *const *x, size_t K, const nl_dist *d, size_t draws, uint64_t seed, size_t bins,
                     nl_gof_boot *out);
const char *nl_gof_boot_name(int stat);

/* analysis/ensemble.h */
typedef struct {
    size_t K;
    const nl_field *const *fields;
    int (*get)(void *ctx, size_t k, const nl_field **out);
    void (*put)(void *ctx, size_t k, const nl_field *f);
    void *ctx;
} nl_ensemble_source;
typedef struct {
    double mean;
    int unbiased;
    int axis;
    int radial;
    int direct;
    size_t nlag;
} nl_ensemble_acf_opts;
typedef struct {
    double mean;
    size_t welch;
} nl_ensemble_psd_opts;
int nl_ensemble_acf(const nl_ensemble_source *src, const nl_ensemble_acf_opts *o, double *lag, double *acf,
                    double *se, size_t *bad);
int nl_ensemble_psd(const nl_ensemble_source *src, const nl_ensemble_psd_opts *o, nl_field **P, double *freq,
                    double *psd, double *se, size_t *nf, size_t *segments, size_t *bad);
int nl_ensemble_moments(const nl_ensemble_source *src, nl_moments *mean, nl_moments *se, size_t *bad);
int nl_ensemble_hist(const nl_ensemble_source *src, size_t bins, double lo, double hi, double *edges,
                     double *counts, double *se, size_t *bad);

/* analysis/check.h */
typedef struct {
    int dim;
    int spectral;
    double scale;
    double variance;
    double min_spectrum;
    double min_spectrum_k;
    double spectrum_kmax;
    double min_eigenvalue;
    size_t eig_side;
    double eig_spacing;
    int positive_definite;
    int why;
    int isotropic;
    double min_r;
    double min_r_lag;
    int isotropic_bound_ok;
    int monotone_3d;
    double line_rise_f;
    double spectral_decay;
    double density_decay;
    int band_limited;
    double band_edge;
    int differentiable_order;
    double r2;
    int singular_checked;
    double singular_below;
} nl_check;
int nl_check_model(const nl_model *m, int dim, nl_check *out);
int nl_check_neighbours(const nl_model *m, const nl_check *c, char *buf, size_t size);

/* analysis/nonlin.h */
typedef struct {
    int terms;
    double c[64];
    double variance;
    double truncation;
} nl_hermite;
int nl_hermite_expand(const nl_dist *to, int terms, nl_hermite *h);
void nl_nonlin_output_acf(const nl_hermite *h, const double *acf, size_t n, double r0, double *out);

/* analysis/krige.h */
typedef struct nl_krige_plan nl_krige_plan;
typedef struct {
    size_t n;
    double rcond;
    int pseudo_inverse;
    double mean;
} nl_krige_info;
int nl_krige_plan_alloc(const nl_model *m, int dim, size_t n, const double *pts, const double *val, int simple,
                        double mean, int strict, nl_krige_plan **out);
int nl_krige_eval_block(const nl_krige_plan *p, size_t count, const double *x, double *est, double *var);
void nl_krige_plan_info(const nl_krige_plan *p, nl_krige_info *info);
void nl_krige_plan_free(nl_krige_plan *p);
int nl_krige_eval_grid(const nl_krige_plan *p, const double *lo, const nl_field *est, nl_field *var);

/* analysis/krige_local.h */
enum { NL_DRIFT_NONE = -1, NL_DRIFT_CONSTANT = 0, NL_DRIFT_LINEAR = 1, NL_DRIFT_QUADRATIC = 2 };
typedef struct {
    size_t nmax;
    double radius;
    int drift;
    double mean;
    size_t ncov;
    const double *cov;
    int missing;
} nl_krige_local_options;
typedef struct nl_krige_local nl_krige_local;
int nl_krige_local_alloc(const nl_model *m, int dim, size_t n, const double *pts, const double *val,
                         const nl_krige_local_options *o, nl_krige_local **out);
void nl_krige_local_free(nl_krige_local *k);
size_t nl_krige_local_terms(const nl_krige_local *k);
int nl_krige_local_eval(const nl_krige_local *k, size_t count, const double *x, double *est, double *var);
int nl_krige_local_grid(const nl_krige_local *k, const double *lo, nl_field *est, nl_field *var);
int nl_krige_local_eval_at(const nl_krige_local *k, size_t count, const double *x, const double *cov, double *est,
                           double *var);
typedef struct {
    double mean_error, var_error;
    double mean_z, var_z;
    double rmse;
    size_t n;
} nl_krige_cv_summary;
int nl_krige_local_cv(const nl_krige_local *k, double *pred, double *var, nl_krige_cv_summary *s);
int nl_krige_local_cv_folds(const nl_krige_local *k, const long *fold, double *pred, double *var,
                            nl_krige_cv_summary *s);
void nl_krige_draw_folds(uint64_t seed, size_t n, size_t K, long *fold);

/* analysis/krige_flavours.h */
typedef struct {
    double size[3];
    int points;
} nl_krige_block;
int nl_krige_block_eval(const nl_krige_local *k, const nl_krige_block *b, size_t count, const double *x, double *est,
                        double *var);
int nl_krige_tg_transform(double lambda, size_t n, const double *val, double *out);
int nl_krige_tg_eval(const nl_krige_local *k, const nl_krige_block *b, double lambda, size_t count, const double *x,
                     double *est, double *var);
int nl_krige_tg_cv(const nl_krige_local *k, double lambda, const double *orig, double *pred, double *var,
                   nl_krige_cv_summary *s);
int nl_krige_indicator(const nl_model *const *m, size_t nk, const double *thr, int dim, size_t n, const double *pts,
                       const double *val, const nl_krige_local_options *o, const nl_krige_block *b, size_t count,
                       const double *x, double *raw, double *cdf, size_t *ncorrected);

/* analysis/condsim.h */
typedef struct nl_condsim_plan nl_condsim_plan;
typedef struct {
    int simple;
    double mean;
    size_t nmax;
    size_t hood;
    int rekrige;
} nl_condsim_options;
typedef struct {
    size_t n;
    size_t on_samples;
    size_t sites;
    size_t hood;
    size_t groups;
    size_t largest;
    size_t unlinked;
    double screening;
    size_t worst;
    double max_move;
    int reuse;
    size_t weight_bytes;
} nl_condsim_info;
int nl_condsim_plan_alloc(const nl_model *m, size_t n, const double *pts, const double *val, const double *lo,
                          const nl_field *grid, const nl_condsim_options *o, size_t np, const double *at,
                          nl_condsim_plan **out);
int nl_condsim_execute(const nl_condsim_plan *p, nl_field *f, uint64_t seed, double *z_at);
void nl_condsim_plan_info(const nl_condsim_plan *p, nl_condsim_info *info);
void nl_condsim_plan_free(nl_condsim_plan *p);

/* core/field_sample.h */
enum { NL_INTERP_NEAREST = 0, NL_INTERP_LINEAR = 1 };
int nl_field_sample(const nl_field *f, const double *x0, int interp, size_t n, const double *pts, double *vals);
void nl_field_random_points(const nl_field *f, const double *x0, uint64_t seed, size_t n, double *pts);

/* core/io_points.h, analysis/variogram.h */
typedef struct {
    int dim;
    size_t n;
    double *pts;
    double *val;
} nl_points;
typedef struct {
    double width;
    double cutoff;
    int estimator;
    int directional;
    double direction;
    double tolerance;
    int bins;
    int drift;
} nl_variogram_options;
void nl_variogram_options_default(nl_variogram_options *o);
typedef struct {
    size_t nbins;
    double *distance;
    double *gamma;
    double *pairs;
} nl_variogram;
int nl_variogram_points(const nl_points *p, const nl_variogram_options *o, nl_variogram **out);
int nl_variogram_points_design(const nl_points *p, const double *design, size_t q, const nl_variogram_options *o,
                               nl_variogram **out);
int nl_variogram_field(const nl_field *f, const nl_variogram_options *o, nl_variogram **out);
void nl_variogram_free(nl_variogram *v);
int nl_variogram_read(const char *path, nl_variogram **out);

/* analysis/fit.h */
typedef struct {
    const char *family;
    int nugget;
    size_t nfix;
    const char *fix_name[8];
    double fix_value[8];
    int weights;
    int likelihood;
    const double *start;
    int intervals;
    double max_work;
    int drift;
    int search;
} nl_fit_options;
typedef struct {
    char name[16];
    double value;
    double se;
    double lower, upper;
    int fixed;
    unsigned flags;
} nl_fit_param;
typedef struct {
    char spec[512];
    size_t np;
    nl_fit_param *param;
    size_t nfree;
    double objective;
    double aic;
    double mean;
    size_t nobs;
    int iterations;
    int converged;
    double rcond;
    unsigned flags;
    size_t ndrift;
    double *drift;
    double *drift_se;
    int starts;
    int restarts;
    double gradient;
} nl_fit_result;
void nl_fit_result_free(nl_fit_result *res);
int nl_fit_check_options(const nl_fit_options *o, int dim);
int nl_fit_variogram(const double *distance, const double *gamma, const double *pairs, size_t nbins, int dim,
                     const nl_fit_options *o, nl_fit_result *res);
double nl_fit_ml_work(size_t n, int dim, const nl_fit_options *o);
int nl_fit_ml(const double *coords, const double *values, size_t n, int dim, const nl_fit_options *o,
              nl_fit_result *res);
int nl_fit_ml_design(const double *coords, const double *values, size_t n, int dim, const double *design, size_t p,
                     const nl_fit_options *o, nl_fit_result *res);
"""
