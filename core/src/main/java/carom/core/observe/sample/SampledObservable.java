package carom.core.observe.sample;

import java.io.IOException;
import java.io.Writer;
import java.util.List;

/**
 * An observable computed on the fly from {@link Sample}s, one at a time, in bounded memory (what its
 * output needs, never the samples themselves). Each writes its CSV as SPEC fixes it and saves its
 * state for a checkpoint. Single-threaded: one writer feeds it.
 */
public sealed interface SampledObservable
        permits RadialDistribution, MeanSquaredDisplacement, BondOrder, PressureSeries {
    /** The keys {@code --observe} accepts, in the order reports list them. */
    List<String> KEYS = List.of(RadialDistribution.KEY, MeanSquaredDisplacement.KEY, BondOrder.KEY, PressureSeries.KEY);

    /** The name on the command line and of the CSV ({@code KEY.csv}) and plot. */
    String key();

    /** Takes the next sample; samples come in increasing time, all of the same discs in the same box. */
    void accept(Sample sample);

    /** {@code KEY.csv}: a header line, then one row per point, numbers as {@link Double#toString}. */
    void writeCsv(Writer out) throws IOException;

    /** Everything accumulated so far, for a checkpoint. */
    ObservableState state();

    /** The observable {@code state} was saved from, continuing exactly where it stopped. */
    static SampledObservable restore(ObservableState state) {
        return switch (state.key()) {
            case RadialDistribution.KEY -> RadialDistribution.restore(state);
            case MeanSquaredDisplacement.KEY -> MeanSquaredDisplacement.restore(state);
            case BondOrder.KEY -> BondOrder.restore(state);
            case PressureSeries.KEY -> PressureSeries.restore(state);
            default -> throw new IllegalArgumentException("unknown observable '" + state.key() + "'");
        };
    }
}
