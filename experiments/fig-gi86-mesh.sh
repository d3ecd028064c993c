#!/bin/sh
# GI '86 Fig. 2 (Lewis 1987 Fig. 3): the planar quadrilateral mesh with a 4x4
# neighbourhood, drawn with the coefficients noiselab computes for the
# isotropic Markov model at spacing 1 (noiselab coeffs).
. "$(dirname "$0")/lib.sh"
"$nl" coeffs --acf markov --dim 2 --levels 1 --spacing0 1 --json > "$d/mesh.json"
# coefficients are row-major over r, c = -1..2 (r along y, c along x)
for k in face edge-x; do
    jq -r --arg k "$k" '.levels[0].classes[] | select(.class == $k) | .coefficients | to_entries[] |
        "\(.key % 4 - 1)\t\(.key / 4 | floor | . - 1)\t\(.value * 1000 | round / 1000)"' "$d/mesh.json" > "$d/mesh-$k.txt"
done
gnuplot -e "face='$d/mesh-face.txt'; edge='$d/mesh-edge-x.txt'; out='$dir/gi86-fig2-mesh.png'" "$top/plots/mesh.gp"
# verdict: the face coefficients of an isotropic model have the square's
# symmetries (mirror in x, in y, and the transpose)
asym=$(jq '[.levels[0].classes[] | select(.class == "face") | .coefficients] | .[0] as $a |
    [range(0; 16) | . as $i | ($i % 4) as $c | ($i / 4 | floor) as $r |
     ([$a[$i] - $a[$r * 4 + 3 - $c], $a[$i] - $a[(3 - $r) * 4 + $c], $a[$i] - $a[$c * 4 + $r]] | map(fabs) | max)] | max' "$d/mesh.json")
verdict=$(awk -v a="$asym" 'BEGIN { print (a <= 1e-12 ? "pass" : "FAIL") }')
cat > "$d/05-mesh.md" <<MD
## GI '86, Fig. 2 (Lewis 1987, Fig. 3): the subdivision mesh

> Planar quadrilateral subdivision mesh using a 4² neighborhood. The vertices 'o' and 'x' are
> estimated using the surrounding 'observation' points '.'.

![mesh](gi86-fig2-mesh.png)

Drawn with the coefficients \`noiselab coeffs --acf markov --dim 2 --levels 1 --spacing0 1\`
computes (eqs. 9-10): the mid-face 'x' from the 16 points around its face (Table 2), the
mid-edge 'o' from the same 4 x 4 block (the edge's neighbourhood is the face's, so it has one row
more on the far side than on the near side). Verdict **$verdict**: the face coefficients of the
isotropic model have the symmetries of the square to $asym (bound 1e-12).

What differs: the paper draws the mesh only; the numbers are ours.
MD
[ "$verdict" = pass ]
