package carom.app;

import static org.assertj.core.api.Assertions.assertThat;

import carom.app.checkpoint.CheckpointFile;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * {@code --trajectory-every} and {@code --observe-every} apart ({@code --every} sets both): frames at
 * k·DT of their own interval, observables at theirs, the final state unmoved by either, a checkpointed
 * run resumed with both; and sampling with nothing to sample is bad input.
 */
class SamplingIntervalsTest {
    @TempDir
    Path dir;

    private static List<String> times(Path xyz) throws IOException {
        return Files.readAllLines(xyz).stream().filter(l -> l.startsWith("Lattice="))
                .map(l -> l.replaceAll(".* Time=(\\S+) .*", "$1")).toList();
    }

    @ParameterizedTest
    @CsvSource({"fast, 1", "slabs, 2"})
    void framesAndObservablesTakeTheirOwnIntervals(String engine, int threads) throws IOException {
        Path scene = Scenes.write(dir, "gas.json", Scenes.periodic());
        String t = Integer.toString(threads);
        Cli.ok("simulate", scene.toString(), "--engine", engine, "--threads", t, "--until", "2", "--trajectory-every", "1",
                "--trajectory", dir.resolve("f.xyz").toString(), "--observe", "pressure", "--observe-every", "0.25",
                "--report", dir.resolve("r").toString(), "--out", dir.resolve("sampled.csv").toString());
        Cli.ok("simulate", scene.toString(), "--engine", engine, "--threads", t, "--until", "2",
                "--out", dir.resolve("plain.csv").toString());
        assertThat(times(dir.resolve("f.xyz"))).containsExactly("0.0", "1.0", "2.0");
        List<String> pressure = Files.readAllLines(dir.resolve("r/pressure.csv"));
        assertThat(pressure).hasSize(1 + 8);
        assertThat(pressure.get(1)).startsWith("0.0,0.25,");
        assertThat(pressure.get(8)).startsWith("1.75,2.0,");
        if (engine.equals("fast")) {
            // Samples are read without disturbing the run (slabs: its windows end at samples, so to rounding).
            assertThat(Files.readString(dir.resolve("sampled.csv"))).isEqualTo(Files.readString(dir.resolve("plain.csv")));
        }
    }

    @Test
    void everySetsBothAndEachOwnIntervalOverridesIt() throws IOException {
        Path scene = Scenes.write(dir, "gas.json", Scenes.periodic());
        Cli.ok("simulate", scene.toString(), "--until", "2", "--every", "0.5", "--trajectory", dir.resolve("f.xyz").toString(),
                "--observe", "pressure", "--observe-every", "1", "--report", dir.resolve("r").toString());
        assertThat(times(dir.resolve("f.xyz"))).containsExactly("0.0", "0.5", "1.0", "1.5", "2.0");
        assertThat(Files.readAllLines(dir.resolve("r/pressure.csv"))).hasSize(1 + 2);
    }

    @Test
    void aCheckpointedRunWithTwoIntervalsResumesToTheBytesOfOneRun() throws IOException {
        Path scene = Scenes.write(dir, "gas.json", Scenes.periodic());
        Path ckpt = dir.resolve("c.ckpt");
        Cli.ok("simulate", scene.toString(), "--until", "1.3", "--trajectory-every", "0.5", "--trajectory",
                dir.resolve("first.xyz").toString(), "--observe", "pressure,msd", "--observe-every", "0.2",
                "--report", dir.resolve("r1").toString(), "--checkpoint", ckpt.toString());
        Cli.ok("resume", ckpt.toString(), "--until", "3", "--out", dir.resolve("resumed.csv").toString(),
                "--trajectory", dir.resolve("rest.xyz").toString(), "--report", dir.resolve("r2").toString());
        Cli.ok("simulate", scene.toString(), "--until", "3", "--trajectory-every", "0.5", "--trajectory",
                dir.resolve("whole.xyz").toString(), "--observe", "pressure,msd", "--observe-every", "0.2",
                "--report", dir.resolve("r3").toString(), "--out", dir.resolve("whole.csv").toString());
        assertThat(Files.readString(dir.resolve("resumed.csv"))).isEqualTo(Files.readString(dir.resolve("whole.csv")));
        assertThat(times(dir.resolve("rest.xyz"))).containsExactly("1.5", "2.0", "2.5", "3.0");
        for (String csv : List.of("pressure.csv", "msd.csv")) {
            assertThat(Files.readString(dir.resolve("r2").resolve(csv))).as(csv)
                    .isEqualTo(Files.readString(dir.resolve("r3").resolve(csv)));
        }
        assertThat(CheckpointFile.read(ckpt).otherEvery()).isEqualTo(0.2);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', textBlock = """
            --every 0.5                                                    | error: --every: nothing to sample; add --trajectory FRAMES or --observe LIST
            --trajectory-every 1                                           | error: --trajectory-every needs --trajectory FRAMES
            --observe-every 1                                              | error: --observe-every needs --observe LIST
            --every 1 --trajectory-every 1 --observe-every 1 --trajectory T --observe gr --report R | error: --every: --trajectory-every and --observe-every set both
            --trajectory-every 0 --trajectory T                            | error: --trajectory-every: must be a finite number > 0
            --observe-every NaN --observe gr --report R                    | error: --observe-every: must be a finite number > 0
            --engine serial --trajectory-every 1 --trajectory T            | error: --trajectory-every: engine serial cannot stop at given times
            """)
    void samplingWithNothingToSampleOrNoIntervalIsBadInput(String options, String firstLine) throws IOException {
        Path scene = Scenes.write(dir, "gas.json", Scenes.periodic());
        List<String> args = new java.util.ArrayList<>(List.of("simulate", scene.toString()));
        for (String o : options.strip().split(" +")) {
            args.add(o.equals("T") ? dir.resolve("f.xyz").toString() : o.equals("R") ? dir.resolve("r").toString() : o);
        }
        Cli r = Cli.run(args.toArray(String[]::new));
        assertThat(r.status()).as(r.err()).isEqualTo(Main.BAD_INPUT);
        assertThat(r.firstErrorLine()).startsWith(firstLine.strip());
        try (var files = Files.list(dir)) {
            assertThat(files.map(p -> p.getFileName().toString())).containsExactly("gas.json");
        }
    }

    @Test
    void withGrowthEveryAloneIsTheThermostatsInterval() {
        Path scene = Scenes.write(dir, "growth.json", Scenes.growth(60, 3));
        Cli.ok("simulate", scene.toString(), "--until", "1", "--every", "0.5", "--out", dir.resolve("f.csv").toString());
    }
}
