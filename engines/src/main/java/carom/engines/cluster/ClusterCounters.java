package carom.engines.cluster;

import carom.core.engine.Counter;

/** The counters of the cluster engine besides the window protocol's ({@link carom.engines.slabs.WindowCounters}) and the generic ones. */
public final class ClusterCounters {
    public static final Counter NODES = new Counter("nodes", "JVMs of the cluster (the coordinator's and its workers)");
    public static final Counter RECOVERIES = new Counter("recoveries",
            "runs carried on from the last checkpoint after a worker was lost");
    public static final Counter MESSAGE_BYTES = new Counter("messageBytes", "bytes of every message as Akka's serializer writes it");
    public static final Counter MESSAGES_PER_WINDOW = new Counter("messagesPerWindow",
            "messages per window, rounded (every message of the run over the windows)");
    public static final Counter MESSAGE_BYTES_PER_WINDOW = new Counter("messageBytesPerWindow", "message bytes per window, rounded");
    public static final Counter MESSAGE_BYTES_PER_CROSS_EVENT = new Counter("messageBytesPerCrossEvent",
            "message bytes per cross-domain event (contact or migration), rounded");

    private ClusterCounters() {
    }
}
