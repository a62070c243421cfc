package carom.app;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.BadInputException;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.Callable;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Parameters;

/** Another program's root command fails as carom does when run through {@link CommandRunner}. */
class CommandRunnerTest {
    @Command(name = "probe")
    static final class Probe implements Callable<Integer> {
        @Parameters(index = "0")
        String what;

        @Override
        public Integer call() {
            return switch (what) {
                case "bad" -> throw new BadInputException("no such thing");
                case "broken" -> throw new IllegalStateException("a bug");
                default -> 0;
            };
        }
    }

    private record Result(int status, String out, String err) {
    }

    private static Result run(String... args) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status = CommandRunner.run(new CommandLine(new Probe()), new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8), args);
        return new Result(status, out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8));
    }

    @Test
    void badInputIsOneErrorLineAndStatusTwo() {
        Result r = run("bad");
        assertThat(r.status()).isEqualTo(Main.BAD_INPUT);
        assertThat(r.err()).isEqualTo("error: no such thing" + System.lineSeparator());
    }

    @Test
    void aBadCommandLineIsBadInputWithUsage() {
        Result r = run();
        assertThat(r.status()).isEqualTo(Main.BAD_INPUT);
        assertThat(r.err()).startsWith("error: Missing required parameter").contains("Usage: probe");
    }

    @Test
    void aBugIsAnInternalFailureWithoutAStackTrace() {
        Result r = run("broken");
        assertThat(r.status()).isEqualTo(Main.INTERNAL_FAILURE);
        assertThat(r.err()).startsWith("error: internal failure: IllegalStateException: a bug").doesNotContain("\tat ");
    }

    @Test
    void successIsStatusZero() {
        assertThat(run("fine").status()).isZero();
    }

    /** The measurements left the app for the lab; the app still says where they are. */
    @Test
    void theAppPointsAtTheLabsCommands() {
        Cli help = Cli.run("--help");
        assertThat(help.out()).contains("carom experiment thesis|actors", "carom study accuracy", "carom bench ARGS");
        Cli none = Cli.run();
        assertThat(none.firstErrorLine()).contains("'carom experiment thesis'", "'carom study accuracy'", "'carom bench'");
        Cli experiment = Cli.run("experiment", "thesis");
        assertThat(experiment.status()).isEqualTo(Main.BAD_INPUT);
    }
}
