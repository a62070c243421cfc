package carom.lab.study.eos;

import static org.assertj.core.api.Assertions.assertThat;

import carom.lab.run.Machine;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The report's judgements: two starts agree or not, a point is accepted only where they do, the loop is
 * looked for among accepted points only, points not run say so; and how it prints a value with its error.
 */
class EosReportTest {
    /** A run whose βPσ² (not Z) is {@code beta} ± {@code error}, its error from converged blocking. */
    private static EosPoint run(double phi, String start, double beta, double error) {
        double toZ = Math.PI / (4 * phi);
        BlockedError z = new BlockedError(beta * toZ, error * toZ, error * toZ, 4, 16, true);
        BlockedError psi6 = new BlockedError(0.5, 0.01, 0.01, 4, 16, true);
        return new EosPoint(phi, start, true, false, 100, 400, 64, 1, z, psi6, 1000, 1, 1.5, null, null);
    }

    private static EosReport report(List<String> starts, List<Double> phis, List<EosPoint> points) {
        EosSettings settings = new EosSettings(256, phis, "fast", 1, 20, 5, 100, 5000, 64, 1, starts, List.of(), "carom study eos",
                false, Deadline.NONE);
        return new EosReport(settings, points, new Machine(2, "cpu", "jvm", "os", 1L << 30), 0, 1, 60);
    }

    private static EosReport single(EosPoint... points) {
        List<Double> phis = List.of(points).stream().map(EosPoint::phi).toList();
        return report(List.of(EosCommand.CRYSTAL), phis, List.of(points));
    }

    /** Both starts at each φ: crystal and liquid values given pairwise, all with the same error. */
    private static EosReport both(double error, double[] phis, double[] crystal, double[] liquid) {
        List<EosPoint> points = new ArrayList<>();
        List<Double> all = new ArrayList<>();
        for (int i = 0; i < phis.length; i++) {
            all.add(phis[i]);
            points.add(run(phis[i], EosCommand.CRYSTAL, crystal[i], error));
            points.add(run(phis[i], EosCommand.FLUID, liquid[i], error));
        }
        return report(List.of(EosCommand.CRYSTAL, EosCommand.FLUID), all, points);
    }

    @Test
    void twoStartsAgreeWithinTwoCombinedErrorsAndNotBeyond() {
        // combined error √2·0.01 = 0.01414: 0.028 apart is 1.98 of them, 0.029 is 2.05
        BranchAgreement close = BranchAgreement.of(run(0.71, "crystal", 9.228, 0.01), run(0.71, "fluid", 9.200, 0.01));
        BranchAgreement apart = BranchAgreement.of(run(0.71, "crystal", 9.171, 0.01), run(0.71, "fluid", 9.200, 0.01));

        assertThat(close.agree()).isTrue();
        assertThat(close.sigmas()).isBetween(1.97, 1.99);
        assertThat(apart.agree()).isFalse();
        assertThat(apart.sigmas()).isBetween(-2.06, -2.04);
        assertThat(new BranchAgreement(0, 0).agree()).isTrue();
        assertThat(new BranchAgreement(0.1, 0).agree()).isFalse();
    }

    @Test
    void aPointIsAcceptedOnlyWhereItsStartsAgreeAndItsValueIsTheirMean() {
        EosReport r = both(0.01, new double[] {0.70, 0.71}, new double[] {9.20, 9.10}, new double[] {9.21, 9.40});

        assertThat(r.accepted(0.70)).isTrue();
        assertThat(r.accepted(0.71)).isFalse();
        assertThat(r.value(0.70)[0]).isCloseTo(9.205, org.assertj.core.api.Assertions.within(1e-12));
        assertThat(r.value(0.70)[1]).isCloseTo(Math.sqrt(2) * 0.01 / 2, org.assertj.core.api.Assertions.within(1e-12));
    }

    @Test
    void theLoopIsLookedForAmongAcceptedPointsOnly() {
        // the crystal branch falls from 0.705 to 0.715 by 10 errors, but the liquid disagrees there: not the loop
        EosReport disagreeing = both(0.01, new double[] {0.70, 0.705, 0.715, 0.72},
                new double[] {9.18, 9.30, 9.15, 9.23}, new double[] {9.19, 9.20, 9.35, 9.24});
        // both branches fall together from 0.705 to 0.715: the loop
        EosReport agreeing = both(0.01, new double[] {0.70, 0.705, 0.715, 0.72},
                new double[] {9.18, 9.25, 9.15, 9.23}, new double[] {9.19, 9.26, 9.16, 9.24});

        assertThat(disagreeing.loopVerdict()).startsWith("**Not visible**").contains("(0.7, 0.72)")
                .contains("Within the crystal start alone:").contains("from φ = 0.705 to 0.715");
        assertThat(agreeing.loopVerdict()).startsWith("**Visible** among the accepted").contains("from φ = 0.705 to 0.715");
    }

    @Test
    void withOneStartTheStationaryPointsAreJudged() {
        // βPσ² 8.289 at 0.70 to 8.272 at 0.71: a fall of 0.017 against errors of 0.0026
        assertThat(single(run(0.70, "crystal", 8.289, 0.0018), run(0.71, "crystal", 8.272, 0.0018), run(0.72, "crystal", 8.6, 0.0018))
                .loopVerdict()).startsWith("**Visible**").contains("from φ = 0.7 to 0.71");
        assertThat(single(run(0.70, "crystal", 8.289, 0.05), run(0.71, "crystal", 8.272, 0.05)).loopVerdict())
                .startsWith("**Not visible");
        assertThat(single(run(0.60, "crystal", 5.0, 0.001)).loopVerdict()).startsWith("**Not tested");
    }

    @Test
    void pointsTheDeadlineCutOffAreReportedAsNotRun() {
        List<Double> phis = List.of(0.70, 0.71);
        EosReport r = report(List.of(EosCommand.CRYSTAL, EosCommand.FLUID), phis,
                List.of(run(0.70, "crystal", 9.2, 0.01), run(0.70, "fluid", 9.2, 0.01), run(0.71, "crystal", 9.2, 0.01)));

        String csv = new String(r.files().get(EosReport.CSV), StandardCharsets.UTF_8);
        assertThat(csv.lines().toList()).hasSize(5).anyMatch(l -> l.startsWith("0.71,256,fluid,not run,"));
        assertThat(r.accepted(0.71)).isFalse();
        assertThat(r.value(0.71)).isNull();
        String md = new String(r.files().get(EosReport.REPORT), StandardCharsets.UTF_8);
        assertThat(md).contains("| not run |").contains("**Not tested**: fewer than two packing fractions in 0.70-0.72 are accepted");
    }

    @Test
    void valuesAreGivenToTheirErrorsTwoSignificantDigits() {
        assertThat(EosReport.pm(9.18541, 0.0123)).isEqualTo("9.185 ± 0.012");
        assertThat(EosReport.pm(9.18541, 0.0034)).isEqualTo("9.1854 ± 0.0034");
        assertThat(EosReport.pm(123.4, 5.6)).isEqualTo("123.4 ± 5.6");
    }
}
