package carom.engines.slabs;

/**
 * The run's local time frame: disc clocks and event times count from {@code epoch}, so that they
 * stay small; {@code untilLocal} is the run's end in local time. Changed by the coordinator in
 * serial phases only (a resync), read by the domains in windows and tasks.
 */
final class RunClock {
    final double until;
    double epoch;
    double untilLocal;

    RunClock(double until) {
        this.until = until;
        this.untilLocal = until;
    }

    /** Local time {@code now} becomes 0. */
    void shift(double now) {
        epoch += now;
        untilLocal = until - epoch;
    }
}
