# Fixtures of tests/bad/bound_hostile.cases (sourced by fixtures.sh in the fixture folder; $nl the program).
# Points whose values reach 1e250 (squared differences overflow), and a 1D series of such values.
awk 'BEGIN { srand(7); print "x\ty\tvalue"; for (i = 0; i < 30; i++) printf "%.6f\t%.6f\t%.6g\n", rand(), rand(), (rand() - 0.5) * 1e250 }' >bigvals.tsv
awk 'BEGIN { srand(7); print "x\ty\tvalue"; for (i = 0; i < 30; i++) printf "%.6f\t%.6f\t%.6g\n", rand(), rand(), (rand() - 0.5) * 1e300 }' >hugevals.tsv
awk 'BEGIN { srand(7); print "x\tvalue"; for (i = 0; i < 30; i++) printf "%.6f\t%.6g\n", rand(), (rand() - 0.5) * 1e250 }' >bigvals1.tsv
# 200,000 points over the unit square: about 8e9 pairs within the default cutoff
awk 'BEGIN { srand(5); print "x\ty\tvalue"; for (i = 0; i < 200000; i++) printf "%.5f\t%.5f\t%.4f\n", rand(), rand(), rand() }' >p200k.tsv
