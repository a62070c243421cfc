package carom.core.engine;

/**
 * A counter an engine may report in {@link RunResult#counters()}: its key (as the summary's JSON writes
 * it) and its meaning. Engines put counters by constants of this type and readers (the command line,
 * the lab, tests) read them by the same constants, so that a key is spelled in one place only.
 *
 * <p>The constants here are the generic ones: those of every engine that schedules events, of resting
 * contact and growth (effects, whichever engine simulates them), of time-stepped and message-passing
 * engines, and the threads a run really had ({@link RunResult#threadsUsed} reads those). Each engine
 * family declares its own next to its engine and lists them in its {@link EngineSpec#counters()}.
 * Families of keys with a variable part ({@code messages.TYPE}, {@code slabK.NAME}) are made by
 * {@link #messagesOf} and {@link #perSlab}.
 */
public final class Counter {
    // Every engine that schedules events.
    public static final Counter EVENTS = new Counter("events",
            "events processed: collisions, cell crossings (or list rebuilds) and stale events");
    public static final Counter PREDICTIONS = new Counter("predictions", "collision predictions computed");
    public static final Counter STALE_EVENTS = new Counter("staleEvents",
            "events found stale when their time came (a partner had collided since)");
    public static final Counter CELL_CROSSINGS = new Counter("cellCrossings", "discs crossing into another grid cell, as events");
    public static final Counter LIST_REBUILDS = new Counter("listRebuilds",
            "neighbour lists made again, as events: a disc had moved half the skin (--option skin)");
    public static final Counter RESYNCS = new Counter("resyncs",
            "clock re-anchorings (every disc advanced to one time so clocks stay small)");
    public static final Counter BYTES = new Counter("bytes", "heap held by the run's disc and queue arrays");
    public static final Counter BYTES_PER_DISC = new Counter("bytesPerDisc", "the same over the number of discs, rounded");
    public static final Counter COLLISIONS_BEFORE_RESUME = new Counter("collisionsBeforeResume",
            "collisions before the checkpoint a resumed run started from (collisions per second count the rest)");

    // Runs with growth.
    public static final Counter GROWTH_STAGES = new Counter("growthStages",
            "stages of a growth run: cell grids rebuilt as the discs grew, and at samples");
    public static final Counter RESCALINGS = new Counter("rescalings", "thermostat rescalings of the kinetic energy (growth runs; a sheared box's thermostat)");

    // Exact engines under gravity: resting contact.
    public static final Counter SLEEPS = new Counter("sleeps",
            "discs put to sleep at rest on a wall, a fixed disc or a sleeping disc (under gravity)");
    public static final Counter WAKES = new Counter("wakes", "sleeping discs woken by a collision with a disc that is awake");

    // Time-stepped engines.
    public static final Counter STEPS = new Counter("steps", "time steps of the grid");

    // Message-passing engines.
    public static final Counter MESSAGES = new Counter("messages", "messages sent, all types");

    // The threads a run really had, by what the engine runs on.
    public static final Counter THREADS = new Counter("threads", "worker threads the engine ran on");
    public static final Counter DISPATCHER_THREADS = new Counter("dispatcherThreads", "threads of the akka dispatcher");
    public static final Counter CARRIER_THREADS = new Counter("carrierThreads",
            "carrier threads of the virtual-thread scheduler in this JVM");
    public static final Counter DOMAINS = new Counter("domains", "slabs (domains) the box was cut into");

    /** The generic counters above, in the order they are declared. */
    public static final java.util.List<Counter> GENERIC = java.util.List.of(EVENTS, PREDICTIONS, STALE_EVENTS,
            CELL_CROSSINGS, LIST_REBUILDS, RESYNCS, BYTES, BYTES_PER_DISC, COLLISIONS_BEFORE_RESUME, GROWTH_STAGES,
            RESCALINGS, SLEEPS, WAKES, STEPS, MESSAGES, THREADS, DISPATCHER_THREADS, CARRIER_THREADS, DOMAINS);

    /** The key in the counters map and in the summary's JSON. */
    public final String key;
    /** One line: what is counted. */
    public final String meaning;

    /** A counter called {@code key} (as the summary's JSON writes it) counting what {@code meaning} says. */
    public Counter(String key, String meaning) {
        this.key = key;
        this.meaning = meaning;
    }

    /** {@code messages.TYPE}: messages of one protocol type. */
    public static String messagesOf(String type) {
        return MESSAGES.key + "." + type;
    }

    /** {@code slabK.NAME}: a counter of slab K alone (for example {@code slab0.events}). */
    public static String perSlab(int slab, Counter counter) {
        return "slab" + slab + "." + counter.key;
    }

    @Override
    public String toString() {
        return key;
    }
}
