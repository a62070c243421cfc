package carom.engines.growth;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.engine.Counter;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import carom.core.scene.SceneReader;
import carom.core.state.Discs;
import carom.engines.fast.FastEngine;
import carom.engines.slabs.SlabsEngine;
import org.junit.jupiter.api.Test;

/**
 * fast and slabs (two domains in windows, never merged) on the same growth scenes, over times short enough that chaos has not amplified
 * rounding beyond 1e-9 (a few collisions per disc): the same collisions, the same final state, with
 * the thermostat at every sample and stage rebuilds on the way.
 */
class GrowthFastAgainstSlabsTest {
    static Scene gas(String boundary, double until) {
        return SceneReader.parse("""
                {"name": "growing-gas", "box": {"width": 40, "height": 30, "boundary": "%s"},
                 "species": [{"name": "small", "radius": 0.5, "mass": 1}, {"name": "large", "radius": 0.7, "mass": 1.5}],
                 "generate": [{"species": ["small", "large"], "fractions": [0.5, 0.5], "count": 400, "layout": "random",
                               "velocity": {"distribution": "maxwell", "temperature": 1}, "seed": 11}],
                 "effects": {"growth": 0.05},
                 "until": %s}
                """.formatted(boundary, until));
    }

    private static void assertSame(Scene scene, RunOptions options) {
        RunResult fast = new FastEngine().run(scene, options);
        // windowEvents=0: split from the start and never merged, so the optimistic windows run.
        RunResult slabs = new SlabsEngine().run(scene, options.withThreads(2).withTunable("windowEvents", "0"));
        assertThat(slabs.counters().get("windows")).as("windows").isPositive();
        assertThat(slabs.pairCollisions()).isEqualTo(fast.pairCollisions());
        assertThat(slabs.wallCollisions()).isEqualTo(fast.wallCollisions());
        assertThat(fast.counter(Counter.GROWTH_STAGES, 0)).as("stages").isGreaterThan(1);
        Discs a = fast.finalState();
        Discs b = slabs.finalState();
        for (int i = 0; i < a.n; i++) {
            assertThat(b.x[i]).as("x of %d", i).isCloseTo(a.x[i], within(1e-9));
            assertThat(b.y[i]).as("y of %d", i).isCloseTo(a.y[i], within(1e-9));
            assertThat(b.vx[i]).as("vx of %d", i).isCloseTo(a.vx[i], within(1e-9));
            assertThat(b.vy[i]).as("vy of %d", i).isCloseTo(a.vy[i], within(1e-9));
            assertThat(b.radius[i]).isEqualTo(a.radius[i]);
        }
        assertThat(slabs.kineticEnergyEnd()).isCloseTo(fast.kineticEnergyEnd(), within(1e-9 * fast.kineticEnergyEnd()));
    }

    @Test
    void periodicGasWithoutThermostat() {
        Scene scene = gas("periodic", 2.5);
        assertSame(scene, RunOptions.until(scene.until()));
    }

    @Test
    void walledGasWithTheThermostatAtEverySample() {
        Scene scene = gas("walls", 2.5);
        assertSame(scene, RunOptions.until(scene.until()).withSamples(0.5, (t, state, virial) -> { }));
    }
}
