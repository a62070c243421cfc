package carom.engines.differential;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.Counter;
import carom.core.engine.Energy;
import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.observe.Observables;
import carom.core.scene.Scene;
import carom.core.scene.SceneReader;
import carom.core.state.Discs;
import carom.engines.fast.FastEngine;
import carom.engines.reference.Invariants;
import carom.engines.serial.SerialEngine;
import carom.engines.slabs.SlabsEngine;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Issue 23: piles under gravity settle and the run goes on to {@code until} in every exact engine
 * (before resting contact, galton-board stopped at t = 16-20 and settling-stack at t = 11-44). Long
 * runs (-Pphysics): each engine's collisions, energy and wall time are printed for the record.
 */
@Tag("physics")
class SettlingPilesLongRunTest {
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

    @ParameterizedTest(name = "{0} to t = {1}, {2} x{3}")
    @CsvSource({
        "settling-stack.json, 60, serial, 1", "settling-stack.json, 60, fast, 1",
        "settling-stack.json, 60, slabs, 1", "settling-stack.json, 60, slabs, 2",
        "galton-board.json, 120, serial, 1", "galton-board.json, 120, fast, 1",
        "galton-board.json, 120, slabs, 1", "galton-board.json, 120, slabs, 2"})
    void aPileSettlesCompletelyAndTheRunReachesUntil(String file, double until, String engine, int threads) {
        Scene scene = example(file);
        Engine e = switch (engine) {
            case "serial" -> new SerialEngine();
            case "fast" -> new FastEngine();
            default -> new SlabsEngine();
        };
        RunResult r = e.run(scene, RunOptions.until(until).withThreads(threads));
        Discs d = r.finalState();
        Invariants.noOverlapsAndInside(scene, d);
        for (int i = 0; i < d.n; i++) {
            assertThat(d.t[i]).isEqualTo(until);
        }
        long mobile = scene.mobileCount();
        assertThat(r.counter(Counter.SLEEPS, -1) - r.counter(Counter.WAKES, -1)).as("every mobile disc asleep")
                .isEqualTo(mobile);
        assertThat(Observables.kineticEnergy(d)).isZero();
        Energy energy = Energy.of(scene, r);
        assertThat(energy.end()).isLessThan(energy.initial());
        assertThat(energy.initial() - energy.end()).as("restitution and rest take energy out")
                .isGreaterThanOrEqualTo(r.energyPutToRest());
        System.out.printf(Locale.ROOT, "%s --until %s %s x%d: %d pair + %d wall collisions, energy %.6g -> %.6g "
                        + "(put to rest %.3g), %d sleeps, %d wakes, %.1f s%n", file, until, engine, threads,
                r.pairCollisions(), r.wallCollisions(), energy.initial(), energy.end(), r.energyPutToRest(),
                r.counter(Counter.SLEEPS, -1), r.counter(Counter.WAKES, -1), r.wallSeconds());
    }
}
