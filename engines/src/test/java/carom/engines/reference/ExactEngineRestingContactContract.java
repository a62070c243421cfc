package carom.engines.reference;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.engine.Counter;
import carom.core.engine.Energy;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.observe.Observables;
import carom.core.physics.RestRule;
import carom.core.scene.BoundaryKind;
import carom.core.scene.Effects;
import carom.core.scene.Scene;
import carom.core.scene.SceneBuilder;
import carom.core.scene.Species;
import carom.core.state.Discs;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Resting contact under gravity ({@link RestRule}), which every exact engine must model the same way:
 * a disc whose bounces on a support become too small falls asleep at the support (velocity 0) and the
 * run goes on to {@code until}; a disc that is awake hitting it wakes it; the kinetic energy taken out
 * by falling asleep is reported (the energy put to rest), so that the energy balances.
 */
public abstract class ExactEngineRestingContactContract extends VariantContract {
    private static final double G = 9.81;

    protected ExactEngineRestingContactContract() {
        super(Contract.RESTING_CONTACT);
    }

    private RunResult run(Scene scene, double until) {
        return engine().run(scene, RunOptions.until(until));
    }

    /** One ball of radius 0.5 and mass 1 dropped from rest with its lowest point {@code h} above the floor. */
    private static Scene droppedBall(double h, double wallRestitution, double tc) {
        return SceneBuilder.create("dropped-ball").box(4, 10, BoundaryKind.WALLS)
                .species(Species.mobile("ball", 0.5, 1))
                .effects(Effects.NONE.withGravity(0, -G).withRestitution(1, wallRestitution).withTc(tc))
                .disc(0, 2, 0.5 + h, 0, 0).until(1).build();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void withTheTcModelADroppedBallFallsAsleepOnTheFloorAtTheBounceTheRuleNamesAndTheRunReachesUntil(EngineVariant variant) {
        use(variant);
        double h = 2;
        double e = 0.8;
        double tc = 1e-3;
        Scene scene = droppedBall(h, e, tc);
        // Bounce k meets the floor at v0 e^k; the first below g tc / 2 (in the air for less than tc)
        // is where the ball rests. Until then every interval is longer than tc: all bounces dissipative.
        double v0 = Math.sqrt(2 * G * h);
        int k = 0;
        double t = Math.sqrt(2 * h / G);
        while (v0 * Math.pow(e, k) >= 0.5 * G * tc) {
            k++;
            t += 2 * v0 * Math.pow(e, k) / G;
        }
        double restSpeed = v0 * Math.pow(e, k);
        RunResult r = run(scene, 20);
        Discs d = r.finalState();
        assertThat(d.y[0]).as("resting height").isCloseTo(0.5, within(1e-12));
        assertThat(d.x[0]).isEqualTo(2);
        assertThat(d.vx[0]).isZero();
        assertThat(d.vy[0]).isZero();
        assertThat(d.t[0]).isEqualTo(20);
        assertThat(r.counter(Counter.SLEEPS, -1)).isEqualTo(1);
        assertThat(r.counter(Counter.WAKES, -1)).isZero();
        assertThat(r.wallCollisions()).as("bounces, the last one the rest").isEqualTo(k + 1);
        // The energy put to rest is the kinetic energy it met the floor with then.
        assertThat(r.energyPutToRest()).isCloseTo(0.5 * restSpeed * restSpeed, within(1e-9 * restSpeed * restSpeed));
        // Asleep from the analytic time on: a run that ends just before it still sees the ball move.
        assertThat(run(scene, t * (1 - 1e-9)).counter(Counter.SLEEPS, -1)).isZero();
        assertThat(run(scene, t * (1 + 1e-9)).counter(Counter.SLEEPS, -1)).isEqualTo(1);
        // What is left is the potential energy at rest on the floor.
        Energy energy = Energy.of(scene, r);
        assertThat(energy.end()).isCloseTo(G * 0.5, within(1e-12));
        assertThat(energy.initial()).isCloseTo(G * (0.5 + h), within(1e-12));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void withoutTheTcModelADroppedBallFallsAsleepNearTheZenoTimeWithEnergyBelowResolution(EngineVariant variant) {
        use(variant);
        double h = 2;
        double e = 0.8;
        Scene scene = droppedBall(h, e, 0);
        double t0 = Math.sqrt(2 * h / G);
        double v0 = Math.sqrt(2 * G * h);
        double zeno = t0 + 2 * v0 * e / (G * (1 - e));
        RunResult before = run(scene, zeno - 0.01);
        assertThat(before.wallCollisions()).isGreaterThan(20);
        assertThat(before.counter(Counter.SLEEPS, -1)).isZero();
        RunResult r = run(scene, zeno + 1);
        Discs d = r.finalState();
        assertThat(d.y[0]).as("resting height").isCloseTo(0.5, within(1e-12));
        assertThat(d.vy[0]).isZero();
        assertThat(d.t[0]).isEqualTo(zeno + 1);
        assertThat(r.counter(Counter.SLEEPS, -1)).isEqualTo(1);
        // Asleep when the bounce would rise less than 2^-40 of the box (10): energy below m g h.
        double restHeight = RestRule.RESOLUTION * 10;
        assertThat(r.energyPutToRest()).isPositive().isLessThan(G * restHeight);
        assertThat(Energy.of(scene, r).end()).isCloseTo(G * 0.5, within(1e-12));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void aSleepingBallHitByAFallingOneWakesPassesTheMomentumOnAndSleepsAgain(EngineVariant variant) {
        use(variant);
        // Ball 0 settles on the floor (asleep by t = 0.35); ball 1, of the same mass, falls onto it
        // head-on from 3 above contact. Pairs are elastic and the TC model makes the floor bounce at
        // the same instant elastic too: 1 stops, 0 goes down, bounces, gives 1 its speed back and
        // stops on the floor. So ball 1 rises as if from a rigid floor, back to its start height at
        // twice the fall time, and ball 0 sleeps again where it was.
        double e = 0.5;
        double tc = 1e-3;
        Scene scene = SceneBuilder.create("wake").box(4, 10, BoundaryKind.WALLS)
                .species(Species.mobile("ball", 0.5, 1))
                .effects(Effects.NONE.withGravity(0, -G).withRestitution(1, e).withTc(tc))
                .disc(0, 2, 0.55, 0, 0)
                .disc(0, 2, 4.5, 0, 0)
                .until(1).build();
        RunResult early = run(scene, 0.4);
        assertThat(early.counter(Counter.SLEEPS, -1)).as("ball 0 asleep before the hit").isEqualTo(1);
        assertThat(early.finalState().y[0]).isCloseTo(0.5, within(1e-12));
        double fall = Math.sqrt(2 * 3 / G);
        RunResult justBefore = run(scene, fall * (1 - 1e-9));
        assertThat(justBefore.counter(Counter.WAKES, -1)).isZero();
        RunResult r = run(scene, 2 * fall);
        Discs d = r.finalState();
        assertThat(r.counter(Counter.WAKES, -1)).isEqualTo(1);
        assertThat(r.counter(Counter.SLEEPS, -1)).isEqualTo(2);
        assertThat(d.y[0]).isCloseTo(0.5, within(1e-12));
        assertThat(d.vy[0]).isZero();
        assertThat(d.x[1]).isEqualTo(2);
        assertThat(d.y[1]).as("ball 1 back at its start height").isCloseTo(4.5, within(1e-9));
        assertThat(d.vy[1]).as("at its apex").isCloseTo(0, within(1e-8));
        // Energy: ball 0's 0.05 of fall went to restitution and rest, ball 1 kept all of its own.
        Energy energy = Energy.of(scene, r);
        assertThat(energy.initial() - energy.end()).isCloseTo(G * 0.05, within(1e-9));
        assertThat(r.energyPutToRest()).isPositive().isLessThan(0.5 * (0.5 * G * tc) * (0.5 * G * tc));
    }

    /** Five discs dropped into a narrow box: three on the floor, two in the hollows above them. */
    public static Scene smallPile() {
        return SceneBuilder.create("small-pile").box(3.2, 6, BoundaryKind.WALLS)
                .species(Species.mobile("d", 0.5, 1))
                .effects(Effects.NONE.withGravity(0, -G).withRestitution(0.7, 0.7).withTc(1e-3))
                .disc(0, 0.55, 0.6, 0, 0)
                .disc(0, 1.6, 0.7, 0, 0)
                .disc(0, 2.65, 0.65, 0, 0)
                .disc(0, 1.075, 1.8, 0, 0)
                .disc(0, 2.125, 1.9, 0, 0)
                .until(5).build();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void aSmallPileSettlesCompletelyAndTheEnergyBalances(EngineVariant variant) {
        use(variant);
        Scene scene = smallPile();
        RunResult r = run(scene, 5);
        Discs d = r.finalState();
        Invariants.noOverlapsAndInside(scene, d);
        assertThat(Observables.kineticEnergy(d)).as("all at rest").isZero();
        assertThat(r.counter(Counter.SLEEPS, -1) - r.counter(Counter.WAKES, -1)).as("all asleep").isEqualTo(5);
        for (int i = 0; i < 3; i++) {
            assertThat(d.y[i]).as("disc %d on the floor", i).isCloseTo(0.5, within(1e-12));
        }
        for (int i = 3; i < 5; i++) {
            assertThat(d.y[i]).as("disc %d on the discs below", i).isBetween(1.2, 1.5);
        }
        Energy energy = Energy.of(scene, r);
        double lost = energy.initial() - energy.end();
        // Restitution and rest take energy out, never put it in.
        assertThat(lost).isGreaterThanOrEqualTo(r.energyPutToRest());
        assertThat(r.energyPutToRest()).isPositive();
        // Stays settled: nothing moves between 5 and 6, and nothing happens.
        RunResult later = run(scene, 6);
        Invariants.assertSameState(later.finalState(), d, 0);
        assertThat(later.collisions()).isEqualTo(r.collisions());
    }
    /**
     * A settled pile written back as a scene (every disc at rest, touching the floor or the discs below
     * it) starts asleep, bottom first, and stays exactly where it is; then a ball dropped on it wakes it.
     */
    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void aPileThatStartsAtRestOnItsSupportsStartsAsleepAndStaysPut(EngineVariant variant) {
        use(variant);
        Discs settled = run(smallPile(), 5).finalState();
        SceneBuilder again = SceneBuilder.create("pile-at-rest").box(3.2, 6, BoundaryKind.WALLS)
                .species(Species.mobile("d", 0.5, 1))
                .effects(Effects.NONE.withGravity(0, -G).withRestitution(0.7, 0.7).withTc(1e-3)).until(1);
        for (int i = 0; i < settled.n; i++) {
            again.disc(0, settled.x[i], settled.y[i], 0, 0);
        }
        Scene atRest = again.build();
        RunResult r = run(atRest, 1);
        // Where it was, to the rounding of a contact (a disc a hair above its support falls that hair).
        Invariants.assertSameState(r.finalState(), settled, 1e-12);
        assertThat(r.counter(Counter.SLEEPS, -1) - r.counter(Counter.WAKES, -1)).as("all asleep").isEqualTo(5);
        assertThat(r.energyPutToRest()).as("nothing was moving (but a hair's fall)").isLessThan(1e-12);

        Scene dropped = again.disc(0, 1.6, 4.5, 0, 0).build();
        RunResult hit = run(dropped, 1);
        Discs d = hit.finalState();
        Invariants.noOverlapsAndInside(dropped, d);
        assertThat(hit.counter(Counter.WAKES, -1)).as("the pile woken").isPositive();
    }
}
