package carom.core.scene;

/**
 * A block of generated discs on the lattice layout (SPEC "generate"): {@code count} discs of one
 * species, site k row-major from the bottom-left, jittered by up to {@code jitter} times the free gap.
 */
public record GenerateBlock(int species, long count, double jitter, VelocityDistribution velocity, long seed) {
}
