package carom.engines.cluster;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.engine.RunStopped;
import carom.core.engine.Sampler;
import carom.core.scene.Scene;
import carom.core.state.Discs;
import carom.engines.reference.EngineVariant;
import carom.engines.reference.ExactEngineCheckpointContract;
import carom.engines.reference.ExactEngineCheckpointContract.Kept;
import carom.engines.reference.RandomScenes;
import carom.engines.reference.Tuned;
import carom.engines.slabs.SlabsEngine;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * Samples and checkpoints of the cluster engine on 2 nodes (real worker JVMs), on one dense periodic
 * scene that rolls windows back: the samples are those of {@code slabs} to rounding, and a run with
 * checkpoints, a run resumed from one in its middle, and a run resumed after a stop all end in the bits
 * (and hand out the samples) of the run that never stopped. The run that never stopped and the stopped
 * one start their own worker ({@code --nodes 2}); the others go over a running one ({@link RunningWorkers}),
 * as checkpoints name how many JVMs resume them, not which. Few runs, as each costs seconds; the whole
 * checkpoint contract of the exact engines runs behind {@code -Pphysics} ({@link Contract}). No worker
 * but the running one may be left after any test.
 */
class ClusterCheckpointTest {
    private static final Scene SCENE = RandomScenes.dense(400, 0.6, true, 3, 0.5);
    private static final double EVERY = SCENE.until() / 5;
    /** The run that never stopped, with samples every {@link #EVERY}, and its samples (once for both tests). */
    private static RunResult straight;
    private static final List<double[]> STRAIGHT_SAMPLES = new ArrayList<>();

    @RegisterExtension
    static final RunningWorkers running = RunningWorkers.forEachClass(1);

    @BeforeAll
    static void runStraight() {
        straight = new ClusterEngine().run(SCENE, twoNodes(SCENE.until()).withSamples(EVERY, collect(STRAIGHT_SAMPLES)));
        assertThat(running.othersAlive()).as("workers left").isEmpty();
    }

    private static RunOptions twoNodes(double until) {
        return RunOptions.until(until).withTunable("nodes", "2");
    }

    /** A sampler that copies every sample into {@code into}: time, virial sum, then x, y, vx, vy of each disc. */
    static Sampler collect(List<double[]> into) {
        return (t, state, virial) -> {
            double[] all = new double[2 + 4 * state.n];
            all[0] = t;
            all[1] = virial;
            for (int i = 0; i < state.n; i++) {
                all[2 + 4 * i] = state.x[i];
                all[3 + 4 * i] = state.y[i];
                all[4 + 4 * i] = state.vx[i];
                all[5 + 4 * i] = state.vy[i];
            }
            into.add(all);
        };
    }

    @Test
    void samplesAreThoseOfSlabsAndCheckpointsResumeToTheBitsOfTheUninterruptedRun() {
        double until = SCENE.until();
        double every = EVERY;
        List<double[]> slabsSamples = new ArrayList<>();
        new SlabsEngine().run(SCENE, RunOptions.until(until).withThreads(2).withTunable("mergeEvents", "64")
                .withSamples(every, collect(slabsSamples)));
        List<double[]> straightSamples = STRAIGHT_SAMPLES;
        assertThat(straight.counters().get("rollbacks")).as("rollbacks").isPositive();
        assertThat(straightSamples).hasSize(6).hasSameSizeAs(slabsSamples);
        for (int k = 0; k < straightSamples.size(); k++) {
            double[] c = straightSamples.get(k);
            double[] s = slabsSamples.get(k);
            assertThat(c[0]).as("sample %d: time", k).isEqualTo(s[0]);
            assertThat(c[1]).as("sample %d: virial sum", k).isCloseTo(s[1], within(1e-9 * Math.max(1, Math.abs(s[1]))));
            for (int q = 2; q < c.length; q++) {
                assertThat(c[q]).as("sample %d, value %d", k, q).isCloseTo(s[q], within(1e-8));
            }
        }

        Kept kept = new Kept(until / 3, Long.MAX_VALUE);
        List<double[]> checkpointedSamples = new ArrayList<>();
        RunResult checkpointed = running.engine().run(SCENE, twoNodes(until)
                .withSamples(every, collect(checkpointedSamples)).withCheckpoints(kept));
        assertSameBits("with checkpoints", checkpointed, straight);
        assertSameSamples("with checkpoints", checkpointedSamples, straightSamples);
        assertThat(kept.saved).as("two periodic checkpoints and the end's").hasSizeGreaterThanOrEqualTo(3);

        List<double[]> resumedSamples = new ArrayList<>();
        RunResult resumed = running.engine().resume(SCENE, twoNodes(until).withSamples(every, collect(resumedSamples)),
                kept.saved.get(0).state());
        assertSameBits("resumed from t = " + kept.saved.get(0).time(), resumed, straight);
        assertThat(resumedSamples).as("samples after the checkpoint").isNotEmpty();
        assertSameSamples("resumed", resumedSamples,
                straightSamples.subList(straightSamples.size() - resumedSamples.size(), straightSamples.size()));
    }

    /** The same samples, bit for bit: time, virial sum, every disc. */
    private static void assertSameSamples(String what, List<double[]> actual, List<double[]> expected) {
        assertThat(actual).as(what + ": samples").hasSameSizeAs(expected);
        for (int k = 0; k < actual.size(); k++) {
            assertThat(actual.get(k)).as(what + ": sample " + k).isEqualTo(expected.get(k));
        }
    }

    /** The same counts and the same final state, bit for bit. */
    static void assertSameBits(String what, RunResult actual, RunResult expected) {
        assertThat(actual.pairCollisions()).as(what + ": pair collisions").isEqualTo(expected.pairCollisions());
        assertThat(actual.wallCollisions()).as(what + ": wall collisions").isEqualTo(expected.wallCollisions());
        assertThat(actual.events()).as(what + ": events").isEqualTo(expected.events());
        Discs a = actual.finalState();
        Discs e = expected.finalState();
        for (double[][] pair : new double[][][] {{a.x, e.x}, {a.y, e.y}, {a.vx, e.vx}, {a.vy, e.vy}}) {
            assertThat(Arrays.equals(pair[0], pair[1])).as(what + ": final state, bit for bit").isTrue();
        }
    }

    @Test
    void aStoppedRunResumesToTheBitsAndAStateThatDoesNotFitIsRefusedBeforeAnyWorkerStarts() {
        Scene scene = SCENE;
        assertThat(straight.counters().get("windows")).as("windows").isGreaterThan(40);
        Kept kept = new Kept(Double.POSITIVE_INFINITY, 20);
        assertThatThrownBy(() -> new ClusterEngine().run(scene, twoNodes(scene.until())
                .withSamples(EVERY, collect(new ArrayList<>())).withCheckpoints(kept))).isInstanceOf(RunStopped.class);
        assertThat(kept.saved).hasSize(1);
        assertThat(running.othersAlive()).as("workers after a stop").isEmpty();
        byte[] state = kept.saved.getFirst().state();
        List<double[]> resumedSamples = new ArrayList<>();
        assertSameBits("resumed after a stop", running.engine().resume(scene, twoNodes(scene.until())
                .withSamples(EVERY, collect(resumedSamples)), state), straight);
        assertSameSamples("resumed after a stop", resumedSamples,
                STRAIGHT_SAMPLES.subList(STRAIGHT_SAMPLES.size() - resumedSamples.size(), STRAIGHT_SAMPLES.size()));

        Engine engine = new ClusterEngine();
        assertThatThrownBy(() -> engine.resume(scene, twoNodes(scene.until()), Arrays.copyOf(state, state.length - 9)))
                .isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> engine.resume(RandomScenes.dense(300, 0.6, true, 3, 0.5), twoNodes(scene.until()), state))
                .isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> engine.resume(scene, twoNodes(scene.until()), new byte[] {1, 2, 3}))
                .isInstanceOf(IllegalArgumentException.class);
    }

    /** The whole checkpoint contract of the exact engines on 2 nodes: hundreds of runs, each with a JVM. */
    @Nested
    @Tag("physics")
    class Contract extends ExactEngineCheckpointContract {
        /** Inelastic collisions under gravity are refused (sleeping discs are not carried across nodes). */
        @Override
        protected Stream<EngineVariant> variants() {
            Engine twoNodes = Tuned.of(new ClusterEngine(), 0, "nodes", "2");
            return Stream.of(EngineVariant.of("cluster on 2 nodes", twoNodes).onScenes(scene -> {
                try {
                    twoNodes.checkSupports(scene);
                    return true;
                } catch (carom.core.BadInputException e) {
                    return false;
                }
            }));
        }
    }
}
