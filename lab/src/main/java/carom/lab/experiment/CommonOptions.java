package carom.lab.experiment;

import carom.core.BadInputException;
import carom.engines.EngineCatalog;
import carom.lab.run.Machine;
import java.nio.file.Path;
import java.util.List;
import picocli.CommandLine.Option;

/**
 * Options both experiments take. Those whose default depends on {@code --quick} are null when not
 * given; each command resolves them.
 */
final class CommonOptions {
    @Option(names = "--out", paramLabel = "DIR", required = true,
            description = "Folder to write (report.md, CSV tables, PNG and SVG plots); must not exist yet, or be empty. "
                    + "Required: nothing is written where it was not asked for.")
    Path out;

    @Option(names = "--trials", paramLabel = "T", description = "Seeded trials per configuration.")
    Integer trials;

    @Option(names = "--seed", paramLabel = "S", defaultValue = "1",
            description = "Seed of trial 1; trial t uses S + t - 1 (default ${DEFAULT-VALUE}).")
    long seed;

    @Option(names = "--heap", paramLabel = "SIZE",
            description = "Maximum heap of each child JVM, as -Xmx takes it (for example 12g); default: half the machine's memory. "
                    + "A size that does not fit is skipped with a note.")
    String heap;

    @Option(names = "--warmup", paramLabel = "N",
            description = "Discs of each child JVM's unmeasured warm-up run, 0 for none (default 10000, at most the largest size; --quick: 0).")
    Integer warmup;

    @Option(names = "--quick", description = "Under half a minute, even on a busy machine: tiny sizes, every engine, no warm-up, "
            + "the runs in this JVM where they can be. To try the command, not to measure.")
    boolean quick;

    @Option(names = "--require-quiet", description = "Refuse to start (error, exit status 2) when the one-minute load average "
            + "is " + Machine.QUIET_LOAD + " or more: another process would share the cores. Without it such a run goes ahead "
            + "and its report says the machine was shared.")
    boolean requireQuiet;

    /** {@code given} if not null, else the quick or the full default. */
    static <T> T resolve(T given, boolean quick, T quickDefault, T fullDefault) {
        return given != null ? given : quick ? quickDefault : fullDefault;
    }

    String heap() {
        String h = heap == null ? Machine.defaultHeap() : heap.strip();
        if (!h.matches("[1-9][0-9]*[kKmMgGtT]?")) {
            throw new BadInputException("--heap: '" + heap + "' is not a heap size (give one like 12g or 8000m)");
        }
        return h;
    }

    int trials(int quickDefault, int fullDefault) {
        return atLeast(resolve(trials, quick, quickDefault, fullDefault), 1, "--trials");
    }

    int warmup(int quickDefault, int fullDefault) {
        return atLeast(resolve(warmup, quick, quickDefault, fullDefault), 0, "--warmup");
    }

    static int atLeast(int value, int min, String option) {
        if (value < min) {
            throw new BadInputException(option + ": must be at least " + min + ", got " + value);
        }
        return value;
    }

    /** A list option's values, each at least {@code min}, none twice, in the given order. */
    static List<Integer> checkedList(List<Integer> values, int min, String option) {
        if (values.isEmpty()) {
            throw new BadInputException(option + ": give at least one value");
        }
        for (int v : values) {
            atLeast(v, min, option);
        }
        if (values.stream().distinct().count() != values.size()) {
            throw new BadInputException(option + ": a value is given twice in " + values);
        }
        return List.copyOf(values);
    }

    /** Engine names, each known ({@code EngineCatalog} says which exist), none twice. */
    static List<String> checkedEngines(List<String> names) {
        if (names.isEmpty()) {
            throw new BadInputException("--engines: give at least one engine");
        }
        for (String name : names) {
            try {
                EngineCatalog.byName(name.strip());
            } catch (BadInputException e) {
                throw new BadInputException("--engines: " + e.getMessage());
            }
        }
        List<String> stripped = names.stream().map(String::strip).toList();
        if (stripped.stream().distinct().count() != stripped.size()) {
            throw new BadInputException("--engines: an engine is named twice in " + String.join(",", stripped));
        }
        return stripped;
    }

}
