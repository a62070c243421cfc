package carom.lab.study.eos;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** The literature point a study compares with: at its packing fraction, from the published size nearest its own. */
class EosLiteratureTest {
    @ParameterizedTest(name = "φ {0}, N = {1}: {2}")
    @CsvSource({
        "0.708, 16384, HistoricDisks N=128^2, 9.17512",
        "0.708, 4096, HistoricDisks N=128^2, 9.17512",
        "0.708, 262144, HistoricDisks N=1024^2, 9.184959",
        "0.700, 16384, HistoricDisks N=1024^2, 9.185405",
        "0.680, 1024, HistoricDisks N=870, 8.513233",
        "0.680, 16384, BK2011, 0",
        "0.500, 144, KR2006, 0",
    })
    void theNearestPublishedSizeThatHasThePoint(double phi, int discs, String source, double value) {
        EosLiterature.Point p = EosLiterature.at(phi, discs);
        assertThat(p.source()).isEqualTo(source);
        if (value > 0) {
            assertThat(p.betaPSigma2()).isEqualTo(value);
        }
    }

    @ParameterizedTest
    @CsvSource({"0.705, 16384", "0.74, 4096"})
    void noneWhereNoSizeHasThePoint(double phi, int discs) {
        assertThat(EosLiterature.at(phi, discs)).isNull();
    }
}
