package carom.engines.kernel;

import carom.core.engine.RunOptions;
import carom.core.engine.Tunable;
import carom.core.scene.Scene;

/** The settings of the one-event-per-disc kernel, shared by {@code fast} and {@code slabs}. */
public final class KernelTunables {
    /**
     * Cells a hair wider than one diameter are the best measured for one event per disc from packing
     * fraction 1/6 up (fewer neighbours to scan per prediction); in dilute gases a disc crosses several
     * cells per collision, and wider cells pay (lab/notes/cell-factor). The step-grid engines' default
     * of 2 does not apply here.
     */
    public static final Tunable.Real CELL_FACTOR = Tunable.Real.atLeast("cellFactor", 1, 1, "diameters",
            "cell side over the largest diameter; wider cells mean fewer crossings but more neighbours per scan")
            .computedByDefault("1 from packing fraction 1/6 up, 0.5/phi - 2 below it, at most 3; 1 under gravity");

    /**
     * The cell factor of a run: the given one, or the default for the scene's packing fraction; 1 under
     * gravity, where discs gather in piles however dilute the box is on average.
     */
    public static double cellFactor(RunOptions options, Scene scene) {
        double given = CELL_FACTOR.of(options);
        if (!Double.isNaN(given)) {
            return given;
        }
        return scene.effects().hasGravity() ? 1 : forPackingFraction(scene.packingFraction());
    }

    /** The default cell factor at packing fraction {@code phi}: 1 from 1/6 up, 2 near 0.125, 3 from 0.1 down. */
    static double forPackingFraction(double phi) {
        return Math.max(1, Math.min(3, 0.5 / phi - 2));
    }

    /** The cell factor of a growth run: the given one, else 1 (the discs grow towards jamming). */
    public static double growthCellFactor(RunOptions options) {
        double given = CELL_FACTOR.of(options);
        return Double.isNaN(given) ? 1 : given;
    }

    private KernelTunables() {
    }
}
