package carom.engines.kernel;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import carom.core.scene.StandardScenes;
import carom.core.state.Discs;
import carom.engines.EngineCatalog;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.Test;

/**
 * The prefetch helper: bound wherever the build made it (the tests run with native access, as
 * {@code carom} does), used only from {@link Prefetch#MIN_DISCS} discs, and only a hint: runs with
 * and without it end in the same bits, and nonsense indices never read outside the arrays.
 */
class PrefetchTest {
    /** Whether this build carries the helper (the build skips it without a C compiler or off Linux). */
    private static boolean built() {
        String arch = System.getProperty("os.arch");
        return Prefetch.class.getResource("/carom/native/linux-" + arch + "/libcarom_prefetch.so") != null;
    }

    @Test
    void theHelperTheBuildMadeIsBound() {
        assumeTrue(built(), "no prefetch helper in this build (no C compiler, or not Linux)");
        assertThat(Prefetch.available()).isTrue();
    }

    @Test
    void onlyLargeTablesThatWantThemGetHints() {
        assumeTrue(Prefetch.available());
        Scene large = StandardScenes.thesis(Prefetch.MIN_DISCS, 3);
        Scene small = StandardScenes.thesis(Prefetch.MIN_DISCS / 2, 3);
        DiscTable big = new DiscTable(large, large.newDiscs(), 2);
        assertThat(Prefetch.forTable(big, true)).isNotNull();
        assertThat(Prefetch.forTable(big, false)).isNull();
        assertThat(Prefetch.forTable(new DiscTable(small, small.newDiscs(), 2), true)).isNull();
    }

    @Test
    void nonsenseIndicesAreIgnored() {
        assumeTrue(Prefetch.available());
        Scene scene = StandardScenes.thesis(Prefetch.MIN_DISCS, 5);
        DiscTable table = new DiscTable(scene, scene.newDiscs(), 2);
        Prefetch hints = Prefetch.forTable(table, true);
        int n = table.n;
        // Discs out of range, and a disc whose record holds a partner and a cell out of range.
        for (int i : new int[] {-1, n, n + 1_000_000, Integer.MAX_VALUE, Integer.MIN_VALUE}) {
            hints.entering(i);
        }
        hints.sliceReady(new int[] {-7, n, Integer.MAX_VALUE, Integer.MIN_VALUE, 0}, 5);
        table.ir[DiscTable.PARTNER] = Integer.MAX_VALUE;
        table.ir[DiscTable.CELL] = -1;
        hints.entering(0);
        hints.sliceReady(new int[] {0}, 1);
        assertThat(table.ir[DiscTable.PARTNER]).isEqualTo(Integer.MAX_VALUE); // hints write nothing
    }

    @ParameterizedTest(name = "{0} on {1} threads, seed {2}")
    @CsvSource({"fast, 1, 11", "fast, 1, 12", "slabs, 2, 13"})
    void hintsChangeNoBit(String engine, int threads, long seed) {
        assumeTrue(Prefetch.available());
        Scene scene = StandardScenes.thesis(40_000, seed);
        RunResult with = run(engine, scene, threads, "true");
        RunResult without = run(engine, scene, threads, "false");
        assertThat(with.events()).isEqualTo(without.events()).isGreaterThan(40_000);
        assertThat(with.pairCollisions()).isEqualTo(without.pairCollisions());
        Discs a = with.finalState();
        Discs b = without.finalState();
        assertThat(a.x).isEqualTo(b.x);
        assertThat(a.y).isEqualTo(b.y);
        assertThat(a.vx).isEqualTo(b.vx);
        assertThat(a.vy).isEqualTo(b.vy);
    }

    private static RunResult run(String engine, Scene scene, int threads, String prefetch) {
        RunOptions options = RunOptions.until(scene.until()).withThreads(threads)
                .withTunable(KernelTunables.PREFETCH.name(), prefetch);
        return EngineCatalog.byName(engine).run(scene, options);
    }
}
