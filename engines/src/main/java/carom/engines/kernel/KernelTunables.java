package carom.engines.kernel;

import carom.core.engine.Tunable;

/** The settings of the one-event-per-disc kernel, shared by {@code fast} and {@code slabs}. */
public final class KernelTunables {
    /**
     * Cells a hair wider than one diameter are the best measured for one event per disc (fewer
     * neighbours to scan per prediction); the step-grid engines' default of 2 does not apply here.
     */
    public static final Tunable.Real CELL_FACTOR = Tunable.Real.atLeast("cellFactor", 1, 1, "diameters",
            "cell side over the largest diameter; wider cells mean fewer crossings but more neighbours per scan");

    private KernelTunables() {
    }
}
