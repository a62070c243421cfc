package carom.core.scene;

import carom.core.state.Discs;
import java.util.List;

/**
 * An immutable, validated scene: the box, the species, the effects, the end time and every disc's
 * initial state (ids 0..N-1 in file order). Build one with {@link SceneBuilder} or read one with
 * {@link SceneReader}; both validate, so an engine can trust what it is given.
 */
public final class Scene {
    private final String name;
    private final Box box;
    private final List<Species> species;
    private final Effects effects;
    private final double until;
    private final Discs initial;
    private final int[] blockStarts;

    Scene(String name, Box box, List<Species> species, Effects effects, double until, Discs initial, int[] blockStarts) {
        this.name = name;
        this.box = box;
        this.species = List.copyOf(species);
        this.effects = effects;
        this.until = until;
        this.initial = initial;
        this.blockStarts = blockStarts;
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
        return initial.n;
    }

    /** The share of the box the discs cover: the sum of their areas over the box's area. */
    public double packingFraction() {
        double area = 0;
        for (int i = 0; i < initial.n; i++) {
            area += Math.PI * initial.radius[i] * initial.radius[i];
        }
        return area / box.area();
    }

    /** The discs that move (all but the fixed ones). */
    public int mobileCount() {
        int mobile = 0;
        for (int i = 0; i < initial.n; i++) {
            mobile += initial.invMass[i] > 0 ? 1 : 0;
        }
        return mobile;
    }

    /** The mobile discs' root-mean-square speed at t = 0, weighted by mass; 0 when none is mobile. */
    public double rmsSpeed() {
        double mass = 0;
        double twiceKinetic = 0;
        for (int i = 0; i < initial.n; i++) {
            if (initial.invMass[i] > 0) {
                double m = 1 / initial.invMass[i];
                mass += m;
                twiceKinetic += m * (initial.vx[i] * initial.vx[i] + initial.vy[i] * initial.vy[i]);
            }
        }
        return mass == 0 ? 0 : Math.sqrt(twiceKinetic / mass);
    }

    /** The mean radius of all discs; 0 without discs. */
    public double meanRadius() {
        double radii = 0;
        for (int i = 0; i < initial.n; i++) {
            radii += initial.radius[i];
        }
        return initial.n == 0 ? 0 : radii / initial.n;
    }

    public boolean hasFixedDiscs() {
        return species.stream().anyMatch(Species::fixed);
    }

    /** A fresh mutable copy of the initial state, clocks at 0; engines own it. */
    public Discs newDiscs() {
        Discs d = initial.copy();
        java.util.Arrays.fill(d.t, 0);
        return d;
    }

    /** Where disc {@code id} came from in the scene file, for error messages. */
    public String originOf(int id) {
        return SceneBuilder.describe(blockStarts, id);
    }

    public Scene withUntil(double newUntil) {
        return new Scene(name, box, species, effects, newUntil, initial, blockStarts);
    }

    public Scene withEffects(Effects newEffects) {
        return new Scene(name, box, species, newEffects, until, initial, blockStarts);
    }

    /**
     * The same scene starting from another state of its discs (for example a run's final state, to
     * continue from an equilibrated configuration). Positions and velocities are taken at each disc's
     * own clock, which must already be synchronised.
     */
    public Scene withState(Discs state) {
        if (state.n != initial.n) {
            throw new IllegalArgumentException("state has " + state.n + " discs, scene has " + initial.n);
        }
        Discs copy = state.copy();
        java.util.Arrays.fill(copy.t, 0);
        return new Scene(name, box, species, effects, until, copy, blockStarts);
    }
}
