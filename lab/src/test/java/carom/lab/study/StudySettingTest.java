package carom.lab.study;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.Engine;
import carom.engines.EngineCatalog;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The default settings come from the catalog: a new catalog engine joins without code changes. */
class StudySettingTest {
    @Test
    void everyCatalogEngineAndThePeerAreKnown() {
        List<String> known = Setting.knownEngines();
        EngineCatalog.all().forEach(e -> assertThat(known).contains(e.name()));
        assertThat(known).endsWith("dyn4j");
    }

    @Test
    void steppingEnginesGetEachDtFactorSingleThreadedOnesOneSettingOthersEachThreadCount() {
        List<Setting> settings = Setting.expand(List.of("serial", "stripes", "stepped", "dyn4j"), List.of(1, 2, 4),
                List.of(10.0, 0.1));
        assertThat(settings).extracting(Setting::label).containsExactly("serial", "stripes ×1", "stripes ×2",
                "stripes ×4", "stepped dt×10", "stepped dt×0.1", "dyn4j dt×10", "dyn4j dt×0.1");
    }

    @Test
    void anEngineWithoutADtThatIsNotKnownToBeSerialRunsAtEveryThreadCount() {
        // Whatever the catalog adds later (an exact parallel engine) is run at each thread count.
        for (Engine e : EngineCatalog.all()) {
            List<Setting> settings = Setting.expand(List.of(e.name()), List.of(1, 2), List.of(1.0));
            int expected = e.name().equals("serial") || e.name().equals("fast") || carom.core.engine.Tunables.declares(e.spec().tunables(), "dt") ? 1 : 2;
            assertThat(settings).as(e.name()).hasSize(expected);
        }
    }
}
