package carom.lab.experiment;

import static org.assertj.core.api.Assertions.assertThat;

import carom.app.Main;
import carom.lab.Lab;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * {@code carom experiment thesis|actors} end to end, in-process (the runs themselves in child JVMs),
 * in --quick mode: the folder holds what the report promises, and bad options never start a run.
 */
class ExperimentCommandTest {
    private static final List<String> ENGINES = List.of("serial", "fast", "stripes", "akka", "vthreads", "slabs");
    private static final List<String> PARALLEL = List.of("stripes", "akka", "vthreads", "slabs");
    private static final List<String> QUICK_SIZES = List.of("16", "200", "400");
    private static final List<String> QUICK_LARGE_SIZES = List.of("600", "800");

    @TempDir
    Path dir;

    @Test
    void quickThesisExperimentWritesReportTablesAndPlots() throws IOException {
        Path out = dir.resolve("thesis");

        Lab r = Lab.run("experiment", "thesis", "--quick", "--out", out.toString());

        assertThat(r.status()).as(r.err()).isZero();
        assertThat(r.err()).isEmpty(); // no progress bar off a terminal
        assertThat(r.out()).contains("wrote " + out).contains("52 of 52 runs measured");
        List<String> expected = new ArrayList<>(List.of("report.md", "runs.csv", "table-4.1-single-thread.csv",
                "table-4.2-non-actor.csv", "table-4.3-actor.csv", "table-4.4-large.csv", "table-beyond-thesis.csv"));
        List<String> plots = new ArrayList<>(List.of("time-all-engines", "time-parallel-engines", "messages-per-collision"));
        ENGINES.forEach(e -> plots.add("time-" + e));
        plots.forEach(p -> expected.addAll(List.of(p + ".png", p + ".svg")));
        assertThat(fileNames(out)).containsExactlyInAnyOrderElementsOf(expected);

        String report = Files.readString(out.resolve("report.md"));
        // the thesis's numbers, beside ours: Table 4.1 at 100k and its corrected 16-disc mean, 4.2 and 4.3 at
        // 100k, 4.4 at 3M, and the messages per collision of section 4.4
        assertThat(report).contains("| 100000 | 7837 ± 49.06 |", "141.6 ± 0.894", "| 100000 | 2660 ± 65.37 |",
                "| 100000 | 10082 ± 243.3 |", "| 3000000 | 600690 ± 5768 | 143939 ± 8269 |", "237.8 messages per collision",
                "## Table 4.1", "## Table 4.2", "## Table 4.3", "## Table 4.4", "2 cores", "Every planned run was measured");
        assertThat(report).contains("carom experiment thesis --quick --out " + out);

        assertOurRows(out.resolve("table-4.1-single-thread.csv"), List.of("serial", "fast"), QUICK_SIZES, 11);
        assertOurRows(out.resolve("table-4.2-non-actor.csv"), List.of("stripes"), QUICK_SIZES, 11);
        assertOurRows(out.resolve("table-4.3-actor.csv"), List.of("akka", "vthreads"), QUICK_SIZES, 11);
        assertOurRows(out.resolve("table-4.4-large.csv"), PARALLEL, QUICK_LARGE_SIZES, 32);
        // slabs, beyond the thesis, beside the thesis's fastest model where the thesis has the size (16 only)
        assertOurRows(out.resolve("table-beyond-thesis.csv"), List.of("slabs"), QUICK_SIZES, 1);
        for (Map<String, String> row : csv(out.resolve("table-4.3-actor.csv"))) {
            if (row.get("source").equals("carom") && !row.get("n").equals("16")) {
                assertThat(Double.parseDouble(row.get("messages_per_collision"))).isPositive();
                assertThat(Double.parseDouble(row.get("actors"))).isGreaterThanOrEqualTo(1);
            }
        }

        List<Map<String, String>> runs = csv(out.resolve("runs.csv"));
        assertThat(runs).hasSize(2 * 3 * 2 + 4 * (3 + 2) * 2); // serial engines: 3 sizes; parallel: 3 + 2 sizes; 2 trials
        assertThat(runs).allSatisfy(run -> {
            assertThat(run.get("skipped")).isEmpty();
            assertThat(Double.parseDouble(run.get("wall_ms"))).isPositive();
            int threads = Integer.parseInt(run.get("threads_used"));
            assertThat(threads).isEqualTo(PARALLEL.contains(run.get("engine")) ? Runtime.getRuntime().availableProcessors() : 1);
        });
        // trial t has seed 1 + t - 1 for every engine: the same workloads
        assertThat(runs.stream().map(run -> run.get("trial") + ":" + run.get("seed")).distinct()).containsExactlyInAnyOrder("1:1", "2:2");

        for (String plot : plots) {
            assertPicture(out.resolve(plot + ".png"));
            carom.lab.report.VectorFiles.assertSvg(out.resolve(plot + ".svg"));
        }
    }

    @Test
    void quickActorsStudyTabulatesActorsPerCore() throws IOException {
        Path out = dir.resolve("actors");

        // two block sizes keep it short: one actor per cell is the slow end of the study
        Lab r = Lab.run("experiment", "actors", "--quick", "--engines", "vthreads", "--threads", "1,2", "--cells-per-actor", "16,256",
                "--out", out.toString());

        assertThat(r.status()).as(r.err()).isZero();
        assertThat(fileNames(out)).containsExactlyInAnyOrder("report.md", "actors.csv", "runs.csv",
                "time-vs-actors-per-core.png", "messages-vs-actors-per-core.png",
                "time-vs-actors-per-core.svg", "messages-vs-actors-per-core.svg");
        List<Map<String, String>> rows = csv(out.resolve("actors.csv"));
        assertThat(rows).extracting(row -> row.get("threads_requested") + "/" + row.get("cells_per_actor"))
                .containsExactly("1/16", "1/256", "2/16", "2/256");
        assertThat(rows).allSatisfy(row -> {
            assertThat(row.get("threads_used")).isEqualTo(row.get("threads_requested")); // a JVM per thread count
            double actors = Double.parseDouble(row.get("actors"));
            assertThat(Double.parseDouble(row.get("actors_per_core")))
                    .isCloseTo(actors / Integer.parseInt(row.get("threads_used")), org.assertj.core.api.Assertions.within(1e-6));
            assertThat(Double.parseDouble(row.get("mean_ms"))).isPositive();
            assertThat(row.get("trials")).isEqualTo("2");
        });
        // fewer cells per actor, more actors
        assertThat(Double.parseDouble(rows.get(0).get("actors"))).isGreaterThan(Double.parseDouble(rows.get(1).get("actors")));
        assertThat(Files.readString(out.resolve("report.md"))).contains("How does the ratio of actors to cores",
                "| vthreads | 2 | 256 |");
        assertPicture(out.resolve("time-vs-actors-per-core.png"));
        assertPicture(out.resolve("messages-vs-actors-per-core.png"));
        carom.lab.report.VectorFiles.assertSvg(out.resolve("time-vs-actors-per-core.svg"));
    }

    @ParameterizedTest
    @ValueSource(strings = {
        "thesis --sizes 0", "thesis --sizes 10,abc", "thesis --trials 0", "thesis --engines serial,nope",
        "thesis --engines serial,serial", "thesis --engines serial,unknown-to-the-thesis", "thesis --heap lots", "thesis --threads 0", "thesis --warmup -1",
        "thesis --no-large --large-sizes 100", "thesis --cells-per-actor 0", "thesis --large-trials 0",
        "actors --engines serial", "actors --cells-per-actor 0", "actors --threads 1,1", "actors --size 0",
        "thesis --bogus"})
    void badOptionsFailBeforeAnyRun(String args) {
        Path out = dir.resolve("never");
        List<String> argv = new ArrayList<>(List.of("experiment"));
        argv.addAll(Arrays.asList(args.split(" ")));
        argv.addAll(List.of("--out", out.toString()));

        Lab r = Lab.run(argv.toArray(String[]::new));

        assertThat(r.status()).as(r.err()).isEqualTo(Main.BAD_INPUT);
        assertThat(r.firstErrorLine()).startsWith("error: ");
        assertThat(r.err()).doesNotContain("Exception").doesNotContain("\tat ");
        assertThat(out).doesNotExist();
    }

    @Test
    void anOutputFolderWithFilesIsNeverOverwritten() throws IOException {
        Path out = Files.createDirectory(dir.resolve("taken"));
        Files.writeString(out.resolve("mine.txt"), "keep");

        Lab r = Lab.run("experiment", "thesis", "--quick", "--out", out.toString());

        assertThat(r.status()).isEqualTo(Main.BAD_INPUT);
        assertThat(r.firstErrorLine()).startsWith("error: --out: " + out).contains("not empty");
        assertThat(fileNames(out)).containsExactly("mine.txt");
    }

    @ParameterizedTest
    @ValueSource(strings = {"thesis", "actors"})
    void anExperimentWithoutOutWritesNothingAndSaysWhy(String experiment) {
        Lab r = Lab.run("experiment", experiment, "--quick");

        assertThat(r.status()).isEqualTo(Main.BAD_INPUT);
        assertThat(r.firstErrorLine()).startsWith("error: ").contains("--out");
        assertThat(r.out()).doesNotContain("wrote");
    }

    @Test
    void experimentAloneNamesTheExperiments() {
        Lab r = Lab.run("experiment");
        assertThat(r.status()).isEqualTo(Main.BAD_INPUT);
        assertThat(r.firstErrorLine()).contains("carom experiment thesis").contains("carom experiment actors");

        Lab help = Lab.run("experiment", "thesis", "--help");
        assertThat(help.status()).isZero();
        assertThat(help.out()).contains("--sizes", "--large-sizes", "--trials", "--engines", "--threads", "--seed", "--quick",
                "--heap", "--out");
    }

    /** The CSV's rows of ours: one per engine and size, with a mean that parses; and the thesis's rows. */
    private static void assertOurRows(Path table, List<String> engines, List<String> sizes, int thesisRows) throws IOException {
        List<Map<String, String>> rows = csv(table);
        List<Map<String, String>> ours = rows.stream().filter(row -> row.get("source").equals("carom")).toList();
        assertThat(ours).extracting(row -> row.get("series") + "@" + row.get("n"))
                .containsExactlyInAnyOrderElementsOf(engines.stream().flatMap(e -> sizes.stream().map(n -> e + "@" + n)).toList());
        assertThat(ours).allSatisfy(row -> {
            assertThat(Double.parseDouble(row.get("mean_ms"))).isPositive();
            assertThat(Double.parseDouble(row.get("sd_ms"))).isNotNegative();
            assertThat(row.get("trials")).isEqualTo("2");
        });
        List<Map<String, String>> thesis = rows.stream().filter(row -> row.get("source").equals("thesis")).toList();
        assertThat(thesis).hasSize(thesisRows).allSatisfy(row -> assertThat(Double.parseDouble(row.get("mean_ms"))).isPositive());
    }

    private static void assertPicture(Path png) throws IOException {
        BufferedImage image = ImageIO.read(png.toFile());
        assertThat(image).as(png.toString()).isNotNull();
        assertThat(image.getWidth()).isEqualTo(900);
        assertThat(image.getHeight()).isEqualTo(560);
    }

    /** A CSV without quoted cells (ours have none but the skipped reasons, empty here) as header-keyed rows. */
    private static List<Map<String, String>> csv(Path file) throws IOException {
        List<String> lines = Files.readAllLines(file);
        String[] header = lines.get(0).split(",", -1);
        return lines.stream().skip(1).map(line -> {
            String[] cells = line.split(",", -1);
            assertThat(cells).as(line).hasSize(header.length);
            return java.util.stream.IntStream.range(0, header.length).boxed()
                    .collect(Collectors.toMap(i -> header[i], i -> cells[i]));
        }).toList();
    }

    private static List<String> fileNames(Path folder) throws IOException {
        try (Stream<Path> files = Files.list(folder)) {
            return files.map(p -> p.getFileName().toString()).toList();
        }
    }
}
