package carom.core.scene;

/**
 * The simulation box [0,width] x [0,height] and what its edges do. A Lees-Edwards box is periodic
 * ({@link #periodic}: both axes wrap) and sheared: its image above moves with x velocity
 * {@code shearRate * height} relative to it, the one below with the opposite; {@code shearRate} is 0
 * for every other boundary. A sheared box may hold a thermostat: the temperature kT its discs'
 * peculiar velocities (less the streaming velocity shearRate·y) are rescaled to at every sample
 * ({@link #thermostatted}); 0 without.
 */
public record Box(double width, double height, BoundaryKind boundary, double shearRate, double thermostat) {
    /** A box that is not sheared. */
    public Box(double width, double height, BoundaryKind boundary) {
        this(width, height, boundary, 0, 0);
    }

    /** A box sheared at {@code shearRate} without a thermostat. */
    public Box(double width, double height, BoundaryKind boundary, double shearRate) {
        this(width, height, boundary, shearRate, 0);
    }

    /** Whether a thermostat rescales the peculiar velocities at every sample. */
    public boolean thermostatted() {
        return thermostat > 0;
    }

    /** Whether both axes wrap (periodic, or Lees-Edwards). */
    public boolean periodic() {
        return boundary != BoundaryKind.WALLS;
    }

    /** Whether the images above and below slide (Lees-Edwards boundaries). */
    public boolean sheared() {
        return boundary == BoundaryKind.LEES_EDWARDS;
    }

    public double area() {
        return width * height;
    }
}
