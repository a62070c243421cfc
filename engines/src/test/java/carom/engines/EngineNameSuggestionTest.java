package carom.engines;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import carom.core.BadInputException;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** An unknown engine name is answered with the name most likely meant, as picocli answers options. */
class EngineNameSuggestionTest {
    @ParameterizedTest
    @CsvSource({"Fast, fast", "FAST, fast", "slab, slabs", "serail, serial", "clustr, cluster", "vthread, vthreads"})
    void aNearMissIsAnsweredWithTheEngineMeant(String typed, String meant) {
        assertThatThrownBy(() -> EngineCatalog.byName(typed))
                .isInstanceOf(BadInputException.class)
                .hasMessageStartingWith("unknown engine '" + typed + "'; did you mean " + meant + "? (known: ");
    }

    @ParameterizedTest
    @CsvSource({"warp", "quantum", "x"})
    void aNameFarFromEveryEngineGetsNoSuggestion(String typed) {
        assertThatThrownBy(() -> EngineCatalog.byName(typed))
                .isInstanceOf(BadInputException.class)
                .hasMessageStartingWith("unknown engine '" + typed + "' (known: ");
        assertThat(EngineCatalog.closestName(typed)).isNull();
    }
}
