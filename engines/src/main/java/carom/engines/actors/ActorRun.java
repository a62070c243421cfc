package carom.engines.actors;

import carom.core.BadInputException;
import carom.core.engine.EngineFailure;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.observe.jfr.ActorMailboxEvent;
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
    /** Engine options every actor engine understands. */
    public static final Set<String> TUNABLES = Set.of("cellFactor", "stepFactor", "cellsPerActor", "stallSeconds", "relayMinimums");

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
        this.frame = new StepFrame(scene, options.until(), options.tunable("cellFactor", 2.0),
                options.tunable("stepFactor", 1.0));
        double cellsPerActor = options.tunable("cellsPerActor", 1.0);
        if (!(cellsPerActor >= 1) || cellsPerActor != Math.rint(cellsPerActor) || cellsPerActor > Integer.MAX_VALUE) {
            throw new BadInputException("engine option cellsPerActor: must be a whole number >= 1, got " + cellsPerActor);
        }
        this.stallSeconds = options.tunable("stallSeconds", 60.0);
        if (!(stallSeconds > 0) || Double.isInfinite(stallSeconds)) {
            throw new BadInputException("engine option stallSeconds: must be a finite number > 0, got " + stallSeconds);
        }
        double relay = options.tunable("relayMinimums", 1.0);
        if (relay != 0 && relay != 1) {
            throw new BadInputException("engine option relayMinimums: must be 1 (on) or 0 (the thesis's rule), got " + relay);
        }
        this.relayMinimums = relay == 1;
        this.layout = new BlockLayout(frame.grid, (int) cellsPerActor);
        this.actors = new BlockActor[layout.actors];
        this.timed = new ActorMailboxEvent().isEnabled();
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
                ActorMailboxEvent.emit(engineName, describe(a.id), a.messagesIn, out, -1, a.busyNanos);
            }
        }
        Map<String, Long> counters = new HashMap<>(engineCounters());
        long total = 0;
        for (Kind kind : Kind.values()) {
            counters.put("messages." + kind.counterName, messages[kind.ordinal()]);
            total += messages[kind.ordinal()];
        }
        counters.put("messages", total);
        counters.put("actors", (long) layout.actors);
        counters.put("cellsPerActor", (long) layout.blockCols * layout.blockRows);
        counters.put("steps", grid.steps);
        counters.put("probeWaves", grid.probeWaves);
        counters.put("threads", (long) threads);
        counters.put("relayMinimums", relayMinimums ? 1L : 0L);
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
