package carom.engines.actors;

import carom.core.engine.Counter;
import carom.engines.cells.StepGridCounters;
import java.util.List;
import java.util.stream.Stream;

/** The counters of the actor engines (akka, vthreads) besides the generic {@link Counter}s and the step grid's. */
public final class ActorCounters {
    public static final Counter ACTORS = new Counter("actors", "block actors");
    public static final Counter CELLS_PER_ACTOR = new Counter("cellsPerActor", "grid cells per block actor");
    public static final Counter PROBE_WAVES = new Counter("probeWaves", "termination-detection probe waves");
    public static final Counter RELAY_MINIMUMS = new Counter("relayMinimums",
            "1 when minimum messages relay the second ring's minimum, else 0");
    public static final Counter THROUGHPUT = new Counter("throughput", "messages an akka actor handles before yielding its thread");

    /** Those every actor run reports: the relaxed step grid's and the actors' (akka adds its {@link #THROUGHPUT}). */
    public static final List<Counter> EVERY_RUN = Stream.concat(StepGridCounters.RELAXED.stream(),
            Stream.of(ACTORS, CELLS_PER_ACTOR, PROBE_WAVES, RELAY_MINIMUMS)).toList();

    private ActorCounters() {
    }
}
