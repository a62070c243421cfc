package carom.engines.slabs;

/**
 * The cross events of a window run, as the {@link WindowCoordinator} reads them between windows:
 * contacts of discs of two domains and migrations into a foreign domain, the earliest of which bounds
 * the next window. {@link CrossPredictions} holds them; a run of one domain has {@link #NONE}.
 */
public interface CrossEvents {
    /** No cross event ever: a run of one domain. */
    CrossEvents NONE = new CrossEvents() {
        @Override
        public int validTop(double now) {
            return -1;
        }

        @Override
        public double time(int i) {
            throw new IllegalStateException("no cross events");
        }

        @Override
        public boolean dueAfterWindow(int i) {
            throw new IllegalStateException("no cross events");
        }

        @Override
        public int partnerOrMigration(int i) {
            throw new IllegalStateException("no cross events");
        }
    };

    /** The earliest valid cross event from local {@code now} (stale ones predicted again): its disc, or -1. */
    int validTop(double now);

    /** Local time of disc i's cross event (while it has one). */
    double time(int i);

    /**
     * Whether disc i's cross event, the earliest, may be processed after the window: i did not change in
     * it and the prediction holds (one whose disc changed is predicted again from the window's end).
     */
    boolean dueAfterWindow(int i);

    /** Disc i's cross event partner: a disc, or -1 for its migration into a foreign domain. */
    int partnerOrMigration(int i);
}
