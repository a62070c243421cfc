package carom.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.Arrays;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The order in which a run's checks come ({@link RunRequest}): each case breaks two things, and the one
 * checked first is the one reported. Following the cases down is the order of precedence: the options,
 * each within its bounds, then the file they apply to. In the arguments, {@code SCENE} is a good scene,
 * {@code ABSENT} a file that does not exist, {@code NODIR} a folder that does not exist and {@code HERE}
 * one that does.
 */
class SimulateResumeCheckOrderTest {
    @TempDir
    Path dir;

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', quoteCharacter = '"', textBlock = """
            simulate SCENE --until 0 --threads 0                          | error: --until: must be a finite number > 0
            simulate SCENE --threads 0 --engine nope                      | error: --threads: must be from 1 to
            simulate SCENE --engine nope --seed-nodes h:1                 | : unknown engine 'nope'
            simulate SCENE --engine serial --seed-nodes h:1 --nodes 2     | error: --seed-nodes: only engine cluster
            simulate SCENE --engine serial --nodes 2 --option nope=1      | error: --nodes: only engine cluster
            simulate SCENE --engine fast --option nope=1 --report NODIR/r | error: --option nope: engine fast has no such option
            simulate SCENE --report NODIR/r --every -1                    | error: --report needs --observe LIST
            simulate SCENE --observe gr --trajectory NODIR/f.xyz          | error: --observe needs --report DIR
            simulate SCENE --trajectory NODIR/f.xyz --observe gr --report NODIR/r | error: --trajectory needs --every DT
            simulate SCENE --every -1 --checkpoint-every 1                | error: --every: must be a finite number > 0
            simulate SCENE --engine serial --every 1 --checkpoint-every 1 | error: --every: engine serial cannot stop at given times
            simulate SCENE --checkpoint-every 1 --out NODIR/f.csv         | error: --checkpoint-every needs --checkpoint FILE.ckpt
            simulate SCENE --checkpoint NODIR/c.ckpt --checkpoint-every 0 | error: --checkpoint-every: must be a finite number > 0
            simulate ABSENT --out NODIR/f.csv --summary NODIR/s.json      | error: --out: directory
            simulate ABSENT --summary NODIR/s.json --jfr NODIR/r.jfr      | error: --summary: directory
            simulate ABSENT --jfr NODIR/r.jfr --every 1 --trajectory NODIR/f.xyz | error: --jfr: directory
            simulate ABSENT --every 1 --trajectory NODIR/f.xyz --checkpoint NODIR/c.ckpt | error: --trajectory: directory
            simulate ABSENT --checkpoint NODIR/c.ckpt --observe gr --every 1 --report NODIR/r | error: --checkpoint: directory
            simulate ABSENT --out HERE/x --observe gr --every 1 --report HERE/x | error: --out and --report name the same path
            simulate ABSENT --observe nope --every 1 --report HERE/r      | ABSENT: cannot read the file
            simulate SCENE --observe nope --every 1 --report HERE/r       | error: --observe: unknown observable 'nope'
            resume ABSENT --until 0 --out NODIR/f.csv                     | error: --until: must be a finite number > 0
            resume ABSENT --out NODIR/f.csv --checkpoint-every 0          | error: --out: directory
            resume ABSENT --trajectory NODIR/f.xyz --report NODIR/r       | error: --trajectory: directory
            resume ABSENT --checkpoint NODIR/c.ckpt --report NODIR/r      | error: --checkpoint: directory
            resume ABSENT --report NODIR/r                                | error: --report: directory
            resume ABSENT --checkpoint-every 0                            | ABSENT: no such file
            """)
    void theFirstCheckThatFailsIsReported(String command, String firstLinePart) {
        Path scene = Scenes.write(dir, "head-on.json", Scenes.headOn());
        String[] args = Arrays.stream(command.split(" +"))
                .map(a -> a.replace("SCENE", scene.toString()).replace("ABSENT", dir.resolve("absent").toString())
                        .replace("NODIR", dir.resolve("no-such-folder").toString())
                        .replace("HERE", dir.toString()))
                .toArray(String[]::new);

        Cli r = Cli.run(args);

        assertThat(r.status()).as(r.err()).isEqualTo(Main.BAD_INPUT);
        assertThat(r.firstErrorLine()).contains(firstLinePart.replace("ABSENT", dir.resolve("absent").toString()));
    }
}
