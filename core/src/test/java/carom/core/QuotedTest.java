package carom.core;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

class QuotedTest {
    @Test
    void plainValuesAreQuotedAsTheyAre() {
        assertThat(Quoted.of("warp")).isEqualTo("'warp'");
        assertThat(Quoted.of("")).isEqualTo("''");
        assertThat(Quoted.of("σφαίρα \uD83D\uDE00")).isEqualTo("'σφαίρα \uD83D\uDE00'");
        assertThat(Quoted.bare("particles")).isEqualTo("particles");
    }

    @Test
    void controlAndInvisibleCharactersAreEscapedAsJavaWritesThem() {
        assertThat(Quoted.of("a\nb\r\tc")).isEqualTo("'a\\nb\\r\\tc'");
        assertThat(Quoted.of("\u001b[31mred")).isEqualTo("'\\u001b[31mred'");
        assertThat(Quoted.of("x\u0000\u007f\u0085")).isEqualTo("'x\\u0000\\u007f\\u0085'");
        // Bidirectional override, zero-width space, line separator, a lone surrogate, a tag character.
        assertThat(Quoted.of("\u202e\u200b\u2028\uD800\uDB40\uDC01")).isEqualTo("'\\u202e\\u200b\\u2028\\ud800\\udb40\\udc01'");
    }

    @Test
    void quotesAndBackslashesInsideAQuotedValueAreEscapedSoTheQuotesDelimitIt() {
        assertThat(Quoted.of("it's a\\b")).isEqualTo("'it\\'s a\\\\b'");
        assertThat(Quoted.bare("it's a\\b")).isEqualTo("it's a\\b");
    }

    @Test
    void longValuesAreCutAndSayHowLongTheyWere() {
        String huge = "k".repeat(10_000_000);
        assertThat(Quoted.of(huge)).isEqualTo("'" + "k".repeat(Quoted.VALUE_CHARS) + "'... (10000000 characters)");
        assertThat(Quoted.fileName("/" + "d".repeat(500)))
                .isEqualTo("/" + "d".repeat(Quoted.FILE_NAME_CHARS - 1) + "... (501 characters)");
        // Exactly at the bound: nothing cut.
        assertThat(Quoted.of("k".repeat(Quoted.VALUE_CHARS))).isEqualTo("'" + "k".repeat(Quoted.VALUE_CHARS) + "'");
    }

    @Test
    void theBoundCountsEscapedTextAndNeverSplitsAnEscapeOrAPair() {
        String newlines = "\n".repeat(1000);
        String shown = Quoted.of(newlines);
        assertThat(shown).isEqualTo("'" + "\\n".repeat(Quoted.VALUE_CHARS / 2) + "'... (1000 characters)");
        String escapes = "\u001b".repeat(100);
        // 60 / 6 escapes fit exactly.
        assertThat(Quoted.of(escapes)).isEqualTo("'" + "\\u001b".repeat(10) + "'... (100 characters)");
        String pairs = "\uD83D\uDE00".repeat(100);
        assertThat(Quoted.of(pairs)).isEqualTo("'" + "\uD83D\uDE00".repeat(30) + "'... (100 characters)");
    }

    @Test
    void nullIsShownAsNull() {
        assertThat(Quoted.of(null)).isEqualTo("null");
        assertThat(Quoted.fileName(null)).isEqualTo("null");
    }
}
