package carom.engines.soak;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.engine.WorkEstimate;
import carom.core.observe.StateChecks;
import carom.core.scene.Scene;
import carom.core.scene.SceneReader;
import carom.core.state.Discs;
import carom.engines.EngineCatalog;
import carom.engines.reference.RandomScenes;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The soak profile (issue 23), outside the default suite: {@code ./mvnw -B -ntp -Psoak -pl engines -am
 * test} (add {@code -Dsoak.collisions=2e7} for a shorter dense gas). The exact engines {@code fast} and
 * {@code slabs} (2 threads) run long and are checked on the way:
 * <ul>
 *   <li>a dense elastic gas, {@value #DENSE_N} discs at packing fraction {@value #DENSE_PHI}, to
 *       {@code soak.collisions} collisions (1e8 by default): no overlap beyond rounding, energy and
 *       momentum kept to rounding;</li>
 *   <li>a cooling gas ({@code examples/cooling-gas.json}, restitution 0.9 with tc) for
 *       {@value #COOLING_SPAN} time units: no overlap, momentum kept, kinetic energy never growing;</li>
 *   <li>a settling pile ({@code examples/settling-stack.json}) to {@value #PILE_HORIZON}: no
 *       overlap, no disc out of the box, total energy (with gravity's) never growing.</li>
 * </ul>
 * Progress: the gases run in {@value #SEGMENTS} segments or more, each continuing from the last one's
 * final state, and every segment must reach its end time with collisions; the pile runs in one go
 * (see its test) and must reach its end. The figures (collisions, wall time, the machine's
 * load, deepest overlap, drifts) are printed for lab/notes/soak. Nothing asserts on wall time.
 */
@Tag("soak")
class SoakTest {
    static final int DENSE_N = 90_000;
    static final double DENSE_PHI = 0.72;
    static final double COOLING_SPAN = 3000;
    static final int SEGMENTS = 10;
    /** Threads for slabs. */
    static final int THREADS = 2;
    /** How far the settling pile runs: with resting contact its discs fall asleep and the run goes on to the end. */
    static final double PILE_HORIZON = 600;
    /** Exact engines leave rounding: overlaps of about 1e-15 of a contact distance, far below this. */
    static final double OVERLAP_BOUND = 1e-10;

    private static double targetCollisions() {
        return Double.parseDouble(System.getProperty("soak.collisions", "1e8"));
    }

    @ParameterizedTest
    @ValueSource(strings = {"fast", "slabs"})
    void aDenseGasKeepsEnergyMomentumAndDistanceOverManyCollisions(String engineName) {
        Scene start = RandomScenes.dense(DENSE_N, DENSE_PHI, true, 23, 1);
        double target = targetCollisions();
        // The estimate sizes the first segment; the measured rate the later ones.
        double rate = WorkEstimate.collisions(start, 1);
        Soak soak = new Soak(engineName, start);
        while (soak.collisions < target && soak.segments < 10 * SEGMENTS) {
            double left = SEGMENTS - Math.min(soak.segments, SEGMENTS - 1);
            // Never a sliver: a last segment of a few collisions may have none, which is no failure.
            double collisionsNext = Math.max((target - soak.collisions) / left, target / SEGMENTS / 10);
            soak.segment(collisionsNext / rate);
            rate = soak.collisions / soak.time;
        }
        soak.report("dense gas N " + DENSE_N + " phi " + DENSE_PHI);
        assertThat(soak.collisions).isGreaterThanOrEqualTo((long) target);
        assertThat(Math.abs(soak.energyDrift())).as("energy drift").isLessThan(1e-11);
        assertThat(soak.deepestOverlap).isLessThan(OVERLAP_BOUND);
        assertThat(soak.momentumDrift()).as("momentum drift per disc").isLessThan(1e-10);
    }

    @ParameterizedTest
    @ValueSource(strings = {"fast", "slabs"})
    void aCoolingGasLosesEnergyKeepsMomentumAndNeverOverlaps(String engineName) throws IOException {
        Soak soak = new Soak(engineName, example("cooling-gas.json"));
        for (int k = 0; k < SEGMENTS; k++) {
            soak.segment(COOLING_SPAN / SEGMENTS);
        }
        soak.report("cooling gas (examples/cooling-gas.json, restitution 0.9, tc 1e-4)");
        assertThat(soak.energy).as("it cooled").isLessThan(soak.energyAtStart / 2);
        assertThat(soak.momentumDrift()).as("momentum drift per disc").isLessThan(1e-10);
    }

    /**
     * In one run: a restart forgets when each disc last collided, which the tc model needs, and a
     * segmented pile came to rest early. Progress is the run reaching its end, and, for an engine that
     * reports it (fast; slabs does not), simulated time advancing on the way.
     */
    @ParameterizedTest
    @ValueSource(strings = {"fast", "slabs"})
    void aSettlingPileRunsOnWithoutOverlapOrEnergyGained(String engineName) throws IOException {
        Scene pile = example("settling-stack.json").withUntil(PILE_HORIZON);
        Engine engine = EngineCatalog.byName(engineName);
        List<Double> progress = new ArrayList<>();
        double load = loadAverage()[0];
        RunResult r = engine.run(pile, RunOptions.until(PILE_HORIZON).withThreads(THREADS)
                .withProgress(progress::add));
        assertThat(r.until()).isEqualTo(PILE_HORIZON);
        assertThat(progress).as("simulated time advances").isSorted().allMatch(t -> t <= PILE_HORIZON);
        double overlap = StateChecks.deepestOverlap(r.finalState(), pile.box());
        assertThat(overlap).isLessThan(OVERLAP_BOUND);
        assertThat(StateChecks.escapes(r.finalState(), pile.box())).isZero();
        double e0 = totalEnergy(pile, pile.newDiscs());
        double e1 = totalEnergy(pile, r.finalState());
        assertThat(e1).as("total energy").isLessThan(e0 / 2);
        System.out.printf("SOAK settling pile (examples/settling-stack.json, restitution 0.7, tc 1e-3, gravity), %s threads %d: "
                        + "until %s, %d collisions, %d progress reports, wall %.1f s (%.3g collisions/s), load %.2f -> %.2f, "
                        + "deepest overlap %.3g, energy %.9g -> %.9g%n",
                engineName, engine.threadsFor(THREADS), PILE_HORIZON, r.collisions(), progress.size(),
                r.wallSeconds(), r.collisionsPerSecond(), load, loadAverage()[0], overlap, e0, e1);
    }

    /**
     * A run segment after segment, each from the last one's final state, checked after each (it reached
     * its end with collisions; no overlap, no disc out of the box; the total energy, gravity's included,
     * never grew), with the figures summed.
     */
    private static final class Soak {
        final Engine engine;
        final String engineName;
        Scene scene;
        final double energyAtStart;
        final double[] momentumAtStart;
        double energy;
        double[] momentum;
        long collisions;
        double time;
        double wallSeconds;
        double deepestOverlap;
        int segments;
        final double loadBefore = loadAverage()[0];

        Soak(String engineName, Scene start) {
            this.engineName = engineName;
            this.engine = EngineCatalog.byName(engineName);
            this.scene = start;
            this.energyAtStart = totalEnergy(start, start.newDiscs());
            this.energy = energyAtStart;
            this.momentumAtStart = momentum(start.newDiscs());
            this.momentum = momentumAtStart;
        }

        void segment(double span) {
            RunResult r = engine.run(scene.withUntil(span), RunOptions.until(span).withThreads(THREADS));
            assertThat(r.until()).as("segment %d reached its end", segments).isEqualTo(span);
            assertThat(r.collisions()).as("segment %d had collisions", segments).isPositive();
            double overlap = StateChecks.deepestOverlap(r.finalState(), scene.box());
            assertThat(overlap).as("deepest overlap after segment %d", segments).isLessThan(OVERLAP_BOUND);
            assertThat(StateChecks.escapes(r.finalState(), scene.box())).as("discs out of the box").isZero();
            double energyNow = totalEnergy(scene, r.finalState());
            assertThat(energyNow).as("energy after segment %d", segments)
                    .isLessThanOrEqualTo(energy + 1e-12 * Math.abs(energyAtStart));
            deepestOverlap = Math.max(deepestOverlap, overlap);
            collisions += r.collisions();
            time += span;
            wallSeconds += r.wallSeconds();
            segments++;
            energy = energyNow;
            momentum = momentum(r.finalState());
            scene = scene.withState(r.finalState());
        }

        double energyDrift() {
            return (energy - energyAtStart) / Math.abs(energyAtStart);
        }

        /** |Δp| per disc, in units of the mean speed's momentum (sqrt(2 KE / N) for unit masses). */
        double momentumDrift() {
            int n = scene.newDiscs().n;
            double dp = Math.hypot(momentum[0] - momentumAtStart[0], momentum[1] - momentumAtStart[1]);
            return dp / n / Math.sqrt(2 * kinetic(scene.newDiscs()) / n);
        }

        void report(String what) {
            System.out.printf("SOAK %s, %s threads %d: %d collisions in %d segments, simulated time %.6g, wall %.1f s "
                            + "(%.3g collisions/s), load %.2f -> %.2f, deepest overlap %.3g, energy %.9g -> %.9g "
                            + "(drift %.3g), momentum drift per disc %.3g%n",
                    what, engineName, engine.threadsFor(THREADS), collisions, segments, time, wallSeconds,
                    collisions / wallSeconds, loadBefore, loadAverage()[0], deepestOverlap, energyAtStart, energy,
                    energyDrift(), momentumDrift());
        }
    }

    static double kinetic(Discs d) {
        double e = 0;
        for (int i = 0; i < d.n; i++) {
            if (!d.isFixed(i)) {
                e += 0.5 * d.mass(i) * (d.vx[i] * d.vx[i] + d.vy[i] * d.vy[i]);
            }
        }
        return e;
    }

    static double[] momentum(Discs d) {
        double px = 0;
        double py = 0;
        for (int i = 0; i < d.n; i++) {
            if (!d.isFixed(i)) {
                px += d.mass(i) * d.vx[i];
                py += d.mass(i) * d.vy[i];
            }
        }
        return new double[] {px, py};
    }

    /** Kinetic plus gravity's potential energy, E = KE - Σ m g·r over the mobile discs. */
    static double totalEnergy(Scene scene, Discs d) {
        double e = kinetic(d);
        for (int i = 0; i < d.n; i++) {
            if (!d.isFixed(i)) {
                e -= d.mass(i) * (scene.effects().gravityX() * d.x[i] + scene.effects().gravityY() * d.y[i]);
            }
        }
        return e;
    }

    /** The 1-minute load average (and the 5 and 15), or NaN where the system does not say. */
    static double[] loadAverage() {
        try {
            String[] f = Files.readString(Path.of("/proc/loadavg")).split(" ");
            return new double[] {Double.parseDouble(f[0]), Double.parseDouble(f[1]), Double.parseDouble(f[2])};
        } catch (IOException | RuntimeException e) {
            return new double[] {Double.NaN, Double.NaN, Double.NaN};
        }
    }

    static Scene example(String name) throws IOException {
        for (Path p = Path.of("").toAbsolutePath(); p != null; p = p.getParent()) {
            if (Files.isDirectory(p.resolve("examples"))) {
                return SceneReader.read(p.resolve("examples").resolve(name));
            }
        }
        throw new IOException("no examples folder above " + Path.of("").toAbsolutePath());
    }
}
