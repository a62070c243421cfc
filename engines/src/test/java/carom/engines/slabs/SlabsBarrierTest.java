package carom.engines.slabs;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import carom.core.BadInputException;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import carom.engines.reference.RandomScenes;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** The window barrier's spin setting, and the per-slab counters a run reports. */
class SlabsBarrierTest {
    private static final RunOptions TWO_THREADS = RunOptions.until(1).withThreads(2);

    @Test
    void largeScenesWithAProcessorPerThreadSpinLong() {
        assertThat(SpinPolicy.spinsOf(TWO_THREADS, SpinPolicy.LONG_SPIN_DISCS, 2, 0.1)).isEqualTo(SpinPolicy.SPINS_LONG);
    }

    @Test
    void smallScenesSpinShortSoThatTheJitKeepsACore() {
        assertThat(SpinPolicy.spinsOf(TWO_THREADS, SpinPolicy.LONG_SPIN_DISCS - 1, 2, 0)).isEqualTo(SpinPolicy.SPINS_SHORT);
    }

    @Test
    void moreThreadsThanProcessorsSpinShortEvenOnLargeScenes() {
        assertThat(SpinPolicy.spinsOf(TWO_THREADS.withThreads(4), 2_000_000, 2, 0)).isEqualTo(SpinPolicy.SPINS_SHORT);
    }

    @Test
    void aLoadedMachineParksSoonEvenOnLargeScenes() {
        // Another process keeps one of two cores busy: a spinning slab would fight it for the core.
        assertThat(SpinPolicy.spinsOf(TWO_THREADS, 2_000_000, 2, 1.2)).isEqualTo(SpinPolicy.SPINS_SHORT);
        assertThat(SpinPolicy.spinsOf(TWO_THREADS, 2_000_000, 4, 1.8)).isEqualTo(SpinPolicy.SPINS_LONG);
        assertThat(SpinPolicy.spinsOf(TWO_THREADS, 2_000_000, 2, -1)).as("no load average reported")
                .isEqualTo(SpinPolicy.SPINS_LONG);
    }

    @Test
    void theTunableOverridesTheDefault() {
        assertThat(SpinPolicy.spinsOf(TWO_THREADS.withTunable("spins", "0"), 2_000_000, 2, 0)).isZero();
        assertThat(SpinPolicy.spinsOf(TWO_THREADS.withTunable("spins", "12345"), 10, 2, 0)).isEqualTo(12345);
    }

    @ParameterizedTest(name = "spins={0}")
    @ValueSource(strings = {"-1", "1.5", "NaN", "Infinity", "2147483648", "abc"})
    void aSpinCountThatIsNotAWholeNumberInRangeIsBadInput(String value) {
        assertThatThrownBy(() -> SpinPolicy.spinsOf(TWO_THREADS.withTunable("spins", value), 10, 2, 0))
                .isInstanceOf(BadInputException.class)
                .hasMessageStartingWith("--option spins: ");
    }

    @Test
    void aRunReportsItsSpinsAndEachSlabsShareOfTheEvents() {
        Scene scene = RandomScenes.dense(1600, 0.5, true, 11, 0.3);
        RunResult r = new SlabsEngine().run(scene,
                FixedDomains.alternating(2, 2000).options(RunOptions.until(scene.until())).withTunable("spins", "77"));
        assertThat(r.counters().get("barrierSpins")).isEqualTo(77);
        long slabEvents = r.counters().get("slab0.events") + r.counters().get("slab1.events");
        // Every event is a slab's, a cross-slab contact or migration processed serially, or a merged phase's.
        assertThat(slabEvents + r.counters().get("crossDomainEvents") + r.counters().get("migrations")
                + r.counters().get("mergedEvents")).isEqualTo(r.events());
        assertThat(r.counters().get("slab0.events")).isPositive();
        assertThat(r.counters().get("slab1.events")).isPositive();
        assertThat(r.counters().get("slab0.windowCpuNanos") + r.counters().get("slab1.windowCpuNanos"))
                .isEqualTo(r.counters().get("windowCpuNanos"));
    }
}
