package carom.lab.eos;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.lab.Lab;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code carom study eos} end to end on a tiny system: every file, the table's columns, a dilute density
 * whose βPσ² must match the literature loosely (400 discs, short runs), and bad options.
 */
class StudyEosCommandTest {
    @TempDir
    Path dir;

    @Test
    void aTinyStudyWritesTheTablePlotAndSnapshot() throws IOException {
        Path out = dir.resolve("eos");
        Lab r = Lab.run("study", "eos", "--n", "400", "--phis", "0.30,0.70", "--equilibrate", "20", "--measure",
                "100", "--blocks", "10", "--max-extensions", "1", "--engine", "fast", "--snapshots", "0.70",
                "--out", out.toString());
        assertThat(r.status()).as(r.err()).isZero();
        assertThat(out.resolve("eos.md")).exists();
        assertThat(out.resolve("eos-z.png")).exists();
        assertThat(out.resolve("eos-z.svg")).exists();
        assertThat(out.resolve("local-psi6-0.700.png")).exists();
        List<String> rows = Files.readAllLines(out.resolve("eos.csv"));
        assertThat(rows).hasSize(3);
        String[] dilute = rows.get(1).split(",", -1);
        assertThat(dilute).hasSize(rows.get(0).split(",").length);
        // φ = 0.3: Z = 2.0633 (Kolafa and Rottner), βPσ² = Z 4φ/π = 0.7881; 400 discs over 100
        // collisions per disc give it to a percent or so.
        assertThat(Double.parseDouble(dilute[2])).isCloseTo(2.0633 * 4 * 0.3 / Math.PI, within(0.02));
        assertThat(Double.parseDouble(dilute[12])).isCloseTo(2.0633 * 4 * 0.3 / Math.PI, within(1e-6));
        String[] dense = rows.get(2).split(",", -1);
        // At 0.70 the lattice start keeps a high bond order over so short a run.
        assertThat(Double.parseDouble(dense[6])).isBetween(0.0, 1.0);
    }

    @Test
    void badDensitiesAreRefusedBeforeRunning() {
        Path out = dir.resolve("eos");
        Lab r = Lab.run("study", "eos", "--phis", "0.9", "--out", out.toString());
        assertThat(r.status()).isEqualTo(2);
        assertThat(r.firstErrorLine()).startsWith("error: --phis: each must be in (0, 0.76]");
        assertThat(out).doesNotExist();
    }
}
