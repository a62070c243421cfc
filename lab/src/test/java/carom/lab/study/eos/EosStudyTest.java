package carom.lab.study.eos;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.lab.Lab;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** {@code carom study eos} end to end on a small system, and its refusals of bad options. */
class EosStudyTest {
    @TempDir
    Path dir;

    @Test
    void aSmallStudyRunsBothStartsWritesItsFolderAndMeetsTheFluidsPressure() throws IOException {
        Path out = dir.resolve("eos");

        Lab r = Lab.run("study", "eos", "--out", out.toString(), "--n", "144", "--phis", "0.3,0.7,0.71", "--engine", "fast",
                "--block-collisions", "5", "--window", "2", "--min-equilibration", "10", "--max-equilibration", "40",
                "--blocks", "16", "--snapshots", "0.7", "--status-every", "1e-9");

        assertThat(r.status()).as(r.err()).isZero();
        // No bar here (stderr is not a terminal): each start says what it does, here at every chance.
        for (String start : List.of("crystal", "fluid")) {
            assertThat(r.err().lines()).as(r.err()).anyMatch(l -> l.matches("eos: phi 0\\.7 " + start + " (equilibrating|measuring).*"));
        }
        assertThat(Files.list(out).map(p -> p.getFileName().toString()).toList()).containsExactlyInAnyOrder("report.md", "eos.csv",
                "eos.png", "eos.svg", "eos-transition.png", "eos-transition.svg", "psi6.png", "psi6.svg",
                "snapshot-phi0.700-crystal.png", "snapshot-phi0.700-fluid.png");
        List<String> rows = Files.readAllLines(out.resolve("eos.csv"));
        assertThat(rows).hasSize(7);
        Map<String, Integer> col = new java.util.HashMap<>();
        String[] header = rows.get(0).split(",");
        for (int i = 0; i < header.length; i++) {
            col.put(header[i], i);
        }
        String[] diluteCrystal = rows.get(1).split(",", -1);
        String[] diluteLiquid = rows.get(2).split(",", -1);
        assertThat(diluteCrystal[col.get("start")]).isEqualTo("crystal");
        assertThat(diluteLiquid[col.get("start")]).isEqualTo("fluid");
        // the fluid at 0.3: Kolafa and Rottner's Z = 2.0633; 144 discs and 80 collisions per disc measure it to about 1%,
        // from either start
        for (String[] dilute : List.of(diluteCrystal, diluteLiquid)) {
            assertThat(dilute[col.get("status")]).isEqualTo("measured");
            assertThat(Double.parseDouble(dilute[col.get("z")])).isCloseTo(2.0633, within(0.05));
            assertThat(Double.parseDouble(dilute[col.get("psi6")])).isLessThan(0.3);
            assertThat(Double.parseDouble(dilute[col.get("z_error")])).isGreaterThan(0);
        }
        // both rows of a packing fraction carry the same judgement of their agreement
        assertThat(diluteCrystal[col.get("branch_difference_sigmas")]).isEqualTo(diluteLiquid[col.get("branch_difference_sigmas")]);
        assertThat(diluteCrystal[col.get("equilibrated")]).isEqualTo(diluteLiquid[col.get("equilibrated")]);
        String[] dense = rows.get(3).split(",", -1);
        // at 0.7 the crystal start keeps strong bond order over so short a run
        assertThat(Double.parseDouble(dense[col.get("psi6")])).isGreaterThan(0.3);
        assertThat(dense[col.get("literature_source")]).isEqualTo("HistoricDisks N=1024^2");
        String report = Files.readString(out.resolve("report.md"));
        assertThat(report).contains("carom study eos --out", "| 0.3 |", "## The loop", "![snapshot-phi0.700-fluid.png]",
                "βPσ², crystal start", "βPσ², liquid start", "Δ c−l");
    }

    @ParameterizedTest
    @CsvSource(delimiter = ';', value = {
        "--n;81;--n: 81 is not the square of an even number",
        "--phis;0.95;--phis: 0.95 is not a packing fraction",
        "--engine;akka;--engine: akka is relaxed",
        "--blocks;1;--blocks: must be 2 to 1000000",
        "--block-collisions;NaN;--block-collisions: must be a number > 0",
        "--status-every;0;--status-every: must be a number > 0",
        "--start;glass;--start: 'glass' is neither both, crystal nor fluid",
        "--deadline;soon;--deadline: 'soon' is neither an instant",
        "--deadline;2020-01-01T00:00:00Z;--deadline: '2020-01-01T00:00:00Z' has passed"})
    void badOptionsAreOneErrorLineAndStatusTwo(String option, String value, String message) {
        Path out = dir.resolve("never");

        Lab r = Lab.run("study", "eos", "--out", out.toString(), option, value);

        assertThat(r.status()).isEqualTo(2);
        assertThat(r.firstErrorLine()).startsWith("error: ").contains(message);
        assertThat(out).doesNotExist();
    }

    @Test
    void fillingNeedsADeadline() {
        Lab r = Lab.run("study", "eos", "--out", dir.resolve("never").toString(), "--fill-to-deadline");

        assertThat(r.status()).isEqualTo(2);
        assertThat(r.firstErrorLine()).isEqualTo("error: --fill-to-deadline needs --deadline");
    }

    @Test
    void aFolderThatIsNotEmptyIsRefusedBeforeAnyRun() throws IOException {
        Path out = Files.createDirectories(dir.resolve("full"));
        Files.writeString(out.resolve("keep.txt"), "mine");

        Lab r = Lab.run("study", "eos", "--out", out.toString(), "--quick");

        assertThat(r.status()).isEqualTo(2);
        assertThat(r.firstErrorLine()).startsWith("error: --out:").contains("not empty");
        assertThat(Files.readString(out.resolve("keep.txt"))).isEqualTo("mine");
    }
}
