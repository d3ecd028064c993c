#!/bin/sh
# Lewis 1987 Fig. 5: stochastic interpolation of a 32 x 32 image (camera.png
# from Debian's python3-skimage data, averaged down by 16 x 16 blocks) to
# 512 x 512 by generalized subdivision seeded with it (external
# consistency), markaussian alpha 1.4, seed 1.  Verdict: every seed sample
# is kept bit for bit.
. "$(dirname "$0")/lib.sh"
"$xb/block_average" "$top/build/exemplars/camera.png" 16 "$d/camera32.exr"
"$nl" synth subdiv --acf markaussian:alpha=1.4,scale=64,var=0.004 --size 512x512 --seed-image "$d/camera32.exr" \
    -o "$d/camera512.exr"
"$nl" render "$d/camera32.exr" --range 0:1 -o "$d/camera32.png"
"$nl" render "$d/camera512.exr" --range 0:1 -o "$d/camera512.png"
# the seed samples at every 16th sample of the result, compared exactly
"$nl" hist "$d/camera32.exr" --json > "$d/c32.json"
kept=$("$xb/seed_kept" "$d/camera32.exr" "$d/camera512.exr" 16)
gnuplot -e "f1='$d/camera32.png'; f2='$d/camera512.png'; t1='seed: 32 x 32 block average'; t2='stochastic interpolation to 512 x 512'; out='$dir/lewis87-fig5-interpolation.png'" "$top/plots/pair.gp"
verdict=FAIL
[ "$kept" = "1024 of 1024" ] && verdict=pass
cat > "$d/24-interpolation.md" <<MD
## Lewis 1987, Fig. 5: stochastic interpolation (external consistency)

> Stochastic interpolation of the low-resolution (32x32 pixels) image at upper left, illustrating
> the external consistency property of stochastic subdivision.

![interpolation](lewis87-fig5-interpolation.png)

\`noiselab synth subdiv --seed-image camera32.exr --acf markaussian:alpha=1.4,scale=64,var=0.004\`:
four levels from the 32 x 32 block average of the camera image (skimage's camera.png; the
paper's image is not named). Verdict: seed samples kept exactly in the result: $kept ($verdict).

What differs: the paper's model and variance are not given; ours adds detail with a standard
deviation of 0.06 (in [0, 1] grey units) at the coarsest level, shrinking with the level. The
subdivision is periodic, so the last rows and columns blend toward the opposite border (the
light band at the bottom is the sky wrapping around); a non-periodic seeding would need the
image's surroundings.
MD
[ "$verdict" = pass ]
