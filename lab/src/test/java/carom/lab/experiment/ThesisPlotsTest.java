package carom.lab.experiment;

import static org.assertj.core.api.Assertions.assertThat;

import carom.lab.report.Charts;
import carom.lab.report.Table;
import carom.lab.run.Machine;
import carom.lab.run.TrialRecord;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** The thesis report's plots as data: one y scale, log axes where times span decades, no thesis row at N = 0. */
class ThesisPlotsTest {
    private static final List<Integer> SIZES = List.of(16, 200, 400);
    private static final List<Integer> LARGE = List.of(600, 800);

    /** Two trials per engine and size, serial about a millisecond, akka hundreds. */
    private static List<TrialRecord> records() {
        Map<String, Double> msPerDisc = Map.of("serial", 0.004, "fast", 0.003, "stripes", 0.03, "akka", 0.6, "vthreads", 0.2,
                "slabs", 0.002);
        List<TrialRecord> records = new ArrayList<>();
        for (String engine : EngineRole.engines()) {
            List<Integer> sizes = new ArrayList<>(SIZES);
            if (EngineRole.isParallel(engine)) {
                sizes.addAll(LARGE);
            }
            for (int n : sizes) {
                for (int trial = 1; trial <= 2; trial++) {
                    double seconds = msPerDisc.get(engine) * n * (trial == 1 ? 0.9 : 1.1) / 1000;
                    records.add(new TrialRecord(engine, ExperimentWorker.SCENE, n, trial, trial, Map.of(), 2, 2, seconds, n / 4, n,
                            0, Map.of(), null, null));
                }
            }
        }
        return records;
    }

    private static Map<String, Charts.Figure> figures() {
        ThesisSettings settings = new ThesisSettings(SIZES, 2, LARGE, 2, EngineRole.engines(), 2, 16, 1, "1g", 0,
                "carom experiment thesis", false);
        return new ThesisReport(settings, Machine.current(), 0, 0, records()).figures();
    }

    @Test
    void theAllEnginesPlotHasLogAxesWhenTimesSpanDecades() {
        Charts.Figure all = figures().get("time-all-engines");

        assertThat(all.yAxis().log()).isTrue();
        assertThat(all.xAxis().log()).isTrue();
        assertThat(all.lines()).extracting(Charts.Line::name).containsExactlyElementsOf(EngineRole.engines());
        // error bars: the sample standard deviation of the two trials
        assertThat(all.lines()).allSatisfy(l -> assertThat(l.errors()).isNotNull().allSatisfy(e -> assertThat(e).isPositive()));
    }

    @Test
    void thePerEnginePlotsHaveOneScaleAndNoThesisRowAtNZero() {
        for (String engine : EngineRole.engines()) {
            Charts.Figure f = figures().get("time-" + engine);
            if (EngineRole.beyondThesis(engine)) {
                assertThat(f.lines()).as(engine + ": no thesis counterpart, no thesis line").hasSize(1);
                assertThat(f.title()).as(engine + ": its title says so").contains("beyond the thesis")
                        .doesNotContain("and the thesis");
                continue;
            }
            assertThat(f.title()).contains("and the thesis");
            assertThat(f.lines()).as(engine).hasSize(2);
            assertThat(f.lines().get(1).reference()).isTrue();
            assertThat(f.lines()).allSatisfy(l -> assertThat(l.x()).as(l.name()).allSatisfy(x -> assertThat(x).isPositive()));
        }
        for (EngineRole role : EngineRole.values()) {
            // even out to Table 4.4's largest size, whose first row the thesis prints as N = 0
            assertThat(ThesisReport.thesisLine(role, 3_000_000).x()).as(role.name())
                    .isNotEmpty().allSatisfy(x -> assertThat(x).isGreaterThanOrEqualTo(16));
        }
    }

    @Test
    void enginesBeyondTheThesisGetATableOfTheirOwnBesideTheThesissFastestModel() {
        ThesisSettings settings = new ThesisSettings(SIZES, 2, LARGE, 2, EngineRole.engines(), 2, 16, 1, "1g", 0,
                "carom experiment thesis", false);
        Map<String, byte[]> files = new ThesisReport(settings, Machine.current(), 0, 0, records()).files();
        String report = new String(files.get(ThesisReport.REPORT), java.nio.charset.StandardCharsets.UTF_8);
        String csv = new String(files.get(ThesisReport.BEYOND_TABLE), java.nio.charset.StandardCharsets.UTF_8);

        assertThat(report).contains("## Beyond the thesis: slabs").contains("slabs speed-up")
                .contains("slabs (ms, beyond the thesis)");
        double fastestAt16 = java.util.Arrays.stream(EngineRole.values())
                .flatMap(role -> ThesisNumbers.table(role).stream()).filter(r -> r.discs() == 16)
                .mapToDouble(r -> r.stats().mean()).min().orElseThrow();
        assertThat(csv).contains("16,thesis fastest,thesis,5," + Table.plain(fastestAt16) + ",")
                .contains("16,slabs,carom,2,");
    }

    @Test
    void everyFigureIsDrawnAsPngAndSvg() {
        ThesisSettings settings = new ThesisSettings(SIZES, 2, LARGE, 2, EngineRole.engines(), 2, 16, 1, "1g", 0,
                "carom experiment thesis", false);
        ThesisReport report = new ThesisReport(settings, Machine.current(), 0, 0, records());
        Map<String, byte[]> files = report.files();
        for (String name : report.figures().keySet()) {
            assertThat(files).containsKeys(name + ".png", name + ".svg");
            carom.lab.report.VectorFiles.assertSvg(files.get(name + ".svg"), name + ".svg");
        }
        assertThat(new String(files.get(ThesisReport.REPORT), java.nio.charset.StandardCharsets.UTF_8))
                .contains("![time-all-engines.png](time-all-engines.png)").doesNotContain("](time-all-engines.svg)");
    }
}
