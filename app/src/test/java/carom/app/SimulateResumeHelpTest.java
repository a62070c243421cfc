package carom.app;

import static org.assertj.core.api.Assertions.assertThat;

import carom.app.report.ObservableKeys;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** The help of simulate and resume: options they share are declared once, and each command words them as it means them. */
class SimulateResumeHelpTest {
    @Test
    void observeListsTheObservablesOfTheRegistry() {
        List<String> keys = new ArrayList<>();
        new ObservableKeys().forEach(keys::add);
        assertThat(keys).isNotEmpty();

        assertThat(helpOf("simulate")).contains("--observe=LIST Observables computed at every sample, comma-separated: "
                + String.join(", ", keys) + "; needs --every or --observe-every, and --report.");
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', quoteCharacter = '"', textBlock = """
            --until=T              | Simulated end time, overriding the scene's.                                   | Simulated end time, overriding the run's; not before the checkpoint's time.
            --report=DIR           | Folder (new or empty) for the observables: KEY.csv and KEY.png each           | Folder (new or empty) for the observables the run had (--observe), accumulated over the whole run.
            "--trajectory=FRAMES.xyz|FRAMES.gsd" | Write every sample as a frame: extended XYZ (OVITO, ASE), or GSD for a name ending in .gsd (gsd, freud, MDAnalysis, OVITO, HOOMD-blue); needs --every or --trajectory-every. | Write the samples from the checkpoint on as frames (extended XYZ, or GSD for a name ending in .gsd); the run must have had --every.
            --checkpoint=FILE.ckpt | Save the run here at its end, every --checkpoint-every                         | Write checkpoints of the continued run here.
            --checkpoint-every=DT  | Simulated time between checkpoints (each replaces the previous one); needs --checkpoint. | Simulated time between checkpoints; default: the checkpoint's interval.
            """)
    void resumeWordsASharedOptionForAContinuedRun(String option, String simulateWords, String resumeWords) {
        String simulate = helpOf("simulate");
        String resume = helpOf("resume");

        assertThat(simulate).contains(option + " " + simulateWords).doesNotContain(resumeWords);
        assertThat(resume).contains(option + " " + resumeWords).doesNotContain(simulateWords);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', quoteCharacter = '"', textBlock = """
            --out=FINAL.csv        | Write the final state here (id,x,y,vx,vy).
            --summary=SUMMARY.json | Write the run's summary here as JSON.
            --out-state=STATE.json | Write the final state here as a scene (box, species, effects, until and every disc with its velocity and radius)
            """)
    void bothCommandsWordAnOutputOptionAlike(String option, String words) {
        for (String command : List.of("simulate", "resume")) {
            assertThat(helpOf(command)).as(command).containsOnlyOnce(option + " " + words);
        }
    }

    /** The command's help with picocli's line wrapping undone: runs of white space as one space. */
    private static String helpOf(String command) {
        Cli help = Cli.run(command, "--help");
        assertThat(help.status()).isZero();
        return help.out().replaceAll("\\s+", " ");
    }
}
