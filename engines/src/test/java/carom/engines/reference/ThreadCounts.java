package carom.engines.reference;

import java.util.concurrent.locks.LockSupport;
import java.util.function.LongSupplier;

/** Counting an engine's threads after it has stopped them. */
public final class ThreadCounts {
    private ThreadCounts() {
    }

    /**
     * The count once it has fallen to {@code atMost}, or whatever it is after 5 s. A pool reports
     * termination when its last worker deregisters, a moment before that thread has exited, so one
     * immediate look can still see it alive.
     */
    public static long settledCount(LongSupplier count, long atMost) {
        long deadline = System.nanoTime() + 5_000_000_000L;
        long now = count.getAsLong();
        while (now > atMost && System.nanoTime() < deadline) {
            LockSupport.parkNanos(10_000_000L);
            now = count.getAsLong();
        }
        return now;
    }
}
