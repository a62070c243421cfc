package carom.engines.actors;

import carom.core.engine.Counter;
import carom.engines.cells.StepGridTunables;
import carom.core.engine.Tunable;
import carom.core.BadInputException;
import carom.core.engine.EngineFailure;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.observe.jfr.EngineEvents;
import carom.core.scene.Scene;
import carom.engines.actors.Protocol.Kind;
import carom.engines.actors.Protocol.ToCell;
import carom.engines.actors.Protocol.ToGrid;
import carom.engines.cells.StepFrame;
import carom.engines.cells.Worker;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.LongAdder;

/**
 * One run of an actor engine: the grid and block actors of the thesis's protocol over a shared
 * {@link StepFrame}; subclasses only deliver messages (Akka, virtual threads) and start and stop
 * whatever runs the actors.
 *
 * <p>The calling thread is the watchdog: it waits for the run to finish and stops it with an
 * {@link EngineFailure} that says where it was when no message has been handled for
 * {@code stallSeconds}. A failure inside any actor ends the run the same way. Whatever happens, the
 * subclass's {@link #shutdown} runs before {@link #run} returns.
 */
public abstract class ActorRun implements BlockActor.Outbox {
    public static final Tunable.Whole CELLS_PER_ACTOR = new Tunable.Whole("cellsPerActor", 1, 1, Integer.MAX_VALUE, "cells",
            "grid cells per block actor (1 is the thesis; cells over threads gives one actor per core; "
                    + "a block is a rectangle as square as possible, whole rows once it reaches a row)");
    public static final Tunable.Real STALL_SECONDS = new Tunable.Real("stallSeconds", 60, 0, true, Tunable.MOST_SECONDS, "seconds",
            "a run in which no message is handled for this long is stopped with error: saying where it was", null);
    public static final Tunable.Flag RELAY_MINIMUMS = new Tunable.Flag("relayMinimums", true,
            "minimum messages also carry the earliest event among the sender's other neighbours (false: the "
                    + "thesis's neighbours-only rule, which lets actors two blocks apart collide one disc at once)");
    /** The settings every actor engine understands. */
    public static final List<Tunable<?>> TUNABLES = List.of(StepGridTunables.CELL_FACTOR, StepGridTunables.STEP_FACTOR,
            CELLS_PER_ACTOR, STALL_SECONDS, RELAY_MINIMUMS);

    private final String engineName;
    protected final StepFrame frame;
    protected final BlockLayout layout;
    protected final BlockActor[] actors;
    protected final GridCoordinator grid;
    protected final int threads;
    private final CompletableFuture<Void> finished = new CompletableFuture<>();
    private final LongAdder heartbeat = new LongAdder();
    private final double stallSeconds;
    private final boolean relayMinimums;
    /** Whether a JFR recording wants mailbox summaries (then actors time their handlers). */
    private final boolean timed;

    protected ActorRun(String engineName, Scene scene, RunOptions options, BlockActor.FaultInjection faults) {
        this.engineName = engineName;
        this.threads = Math.max(1, options.threads());
        this.frame = StepGridTunables.frame(scene, options);
        int cellsPerActor = CELLS_PER_ACTOR.intOf(options);
        this.stallSeconds = STALL_SECONDS.of(options);
        this.relayMinimums = RELAY_MINIMUMS.of(options);
        this.layout = new BlockLayout(frame.grid, cellsPerActor);
        this.actors = new BlockActor[layout.actors];
        this.timed = EngineEvents.mailboxesRecorded();
        for (int a = 0; a < actors.length; a++) {
            actors[a] = new BlockActor(a, frame, layout, this, relayMinimums, faults, heartbeat, timed);
        }
        this.grid = new GridCoordinator(engineName, frame, layout, this::toCell, this::collisions, options.progress(),
                finished, heartbeat);
    }

    /** Creates whatever runs the actors and has the grid start the first step in its own context. */
    protected abstract void start();

    /** Stops every actor and thread of the run; must return promptly, also after a failure. */
    protected abstract void shutdown();

    /** Extra counters of the engine (dispatcher settings and the like). */
    protected abstract Map<String, Long> engineCounters();

    /** Called by the engine when a handler threw: the run ends with an internal failure saying where. */
    protected final void failed(String where, Throwable cause) {
        finished.completeExceptionally(new EngineFailure(where + " failed in step " + grid.steps + ": "
                + cause.getClass().getSimpleName() + ": " + cause.getMessage(), cause));
    }

    protected final String describe(int actor) {
        return layout.describe(actor);
    }

    public final RunResult run() {
        long started = System.nanoTime();
        try {
            start();
            awaitWithWatchdog();
        } finally {
            shutdown();
        }
        double seconds = (System.nanoTime() - started) * 1e-9;
        List<Worker> workers = new ArrayList<>(actors.length);
        long[] messages = grid.sentByKind.clone();
        for (BlockActor a : actors) {
            workers.add(a.worker);
            for (int k = 0; k < messages.length; k++) {
                messages[k] += a.sentByKind[k];
            }
        }
        if (timed) {
            for (BlockActor a : actors) {
                long out = java.util.Arrays.stream(a.sentByKind).sum();
                EngineEvents.actorMailbox(engineName, describe(a.id), a.messagesIn, out, -1, a.busyNanos);
            }
        }
        Map<String, Long> counters = new HashMap<>(engineCounters());
        long total = 0;
        for (Kind kind : Kind.values()) {
            counters.put(Counter.messagesOf(kind.counterName), messages[kind.ordinal()]);
            total += messages[kind.ordinal()];
        }
        counters.put(Counter.MESSAGES.key, total);
        counters.put(ActorCounters.ACTORS.key, (long) layout.actors);
        counters.put(ActorCounters.CELLS_PER_ACTOR.key, (long) layout.blockCols * layout.blockRows);
        counters.put(Counter.STEPS.key, grid.steps);
        counters.put(ActorCounters.PROBE_WAVES.key, grid.probeWaves);
        counters.put(Counter.THREADS.key, (long) threads);
        counters.put(ActorCounters.RELAY_MINIMUMS.key, relayMinimums ? 1L : 0L);
        return frame.result(engineName, workers, seconds, counters);
    }

    /** Collisions so far; read by the grid between steps, when every actor has reported done. */
    private long collisions() {
        long sum = 0;
        for (BlockActor a : actors) {
            sum += a.worker.pairCollisions + a.worker.wallCollisions;
        }
        return sum;
    }

    private void awaitWithWatchdog() {
        long lastBeat = -1;
        long lastChange = System.nanoTime();
        long poll = Math.max(1, Math.min(500, (long) (stallSeconds * 1000 / 4)));
        while (true) {
            try {
                finished.get(poll, TimeUnit.MILLISECONDS);
                return;
            } catch (TimeoutException e) {
                long beat = heartbeat.sum();
                long now = System.nanoTime();
                if (beat != lastBeat) {
                    lastBeat = beat;
                    lastChange = now;
                } else if ((now - lastChange) * 1e-9 >= stallSeconds) {
                    throw new EngineFailure(engineName + ": no progress for " + stallSeconds + " s, stuck at "
                            + grid.whereStuck());
                }
            } catch (ExecutionException e) {
                if (e.getCause() instanceof RuntimeException re) {
                    throw re;
                }
                throw new EngineFailure(engineName + ": " + e.getCause(), e.getCause());
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new EngineFailure(engineName + ": interrupted while waiting for the run");
            }
        }
    }

    @Override
    public abstract void toCell(int actor, ToCell message);

    @Override
    public abstract void toGrid(ToGrid message);
}
