package carom.engines.slabs;

/**
 * The check of a window against the segments its discs really followed, as the {@link WindowCoordinator}
 * sees it: the earliest contact, before a limit, between a disc that changed in the window and a foreign
 * disc. {@link WindowVerifier} is the check of both engines.
 */
public interface WindowCheck {
    /**
     * The earliest contact before {@code limit} between a disc that changed in the window (which began
     * at local {@code start}) and a foreign disc; its time, +Infinity if none.
     */
    double verify(double start, double limit);

    /** The two discs of the contact the last {@link #verify} found. */
    int violationX();

    int violationY();
}
