package carom.lab;

import static org.assertj.core.api.Assertions.assertThat;

import carom.app.Main;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

/** The lab's root command: what it offers, how it fails, and that {@code bench} hands everything to JMH. */
class LabMainTest {
    @Test
    void helpNamesTheLabsCommandsButNotTheWorkers() {
        Lab help = Lab.run("--help");
        assertThat(help.status()).isZero();
        assertThat(help.out()).contains("experiment", "study", "bench").doesNotContain("worker");
    }

    @Test
    void noCommandIsBadInputThatNamesTheCommands() {
        Lab r = Lab.run();
        assertThat(r.status()).isEqualTo(Main.BAD_INPUT);
        assertThat(r.firstErrorLine()).startsWith("error: missing command")
                .contains("carom experiment thesis|actors", "carom study accuracy", "carom bench");
    }

    @Test
    void anUnknownCommandIsBadInput() {
        Lab r = Lab.run("simulate", "scene.json");
        assertThat(r.status()).isEqualTo(Main.BAD_INPUT);
        assertThat(r.firstErrorLine()).startsWith("error: ");
    }

    /** {@code -l} is JMH's option (list the benchmarks), not picocli's: it reaches JMH, which prints the list. */
    @Test
    void benchPassesOptionsToJmh() {
        ByteArrayOutputStream jmhOut = new ByteArrayOutputStream();
        PrintStream stdout = System.out;
        Lab r;
        System.setOut(new PrintStream(jmhOut, true, StandardCharsets.UTF_8));
        try {
            r = Lab.run("bench", "-l", "Thesis");
        } finally {
            System.setOut(stdout);
        }
        assertThat(r.status()).as(r.err()).isZero();
        assertThat(jmhOut.toString(StandardCharsets.UTF_8)).contains("carom.lab.bench.ThesisWorkloadBenchmark.run")
                .doesNotContain("GasThroughput");
    }
}
