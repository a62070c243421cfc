package carom.core.scene;

/** How a generate block draws velocities (its {@code velocity} key). */
public sealed interface VelocityDistribution {
    /** Every disc at rest. */
    record AtRest() implements VelocityDistribution {
    }

    /** Each component uniform in [-scale, scale]. */
    record Uniform(double scale) implements VelocityDistribution {
    }

    /**
     * Gaussian components, shifted to zero total momentum and scaled so the block's kinetic energy is
     * exactly {@code count * temperature}.
     */
    record Maxwell(double temperature) implements VelocityDistribution {
    }
}
