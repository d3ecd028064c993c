/* Distributed periodic FFT synthesis and circulant embedding on FFTW-MPI.
 *
 * The same fields as synth/fft.h and synth/circulant.h (read their
 * contracts: model sampling, clamping rule, white noise, normalisation),
 * computed by the processes of a communicator, each holding a slab of the
 * field along its slowest axis (mpi/dist.h), never the whole of it.
 *
 * The white spectrum G is indexed by global frequency exactly as in
 * synth/fft.h (the pair nl_rng_gauss_pair(seed, NL_STREAM_WHITE, k) for
 * half-grid index k, Hermitian in the columns k0 = 0 and n0/2), so each
 * process draws the noise of its own frequencies and the field is the
 * one-process field whatever the process count, up to the rounding of the
 * transforms, whose order of operations depends on the decomposition
 * (tests/mpi/fft.c: relative difference below 1e-12 of the field's largest
 * magnitude).  Lag models' spectra come from a distributed forward
 * transform of R sampled at the wrapped lags (core/wk.h); spectral models
 * are sampled at each process's frequencies.
 *
 * Layout.  The frequency data live in FFTW-MPI's transposed order
 * (FFTW_MPI_TRANSPOSED_OUT for the model's forward transform,
 * FFTW_MPI_TRANSPOSED_IN for the synthesis), which spares each transform
 * its final all-to-all; the field comes back in the ordinary slab order:
 * process r holds rows s0 .. s0 + ns - 1 of the slowest axis
 * (nl_mpi_fft_local; FFTW's block distribution, possibly ns = 0).
 * 2D and 3D only (FFTW-MPI has no 1D real transforms; a 1D field fits one
 * process: NL_EINVAL).
 *
 * Every function but _local, _info and _free is collective over the plan's
 * communicator and agrees on its status (mpi/dist.h).  Memory per process:
 * about 2.5 local slabs of doubles (the transform's buffer, the amplitudes
 * and the output) plus FFTW's own transpose buffers. */
#ifndef NL_MPI_FFT_H
#define NL_MPI_FFT_H

#include "../core/model.h"
#include "../synth/circulant.h"
#include "../synth/fft.h"

#include <mpi.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct nl_mpi_fft_plan nl_mpi_fft_plan;

/* Plan synthesis of m on a dim-D grid (2 or 3) of n[] samples at spacing h
 * (NULL: unit) over comm; flags as nl_synth_fft_plan_alloc.  Returns NL_OK
 * and *out, or (*out NULL) the statuses of nl_synth_fft_plan_alloc, the
 * same on every process. */
int nl_mpi_fft_plan_alloc(MPI_Comm comm, const nl_model *m, int dim, const size_t *n, const double *h,
                          unsigned flags, nl_mpi_fft_plan **out);

/* This process's rows of the slowest axis: s0 .. s0 + ns - 1. */
void nl_mpi_fft_local(const nl_mpi_fft_plan *p, size_t *s0, size_t *ns);

/* The plan's statistics, the one-process plan's up to rounding of sums. */
void nl_mpi_fft_plan_info(const nl_mpi_fft_plan *p, nl_synth_fft_info *info);

/* Synthesise the field for seed: this process's slab into out (ns rows of
 * n[0] (x n[1] in 3D) doubles, row-major; may be NULL when ns = 0).
 * NL_OK or NL_ENOMEM (agreed). */
int nl_mpi_fft_execute(const nl_mpi_fft_plan *p, uint64_t seed, double *out);

void nl_mpi_fft_plan_free(nl_mpi_fft_plan *p);

/* Circulant embedding, distributed: the embedding grid m (chosen and
 * doubled as nl_synth_circulant_plan_alloc does) is synthesised by a
 * distributed FFT plan and cropped to the first n samples per axis.  The
 * output's rows of the slowest axis held by this process are the
 * embedding's rows it holds that fall below n: nl_mpi_circulant_local
 * (the processes holding the embedding's upper part hold none). */
typedef struct nl_mpi_circulant_plan nl_mpi_circulant_plan;

int nl_mpi_circulant_plan_alloc(MPI_Comm comm, const nl_model *m, int dim, const size_t *n, const double *h,
                                unsigned flags, int max_factor, nl_mpi_circulant_plan **out);
void nl_mpi_circulant_local(const nl_mpi_circulant_plan *p, size_t *s0, size_t *ns);
void nl_mpi_circulant_plan_info(const nl_mpi_circulant_plan *p, nl_synth_circulant_info *info);
int nl_mpi_circulant_execute(const nl_mpi_circulant_plan *p, uint64_t seed, double *out);
void nl_mpi_circulant_plan_free(nl_mpi_circulant_plan *p);

/* Peak bytes per process of a distributed FFT synthesis of n[0..dim-1]
 * samples on P processes (the busiest process's slab; an estimate within
 * FFTW's transpose buffers), for a memory check before planning.  Pure. */
size_t nl_mpi_fft_bytes(int dim, const size_t *n, int P);

#ifdef __cplusplus
}
#endif

#endif
