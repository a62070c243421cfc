package carom.engines.cells;

import carom.core.engine.Counter;
import java.util.List;

/** The counters of the step-grid engines (serial, stripes, the actor engines) besides the generic {@link Counter}s. */
public final class StepGridCounters {
    public static final Counter EARLY_STEP_ENDS = new Counter("earlyStepEnds",
            "steps ended early because a disc became faster than the step allows (serial)");
    public static final Counter ROUNDS = new Counter("rounds", "phase rounds of the stripes (three per step)");
    public static final Counter OVERRUNS = new Counter("overruns", "discs that outran the grid within a step (stepFactor above 1)");
    public static final Counter PREEMPTED = new Counter("preempted",
            "stale events that a later collision may have pre-empted (relaxed engines)");

    /** Those every relaxed step-grid run reports ({@link StepFrame}). */
    public static final List<Counter> RELAXED = List.of(OVERRUNS, PREEMPTED);

    private StepGridCounters() {
    }
}
