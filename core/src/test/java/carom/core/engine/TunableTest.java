package carom.core.engine;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import carom.core.BadInputException;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.Test;

class TunableTest {
    private static final Tunable.Real CELL = Tunable.Real.atLeast("cellFactor", 2, 1, "diameters",
            "cell side over the largest diameter");
    private static final Tunable.Real STEP = Tunable.Real.above("stepFactor", 1, 0, "", "step over the guaranteed one");
    private static final Tunable.Whole SPINS = new Tunable.Whole("spins", 2048, 0, 1 << 30, "iterations",
            "busy-wait iterations", "from N and processors");
    private static final Tunable.Flag AUDIT = new Tunable.Flag("auditEnergy", false, "check energy after every event");

    private static RunOptions with(String key, String value) {
        return RunOptions.until(1).withTunable(key, value);
    }

    @Test
    void absentSettingsTakeTheirDefault() {
        RunOptions none = RunOptions.until(1);
        assertThat(CELL.of(none)).isEqualTo(2.0);
        assertThat(SPINS.isGiven(none)).isFalse();
        assertThat(AUDIT.of(none)).isFalse();
    }

    @Test
    void givenSettingsParse() {
        assertThat(CELL.of(with("cellFactor", "1.5"))).isEqualTo(1.5);
        assertThat(CELL.of(with("cellFactor", "3e0"))).isEqualTo(3.0);
        assertThat(SPINS.intOf(with("spins", "0"))).isZero();
        assertThat(AUDIT.of(with("auditEnergy", "true"))).isTrue();
    }

    @ParameterizedTest
    @ValueSource(strings = {"ture", "TRUE", "1", "yes", "", " true"})
    void aFlagIsTrueOrFalseAndNothingElse(String text) {
        assertThatThrownBy(() -> AUDIT.of(with("auditEnergy", text))).isInstanceOf(BadInputException.class)
                .hasMessageContaining("auditEnergy");
    }

    @ParameterizedTest
    @ValueSource(strings = {"NaN", "Infinity", "1d", "0x1p1", "two", "", "0.5", "-3"})
    void aRealIsAPlainDecimalInRange(String text) {
        assertThatThrownBy(() -> CELL.of(with("cellFactor", text))).isInstanceOf(BadInputException.class)
                .hasMessageStartingWith("--option cellFactor: ");
    }

    @ParameterizedTest
    @ValueSource(strings = {"1.5", "-1", "1073741825", "99999999999999999999", "1e3"})
    void aWholeNumberIsWholeAndInRange(String text) {
        assertThatThrownBy(() -> SPINS.of(with("spins", text))).isInstanceOf(BadInputException.class)
                .hasMessageStartingWith("--option spins: ");
    }

    @Test
    void aLongBadValueIsShownBoundedOnOneLine() {
        String value = "x".repeat(10_000) + "\nerror: fake";
        assertThatThrownBy(() -> AUDIT.parse(value)).isInstanceOf(BadInputException.class)
                .satisfies(e -> assertThat(e.getMessage()).doesNotContain("\n").hasSizeLessThan(200));
    }

    @Test
    void checkNamesAnUnknownKeyAndTheKnownOnes() {
        assertThatThrownBy(() -> Tunables.check("fast", List.of(CELL, AUDIT), Map.of("cellfactor", "2")))
                .isInstanceOf(BadInputException.class)
                .hasMessage("--option cellfactor: engine fast has no such option (known: cellFactor, auditEnergy)");
        Tunables.check("fast", List.of(CELL, AUDIT), Map.of("cellFactor", "2", "auditEnergy", "false"));
    }

    @Test
    void anOpenLowerBoundExcludesTheBound() {
        assertThat(STEP.of(with("stepFactor", "1e-300"))).isEqualTo(1e-300);
        assertThatThrownBy(() -> STEP.of(with("stepFactor", "0"))).isInstanceOf(BadInputException.class)
                .hasMessage("--option stepFactor: must be > 0, got 0");
        assertThat(STEP.describe()).isEqualTo("stepFactor=1 (real > 0): step over the guaranteed one");
        assertThat(STEP.computedByDefault("from the scene").describe())
                .isEqualTo("stepFactor=auto (from the scene) (real > 0): step over the guaranteed one");
    }

    @Test
    void describeGivesNameDefaultTypeUnitAndMeaning() {
        assertThat(CELL.describe()).isEqualTo("cellFactor=2 (real >= 1, diameters): cell side over the largest diameter");
        assertThat(SPINS.describe()).isEqualTo("spins=auto (from N and processors) (whole in [0, 1073741824], iterations): busy-wait iterations");
        assertThat(AUDIT.describe()).isEqualTo("auditEnergy=false (true|false): check energy after every event");
    }
}
