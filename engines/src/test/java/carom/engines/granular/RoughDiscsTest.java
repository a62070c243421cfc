package carom.engines.granular;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import carom.core.BadInputException;
import carom.core.engine.Engine;
import carom.core.engine.Energy;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.observe.Observables;
import carom.core.scene.BoundaryKind;
import carom.core.scene.Effect;
import carom.core.scene.Effects;
import carom.core.scene.GenerateBlock;
import carom.core.scene.Layout;
import carom.core.scene.Scene;
import carom.core.scene.SceneBuilder;
import carom.core.scene.Species;
import carom.core.scene.VelocityDistribution;
import carom.engines.EngineCatalog;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Rough discs on every engine that simulates them, and the refusal of every other: with e = 1 and
 * β = +1 (perfectly rough), or a hair above −1 (barely gripping: β = −1 itself is smooth discs), a gas
 * keeps its kinetic energy, translational plus rotational, to rounding; for β = +1 the rotation takes
 * its share of it, for the other hardly any. Every engine that does not simulate them says so before
 * it starts.
 */
class RoughDiscsTest {
    /** A gas of 400 spinning discs of two species (q = 1/2 and 1/4) at packing fraction 0.3, walls or periodic. */
    static Scene gas(double e, double beta, boolean periodic, long seed) {
        double side = Math.sqrt(400 * Math.PI * 0.25 / 0.3);
        SceneBuilder b = SceneBuilder.create("rough-gas-" + seed)
                .box(side, side, periodic ? BoundaryKind.PERIODIC : BoundaryKind.WALLS)
                .species(Species.mobile("disc", 0.5, 1))
                .species(Species.mobile("ring", 0.5, 2).withInertia(0.25))
                .generate(new GenerateBlock(Layout.LATTICE, new int[] {0, 1}, new double[] {0.5, 0.5}, 400, 0.5,
                        new VelocityDistribution.Maxwell(1), seed))
                .effects(Effects.NONE.withRestitution(e, e).withTangentialRestitution(beta))
                .until(10);
        return b.build();
    }

    static Stream<Arguments> roughEnginesAndBetas() {
        return EngineCatalog.all().stream().filter(engine -> engine.spec().simulates(Effect.TANGENTIAL_RESTITUTION))
                .flatMap(engine -> Stream.of(-1 + 1e-12, 1.0).flatMap(beta -> Stream.of(true, false)
                        .map(periodic -> Arguments.of(engine.name(), beta, periodic))));
    }

    @ParameterizedTest(name = "{0}, beta {1}, periodic {2}")
    @MethodSource("roughEnginesAndBetas")
    void elasticPerfectlyRoughOrBarelyGrippingDiscsKeepTheirTotalKineticEnergy(String name, double beta, boolean periodic) {
        Engine engine = EngineCatalog.byName(name);
        Scene scene = gas(1, beta, periodic, 7);
        RunResult run = engine.run(scene, RunOptions.until(scene.until()));
        assertThat(run.pairCollisions()).isGreaterThan(2000);
        Energy energy = Energy.of(scene, run);
        assertThat(energy.end()).isCloseTo(energy.initial(), within(1e-9 * energy.initial()));
        double rotation = Observables.rotationalEnergy(run.finalState());
        if (beta == 1) {
            // Starting without spin, perfectly rough collisions hand rotation a good part of the energy.
            assertThat(rotation).isGreaterThan(0.1 * energy.end());
        } else {
            assertThat(rotation).isLessThan(1e-3 * energy.end());
        }
    }

    static Stream<String> otherEngines() {
        return EngineCatalog.all().stream().filter(engine -> !engine.spec().simulates(Effect.TANGENTIAL_RESTITUTION))
                .map(Engine::name);
    }

    @ParameterizedTest
    @MethodSource("otherEngines")
    void everyOtherEngineRefusesRoughDiscsNamingThoseThatSimulateThem(String name) {
        Scene scene = gas(0.9, 0.5, true, 1);
        assertThatThrownBy(() -> EngineCatalog.byName(name).run(scene, RunOptions.until(1)))
                .isInstanceOf(BadInputException.class)
                .hasMessageStartingWith("effects.tangentialRestitution: engine " + name + " does not simulate rough discs")
                .hasMessageContaining("serial");
    }
}
