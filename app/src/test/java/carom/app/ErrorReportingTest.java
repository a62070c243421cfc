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
    void fileSystemFailureIsStatusOne() {
        int status = reporting(false).report(new UncheckedIOException("cannot write out.csv: No space left on device",
                new IOException("No space left on device")));
        assertThat(status).isEqualTo(1);
        assertThat(text.toString()).startsWith("error: cannot write out.csv: No space left on device");
    }
}
