package carom.core.physics;

import carom.core.scene.Effects;
import carom.core.scene.Scene;

/**
 * The physics a scene calls for, composed once when a run starts (in the spirit of DynamO's
 * pluggable dynamics, interactions and boundaries): how discs fly ({@link Flight}: straight lines,
 * or parabolas under gravity), what the box's edges do ({@link Boundary}: walls or periodic), which
 * restitution a contact gets ({@link Restitution}: elastic, constant, or the TC model), what it does
 * along the tangent ({@link Roughness}: nothing for smooth discs, spin for rough ones) and how radii
 * change ({@link GrowthLaw}: rigid, or linear growth), and whether the bottom wall vibrates
 * ({@link VibratingFloor}). Each law's {@code of} picks its implementation
 * from the scene's effects ({@link carom.core.scene.Effect} describes them). Engines read these fields
 * once and call them on hot paths, where each call site then sees exactly one implementation and the
 * JIT inlines it: a scene never pays for an effect it does not name.
 */
public final class Physics {
    public final Flight flight;
    public final Boundary boundary;
    /** Shared template; a run takes its own with {@code restitution.forRun(n)}. */
    public final Restitution restitution;
    public final GrowthLaw growth;
    public final Roughness roughness;
    /** The vibrated floor, or null when the bottom wall stands still (engines choose their floor variant once by it). */
    public final VibratingFloor floor;

    private Physics(Flight flight, Boundary boundary, Restitution restitution, GrowthLaw growth, Roughness roughness,
                    VibratingFloor floor) {
        this.flight = flight;
        this.boundary = boundary;
        this.restitution = restitution;
        this.growth = growth;
        this.roughness = roughness;
        this.floor = floor;
    }

    public static Physics of(Scene scene) {
        Effects e = scene.effects();
        return new Physics(Flight.of(e), Boundary.of(scene.box()), Restitution.of(e).forRun(scene.size()),
                GrowthLaw.of(e), Roughness.of(e), VibratingFloor.of(scene));
    }
}
