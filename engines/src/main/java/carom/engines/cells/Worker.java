package carom.engines.cells;

import carom.core.engine.Contacts;
import carom.core.engine.StallGuard;
import carom.core.physics.Boundary;
import carom.core.physics.Flight;
import carom.core.observe.VirialAccumulator;
import carom.core.scene.Scene;

/**
 * What one unit of scheduled work (a stripe row, an actor) counts and defers. Single writer: a
 * worker is used by one thread at a time, and the schedulers sum workers after joining them
 * ({@link StepFrame#result}). A plain counter bag, so its fields are open to every scheduler.
 */
public final class Worker {
    public long pairCollisions;
    public long wallCollisions;
    public long staleEvents;
    public long violations;
    public long preempted;
    public long overruns;
    public long predictions;
    /** Collision virial for the pressure. */
    public final VirialAccumulator virial;
    public final StallGuard stallGuard;
    /** The shared collision physics, reporting to this worker's stall guard. */
    public final Contacts contacts;
    /** Predictions deferred because they reach beyond the worker's band: disc, its stamp, band row. */
    int[] deferred = new int[48];
    int deferredCount;

    Worker(Scene scene, double until, Flight flight, Boundary boundary) {
        this.virial = VirialAccumulator.forRun(until);
        this.stallGuard = new StallGuard(scene);
        this.contacts = new Contacts(flight, boundary, stallGuard);
    }

    void defer(int disc, int stamp, int bandRow) {
        if (deferredCount + 3 > deferred.length) {
            deferred = java.util.Arrays.copyOf(deferred, 2 * deferred.length);
        }
        deferred[deferredCount++] = disc;
        deferred[deferredCount++] = stamp;
        deferred[deferredCount++] = bandRow;
    }
}
