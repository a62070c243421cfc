package carom.core;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.util.HexFormat;
import java.util.Random;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.Test;

class StrictUtf8Test {
    private static String readAll(byte[] bytes, int chunk) throws IOException {
        StringBuilder sb = new StringBuilder();
        try (Reader r = StrictUtf8.reader(new ByteArrayInputStream(bytes))) {
            char[] buf = new char[chunk];
            for (int n; (n = r.read(buf, 0, chunk)) >= 0; ) {
                assertThat(n).as("a read returns at least one char until the end").isPositive();
                sb.append(buf, 0, n);
            }
        }
        return sb.toString();
    }

    @Test
    void wellFormedTextReadsBackTheSameInAnyChunkSize() throws IOException {
        // Seeded: characters of one to four bytes, many times across the 64 KiB buffer.
        Random random = new Random(23);
        int[] samples = {'a', 0xe4, 0x3c3, 0x20ac, 0xffff - 2, 0x1f600, 0x10ffff};
        StringBuilder text = new StringBuilder();
        while (text.length() < 300_000) {
            text.appendCodePoint(samples[random.nextInt(samples.length)]);
        }
        byte[] bytes = text.toString().getBytes(StandardCharsets.UTF_8);
        for (int chunk : new int[] {1, 2, 3, 4096, 1 << 20}) {
            assertThat(readAll(bytes, chunk)).as("chunk %d", chunk).isEqualTo(text.toString());
        }
    }

    @Test
    void aLeadingByteOrderMarkIsSkippedAndOnlyThere() throws IOException {
        assertThat(readAll("\ufeff{}".getBytes(StandardCharsets.UTF_8), 1)).isEqualTo("{}");
        assertThat(readAll("\ufeff".getBytes(StandardCharsets.UTF_8), 8)).isEmpty();
        assertThat(readAll("{\ufeff}".getBytes(StandardCharsets.UTF_8), 8)).isEqualTo("{\ufeff}");
    }

    /** Malformed bytes in hex, and the byte (1 = first) where each goes wrong. */
    @ParameterizedTest
    @CsvSource({
        "7b7d ff,                3",
        "c0ae,                   1",
        "41 e080ae,              2",
        "41 f08080ae,            2",
        "eda080,                 1",
        "f4908080,               1",
        "80,                     1",
        "4142 e282,              3",
        "e28241,                 1",
        "f09f98,                 1",
        "f8888080 80,            1"})
    void malformedBytesAreReportedWithTheirPosition(String hex, long byteNumber) {
        byte[] bytes = HexFormat.of().parseHex(hex.replace(" ", ""));
        for (int chunk : new int[] {1, 1024}) {
            assertThatThrownBy(() -> readAll(bytes, chunk)).isInstanceOf(StrictUtf8.MalformedException.class)
                    .hasMessage("not valid UTF-8 at byte " + byteNumber)
                    .satisfies(e -> assertThat(((StrictUtf8.MalformedException) e).byteNumber()).isEqualTo(byteNumber));
        }
    }
}
