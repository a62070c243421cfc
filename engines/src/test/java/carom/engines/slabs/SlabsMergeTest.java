package carom.engines.slabs;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Effects;
import carom.core.scene.Scene;
import carom.core.scene.SceneReader;
import carom.engines.reference.Invariants;
import carom.engines.reference.RandomScenes;
import carom.engines.serial.SerialEngine;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Merged phases ({@link MergePolicy}): where discs touch across slab edges all the time, the run
 * stops paying for windows and goes on as one domain; it changes phase without changing the physics.
 * Counts only, no timing.
 */
class SlabsMergeTest {
    private static Scene example(String name) {
        // Surefire runs in engines/; look upwards for the repository's examples.
        for (Path dir = Path.of("").toAbsolutePath(); dir != null; dir = dir.getParent()) {
            Path file = dir.resolve("examples").resolve(name);
            if (Files.isRegularFile(file)) {
                return SceneReader.read(file);
            }
        }
        throw new IllegalStateException("no examples/" + name + " above " + Path.of("").toAbsolutePath());
    }

    @ParameterizedTest(name = "{0} to t = {1}")
    @CsvSource({"settling-stack.json, 4", "galton-board.json, 4"})
    void aGranularPileDoesNotRollWindowsBackForEveryContact(String file, double until) {
        // Issue 22: windows a few events long, each rolled back by the next contact across the slab edge
        // (settling-stack to t = 4: 2,910 rollbacks undoing 1,902,796 events for 67,101 collisions; to
        // t = 2, 150 undoing 21,042 for 3,181; the Galton board to t = 2: 316 and 20,325 for 25,168).
        // Now the run starts merged and sees that contacts across the slab edge come every few events:
        // it tries the slabs rarely if at all, and merges again at once.
        Scene scene = example(file);
        RunResult r = new SlabsEngine().run(scene, RunOptions.until(until).withThreads(2));
        long collisions = r.pairCollisions();
        assertThat(collisions).isGreaterThan(3000);
        assertThat(r.counters().get("rollbacks")).as("rollbacks").isLessThan(collisions / 100);
        assertThat(r.counters().get("undoneEvents")).as("undone events").isLessThan(collisions / 5);
        assertThat(r.counters().get("windows")).as("windows").isLessThan(collisions / 50)
                .isLessThanOrEqualTo(2 * MergePolicy.BLOCK_WINDOWS);
        assertThat(r.counters().get("mergedCrossSlabEvents")).as("would-be cross-slab events").isPositive();
        assertThat(r.counters().get("mergedEvents")).as("events in merged phases").isGreaterThan(r.events() / 2);
    }

    @Test
    void aRunStartsMergedForTheStartBudgetAndOnlyThenMaySplit() {
        // From a fresh JVM a split before the loop is compiled costs more than it saves (lab note
        // slabs-short-runs): a run shorter than the start budget never starts a thread, a longer one
        // splits once the budget is spent, where windows pay (a large gas).
        Scene shortRun = example("thesis-100k.json");
        RunResult merged = new SlabsEngine().run(shortRun, RunOptions.until(shortRun.until()).withThreads(2));
        assertThat(merged.events()).isLessThan(MergePolicy.START_BUDGET);
        assertThat(merged.counters().get("windows")).as("windows").isZero();
        assertThat(merged.counters().get("mergedEvents")).isEqualTo(merged.events());

        Scene longRun = example("thesis-100k.json").withUntil(2.0);
        RunResult split = new SlabsEngine().run(longRun, RunOptions.until(longRun.until()).withThreads(2));
        assertThat(split.events()).isGreaterThan(MergePolicy.START_BUDGET);
        assertThat(split.counters().get("mergedEvents")).as("merged at the start")
                .isGreaterThanOrEqualTo(MergePolicy.START_BUDGET).isLessThan(split.events());
        assertThat(split.counters().get("windows")).as("windows after the start").isPositive();
    }

    @Test
    void everyEventIsASlabsASerialPhasesOrAMergedPhases() {
        Scene scene = example("settling-stack.json");
        RunResult r = FixedDomains.alternating(2, 500).run(scene, RunOptions.until(2));
        assertThat(r.counters().get("merges")).as("tries of the slabs that failed").isGreaterThan(2);
        assertThat(r.counters().get("slab0.events") + r.counters().get("slab1.events")
                + r.counters().get("crossDomainEvents") + r.counters().get("migrations")
                + r.counters().get("mergedEvents")).isEqualTo(r.events());
        assertThat(r.counters().get("windows")).isEqualTo(r.counters().get("commits") + r.counters().get("rollbacks"));
    }

    @ParameterizedTest(name = "N {0}, phi {1}, periodic {2}, {5} domains, merged phases of {6} events")
    @CsvSource({
            "900, 0.7, false, 4, 0.15, 2, 50",
            "1600, 0.45, true, 5, 0.4, 4, 200",
            "2500, 0.7, true, 7, 0.12, 3, 1000",
    })
    void phasesInTurnMatchSerial(int n, double phi, boolean periodic, long seed, double until, int domains,
                                 int mergeEvents) {
        Scene scene = RandomScenes.dense(n, phi, periodic, seed, until);
        RunResult r = Invariants.check(scene, FixedDomains.alternating(domains, mergeEvents).run(scene,
                RunOptions.until(until)));
        // Merged at the start, split, merged again at least once.
        assertThat(r.counters().get("merges")).as("merged phases after the first").isPositive();
        assertThat(r.counters().get("windows")).isGreaterThanOrEqualTo(MergePolicy.BLOCK_WINDOWS);
        assertThat(r.counters().get("mergedEvents")).isPositive().isLessThan(r.events());
        Invariants.assertSameRun(scene.name(), r, new SerialEngine().run(scene, RunOptions.until(until)), 1e-8);
    }

    @Test
    void phasesInTurnUnderGravityRestitutionAndTcMatchSerial() {
        Scene scene = RandomScenes.dense(900, 0.5, false, 11, 0.25)
                .withEffects(Effects.NONE.withGravity(0, -2).withRestitution(0.8, 0.9).withTc(1e-3));
        RunResult r = FixedDomains.alternating(2, 20).run(scene, RunOptions.until(scene.until()));
        Invariants.noOverlapsAndInside(scene, r.finalState());
        assertThat(r.counters().get("mergedEvents")).isPositive();
        assertThat(r.counters().get("windows")).isPositive();
        Invariants.assertSameRun(scene.name(), r, new SerialEngine().run(scene, RunOptions.until(scene.until())), 1e-8);
    }

    @Test
    void windowsThatPayKeepTheSlabsAndResetTheBudget() {
        MergePolicy p = new MergePolicy(100, true, 1000, 1000, 1000);
        for (int w = 1; w < MergePolicy.BLOCK_WINDOWS; w++) {
            assertThat(p.mergeAfter(0, 0)).as("judged only after a whole block").isFalse();
        }
        // The block's kept events less twice the undone ones reach half of 100 a window.
        assertThat(p.mergeAfter(50 * MergePolicy.BLOCK_WINDOWS + 2 * 50, 50)).isFalse();
        for (int w = 1; w < MergePolicy.BLOCK_WINDOWS; w++) {
            p.mergeAfter(49, 0);
        }
        assertThat(p.mergeAfter(49, 0)).as("49 events a window do not pay").isTrue();
        assertThat(p.nextBudget()).isEqualTo(1000);
        assertThat(p.nextBudget()).as("a failed try doubles the next phase").isEqualTo(2000);
        for (int k = 0; k < 20; k++) {
            p.nextBudget();
        }
        assertThat(p.nextBudget()).as("up to a cap").isEqualTo(1000L << MergePolicy.MAX_DOUBLINGS);
        for (int w = 0; w < MergePolicy.BLOCK_WINDOWS; w++) {
            p.mergeAfter(1000, 0);
        }
        assertThat(p.nextBudget()).as("a block that pays resets the budget").isEqualTo(1000);
    }

    @Test
    void aMergedPhaseTriesTheSlabsOnlyIfItsCrossSlabEventsLeaveRoomForWindowsThatPay() {
        MergePolicy p = new MergePolicy(100, true, 1000, 1000, 1000);
        assertThat(p.worthTrying(1000, 10)).isTrue();
        assertThat(p.worthTrying(1000, 11)).as("fewer than 100 events between cross-slab events").isFalse();
        assertThat(p.worthTrying(5, 0)).isTrue();
        assertThat(new MergePolicy(100, false, 1000, 1000, 1000).worthTrying(1000, 1000)).as("without the estimate").isTrue();
    }

    @Test
    void windowEventsZeroNeverMerges() {
        MergePolicy p = new MergePolicy(0, true, 1000, 1000, 1000);
        for (int w = 0; w < 10 * MergePolicy.BLOCK_WINDOWS; w++) {
            assertThat(p.mergeAfter(0, 1000)).isFalse();
        }
    }
}
