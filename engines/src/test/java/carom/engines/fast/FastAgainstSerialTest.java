package carom.engines.fast;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.engine.SimulationStuckException;
import carom.core.scene.BoundaryKind;
import carom.core.scene.Effects;
import carom.core.scene.Scene;
import carom.core.scene.SceneBuilder;
import carom.core.scene.Species;
import carom.core.state.Discs;
import carom.engines.reference.Invariants;
import carom.engines.reference.RandomScenes;
import carom.engines.serial.SerialEngine;
import java.util.stream.LongStream;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.api.Test;

/**
 * The fast engine against the serial reference where the brute-force judge is too slow or does not
 * model the effect: dense short scenes (hundreds of discs, a few collisions per disc, before chaos
 * amplifies rounding beyond 1e-8), random scenes with gravity, restitution, the TC model and pegs, and
 * hand-made gravity cases (a bouncing ball, a ball bouncing on a fixed peg).
 */
class FastAgainstSerialTest {
    private static final double SAME = 1e-8;

    private static void assertSame(String name, RunResult fast, RunResult serial) {
        Invariants.assertSameRun(name, fast, serial, SAME);
        Discs f = fast.finalState();
        Discs s = serial.finalState();
        for (int i = 0; i < s.n; i++) {
            assertThat(f.t[i]).as("%s: clock of %d", name, i).isEqualTo(s.t[i]);
        }
    }

    @ParameterizedTest(name = "N {0}, phi {1}, periodic {2}")
    @CsvSource({
            "400, 0.3, true, 1, 1.0",
            "400, 0.5, false, 2, 0.5",
            "900, 0.6, true, 3, 0.3",
            "900, 0.7, false, 4, 0.15",
            "1600, 0.45, true, 5, 0.4",
    })
    void denseShortScenesMatchSerial(int n, double phi, boolean periodic, long seed, double until) {
        Scene scene = RandomScenes.dense(n, phi, periodic, seed, until);
        RunResult fast = Invariants.check(scene, new FastEngine().run(scene, RunOptions.until(until)));
        RunResult serial = new SerialEngine().run(scene, RunOptions.until(until));
        assertThat(fast.pairCollisions()).as("collisions").isGreaterThan(n / 2);
        assertSame(scene.name(), fast, serial);
    }

    static Stream<Long> seeds() {
        return LongStream.range(1, 61).boxed();
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void effectScenesMatchSerial(long seed) {
        Scene scene = RandomScenes.effects(seed);
        RunResult fast = null;
        RunResult serial = null;
        SimulationStuckException fastStuck = null;
        SimulationStuckException serialStuck = null;
        try {
            // The audit sums gravity's potential, which jumps when a disc wraps: walled scenes only.
            String audit = Boolean.toString(!scene.box().periodic());
            fast = new FastEngine().run(scene, RunOptions.until(scene.until()).withTunable("auditEnergy", audit));
        } catch (SimulationStuckException e) {
            fastStuck = e;
        }
        try {
            serial = new SerialEngine().run(scene, RunOptions.until(scene.until()));
        } catch (SimulationStuckException e) {
            serialStuck = e;
        }
        if (fastStuck != null || serialStuck != null) {
            assertThat(fastStuck).as("fast stuck as serial (%s)", serialStuck).isNotNull();
            assertThat(serialStuck).as("serial stuck as fast (%s)", fastStuck).isNotNull();
            return;
        }
        assertSame(scene.name(), fast, serial);
        Invariants.noOverlapsAndInside(scene, fast.finalState());
    }

    @Test
    void bouncingBallUnderGravityMatchesSerial() {
        // Elastic ball dropped from rest at height 5 bounces back to 5 every 2 sqrt(2 * 4.5 / 9.81) s.
        Scene scene = SceneBuilder.create("bounce").box(4, 10, BoundaryKind.WALLS)
                .species(Species.mobile("ball", 0.5, 1)).disc(0, 2, 5, 0.3, 0)
                .effects(Effects.NONE.withGravity(0, -9.81)).until(7).build();
        RunResult fast = new FastEngine().run(scene, RunOptions.until(7));
        RunResult serial = new SerialEngine().run(scene, RunOptions.until(7));
        assertThat(fast.wallCollisions()).isGreaterThanOrEqualTo(4);
        assertSame("bounce", fast, serial);
        double period = 2 * Math.sqrt(2 * 4.5 / 9.81);
        double phase = 7 - period * Math.floor(7 / period);
        // Back at height 5 at whole periods; between, free fall from the top of the arc.
        double expectedY = phase < period / 2 ? 5 - 0.5 * 9.81 * phase * phase
                : 5 - 0.5 * 9.81 * (period - phase) * (period - phase);
        assertThat(fast.finalState().y[0]).isCloseTo(expectedY, within(1e-9));
    }

    @Test
    void ballOnAFixedPegUnderGravityMatchesSerial() {
        // A ball dropped slightly off-centre onto a peg, with restitution and the TC model, among walls.
        Scene scene = SceneBuilder.create("peg").box(6, 10, BoundaryKind.WALLS)
                .species(Species.mobile("ball", 0.4, 1)).species(Species.fixed("peg", 0.3))
                .disc(1, 3, 3, 0, 0).disc(0, 3.05, 6, 0, 0).disc(0, 1, 8, 0.5, 0)
                .effects(Effects.NONE.withGravity(0, -9.81).withRestitution(0.8, 0.9).withTc(1e-3)).until(5).build();
        RunResult fast = new FastEngine().run(scene, RunOptions.until(5).withTunable("auditEnergy", "true"));
        RunResult serial = new SerialEngine().run(scene, RunOptions.until(5));
        assertThat(fast.pairCollisions()).isPositive();
        assertSame("peg", fast, serial);
        assertThat(fast.finalState().x[0]).isEqualTo(3);
        assertThat(fast.finalState().y[0]).isEqualTo(3);
    }
}
