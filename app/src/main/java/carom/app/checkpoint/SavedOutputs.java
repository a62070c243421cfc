package carom.app.checkpoint;

import java.util.ArrayList;
import java.util.List;

/**
 * The outputs a checkpointed run was asked for, as absolute paths (null: not asked for), so that
 * {@code carom resume FILE.ckpt} alone writes them wherever it is run from: the final state
 * ({@code --out}), the summary, the trajectory, the report folder and the state file
 * ({@code --out-state}).
 */
public record SavedOutputs(String out, String summary, String trajectory, String report, String outState) {
    /** What a checkpoint of format version 1, which kept no outputs, stands for. */
    public static final SavedOutputs NONE = new SavedOutputs(null, null, null, null, null);

    public boolean none() {
        return equals(NONE);
    }

    /** The options and paths, as a command line would name them ({@code --out /a/final.csv}), in order. */
    public List<String> asOptions() {
        List<String> options = new ArrayList<>();
        add(options, "--out", out);
        add(options, "--summary", summary);
        add(options, "--trajectory", trajectory);
        add(options, "--report", report);
        add(options, "--out-state", outState);
        return options;
    }

    private static void add(List<String> options, String option, String path) {
        if (path != null) {
            options.add(option + " " + path);
        }
    }
}
