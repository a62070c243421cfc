package carom.app;

import static carom.app.SimulateCommandTest.filesIn;
import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.io.TempDir;

/**
 * Bad input: exit status 2, one {@code error: } line naming the file (or the option) and what is wrong,
 * no stack trace, nothing on stdout, and no output file created, half-written or left as a temp file.
 */
class SimulateErrorsTest {
    @TempDir
    Path dir;

    private Path out() {
        return dir.resolve("final.csv");
    }

    private Path summary() {
        return dir.resolve("summary.json");
    }

    /** Runs simulate on {@code scene} with both outputs asked for in {@link #dir}, plus {@code extra}. */
    private Cli simulate(Path scene, String... extra) {
        List<String> args = new ArrayList<>(List.of("simulate", scene.toString(),
                "--out", out().toString(), "--summary", summary().toString()));
        args.addAll(List.of(extra));
        return Cli.run(args.toArray(String[]::new));
    }

    private void assertRejected(Cli r, String firstLineStart, String... sceneFiles) {
        assertThat(r.status()).as(r.err()).isEqualTo(2);
        assertThat(r.firstErrorLine()).startsWith(firstLineStart);
        assertThat(r.err()).doesNotContain("\tat ").doesNotContain("Exception");
        assertThat(r.out()).isEmpty();
        assertThat(filesIn(dir)).containsExactlyInAnyOrder(sceneFiles);
    }

    @Test
    void malformedJson() {
        Path scene = Scenes.write(dir, "broken.json", "{ \"name\": \"x\", \"box\": ");
        assertRejected(simulate(scene), "error: " + scene + ": malformed JSON", "broken.json");
    }

    @Test
    void unknownKeyIsNamedByItsJsonPath() {
        Path scene = Scenes.write(dir, "typo.json", Scenes.headOn().replace("\"radius\"", "\"radios\""));
        Cli r = simulate(scene);
        assertRejected(r, "error: " + scene + ": species[0].", "typo.json");
        assertThat(r.firstErrorLine()).contains("radios");
    }

    @Test
    void overlappingDiscsAreNamedByTheirIds() {
        Path scene = Scenes.write(dir, "overlap.json", Scenes.headOn().replace("\"x\": 8", "\"x\": 2.5"));
        Cli r = simulate(scene);
        assertRejected(r, "error: " + scene + ": ", "overlap.json");
        assertThat(r.firstErrorLine()).contains("0").contains("1").contains("overlap");
    }

    @Test
    void missingSceneFile() {
        Path scene = dir.resolve("absent.json");
        assertRejected(simulate(scene), "error: " + scene + ": ");
    }

    @Test
    void unknownEngine() {
        Path scene = Scenes.write(dir, "head-on.json", Scenes.headOn());
        Cli r = simulate(scene, "--engine", "warp");
        assertRejected(r, "error: " + scene + ": unknown engine 'warp'", "head-on.json");
        assertThat(r.firstErrorLine()).contains("serial");
    }

    @Test
    void unknownOption() {
        Path scene = Scenes.write(dir, "head-on.json", Scenes.headOn());
        assertRejected(simulate(scene, "--bogus"), "error: Unknown option: '--bogus'", "head-on.json");
    }

    @Test
    void missingSceneArgument() {
        assertRejected(Cli.run("simulate", "--out", out().toString()), "error: Missing required parameter");
    }

    @Test
    void untilMustBePositive() {
        Path scene = Scenes.write(dir, "head-on.json", Scenes.headOn());
        assertRejected(simulate(scene, "--until", "-1"), "error: --until: must be a finite number > 0, got -1.0",
                "head-on.json");
        assertRejected(simulate(scene, "--until", "0"), "error: --until: must be a finite number > 0", "head-on.json");
        assertRejected(simulate(scene, "--until", "Infinity"), "error: --until: must be a finite number > 0",
                "head-on.json");
        assertRejected(simulate(scene, "--until", "NaN"), "error: --until: must be a finite number > 0", "head-on.json");
    }

    @Test
    void untilMustBeANumber() {
        Path scene = Scenes.write(dir, "head-on.json", Scenes.headOn());
        Cli r = simulate(scene, "--until", "soon");
        assertRejected(r, "error: Invalid value for option '--until'", "head-on.json");
    }

    @Test
    void threadsMustBeAtLeastOne() {
        Path scene = Scenes.write(dir, "head-on.json", Scenes.headOn());
        assertRejected(simulate(scene, "--threads", "0"), "error: --threads: must be from 1 to 4096, got 0", "head-on.json");
    }

    /** Beyond the bound no engine starts: the pools of akka and stripes and the virtual-thread scheduler broke at 32,768. */
    @org.junit.jupiter.params.ParameterizedTest
    @org.junit.jupiter.params.provider.CsvSource({"akka, 32768", "stripes, 32768", "vthreads, 32768", "slabs, 4097",
        "fast, 2147483647", "serial, -1"})
    void threadsBeyondTheBoundAreBadInputForEveryEngine(String engine, String threads) {
        Path scene = Scenes.write(dir, "head-on.json", Scenes.headOn());
        assertRejected(simulate(scene, "--engine", engine, "--threads", threads),
                "error: --threads: must be from 1 to 4096, got " + threads, "head-on.json");
    }

    @Test
    void threadsBeyondAnIntAreAUsageError() {
        Path scene = Scenes.write(dir, "head-on.json", Scenes.headOn());
        assertRejected(simulate(scene, "--threads", "99999999999"), "error: Invalid value for option '--threads'",
                "head-on.json");
    }

    @Test
    void optionsAreCheckedBeforeTheSceneIsRead() {
        Path missing = dir.resolve("absent.json");
        assertRejected(simulate(missing, "--threads", "5000"), "error: --threads: ");
        assertRejected(simulate(missing, "--until", "-1"), "error: --until: ");
    }

    @Test
    void untilBeyondTheRangeOfADoubleIsBadInput() {
        Path scene = Scenes.write(dir, "head-on.json", Scenes.headOn());
        assertRejected(simulate(scene, "--until", "1e999"), "error: --until: must be a finite number > 0, got Infinity",
                "head-on.json");
    }

    @Test
    void aSceneThatIsNotUtf8NamesTheByte() throws IOException {
        Path scene = dir.resolve("latin1.json");
        Files.write(scene, Scenes.headOn().replace("head-on", "h\u00e9ad-on").getBytes(java.nio.charset.StandardCharsets.ISO_8859_1));
        int at = Scenes.headOn().indexOf("head-on") + 2;
        assertRejected(simulate(scene), "error: " + scene + ": not valid UTF-8 at byte " + at, "latin1.json");
    }

    @Test
    void engineOptionsNeedKeyAndValue() {
        Path scene = Scenes.write(dir, "head-on.json", Scenes.headOn());
        assertRejected(simulate(scene, "--option", "cellFactor"), "error: ", "head-on.json");
    }

    @Test
    void slabsBarrierSpinsMustBeAWholeNumber() {
        Path scene = Scenes.write(dir, "head-on.json", Scenes.headOn());
        assertRejected(simulate(scene, "--engine", "slabs", "--threads", "2", "--option", "spins=-5"),
                "error: --option spins: must be in [0, 1073741824], got -5",
                "head-on.json");
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"{ \"gravity\": [0, -1] }", "{ \"growth\": 0.01 }"})
    void neighbourListsAskedForWhereTheyCannotServeAreBadInput(String effects) {
        Path scene = Scenes.write(dir, "head-on.json", Scenes.headOn(effects));
        Cli r = simulate(scene, "--option", "skin=0.5");
        assertRejected(r, "error: ", "head-on.json");
        assertThat(r.firstErrorLine()).contains("--option skin");
    }

    @Test
    void outputInANonexistentDirectory() {
        Path scene = Scenes.write(dir, "head-on.json", Scenes.headOn());
        Path csv = dir.resolve("no/such/dir/final.csv");
        Cli r = Cli.run("simulate", scene.toString(), "--out", csv.toString(), "--summary", summary().toString());
        assertRejected(r, "error: --out: directory " + csv.getParent().toAbsolutePath() + " does not exist",
                "head-on.json");
    }

    @Test
    void summaryInANonexistentDirectoryCreatesNoFinalState() {
        Path scene = Scenes.write(dir, "head-on.json", Scenes.headOn());
        Path json = dir.resolve("missing/summary.json");
        Cli r = Cli.run("simulate", scene.toString(), "--out", out().toString(), "--summary", json.toString());
        assertRejected(r, "error: --summary: directory ", "head-on.json");
    }

    @Test
    void outputThatIsADirectory() throws IOException {
        Path scene = Scenes.write(dir, "head-on.json", Scenes.headOn());
        Files.createDirectory(dir.resolve("taken"));
        Cli r = Cli.run("simulate", scene.toString(), "--out", dir.resolve("taken").toString());
        assertRejected(r, "error: --out: ", "head-on.json", "taken");
        assertThat(r.firstErrorLine()).contains("is a directory");
    }

    @Test
    void bothOutputsToOneFile() {
        Path scene = Scenes.write(dir, "head-on.json", Scenes.headOn());
        Cli r = Cli.run("simulate", scene.toString(), "--out", out().toString(), "--summary", out().toString());
        assertRejected(r, "error: --out and --summary name the same file", "head-on.json");
    }

    @Test
    void discSlidingOnTheFloorUnderGravity() {
        Path scene = Scenes.write(dir, "rest.json", SLIDING_ON_FLOOR);
        Cli r = simulate(scene);
        assertRejected(r, "error: " + scene + ": particles[0]: disc 0 touches the bottom wall", "rest.json");
    }

    @Test
    void unknownEngineOption() {
        Path scene = Scenes.write(dir, "head-on.json", Scenes.headOn());
        Cli r = Cli.run("simulate", scene.toString(), "--option", "cellFactr=2", "--out", out().toString());
        assertRejected(r, "error: --option cellFactr: engine fast has no such option", "head-on.json");
    }

    @Test
    void unknownEffect() {
        Path scene = Scenes.write(dir, "magic.json", Scenes.headOn("{ \"magnetism\": 1 }"));
        assertRejected(simulate(scene), "error: " + scene + ": effects.magnetism", "magic.json");
    }

    /** One disc touching the floor at rest, with gravity pressing it down: resting contact. */
    private static final String SLIDING_ON_FLOOR = """
            { "box": { "width": 4, "height": 4, "boundary": "walls" },
              "species": [ { "name": "ball", "radius": 0.5, "mass": 1 } ],
              "particles": [ { "species": "ball", "x": 2, "y": 0.5, "vx": 1 } ],
              "effects": { "gravity": [0, -9.81] },
              "until": 1 }
            """;

    @Test
    void aFailedRunLeavesExistingOutputsAlone() throws IOException {
        Path scene = Scenes.write(dir, "soft.json", SLIDING_ON_FLOOR);
        Files.writeString(out(), "previous final state\n");
        Files.writeString(summary(), "{}\n");
        Cli r = simulate(scene);
        assertRejected(r, "error: " + scene + ": ", "soft.json", "final.csv", "summary.json");
        assertThat(Files.readString(out())).isEqualTo("previous final state\n");
        assertThat(Files.readString(summary())).isEqualTo("{}\n");
    }
}
