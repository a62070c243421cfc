package carom.engines.cells;

import carom.core.engine.RunOptions;
import carom.core.engine.Tunable;

/** The settings of the step grid, shared by every engine built on it (serial, stripes, the actor engines). */
public final class StepGridTunables {
    /** Cells must be more than one diameter wide so that a step can be longer than zero. */
    public static final Tunable.Real CELL_FACTOR = Tunable.Real.above("cellFactor", 2, 1, "diameters",
            "cell side over the largest diameter; wider cells allow longer steps but hold more discs");
    /**
     * Bounded both ways: a thousandth of the guaranteed step already means a thousand times the steps
     * (a run that never ends for a slip of a digit), and beyond a thousand every disc outruns the grid.
     */
    public static final Tunable.Real STEP_FACTOR = new Tunable.Real("stepFactor", 1, 1e-3, false, 1e3, "",
            "step length over what the grid guarantee allows; above 1 recreates the thesis's longer steps, "
                    + "and discs that outrun the grid are counted as overruns", null);

    private StepGridTunables() {
    }

    /** The step frame a run with these options uses. */
    public static StepFrame frame(carom.core.scene.Scene scene, RunOptions options) {
        return new StepFrame(scene, options.until(), CELL_FACTOR.of(options), STEP_FACTOR.of(options));
    }
}
