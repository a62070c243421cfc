package carom.engines.stripes;

import carom.engines.cells.StepGridCounters;
import carom.core.engine.Counter;
import carom.engines.cells.StepGridTunables;
import carom.core.engine.ProgressListener;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.observe.jfr.EngineEvents;
import carom.engines.cells.CellStepWork;
import carom.engines.cells.Worker;
import carom.core.scene.Scene;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ForkJoinPool;
import java.util.stream.IntStream;

/**
 * One run of the stripes engine.
 *
 * <h2>Why it is race-free</h2>
 * Processing a cell touches only cells within one row of it ({@link CellStepWork} contract), so rows
 * three apart never share data: walled boxes use phase r mod 3; a periodic box whose row count is not
 * a multiple of three gives its last one or two rows phases of their own, so that rows adjacent across
 * the wrap never run together. Each row has its own {@link Worker}, summed in row order, so a run is
 * deterministic for any thread count.
 *
 * <h2>Why phases repeat</h2>
 * A row can receive new potentials after its phase ran (from a neighbouring row's collisions, or
 * from predictions deferred to the phase barrier); the three phases repeat until no cell has an event
 * left in the step.
 */
final class StripesRun {
    private final CellStepWork work;
    private final int threads;
    private final ProgressListener progress;
    private final int[][] phases;
    private final List<Worker> workers = new ArrayList<>();

    StripesRun(Scene scene, RunOptions options) {
        this.work = new CellStepWork(scene, options.until(), StepGridTunables.CELL_FACTOR.of(options),
                StepGridTunables.STEP_FACTOR.of(options));
        this.threads = Math.max(1, options.threads());
        this.progress = options.progress();
        int rows = work.grid.rows;
        for (int r = 0; r < rows; r++) {
            workers.add(work.newWorker());
        }
        this.phases = phasesFor(rows, scene.box().periodic());
    }

    static int[][] phasesFor(int rows, boolean periodic) {
        int regular = periodic ? rows - rows % 3 : rows;
        int[] phaseOf = new int[rows];
        int phaseCount = Math.min(3, rows);
        for (int r = 0; r < rows; r++) {
            phaseOf[r] = r < regular ? r % 3 : 3 + (r - regular);
            phaseCount = Math.max(phaseCount, phaseOf[r] + 1);
        }
        int[][] result = new int[phaseCount][];
        for (int p = 0; p < phaseCount; p++) {
            final int phase = p;
            result[p] = IntStream.range(0, rows).filter(r -> phaseOf[r] == phase).toArray();
        }
        return result;
    }

    RunResult run() {
        long started = System.nanoTime();
        long steps = 0;
        long rounds = 0;
        double until = work.until();
        ForkJoinPool pool = new ForkJoinPool(threads);
        try {
            double epoch = 0;
            while (epoch < until) {
                double remaining = until - epoch;
                Object stepEvent = EngineEvents.stepStarted();
                long stepCollisions = 0;
                double length = work.beginStep(epoch, remaining);
                steps++;
                int cols = work.grid.cols;
                pool.submit(() -> IntStream.range(0, work.grid.rows).parallel().forEach(r -> {
                    for (int c = r * cols; c < (r + 1) * cols; c++) {
                        work.findPotentials(c, workers.get(r));
                    }
                })).join();
                long processed;
                do {
                    rounds++;
                    processed = 0;
                    for (int[] phase : phases) {
                        processed += pool.submit(() -> Arrays.stream(phase).parallel()
                                .mapToLong(this::processRow).sum()).join();
                        for (int r : phase) {
                            work.completeDeferred(workers.get(r));
                        }
                    }
                    stepCollisions += processed; // the round's events, each one collision
                } while (processed > 0 || anyEventLeft());
                work.endStep();
                EngineEvents.stepFinished(stepEvent, "stripes", steps, epoch, epoch + length, stepCollisions);
                epoch = length >= remaining ? until : epoch + length;
                progress.simulatedTime(epoch);
            }
        } finally {
            pool.shutdownNow();
            awaitQuietly(pool);
        }
        double seconds = (System.nanoTime() - started) * 1e-9;
        return work.result("stripes", workers, seconds, Map.of(Counter.STEPS.key, steps, StepGridCounters.ROUNDS.key, rounds));
    }

    /** No worker may outlive the run, also after a failure inside a task. */
    private static void awaitQuietly(ForkJoinPool pool) {
        try {
            pool.awaitTermination(10, java.util.concurrent.TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private long processRow(int r) {
        Worker w = workers.get(r);
        int cols = work.grid.cols;
        long taken = 0;
        for (int c = r * cols; c < (r + 1) * cols; c++) {
            taken += work.processCell(c, w);
        }
        return taken;
    }

    private boolean anyEventLeft() {
        for (int c = 0; c < work.grid.cellCount(); c++) {
            if (work.hasEventInStep(c)) {
                return true;
            }
        }
        return false;
    }
}
