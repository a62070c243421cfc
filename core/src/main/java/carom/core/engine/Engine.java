package carom.core.engine;

import carom.core.scene.Scene;
import java.util.List;

/**
 * A way of advancing a scene's discs to a given time. All engines consume the same {@link Scene} and
 * core physics and produce the same {@link RunResult}; they differ only in how they schedule the work.
 * What an engine is and can do (exact or relaxed, samples, checkpoints, threads, effects, settings,
 * counters) is its {@link #spec()}; the methods here are what it does.
 */
public interface Engine {
    /** What this engine is and can do, declared once. */
    EngineSpec spec();

    /** Name used on the command line ({@code --engine NAME}): the spec's. */
    default String name() {
        return spec().name();
    }

    /**
     * Throws {@link carom.core.BadInputException} if the scene needs something this engine does not
     * simulate. Called before any output is written; {@link #run} calls it too. The default refuses
     * every effect the spec does not list ({@link EngineSpec#checkSupports}).
     */
    default void checkSupports(Scene scene) {
        spec().checkSupports(scene);
    }

    /**
     * The threads a run gets when the user names none, given the machine's {@code processors}: all of
     * them, unless the engine knows better.
     */
    default int defaultThreads(int processors) {
        return processors;
    }

    /** The threads this engine runs on when given {@code requested}: those, or 1 without {@link Capability#THREADS}. */
    default int threadsFor(int requested) {
        return spec().can(Capability.THREADS) ? requested : 1;
    }

    /**
     * Throws {@link carom.core.BadInputException} if this engine cannot run on {@code threads}, before
     * anything starts; the default accepts any count (engines without {@link Capability#THREADS} use one).
     */
    default void checkThreads(int threads) {
    }

    RunResult run(Scene scene, RunOptions options);

    /**
     * Continues the run whose state this engine saved as {@code saved} ({@link Checkpoints#save}) to
     * {@code options.until()}; {@code scene} is the run's scene and the options its engine settings,
     * as they were. The result is the whole run's: collisions and counters from t = 0, the initial
     * energy and momentum of the scene. A state that does not fit is an {@link IllegalArgumentException}.
     * Only engines with {@link Capability#CHECKPOINTS} resume; commands refuse {@code --checkpoint} for
     * the others before anything runs, and those ignore {@link RunOptions#checkpoints()}. A checkpoint
     * that names such an engine (none writes one) does not fit either: the default refuses it so.
     */
    default RunResult resume(Scene scene, RunOptions options, byte[] saved) {
        throw new IllegalArgumentException("engine " + name() + " cannot resume from a checkpoint");
    }

    /**
     * This engine over workers already running ({@code ./carom node}), reached through {@code seeds}
     * ("host:port" each): only engines with {@link Capability#NODES}.
     */
    default Engine overWorkers(List<String> seeds) {
        throw new UnsupportedOperationException(name() + " runs on one JVM");
    }
}
