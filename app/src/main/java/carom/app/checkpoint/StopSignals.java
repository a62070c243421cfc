package carom.app.checkpoint;

import java.util.ArrayList;
import java.util.List;
import sun.misc.Signal;
import sun.misc.SignalHandler;

/**
 * SIGINT (Ctrl-C) and SIGTERM during a run with {@code --checkpoint}: instead of the JVM's default
 * (exit at once), the run is asked to save a checkpoint and stop ({@link RunCheckpoints#requestStop});
 * the command then exits with 128 + the signal's number, 130 or 143, as a shell expects of a process a
 * signal ended. A second signal of either kind while the first is being served takes the default
 * course: a user who presses Ctrl-C twice is not kept waiting. Closing restores the handlers found.
 */
public final class StopSignals implements AutoCloseable {
    private record Installed(Signal signal, SignalHandler previous) {
    }

    private final List<Installed> installed = new ArrayList<>();

    private StopSignals() {
    }

    /** Routes SIGINT and SIGTERM to {@code run} until closed. */
    public static StopSignals routeTo(RunCheckpoints run) {
        StopSignals signals = new StopSignals();
        for (String name : new String[] {"INT", "TERM"}) {
            try {
                Signal signal = new Signal(name);
                SignalHandler previous = Signal.handle(signal, s -> signals.stop(run, s));
                signals.installed.add(new Installed(signal, previous));
            } catch (IllegalArgumentException e) {
                // The JVM keeps this signal for itself (-Xrs, some platforms): it keeps its default course.
            }
        }
        return signals;
    }

    private void stop(RunCheckpoints run, Signal s) {
        if (run.stopRequested()) {
            close();
            Signal.raise(s);
            return;
        }
        run.requestStop(s.getNumber());
    }

    /** The exit status of a run a signal stopped: 128 + its number. */
    public static int exitStatus(int signal) {
        return 128 + signal;
    }

    @Override
    public synchronized void close() {
        for (Installed i : installed) {
            Signal.handle(i.signal(), i.previous());
        }
        installed.clear();
    }
}
