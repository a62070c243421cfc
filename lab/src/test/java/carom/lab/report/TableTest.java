package carom.lab.report;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;

class TableTest {
    @Test
    void markdownAndCsvOfTheSameCells() {
        Table t = new Table("N", "time (ms)", "note");
        t.add("16", "0.5 ± 0.1", "a|b");
        t.add("100", "7", "say \"hi\", then go");

        assertThat(t.markdown()).isEqualTo("""
                | N | time (ms) | note |
                |---|--:|--:|
                | 16 | 0.5 ± 0.1 | a\\|b |
                | 100 | 7 | say "hi", then go |
                """);
        assertThat(t.csv()).isEqualTo("""
                N,time (ms),note
                16,0.5 ± 0.1,a|b
                100,7,"say ""hi"", then go"
                """);
        assertThat(t.rows()).isEqualTo(2);
    }

    @Test
    void aRowMustFillEveryColumn() {
        Table t = new Table("a", "b");
        assertThatThrownBy(() -> t.add("1")).isInstanceOf(IllegalArgumentException.class);
    }

    @Test
    void numbersForPeopleAndForFiles() {
        assertThat(Table.readable(7837)).isEqualTo("7837");
        assertThat(Table.readable(141.6)).isEqualTo("141.6");
        assertThat(Table.readable(49.05609035)).isEqualTo("49.06");
        assertThat(Table.readable(0.894427191)).isEqualTo("0.894");
        assertThat(Table.readable(Double.NaN)).isEqualTo("–");
        assertThat(Table.meanSd(Stats.of(1, 2, 3))).isEqualTo("2 ± 1");
        assertThat(Table.meanSd(Stats.of(2.5))).isEqualTo("2.500");
        assertThat(Table.meanSd(Stats.of())).isEqualTo("–");

        assertThat(Table.plain(0.1234567)).isEqualTo("0.123457");
        assertThat(Table.plain(100.0)).isEqualTo("100");
        assertThat(Table.plain(1e-9)).isEqualTo("0");
        assertThat(Table.plain(Double.NaN)).isEmpty();
        assertThat(Table.plain((Long) null)).isEmpty();
        assertThat(Double.parseDouble(Table.plain(12345.678901))).isEqualTo(12345.678901);
    }
}
