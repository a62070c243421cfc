package carom.lab.experiment;

import static org.assertj.core.api.Assertions.assertThatCode;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import carom.core.BadInputException;
import carom.lab.run.Machine;
import org.junit.jupiter.api.Test;

/** --require-quiet refuses a run on a machine whose load says another process is running, and only then. */
class RequireQuietTest {
    private static final Machine TWO_CORES = new Machine(2, "test cpu", "test jvm", "test os", 1L << 30);

    @Test
    void aBusyMachineIsRefusedWithTheLoadInTheMessage() {
        assertThatThrownBy(() -> ExperimentCommand.refuseBusy(TWO_CORES, 0.5)).isInstanceOf(BadInputException.class)
                .hasMessage("--require-quiet: the load average is 0.50 on 2 cores (0.5 or more means another process is running); "
                        + "nothing was run");
        assertThatThrownBy(() -> ExperimentCommand.refuseBusy(TWO_CORES, 7.3)).isInstanceOf(BadInputException.class);
    }

    @Test
    void aQuietMachineGoesAhead() {
        assertThatCode(() -> ExperimentCommand.refuseBusy(TWO_CORES, 0.49)).doesNotThrowAnyException();
        // no load average (Windows): nothing says the machine is busy
        assertThatCode(() -> ExperimentCommand.refuseBusy(TWO_CORES, Double.NaN)).doesNotThrowAnyException();
    }
}
