package carom.engines.reference;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.engine.RunResult;
import carom.core.observe.Observables;
import carom.core.scene.Box;
import carom.core.scene.Scene;
import carom.core.state.Discs;

/**
 * The invariants every run of an exact engine on an elastic scene must keep, checked on its final
 * state against the scene's initial one:
 * <ul>
 *   <li>no NaN or infinity anywhere in the final state, every clock at {@code until};</li>
 *   <li>kinetic energy conserved to {@value #ENERGY_TOLERANCE} relative (elastic scenes);</li>
 *   <li>momentum conserved to {@value #MOMENTUM_TOLERANCE} of the sum of |p_i| (periodic boxes
 *       without fixed discs: walls and pegs take momentum);</li>
 *   <li>no two discs overlapping by more than {@value #OVERLAP_TOLERANCE} of their contact distance
 *       (all pairs, nearest image);</li>
 *   <li>every disc inside the box: with walls within its radius of every wall (up to
 *       {@value #OVERLAP_TOLERANCE} of the radius plus a few ulps of the box size), periodic positions
 *       wrapped into [0, L);</li>
 *   <li>fixed discs have not moved; the reported counters and observables agree with the state.</li>
 * </ul>
 * O(N^2) pair check: fine up to a few thousand discs, which is all the tests use.
 */
public final class Invariants {
    public static final double ENERGY_TOLERANCE = 1e-12;
    public static final double MOMENTUM_TOLERANCE = 1e-12;
    public static final double OVERLAP_TOLERANCE = 1e-9;

    private Invariants() {
    }

    /** Every disc's position and velocity agree within {@code tolerance}. */
    public static void assertSameState(Discs actual, Discs expected, double tolerance) {
        assertSameState("", actual, expected, tolerance);
    }

    /** As {@link #assertSameState(Discs, Discs, double)}, each failure message prefixed with {@code name}. */
    public static void assertSameState(String name, Discs actual, Discs expected, double tolerance) {
        String prefix = name.isEmpty() ? "" : name + ": ";
        assertThat(actual.n).as("%sdisc count", prefix).isEqualTo(expected.n);
        for (int i = 0; i < expected.n; i++) {
            assertThat(actual.x[i]).as("%sx of %d", prefix, i).isCloseTo(expected.x[i], within(tolerance));
            assertThat(actual.y[i]).as("%sy of %d", prefix, i).isCloseTo(expected.y[i], within(tolerance));
            assertThat(actual.vx[i]).as("%svx of %d", prefix, i).isCloseTo(expected.vx[i], within(tolerance));
            assertThat(actual.vy[i]).as("%svy of %d", prefix, i).isCloseTo(expected.vy[i], within(tolerance));
        }
    }

    /** Two runs of one scene agree: the same pair and wall collision counts, and final states within {@code tolerance}. */
    public static void assertSameRun(String name, RunResult actual, RunResult expected, double tolerance) {
        assertThat(actual.pairCollisions()).as("%s: pair collisions", name).isEqualTo(expected.pairCollisions());
        assertThat(actual.wallCollisions()).as("%s: wall collisions", name).isEqualTo(expected.wallCollisions());
        assertSameState(name, actual.finalState(), expected.finalState(), tolerance);
        // The same collisions give the same virial (summed in another order: rounding only), walls or not.
        assertThat(actual.pressure()).as("%s: pressure", name).isNotNull();
        assertThat(actual.pressure().compressibility()).as("%s: Z", name)
                .isCloseTo(expected.pressure().compressibility(), within(tolerance * expected.pressure().compressibility()));
    }

    /** Checks every invariant of an elastic run; returns the result for chaining. */
    public static RunResult check(Scene scene, RunResult result) {
        Discs initial = scene.newDiscs();
        Discs end = result.finalState();
        String name = scene.name();
        assertThat(end.n).as("%s: disc count", name).isEqualTo(initial.n);
        noNaN(name, end, result.until());
        assertThat(result.pairCollisions()).as("%s: pair collisions", name).isNotNegative();
        assertThat(result.wallCollisions()).as("%s: wall collisions", name).isNotNegative();
        if (scene.box().periodic()) {
            assertThat(result.wallCollisions()).as("%s: wall collisions in a periodic box", name).isZero();
        }
        energy(name, initial, end, result);
        if (scene.box().periodic() && !scene.hasFixedDiscs()) {
            momentum(name, initial, end, result);
        }
        fixedDiscsStayPut(name, initial, end);
        insideBox(name, scene.box(), end);
        noOverlaps(name, scene.box(), end);
        return result;
    }

    /**
     * The invariants that hold whatever the effects (gravity and restitution change energy and
     * momentum): a finite state, fixed discs in place, every disc inside the box, no overlaps.
     */
    public static void noOverlapsAndInside(Scene scene, Discs d) {
        String name = scene.name();
        Discs initial = scene.newDiscs();
        for (int i = 0; i < d.n; i++) {
            assertThat(Double.isFinite(d.x[i]) && Double.isFinite(d.y[i]) && Double.isFinite(d.vx[i])
                    && Double.isFinite(d.vy[i]))
                    .as("%s: disc %d is finite: (%s, %s) v (%s, %s)", name, i, d.x[i], d.y[i], d.vx[i], d.vy[i])
                    .isTrue();
        }
        fixedDiscsStayPut(name, initial, d);
        insideBox(name, scene.box(), d);
        noOverlaps(name, scene.box(), d);
    }

    static void noNaN(String name, Discs d, double until) {
        for (int i = 0; i < d.n; i++) {
            assertThat(Double.isFinite(d.x[i]) && Double.isFinite(d.y[i]) && Double.isFinite(d.vx[i])
                    && Double.isFinite(d.vy[i]))
                    .as("%s: disc %d is finite: (%s, %s) v (%s, %s)", name, i, d.x[i], d.y[i], d.vx[i], d.vy[i])
                    .isTrue();
            assertThat(d.t[i]).as("%s: clock of disc %d", name, i).isEqualTo(until);
        }
    }

    static void energy(String name, Discs initial, Discs end, RunResult result) {
        double e0 = Observables.kineticEnergy(initial);
        double e1 = Observables.kineticEnergy(end);
        assertThat(result.kineticEnergyStart()).as("%s: reported initial energy", name).isEqualTo(e0);
        assertThat(result.kineticEnergyEnd()).as("%s: reported final energy", name).isEqualTo(e1);
        assertThat(Math.abs(e1 - e0)).as("%s: energy change (initial %s, final %s)", name, e0, e1)
                .isLessThanOrEqualTo(ENERGY_TOLERANCE * e0);
    }

    static void momentum(String name, Discs initial, Discs end, RunResult result) {
        double[] p0 = Observables.momentum(initial);
        double[] p1 = Observables.momentum(end);
        double scale = 0;
        for (int i = 0; i < initial.n; i++) {
            if (initial.invMass[i] > 0) {
                scale += Math.hypot(initial.vx[i], initial.vy[i]) / initial.invMass[i];
            }
        }
        double tolerance = MOMENTUM_TOLERANCE * Math.max(scale, Double.MIN_NORMAL);
        assertThat(Math.abs(p1[0] - p0[0])).as("%s: px change (%s -> %s)", name, p0[0], p1[0])
                .isLessThanOrEqualTo(tolerance);
        assertThat(Math.abs(p1[1] - p0[1])).as("%s: py change (%s -> %s)", name, p0[1], p1[1])
                .isLessThanOrEqualTo(tolerance);
        assertThat(result.momentumEnd()[0]).as("%s: reported final px", name).isEqualTo(p1[0]);
        assertThat(result.momentumEnd()[1]).as("%s: reported final py", name).isEqualTo(p1[1]);
    }

    static void fixedDiscsStayPut(String name, Discs initial, Discs end) {
        for (int i = 0; i < initial.n; i++) {
            if (initial.invMass[i] == 0) {
                assertThat(end.vx[i] == 0 && end.vy[i] == 0).as("%s: fixed disc %d at rest", name, i).isTrue();
                assertThat(end.x[i]).as("%s: fixed disc %d x", name, i).isEqualTo(initial.x[i]);
                assertThat(end.y[i]).as("%s: fixed disc %d y", name, i).isEqualTo(initial.y[i]);
            }
        }
    }

    static void insideBox(String name, Box box, Discs d) {
        double w = box.width();
        double h = box.height();
        for (int i = 0; i < d.n; i++) {
            double x = d.x[i];
            double y = d.y[i];
            if (box.periodic()) {
                assertThat(x >= 0 && x < w && y >= 0 && y < h)
                        .as("%s: disc %d at (%s, %s) wrapped into the %s x %s box", name, i, x, y, w, h).isTrue();
            } else {
                double r = d.radius[i];
                double slack = OVERLAP_TOLERANCE * r + 4 * Math.ulp(Math.max(w, h));
                assertThat(x - r >= -slack && x + r <= w + slack && y - r >= -slack && y + r <= h + slack)
                        .as("%s: disc %d at (%s, %s), radius %s, inside the walls of %s x %s", name, i, x, y, r, w, h)
                        .isTrue();
            }
        }
    }

    static void noOverlaps(String name, Box box, Discs d) {
        boolean periodic = box.periodic();
        double w = box.width();
        double h = box.height();
        double coordinateUlp = 4 * Math.ulp(Math.max(w, h));
        for (int i = 0; i < d.n; i++) {
            double xi = d.x[i];
            double yi = d.y[i];
            double ri = d.radius[i];
            for (int j = i + 1; j < d.n; j++) {
                double dx = d.x[j] - xi;
                double dy = d.y[j] - yi;
                if (periodic) {
                    dx -= w * Math.rint(dx / w);
                    dy -= h * Math.rint(dy / h);
                }
                double sigma = ri + d.radius[j];
                double gap = Math.sqrt(dx * dx + dy * dy) - sigma;
                if (gap < -(OVERLAP_TOLERANCE * sigma + coordinateUlp)) {
                    throw new AssertionError(String.format(
                            "%s: discs %d and %d overlap: centres %s apart, contact distance %s",
                            name, i, j, gap + sigma, sigma));
                }
            }
        }
    }
}
