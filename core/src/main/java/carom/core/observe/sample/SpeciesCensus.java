package carom.core.observe.sample;

/**
 * The discs of each species in one sample: how many, their mean and smallest radius. What the
 * species-resolved observables fix at their first sample (and save, to rebuild their geometry).
 */
record SpeciesCensus(long[] counts, double[] meanRadius, double[] minRadius) {
    /** Of {@code s}'s discs, for {@code speciesCount} species (indices beyond the sample's have no discs). */
    static SpeciesCensus of(Sample s, int speciesCount) {
        long[] counts = new long[speciesCount];
        double[] mean = new double[speciesCount];
        double[] min = new double[speciesCount];
        java.util.Arrays.fill(min, Double.POSITIVE_INFINITY);
        // The mean as the first radius plus the mean difference from it: exactly the radius when all are equal.
        double[] first = new double[speciesCount];
        for (int i = 0; i < s.n; i++) {
            int a = s.species[i];
            if (a < 0 || a >= speciesCount) {
                throw new IllegalArgumentException("a disc of species " + a + " of " + speciesCount);
            }
            if (counts[a]++ == 0) {
                first[a] = s.radius[i];
            }
            mean[a] += s.radius[i] - first[a];
            min[a] = Math.min(min[a], s.radius[i]);
        }
        for (int a = 0; a < speciesCount; a++) {
            mean[a] = counts[a] == 0 ? 0 : first[a] + mean[a] / counts[a];
            min[a] = counts[a] == 0 ? 0 : min[a];
        }
        return new SpeciesCensus(counts, mean, min);
    }

    int species() {
        return counts.length;
    }

    void save(StateCodec.Out out) {
        out.put(counts.length).put(counts, counts.length).put(meanRadius, counts.length).put(minRadius, counts.length);
    }

    static SpeciesCensus restore(StateCodec.In in) {
        int species = in.nextSize();
        long[] counts = in.nextLongs(species);
        for (long c : counts) {
            if (c < 0) {
                throw new IllegalArgumentException("species census: negative count");
            }
        }
        return new SpeciesCensus(counts, in.nextDoubles(species), in.nextDoubles(species));
    }
}
