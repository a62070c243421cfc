package carom.core.physics;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.scene.BoundaryKind;
import carom.core.scene.Effects;
import carom.core.scene.Scene;
import carom.core.scene.SceneBuilder;
import carom.core.scene.Species;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** {@link Physics#of} picks each law from the scene's effects, and only what the scene names. */
class PhysicsTest {
    private static Scene scene(Effects effects, BoundaryKind boundary) {
        return SceneBuilder.create("t").box(10, 10, boundary).species(Species.mobile("d", 0.5, 1))
                .disc(0, 5, 5, 1, 0).disc(0, 2, 5, 0, 0).effects(effects).until(1).build();
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', textBlock = """
            # gy | e   | tc   | growth | boundary | flight    | restitution | grows
              0  | 1   | 0    | 0      | WALLS    | Straight  | Elastic     | false
              -2 | 1   | 0    | 0      | WALLS    | Parabolic | Elastic     | false
              0  | 0.8 | 0    | 0      | PERIODIC | Straight  | Constant    | false
              -2 | 0.8 | 1e-3 | 0      | WALLS    | Parabolic | TcModel     | false
              0  | 1   | 1e-3 | 0      | WALLS    | Straight  | Elastic     | false
              0  | 1   | 0    | 0.05   | PERIODIC | Straight  | Elastic     | true
              0  | 0.9 | 1e-3 | 0.05   | WALLS    | Straight  | TcModel     | true
            """)
    void eachLawIsChosenFromTheEffectsItReads(double gy, double e, double tc, double growth, BoundaryKind boundary,
                                              String flight, String restitution, boolean grows) {
        Effects effects = Effects.NONE.withGravity(0, gy).withRestitution(e, e).withTc(tc).withGrowth(growth);
        Physics physics = Physics.of(scene(effects, boundary));

        assertThat(physics.flight.getClass().getSimpleName()).isEqualTo(flight);
        assertThat(physics.flight.maxAcceleration()).isEqualTo(Math.abs(gy));
        assertThat(physics.boundary.periodic()).isEqualTo(boundary == BoundaryKind.PERIODIC);
        assertThat(physics.restitution.getClass().getSimpleName()).isEqualTo(restitution);
        assertThat(physics.restitution.pair(0, 1, 0)).isEqualTo(e);
        assertThat(physics.growth.grows()).isEqualTo(grows);
        assertThat(physics.growth.rate()).isEqualTo(growth);
    }
}
