package carom.engines.reference;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatCode;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.engine.SimulationStuckException;
import carom.core.observe.Observables;
import carom.core.scene.BoundaryKind;
import carom.core.scene.Effects;
import carom.core.scene.Scene;
import carom.core.scene.SceneBuilder;
import carom.core.scene.Species;
import carom.core.state.Discs;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * An exact engine under effects (SPEC "Physics": gravity, restitution, wallRestitution, the TC model,
 * resting contact), on scenes whose behaviour is known: a bouncing ball (analytic bounce times, the
 * TC model's floor on the bounce interval, the Zeno stop without it), a settling stack, a Galton board
 * under the energy audit, random gravity scenes (the audit never fires; elastic ones conserve kinetic
 * plus potential energy), a cooling gas, and a ball that comes to rest without sinking into the floor.
 */
public abstract class ExactEngineEffectsContract extends VariantContract {
    private static final double G = 9.81;

    protected ExactEngineEffectsContract() {
        super(Contract.EFFECTS);
    }

    private RunResult run(Scene scene, double until) {
        return engine().run(scene, RunOptions.until(until));
    }

    private RunResult audited(Scene scene, double until) {
        return engine().run(scene, RunOptions.until(until).withTunable("auditEnergy", "true"));
    }

    // ---------------------------------------------------------------------------------------------
    // Bouncing ball

    /** One ball of radius 0.5 dropped from rest with its lowest point {@code h} above the floor. */
    private Scene bouncingBall(double h, double wallRestitution, double tc) {
        return SceneBuilder.create("bouncing-ball").box(4, 10, BoundaryKind.WALLS)
                .species(Species.mobile("ball", 0.5, 1))
                .effects(Effects.NONE.withGravity(0, -G).withRestitution(1, wallRestitution).withTc(tc))
                .disc(0, 2, 0.5 + h, 0, 0).until(1).build();
    }

    /**
     * The time of the k-th wall collision, found by bisecting {@code until} on the collision count (the
     * engine has no event log; each run of one ball takes microseconds): the earliest until at which
     * the count reaches k, to the last bits.
     */
    private double timeOfCollision(Scene scene, long k, double lo, double hi) {
        while (run(scene, hi).wallCollisions() < k) {
            hi = lo + 2 * (hi - lo);
        }
        for (int it = 0; it < 200; it++) {
            double mid = 0.5 * (lo + hi);
            if (mid <= lo || mid >= hi) {
                break;
            }
            if (run(scene, mid).wallCollisions() >= k) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        return hi;
    }

    /** The first {@code count} bounce times of the ball. */
    private double[] bounceTimes(Scene scene, int count, double first) {
        double[] t = new double[count];
        t[0] = timeOfCollision(scene, 1, 0, 1.5 * first);
        double interval = first;
        for (int k = 1; k < count; k++) {
            t[k] = timeOfCollision(scene, k + 1, t[k - 1], t[k - 1] + 1.5 * interval);
            interval = t[k] - t[k - 1];
        }
        return t;
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void bouncingBallIntervalsShrinkByTheWallRestitutionUntilTheTcModelHoldsThemAboveTc(EngineVariant variant) {
        use(variant);
        double h = 2;
        double e = 0.8;
        double tc = 1e-3;
        // Drifting sideways at 0.01, faster than g tc / 2, the ball is not at rest when its bounces
        // come closer than tc (resting contact would put a ball without drift to sleep there): the TC
        // model holds them. It drifts 0.06 in 6 time units, far from the side walls.
        Scene scene = SceneBuilder.create("bouncing-ball").box(4, 10, BoundaryKind.WALLS)
                .species(Species.mobile("ball", 0.5, 1))
                .effects(Effects.NONE.withGravity(0, -G).withRestitution(1, e).withTc(tc))
                .disc(0, 2, 0.5 + h, 0.01, 0).until(1).build();
        double t0 = Math.sqrt(2 * h / G);
        double v0 = Math.sqrt(2 * G * h);
        // Intervals 2 v0 e^k / g fall below tc after k = ln(2 v0 / (g tc)) / ln(1/e) ~ 31 bounces; look at 40.
        int count = 40;
        double[] t = bounceTimes(scene, count, t0);
        assertThat(t[0]).as("first impact sqrt(2h/g)").isCloseTo(t0, within(1e-12));
        assertThat(t[1] - t[0]).as("first flight 2 e v0 / g").isCloseTo(2 * e * v0 / G, within(1e-12));
        int dissipative = 0;
        int tcHeld = 0;
        for (int k = 1; k + 1 < count; k++) {
            double before = t[k] - t[k - 1];
            double after = t[k + 1] - t[k];
            if (before >= tc * (1 + 1e-6)) {
                // Bounce k came at least tc after bounce k-1: dissipative, the next flight is e times shorter.
                assertThat(after / before).as("interval ratio after bounce %d (%s -> %s)", k, before, after)
                        .isCloseTo(e, within(1e-9 * e));
                dissipative++;
            } else if (before < tc * (1 - 1e-6)) {
                // Within tc of the previous bounce: elastic, the flight repeats.
                assertThat(after).as("interval after bounce %d under the TC model", k).isCloseTo(before, within(1e-7 * before));
                tcHeld++;
            }
            assertThat(after).as("interval after bounce %d never shrinks below e tc", k).isGreaterThan(e * tc * (1 - 1e-9));
        }
        assertThat(dissipative).as("dissipative bounces").isGreaterThan(25);
        assertThat(tcHeld).as("bounces held elastic by the TC model").isGreaterThan(3);
    }

    private static final Pattern AT_TIME = Pattern.compile("at t = ([-0-9.eE+]+)");

    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    @Timeout(value = 20, unit = TimeUnit.SECONDS)
    void withoutTheTcModelTheBouncingBallFallsAsleepNearTheZenoTime(EngineVariant variant) {
        use(variant);
        double h = 2;
        double e = 0.8;
        Scene scene = bouncingBall(h, e, 0);
        double t0 = Math.sqrt(2 * h / G);
        double v0 = Math.sqrt(2 * G * h);
        double zeno = t0 + 2 * v0 * e / (G * (1 - e));
        // Before the Zeno time it bounces; after it, it lies on the floor (resting contact).
        assertThat(run(scene, zeno - 0.01).wallCollisions()).isGreaterThan(20);
        RunResult r = run(scene, zeno + 1);
        assertThat(r.finalState().y[0]).isCloseTo(0.5, within(1e-12));
        assertThat(r.finalState().vy[0]).isZero();
        // The bounce it rests at rises less than 1e-11: the remaining Zeno time is ~1e-5, so the
        // bounces it is spared are the last ones, and a run to just after the Zeno time has them all.
        assertThat(run(scene, zeno + 1e-4).wallCollisions()).isEqualTo(r.wallCollisions());
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void aBallBouncingToRestNeverSinksBelowTheFloorAndReachesUntil(EngineVariant variant) {
        use(variant);
        Scene scene = bouncingBall(2, 0.8, 1e-3);
        // Dissipative bounces end near t0 + 2 v0 e / (g (1 - e)) = 5.74; sample the TC regime after that.
        SplittableRandom random = new SplittableRandom(7);
        for (int k = 0; k < 200; k++) {
            double until = 6 + 9 * random.nextDouble();
            RunResult r = run(scene, until);
            Discs d = r.finalState();
            assertThat(d.y[0]).as("height at %s", until).isGreaterThanOrEqualTo(0.5 - 1e-9);
            assertThat(d.t[0]).as("clock").isEqualTo(until);
            assertThat(d.x[0]).as("no sideways drift").isEqualTo(2);
            // Held by the TC model at bounces of ~tc: speed about g tc / 2 or less (times e when the
            // bounce before last was dissipative).
            assertThat(Math.abs(d.vy[0])).as("speed at %s", until).isLessThan(G * 1e-3);
        }
    }

    // ---------------------------------------------------------------------------------------------
    // Many balls

    /** Potential energy m g y of every mobile disc (gravity along -y). */
    private double potential(Discs d, double g) {
        double sum = 0;
        for (int i = 0; i < d.n; i++) {
            if (d.invMass[i] > 0) {
                sum += g * d.y[i] / d.invMass[i];
            }
        }
        return sum;
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void aSettlingStackEndsNearlyAtRestWithoutOverlapsInsideTheBox(EngineVariant variant) {
        use(variant);
        // 35 discs of radius 0.25 in a box 3 wide: 5 columns 0.6 apart, 7 rows from y = 3.5 up, jittered,
        // random velocities.
        SplittableRandom random = new SplittableRandom(11);
        SceneBuilder b = SceneBuilder.create("settling-stack").box(3, 10, BoundaryKind.WALLS)
                .species(Species.mobile("d", 0.25, 1))
                .effects(Effects.NONE.withGravity(0, -G).withRestitution(0.7, 0.7).withTc(1e-3));
        for (int row = 0; row < 7; row++) {
            for (int col = 0; col < 5; col++) {
                b.disc(0, 0.3 + 0.6 * col + 0.08 * (random.nextDouble() - 0.5),
                        3.5 + 0.9 * row, random.nextDouble() - 0.5, random.nextDouble() - 0.5);
            }
        }
        Scene scene = b.until(3).build();
        Discs start = scene.newDiscs();
        RunResult r = run(scene, scene.until());
        Discs end = r.finalState();
        Invariants.noOverlapsAndInside(scene, end);
        double released = potential(start, G) - potential(end, G) + Observables.kineticEnergy(start);
        assertThat(released).as("energy released").isGreaterThan(35 * G * 2);
        assertThat(Observables.kineticEnergy(end)).as("kinetic energy left (released %s)", released)
                .isLessThan(1e-3 * released);
        for (int i = 0; i < end.n; i++) {
            assertThat(end.y[i]).as("disc %d settled in the bottom of the box", i).isLessThan(3.5);
        }
    }

    /**
     * A Galton board: rows of fixed pegs, balls dropped from above. Run under the energy audit (throws if
     * kinetic plus potential energy ever grows) to several horizons: no overlap beyond 1e-9 relative,
     * nothing leaves the box.
     */
    @ParameterizedTest(name = "{0}, until {1}")
    @MethodSource("galtonBoardKeepsBallsOutOfPegsAndEachOtherAndNeverGainsEnergyCases")
    void galtonBoardKeepsBallsOutOfPegsAndEachOtherAndNeverGainsEnergy(EngineVariant variant, double until) {
        use(variant);
        Scene scene = galtonBoard(30, 5);
        RunResult r = audited(scene, until);
        Invariants.noOverlapsAndInside(scene, r.finalState());
        assertThat(r.pairCollisions()).as("collisions").isGreaterThan(until < 1 ? 10 : 100);
        for (int i = 0; i < r.finalState().n; i++) {
            assertThat(r.finalState().t[i]).isEqualTo(until);
        }
    }

    private Scene galtonBoard(int balls, long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        double width = 8;
        SceneBuilder b = SceneBuilder.create("galton-" + seed).box(width, 12, BoundaryKind.WALLS)
                .species(Species.fixed("peg", 0.12))
                .species(Species.mobile("ball", 0.2, 1))
                .effects(Effects.NONE.withGravity(0, -G).withRestitution(0.6, 0.6).withTc(1e-3));
        for (int row = 0; row < 6; row++) {
            double y = 2.5 + 1.0 * row;
            double offset = row % 2 == 0 ? 0.5 : 1.0;
            for (double x = offset; x < width - 0.2; x += 1.0) {
                b.disc(0, x, y, 0, 0);
            }
        }
        int cols = 10;
        for (int k = 0; k < balls; k++) {
            double x = 0.6 + (width - 1.2) * (k % cols + 0.5) / cols + 0.1 * (random.nextDouble() - 0.5);
            double y = 9.2 + 0.8 * (k / cols);
            b.disc(1, x, y, 0.5 * (random.nextDouble() - 0.5), 0);
        }
        return b.until(3).build();
    }

    static java.util.stream.Stream<Long> auditSeeds() {
        return java.util.stream.LongStream.range(1, 41).boxed();
    }

    /** Random gravity scenes with restitution and the TC model, run past the judged horizon: the audit never fires. */
    @ParameterizedTest(name = "{0}, seed {1}")
    @MethodSource("auditSeedCases")
    void energyAuditNeverFiresOnRandomDissipativeGravityScenes(EngineVariant variant, long seed) {
        use(variant);
        Scene scene = RandomScenes.effects(seed);
        if (scene.box().periodic()) {
            return; // the audit refuses periodic boxes with gravity (energyAuditRefusesGravityInAPeriodicBox)
        }
        try {
            RunResult r = audited(scene, 2.5);
            Invariants.noOverlapsAndInside(scene, r.finalState());
        } catch (SimulationStuckException e) {
            // Without the TC model a disc may come to rest on a wall or peg: SPEC's error, not the audit.
            assertThat(scene.effects().tc()).as("stuck only without the TC model: %s", e.getMessage()).isZero();
        }
    }

    /** The same scenes made elastic (walls boxes): kinetic plus potential energy is conserved to 1e-9. */
    @ParameterizedTest(name = "{0}, seed {1}")
    @MethodSource("auditSeedCases")
    void elasticGravityScenesConserveKineticPlusPotentialEnergy(EngineVariant variant, long seed) {
        use(variant);
        Scene random = RandomScenes.effects(seed);
        if (random.box().periodic()) {
            return; // positions wrap, so potential energy is not defined across the box
        }
        Scene scene = random.withEffects(random.effects().withRestitution(1, 1).withTc(0));
        double e0 = BruteForceReference.mechanicalEnergy(scene, scene.newDiscs());
        RunResult r = audited(scene, 2.5);
        double e1 = BruteForceReference.mechanicalEnergy(scene, r.finalState());
        double scale = Observables.kineticEnergy(scene.newDiscs()) + Math.abs(e0);
        assertThat(Math.abs(e1 - e0)).as("%s: energy %s -> %s", scene.name(), e0, e1).isLessThanOrEqualTo(1e-9 * scale);
        Invariants.noOverlapsAndInside(scene, r.finalState());
    }

    // ---------------------------------------------------------------------------------------------
    // Cooling gas

    private Scene gas(double restitution, double tc) {
        Scene base = RandomScenes.dense(484, 0.5, true, 3, 4.0);
        return base.withEffects(Effects.NONE.withRestitution(restitution, restitution).withTc(tc));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    @Timeout(value = 60, unit = TimeUnit.SECONDS)
    void aCoolingGasLosesKineticEnergyMonotonicallyWithoutStalling(EngineVariant variant) {
        use(variant);
        Scene scene = gas(0.9, 1e-4);
        List<Double> energies = new ArrayList<>();
        for (double until : new double[] {1.0, 2.0, 4.0}) {
            RunResult r = audited(scene, until); // the audit throws if energy ever grows between events
            Invariants.noOverlapsAndInside(scene, r.finalState());
            assertThat(r.kineticEnergyEnd()).isEqualTo(Observables.kineticEnergy(r.finalState()));
            energies.add(r.kineticEnergyEnd());
            assertThat(r.pairCollisions()).as("collisions by %s", until).isGreaterThan((long) (484 * until));
        }
        double start = Observables.kineticEnergy(scene.newDiscs());
        assertThat(energies.get(0)).isLessThan(0.95 * start);
        assertThat(energies.get(1)).isLessThan(energies.get(0));
        assertThat(energies.get(2)).isLessThan(energies.get(1));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void theSameGasWithRestitutionOneConservesEnergy(EngineVariant variant) {
        use(variant);
        Scene scene = gas(1, 1e-4);
        Invariants.check(scene, run(scene, 4.0));
    }

    // ---------------------------------------------------------------------------------------------
    // Bugs

    /**
     * BUG (StepGrid.timeToTravel): with walls and at most two grid cells per axis, StepGrid's slack is
     * +Infinity (the neighbourhood spans every cell). Under gravity stepLength computes
     * 2 * Inf / (v + sqrt(v^2 + 2 a Inf)) = Inf / Inf = NaN, so the step end is NaN: nothing is
     * predicted (t <= NaN is false), every disc is advanced to NaN and the run loop ends at once
     * (epoch + NaN < until is false), returning an all-NaN final state with zero collisions and no error.
     */
    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void gravityInABoxOfAtMostTwoGridCellsPerAxisStaysFinite(EngineVariant variant) {
        use(variant);
        // Box 3 x 3, radius 0.5: cells of 2 diameters give at most 2 cells per axis.
        Scene scene = SceneBuilder.create("small-box").box(3, 3, BoundaryKind.WALLS)
                .species(Species.mobile("ball", 0.5, 1))
                .effects(Effects.NONE.withGravity(0, -G))
                .disc(0, 1.5, 2, 0.3, 0).until(1).build();
        RunResult r = run(scene, 1);
        Invariants.noOverlapsAndInside(scene, r.finalState());
        // Falls 1.5 - 0.5 = 1 in sqrt(2/g) = 0.45: at least one floor bounce by t = 1.
        assertThat(r.wallCollisions()).isPositive();
        BruteForceReference.Result reference = BruteForceReference.run(scene, 1);
        assertThat(r.finalState().y[0]).isCloseTo(reference.state().y[0], within(1e-9));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void gravityFreeScenesInTinyBoxesAreUnaffectedByTheInfiniteSlack(EngineVariant variant) {
        use(variant);
        // The same tiny box without gravity: timeToTravel takes its a == 0 branch (Inf / v = Inf), fine.
        Scene scene = SceneBuilder.create("small-box").box(3, 3, BoundaryKind.WALLS)
                .species(Species.mobile("ball", 0.5, 1))
                .disc(0, 1.5, 2, 0.3, -1).until(1).build();
        assertThatCode(() -> Invariants.check(scene, run(scene, 1))).doesNotThrowAnyException();
    }

    /**
     * BUG, seen through the engine (root cause in GravityContact.firstContact, see GravityContactTest's
     * disabled tangentialTouchingWithOutwardRoundingWhilePressedInGetsAnEventBeforeSinking).
     * A ball dropped onto a peg off-centre with restitution 0 (legal: [0, 1]): after the first impact
     * its normal speed is 0 up to rounding while gravity presses it into the peg. The engine must either
     * keep it out of the peg or stop with SimulationStuckException (resting contact is not modelled),
     * never let it sink in silently.
     */
    @ParameterizedTest(name = "{0}, offset {1}")
    @MethodSource("pegOffsetCases")
    void aBallStoppedDeadOnAPegNeverSinksIntoItSilently(EngineVariant variant, double offset) {
        use(variant);
        checkDeadStopOnPeg(offset, 0);
    }

    @ParameterizedTest(name = "{0}, offset {1}")
    @MethodSource("pegOffsetCases")
    void aBallStoppedDeadOnAPegUnderTheTcModelNeverSinksIntoItSilently(EngineVariant variant, double offset) {
        use(variant);
        checkDeadStopOnPeg(offset, 1e-3);
    }

    /**
     * BUG (EnergyAudit with a periodic box): the audit sums gravity's potential energy -m g.r over the
     * wrapped positions, so each time a falling disc re-enters at the top its potential energy jumps by
     * m g H and the audit reports "energy grew" on a correct run. Seeds 5, 6, 7, 19, 23, 24, 33 and 36 of
     * RandomScenes.effects (all periodic) throw, e.g. seed 5: "energy grew from 499.37 to 749.72 at
     * t = 0.7427". (A lone falling disc does not trip it: the audit runs only after collisions.)
     */
    /** With gravity in a periodic box potential energy has no bound: the audit refuses, clearly. */
    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void energyAuditRefusesGravityInAPeriodicBox(EngineVariant variant) {
        use(variant);
        Scene random = RandomScenes.effects(5);
        assertThat(random.box().periodic()).isTrue();
        assertThatThrownBy(() -> audited(random, 2.5)).isInstanceOf(carom.core.BadInputException.class)
                .hasMessageContaining("auditEnergy");
    }

    private void checkDeadStopOnPeg(double offset, double tc) {
        Scene scene = SceneBuilder.create("dead-stop").box(6, 6, BoundaryKind.WALLS)
                .species(Species.fixed("peg", 0.3))
                .species(Species.mobile("ball", 0.3, 1))
                .effects(Effects.NONE.withGravity(0, -G).withRestitution(0, 1).withTc(tc))
                .disc(0, 3, 2, 0, 0).disc(1, 3 + offset, 2.7, 0, 0).until(1).build();
        for (double until : new double[] {0.15, 0.2, 0.3, 0.5}) {
            try {
                RunResult r = run(scene, until);
                Invariants.noOverlapsAndInside(scene, r.finalState());
            } catch (SimulationStuckException e) {
                assertThat(e.getMessage()).contains("disc 1");
            }
        }
    }

    Stream<Arguments> galtonBoardKeepsBallsOutOfPegsAndEachOtherAndNeverGainsEnergyCases() {
        return EngineVariants.crossed(variants(), List.of(0.7, 1.5, 3d));
    }

    Stream<Arguments> auditSeedCases() {
        return EngineVariants.crossed(variants(), auditSeeds().toList());
    }

    Stream<Arguments> pegOffsetCases() {
        return EngineVariants.crossed(variants(), List.of(0.05, 0.1, 0.13, 0.2, 0.27, 0.31));
    }
}
