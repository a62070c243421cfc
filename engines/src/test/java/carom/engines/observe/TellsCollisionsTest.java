package carom.engines.observe;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.Capability;
import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.observe.CollisionObserver;
import carom.core.scene.Scene;
import carom.core.scene.StandardScenes;
import carom.engines.EngineCatalog;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * An engine that says it tells collisions (({@link Capability#COLLISION_OBSERVERS} in its spec)) tells every one it carries
 * out: the observer's counts of pair and wall collisions are the run's.
 */
class TellsCollisionsTest {
    static Stream<Engine> tellers() {
        return EngineCatalog.all().stream().filter(e -> e.spec().can(Capability.COLLISION_OBSERVERS));
    }

    @Test
    void theExactSingleThreadEnginesTellCollisions() {
        assertThat(tellers().map(Engine::name)).contains("fast", "serial");
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("tellers")
    void everyCollisionCarriedOutIsTold(Engine engine) {
        Scene walled = StandardScenes.gas(400, 0.4, false, 3, 11);
        long[] told = new long[2];
        CollisionObserver counter = new CollisionObserver() {
            @Override
            public void pair(double time, int i, int k, double dx, double dy, double nx, double ny, double j) {
                told[0]++;
            }

            @Override
            public void wall(double time, int i, int wall, double j) {
                told[1]++;
            }
        };
        RunResult result = engine.run(walled, RunOptions.until(walled.until()).withCollisions(counter));
        assertThat(result.pairCollisions()).isPositive();
        assertThat(result.wallCollisions()).isPositive();
        assertThat(told).containsExactly(result.pairCollisions(), result.wallCollisions());
    }
}
