package carom.app.checkpoint;

import carom.app.AtomicOutput;
import carom.app.report.Observing;
import carom.core.engine.Checkpoints;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/**
 * The checkpoints of one run of {@code simulate} or {@code resume}: each the engine saves is written to
 * the one file, atomically ({@link AtomicOutput}: the previous checkpoint stays whole until the new one
 * replaces it), with the run's settings and the observables' states at that moment. A signal sets
 * {@link #requestStop}, which the engine reads at its next consistent point.
 */
public final class RunCheckpoints implements Checkpoints {
    private final Path file;
    /** The run's settings; its time, engine state and observables are replaced at each save. */
    private final CheckpointFile settings;
    private final Observing observing;
    private volatile int stopSignal;
    private volatile double lastSaved = Double.NaN;

    /** Checkpoints into {@code file} of a run with {@code settings}, with {@code observing}'s states (or none). */
    public RunCheckpoints(Path file, CheckpointFile settings, Observing observing) {
        this.file = file;
        this.settings = settings;
        this.observing = observing;
    }

    @Override
    public double every() {
        return settings.checkpointEvery();
    }

    @Override
    public boolean stopRequested() {
        return stopSignal != 0;
    }

    /** Asks the run to save and stop: {@code signal} is the number of the signal that asked (2 INT, 15 TERM). */
    public void requestStop(int signal) {
        stopSignal = signal;
    }

    /** The outputs the checkpoints remember, which {@code resume} writes when given none. */
    public SavedOutputs outputs() {
        return settings.outputs();
    }

    /** The signal that asked the run to stop, 0 if none. */
    public int stopSignal() {
        return stopSignal;
    }

    /** The simulated time of the last checkpoint written, NaN before the first. */
    public double lastSaved() {
        return lastSaved;
    }

    @Override
    public void save(double time, byte[] engineState) {
        hold(time, engineState).write();
    }

    /** The observables are taken as they are now, when the engine's state is. */
    @Override
    public Held hold(double time, byte[] engineState) {
        CheckpointFile now = settings.at(time, engineState, observing == null ? List.of() : observing.states(),
                observing == null ? 0 : observing.lastVirialSum());
        return () -> write(now);
    }

    private void write(CheckpointFile now) {
        byte[] bytes = now.encode();
        try (AtomicOutput out = new AtomicOutput()) {
            out.stageFile(file, temp -> Files.write(temp, bytes));
            out.commit();
        }
        lastSaved = now.time();
    }
}
