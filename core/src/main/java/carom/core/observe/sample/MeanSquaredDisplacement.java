package carom.core.observe.sample;

import carom.core.scene.Species;
import java.io.IOException;
import java.io.Writer;
import java.util.List;

/**
 * The mean squared displacement against lag, from unwrapped positions, averaged over discs and time
 * origins ({@code msd.csv}: {@code lag,msd}, lag in the scene's time unit, msd in its length unit
 * squared). Samples come every {@code interval} of simulated time.
 *
 * <p>The unwrapping, the multiple-tau lags with decimation and the memory they take are
 * {@link DisplacementLadder}'s: every multiple of the interval up to p samples, then p/2 lags per
 * doubling, at most p + (levels - 1) p/2 stored configurations. Discs of species excluded by the mask
 * (fixed obstacles, say) are left out of the average. {@link SpeciesDisplacement} gives it per species
 * with error bars.
 */
public final class MeanSquaredDisplacement implements SampledObservable {
    public static final String KEY = "msd";
    public static final int DEFAULT_POINTS_PER_LEVEL = 8;
    public static final int DEFAULT_LEVELS = 16;
    private static final long LAYOUT = 1;

    private final DisplacementLadder ladder;

    private MeanSquaredDisplacement(DisplacementLadder ladder) {
        this.ladder = ladder;
    }

    /** Every disc counts, default lags. */
    public MeanSquaredDisplacement(double interval) {
        this(interval, DEFAULT_POINTS_PER_LEVEL, DEFAULT_LEVELS, null);
    }

    /**
     * @param interval        simulated time between samples (each sample must come that long after the last)
     * @param pointsPerLevel  p: lags 1 ... p samples exactly, then p/2 per doubling (even, at least 2)
     * @param levels          levels of the lag ladder; the longest lag is p 2^(levels-1) samples
     * @param includedSpecies which species count, by index; null for all
     */
    public MeanSquaredDisplacement(double interval, int pointsPerLevel, int levels, boolean[] includedSpecies) {
        this(new DisplacementLadder(KEY, interval, pointsPerLevel, levels, includedSpecies, null, 1, Double.NaN, false));
    }

    /** Only the mobile species of a scene count, default lags. */
    public static MeanSquaredDisplacement mobileDiscsOf(List<Species> species, double interval) {
        return new MeanSquaredDisplacement(interval, DEFAULT_POINTS_PER_LEVEL, DEFAULT_LEVELS, mobile(species));
    }

    /** Which of the species are mobile, by index. */
    static boolean[] mobile(List<Species> species) {
        boolean[] mobile = new boolean[species.size()];
        for (int s = 0; s < mobile.length; s++) {
            mobile[s] = !species.get(s).fixed();
        }
        return mobile;
    }

    @Override
    public String key() {
        return KEY;
    }

    @Override
    public void accept(Sample s) {
        ladder.accept(s);
    }

    public long samples() {
        return ladder.samples();
    }

    /** Steps (disc and sample) whose unwrapping may have gone wrong; 0 in a walled box. */
    public long suspectSteps() {
        return ladder.suspectSteps();
    }

    /** Configurations held now (each 2 doubles per counted disc). */
    public int storedConfigurations() {
        return ladder.storedConfigurations();
    }

    /** The most configurations ever held at once for these lags: p + (levels - 1) p/2, plus the newest. */
    public int maxStoredConfigurations() {
        return ladder.maxStoredConfigurations();
    }

    /** Lags measured so far (at least one time origin), in the scene's time unit, increasing. */
    public double[] lags() {
        return ladder.lags();
    }

    /** The mean squared displacement at each of {@link #lags()}. */
    public double[] values() {
        return ladder.values(0);
    }

    /** Time origins averaged at each of {@link #lags()}. */
    public long[] originCounts() {
        return ladder.originCounts();
    }

    @Override
    public void writeRows(Writer out) throws IOException {
        double[] lags = lags();
        double[] v = values();
        StringBuilder row = new StringBuilder(64);
        for (int k = 0; k < lags.length; k++) {
            row.setLength(0);
            row.append(lags[k]).append(',').append(v[k]).append('\n');
            out.append(row);
        }
    }

    @Override
    public ObservableState state() {
        StateCodec.Out out = new StateCodec.Out(LAYOUT);
        ladder.save(out);
        return out.state(KEY);
    }

    /** The observable {@code state} was saved from ({@link #state}), continuing exactly where it stopped. */
    public static MeanSquaredDisplacement restore(ObservableState state) {
        StateCodec.In in = new StateCodec.In(state, KEY, LAYOUT);
        MeanSquaredDisplacement msd = new MeanSquaredDisplacement(
                DisplacementLadder.restore(in, KEY, null, 1, Double.NaN, false));
        in.end();
        return msd;
    }
}
