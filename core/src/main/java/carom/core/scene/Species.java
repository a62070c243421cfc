package carom.core.scene;

/**
 * A kind of disc. A fixed species is immovable: infinite mass ({@link #inverseMass()} is 0), zero
 * velocity, unaffected by gravity.
 */
public record Species(String name, double radius, double mass, boolean fixed) {
    public static Species mobile(String name, double radius, double mass) {
        return new Species(name, radius, mass, false);
    }

    public static Species fixed(String name, double radius) {
        return new Species(name, radius, Double.POSITIVE_INFINITY, true);
    }

    public double inverseMass() {
        return fixed ? 0.0 : 1.0 / mass;
    }
}
