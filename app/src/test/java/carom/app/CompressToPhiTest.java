package carom.app;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.observe.Observables;
import carom.core.observe.StateChecks;
import carom.core.scene.Scene;
import carom.core.scene.SceneReader;
import carom.core.state.Discs;
import java.io.IOException;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * {@code compress --to-phi PHI}: the state written is at packing fraction PHI to rounding, without
 * overlaps, at the scene's kinetic energy; a PHI the scene is already at, or both or neither stop, is
 * bad input.
 */
class CompressToPhiTest {
    @TempDir
    Path dir;

    @ParameterizedTest
    @CsvSource({"0.55, 1, 31", "0.62, 0.5, 32", "0.5, 0.25, 33"})
    void theStateIsAtThePackingFractionAskedForWithTheScenesKineticEnergy(double phi, double every, long seed)
            throws IOException {
        Path scene = Scenes.write(dir, "mix.json", Scenes.mixture(150, seed, 0.05));
        Path state = dir.resolve("s.json");
        Cli r = Cli.run("compress", scene.toString(), "--to-phi", Double.toString(phi), "--every", Double.toString(every),
                "--out-state", state.toString(), "--summary", dir.resolve("c.json").toString());
        assertThat(r.status()).as(r.err()).isZero();
        Scene grown = SceneReader.read(state);
        assertThat(grown.packingFraction()).isCloseTo(phi, within(1e-12));
        Discs d = grown.newDiscs();
        assertThat(StateChecks.smallestGap(d, grown.box())).isGreaterThan(-1e-12);
        double start = Observables.kineticEnergy(SceneReader.read(scene).newDiscs());
        assertThat(Observables.kineticEnergy(d)).isCloseTo(start, within(1e-9 * start));
        assertThat(new com.fasterxml.jackson.databind.ObjectMapper().readTree(dir.resolve("c.json").toFile())
                .path("compression").path("stop").asText()).isEqualTo("phi");
    }

    @Test
    void aPhiNotAboveTheScenesOrTwoStopsOrNoneAreBadInput() {
        Path scene = Scenes.write(dir, "mix.json", Scenes.mixture(60, 1, 0.05));
        assertThat(Cli.run("compress", scene.toString(), "--to-phi", "0.3").firstErrorLine())
                .startsWith("error: --to-phi: 0.3 is not above the scene's packing fraction");
        assertThat(Cli.run("compress", scene.toString(), "--to-phi", "1.2").firstErrorLine())
                .isEqualTo("error: --to-phi: must be a packing fraction between 0 and 1, got 1.2");
        assertThat(Cli.run("compress", scene.toString(), "--to-phi", "0.5", "--to-pressure", "10").firstErrorLine())
                .isEqualTo("error: --to-pressure and --to-phi: give one (where to stop)");
        assertThat(Cli.run("compress", scene.toString()).firstErrorLine())
                .isEqualTo("error: compress needs --to-pressure P or --to-phi PHI (where to stop)");
    }
}
