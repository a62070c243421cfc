package carom.core.scene;

/** The simulation box [0,width] x [0,height] and what its edges do. */
public record Box(double width, double height, BoundaryKind boundary) {
    public boolean periodic() {
        return boundary == BoundaryKind.PERIODIC;
    }

    public double area() {
        return width * height;
    }
}
