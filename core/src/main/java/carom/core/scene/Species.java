package carom.core.scene;

/**
 * A kind of disc. A fixed species is immovable: infinite mass ({@link #inverseMass()} is 0), zero
 * velocity, unaffected by gravity. {@code inertia} is q of the moment of inertia q·m·R², which only rough
 * discs use (they spin): 1/2, a uniform disc, unless the scene says otherwise.
 */
public record Species(String name, double radius, double mass, boolean fixed, double inertia) {
    /** A uniform disc's moment of inertia, m·R²/2: the default. */
    public static final double UNIFORM_DISC = 0.5;

    public static Species mobile(String name, double radius, double mass) {
        return new Species(name, radius, mass, false, UNIFORM_DISC);
    }

    public static Species fixed(String name, double radius) {
        return new Species(name, radius, Double.POSITIVE_INFINITY, true, UNIFORM_DISC);
    }

    /** This species with moment of inertia {@code q}·m·R². */
    public Species withInertia(double q) {
        return new Species(name, radius, mass, fixed, q);
    }

    public double inverseMass() {
        return fixed ? 0.0 : 1.0 / mass;
    }
}
