# Sourced by experiments that need an isotropic oscillatory model valid in 2D.
# ring_acf N S: the Laguerre-Gauss autocorrelation L_N((r/S)^2) exp(-(r/S)^2)
# as a noiselab expression in r (without the expr: prefix).  In 2D it is
# the Hankel transform of a ring, S(k) ~ k^(2N) exp(-(pi S k)^2), so it is
# positive definite for every N (Laplace transform of u^N J0(b sqrt(u)));
# the ring peaks at k0 = sqrt(N) / (pi S) cycles per sample, with relative
# width about 1 / (2 sqrt(N)).
ring_acf() {
    awk -v n="$1" -v s="$2" 'BEGIN { c = 1; f = 1
        for (k = 0; k <= n; k++) {
            if (k > 0) { c = c * (n - k + 1) / k; f = f * k }
            e = e sprintf("%s%.10g*(r/%g)^%d", k ? (k % 2 ? "-" : "+") : "", c / f, s, 2 * k)
        }
        printf "(%s)*exp(-(r/%g)^2)", e, s }'
}
