package carom.core.engine;

/**
 * Every counter an engine may report in {@link RunResult#counters()}: its key (as the summary's JSON
 * writes it) and its meaning. Engines put counters by these constants and readers (the command line,
 * the lab, tests) read them by the same constants, so a key is spelled in one place only. Families
 * of keys with a variable part ({@code messages.TYPE}, {@code slabK.NAME}) are made by
 * {@link #messagesOf} and {@link #perSlab}.
 */
public enum Counter {
    // Every engine that schedules events.
    EVENTS("events", "events processed: collisions, cell crossings (or list rebuilds) and stale events"),
    PREDICTIONS("predictions", "collision predictions computed"),
    STALE_EVENTS("staleEvents", "events found stale when their time came (a partner had collided since)"),
    CELL_CROSSINGS("cellCrossings", "discs crossing into another grid cell, as events"),
    LIST_REBUILDS("listRebuilds", "neighbour lists made again, as events: a disc had moved half the skin (--option skin)"),
    RESYNCS("resyncs", "clock re-anchorings (every disc advanced to one time so clocks stay small)"),
    BYTES("bytes", "heap held by the run's disc and queue arrays"),
    BYTES_PER_DISC("bytesPerDisc", "the same over the number of discs, rounded"),
    COLLISIONS_BEFORE_RESUME("collisionsBeforeResume",
            "collisions before the checkpoint a resumed run started from (collisions per second count the rest)"),

    // Runs with growth (fast, slabs).
    GROWTH_STAGES("growthStages", "stages of a growth run: cell grids rebuilt as the discs grew, and at samples"),
    RESCALINGS("rescalings", "thermostat rescalings of the kinetic energy (growth runs)"),

    // Exact engines under gravity: resting contact.
    SLEEPS("sleeps", "discs put to sleep at rest on a wall, a fixed disc or a sleeping disc (under gravity)"),
    WAKES("wakes", "sleeping discs woken by a collision with a disc that is awake"),

    // Step-grid engines (serial, stripes, the actor engines).
    STEPS("steps", "time steps of the grid"),
    EARLY_STEP_ENDS("earlyStepEnds", "steps ended early because a disc became faster than the step allows (serial)"),
    ROUNDS("rounds", "phase rounds of the stripes (three per step)"),
    OVERRUNS("overruns", "discs that outran the grid within a step (stepFactor above 1)"),
    PREEMPTED("preempted", "stale events that a later collision may have pre-empted (relaxed engines)"),
    THREADS("threads", "worker threads the engine ran on"),

    // Actor engines.
    MESSAGES("messages", "messages sent, all types"),
    ACTORS("actors", "block actors"),
    CELLS_PER_ACTOR("cellsPerActor", "grid cells per block actor"),
    PROBE_WAVES("probeWaves", "termination-detection probe waves"),
    RELAY_MINIMUMS("relayMinimums", "1 when minimum messages relay the second ring's minimum, else 0"),
    DISPATCHER_THREADS("dispatcherThreads", "threads of the akka dispatcher"),
    THROUGHPUT("throughput", "messages an akka actor handles before yielding its thread"),
    CARRIER_THREADS("carrierThreads", "carrier threads of the virtual-thread scheduler in this JVM"),

    // stepped.
    ESCAPES("escapes", "discs found outside a wall before being clamped back"),
    DEEPEST_OVERLAP_PPB("deepestOverlapPpb", "deepest overlap seen, in parts per billion of the contact distance"),

    // slabs.
    DOMAINS("domains", "slabs (domains) the box was cut into"),
    DOMAIN_ROWS("domainRows", "rows the domains are laid out in: 1 for vertical slabs, more for blocks"),
    WINDOWS("windows", "optimistic windows run"),
    COMMITS("commits", "windows verified and kept"),
    ROLLBACKS("rollbacks", "windows undone back to the first cross-slab contact"),
    UNDONE_EVENTS("undoneEvents", "events undone by rollbacks"),
    CROSS_DOMAIN_EVENTS("crossDomainEvents", "contacts between discs of two slabs, processed serially"),
    MIGRATIONS("migrations", "discs moving into another slab"),
    CROSS_PREDICTIONS("crossPredictions", "cross-slab predictions computed at barriers"),
    MERGES("merges", "merged phases begun: one domain runs every disc while the slabs' windows do not pay"),
    MERGED_EVENTS("mergedEvents", "events processed in merged phases"),
    MERGED_CROSS_SLAB_EVENTS("mergedCrossSlabEvents", "events of merged phases that would have been cross-slab ones"),
    // cluster (with the slabs' window counters above and messages, messages.TYPE).
    NODES("nodes", "JVMs of the cluster (the coordinator's and its workers)"),
    RECOVERIES("recoveries", "runs carried on from the last checkpoint after a worker was lost"),
    MESSAGE_BYTES("messageBytes", "bytes of every message as Akka's serializer writes it"),
    MESSAGES_PER_WINDOW("messagesPerWindow", "messages per window, rounded (every message of the run over the windows)"),
    MESSAGE_BYTES_PER_WINDOW("messageBytesPerWindow", "message bytes per window, rounded"),
    MESSAGE_BYTES_PER_CROSS_EVENT("messageBytesPerCrossEvent", "message bytes per cross-domain event (contact or migration), rounded"),
    BARRIER_SPINS("barrierSpins", "busy-wait iterations at the window barrier before a thread parks"),
    SETUP_NANOS("setupNanos", "wall nanoseconds building the table and domains"),
    START_NANOS("startNanos", "wall nanoseconds of the first predictions"),
    WINDOW_NANOS("windowNanos", "wall nanoseconds inside windows"),
    SERIAL_NANOS("serialNanos", "wall nanoseconds in serial phases between windows"),
    FINAL_NANOS("finalNanos", "wall nanoseconds writing the final state"),
    WINDOW_CPU_NANOS("windowCpuNanos", "CPU nanoseconds of all slabs' threads inside windows"),
    SERIAL_CPU_NANOS("serialCpuNanos", "CPU nanoseconds of the serial phases"),
    CRITICAL_CPU_NANOS("criticalCpuNanos", "CPU nanoseconds of the slowest slab in each window, summed over windows");

    /** The key in the counters map and in the summary's JSON. */
    public final String key;
    /** One line: what is counted. */
    public final String meaning;

    Counter(String key, String meaning) {
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
}
