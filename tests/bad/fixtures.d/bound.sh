# Fixtures of tests/bad/bound_hostile.cases (sourced by fixtures.sh in the fixture folder; $nl the program).
# Points whose values reach 1e250 (squared differences overflow), and a 1D series of such values.
awk 'BEGIN { srand(7); print "x\ty\tvalue"; for (i = 0; i < 30; i++) printf "%.6f\t%.6f\t%.6g\n", rand(), rand(), (rand() - 0.5) * 1e250 }' >bigvals.tsv
awk 'BEGIN { srand(7); print "x\ty\tvalue"; for (i = 0; i < 30; i++) printf "%.6f\t%.6f\t%.6g\n", rand(), rand(), (rand() - 0.5) * 1e300 }' >hugevals.tsv
awk 'BEGIN { srand(7); print "x\tvalue"; for (i = 0; i < 30; i++) printf "%.6f\t%.6g\n", rand(), (rand() - 0.5) * 1e250 }' >bigvals1.tsv
# 200,000 points over the unit square: about 8e9 pairs within the default cutoff
awk 'BEGIN { srand(5); print "x\ty\tvalue"; for (i = 0; i < 200000; i++) printf "%.5f\t%.5f\t%.4f\n", rand(), rand(), rand() }' >p200k.tsv
# Cloud scenes: 5,000 points; a grid of 128 (1.9e9 covariance evaluations); a point given twice (singular).
cloud_scene() { # N GRID DUP
    awk -v n="$1" -v g="$2" -v dup="$3" 'BEGIN { srand(3); printf "{\"size\": [16, 12], \"box\": [[-3, -1.2, -2], [3, 2.5, 2]], \"points\": [";
        for (i = 0; i < n; i++) { x = 6 * rand() - 3; y = 3.7 * rand() - 1.2; z = 4 * rand() - 2; v = rand();
            printf "%s[%.4f, %.4f, %.4f, %.3f]", i ? ", " : "", x, y, z, v; if (dup) printf ", [%.4f, %.4f, %.4f, %.3f]", x, y, z, v }
        printf "], \"acf\": \"gauss:scale=0.9\", \"noise\": {\"acf\": \"markov:scale=0.12\", \"amplitude\": 0.6, \"period\": 1.6, \"grid\": 8, \"seed\": 3}, ";
        printf "\"threshold\": 0.3, \"extinction\": 9, \"grid\": %d, \"camera\": {\"position\": [0, 0.6, -7], \"look_at\": [0, 0.5, 0], \"fov\": 42}, \"sun\": [0.6, 0.7, -0.4]}\n", g }'
}
cloud_scene 5000 16 0 >cloud5000.json
cloud_scene 2001 8 0 >cloud2001.json
cloud_scene 4 128 0 >cloudgrid128.json
cloud_scene 20 16 1 >clouddup.json
cloud_scene 600 8 1 >clouddup1200.json
# 1,200 points in the unit square, each given twice: a singular kriging system above the pseudo-inverse's limit
awk 'BEGIN { srand(4); print "x\ty\tvalue"; for (i = 0; i < 600; i++) { x = rand(); y = rand(); v = rand(); printf "%.6f\t%.6f\t%.6f\n%.6f\t%.6f\t%.6f\n", x, y, v, x, y, v } }' >dup1200.tsv
