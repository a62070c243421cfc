package carom.app;

import carom.core.engine.ProgressListener;
import java.io.PrintStream;
import java.util.Locale;

/**
 * A progress bar on an interactive stderr, {@code [=====     ]  42%  t=4.2/10  3.1e+05 coll/s  ~12s left},
 * redrawn by a daemon thread from the latest simulated time the engine reported; the time left is the
 * wall time so far scaled by the fraction still to go. Collisions per second show for engines that
 * report their count ({@link ProgressListener#progress}), measured from the first report (a resumed
 * run's count starts where it stopped). The engine's side is a few volatile writes,
 * so reporting costs it nothing measurable. Short runs never show a bar: it appears only after
 * {@link #DELAY_MILLIS}, and it is erased when the run ends.
 *
 * <p>{@link #forCount} makes the same bar count units of work instead ({@code 12/30 runs}), with a
 * status line of what is running; {@code carom experiment} uses it.
 *
 * <p>When the process's stderr is not a terminal (a batch job, a pipe, a log file), a run's bar prints a
 * status line instead, every {@value #STATUS_VARIABLE} seconds (default {@value #DEFAULT_STATUS_SECONDS};
 * 0 for none), {@code progress: t=4.2/10 (42%)  3.1e+05 coll/s  ~12s left}, so that a long job shows
 * it is alive; the first comes after one period, so short runs print none.
 */
public final class ProgressBar implements ProgressListener, AutoCloseable {
    static final long DELAY_MILLIS = 2000;
    /** The environment variable that sets the seconds between status lines on a stderr that is no terminal. */
    static final String STATUS_VARIABLE = "CAROM_STATUS_EVERY";
    static final long DEFAULT_STATUS_SECONDS = 10;
    private static final long PERIOD_MILLIS = 200;
    private static final int WIDTH = 30;

    private final PrintStream err;
    private final double until;
    /** What is counted ("runs"), or null for simulated time. */
    private final String unit;
    private final Thread painter;
    private volatile double time;
    private volatile String status = "";
    /** The latest collision count reported and when; the first such report, the rate's baseline. */
    private volatile long collisions = -1;
    private volatile long collisionsNanos;
    private long firstCollisions = -1;
    private long firstNanos;
    private final long startNanos = System.nanoTime();
    /** Length of what is on screen, to erase it; touched only by the painter until it has stopped. */
    private int drawn;

    /** Milliseconds between status lines, or 0 when this bar draws on a terminal (or not at all). */
    private final long statusMillis;

    private ProgressBar(PrintStream err, double until, String unit, boolean visible, long statusMillis) {
        this.err = err;
        this.until = until;
        this.unit = unit;
        this.statusMillis = statusMillis;
        if (visible || statusMillis > 0) {
            Runnable work = visible ? this::paint : this::printStatus;
            painter = new Thread(work, "carom-progress");
            painter.setDaemon(true);
            painter.start();
        } else {
            painter = null;
        }
    }

    /**
     * A bar that shows when {@code err} is the process's stderr and a terminal; status lines every
     * {@value #STATUS_VARIABLE} seconds when it is the process's stderr and no terminal; otherwise (tests)
     * one that only records the time and never draws.
     */
    public static ProgressBar forRun(PrintStream err, double until) {
        boolean visible = visibleOn(err);
        return new ProgressBar(err, until, null, visible, visible || err != System.err ? 0 : statusMillis(System.getenv()));
    }

    /** A run's progress as status lines on {@code err} every {@code periodMillis}, whatever {@code err} is. */
    static ProgressBar statusLines(PrintStream err, double until, long periodMillis) {
        return new ProgressBar(err, until, null, false, periodMillis);
    }

    /**
     * The period of status lines {@code environment}'s {@value #STATUS_VARIABLE} asks for, in milliseconds (0:
     * none); the default when it is unset or not a number of seconds >= 0.
     */
    static long statusMillis(java.util.Map<String, String> environment) {
        String value = environment.get(STATUS_VARIABLE);
        double seconds = DEFAULT_STATUS_SECONDS;
        if (value != null) {
            try {
                double parsed = Double.parseDouble(value.strip());
                seconds = parsed >= 0 && parsed < 1e9 ? parsed : seconds;
            } catch (NumberFormatException e) {
                // the default
            }
        }
        return Math.round(seconds * 1000);
    }

    /** A bar counting {@code total} units of work named {@code unit}, shown as {@link #forRun}'s is. */
    public static ProgressBar forCount(PrintStream err, long total, String unit) {
        return new ProgressBar(err, total, unit, visibleOn(err), 0);
    }

    private static boolean visibleOn(PrintStream err) {
        return err == System.err && Terminal.interactive();
    }

    /** Whether this bar draws (stderr is a terminal), so that callers print progress lines otherwise. */
    public boolean visible() {
        return painter != null && statusMillis == 0;
    }

    @Override
    public void simulatedTime(double t) {
        time = t;
    }

    @Override
    public void progress(double t, long count) {
        long nanos = System.nanoTime();
        if (firstCollisions < 0) {
            firstNanos = nanos;
            firstCollisions = count;
        }
        collisionsNanos = nanos;
        collisions = count;
        time = t;
    }

    /** {@code   3.1e+05 coll/s} since the first report, or nothing before a second one. */
    private String rate() {
        long count = collisions;
        long nanos = collisionsNanos;
        long first = firstCollisions;
        return count < 0 || first < 0 ? "" : collisionRate(count - first, nanos - firstNanos);
    }

    static String collisionRate(long collisionsDone, long elapsedNanos) {
        if (elapsedNanos <= 0 || collisionsDone <= 0) {
            return "";
        }
        return String.format(Locale.ROOT, "  %.2g coll/s", collisionsDone / (elapsedNanos * 1e-9));
    }

    /** A time bar's note after the time left (for simulate: the collisions expected). */
    public ProgressBar withStatus(String note) {
        status = note;
        return this;
    }

    /** For a counting bar: {@code done} units are finished, and {@code now} is what runs next. */
    public void completed(long done, String now) {
        status = now;
        time = done;
    }

    private void paint() {
        try {
            Thread.sleep(DELAY_MILLIS);
            while (!Thread.currentThread().isInterrupted()) {
                String bar = unit == null ? render(time, until) : renderCount((long) time, (long) until, unit, status);
                String note = unit == null && !status.isEmpty() ? "  " + status : "";
                String rate = unit == null ? rate() : "";
                draw(bar + rate + timeLeft(time / until, System.nanoTime() - startNanos) + note);
                Thread.sleep(PERIOD_MILLIS);
            }
        } catch (InterruptedException e) {
            // close() asks us to stop.
        }
    }

    /** Status lines, for a stderr that is no terminal: the simulated time, the rate, the time left. */
    private void printStatus() {
        try {
            while (!Thread.currentThread().isInterrupted()) {
                Thread.sleep(statusMillis);
                String line = statusLine(time, until, rate(), System.nanoTime() - startNanos);
                synchronized (this) {
                    err.print(line + System.lineSeparator());
                    err.flush();
                }
            }
        } catch (InterruptedException e) {
            // close() asks us to stop.
        }
    }

    /** {@code progress: t=4.2/10 (42%)  3.1e+05 coll/s  ~12s left}. */
    static String statusLine(double t, double until, String rate, long elapsedNanos) {
        double fraction = until > 0 ? Math.max(0, Math.min(1, t / until)) : 0;
        return "progress: t=" + compact(t) + "/" + compact(until) + " (" + (int) Math.floor(100 * fraction) + "%)"
                + rate + timeLeft(fraction, elapsedNanos);
    }

    /**
     * Prints {@code note: LINE} on a line of its own, whether or not the bar shows (the bar, if it
     * does, is drawn again below it at its next tick).
     */
    @Override
    public synchronized void notice(String line) {
        erase();
        err.print("note: " + line + System.lineSeparator());
        err.flush();
    }

    /** Blanks the bar drawn last, if any, and returns to the start of its line. */
    private synchronized void erase() {
        if (drawn > 0) {
            err.print("\r" + " ".repeat(drawn) + "\r");
            err.flush();
            drawn = 0;
        }
    }

    private synchronized void draw(String bar) {
        StringBuilder sb = new StringBuilder("\r").append(bar);
        for (int i = bar.length(); i < drawn; i++) {
            sb.append(' ');
        }
        drawn = bar.length();
        err.print(sb);
        err.flush();
    }

    static String render(double t, double until) {
        return bar(t, until) + "t=" + compact(t) + "/" + compact(until);
    }

    static String renderCount(long done, long total, String unit, String status) {
        String s = bar(done, total) + done + "/" + total + " " + unit;
        return status.isEmpty() ? s : s + "  " + status;
    }

    /**
     * {@code   ~1m 05s left}: the wall time still to go if the rest goes as fast as what is done, or
     * nothing while too little is done to say (under 1%).
     */
    static String timeLeft(double fraction, long elapsedNanos) {
        if (!(fraction >= 0.01) || fraction >= 1) {
            return "";
        }
        long seconds = Math.round(elapsedNanos * 1e-9 * (1 - fraction) / fraction);
        String left = seconds < 60 ? seconds + "s"
                : seconds < 3600 ? String.format(Locale.ROOT, "%dm %02ds", seconds / 60, seconds % 60)
                : String.format(Locale.ROOT, "%dh %02dm", seconds / 3600, seconds % 3600 / 60);
        return "  ~" + left + " left";
    }

    /** {@code [=====     ]  42%  }: the bar and percentage that every rendering starts with. */
    private static String bar(double t, double until) {
        double fraction = until > 0 ? Math.max(0, Math.min(1, t / until)) : 0;
        int filled = (int) Math.round(fraction * WIDTH);
        StringBuilder sb = new StringBuilder(WIDTH + 32).append('[');
        for (int i = 0; i < WIDTH; i++) {
            sb.append(i < filled ? '=' : ' ');
        }
        return sb.append(']').append(String.format(Locale.ROOT, " %3d%%  ", (int) Math.floor(100 * fraction))).toString();
    }

    /** Four significant digits without trailing zeros: 4.2, 10, 1.235e+06. */
    static String compact(double v) {
        String s = String.format(Locale.ROOT, "%.4g", v);
        if (s.indexOf('.') < 0 || s.indexOf('e') >= 0) {
            return s;
        }
        int end = s.length();
        while (s.charAt(end - 1) == '0') {
            end--;
        }
        if (s.charAt(end - 1) == '.') {
            end--;
        }
        return s.substring(0, end);
    }

    /** Stops redrawing and erases the bar, so that the summary or an error starts on a clean line. */
    @Override
    public void close() {
        if (painter == null) {
            return;
        }
        painter.interrupt();
        try {
            painter.join();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        erase();
    }

    /** Whether stderr goes to a person. */
    static final class Terminal {
        private Terminal() {
        }

        static boolean interactive() {
            java.io.Console console = System.console();
            if (console == null) {
                return false;
            }
            // Since Java 22 System.console() may exist for redirected streams; Console.isTerminal()
            // (absent in 21, which we compile for) tells them apart.
            try {
                return (Boolean) java.io.Console.class.getMethod("isTerminal").invoke(console);
            } catch (ReflectiveOperationException e) {
                return true;
            }
        }
    }
}
