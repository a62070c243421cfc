package carom.app;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.BadInputException;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.io.UncheckedIOException;
import org.junit.jupiter.api.Test;

class ErrorReportingTest {
    private final StringWriter text = new StringWriter();

    private ErrorReporting reporting(boolean debug) {
        return new ErrorReporting(new PrintWriter(text), debug);
    }

    @Test
    void badInputIsStatusTwoWithItsMessage() {
        assertThat(reporting(false).report(new BadInputException("x.json: until: missing"))).isEqualTo(2);
        assertThat(text.toString()).isEqualTo("error: x.json: until: missing" + System.lineSeparator());
    }

    @Test
    void internalFailureIsStatusOneWithoutStackTrace() {
        int status = reporting(false).report(new IllegalStateException("queue corrupted"));
        assertThat(status).isEqualTo(1);
        assertThat(text.toString()).isEqualTo("error: internal failure: IllegalStateException: queue corrupted"
                + System.lineSeparator());
    }

    @Test
    void debugModeAddsTheStackTrace() {
        reporting(true).report(new IllegalStateException("queue corrupted"));
        assertThat(text.toString()).startsWith("error: internal failure: IllegalStateException: queue corrupted")
                .contains("\tat carom.app.ErrorReportingTest");
    }

    @Test
    void outOfMemoryTellsHowToGetMore() {
        int status = reporting(false).report(new RuntimeException("worker died", new OutOfMemoryError("Java heap space")));
        assertThat(status).isEqualTo(1);
        assertThat(text.toString()).startsWith("error: out of memory").contains("CAROM_JAVA_OPTS=-Xmx");
    }

    @Test
    void fileSystemFailureIsStatusTwo() {
        int status = reporting(false).report(new UncheckedIOException("cannot write out.csv: No space left on device",
                new IOException("No space left on device")));
        assertThat(status).as("the user can free space or pick another folder").isEqualTo(2);
        assertThat(text.toString()).startsWith("error: cannot write out.csv: No space left on device");
    }

    @Test
    void aMessageThatCopiedAValueUnquotedIsStillOneBoundedLine() {
        String value = "x".repeat(5_000_000) + "\nerror: fake";
        int status = reporting(false).report(new BadInputException("engine option spins: not a number: " + value));
        assertThat(status).isEqualTo(2);
        String out = text.toString();
        assertThat(out.lines()).hasSize(1);
        assertThat(out).startsWith("error: engine option spins: not a number: xxx")
                .endsWith("... (" + ("engine option spins: not a number: ".length() + value.length()) + " characters)"
                        + System.lineSeparator())
                .hasSizeLessThan(1100);
    }

    @Test
    void controlCharactersInAnyMessageAreEscaped() {
        reporting(false).report(new IllegalStateException("bad \u001b[2J\r\nerror: fake"));
        assertThat(text.toString()).isEqualTo("error: internal failure: IllegalStateException: bad \\u001b[2J\\r\\nerror: fake"
                + System.lineSeparator());
    }

    @Test
    void picocliOwnErrorPrefixIsDropped() {
        assertThat(ErrorReporting.withoutPicocliPrefix("Error: Missing required argument(s): --x")).isEqualTo(
                "Missing required argument(s): --x");
        assertThat(ErrorReporting.withoutPicocliPrefix("Unknown option: '--bogus'")).isEqualTo("Unknown option: '--bogus'");
    }
}
