package carom.lab.bench;

import carom.engines.cells.StepGridTunables;
import carom.engines.actors.ActorRun;
import carom.core.BadInputException;
import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.scene.Scene;
import carom.engines.EngineCatalog;
import carom.engines.cells.StepFrame;
import carom.engines.vthreads.VThreadsEngine;
import carom.lab.run.Carriers;

/**
 * The engine and run options of one benchmark trial, built from the benchmark's parameters and
 * checked, so that a trial measures what its parameters say or fails before it measures anything.
 *
 * <p>{@code threads} is what every engine gets as cores: the stripes engine's ForkJoinPool
 * parallelism, the akka dispatcher's parallelism-min = parallelism-max, and for vthreads the virtual
 * thread scheduler's carrier count ({@link #fixCarriers}). Single-thread engines (serial, fast, stepped) ignore it.
 */
record EngineSetup(Engine engine, RunOptions options) {
    /** {@code cellsPerActor} value meaning one block of whole rows per thread: cells / threads. */
    static final String PER_THREAD = "perThread";

    /**
     * @param cellsPerActor "" for the engine's default, a whole number, or {@link #PER_THREAD};
     *                      applied only to engines that list the {@code cellsPerActor} tunable
     *                      (the actor engines), ignored by the others
     * @param tunables      {@code key=value;key=value}, each key one the engine lists
     */
    static EngineSetup of(String engineName, Scene scene, int threads, String cellsPerActor, String tunables) {
        Engine engine = EngineCatalog.byName(engineName);
        RunOptions options = Tunables.apply(engine, RunOptions.until(scene.until()).withThreads(threads), tunables);
        if (!cellsPerActor.isBlank() && carom.core.engine.Tunables.declares(engine.spec().tunables(), ActorRun.CELLS_PER_ACTOR.name())) {
            if (options.tunables().containsKey("cellsPerActor")) {
                throw new BadInputException("cellsPerActor given twice: as the parameter and in tunables");
            }
            String value = cellsPerActor.equals(PER_THREAD)
                    ? Integer.toString(cellsPerThread(scene, options, threads))
                    : cellsPerActor;
            options = options.withTunable("cellsPerActor", value);
        }
        if (engine instanceof VThreadsEngine) {
            fixCarriers(threads);
        }
        return new EngineSetup(engine, options);
    }

    /**
     * Cells per actor that give one actor per thread: the actor engines' grid (the same
     * {@link StepFrame} they build) divided among the threads, rounded up, which the block layout turns
     * into blocks of whole rows once a block reaches a row.
     */
    static int cellsPerThread(Scene scene, RunOptions options, int threads) {
        StepFrame frame = StepGridTunables.frame(scene, options);
        return Math.ceilDiv(frame.grid.cellCount(), Math.max(1, threads));
    }

    /**
     * Makes this JVM's virtual-thread scheduler have exactly {@code threads} carriers, or fails.
     *
     * <p>The JDK reads {@link Carriers#PARALLELISM} once, when the JVM's first virtual thread starts, and a
     * JMH {@code @Fork} cannot take a {@code @Param} into its JVM arguments. Each trial runs in a
     * fresh fork in which nothing has started a virtual thread yet, so setting the property here is
     * equivalent to a {@code -D} on the fork's command line; a {@code -D} that is given
     * ({@code -jvmArgsAppend -Djdk.virtualThreadScheduler.parallelism=K}) must agree with
     * {@code threads}. Then the scheduler itself is asked ({@link Carriers#current}) whether it got
     * that count, which catches a virtual thread started earlier and {@code -f 0} (every trial in one
     * JVM, whose carriers the first trial fixed).
     */
    static void fixCarriers(int threads) {
        String given = System.getProperty(Carriers.PARALLELISM);
        if (given == null) {
            System.setProperty(Carriers.PARALLELISM, Integer.toString(threads));
        } else if (!given.trim().equals(Integer.toString(threads))) {
            throw new IllegalStateException(Carriers.PARALLELISM + " is " + given + " in this JVM but the trial asks for threads = "
                    + threads + ": drop the -D (each fork sets it from threads) or make it agree, and keep forking (-f 1 or more)");
        }
        int actual = Carriers.current();
        if (actual != threads) {
            throw new IllegalStateException("the virtual thread scheduler has " + actual + " carriers, not threads = " + threads
                    + ": its size was fixed before this trial (an earlier trial in the same JVM, -f 0?)");
        }
    }
}
