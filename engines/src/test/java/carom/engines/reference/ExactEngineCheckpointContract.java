package carom.engines.reference;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import carom.core.engine.Checkpoints;
import carom.core.engine.Counter;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.engine.RunStopped;
import carom.core.scene.Effect;
import carom.core.scene.Scene;
import carom.core.state.Discs;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.stream.LongStream;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * What every engine that {@link carom.core.engine.Capability#CHECKPOINTS checkpoints} promises: checkpoints change nothing
 * of the run, and a run resumed from any of them, also from the end of a shorter run or from a stop,
 * ends in the same bits (final state, collision counts) and hands out the same samples as one run that
 * never stopped.
 */
public abstract class ExactEngineCheckpointContract extends VariantContract {
    protected ExactEngineCheckpointContract() {
        super(Contract.CHECKPOINTS);
    }

    /** Options to {@code until}: the variant's engine adds its own threads and settings. */
    private static RunOptions options(double until) {
        return RunOptions.until(until);
    }

    /** Whether the variant runs this scene at all (an engine that refuses some effects, or shear, skips them). */
    private boolean runs(Scene scene) {
        return variant().scenes().test(scene) && Effect.of(scene.effects()).stream().allMatch(engine().spec()::simulates)
                && (!scene.box().sheared() || engine().spec().can(carom.core.engine.Capability.LEES_EDWARDS));
    }

    /** A saved checkpoint. */
    public record Saved(double time, byte[] state) {
    }

    /** Keeps every checkpoint in memory; asks to stop once {@code stopAfterPolls} polls have come. */
    public static final class Kept implements Checkpoints {
        public final List<Saved> saved = new ArrayList<>();
        private final double every;
        private final long stopAfterPolls;
        private long polls;

        public Kept(double every, long stopAfterPolls) {
            this.every = every;
            this.stopAfterPolls = stopAfterPolls;
        }

        @Override
        public double every() {
            return every;
        }

        @Override
        public boolean stopRequested() {
            return ++polls > stopAfterPolls;
        }

        @Override
        public void save(double time, byte[] engineState) {
            saved.add(new Saved(time, engineState));
        }
    }

    static Stream<Long> seeds() {
        return LongStream.range(1, 7).boxed();
    }

    /**
     * Small scenes: plain, with effects (gravity, restitution, TC, pegs), the same of rough discs, dense
     * periodic and walled, mixed masses, sheared, on a vibrated floor (whose phase is the run's absolute
     * time, so a resumed run must see it where the unbroken one did).
     */
    static List<Scene> scenes(long seed) {
        return List.of(RandomScenes.small(seed), RandomScenes.effects(seed), RandomScenes.rough(seed),
                RandomScenes.dense(300, 0.6, seed % 2 == 0, seed, 1.0), RandomScenes.lightAmongHeavy(seed),
                RandomScenes.sheared(seed), VibratedFloorTest.randomScene(seed));
    }

    @ParameterizedTest(name = "{0}, seed {1}")
    @MethodSource("seedCases")
    void resumedFromAnyPeriodicCheckpointEndsInTheSameBits(EngineVariant variant, long seed) {
        use(variant);
        for (Scene scene : scenes(seed).stream().filter(this::runs).toList()) {
            double until = scene.until();
            List<double[]> straightSamples = new ArrayList<>();
            RunResult straight = engine().run(scene, sampled(options(until), until / 7, straightSamples));
            Kept kept = new Kept(until / 5, Long.MAX_VALUE);
            List<double[]> checkpointedSamples = new ArrayList<>();
            RunResult checkpointed = engine().run(scene, sampled(options(until), until / 7, checkpointedSamples)
                    .withCheckpoints(kept));
            assertThat(checkpointedSamples).as(scene.name()).hasSameSizeAs(straightSamples);
            assertSame(scene.name() + " with checkpoints", checkpointed, straight);
            assertThat(kept.saved).as(scene.name()).hasSizeGreaterThanOrEqualTo(2);
            assertThat(kept.saved.getLast().time()).isLessThanOrEqualTo(until);
            for (Saved from : kept.saved) {
                List<double[]> samples = new ArrayList<>();
                RunResult resumed = engine().resume(scene, sampled(options(until), until / 7, samples), from.state());
                assertSame(scene.name() + " resumed from t = " + from.time(), resumed, straight);
                List<double[]> after = straightSamples.subList(straightSamples.size() - samples.size(), straightSamples.size());
                if (engine().spec().can(carom.core.engine.Capability.SAMPLES) && from.time() < 0.8 * until) {
                    assertThat(samples).as(scene.name() + " samples after t = " + from.time()).isNotEmpty();
                }
                for (int k = 0; k < samples.size(); k++) {
                    assertThat(samples.get(k)).as(scene.name() + " sample after t = " + from.time()).isEqualTo(after.get(k));
                }
            }
        }
    }

    @ParameterizedTest(name = "{0}, seed {1}")
    @MethodSource("seedCases")
    void resumedPastTheEndOfAShorterRunEqualsOneLongerRun(EngineVariant variant, long seed) {
        use(variant);
        for (Scene scene : scenes(seed).stream().filter(this::runs).toList()) {
            double t1 = 0.4 * scene.until();
            double t2 = scene.until();
            Kept kept = new Kept(Double.POSITIVE_INFINITY, Long.MAX_VALUE);
            RunResult shorter = engine().run(scene, options(t1).withCheckpoints(kept));
            assertSame(scene.name() + " to t1 with a checkpoint", shorter, engine().run(scene, options(t1)));
            assertThat(kept.saved).hasSize(1);
            RunResult resumed = engine().resume(scene, options(t2), kept.saved.getFirst().state());
            assertSame(scene.name() + " resumed to t2", resumed, engine().run(scene, options(t2)));
            RunResult again = engine().resume(scene, options(t1), kept.saved.getFirst().state());
            assertSame(scene.name() + " resumed to t1 itself", again, shorter);
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void aSettlingPileResumesWithItsSleepersToTheSameBits(EngineVariant variant) {
        use(variant);
        // Discs fall asleep from t ~ 1; checkpoints before, among and after the sleeps.
        Scene scene = ExactEngineRestingContactContract.smallPile();
        org.junit.jupiter.api.Assumptions.assumeTrue(runs(scene), "the engine does not run a settling pile");
        double until = scene.until();
        RunResult straight = engine().run(scene, options(until));
        assertThat(straight.counter(Counter.SLEEPS, 0)).as("discs fell asleep").isPositive();
        Kept kept = new Kept(until / 10, Long.MAX_VALUE);
        assertSame("pile with checkpoints", engine().run(scene, options(until).withCheckpoints(kept)), straight);
        for (Saved from : kept.saved) {
            RunResult resumed = engine().resume(scene, options(until), from.state());
            assertSame("pile resumed from t = " + from.time(), resumed, straight);
            assertThat(resumed.counter(Counter.SLEEPS, 0)).isEqualTo(straight.counter(Counter.SLEEPS, 0));
            assertThat(resumed.counter(Counter.WAKES, 0)).isEqualTo(straight.counter(Counter.WAKES, 0));
            assertThat(resumed.energyPutToRest()).isEqualTo(straight.energyPutToRest());
        }
        // and a run that ended among the sleeps, resumed to the end
        Kept shorter = new Kept(Double.POSITIVE_INFINITY, Long.MAX_VALUE);
        engine().run(scene, options(0.4 * until).withCheckpoints(shorter));
        assertSame("pile resumed past a shorter run", engine().resume(scene, options(until), shorter.saved.getFirst().state()),
                straight);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void aStoppedRunSavesAndResumesToTheSameBits(EngineVariant variant) {
        use(variant);
        Scene scene = RandomScenes.dense(1000, 0.6, true, 3, 2.0);
        RunResult straight = engine().run(scene, options(scene.until()));
        Kept kept = new Kept(Double.POSITIVE_INFINITY, 1);
        assertThatThrownBy(() -> engine().run(scene, options(scene.until()).withCheckpoints(kept)))
                .isInstanceOf(RunStopped.class);
        assertThat(kept.saved).hasSize(1);
        assertThat(kept.saved.getFirst().time()).isBetween(0.0, scene.until());
        RunResult resumed = engine().resume(scene, options(scene.until()), kept.saved.getFirst().state());
        assertSame("resumed after a stop", resumed, straight);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void aDamagedStateIsRefused(EngineVariant variant) {
        use(variant);
        Scene scene = RandomScenes.small(1);
        Kept kept = new Kept(Double.POSITIVE_INFINITY, Long.MAX_VALUE);
        engine().run(scene, options(scene.until()).withCheckpoints(kept));
        byte[] state = kept.saved.getFirst().state();
        assertThatThrownBy(() -> engine().resume(scene, options(scene.until()), Arrays.copyOf(state, state.length - 9)))
                .isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> engine().resume(RandomScenes.small(2), options(scene.until()), state))
                .isInstanceOf(IllegalArgumentException.class);
    }

    /** The options with samples every {@code every} collected into {@code into}, if the engine samples. */
    private RunOptions sampled(RunOptions options, double every, List<double[]> into) {
        return engine().spec().can(carom.core.engine.Capability.SAMPLES) ? options.withSamples(every, collect(into)) : options;
    }

    private static carom.core.engine.Sampler collect(List<double[]> into) {
        return (t, state, virial) -> into.add(flatten(t, state));
    }

    /** The time, then x, y, vx, vy of every disc, then (rough discs) every angular velocity. */
    private static double[] flatten(double t, Discs d) {
        double[] all = new double[1 + 4 * d.n + (d.spins == null ? 0 : d.n)];
        all[0] = t;
        for (int i = 0; i < d.n; i++) {
            all[1 + 4 * i] = d.x[i];
            all[2 + 4 * i] = d.y[i];
            all[3 + 4 * i] = d.vx[i];
            all[4 + 4 * i] = d.vy[i];
            if (d.spins != null) {
                all[1 + 4 * d.n + i] = d.spins.omega[i];
            }
        }
        return all;
    }

    public static void assertSame(String what, RunResult actual, RunResult expected) {
        assertThat(actual.pairCollisions()).as(what + ": pair collisions").isEqualTo(expected.pairCollisions());
        assertThat(actual.wallCollisions()).as(what + ": wall collisions").isEqualTo(expected.wallCollisions());
        assertThat(actual.events()).as(what + ": events").isEqualTo(expected.events());
        assertThat(flatten(actual.until(), actual.finalState())).as(what + ": final state")
                .isEqualTo(flatten(expected.until(), expected.finalState()));
        assertThat(actual.kineticEnergyStart()).as(what + ": initial energy").isEqualTo(expected.kineticEnergyStart());
    }

    Stream<Arguments> seedCases() {
        return EngineVariants.crossed(variants(), seeds().toList());
    }
}
