package carom.core.observe;

import java.util.List;

/**
 * Told every collision an exact engine carries out, at its time, with its impulse: the seam for
 * observables that need events rather than sampled states (the stress tensor, collision statistics).
 * Engines hold one (or none: {@link carom.core.engine.RunOptions#collisions()} is null, and a run then
 * pays only a null test per collision). Called on the thread that carried the collision out, in the
 * order of that thread's events; an observer must not change the simulation and must not allocate.
 * Collisions at exactly a sample's time come after that sample, as the engine's other events do.
 *
 * <p>Units are the scene's: {@code time} absolute simulated time; the impulse {@code j} is the
 * magnitude of the momentum change along the normal ({@code (nx, ny)}, a unit vector from the first
 * disc to the second, or out of the wall); {@code dx, dy} the centre-to-centre vector at contact (the
 * nearest image in a periodic box).
 */
public interface CollisionObserver {
    /** Discs {@code i} and {@code k} collided at {@code time}: {@code i} lost momentum {@code j} along n, {@code k} gained it. */
    void pair(double time, int i, int k, double dx, double dy, double nx, double ny, double j);

    /** Disc {@code i} hit wall {@code wall} ({@link carom.core.physics.Boundary#LEFT} and so on) at {@code time} with impulse {@code j}. */
    void wall(double time, int i, int wall, double j);

    /**
     * One observer that tells each of {@code observers} every collision, in list order: null for none
     * (so that the engine pays only its null test), the observer itself for one.
     */
    static CollisionObserver all(List<? extends CollisionObserver> observers) {
        return switch (observers.size()) {
            case 0 -> null;
            case 1 -> observers.getFirst();
            default -> new CollisionFanOut(observers.toArray(new CollisionObserver[0]));
        };
    }
}
