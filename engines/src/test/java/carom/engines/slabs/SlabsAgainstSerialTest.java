package carom.engines.slabs;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.engine.SimulationStuckException;
import carom.core.scene.Effects;
import carom.core.scene.BoundaryKind;
import carom.core.scene.Scene;
import carom.core.scene.SceneBuilder;
import carom.core.scene.Species;
import carom.engines.reference.ChainScenes;
import carom.engines.reference.Invariants;
import carom.engines.reference.RandomScenes;
import carom.engines.serial.SerialEngine;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.Test;

/**
 * Several domains against the serial reference where cross-slab traffic is heavy: dense mid-size
 * scenes cut into 2 to 4 slabs (the windows are short, some are rolled back) and the six-disc chains
 * laid across slab boundaries, whose momentum crosses a boundary faster than any disc moves. Kept to
 * windows (tunable {@code windowEvents=0}): such traffic would otherwise soon merge the run
 * ({@link SlabsMergeTest}), and these tests are for the windows.
 */
class SlabsAgainstSerialTest {
    private static final double SAME = 1e-8;

    private static RunResult slabs(Scene scene, int domains) {
        return Invariants.check(scene, slabsWithEffects(scene, domains));
    }

    /** Without {@link Invariants#check}, whose energy check assumes elastic flight without gravity. */
    private static RunResult slabsWithEffects(Scene scene, int domains) {
        // The grid these scenes were laid out on (cells a hair wider than a diameter), whatever the
        // default for their packing fraction: the chains cross slab edges between given cells.
        RunResult r = FixedDomains.windowsOnly(domains).run(scene, RunOptions.until(scene.until()).withTunable("cellFactor", "1"));
        Invariants.noOverlapsAndInside(scene, r.finalState());
        return r;
    }

    private static void assertSame(String name, RunResult actual, RunResult serial) {
        Invariants.assertSameRun(name, actual, serial, SAME);
    }

    @ParameterizedTest(name = "N {0}, phi {1}, periodic {2}, {5} domains")
    @CsvSource({
            "900, 0.7, false, 4, 0.15, 2",
            "900, 0.7, true, 4, 0.15, 3",
            "1600, 0.45, true, 5, 0.4, 4",
            "1600, 0.6, false, 6, 0.3, 3",
            "2500, 0.7, true, 7, 0.12, 4",
    })
    void denseScenesCutIntoSlabsMatchSerial(int n, double phi, boolean periodic, long seed, double until, int domains) {
        Scene scene = RandomScenes.dense(n, phi, periodic, seed, until);
        RunResult r = slabs(scene, domains);
        RunResult serial = new SerialEngine().run(scene, RunOptions.until(until));
        assertThat(r.counters().get("domains")).isEqualTo(domains);
        assertThat(r.pairCollisions()).as("collisions").isGreaterThan(n / 2);
        assertThat(r.counters().get("crossDomainEvents")).as("cross-slab contacts").isPositive();
        assertThat(r.counters().get("windows")).isEqualTo(r.counters().get("commits") + r.counters().get("rollbacks"));
        // The phases' wall times: each measured, and the timed ones nested in the run's wall time.
        assertThat(r.counters()).extractingByKeys("setupNanos", "startNanos", "finalNanos").allMatch(t -> t > 0);
        assertThat(r.counters().get("startNanos") + r.counters().get("windowNanos") + r.counters().get("serialNanos"))
                .isLessThanOrEqualTo((long) Math.ceil(r.wallSeconds() * 1e9));
        assertSame(scene.name(), r, serial);
    }

    @Test
    void denseScenesDoRollBackAndStillMatch() {
        // Many short windows with heavy traffic at four boundaries: the undo path must be exercised.
        Scene scene = RandomScenes.dense(2500, 0.7, true, 7, 0.12);
        RunResult r = slabs(scene, 4);
        assertThat(r.counters().get("rollbacks")).as("rollbacks").isPositive();
        assertThat(r.counters().get("undoneEvents")).as("undone events").isPositive();
        assertSame(scene.name(), r, new SerialEngine().run(scene, RunOptions.until(scene.until())));
    }

    @ParameterizedTest(name = "{0} domains")
    @CsvSource({"2", "4"})
    void denseWalledGasWithGravityRestitutionAndTcMatchesSerial(int domains) {
        // Parabolic flight, dissipative pairs and walls, TC memory: all undone and redone by rollbacks.
        Scene scene = RandomScenes.dense(900, 0.5, false, 11, 0.25)
                .withEffects(Effects.NONE.withGravity(0, -2).withRestitution(0.8, 0.9).withTc(1e-3));
        RunResult r = slabsWithEffects(scene, domains);
        assertThat(r.counters().get("domains")).isEqualTo(domains);
        assertThat(r.counters().get("crossDomainEvents")).isPositive();
        assertSame(scene.name(), r, new SerialEngine().run(scene, RunOptions.until(scene.until())));
    }

    @ParameterizedTest(name = "{0} domains")
    @CsvSource({"2", "3"})
    void randomEffectScenesMatchSerialOnSeveralDomains(int domains) {
        int split = 0;
        for (long seed = 1; seed <= 40; seed++) {
            Scene scene = RandomScenes.effects(seed);
            RunResult r;
            RunResult serial;
            try {
                serial = new SerialEngine().run(scene, RunOptions.until(scene.until()));
            } catch (SimulationStuckException e) {
                continue;
            }
            r = slabsWithEffects(scene, domains);
            if (r.counters().get("domains") > 1) {
                split++;
            }
            assertSame(scene.name(), r, serial);
        }
        assertThat(split).as("scenes that ran on several domains").isGreaterThan(10);
    }

    @ParameterizedTest(name = "{0} domains")
    @CsvSource({"2", "3"})
    void theSixDiscChainAcrossASlabBoundaryMatchesSerial(int domains) {
        for (Scene scene : new Scene[] {ChainScenes.alongX(), ChainScenes.downTheRows()}) {
            RunResult r = slabs(scene, domains);
            assertThat(r.counters().get("domains")).isEqualTo(domains);
            assertSame(scene.name(), r, new SerialEngine().run(scene, RunOptions.until(scene.until())));
        }
        RunResult along = slabs(ChainScenes.alongX(), domains);
        assertThat(along.counters().get("crossDomainEvents")).as("chain contacts across the boundary").isPositive();
    }

    @Test
    void theSixDiscChainAcrossTheCornerOfFourBlocksMatchesSerial() {
        Scene scene = ChainScenes.acrossACorner();
        RunResult r = Invariants.check(scene, new FixedDomains(4, "windowEvents", "0", "domainRows", "2")
                .run(scene, RunOptions.until(scene.until()).withTunable("cellFactor", "1")));
        assertThat(r.counters().get("domains")).isEqualTo(4);
        assertThat(r.counters().get("domainRows")).isEqualTo(2);
        assertThat(r.counters().get("crossDomainEvents")).as("chain contacts across block edges").isPositive();
        assertThat(r.pairCollisions()).isEqualTo(new SerialEngine().run(scene, RunOptions.until(scene.until())).pairCollisions());
        assertSame(scene.name(), r, new SerialEngine().run(scene, RunOptions.until(scene.until())));
    }

    @ParameterizedTest(name = "{0} domains")
    @CsvSource({"2", "3", "4"})
    void theLongChainThroughSeveralSlabsMatchesSerial(int domains) {
        Scene scene = ChainScenes.longAlongX();
        RunResult r = slabs(scene, domains);
        assertThat(r.counters().get("domains")).isEqualTo(domains);
        assertThat(r.counters().get("crossDomainEvents")).as("chain contacts across boundaries").isPositive();
        assertSame(scene.name(), r, new SerialEngine().run(scene, RunOptions.until(scene.until())));
    }

    @ParameterizedTest(name = "{0} domains")
    @CsvSource({"2", "3", "5", "8"})
    void aTouchingCradleThroughEverySlabPassesItsMomentumAtOneInstant(int domains) {
        // 30 touching discs at x = 4..33 in a box 40 wide, struck from the left at t = 1: the momentum
        // crosses every slab edge at that one instant, by contacts between discs that were at rest. The last
        // disc leaves at speed 1 and is at 33 + 2 at t = 3; every other disc has moved back by nothing.
        SceneBuilder b = SceneBuilder.create("long-cradle").box(40, 4, BoundaryKind.WALLS)
                .species(Species.mobile("ball", 0.5, 1)).disc(0, 2, 2, 1, 0);
        for (int k = 0; k < 30; k++) {
            b.disc(0, 4 + k, 2, 0, 0);
        }
        Scene scene = b.until(3).build();
        RunResult r = slabs(scene, domains);
        assertThat(r.counters().get("domains")).isEqualTo(domains);
        assertThat(r.counters().get("crossDomainEvents")).as("contacts across slab edges").isPositive();
        assertThat(r.pairCollisions()).isEqualTo(30);
        assertThat(r.finalState().x[30]).isCloseTo(35, within(1e-12));
        assertThat(r.finalState().vx[30]).isCloseTo(1, within(1e-12));
        assertSame(scene.name(), r, new SerialEngine().run(scene, RunOptions.until(scene.until())));
    }

    @Test
    void threadsChangeNothing() {
        // Each window is a deterministic function of its start state, and so is the choice of merging
        // (counts, not time): threaded, parking and sequential (measurement mode) runs give the same bits,
        // the same windows and the same merged phases (here as many as can be).
        Scene scene = RandomScenes.dense(1600, 0.6, true, 9, 0.3);
        RunOptions options = FixedDomains.alternating(3, 400).options(RunOptions.until(scene.until()));
        RunResult threaded = new SlabsEngine().run(scene, options);
        RunResult sequential = new SlabsEngine().run(scene, options.withTunable("sequential", "true"));
        // Threads that park at once at every barrier (no spinning) hand off through park/unpark only.
        RunResult parking = new SlabsEngine().run(scene, options.withTunable("spins", "0"));
        for (RunResult other : new RunResult[] {sequential, parking}) {
            assertThat(other.finalState().x).isEqualTo(threaded.finalState().x);
            assertThat(other.finalState().vy).isEqualTo(threaded.finalState().vy);
            for (String counter : new String[] {"windows", "rollbacks", "undoneEvents", "crossDomainEvents", "events",
                    "merges", "mergedEvents"}) {
                assertThat(other.counters().get(counter)).as(counter).isEqualTo(threaded.counters().get(counter));
            }
        }
    }

    @Test
    void aBoxTooNarrowForSlabsRunsOnOneDomain() {
        Scene scene = RandomScenes.small(3);
        RunResult r = slabs(scene, 64);
        assertThat(r.counters().get("domains")).isLessThan(64);
        RunResult one = new SlabsEngine().run(scene.withUntil(1.0), RunOptions.until(1.0).withThreads(1));
        assertThat(one.counters().get("domains")).isEqualTo(1);
        assertThat(one.counters().get("windows")).isZero();
    }
}
