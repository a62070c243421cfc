package carom.engines.slabs;

/**
 * The optimistic-window protocol's counts, kept by {@link WindowCoordinator} (and read, saved and
 * restored by the adapters): windows, those committed and rolled back, the cross events processed
 * serially (contacts, migrations), re-anchorings of time; and the coordinator's wall time in windows
 * and wall and CPU time in the serial phases after them (measurement only, never saved).
 */
public final class WindowCounts {
    public long windows;
    public long commits;
    public long rollbacks;
    public long crossDomainEvents;
    public long migrations;
    public long resyncs;
    public long windowNanos;
    public long serialNanos;
    public long serialCpuNanos;
}
