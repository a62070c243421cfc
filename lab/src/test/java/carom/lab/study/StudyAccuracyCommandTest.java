package carom.lab.study;

import static org.assertj.core.api.Assertions.assertThat;

import carom.app.Main;
import carom.lab.Lab;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code carom study accuracy} end to end through {@link carom.lab.LabMain#run}: the quick study in this JVM once for the
 * whole class (a few seconds), a small one with worker JVMs, and bad options.
 */
class StudyAccuracyCommandTest {
    @TempDir
    static Path quickDir;
    private static Lab quick;
    private static List<Map<String, String>> rows;

    private static Lab run(String... args) {
        return Lab.run(args);
    }

    @BeforeAll
    static void quickStudy() throws IOException {
        // --quick with smaller scenes and no warm-up, to keep the suite short, but every scene, thread count and
        // step of the full study; in one JVM (no worker JVMs). Every engine but cluster, whose runs each start a
        // worker JVM (some 4 s, 12 of them here): the quick-alone test below runs it, and its own tests hold it
        // to serial's trajectory on periodic scenes.
        quick = run("study", "accuracy", "--quick", "--sizes", "200", "--warmups", "0", "--no-fork",
                "--scenes", "periodic:0.3,periodic:0.6,walls:0.3", "--threads", "1,2", "--dt-factors", "10,1,0.1",
                "--engines", String.join(",", studied()), "--out", quickDir.resolve("out").toString());
        assertThat(quick.status()).as(quick.err()).isZero();
        rows = csv(quickDir.resolve("out/accuracy.csv"));
    }

    /** The engines of the class's study: all but cluster. */
    private static List<String> studied() {
        return Setting.knownEngines().stream().filter(e -> !e.equals("cluster")).toList();
    }

    private static List<Map<String, String>> csv(Path file) throws IOException {
        List<String> lines = Files.readAllLines(file);
        String[] header = lines.get(0).split(",", -1);
        return lines.stream().skip(1).map(line -> {
            String[] cells = line.split(",", -1);
            assertThat(cells).as("columns of %s", line).hasSameSizeAs(header);
            Map<String, String> row = new HashMap<>();
            for (int i = 0; i < header.length; i++) {
                row.put(header[i], cells[i]);
            }
            return row;
        }).toList();
    }

    private static List<Map<String, String>> rowsOf(String scene) {
        return rows.stream().filter(r -> r.get("scene").equals(scene)).toList();
    }

    private static double num(Map<String, String> row, String column) {
        return Double.parseDouble(row.get(column));
    }

    @Test
    void writesTableCsvAndPicture() throws IOException {
        Path out = quickDir.resolve("out");
        assertThat(Files.readString(out.resolve("accuracy.md"))).contains("### N = 200, periodic φ=0.3", "### N = 200, periodic φ=0.6",
                "### N = 200, walls φ=0.3", "| fast | 1 |");
        var png = ImageIO.read(out.resolve("accuracy-pareto.png").toFile());
        assertThat(png.getWidth()).isGreaterThan(1000);
        assertThat(quick.out()).contains("| serial | 1 |", "wrote");
        try (var listing = Files.list(out)) {
            assertThat(listing.map(p -> p.getFileName().toString()))
                    .containsExactlyInAnyOrder("accuracy.md", "accuracy.csv", "accuracy-pareto.png", "accuracy-pareto.svg");
        }
        carom.lab.report.VectorFiles.assertSvg(out.resolve("accuracy-pareto.svg"));
    }

    @Test
    void quickAloneRunsEveryEngineOnceOnOneWalledSceneInThisJvm(@TempDir Path dir) throws IOException {
        Lab r = run("study", "accuracy", "--quick", "--sizes", "100", "--warmups", "0", "--collisions", "0.5",
                "--short-collisions", "0.25", "--out", dir.toString());

        assertThat(r.status()).as(r.err()).isZero();
        List<Map<String, String>> quickRows = csv(dir.resolve("accuracy.csv"));
        assertThat(quickRows).allSatisfy(row -> assertThat(row.get("scene")).isEqualTo("walls-0.3"));
        assertThat(quickRows.stream().map(row -> row.get("engine")).distinct().sorted().toList())
                .isEqualTo(Setting.knownEngines().stream().sorted().toList());
        assertThat(quickRows.stream().map(row -> row.get("setting")).sorted().toList()).isEqualTo(
                Setting.expand(Setting.knownEngines(), List.of(2), List.of(10.0, 1.0)).stream().map(Setting::label).sorted().toList());
        assertThat(Files.readString(dir.resolve("accuracy.md"))).contains("all settings in one JVM");
    }

    @Test
    void everySceneHasARowPerEngineAndSetting() {
        assertThat(studied()).contains("serial", "fast", "slabs", "stepped", "dyn4j").doesNotContain("cluster");
        List<String> expected = Setting.expand(studied(), List.of(1, 2), List.of(10.0, 1.0, 0.1)).stream()
                .map(Setting::label).sorted().toList();
        for (String scene : List.of("periodic-0.3", "periodic-0.6", "walls-0.3")) {
            assertThat(rowsOf(scene).stream().map(r -> r.get("setting")).sorted().toList()).as(scene).isEqualTo(expected);
        }
    }

    @Test
    void dyn4jRunsOnlyOnWalledScenesAndSaysWhy() {
        for (Map<String, String> r : rows) {
            if (r.get("engine").equals("dyn4j")) {
                boolean periodic = Boolean.parseBoolean(r.get("periodic"));
                assertThat(r.get("skipped")).as(r.get("scene")).isEqualTo(periodic ? "dyn4j has no periodic boundary" : "");
            }
        }
        assertThat(quick.out()).contains("not run: dyn4j has no periodic boundary");
    }

    @Test
    void exactEnginesHaveNoViolationsNoOverlapAndSerialsTrajectoryToRounding() {
        List<String> exact = carom.engines.EngineCatalog.all().stream().filter(e -> e.spec().exact()).map(e -> e.name()).toList();
        assertThat(exact).contains("serial", "fast");
        for (Map<String, String> r : rows) {
            if (exact.contains(r.get("engine"))) {
                String what = r.get("scene") + " " + r.get("setting");
                assertThat(num(r, "violations_per_million")).as(what).isZero();
                assertThat(num(r, "deepest_overlap")).as(what).isLessThan(1e-9);
                assertThat(num(r, "escapes")).as(what).isZero();
                assertThat(num(r, "deviation_max")).as(what).isLessThan(1e-9);
                assertThat(Math.abs(num(r, "energy_drift"))).as(what).isLessThan(1e-12);
                if (Boolean.parseBoolean(r.get("periodic"))) {
                    assertThat(num(r, "pressure_error")).as(what).isLessThan(1e-9);
                }
            }
        }
    }

    @Test
    void steppedAtALargeStepIsFurtherFromTheExactPressureAndTrajectoryThanAtASmallOne() {
        for (String scene : List.of("periodic-0.3", "periodic-0.6")) {
            Map<String, Map<String, String>> stepped = rowsOf(scene).stream().filter(r -> r.get("engine").equals("stepped"))
                    .collect(Collectors.toMap(r -> r.get("dt_factor"), r -> r));
            assertThat(num(stepped.get("10.0"), "pressure_error")).as(scene)
                    .isGreaterThan(num(stepped.get("0.1"), "pressure_error"));
            assertThat(num(stepped.get("10.0"), "deviation_rms")).as(scene)
                    .isGreaterThan(num(stepped.get("1.0"), "deviation_rms"))
                    .isGreaterThan(num(stepped.get("0.1"), "deviation_rms"));
            assertThat(num(stepped.get("10.0"), "deepest_overlap")).as(scene)
                    .isGreaterThan(num(stepped.get("0.1"), "deepest_overlap"));
        }
    }

    @Test
    void workerJvmsGetTheirOwnCarrierCount(@TempDir Path dir) throws IOException {
        Lab r = run("study", "accuracy", "--sizes", "200", "--scenes", "periodic:0.3", "--engines", "serial,vthreads",
                "--threads", "2,1", "--reps", "2", "--warmups", "0", "--collisions", "1", "--out", dir.toString());
        assertThat(r.status()).as(r.err()).isZero();
        assertThat(r.err()).contains("study: [3/3]");
        List<Map<String, String>> forked = csv(dir.resolve("accuracy.csv"));
        assertThat(forked).extracting(m -> m.get("setting") + " " + m.get("carriers"))
                .containsExactly("serial ", "vthreads ×2 2", "vthreads ×1 1");
        assertThat(forked).allSatisfy(m -> assertThat(m.get("reps")).isEqualTo("2"));
        assertThat(num(forked.get(0), "collisions")).isPositive();
    }

    @Test
    void badOptionsAreErrorsWithStatusTwoAndNoOutput(@TempDir Path dir) {
        String out = dir.resolve("o").toString();
        for (String[] args : List.of(
                new String[] {"--engines", "warp"},
                new String[] {"--scenes", "torus:0.3"},
                new String[] {"--scenes", "periodic:0.9"},
                new String[] {"--threads", "0"},
                new String[] {"--dt-factors", "-1"},
                new String[] {"--sizes", "1"},
                new String[] {"--short-collisions", "9"},
                new String[] {"--reps", "0"},
                new String[] {"--reps", "many"},
                new String[] {"--frobnicate"})) {
            String[] all = new String[args.length + 5];
            all[0] = "study";
            all[1] = "accuracy";
            all[2] = "--quick";
            all[3] = "--out";
            all[4] = out;
            System.arraycopy(args, 0, all, 5, args.length);
            Lab r = run(all);
            assertThat(r.status()).as(Arrays.toString(args)).isEqualTo(Main.BAD_INPUT);
            assertThat(r.err()).as(Arrays.toString(args)).startsWith("error: ");
            assertThat(dir.resolve("o")).as(Arrays.toString(args)).doesNotExist();
        }
        Lab missingParent = run("study", "accuracy", "--quick", "--out", dir.resolve("no/such").toString());
        assertThat(missingParent.status()).isEqualTo(Main.BAD_INPUT);
        assertThat(missingParent.err()).startsWith("error: --out: directory");
        Lab noStudy = run("study");
        assertThat(noStudy.status()).isEqualTo(Main.BAD_INPUT);
        assertThat(noStudy.err()).startsWith("error: missing study");
    }
}
