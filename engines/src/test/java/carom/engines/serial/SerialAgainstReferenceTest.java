package carom.engines.serial;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import carom.engines.reference.BruteForceReference;
import carom.engines.reference.RandomScenes;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/** The serial engine against the brute-force judge on seeded random small scenes. */
class SerialAgainstReferenceTest {
    static java.util.stream.Stream<Long> seeds() {
        return java.util.stream.LongStream.range(1, 81).boxed();
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void finalStateMatchesBruteForce(long seed) {
        Scene scene = RandomScenes.small(seed);
        RunResult serial = new SerialEngine().run(scene, RunOptions.until(scene.until()));
        BruteForceReference.Result reference = BruteForceReference.run(scene, scene.until());
        assertThat(serial.pairCollisions()).as("pair collisions").isEqualTo(reference.pairCollisions());
        assertThat(serial.wallCollisions()).as("wall collisions").isEqualTo(reference.wallCollisions());
        for (int i = 0; i < scene.size(); i++) {
            assertThat(serial.finalState().x[i]).as("x of %d", i).isCloseTo(reference.state().x[i], org.assertj.core.data.Offset.offset(1e-9));
            assertThat(serial.finalState().y[i]).as("y of %d", i).isCloseTo(reference.state().y[i], org.assertj.core.data.Offset.offset(1e-9));
            assertThat(serial.finalState().vx[i]).as("vx of %d", i).isCloseTo(reference.state().vx[i], org.assertj.core.data.Offset.offset(1e-9));
            assertThat(serial.finalState().vy[i]).as("vy of %d", i).isCloseTo(reference.state().vy[i], org.assertj.core.data.Offset.offset(1e-9));
        }
    }
}
