package carom.lab.run;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** The report's verdict on whether another process shared the cores, from the load before and after. */
class MachineTest {
    private static final Machine TWO_CORES = new Machine(2, "test cpu", "test jvm", "test os", 1L << 30);

    @Test
    void aQuietMachineUnderItsOwnLoadIsNotFlagged() {
        // two busy threads of ours and the JVM's own GC and JIT: up to 3 after the run is ours
        assertThat(TWO_CORES.sharedVerdict(0.1, 2.9, 2)).isNull();
        assertThat(TWO_CORES.sharedVerdict(0.49, 1.5, 1)).isNull();
    }

    @Test
    void loadBeforeTheFirstRunMeansAnotherProcess() {
        assertThat(TWO_CORES.sharedVerdict(0.5, 1.0, 2)).startsWith("shared:").contains("0.50 on 2 cores before");
    }

    @Test
    void loadAfterAboveWhatOurThreadsExplainIsFlagged() {
        assertThat(TWO_CORES.sharedVerdict(0.1, 2.1, 1)).startsWith("shared:").contains("after the last run");
        // more threads than cores explain at most the cores
        assertThat(TWO_CORES.sharedVerdict(0.1, 3.5, 8)).startsWith("shared:");
    }
}
