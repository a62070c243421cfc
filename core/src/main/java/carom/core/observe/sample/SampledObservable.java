package carom.core.observe.sample;

import java.io.IOException;
import java.io.Writer;

/**
 * An observable computed on the fly from {@link Sample}s, one at a time, in bounded memory (what its
 * output needs, never the samples themselves). It writes the rows of its table and saves its state for
 * a checkpoint; its key, the table's columns and how it is made, restored and plotted are said once, in
 * its descriptor in the command line's registry of observables. Single-threaded: one writer feeds it.
 *
 * <p>An implementation also has a {@code public static restore(ObservableState)} that rebuilds it from
 * {@link #state()}, continuing bit for bit, and refuses a state of another key or layout.
 */
public interface SampledObservable {
    /** The observable's name: on the command line, of its table ({@code KEY.csv}) and plot, and of its state. */
    String key();

    /** Takes the next sample; samples come in increasing time, all of the same discs in the same box. */
    void accept(Sample sample);

    /**
     * The rows of {@code KEY.csv} (the header line is its descriptor's): one line per point, values
     * comma-separated as {@link Double#toString} (or {@link Long#toString} for counts) writes them.
     */
    void writeRows(Writer out) throws IOException;

    /** Everything accumulated so far, for a checkpoint. */
    ObservableState state();
}
