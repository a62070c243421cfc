package carom.engines.vthreads;

/**
 * The virtual-thread scheduler's carrier count. The JDK reads
 * {@code jdk.virtualThreadScheduler.parallelism} once, when the first virtual thread starts, and has no
 * API to change it afterwards, so it is set here before the first run starts any; later runs in the
 * same JVM get whatever the first one set (a benchmark passes {@code -D...parallelism} to each fork's
 * JVM instead). Runs report the carrier count they actually got.
 */
final class Carriers {
    static final String PARALLELISM = "jdk.virtualThreadScheduler.parallelism";
    private static boolean configured;

    private Carriers() {
    }

    /** Sets the carrier count if nothing has yet; returns the count in effect. */
    static synchronized int configure(int threads) {
        if (!configured && System.getProperty(PARALLELISM) == null) {
            System.setProperty(PARALLELISM, Integer.toString(threads));
        }
        configured = true;
        try {
            return Integer.parseInt(System.getProperty(PARALLELISM));
        } catch (NumberFormatException e) {
            return Runtime.getRuntime().availableProcessors();
        }
    }
}
