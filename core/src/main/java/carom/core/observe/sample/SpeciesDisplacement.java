package carom.core.observe.sample;

import carom.core.scene.Species;
import java.io.IOException;
import java.io.Writer;
import java.util.List;

/**
 * Two observables of each mobile species' displacements against lag, with block-average error bars;
 * the lags, the unwrapping and their limits are those of {@link MeanSquaredDisplacement}
 * ({@link DisplacementLadder}), and a species without discs, or fixed, has no rows. Lags are in the
 * scene's time unit.
 * <ul>
 * <li>{@value #MSD_KEY}: the mean squared displacement ({@code msd-species.csv}:
 *     {@code species,lag,msd,error}, msd and its error in the length unit squared).</li>
 * <li>{@value #FS_KEY}: the self-intermediate scattering function F_s(k, t) = ⟨J₀(k |Δr(t)|)⟩, the mean
 *     of cos(k·Δr) over the directions of k, at one wave number k ({@code fs.csv}:
 *     {@code species,k,lag,Fs,error}, k in inverse length units). By default k is the position of the
 *     highest peak of S(k) for kσ in [2, 12] in the scene's starting state (the first peak of a
 *     liquid's), σ the mean diameter, from {@link StructureFactor}'s wave vectors in bins 0.1/σ wide;
 *     2π/σ in a walled box.</li>
 * </ul>
 *
 * <p>Errors: each lag's per-origin means of a species go into {@link BlockAverages} in time order, so
 * the error is the spread of block means of consecutive origins; at lags near the length of a block
 * (the run's length over 16 to 32) neighbouring origins overlap and the error is too small.
 */
public final class SpeciesDisplacement implements SampledObservable {
    public static final String MSD_KEY = "msd-species";
    public static final String FS_KEY = "fs";
    /** The window of kσ where the default k of F_s is looked for. */
    public static final double PEAK_FROM_SIGMA = 2;
    public static final double PEAK_TO_SIGMA = 12;
    /** Bins of S(k) the peak is looked for in, in units of 1/σ: one sample, so finer than S(k)'s own. */
    static final double PEAK_BIN_WIDTH_SIGMA = 0.1;
    private static final long LAYOUT = 1;

    private final String key;
    private final List<String> names;
    private final DisplacementLadder ladder;

    private SpeciesDisplacement(String key, List<String> names, DisplacementLadder ladder) {
        this.key = key;
        this.names = List.copyOf(names);
        this.ladder = ladder;
    }

    /** The mean squared displacement of each of a scene's species sampled every {@code interval}. */
    public static SpeciesDisplacement meanSquared(List<Species> species, double interval) {
        return of(MSD_KEY, species, interval, Double.NaN);
    }

    /** F_s(k, t) of each of a scene's species sampled every {@code interval}, at wave number {@code k} (> 0). */
    public static SpeciesDisplacement selfScattering(List<Species> species, double interval, double k) {
        if (!(k > 0) || Double.isInfinite(k)) {
            throw new IllegalArgumentException("the wave number must be positive and finite: " + k);
        }
        return of(FS_KEY, species, interval, k);
    }

    private static SpeciesDisplacement of(String key, List<Species> species, double interval, double k) {
        return new SpeciesDisplacement(key, species.stream().map(Species::name).toList(), new DisplacementLadder(key,
                interval, MeanSquaredDisplacement.DEFAULT_POINTS_PER_LEVEL, MeanSquaredDisplacement.DEFAULT_LEVELS,
                MeanSquaredDisplacement.mobile(species), identity(species.size()), species.size(), k, true));
    }

    /**
     * F_s's default wave number for discs starting as {@code start} does: the highest S(k) for kσ in
     * [{@value #PEAK_FROM_SIGMA}, {@value #PEAK_TO_SIGMA}] in a periodic box, else 2π/σ.
     */
    public static double firstPeak(Sample start, List<String> speciesNames) {
        double sigma = start.contactDistance();
        if (!(sigma > 0)) {
            throw new IllegalArgumentException("F_s needs discs of positive radius");
        }
        if (!start.box.periodic()) {
            return 2 * Math.PI / sigma;
        }
        StructureFactor sk = new StructureFactor(speciesNames, PEAK_TO_SIGMA, PEAK_BIN_WIDTH_SIGMA);
        sk.accept(start);
        double[] k = sk.k();
        double[] s = sk.s();
        double best = 2 * Math.PI / sigma;
        double highest = Double.NEGATIVE_INFINITY;
        for (int m = 0; m < k.length; m++) {
            if (k[m] * sigma >= PEAK_FROM_SIGMA && s[m] > highest) {
                highest = s[m];
                best = k[m];
            }
        }
        return best;
    }

    private static int[] identity(int n) {
        int[] g = new int[n];
        for (int s = 0; s < n; s++) {
            g[s] = s;
        }
        return g;
    }

    @Override
    public String key() {
        return key;
    }

    @Override
    public void accept(Sample s) {
        ladder.accept(s);
    }

    public long samples() {
        return ladder.samples();
    }

    public List<String> speciesNames() {
        return names;
    }

    /** F_s's wave number (NaN for the mean squared displacement). */
    public double waveNumber() {
        return ladder.waveNumber();
    }

    /** Discs of species {@code a} counted (0 for a fixed species or before the first sample). */
    public int discs(int a) {
        return ladder.groupCount(a);
    }

    /** Lags measured so far, in the scene's time unit. */
    public double[] lags() {
        return ladder.lags();
    }

    /** The mean squared displacement, or F_s, of species {@code a} at each of {@link #lags()}. */
    public double[] values(int a) {
        return ladder.values(a);
    }

    /** The standard error of {@link #values}(a). */
    public double[] errors(int a) {
        return ladder.errors(a);
    }

    @Override
    public void writeRows(Writer out) throws IOException {
        double[] lags = lags();
        boolean scattering = key.equals(FS_KEY);
        StringBuilder row = new StringBuilder(80);
        for (int a = 0; a < names.size(); a++) {
            if (discs(a) == 0) {
                continue;
            }
            String name = CsvCells.of(names.get(a));
            double[] v = values(a);
            double[] e = errors(a);
            for (int k = 0; k < lags.length; k++) {
                row.setLength(0);
                row.append(name).append(',');
                if (scattering) {
                    row.append(waveNumber()).append(',');
                }
                row.append(lags[k]).append(',').append(v[k]).append(',').append(e[k]).append('\n');
                out.append(row);
            }
        }
    }

    @Override
    public ObservableState state() {
        StateCodec.Out out = new StateCodec.Out(LAYOUT).put(names.size());
        names.forEach(out::put);
        out.put(ladder.waveNumber());
        ladder.save(out);
        ladder.saveGroups(out);
        return out.state(key);
    }

    /** The {@value #MSD_KEY} observable {@code state} was saved from, continuing exactly where it stopped. */
    public static SpeciesDisplacement restoreMeanSquared(ObservableState state) {
        return restore(state, MSD_KEY);
    }

    /** The {@value #FS_KEY} observable {@code state} was saved from, continuing exactly where it stopped. */
    public static SpeciesDisplacement restoreSelfScattering(ObservableState state) {
        return restore(state, FS_KEY);
    }

    private static SpeciesDisplacement restore(ObservableState state, String key) {
        StateCodec.In in = new StateCodec.In(state, key, LAYOUT);
        int species = in.nextSize();
        String[] names = new String[species];
        for (int a = 0; a < species; a++) {
            names[a] = in.nextString();
        }
        double k = in.nextDouble();
        if (species == 0 || key.equals(FS_KEY) != !Double.isNaN(k)) {
            throw new IllegalArgumentException(key + " state: no species, or a wave number that does not fit");
        }
        SpeciesDisplacement observable = new SpeciesDisplacement(key, List.of(names),
                DisplacementLadder.restore(in, key, identity(species), species, k, true));
        in.end();
        return observable;
    }
}
