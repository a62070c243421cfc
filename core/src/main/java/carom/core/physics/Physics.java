package carom.core.physics;

import carom.core.scene.Effects;
import carom.core.scene.Scene;

/**
 * The physics a scene calls for, composed once when a run starts (in the spirit of DynamO's
 * pluggable dynamics, interactions and boundaries): how discs fly ({@link Flight}: straight lines,
 * or parabolas under gravity), what the box's edges do ({@link Boundary}: walls or periodic), and
 * which restitution a contact gets ({@link Restitution}: elastic, constant, or the TC model).
 * Engines read these fields once and call them on hot paths, where each call site then sees exactly
 * one implementation and the JIT inlines it: a scene never pays for an effect it does not name.
 */
public final class Physics {
    public final Flight flight;
    public final Boundary boundary;
    /** Shared template; a run takes its own with {@code restitution.forRun(n)}. */
    public final Restitution restitution;

    private Physics(Flight flight, Boundary boundary, Restitution restitution) {
        this.flight = flight;
        this.boundary = boundary;
        this.restitution = restitution;
    }

    public static Physics of(Scene scene) {
        Effects e = scene.effects();
        Flight flight = e.hasGravity() ? Flight.parabolic(e.gravityX(), e.gravityY()) : Flight.STRAIGHT;
        Restitution restitution = Restitution.of(e.restitution(), e.wallRestitution(), e.tc());
        return new Physics(flight, Boundary.of(scene.box()), restitution.forRun(scene.size()));
    }
}
