package carom.engines.kernel;

import carom.core.BadInputException;
import carom.core.observe.Observables;
import carom.core.scene.Scene;
import carom.core.state.Discs;
import java.util.Locale;

/**
 * What every engine that runs the growth effect on this kernel does between its stages, in one place:
 * a stage is a {@link DiscTable} whose cells hold the largest disc up to {@link #MARGIN} times its
 * size when the stage starts (or more where the grid's cap makes cells wider), run until the discs
 * would outgrow them ({@link DiscTable#largestRadiusHeld}) or an earlier stop, then rebuilt from every
 * disc's state at that time. Radii are R(0)(1 + G t) at absolute t; tables hold R(0) and are anchored
 * at the stage's start ({@link DiscTable#anchorGrowth}).
 */
public final class GrowthStages {
    /**
     * Growth runs cannot save their state yet (their table is rebuilt in stages, and a stage's state is
     * not in a checkpoint): bad input when {@code options} ask for checkpoints.
     */
    public static void refuseCheckpoints(carom.core.engine.RunOptions options) {
        if (options.checkpoints() != null) {
            throw new BadInputException("--checkpoint: runs with growing discs cannot be checkpointed yet");
        }
    }

    /** How much bigger than the largest disc now a stage's cells are planned for. */
    public static final double MARGIN = 1.05;

    private final Scene scene;
    private final double growth;
    private final double cellFactor;
    private final double largestStartRadius;

    public GrowthStages(Scene scene, double largestStartRadius, double cellFactor) {
        this.scene = scene;
        this.growth = scene.effects().growth();
        this.cellFactor = cellFactor;
        this.largestStartRadius = largestStartRadius;
    }

    /**
     * The table of the stage that starts at absolute {@code at} from {@code state} (scene order,
     * positions at {@code at}, radii R(0)); bad input if the discs outgrew a periodic box (its nearest
     * image must stay unique: the box wider than two largest diameters).
     */
    public DiscTable table(Discs state, double at) {
        double largest = largestStartRadius * (1 + growth * at);
        double planned = largest * MARGIN;
        if (scene.box().periodic()) {
            double boxLimit = Math.min(scene.box().width(), scene.box().height()) / 4;
            // Stages halve the room left, so the limit is met to 1e-9 after some 30 of them.
            if (!(largest < boxLimit * (1 - 1e-9))) {
                throw new BadInputException(String.format(Locale.ROOT,
                        "effects.growth: at t = %s the largest disc (radius %s) has outgrown the periodic box "
                                + "(which must exceed twice the largest diameter); lower until", at, largest));
            }
            planned = Math.min(planned, largest + 0.5 * (boxLimit - largest));
        }
        DiscTable table = new DiscTable(scene, state, cellFactor, planned);
        table.anchorGrowth(at);
        return table;
    }

    /** The absolute time at which the discs outgrow {@code table}'s cells (+Infinity if never). */
    public double end(DiscTable table) {
        return (table.largestRadiusHeld() / largestStartRadius - 1) / growth;
    }

    /** Sets the radii of {@code d} to those at absolute {@code at}, from the R(0) of {@code start}. */
    public void grownRadii(Discs start, Discs d, double at) {
        double scale = 1 + growth * at;
        for (int i = 0; i < d.n; i++) {
            d.radius[i] = start.radius[i] * scale;
        }
    }

    /**
     * The thermostat: every velocity of {@code state} times one factor that brings its kinetic energy to
     * {@code target}; returns the energy taken out (0, and nothing changed, if either energy is 0).
     */
    public static double rescale(Discs state, double target) {
        double now = Observables.kineticEnergy(state);
        if (!(now > 0) || !(target > 0)) {
            return 0;
        }
        double factor = Math.sqrt(target / now);
        for (int i = 0; i < state.n; i++) {
            state.vx[i] *= factor;
            state.vy[i] *= factor;
        }
        return now - target;
    }
}
