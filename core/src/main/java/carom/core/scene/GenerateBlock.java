package carom.core.scene;

import java.util.Arrays;

/**
 * A block of generated discs (the scene's {@code generate} entries): {@code count} discs placed by
 * {@code layout}, of one species or a mixture ({@code species} indices into the scene's species with
 * their {@code fractions}, positive and summing to 1), jittered by up to {@code jitter} times the free
 * gap on the lattices, with velocities drawn from {@code velocity}, all seeded by {@code seed}. See
 * {@link BlockGenerator} for the exact rules.
 */
public record GenerateBlock(Layout layout, int[] species, double[] fractions, long count, double jitter,
                            VelocityDistribution velocity, long seed) {
    public GenerateBlock {
        species = species.clone();
        fractions = fractions.clone();
    }

    /** A single-species block on the rectangular lattice. */
    public GenerateBlock(int species, long count, double jitter, VelocityDistribution velocity, long seed) {
        this(Layout.LATTICE, new int[] {species}, new double[] {1.0}, count, jitter, velocity, seed);
    }

    /** A single-species block on any layout. */
    public static GenerateBlock of(Layout layout, int species, long count, double jitter, VelocityDistribution velocity,
                                   long seed) {
        return new GenerateBlock(layout, new int[] {species}, new double[] {1.0}, count, jitter, velocity, seed);
    }

    @Override
    public int[] species() {
        return species.clone();
    }

    @Override
    public double[] fractions() {
        return fractions.clone();
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof GenerateBlock b && layout == b.layout && Arrays.equals(species, b.species)
                && Arrays.equals(fractions, b.fractions) && count == b.count
                && Double.compare(jitter, b.jitter) == 0 && velocity.equals(b.velocity) && seed == b.seed;
    }

    @Override
    public int hashCode() {
        return Arrays.hashCode(species) * 31 + Long.hashCode(seed) + Long.hashCode(count) * 17 + layout.hashCode();
    }

    @Override
    public String toString() {
        return "GenerateBlock[" + layout.key() + ", species " + Arrays.toString(species) + " fractions "
                + Arrays.toString(fractions) + ", count " + count + ", jitter " + jitter + ", " + velocity + ", seed " + seed + "]";
    }
}
