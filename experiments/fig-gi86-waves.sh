#!/bin/sh
# GI '86 Fig. 6, the shaped impulse process waves: rough waves shaded as an
# obliquely illuminated height field, and a perspective view of a wave-like
# texture.  Sparse convolution with a directional band-pass kernel
# h = cos(0.3 x + 0.1 y) exp(-(x^2 + y^2)/200), 32 impulses per cell, seed 3.
. "$(dirname "$0")/lib.sh"
k='cos(0.3*x+0.1*y)*exp(-(x*x+y*y)/200)'
"$nl" synth sparse --kernel "$k" --radius 32 --density 32 --size 512x512 --seed 3 --wrap -o "$d/waves.exr"
"$nl" render "$d/waves.exr" --shade 315,35 --zscale 1.2 -o "$dir/gi86-fig6-rough-waves.png"
"$nl" synth sparse --kernel "$k" --radius 32 --density 32 --size 256x256 --seed 4 --wrap -o "$d/waves-p.exr"
landscape "$d/waves-p.exr" "$dir/gi86-fig6-waves-perspective.png" 0.8 --sea --tile --camera 128,-20,10 --look 90,6 \
    --sun 60,25 --haze 400
# verdict: the radial spectrum peaks at the kernel's frequency
# f0 = |(0.3, 0.1)| / 2 pi; the kernel's spectrum is a Gaussian blob of
# standard deviation 1 / (2 pi sqrt(100)) = 0.016 cycles per sample around it,
# and we require the peak within half of that
fpk=$(psd_peak "$d/waves.exr")
f0=$(awk 'BEGIN { printf "%.4f", sqrt(0.09 + 0.01) / (8 * atan2(1, 1)) }')
verdict=$(awk -v a="$fpk" -v b="$f0" 'BEGIN { print ((a - b) ^ 2 <= 0.008 ^ 2 ? "pass" : "FAIL") }')
fpk=$(printf '%.4f' "$fpk")
cat > "$d/52-waves.md" <<MD
## GI '86, Fig. 6: rough waves and a wave-like texture in perspective

> Several shaped impulse process textures. Counterclockwise from top right: rough waves (shaded
> as an obliquely illuminated height field), [...] The last figure is a perspective view of a
> wave-like texture.

![rough waves](gi86-fig6-rough-waves.png)

![waves in perspective](gi86-fig6-waves-perspective.png)

\`noiselab synth sparse --kernel '$k' --radius 32 --density 32 --wrap\`: Poisson impulses
convolved with a directional band-pass kernel (a plane wave under a Gaussian window), 512 x 512
shaded from the north-west, and 256 x 256 in perspective (\`noiselab render --perspective --sea\`,
tiled to the horizon, 0.8 samples of height per standard deviation).
Verdict **$verdict**: the radial spectrum peaks at f = $fpk cycles per sample against the
kernel's $f0 (bound: half the kernel's spectral width, 0.008).

What differs: the paper's kernels are not given; ours is chosen to look like wind waves. The
crests are short because the window is: a longer window gives longer, more regular crests.
MD
[ "$verdict" = pass ]
