package carom.app.study;

import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.observe.Observables;
import carom.core.physics.Flight;
import carom.core.physics.Physics;
import carom.core.scene.Scene;
import carom.engines.stepped.SteppedEngine;
import java.util.HashMap;
import java.util.Map;

/**
 * Runs one engine and setting on one scene in this JVM: warm-up runs (untimed, for the JIT), the run to
 * the short horizon whose positions are compared with the reference's (untimed, so it warms the JIT as
 * well), then the timed runs; the errors are measured on the first timed run.
 *
 * @param dt the step for engines with a {@code dt} tunable (the same absolute step at both horizons), else NaN
 */
record Trial(StudyScene studyScene, Setting setting, double until, double shortUntil, double dt, int warmups, int reps) {
    Measured run() {
        Engine engine = Setting.engineNamed(setting.engine());
        Scene full = studyScene.scene(until);
        Scene shortScene = studyScene.scene(shortUntil);
        for (int i = 0; i < warmups; i++) {
            engine.run(full, options(until));
        }
        RunResult atShort = engine.run(shortScene, options(shortUntil));
        double[] seconds = new double[reps];
        RunResult first = null;
        for (int i = 0; i < reps; i++) {
            RunResult r = engine.run(full, options(until));
            seconds[i] = r.wallSeconds();
            if (first == null) {
                first = r;
            }
        }
        return measure(full, first, seconds, atShort);
    }

    private RunOptions options(double horizon) {
        Map<String, String> tunables = new HashMap<>();
        if (!Double.isNaN(dt)) {
            tunables.put("dt", Double.toString(dt));
        }
        return new RunOptions(horizon, setting.threads(), null, tunables);
    }

    private Measured measure(Scene scene, RunResult r, double[] seconds, RunResult atShort) {
        Flight flight = Physics.of(scene).flight;
        double energyStart = Observables.totalEnergy(scene.newDiscs(), flight);
        double energyEnd = Observables.totalEnergy(r.finalState(), flight);
        double z = r.pressure() == null ? Double.NaN : r.pressure().compressibility();
        double zError = r.pressure() == null ? Double.NaN : r.pressure().compressibilityError();
        Map<String, Long> counters = r.counters() == null ? Map.of() : r.counters();
        return new Measured(seconds, r.collisions(), (energyEnd - energyStart) / energyStart, z, zError,
                r.violationsPerMillionCollisions(),
                StateErrors.deepestOverlap(r.finalState(), scene.box()), SteppedEngine.deepestOverlap(r),
                StateErrors.escapes(r.finalState(), scene.box()), counters.getOrDefault(SteppedEngine.ESCAPES, -1L),
                counters.getOrDefault("carrierThreads", -1L), atShort.collisions(),
                atShort.finalState().x.clone(), atShort.finalState().y.clone());
    }
}
