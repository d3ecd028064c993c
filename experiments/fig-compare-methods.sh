#!/bin/sh
# Lewis 1987, "Comparison of Stochastic Synthesis Methods", as a measured
# table: every synthesis method of noiselab on the same four targets
# (experiments/compare_methods.c).  COMPARE_FULL=1 times 256^2..1024^2
# instead of 128^2..512^2 (1024^2 then measured, not extrapolated).
. "$(dirname "$0")/lib.sh"
md=$d/47-compare-methods.md
status=0
"$xb/compare_methods" "$d" ${COMPARE_FULL:+full} >&2 || status=1
names=$(awk 'NR > 1 { printf "%s ", $1 }' "$d/compare-cost.tsv")
gnuplot <<EOF
set terminal pngcairo size 1200,500 font "DejaVu Sans,10"
set output "$dir/compare-methods.png"
set datafile separator "\t"
set multiplot layout 1,2
set title "cost against accuracy (the markov, gauss and ring targets each method ran)"
set logscale xy
set xlabel "one realization at 1024^2 (s, one thread; ≈ extrapolated from 512^2)"
set ylabel "largest ACF error |mean - R| / R(0) over the targets"
set grid
set key top right font ",9" box opaque
set xrange [0.003:30000]
set yrange [0.01:1]
names = "$names"
plot for [i = 1:words(names)] "$d/compare-cost.tsv" every ::i::i using 2:4 with points pt (4 + i % 9) \
     ps 1.6 lw 2 title word(names, i)
unset logscale
set title "the ring target (oscillating R, valid in 2D): ensemble-mean ACF along x"
set xlabel "lag (samples)"
set ylabel "R"
set key top right font ",9"
set xrange [0:16]
set yrange [-0.3:1.05]
plot "$d/compare-ring-acf.tsv" using 1:2 skip 1 with lines lw 3 lc rgb "black" title "target", \
     "" using 1:3 skip 1 with linespoints pt 7 ps 0.5 title "fft", \
     "" using 1:4 skip 1 with linespoints pt 7 ps 0.5 title "circulant", \
     "" using 1:6 skip 1 with linespoints pt 5 ps 0.5 title "subdiv (N = 2)", \
     "" using 1:7 skip 1 with linespoints pt 5 ps 0.5 title "subdiv, correlated", \
     "" using 1:11 skip 1 with linespoints pt 9 ps 0.5 title "sparse", \
     "" using 1:13 skip 1 with linespoints pt 11 ps 0.5 title "lattice, Wiener", \
     "" using 1:14 skip 1 with linespoints pt 13 ps 0.5 title "rank-1 (Keller)"
unset multiplot
EOF
{
    cat <<'EOF'
## The comparison of synthesis methods (Lewis 1987), measured

Lewis 1987 closes with a comparison of stochastic synthesis methods by locality, efficiency,
spectral control and refinement, in words. Here it is a table of measurements: every synthesis
method of noiselab on the same four 2D targets, each given in closed form both as R and as S
(a method takes R when it can, else S):

- **markov** `markov:scale=6`, R = exp(-r/6): rough, not fractal, S ~ k^-3 at high frequency;
- **gauss** `gauss:scale=6`: smooth, a singular process (its covariance matrices are numerically
  singular), S falling faster than any power;
- **ring** R = (1 - 2q + q²/2) exp(-q), q = (r/8)², the biharmonic of a Gaussian: valid in 2D, its
  spectrum S ∝ k⁴ exp(-(8πk)²) a ring at k = 0.056 cycles per sample, R oscillating (negative
  lobe, then positive) — Lewis's "oscillatory noises", which Haruyama-Barsky subdivision cannot make;
- **fractal** `power:d=3` (H = 1/2 in 2D): what midpoint displacement, Miller's subdivision and
  Poisson faulting make; judged by the log-periodogram slope over 1/32 ≤ |f| ≤ 1/4 (target -3).

How it is measured: 32 realizations (seeds 1..32) per method and target on 64x64 (Cholesky 32x32:
its plan is O(N³) in samples); the unbiased ACF with the known mean 0 along x, y and the diagonal,
lags 0..16 (Cholesky 0..8); **ACF error** = the largest |ensemble mean - R| / R(0) over those lags
with its simultaneous 95% interval, "(z)" when the z test finds an error (Bonferroni threshold of
t(31) at 1e-3; analysis/validate.h); **spectrum ratio** = ensemble-mean periodogram over its
expectation (the sampled spectrum for periodic methods, Fejér-smoothed for circulant, Cholesky and
faulting) in the bands (0, 1/32] (low; Cholesky's 32x32: (0, 1/16]; DC excluded), (1/16, 1/8]
(mid) and (1/4, 1/2] with the corners (high), as analysis/validate.h bins them, ± 2 standard
errors, "-" where the target has no power. **Cost**: wall time of one realization (best of
3, one thread, FFTW_ESTIMATE) after the plan, at 128², 256², 512² (`COMPARE_FULL=1`: 256² to
1024²); the exponent is the least-squares slope of log time on log samples, the 1024² figure
extrapolated with it (≈); the plan's time and the peak resident memory of the child process that
ran the largest size are beside it. Descriptive columns (local, refinable, exact) state what each
implementation is; "oscillatory" and "non-fractal" are what the ring, markov and gauss runs gave:
yes (no error detected by the z test; the upper end of the error's interval beside it), approx.
(an error detected; its estimate), or refused.

EOF
    cat "$d/compare-tables.frag"
    cat <<'EOF'

![cost against accuracy, and the ring's ACF by method](compare-methods.png)

What the paper says beside what we measured:

- *FFT: "global", "exact spectral control".* Its ensembles meet R on every target within
  sampling error, and it is the cheapest of the methods that reach every target. (For the ring, R sampled on the 64-periodic
  grid is not positive definite, so it synthesises from the sampled spectrum, as Lewis's FFT method does.)
- *Fellous et al.'s Cholesky method: "global and less efficient than FFT synthesis", with "an
  incremental refinement method that is local in a limited-precision implementation".* Our Cholesky
  row is the global method: exact where it runs, its plan O(N³) (here, at 256 to 1024 samples,
  evaluating R at every pair still weighs: exponent 2.5 to 3.9 in our runs; the paper's O(N²)
  is the cost of one realization once the factor exists), and refused for gauss and the ring, whose
  covariance matrices are numerically singular (the singular-process section). The local
  refinement is **not built**: the seeds hold neither Fellous et al.'s text nor its equations, and
  its limited-precision locality cannot be reproduced faithfully from one sentence. Exact
  refinement of an existing field is conditional simulation (`synth --condition`, global), and
  its local approximation is generalized subdivision itself.
- *Stochastic subdivision: "local", "approximate f^-d", "creases"; Haruyama-Barsky variances
  widen the spectra, "oscillatory noises are not possible"; Miller "uses a higher quality
  interpolant ... alleviating the problem with creases".* Midpoint displacement and Miller's
  square-square subdivision (`synth midpoint --interpolant miller`) make only fBm and are refused
  for the other targets. Both come out shallower than -3 (table): the coarse levels carry too little
  power against the fine ones; Miller's more so, because every later level's B-spline averaging
  smooths the detail of the earlier ones again, and the displacement variances (the interpolant's
  error variances for fBm, as for midpoint displacement) do not make up for it. What Miller gains
  is the absence of grid-aligned slope breaks (the noise-free limit is a C1 biquadratic spline,
  not a bilinear surface); the crease index of analysis/creases.h does not apply to his scheme,
  whose grid moves by a quarter cell per level. `--variance-scale` is the Haruyama-Barsky-style
  knob, geometric per level: it changes the slope, it cannot make the ring.
- *Poisson faulting: "Brownian noise" only.* Slope -3 within its interval, refused for the rest.
- *Sparse convolution: "equivalent in efficiency to convolution", any spectrum that is the
  transform of the kernel's autocorrelation.* Right on average on every target; its intervals are
  the widest, because at one impulse per cell the field is far from Gaussian (the variance of the
  ACF estimate grows with the kurtosis). For markov the kernel was cut at the 64-sample tile
  (flagged truncated by the method).
- *Interpolated noise lattice: "the low frequency power in the noise lattice is not removed and
  cannot be removed in summation".* Measured: on markov the octave sum's spectrum is 0.4 of the
  target at low frequencies and 0.54 at high ones, and its ACF error is detected; on gauss and the ring the octave
  fit finds no positive weight at all (a spectrum falling faster than the basis), which before this
  comparison gave a field of zeros and is now refused.
- *Wiener interpolation: "greater spectral control (with some restrictions) and eliminates the
  spectral summation".* Our reading (ref. [17] is unpublished): one lattice with the target's own
  covariance at the node lags (FFT on the lattice), every sample its simple-kriging estimate from
  the 4x4 nearest nodes, nodes every 4 samples (`synth lattice --interpolant wiener`). It meets gauss
  and the ring where the Perlin sum cannot; the restriction is markov: nothing above the lattice's
  Nyquist frequency 1/8 is synthesised (high band 0.02 of the target, fractal slope far too steep).
- *Generalized subdivision: "semi-local", "arbitrary spectrum to a desired degree of accuracy",
  refinement of an existing database.* With N = 2 (4x4 neighbourhoods) it is close on markov and
  gauss and detectably off on the ring (its oscillation needs larger neighbourhoods); with
  correlated displacements it meets all three.
- Beyond the paper: circulant embedding (exact on a non-periodic grid, the most memory: the embedding
  is twice the grid per axis) and Keller's rank-1 lattice (its N minimal wave vectors cut the
  spectrum's corners: high band 0.3 on markov).

Not in the table: `ocean` (Tessendorf's Phillips spectrum on a rank-1 lattice, one fixed model) and
`synth --condition` (conditioning, not a synthesis method). The cost exponents are above 1 on
this machine because 512² no longer fits the cache and other work shares the two cores; the verdict
separates linear and n log n methods (exponent below 1.8) from quadratic ones and from Cholesky.

Verdicts (above): the methods that claim exactness (fft, circulant, Cholesky) show no ACF error
on any target they run; every method that claims O(n) or O(n log n) grows below samples^1.8;
Cholesky's plan grows at least as samples² (R at every pair of samples, then the O(N³)
factorisation, which dominates only beyond these sizes); the Wiener lattice reproduces gauss and
the ring within 0.25 of R(0). Broken on purpose: FFT amplitudes 10% high turn fft, circulant
(whose embedding is synthesised by FFT) and the Wiener lattice red; the Wiener weights of the
wrong offset turn its two verdicts red (0.27 and 0.39); an O(n²) term in Miller's refinement
turns its cost verdict red once it dominates at 512² (exponent 2.10; a term 8 times smaller
gave 1.72, not caught: the verdict tells linear from quadratic, not a small quadratic part).
EOF
} > "$md"
echo "compare-methods: $(grep -c '^- PASS' "$d/compare-tables.frag") passed, $(grep -c '^- FAIL' "$d/compare-tables.frag") failed" >&2
rm -f "$d/compare-tables.frag"
exit $status
