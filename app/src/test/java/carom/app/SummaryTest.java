package carom.app;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.RunResult;
import carom.core.engine.Energy;
import carom.core.observe.Pressure;
import carom.core.state.Discs;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** The JSON and readable summaries of a hand-made result. */
class SummaryTest {
    private static final FinalChecks NO_OVERLAP = new FinalChecks(0, 0);

    /** The energy of {@link #result} without gravity: its kinetic energy. */
    private static final Energy KINETIC_ONLY = new Energy(3.0, 2.7);

    private static RunResult result(Pressure pressure) {
        return RunResult.of("fast", false, new Discs(3), 2.0)
                .collisions(40, 10)
                .events(55)
                .kineticEnergy(3.0, 2.7)
                .momentum(new double[] {0.5, -0.25}, new double[] {0.5, -0.25})
                .pressure(pressure)
                .causalityViolations(4)
                .wallSeconds(0.5)
                .counters(Map.of("steps", 20L, "messages", 7L))
                .build();
    }

    @Test
    void jsonCarriesEveryField() throws IOException {
        StringWriter w = new StringWriter();
        SummaryJson.write(SummaryJson.toJson(new FinishedRun("gas", 3, 8, result(new Pressure(1.25, 0.01, 0.4, 0.003, 12)), KINETIC_ONLY, NO_OVERLAP)), w);
        JsonNode s = new ObjectMapper().readTree(w.toString());

        assertThat(s.get("engine").asText()).isEqualTo("fast");
        assertThat(s.get("exact").asBoolean()).isFalse();
        assertThat(s.get("scene").asText()).isEqualTo("gas");
        assertThat(s.get("particles").asInt()).isEqualTo(3);
        assertThat(s.get("threads").asInt()).isEqualTo(8);
        assertThat(s.get("until").asDouble()).isEqualTo(2.0);
        assertThat(s.at("/collisions/pair").asLong()).isEqualTo(40);
        assertThat(s.at("/collisions/wall").asLong()).isEqualTo(10);
        assertThat(s.get("events").asLong()).isEqualTo(55);
        assertThat(s.get("collisionsPerSecond").asDouble()).isEqualTo(100.0);
        assertThat(s.get("energyDrift").asDouble()).isCloseTo(-0.1, org.assertj.core.api.Assertions.within(1e-12));
        assertThat(s.at("/kineticEnergy/initial").asDouble()).isEqualTo(3.0);
        assertThat(s.at("/energy/initial").asDouble()).isEqualTo(3.0);
        assertThat(s.at("/energy/final").asDouble()).isEqualTo(2.7);
        assertThat(s.at("/momentum/final/1").asDouble()).isEqualTo(-0.25);
        assertThat(s.get("causalityViolations").asLong()).isEqualTo(4);
        assertThat(s.at("/pressure/Z").asDouble()).isEqualTo(1.25);
        assertThat(s.at("/pressure/Zerror").asDouble()).isEqualTo(0.01);
        assertThat(s.at("/pressure/P").asDouble()).isEqualTo(0.4);
        assertThat(s.at("/pressure/Perror").asDouble()).isEqualTo(0.003);
        assertThat(s.at("/pressure/blocks").asInt()).isEqualTo(12);
        assertThat(s.at("/counters/steps").asLong()).isEqualTo(20);
        assertThat(s.at("/counters/messages").asLong()).isEqualTo(7);
        // Pretty printed.
        assertThat(w.toString()).contains("\n  \"engine\" : \"fast\"");
    }

    @Test
    void nonFiniteNumbersBecomeNullSoTheJsonStaysValid() throws IOException {
        StringWriter w = new StringWriter();
        SummaryJson.write(SummaryJson.toJson(new FinishedRun("gas", 3, 1, result(new Pressure(1.25, Double.NaN, 0.4, Double.NaN, 1)), KINETIC_ONLY, NO_OVERLAP)), w);
        JsonNode s = new ObjectMapper().readTree(w.toString());
        assertThat(s.at("/pressure/Zerror").isNull()).isTrue();
        assertThat(s.at("/pressure/Z").asDouble()).isEqualTo(1.25);
    }

    @Test
    void readableSummaryShowsPressureAndCounters() {
        StringWriter w = new StringWriter();
        ReadableSummary.print(new FinishedRun("gas", 3, 8, result(new Pressure(1.25, 0.01, 0.4, 0.003, 12)), KINETIC_ONLY, NO_OVERLAP), new PrintWriter(w),
                StandardCharsets.UTF_8);
        assertThat(w.toString()).containsPattern("(?m)^engine +fast \\(relaxed\\)$")
                .containsPattern("(?m)^pressure Z +1\\.25000 \u00b1 0\\.010 ")
                .containsPattern("(?m)^causality violations +4$")
                .containsPattern("(?m)^energy drift +-1\\.000e-01$")
                .containsPattern("(?m)^momentum final +\\(0\\.5, -0\\.25\\)$")
                .containsPattern("(?m)^  messages +7$")
                .containsPattern("(?m)^  steps +20$");
    }

    @Test
    void readableSummaryAvoidsCharactersTheConsoleCannotShow() {
        StringWriter w = new StringWriter();
        ReadableSummary.print(new FinishedRun("gas", 3, 8, result(new Pressure(1.25, 0.01, 0.4, 0.003, 12)), KINETIC_ONLY, NO_OVERLAP), new PrintWriter(w),
                StandardCharsets.US_ASCII);
        assertThat(w.toString()).contains("1.25000 +/- 0.010").doesNotContain("\u00b1");
    }

    @Test
    void underGravityTheTotalEnergyCarriesTheDriftAndTheKineticPartIsShownBesideIt() throws IOException {
        // Kinetic energy fell from 3 to 2.7 while the total stayed at 10: nothing was lost.
        Energy total = new Energy(10.0, 10.0);
        StringWriter w = new StringWriter();
        SummaryJson.write(SummaryJson.toJson(new FinishedRun("pile", 3, 1, result(null), total, NO_OVERLAP)), w);
        JsonNode s = new ObjectMapper().readTree(w.toString());
        assertThat(s.at("/energy/initial").asDouble()).isEqualTo(10.0);
        assertThat(s.at("/energy/final").asDouble()).isEqualTo(10.0);
        assertThat(s.at("/kineticEnergy/final").asDouble()).isEqualTo(2.7);
        assertThat(s.get("energyDrift").asDouble()).isZero();

        StringWriter text = new StringWriter();
        ReadableSummary.print(new FinishedRun("pile", 3, 1, result(null), total, NO_OVERLAP), new PrintWriter(text), StandardCharsets.UTF_8);
        assertThat(text.toString()).containsPattern("(?m)^energy initial +10\\.0  \\(kinetic 3\\.0\\)$")
                .containsPattern("(?m)^energy final +10\\.0  \\(kinetic 2\\.7\\)$")
                .containsPattern("(?m)^energy drift +0\\.000e\\+00$");
    }

    @Test
    void anUndefinedEnergyIsNullAndSaysWhy() throws IOException {
        Energy undefined = new Energy(Double.NaN, Double.NaN);
        StringWriter w = new StringWriter();
        SummaryJson.write(SummaryJson.toJson(new FinishedRun("falling gas", 3, 1, result(null), undefined, NO_OVERLAP)), w);
        JsonNode s = new ObjectMapper().readTree(w.toString());
        assertThat(s.at("/energy/initial").isNull()).isTrue();
        assertThat(s.get("energyDrift").isNull()).isTrue();
        StringWriter text = new StringWriter();
        ReadableSummary.print(new FinishedRun("falling gas", 3, 1, result(null), undefined, NO_OVERLAP), new PrintWriter(text), StandardCharsets.UTF_8);
        assertThat(text.toString()).containsPattern("(?m)^energy drift +undefined \\(gravity in a periodic box\\)$");
    }

    @Test
    void aSceneNameCannotWriteControlCharactersToTheTerminal() {
        StringWriter text = new StringWriter();
        ReadableSummary.print(new FinishedRun("gas\n\u001b[2J", 3, 1, result(null), KINETIC_ONLY, NO_OVERLAP), new PrintWriter(text),
                StandardCharsets.UTF_8);
        assertThat(text.toString()).contains("gas\\n\\u001b[2J" + System.lineSeparator()).doesNotContain("\u001b");
    }

    @org.junit.jupiter.api.io.TempDir
    java.nio.file.Path dir;

    @Test
    void theSummarySaysHowDeepTheFinalStateOverlaps() throws Exception {
        java.nio.file.Path scene = dir.resolve("dense.json");
        java.nio.file.Files.writeString(scene, """
                { "name": "dense", "box": { "width": 20, "height": 20, "boundary": "periodic" },
                  "species": [ { "name": "d", "radius": 0.5, "mass": 1 } ],
                  "generate": [ { "species": "d", "count": 324, "layout": "triangular", "jitter": 0.5,
                                  "velocity": { "distribution": "maxwell", "temperature": 1 }, "seed": 2 } ],
                  "until": 1 }""");
        double[] overlaps = new double[2];
        String[] engines = {"fast", "stepped"};
        for (int k = 0; k < 2; k++) {
            java.nio.file.Path summary = dir.resolve(engines[k] + ".json");
            String[] args = k == 0 ? new String[] {"simulate", scene.toString(), "--engine", "fast", "--summary", summary.toString()}
                    : new String[] {"simulate", scene.toString(), "--engine", "stepped", "--option", "dt=0.05", "--summary", summary.toString()};
            Cli r = Cli.run(args);
            assertThat(r.status()).as(r.err()).isZero();
            var json = new com.fasterxml.jackson.databind.ObjectMapper().readTree(summary.toFile());
            overlaps[k] = json.get("finalState").get("deepestOverlap").asDouble();
            assertThat(json.get("finalState").get("discsOutsideWalls").asInt()).isZero();
        }
        assertThat(overlaps[0]).as("exact: rounding only").isLessThan(1e-12);
        assertThat(overlaps[1]).as("stepped at a coarse dt overlaps").isGreaterThan(1e-4);
    }
}
