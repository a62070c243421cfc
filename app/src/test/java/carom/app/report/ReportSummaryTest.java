package carom.app.report;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * What the page says beside the plots: a simulate report's summary table, labels for quick runs and
 * loaded machines, and a folder of render's pictures taken as a report of its own.
 */
class ReportSummaryTest {
    @TempDir
    Path dir;

    /** The run's summary (collisions, energy drift, Z with its error) is a table of the simulate report's section. */
    @Test
    void aSimulateReportShowsTheRunsSummaryTable() throws Exception {
        Path scene = Files.writeString(dir.resolve("gas.json"), ReportPageTest.SCENE);
        Path report = dir.resolve("r");
        ReportPageTest.Run s = ReportPageTest.carom("simulate", scene.toString(), "--every", "0.25", "--observe", "gr,pressure",
                "--report", report.toString());
        assertThat(s.status()).as(s.err()).isZero();
        assertThat(report.resolve(RunRecord.SUMMARY_FILE)).isRegularFile();
        Path page = dir.resolve("page.html");
        ReportPageTest.Run r = ReportPageTest.carom("report", report.toString(), "--out", page.toString());
        assertThat(r.status()).as(r.err()).isZero();
        String html = Files.readString(page);
        assertThat(html).contains("<h3>Summary</h3>").containsPattern("<th>pair collisions</th><td>[0-9]+ \\([0-9.e+-]+ per disc\\)</td>")
                .containsPattern("<th>Z = PA/\\(NkT\\)</th><td>[0-9]+\\.[0-9]+ ± 0\\.[0-9]+ \\(20 blocks\\)</td>")
                .contains("<th>energy drift</th>");
    }

    /** render's PNGs carry their command; a folder of them is a section of kind render, its pictures shown. */
    @Test
    void aFolderOfRenderPicturesIsAReport() throws Exception {
        Path scene = Files.writeString(dir.resolve("gas.json"), ReportPageTest.SCENE);
        Path pictures = dir.resolve("pictures");
        ReportPageTest.Run s = ReportPageTest.carom("render", scene.toString(), "--at", "0,0.5", "--out", pictures.toString(),
                "--size", "200");
        assertThat(s.status()).as(s.err()).isZero();
        try (var files = Files.list(pictures)) {
            for (Path png : files.toList()) {
                assertThat(ReportSource.pngComment(png)).startsWith("carom render " + scene).contains("\nmachine: ");
            }
        }
        Path page = dir.resolve("page.html");
        ReportPageTest.Run r = ReportPageTest.carom("report", pictures.toString(), "--out", page.toString());
        assertThat(r.status()).as(r.err()).isZero();
        String html = Files.readString(page);
        assertThat(html).contains("(render)").contains("carom render " + scene).contains("gas-t0.png").contains("gas-t0.5.png");
    }

    @Test
    void quickRunsAndSharedMachinesAreLabelled() {
        assertThat(ReportSource.labelsOf("no such sentence", "carom study accuracy --quick --out s")).singleElement()
                .asString().startsWith("quick run");
        assertThat(ReportSource.labelsOf("x\n- note: shared: the load average was 7.50 on 2 cores before the first run, so "
                + "another process shared the machine.\n", "carom study accuracy --out s")).singleElement().asString()
                .isEqualTo("loaded machine: shared: the load average was 7.50 on 2 cores before the first run, so another "
                        + "process shared the machine.");
        assertThat(ReportSource.labelsOf("text", "carom study accuracy --quickly")).isEmpty();
    }
}
