package carom.core.scene;

import carom.core.state.Discs;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Supplier;

/**
 * An immutable, validated scene: the box, the species, the effects, the end time and every disc's
 * initial state (ids 0..N-1 in file order). Build one with {@link SceneBuilder} or read one with
 * {@link SceneReader}; both validate, so an engine can trust what it is given.
 *
 * <p>Memory: a scene does not keep its discs for the length of a run. The state made when it was built
 * (and validated) is handed to the first {@link #newDiscs()} without a copy, and any later call makes
 * the state again from the scene's recipe: its explicit discs and its generate blocks, whose generation
 * is deterministic, so every call gives the same numbers. A scene made {@link #withState} keeps the
 * state it was given and hands out copies. The figures that describe the discs (size, packing
 * fraction, speeds) are taken once, when the scene is made.
 */
public final class Scene {
    private final String name;
    private final Box box;
    private final List<Species> species;
    private final Effects effects;
    private final double until;
    /** The initial state made when the scene was built, until the first {@link #newDiscs()} takes it. */
    private final AtomicReference<Discs> unclaimed;
    /** Makes the initial state afresh, each call a new one with the same numbers. */
    private final Supplier<Discs> recipe;
    private final Figures figures;
    private final int[] blockStarts;

    /** A scene whose discs are {@code initial}, made by {@code recipe} (which makes them again on demand). */
    Scene(String name, Box box, List<Species> species, Effects effects, double until, Discs initial,
          Supplier<Discs> recipe, int[] blockStarts) {
        this(name, box, species, effects, until, new AtomicReference<>(initial), recipe, Figures.of(initial), blockStarts);
    }

    private Scene(String name, Box box, List<Species> species, Effects effects, double until,
                  AtomicReference<Discs> unclaimed, Supplier<Discs> recipe, Figures figures, int[] blockStarts) {
        this.name = name;
        this.box = box;
        this.species = List.copyOf(species);
        this.effects = effects;
        this.until = until;
        this.unclaimed = unclaimed;
        this.recipe = recipe;
        this.figures = figures;
        this.blockStarts = blockStarts;
    }

    /** What summaries and estimates read of the initial discs, taken once: the sums the accessors below name. */
    private record Figures(int size, double discArea, int mobileCount, double rmsSpeed, double meanRadius) {
        static Figures of(Discs initial) {
            double area = 0;
            int mobile = 0;
            double mass = 0;
            double twiceKinetic = 0;
            double radii = 0;
            for (int i = 0; i < initial.n; i++) {
                area += Math.PI * initial.radius[i] * initial.radius[i];
                mobile += initial.invMass[i] > 0 ? 1 : 0;
                if (initial.invMass[i] > 0) {
                    double m = 1 / initial.invMass[i];
                    mass += m;
                    twiceKinetic += m * (initial.vx[i] * initial.vx[i] + initial.vy[i] * initial.vy[i]);
                }
                radii += initial.radius[i];
            }
            return new Figures(initial.n, area, mobile, mass == 0 ? 0 : Math.sqrt(twiceKinetic / mass),
                    initial.n == 0 ? 0 : radii / initial.n);
        }
    }

    public String name() {
        return name;
    }

    public Box box() {
        return box;
    }

    public List<Species> species() {
        return species;
    }

    public Effects effects() {
        return effects;
    }

    public double until() {
        return until;
    }

    public int size() {
        return figures.size();
    }

    /** The share of the box the discs cover: the sum of their areas over the box's area. */
    public double packingFraction() {
        return figures.discArea() / box.area();
    }

    /** The discs that move (all but the fixed ones). */
    public int mobileCount() {
        return figures.mobileCount();
    }

    /** The mobile discs' root-mean-square speed at t = 0, weighted by mass; 0 when none is mobile. */
    public double rmsSpeed() {
        return figures.rmsSpeed();
    }

    /** The mean radius of all discs; 0 without discs. */
    public double meanRadius() {
        return figures.meanRadius();
    }

    public boolean hasFixedDiscs() {
        return species.stream().anyMatch(Species::fixed);
    }

    /**
     * A fresh mutable initial state, clocks at 0, owned by the caller: the state the scene was built
     * with for the first caller, made again for every later one (see the class comment).
     */
    public Discs newDiscs() {
        Discs d = unclaimed.getAndSet(null);
        if (d == null) {
            d = recipe.get();
        }
        Arrays.fill(d.t, 0);
        return d;
    }

    /** Where disc {@code id} came from in the scene file, for error messages. */
    public String originOf(int id) {
        return SceneBuilder.describe(blockStarts, id);
    }

    public Scene withUntil(double newUntil) {
        return new Scene(name, box, species, effects, newUntil, unclaimed, recipe, figures, blockStarts);
    }

    public Scene withEffects(Effects newEffects) {
        return new Scene(name, box, species, newEffects, until, unclaimed, recipe, figures, blockStarts);
    }

    /**
     * The same scene starting from another state of its discs (for example a run's final state, to
     * continue from an equilibrated configuration). Positions and velocities are taken at each disc's
     * own clock, which must already be synchronised.
     */
    public Scene withState(Discs state) {
        if (state.n != figures.size()) {
            throw new IllegalArgumentException("state has " + state.n + " discs, scene has " + figures.size());
        }
        Discs copy = state.copy();
        Arrays.fill(copy.t, 0);
        return new Scene(name, box, species, effects, until, new AtomicReference<>(), copy::copy, Figures.of(copy), blockStarts);
    }
}
