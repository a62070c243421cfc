package carom.lab.study.eos;

import java.io.PrintWriter;
import java.util.function.LongSupplier;

/**
 * What a study's branch is doing, as a line on a log now and then, for when no progress bar shows
 * (stderr redirected to a file, as for a run of hours): a point takes tens of minutes, and its line
 * when it ends would otherwise be the only sign that the study is alive. At most one line per
 * {@code everyMillis} per branch ({@code --status-every}, 5 minutes by default: often enough to watch,
 * rarely enough to read), the first once that long has passed; the clock is given
 * (milliseconds) so that the pacing can be tested without waiting.
 */
final class StatusLines {
    private final PrintWriter log;
    private final long everyMillis;
    private final LongSupplier clock;
    private long last;

    StatusLines(PrintWriter log, long everyMillis, LongSupplier clock) {
        this.log = log;
        this.everyMillis = everyMillis;
        this.clock = clock;
        this.last = clock.getAsLong();
    }

    /** Prints {@code eos: STATUS} if the last line (or the start) is {@code everyMillis} ago or more. */
    void offer(String status) {
        long now = clock.getAsLong();
        if (now - last < everyMillis) {
            return;
        }
        last = now;
        synchronized (log) {
            log.println("eos: " + status);
            log.flush();
        }
    }
}
