package carom.engines.cluster;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import carom.core.engine.ProgressListener;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Effects;
import carom.core.scene.Scene;
import carom.core.state.Discs;
import carom.engines.fast.FastEngine;
import carom.engines.reference.ChainScenes;
import carom.engines.reference.ExactEngineCheckpointContract;
import carom.engines.reference.ExactEngineCheckpointContract.Kept;
import carom.engines.reference.Invariants;
import carom.engines.reference.RandomScenes;
import carom.engines.serial.SerialEngine;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * The cluster engine with real worker JVMs on 127.0.0.1 (2 and 3 nodes, one or two slabs on each) against
 * the serial reference and {@code fast}, on short horizons (before chaos separates exact engines): a walled
 * and a periodic gas, a gas with gravity, restitution and the TC model, the six-disc chain across a slab
 * edge, and a dense scene at packing fraction 0.7 that rolls windows back. Most runs go one after another
 * over two workers started once for the class, as {@code ./carom node} runs them ({@link RunningWorkers});
 * the runs that lose a worker start their own: a {@code --nodes} run's worker killed mid-run, with samples
 * and checkpoint files being taken, and a {@code ./carom node} worker killed (two of the three kills are in
 * the fault suite, {@code -Pfaults}, for their time). After every test, passed or failed, no process but
 * the class's two workers may be left, and they must still serve at the end.
 */
class ClusterEngineTest {
    private static final double SAME = 1e-8;
    @RegisterExtension
    static final RunningWorkers workers = RunningWorkers.forEachClass(2);

    /** A run of {@code nodes} JVMs over the class's running workers, checked for overlaps and escapes. */
    private static RunResult cluster(Scene scene, int nodes) {
        return cluster(scene, RunOptions.until(scene.until()).withTunable("nodes", Integer.toString(nodes)));
    }

    private static RunResult cluster(Scene scene, RunOptions options) {
        RunResult r = workers.engine().run(scene, options);
        Invariants.noOverlapsAndInside(scene, r.finalState());
        return r;
    }

    @Test
    void denseWalledAndPeriodicScenesOnTwoNodesMatchSerial() {
        Scene walls = RandomScenes.dense(900, 0.7, false, 4, 0.15);
        RunResult r = cluster(walls, 2);
        assertThat(r.counters().get("domains")).isEqualTo(2);
        assertThat(r.counters().get("crossDomainEvents")).as("cross-slab contacts").isPositive();
        assertThat(r.counters().get("rollbacks")).as("rollbacks").isPositive();
        assertThat(r.counters().get("windows")).isEqualTo(r.counters().get("commits") + r.counters().get("rollbacks"));
        assertThat(r.counters().get("messages")).isPositive();
        assertThat(r.counters().get("messageBytes")).isGreaterThan(r.counters().get("messages"));
        Invariants.assertSameRun(walls.name(), r, new SerialEngine().run(walls, RunOptions.until(walls.until())), SAME);
    }

    @Test
    void periodicDenseSceneOnThreeNodesMatchesSerialAndFast() {
        Scene scene = RandomScenes.dense(900, 0.7, true, 4, 0.15);
        RunResult r = cluster(scene, 3);
        assertThat(r.counters().get("domains")).isEqualTo(3);
        assertThat(r.counters().get("rollbacks")).as("rollbacks").isPositive();
        Invariants.assertSameRun(scene.name(), r, new SerialEngine().run(scene, RunOptions.until(scene.until())), SAME);
        Invariants.assertSameRun(scene.name(), r, new FastEngine().run(scene, RunOptions.until(scene.until())), SAME);
    }

    @Test
    void oneNodeRunsTheWholeBoxInTheCoordinatorsJvmAndMatchesSerial() {
        Scene scene = RandomScenes.dense(900, 0.7, true, 4, 0.15);
        RunResult r = new ClusterEngine().run(scene, RunOptions.until(scene.until()).withTunable("nodes", "1"));
        assertThat(r.counters().get("domains")).isEqualTo(1);
        assertThat(r.counters().get("crossDomainEvents")).isZero();
        Invariants.assertSameRun(scene.name(), r, new SerialEngine().run(scene, RunOptions.until(scene.until())), SAME);
    }

    @Test
    void finalStatesOfMoreDiscsThanOneMessageHoldsComeInPartsAndMatchFast() {
        // 40,000 discs: each node's final states exceed one part of 16,384 (and, at 1e6 discs, Artery's frame).
        Scene scene = RandomScenes.dense(40_000, 0.5, true, 5, 0.05);
        RunResult r = cluster(scene, 2);
        assertThat(r.counters().get("messages.finish")).isEqualTo(2L * 3);
        Invariants.assertSameRun(scene.name(), r, new FastEngine().run(scene, RunOptions.until(scene.until())), SAME);
    }

    @Test
    void theSixDiscChainAcrossASlabEdgeMatchesSerial() {
        Scene scene = ChainScenes.alongX();
        // On the grid the chain was laid out on (cells a hair wider than a diameter), not the dilute default.
        RunResult r = cluster(scene, RunOptions.until(scene.until()).withTunable("nodes", "2").withTunable("cellFactor", "1"));
        assertThat(r.counters().get("domains")).isEqualTo(2);
        assertThat(r.counters().get("crossDomainEvents")).isPositive();
        Invariants.assertSameRun(scene.name(), r, new SerialEngine().run(scene, RunOptions.until(scene.until())), SAME);
    }

    @Test
    void theSixDiscChainAcrossTheCornerOfFourBlocksMatchesSerial() {
        // Two JVMs of two domains each: 2 x 2 blocks, the chain crossing diagonally where all four meet.
        Scene scene = ChainScenes.acrossACorner();
        // The grid the chain was laid out on (cells a hair wider than a diameter), not the dilute default.
        RunResult r = cluster(scene, RunOptions.until(scene.until()).withThreads(2).withTunable("nodes", "2")
                .withTunable("cellFactor", "1"));
        assertThat(r.counters().get("domains")).isEqualTo(4);
        assertThat(r.counters().get("domainRows")).isEqualTo(2);
        assertThat(r.counters().get("crossDomainEvents")).isPositive();
        Invariants.assertSameRun(scene.name(), r, new SerialEngine().run(scene, RunOptions.until(scene.until())), SAME);
    }

    @Test
    void gasesWithGravityAndWithRestitutionAndTcMatchSerialOnThreeNodes() {
        // Gravity with elastic collisions, and restitution with the TC model without gravity; inelastic
        // collisions under gravity (resting contact): ClusterRestingContactTest.
        for (Effects effects : List.of(Effects.NONE.withGravity(0, -2), Effects.NONE.withRestitution(0.8, 0.9).withTc(1e-3))) {
            Scene scene = RandomScenes.dense(900, 0.5, false, 11, 0.25).withEffects(effects);
            RunResult r = cluster(scene, 3);
            assertThat(r.counters().get("crossDomainEvents")).isPositive();
            Invariants.assertSameRun(scene.name(), r, new SerialEngine().run(scene, RunOptions.until(scene.until())), SAME);
        }
    }

    /** Eleven discs dropped onto the floor of a box wide enough for two slabs, ten into the hollows above them. */
    private static Scene widePile() {
        carom.core.scene.SceneBuilder b = carom.core.scene.SceneBuilder.create("wide-pile")
                .box(11.6, 6, carom.core.scene.BoundaryKind.WALLS)
                .species(carom.core.scene.Species.mobile("d", 0.5, 1))
                .effects(Effects.NONE.withGravity(0, -9.81).withRestitution(0.7, 0.7).withTc(1e-3));
        for (int k = 0; k < 11; k++) {
            b.disc(0, 0.55 + 1.05 * k, 0.6 + 0.05 * (k % 3), 0, 0);
        }
        for (int k = 0; k < 10; k++) {
            b.disc(0, 1.075 + 1.05 * k, 1.8 + 0.07 * (k % 2), 0, 0);
        }
        return b.until(5).build();
    }

    @Test
    void aPileSettlesAcrossTheSlabEdgeAsInSerial() {
        // Resting contact across nodes: discs sleep and wake in both slabs and in the coordinator's
        // cross-slab collisions. This pile is chaotic (serial and fast already end with floor discs up to
        // 0.15 apart), so the engines agree on the pile's shape, not on each disc: all asleep, the floor
        // row on the floor (some up to 1e-5 above it, held asleep in a nearly flat wedge between sleeping
        // neighbours, as in the other exact engines), the upper row resting on it, and the same height of
        // the pile's centre of mass.
        Scene scene = widePile();
        RunResult r = cluster(scene, 2);
        RunResult reference = new SerialEngine().run(scene, RunOptions.until(scene.until()));
        assertThat(r.counters().get("domains")).isEqualTo(2);
        assertThat(r.counters().get("crossDomainEvents")).as("cross-slab contacts").isPositive();
        assertThat(r.counters().get("sleeps") - r.counters().get("wakes")).as("all asleep").isEqualTo(scene.size());
        assertThat(r.energyPutToRest()).isPositive();
        Discs d = r.finalState();
        Invariants.noOverlapsAndInside(scene, d);
        long onFloor = java.util.stream.IntStream.range(0, d.n).filter(i -> Math.abs(d.y[i] - 0.5) < 1e-4).count();
        long above = java.util.stream.IntStream.range(0, d.n).filter(i -> d.y[i] > 0.6).count();
        assertThat(onFloor).as("floor row in %s", java.util.Arrays.toString(d.y)).isEqualTo(11);
        assertThat(above).as("upper row").isEqualTo(10);
        for (int i = 0; i < d.n; i++) {
            assertThat(d.vx[i]).isZero();
            assertThat(d.vy[i]).isZero();
        }
        assertThat(meanHeight(d)).as("centre of mass").isCloseTo(meanHeight(reference.finalState()), within(0.01));
    }

    private static double meanHeight(Discs d) {
        return java.util.Arrays.stream(d.y, 0, d.n).average().orElseThrow();
    }

    @Test
    void fourBlocksOnTwoJvmsMatchSerial() {
        // --threads 2: each JVM hosts two node actors, four domains in all, two of them in the coordinator's
        // JVM; in this walled square box they are 2 x 2 blocks (the layout with the shortest cuts), so
        // contacts and migrations cross vertical and horizontal edges and the corner where all four meet.
        Scene scene = RandomScenes.dense(900, 0.7, false, 4, 0.15);
        RunResult r = cluster(scene, RunOptions.until(scene.until()).withThreads(2).withTunable("nodes", "2"));
        assertThat(r.counters().get("nodes")).isEqualTo(2);
        assertThat(r.counters().get("domains")).isEqualTo(4);
        assertThat(r.counters().get("domainRows")).isEqualTo(2);
        assertThat(r.counters().get("crossDomainEvents")).as("cross-domain contacts").isPositive();
        assertThat(r.counters().get("rollbacks")).as("rollbacks").isPositive();
        Invariants.assertSameRun(scene.name(), r, new SerialEngine().run(scene, RunOptions.until(scene.until())), SAME);
    }

    @Test
    void moreSlabsPerJvmThanTheDispatcherServesAreRefusedBeforeAnyWorkerStarts() {
        Scene scene = RandomScenes.dense(100, 0.5, false, 11, 0.25);
        assertThatThrownBy(() -> new ClusterEngine().run(scene, RunOptions.until(scene.until()).withThreads(65)))
                .isInstanceOf(carom.core.BadInputException.class).hasMessageContaining("--threads");
        assertThat(workers.othersAlive()).isEmpty();
    }

    @Test
    void aWorkerKilledMidRunIsRecoveredFromTheLastCheckpointAndTheRunEndsInTheSameState() throws Exception {
        // Two slabs a JVM: six domains' state re-cut into four.
        killAWorkerMidRunAndRecover("40", 2);
    }

    /** In the fault suite ({@code -Pfaults}), as the seed-node case below: each kill costs worker JVMs' start. */
    @Test
    @Tag("faults")
    void aWorkerKilledBeforeTheFirstSavedCheckpointIsRecoveredFromTheStartAndTheRunEndsInTheSameState() throws Exception {
        killAWorkerMidRunAndRecover("1000000", 1);
    }

    private void killAWorkerMidRunAndRecover(String checkpointWindows, int slabsPerJvm) throws Exception {
        // Killed at the first progress report (after 64 windows): recovered from the checkpoint of window
        // 40, or from the scene (the first checkpoint). The run hands out samples and saves checkpoint
        // files all along. The two cases cover both choices (where from, slabs per JVM) in pairs: from a
        // checkpoint with two slabs a JVM, from the start with one; the seed-node test below recovers with
        // one slab a JVM from wherever it stood.
        Scene scene = RandomScenes.dense(900, 0.5, true, 5, 0.5);
        double every = scene.until() / 8;
        Going running = new Going();
        List<double[]> samples = new ArrayList<>();
        Kept kept = new Kept(scene.until() / 4, Long.MAX_VALUE);
        RunOptions o = RunOptions.until(scene.until()).withThreads(slabsPerJvm).withProgress(running).withTunables(Map.of("nodes", "3", "checkpointWindows", checkpointWindows))
                .withSamples(every, ClusterCheckpointTest.collect(samples)).withCheckpoints(kept);
        CompletableFuture<RunResult> run = CompletableFuture.supplyAsync(() -> new ClusterEngine().run(scene, o));
        try {
            awaitGoing(running, run);
            ProcessHandle worker = workers.othersAlive().getFirst();
            worker.destroyForcibly();
            RunResult r = run.get(300, TimeUnit.SECONDS);
            assertThat(r.counters().get("recoveries")).as("recoveries").isEqualTo(1);
            assertThat(running.notices).as("what the user is told").singleElement().asString()
                    .matches("cluster: worker \\d \\(pid " + worker.pid() + "\\) exited with status \\d+ in the middle of"
                            + " the run; going on from " + ("40".equals(checkpointWindows) ? "the checkpoint at t = \\S+" : "the start")
                            + " on the 2 JVMs left");
            assertThat(r.counters().get("domains")).as("slabs after the recovery").isEqualTo(2L * slabsPerJvm);
            Invariants.noOverlapsAndInside(scene, r.finalState());
            Invariants.assertSameRun(scene.name(), r, new SerialEngine().run(scene, RunOptions.until(scene.until())), SAME);

            // Every sample once, in order, as fast's to rounding, whether before or after the recovery.
            List<double[]> fastSamples = new ArrayList<>();
            new FastEngine().run(scene, RunOptions.until(scene.until()).withSamples(every, ClusterCheckpointTest.collect(fastSamples)));
            assertThat(samples).as("samples").hasSize(9).hasSameSizeAs(fastSamples);
            for (int k = 0; k < samples.size(); k++) {
                assertThat(samples.get(k)[0]).as("sample %d: time", k).isEqualTo(fastSamples.get(k)[0]);
                for (int q = 2; q < samples.get(k).length; q++) {
                    assertThat(samples.get(k)[q]).as("sample %d, value %d", k, q).isCloseTo(fastSamples.get(k)[q], within(SAME));
                }
            }

            // A checkpoint file saved after the recovery resumes on as many JVMs as were left (here the
            // class's running workers: a checkpoint names how many JVMs, not which), with the same samples
            // (windows end at sample times) and tunables (a recovery checkpoint re-anchors the clocks), as
            // 'carom resume' does, to the recovered run's bits and samples.
            ExactEngineCheckpointContract.Saved after = kept.saved.stream().filter(c -> ClusterCheckpoint.nodesOf(c.state()) == 2).findFirst()
                    .orElseThrow(() -> new AssertionError("no checkpoint after the recovery: " + kept.saved.size() + " saved"));
            assertThat(ClusterCheckpoint.slabsPerJvmOf(after.state())).isEqualTo(slabsPerJvm);
            List<double[]> resumedSamples = new ArrayList<>();
            RunResult resumed = workers.engine().resume(scene, RunOptions.until(scene.until()).withThreads(1).withProgress(t -> { }).withTunables(Map.of("nodes", "3", "checkpointWindows", checkpointWindows))
                    .withSamples(every, ClusterCheckpointTest.collect(resumedSamples)), after.state());
            String what = "resumed from t = " + after.time() + ", after the recovery";
            ClusterCheckpointTest.assertSameBits(what, resumed, r);
            assertThat(resumedSamples).as(what + ": samples").isNotEmpty();
            for (int k = 0; k < resumedSamples.size(); k++) {
                assertThat(resumedSamples.get(k)).as(what + ": sample " + k)
                        .isEqualTo(samples.get(samples.size() - resumedSamples.size() + k));
            }
        } finally {
            // Whatever failed above, the run must end (and with it its workers) before the next test.
            if (!run.isDone()) {
                workers.othersAlive().forEach(ProcessHandle::destroyForcibly);
            }
            try {
                run.get(300, TimeUnit.SECONDS);
            } catch (Exception failed) {
                // Reported above if it mattered.
            }
        }
    }

    /** A run's progress listener: counts down once the run reports progress, and keeps its notices. */
    private static final class Going implements ProgressListener {
        final CountDownLatch started = new CountDownLatch(1);
        final List<String> notices = new java.util.concurrent.CopyOnWriteArrayList<>();

        @Override
        public void simulatedTime(double time) {
            started.countDown();
        }

        @Override
        public void notice(String line) {
            notices.add(line);
        }
    }

    /**
     * Waits until the run reports progress; a run that ends first (it failed to start) fails the test at
     * once with the run's own error, not after the whole wait with none.
     */
    private static void awaitGoing(Going running, CompletableFuture<RunResult> run) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(300);
        while (!running.started.await(200, TimeUnit.MILLISECONDS)) {
            if (run.isDone()) {
                Throwable why = run.handle((r, e) -> e).join();
                throw new AssertionError("the run ended before it got going: " + why, why);
            }
            assertThat(System.nanoTime()).as("the run got going within 300 s").isLessThan(deadline);
        }
    }

    @Test
    @Tag("faults")
    void aSeedNodeWorkerKilledMidRunIsRecoveredOnTheNodesLeft() throws Exception {
        // Two workers as './carom node' runs them on two machines: the first seeds the cluster, the second
        // joins it. The second is killed mid-run: the failure detector holds it unreachable, the
        // coordinator downs it and recovers from the last checkpoint on itself and the first.
        int seedPort = ClusterLife.freePort();
        String seed = "127.0.0.1:" + seedPort;
        Process first = RunningWorkers.worker(seed, seedPort);
        Process second = RunningWorkers.worker(seed, ClusterLife.freePort());
        try {
            Scene scene = RandomScenes.dense(900, 0.5, true, 5, 0.5);
            Going running = new Going();
            RunOptions o = RunOptions.until(scene.until()).withThreads(1).withProgress(running).withTunables(
                    // 2 s unreachable rather than 20 (past the failure detector's 10 s pause): the test's wait.
                    Map.of("nodes", "3", "checkpointWindows", "40", "lostSeconds", "2"));
            CompletableFuture<RunResult> run = CompletableFuture.supplyAsync(
                    () -> ClusterEngine.joining(List.of(seed)).run(scene, o));
            awaitGoing(running, run);
            second.destroyForcibly();
            RunResult r = run.get(300, TimeUnit.SECONDS);
            assertThat(r.counters().get("recoveries")).as("recoveries").isEqualTo(1);
            // Lost after lostSeconds (2 here): the notice names the setting's value, not the default 20 s.
            assertThat(running.notices).as("what the user is told").singleElement().asString()
                    .matches("cluster: node at carom@127\\.0\\.0\\.1:\\d+ unreachable for 2\\.0 s in the middle of the run;"
                            + " going on from (the start|the checkpoint at t = \\S+) on the 2 JVMs left");
            assertThat(r.counters().get("domains")).as("domains after the recovery").isEqualTo(2);
            Invariants.noOverlapsAndInside(scene, r.finalState());
            Invariants.assertSameRun(scene.name(), r, new SerialEngine().run(scene, RunOptions.until(scene.until())), SAME);
            assertThat(first.isAlive()).as("the worker left serves on").isTrue();
        } finally {
            ClusterLife.destroyAndWait(List.of(first, second));
        }
    }
}
