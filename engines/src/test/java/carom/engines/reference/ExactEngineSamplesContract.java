package carom.engines.reference;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import carom.core.state.Discs;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.LongStream;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * What every engine that samples ({@link carom.core.engine.Capability#SAMPLES}) promises of its samples: they come at
 * k·every in order, each is the exact state at its time (the brute-force judge's, to rounding), the
 * one at {@code until} is the final state to the bit, and asking for samples does not change the run:
 * the same collision counts and the same final state, bit for bit unless the engine says otherwise
 * ({@link EngineVariant#samplingTolerance}).
 */
public abstract class ExactEngineSamplesContract extends VariantContract {
    /** Short runs (see ExactEngineAgainstReferenceContract.SAME_AFTER_CHAOS for why short). */
    private static final double SAME = 1e-9;

    protected ExactEngineSamplesContract() {
        super(Contract.SAMPLES);
    }

    /** One sample as the sampler saw it (the engine reuses its buffer, so a copy). */
    record Taken(double time, Discs state, double virialSum) {
    }

    protected RunResult run(Scene scene, RunOptions options) {
        return engine().run(scene, options);
    }

    private List<Taken> sampled(Scene scene, double every, List<RunResult> result) {
        List<Taken> taken = new ArrayList<>();
        result.add(run(scene, RunOptions.until(scene.until())
                .withSamples(every, (t, state, virial) -> taken.add(new Taken(t, state.copy(), virial)))));
        return taken;
    }

    static Stream<Long> seeds() {
        return LongStream.range(1, 21).boxed();
    }

    @ParameterizedTest(name = "{0}, seed {1}")
    @MethodSource("seedCases")
    void samplesAreTheJudgesStateAtTheirTimes(EngineVariant variant, long seed) {
        use(variant);
        for (Scene scene : List.of(RandomScenes.small(seed).withUntil(1.0), RandomScenes.effects(seed).withUntil(1.0))) {
            List<RunResult> result = new ArrayList<>();
            List<Taken> taken = sampled(scene, 0.25, result);
            assertThat(taken).extracting(Taken::time).containsExactly(0.0, 0.25, 0.5, 0.75, 1.0);
            for (Taken sample : taken) {
                Discs judge = BruteForceReference.run(scene, sample.time()).state();
                Invariants.assertSameState(scene.name() + " at t = " + sample.time(), sample.state(), judge, SAME);
            }
        }
    }

    @ParameterizedTest(name = "{0}, seed {1}")
    @MethodSource("seedCases")
    void samplingChangesNothingOfTheRun(EngineVariant variant, long seed) {
        use(variant);
        for (Scene scene : List.of(RandomScenes.small(seed), RandomScenes.effects(seed),
                RandomScenes.dense(400, 0.6, seed % 2 == 0, seed, 0.5))) {
            RunResult plain = run(scene, RunOptions.until(scene.until()));
            List<RunResult> result = new ArrayList<>();
            List<Taken> taken = sampled(scene, scene.until() / 9.5, result);
            RunResult withSamples = result.get(0);
            assertThat(taken).hasSize(10);
            assertThat(withSamples.pairCollisions()).as("pair collisions").isEqualTo(plain.pairCollisions());
            assertThat(withSamples.wallCollisions()).as("wall collisions").isEqualTo(plain.wallCollisions());
            if (variant().samplingTolerance() == 0) {
                assertSameBits(withSamples.finalState(), plain.finalState());
            } else {
                Invariants.assertSameState(scene.name(), withSamples.finalState(), plain.finalState(), variant().samplingTolerance());
            }
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void theSampleAtUntilIsTheFinalStateToTheBit(EngineVariant variant) {
        use(variant);
        Scene scene = RandomScenes.dense(400, 0.5, true, 3, 2.0);
        List<RunResult> result = new ArrayList<>();
        List<Taken> taken = sampled(scene, 0.5, result);
        Taken last = taken.get(taken.size() - 1);
        assertThat(last.time()).isEqualTo(2.0);
        assertSameBits(last.state(), result.get(0).finalState());
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void theVirialSumGrowsAndEndsAtTheRunsPressure(EngineVariant variant) {
        use(variant);
        Scene scene = RandomScenes.dense(400, 0.5, true, 5, 2.0);
        List<RunResult> result = new ArrayList<>();
        List<Taken> taken = sampled(scene, 0.25, result);
        assertThat(taken.get(0).virialSum()).isZero();
        for (int k = 1; k < taken.size(); k++) {
            assertThat(taken.get(k).virialSum()).isGreaterThan(taken.get(k - 1).virialSum());
        }
        // Z = 1 + virial / (2 t E_kin) over the run, which the run reports from its blocks.
        RunResult r = result.get(0);
        double z = 1 + taken.get(taken.size() - 1).virialSum() / (2 * 2.0 * r.kineticEnergyStart());
        assertThat(z).isCloseTo(r.pressure().compressibility(), within(1e-9 * z));
    }

    private static void assertSameBits(Discs actual, Discs expected) {
        assertThat(actual.x).isEqualTo(expected.x);
        assertThat(actual.y).isEqualTo(expected.y);
        assertThat(actual.vx).isEqualTo(expected.vx);
        assertThat(actual.vy).isEqualTo(expected.vy);
    }

    Stream<Arguments> seedCases() {
        return EngineVariants.crossed(variants(), seeds().toList());
    }
}
