package carom.lab.bench;

import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import carom.core.scene.StandardScenes;
import carom.engines.EngineCatalog;

/**
 * A periodic gas run from the lattice with the serial reference engine for about two collisions per
 * disc, then given an end time that yields about {@code collisionsPerDisc} more, from the measured rate.
 * Serial by name, not the default engine: exact engines agree only to rounding, which a chaotic gas
 * amplifies, and every recorded measurement (the lab's notes) started from serial's state.
 */
record Equilibrated(Scene scene, double collisionRatePerDisc) {
    static Equilibrated gas(int n, double phi, double collisionsPerDisc) {
        // Rough rate guess (Enskog-like growth with phi) just to size the equilibration run.
        double guessPerDiscPerTime = 4 * phi / (1 - phi);
        Scene lattice = StandardScenes.gas(n, phi, true, 2 / guessPerDiscPerTime, 42);
        RunResult warm = EngineCatalog.byName("serial").run(lattice, RunOptions.until(lattice.until()));
        double rate = warm.pairCollisions() / (double) n / lattice.until();
        double until = collisionsPerDisc / rate;
        return new Equilibrated(lattice.withState(warm.finalState()).withUntil(until), rate);
    }
}
