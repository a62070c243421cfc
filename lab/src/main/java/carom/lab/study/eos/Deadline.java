package carom.lab.study.eos;

import carom.core.BadInputException;
import java.time.Duration;
import java.time.Instant;
import java.time.format.DateTimeParseException;
import java.util.Locale;
import java.util.function.LongSupplier;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The wall-clock time by which the study stops running (then writes its report), and, with
 * {@code fill}, the pacing that spreads the time left evenly over the points still to run. The clock is
 * given (milliseconds since the epoch) so that the runner's reaction to a deadline can be tested
 * without waiting for one.
 *
 * @param endMillis the deadline, milliseconds since the epoch ({@link Long#MAX_VALUE}: none)
 * @param fill      whether each point runs for its share of the time left rather than a fixed number of blocks
 * @param clock     the wall clock, milliseconds since the epoch
 */
record Deadline(long endMillis, boolean fill, LongSupplier clock) {
    static final Deadline NONE = new Deadline(Long.MAX_VALUE, false, System::currentTimeMillis);
    private static final Pattern DURATION = Pattern.compile("(\\d+(?:\\.\\d+)?)(s|m|h)");

    /**
     * The deadline {@code text} says: an ISO-8601 instant ({@code 2026-12-02T01:05:00Z}) or a duration
     * from now ({@code 90s}, {@code 70m}, {@code 2.5h}); bad input otherwise, or if it has passed.
     */
    static Deadline parse(String text, boolean fill, LongSupplier clock) {
        long now = clock.getAsLong();
        long end;
        Matcher m = DURATION.matcher(text.trim().toLowerCase(Locale.ROOT));
        if (m.matches()) {
            double unit = switch (m.group(2)) {
                case "s" -> 1e3;
                case "m" -> 60e3;
                default -> 3600e3;
            };
            end = now + (long) (Double.parseDouble(m.group(1)) * unit);
        } else {
            try {
                end = Instant.parse(text.trim()).toEpochMilli();
            } catch (DateTimeParseException e) {
                throw new BadInputException("--deadline: " + carom.core.Quoted.of(text) + " is neither an instant such as "
                        + "2026-12-02T01:05:00Z nor a duration such as 90s, 70m or 2h");
            }
        }
        if (end <= now) {
            throw new BadInputException("--deadline: " + carom.core.Quoted.of(text) + " has passed");
        }
        return new Deadline(end, fill, clock);
    }

    boolean passed() {
        return clock.getAsLong() >= endMillis;
    }

    /** Seconds until the deadline (infinite without one). */
    double secondsLeft() {
        return endMillis == Long.MAX_VALUE ? Double.POSITIVE_INFINITY : (endMillis - clock.getAsLong()) / 1e3;
    }

    /** Wall seconds the next point gets when {@code pointsLeft} (it included) remain: infinite unless filling. */
    double shareSeconds(int pointsLeft) {
        return fill ? Math.max(0, secondsLeft()) / pointsLeft : Double.POSITIVE_INFINITY;
    }

    /** Seconds since {@code startMillis} by this deadline's clock. */
    double secondsSince(long startMillis) {
        return (clock.getAsLong() - startMillis) / 1e3;
    }

    long now() {
        return clock.getAsLong();
    }

    /** The deadline as an instant, for the report (null without one). */
    Instant end() {
        return endMillis == Long.MAX_VALUE ? null : Instant.ofEpochMilli(endMillis);
    }

    /** How long a duration of {@code seconds} reads: "1 h 05 min", "3 min 20 s". */
    static String readable(double seconds) {
        Duration d = Duration.ofMillis((long) (seconds * 1e3));
        if (d.toHours() > 0) {
            return String.format(Locale.ROOT, "%d h %02d min", d.toHours(), d.toMinutesPart());
        }
        return String.format(Locale.ROOT, "%d min %02d s", d.toMinutes(), d.toSecondsPart());
    }
}
