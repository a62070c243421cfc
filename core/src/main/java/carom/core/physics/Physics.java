package carom.core.physics;

import carom.core.scene.Scene;

/**
 * The physics a scene calls for, composed once when a run starts (in the spirit of DynamO's
 * pluggable dynamics, interactions and boundaries): how discs fly, what the box's edges do, and the
 * restitution of each kind of contact. Engines read these fields once and call them on hot paths,
 * where each call site sees one implementation.
 */
public final class Physics {
    public final Flight flight;
    public final Boundary boundary;
    public final double pairRestitution;
    public final double wallRestitution;

    private Physics(Flight flight, Boundary boundary, double pairRestitution, double wallRestitution) {
        this.flight = flight;
        this.boundary = boundary;
        this.pairRestitution = pairRestitution;
        this.wallRestitution = wallRestitution;
    }

    public static Physics of(Scene scene) {
        return new Physics(Flight.STRAIGHT, Boundary.of(scene.box()),
                scene.effects().restitution(), scene.effects().wallRestitution());
    }
}
