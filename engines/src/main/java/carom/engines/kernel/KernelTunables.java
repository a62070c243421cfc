package carom.engines.kernel;

import carom.core.engine.RunOptions;
import carom.core.engine.Tunable;
import carom.core.scene.Scene;

/** The settings of the one-event-per-disc kernel, shared by {@code fast} and {@code slabs}. */
public final class KernelTunables {
    /**
     * The widest skin, in diameters: a list holds every disc within it, so a skin of the box's size would
     * hold N discs per disc (N squared ints); ten diameters is some 400 neighbours at close packing.
     */
    static final double MAX_SKIN = 10;

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
     * Neighbour lists instead of cell scans ({@link ListPredictor}): at high density a disc rattles in
     * its cage, a list outlives many collisions and holds fewer discs than 3x3 cells (lab note
     * smallenburg-2d): 1.2x at packing fraction 0.65, a median 1.2-1.4x at 0.70-0.74. In a gas lists expire every
     * few collisions (0.7-0.9x at 0.5), so they are the default only from {@link #LIST_PACKING_FRACTION} up; and
     * only up to {@link #LIST_MAX_DISCS} discs: at 0.72 they gained 1.17x at N = 16,384 but lost at 40,000
     * (0.63x) and did not pay at 90,000 (median 0.96x), where their 50 more bytes a disc take the run out
     * of the measuring machine's 1 MiB level-2 cache.
     */
    public static final Tunable.Real SKIN = new Tunable.Real("skin", 0, 0, false, MAX_SKIN, "diameters",
            "0: predict against the 3x3 cells around a disc; s > 0: against a list per disc of the discs within contact"
                    + " distance plus s diameters, made again when the disc has moved s/2 (straight flight only)", null)
            .computedByDefault("0.5 from packing fraction 0.65 up with at most 20,000 discs, without gravity or growth; else 0");
    /**
     * Prefetch hints ({@link Prefetch}): where the native helper is loaded, from 32,768 discs up, the
     * calendar asks for the records its next events will read (about 1.05-1.1x at N = 1e6, lab note prefetch).
     * Only speed: the same bits either way; {@code false} is for measuring what they buy.
     */
    public static final Tunable.Flag PREFETCH = new Tunable.Flag("prefetch", true,
            "true: prefetch hints for the next events' records from 32,768 discs up, where the native helper is loaded"
                    + " (same results, faster at large N); false: none");

    /** Packing fraction from which {@code fast} predicts from neighbour lists by default. */
    public static final double LIST_PACKING_FRACTION = 0.65;
    /** The most discs for which {@code fast} predicts from neighbour lists by default. */
    public static final int LIST_MAX_DISCS = 20_000;
    /** The default skin there, in diameters (Smallenburg's shell of 1.5 diameters). */
    static final double DEFAULT_SKIN = 0.5;

    /** The skin of a run of {@code fast}: the given one, else {@link #DEFAULT_SKIN} in dense scenes that allow lists. */
    public static double skin(RunOptions options, Scene scene) {
        double given = SKIN.of(options);
        if (!Double.isNaN(given)) {
            return given;
        }
        boolean allowed = !scene.effects().hasGravity() && !scene.effects().grows();
        boolean pays = scene.packingFraction() >= LIST_PACKING_FRACTION && scene.size() <= LIST_MAX_DISCS;
        return allowed && pays ? DEFAULT_SKIN : 0;
    }

    /** Whether the skin was given ({@code --option skin}) rather than chosen by default. */
    public static boolean skinGiven(RunOptions options) {
        return !Double.isNaN(SKIN.of(options));
    }

    /** The cell factor of a run with neighbour lists: cells of a diameter plus the skin (wider if asked). */
    public static double listCellFactor(RunOptions options, double skin) {
        double given = CELL_FACTOR.of(options);
        return Double.isNaN(given) ? 1 + skin : Math.max(given, 1 + skin);
    }

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
