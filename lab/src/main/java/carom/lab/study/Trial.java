package carom.lab.study;

import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.observe.Observables;
import carom.core.physics.Flight;
import carom.core.physics.Physics;
import carom.core.scene.Scene;
import carom.engines.stepped.SteppedEngine;
import carom.lab.run.TrialRecord;
import java.util.Map;
import java.util.function.Consumer;

/**
 * Runs one engine and setting on one scene in this JVM: warm-up runs (untimed, for the JIT), the run to
 * the short horizon whose positions are compared with the reference's (untimed, so it warms the JIT as
 * well), then the timed runs, one {@link TrialRecord} each; the errors are measured on the first timed
 * run and travel in its record. Also the job a worker JVM is given ({@link AccuracyWorker}).
 *
 * @param dt the step for engines with a {@code dt} tunable (the same absolute step at both horizons), else NaN
 */
record Trial(StudyScene studyScene, Setting setting, double until, double shortUntil, double dt, int warmups, int reps) {
    void run(Consumer<TrialRecord> records) {
        Engine engine = Setting.engineNamed(setting.engine());
        Scene full = studyScene.scene(until);
        Scene shortScene = studyScene.scene(shortUntil);
        for (int i = 0; i < warmups; i++) {
            engine.run(full, options(until));
        }
        RunResult atShort = engine.run(shortScene, options(shortUntil));
        for (int i = 0; i < reps; i++) {
            RunResult r = engine.run(full, options(until));
            TrialRecord record = TrialRecord.measured(engine, studyScene.key(), studyScene.discs(), studyScene.seed(),
                    i + 1, tunables(), setting.threads(), r);
            records.accept(i == 0 ? record.withAccuracy(accuracy(full, r, atShort)) : record);
        }
    }

    private Map<String, String> tunables() {
        return Double.isNaN(dt) ? Map.of() : Map.of("dt", Double.toString(dt));
    }

    private RunOptions options(double horizon) {
        return RunOptions.until(horizon).withThreads(setting.threads()).withProgress(null).withTunables(tunables());
    }

    private static TrialRecord.Accuracy accuracy(Scene scene, RunResult r, RunResult atShort) {
        Flight flight = Physics.of(scene).flight;
        double energyStart = Observables.totalEnergy(scene.newDiscs(), flight);
        double energyEnd = Observables.totalEnergy(r.finalState(), flight);
        double z = r.pressure() == null ? Double.NaN : r.pressure().compressibility();
        double zError = r.pressure() == null ? Double.NaN : r.pressure().compressibilityError();
        Map<String, Long> counters = r.counters() == null ? Map.of() : r.counters();
        return new TrialRecord.Accuracy((energyEnd - energyStart) / energyStart, z, zError,
                StateErrors.deepestOverlap(r.finalState(), scene.box()), SteppedEngine.deepestOverlap(r),
                StateErrors.escapes(r.finalState(), scene.box()), counters.getOrDefault(SteppedEngine.ESCAPES.key, -1L),
                atShort.collisions(), atShort.finalState().x.clone(), atShort.finalState().y.clone());
    }
}
