package carom.core.engine;

import carom.core.scene.Scene;

/**
 * A way of advancing a scene's discs to a given time. All engines consume the same {@link Scene} and
 * core physics and produce the same {@link RunResult}; they differ only in how they schedule the work.
 *
 * <p>An exact engine gives the serial reference's final state to rounding. A relaxed one may reorder
 * causally linked events and says so in {@link #exact()}.
 */
public interface Engine {
    /** Name used on the command line ({@code --engine NAME}). */
    String name();

    boolean exact();

    /** One line for {@code carom engines}. */
    String description();

    /**
     * Throws {@link carom.core.BadInputException} if the scene needs an effect this engine does not
     * simulate. Called before any output is written; {@link #run} calls it too. The default accepts
     * every effect but growth, which only engines that say {@link #supportsGrowth} simulate.
     */
    default void checkSupports(Scene scene) {
        if (scene.effects().grows() && !supportsGrowth()) {
            throw new carom.core.BadInputException("effects.growth: engine " + name()
                    + " does not simulate growing discs (engines that do: fast, slabs)");
        }
    }

    /** Whether this engine simulates the {@code growth} effect (radii growing in time). */
    default boolean supportsGrowth() {
        return false;
    }

    /**
     * The settings ({@code --option key=value}) this engine understands, each declared once with its
     * type, default, range and meaning; any other key, and any value that does not parse, is bad input
     * ({@link Tunables#check}), so that a typo never silently changes a run.
     */
    default java.util.List<Tunable<?>> tunables() {
        return java.util.List.of();
    }

    /**
     * Whether this engine can hand out samples at given times ({@link RunOptions#sampler()}): the exact
     * engines can. {@link #run} of one that cannot refuses options with a sampler as bad input.
     */
    default boolean samples() {
        return false;
    }

    /**
     * Whether this engine tells {@link RunOptions#collisions()} every pair and wall collision it carries
     * out (one that does not ignores the observer).
     */
    default boolean tellsCollisions() {
        return false;
    }

    /**
     * The threads a run gets when the user names none, given the machine's {@code processors}: all of
     * them, unless the engine knows better.
     */
    default int defaultThreads(int processors) {
        return processors;
    }

    /** The threads this engine runs on when given {@code requested} (single-threaded engines: 1). */
    default int threadsFor(int requested) {
        return requested;
    }

    RunResult run(Scene scene, RunOptions options);

    /**
     * Whether this engine can save its state while it runs ({@link RunOptions#checkpoints()}) and
     * continue from it ({@link #resume}) to the same bits as a run that never stopped. Commands refuse
     * {@code --checkpoint} for one that cannot, before anything runs; it ignores
     * {@link RunOptions#checkpoints()}.
     */
    default boolean checkpoints() {
        return false;
    }

    /**
     * Continues the run whose state this engine saved as {@code saved} ({@link Checkpoints#save}) to
     * {@code options.until()}; {@code scene} is the run's scene and the options its engine settings,
     * as they were. The result is the whole run's: collisions and counters from t = 0, the initial
     * energy and momentum of the scene. A state that does not fit is an {@link IllegalArgumentException}.
     */
    default RunResult resume(Scene scene, RunOptions options, byte[] saved) {
        throw new UnsupportedOperationException(name() + " cannot resume from a checkpoint");
    }
}
