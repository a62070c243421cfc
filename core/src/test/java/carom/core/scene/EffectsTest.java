package carom.core.scene;

import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;
import static org.assertj.core.api.Assertions.assertThat;

import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import java.util.EnumSet;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Effects are built by name: each wither sets its own fields, and nothing but Effects calls the constructor. */
class EffectsTest {
    @ParameterizedTest
    @CsvSource(delimiter = '|', textBlock = """
            # wither         | a    | b
              gravity        | 0.5  | -9.81
              restitution    | 0.8  | 0.6
              tc             | 1e-4 | 0
              growth         | 0.02 | 0
            """)
    void eachWitherSetsItsOwnFieldsOnly(String wither, double a, double b) {
        Effects effects = switch (wither) {
            case "gravity" -> Effects.NONE.withGravity(a, b);
            case "restitution" -> Effects.NONE.withRestitution(a, b);
            case "tc" -> Effects.NONE.withTc(a);
            default -> Effects.NONE.withGrowth(a);
        };
        Set<Effect> expected = switch (wither) {
            case "gravity" -> EnumSet.of(Effect.GRAVITY);
            case "restitution" -> EnumSet.of(Effect.RESTITUTION, Effect.WALL_RESTITUTION);
            case "tc" -> EnumSet.of(Effect.TC);
            default -> EnumSet.of(Effect.GROWTH);
        };
        assertThat(Effect.of(effects)).isEqualTo(expected);
        for (Effect other : EnumSet.complementOf(EnumSet.copyOf(expected))) {
            for (int k = 0; k < other.size(); k++) {
                assertThat(other.valueIn(effects, k)).as(other.path(k)).isEqualTo(other.valueIn(Effects.NONE, k));
            }
        }
    }

    @Test
    void theWithersCompose() {
        Effects effects = Effects.NONE.withGravity(0, -2).withRestitution(0.8, 0.9).withTc(1e-3);
        assertThat(effects.gravityY()).isEqualTo(-2);
        assertThat(effects.restitution()).isEqualTo(0.8);
        assertThat(effects.wallRestitution()).isEqualTo(0.9);
        assertThat(effects.tc()).isEqualTo(1e-3);
        assertThat(effects.usesTcModel()).isTrue();
        assertThat(effects.grows()).isFalse();
    }

    @Test
    void onlyEffectsCallsItsPositionalConstructor() {
        // Core's classes, main and test (the other modules' are checked where they are built).
        JavaClasses classes = new ClassFileImporter().importPackages("carom.core");
        double[] none = new double[6];
        Class<?>[] sixDoubles = new Class<?>[none.length];
        java.util.Arrays.fill(sixDoubles, double.class);
        noClasses().that().doNotHaveFullyQualifiedName(Effects.class.getName())
                .should().callConstructor(Effects.class, sixDoubles)
                .because("effects are built by name, from Effects.NONE with the withers")
                .check(classes);
    }
}
