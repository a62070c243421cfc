package carom.lab.study.eos;

import static org.assertj.core.api.Assertions.assertThat;

import carom.lab.run.Machine;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The report's verdict on the loop, and how it prints a value with its error. */
class EosReportTest {
    private static EosPoint point(double phi, double z, double zError) {
        return new EosPoint(phi, true, 100, 400, 20, 1, z, zError, 0.5, 0.01, 1000, 1, null, null);
    }

    private static EosReport report(List<EosPoint> points) {
        EosSettings settings = new EosSettings(256, points.stream().map(EosPoint::phi).toList(), "fast", 1, 20, 5, 100, 5000, 20, 1,
                "crystal", List.of(), "carom study eos", false);
        return new EosReport(settings, points, new Machine(2, "cpu", "jvm", "os", 1L << 30), 0, 1);
    }

    @Test
    void aPressureThatFallsAsDensityRisesBeyondTheErrorsIsTheLoop() {
        // βPσ² = Z·4φ/π: 9.30 at 0.70 -> 8.289, 9.15 at 0.71 -> 8.272: a fall of 0.017 against errors of 0.0026
        String verdict = report(List.of(point(0.70, 9.30, 0.002), point(0.71, 9.15, 0.002), point(0.72, 9.40, 0.002))).loopVerdict();

        assertThat(verdict).startsWith("**Visible**").contains("from φ = 0.7 to 0.71");
    }

    @Test
    void aRiseOrAFallWithinTheErrorsIsNoLoop() {
        assertThat(report(List.of(point(0.70, 9.30, 0.05), point(0.71, 9.15, 0.05))).loopVerdict()).startsWith("**Not visible");
        assertThat(report(List.of(point(0.70, 9.0, 0.001), point(0.72, 9.5, 0.001))).loopVerdict()).startsWith("**Not visible");
        assertThat(report(List.of(point(0.60, 5.0, 0.001))).loopVerdict()).startsWith("Not tested");
    }

    @Test
    void valuesAreGivenToTheirErrorsTwoSignificantDigits() {
        assertThat(EosReport.pm(9.18541, 0.0123)).isEqualTo("9.185 ± 0.012");
        assertThat(EosReport.pm(9.18541, 0.0034)).isEqualTo("9.1854 ± 0.0034");
        assertThat(EosReport.pm(123.4, 5.6)).isEqualTo("123.4 ± 5.6");
    }
}
