package carom.core.observe.sample;

import java.io.IOException;
import java.io.Writer;
import java.util.List;

/**
 * The static structure factor S(k) and the partial S_ab(k) of every pair of species a ≤ b, by direct
 * sums over wave vectors of the periodic box, binned by |k| and averaged over samples with
 * block-average error bars ({@code sk.csv}: {@code a,b,k,S,error}; rows of the total S(k) have a and b
 * empty, k is the bin centre in inverse length units).
 *
 * <p>Definitions, with ρ_a(k) = Σ_{j of species a} exp(i k·r_j) and ρ = Σ_a ρ_a:
 * S(k) = |ρ(k)|² / N, and S_ab(k) = Re[ρ_a(k) ρ_b(k)*] / √(N_a N_b) (Ashcroft-Langreth: S_aa → 1 and
 * S_ab → 0 at large k; S(k) = Σ_ab √(x_a x_b) S_ab(k) over ordered pairs, x the number fractions).
 *
 * <p>Wave vectors: those of the box, k = 2π (n_x / W, n_y / H), taken along the eight lattice
 * directions (n_x, n_y) ∝ (1, 0), (0, 1), (1, ±1), (1, ±2), (2, ±1) (k and -k give the same |ρ|², so
 * half the plane suffices). Along a direction whose shortest vector k₁ is shorter than the bin width,
 * every m-th multiple is taken, m = ⌊bin width / k₁⌋, so the vectors are about a bin width apart; up
 * to {@code kMax}. Bins: width {@code binWidth}, from 0; bin centres. The sums of a ray are
 * {@link RaySums}: by recurrence from exp(i m k₁·r) (one sine and cosine per disc and direction, then a
 * complex multiplication per disc and vector) for short rays, and for long ones, which a large box
 * has, by gridding: a one-dimensional non-uniform FFT of the discs' phases along the ray (Taylor
 * moments about a grid's points, then FFTs of the grid: about 40 operations per disc and direction
 * whatever the number of vectors, to about 1e-14 of N). An isotropic fluid's S(k) is the same along every direction; a crystal's Bragg peaks show only
 * where a direction meets them.
 *
 * <p>Defaults: bins 0.2/σ wide up to k = 20/σ, σ the first sample's mean diameter (the vectors along a
 * direction are a bin apart, so a bin holds about one per direction whatever its width: wider bins cost
 * less and are as precise). Needs a periodic
 * box (walls are not translation-invariant, and the wave vectors are the periodic box's).
 */
public final class StructureFactor implements SampledObservable {
    public static final String KEY = "sk";
    /** kMax in units of 1/σ when not given. */
    public static final double DEFAULT_K_MAX_SIGMA = 20;
    /** Bin width in units of 1/σ. */
    public static final double DEFAULT_BIN_WIDTH_SIGMA = 0.2;
    private static final int[][] DIRECTIONS = {{1, 0}, {0, 1}, {1, 1}, {1, -1}, {1, 2}, {1, -2}, {2, 1}, {2, -1}};
    private static final long LAYOUT = 1;

    private final List<String> names;
    /** In units of 1/σ (σ fixed by the first sample). */
    private final double kMaxSigma;
    private final double binWidthSigma;

    // Fixed by the first sample.
    private int discs = -1;
    private double width;
    private double height;
    private SpeciesCensus census;
    private double sigma;
    private double binWidth;
    private int bins;
    /** Per direction: the step vector (m k₁) and how many multiples of it are taken. */
    private double[] stepX = new double[0];
    private double[] stepY = new double[0];
    private int[] steps = new int[0];
    /** Per direction: its sums, by recurrence or gridding. */
    private RaySums[] rays = new RaySums[0];
    /** Per vector (directions one after the other): its bin. */
    private int[] binOf = new int[0];
    private int[] vectorsInBin = new int[0];
    /** Pairs of species with discs: (a, b) per pair, a ≤ b. */
    private int[] pairA = new int[0];
    private int[] pairB = new int[0];

    // Scratch of one sample: ρ_a per species and vector.
    private double[] rhoRe = new double[0];
    private double[] rhoIm = new double[0];
    private double[] sampleValues = new double[0];
    private BlockAverages averages = new BlockAverages(0);

    /** For a scene's species, by name in index order, with the default bins. */
    public StructureFactor(List<String> speciesNames) {
        this(speciesNames, DEFAULT_K_MAX_SIGMA, DEFAULT_BIN_WIDTH_SIGMA);
    }

    /**
     * @param kMaxSigma     the largest |k| taken, times σ
     * @param binWidthSigma bins' width in |k|, times σ
     */
    public StructureFactor(List<String> speciesNames, double kMaxSigma, double binWidthSigma) {
        if (!(kMaxSigma > 0) || !(binWidthSigma > 0) || Double.isInfinite(kMaxSigma) || speciesNames.isEmpty()
                || kMaxSigma / binWidthSigma > 1e6) {
            throw new IllegalArgumentException("kMax and the bin width must be positive and finite, at most 1e6 bins");
        }
        this.names = List.copyOf(speciesNames);
        this.kMaxSigma = kMaxSigma;
        this.binWidthSigma = binWidthSigma;
    }

    @Override
    public String key() {
        return KEY;
    }

    @Override
    public void accept(Sample s) {
        if (!s.box.periodic()) {
            throw new IllegalArgumentException("S(k) needs a periodic box");
        }
        if (discs < 0) {
            setUp(s.n, s.box.width(), s.box.height(), SpeciesCensus.of(s, names.size()), s.contactDistance());
            averages = new BlockAverages((1 + pairA.length) * bins);
        } else if (s.n != discs || s.box.width() != width || s.box.height() != height) {
            throw new IllegalArgumentException("S(k): a sample of other discs or another box");
        }
        computeDensities(s);
        binSample();
        averages.add(sampleValues);
    }

    private void setUp(int n, double w, double h, SpeciesCensus c, double contact) {
        discs = n;
        width = w;
        height = h;
        census = c;
        sigma = contact;
        binWidth = contact > 0 ? binWidthSigma / contact : 0;
        double kMax = contact > 0 ? kMaxSigma / contact : 0;
        bins = binWidth > 0 ? (int) Math.ceil(kMax / binWidth) : 0;
        int d = DIRECTIONS.length;
        stepX = new double[d];
        stepY = new double[d];
        steps = new int[d];
        int vectors = 0;
        for (int k = 0; k < d; k++) {
            double kx = 2 * Math.PI * DIRECTIONS[k][0] / w;
            double ky = 2 * Math.PI * DIRECTIONS[k][1] / h;
            double k1 = Math.hypot(kx, ky);
            int m = bins == 0 ? 1 : Math.max(1, (int) Math.floor(binWidth / k1));
            stepX[k] = m * kx;
            stepY[k] = m * ky;
            steps[k] = bins == 0 ? 0 : (int) Math.floor(kMax / (m * k1));
            vectors += steps[k];
        }
        binOf = new int[vectors];
        vectorsInBin = new int[bins];
        int v = 0;
        for (int k = 0; k < d; k++) {
            double step = Math.hypot(stepX[k], stepY[k]);
            for (int j = 1; j <= steps[k]; j++) {
                int bin = Math.min(bins - 1, (int) (j * step / binWidth));
                binOf[v++] = bin;
                vectorsInBin[bin]++;
            }
        }
        int species = c.species();
        int[] a = new int[species * (species + 1) / 2];
        int[] b = new int[a.length];
        int pairs = 0;
        for (int i = 0; i < species; i++) {
            for (int j = i; j < species; j++) {
                if (c.counts()[i] > 0 && c.counts()[j] > 0) {
                    a[pairs] = i;
                    b[pairs++] = j;
                }
            }
        }
        pairA = java.util.Arrays.copyOf(a, pairs);
        pairB = java.util.Arrays.copyOf(b, pairs);
        rays = new RaySums[d];
        for (int k = 0; k < d; k++) {
            rays[k] = RaySums.of(stepX[k], stepY[k], steps[k], species, n);
        }
        rhoRe = new double[species * vectors];
        rhoIm = new double[species * vectors];
        sampleValues = new double[(1 + pairs) * bins];
    }

    /** ρ_a(k) of every species and vector, ray by ray ({@link RaySums}: by recurrence or by gridding). */
    private void computeDensities(Sample s) {
        int vectors = binOf.length;
        java.util.Arrays.fill(rhoRe, 0);
        java.util.Arrays.fill(rhoIm, 0);
        int offset = 0;
        for (RaySums ray : rays) {
            ray.addTo(s, rhoRe, rhoIm, offset, vectors);
            offset += ray.steps;
        }
    }

    /** This sample's bin means: the total S first, then each pair's S_ab. */
    private void binSample() {
        java.util.Arrays.fill(sampleValues, 0);
        int vectors = binOf.length;
        int species = census.species();
        for (int v = 0; v < vectors; v++) {
            double tr = 0;
            double ti = 0;
            for (int a = 0; a < species; a++) {
                tr += rhoRe[a * vectors + v];
                ti += rhoIm[a * vectors + v];
            }
            int bin = binOf[v];
            double weight = 1.0 / vectorsInBin[bin];
            sampleValues[bin] += (tr * tr + ti * ti) / discs * weight;
            for (int p = 0; p < pairA.length; p++) {
                int a = pairA[p] * vectors + v;
                int b = pairB[p] * vectors + v;
                double norm = Math.sqrt((double) census.counts()[pairA[p]] * census.counts()[pairB[p]]);
                sampleValues[(1 + p) * bins + bin] += (rhoRe[a] * rhoRe[b] + rhoIm[a] * rhoIm[b]) / norm * weight;
            }
        }
    }

    public long samples() {
        return averages.samples();
    }

    /** The wave vectors taken, for tests: per vector its kx, ky and bin, directions one after the other. */
    double[][] waveVectors() {
        double[][] v = new double[3][binOf.length];
        int m = 0;
        for (int d = 0; d < steps.length; d++) {
            for (int j = 1; j <= steps[d]; j++) {
                v[0][m] = j * stepX[d];
                v[1][m] = j * stepY[d];
                v[2][m] = binOf[m];
                m++;
            }
        }
        return v;
    }

    /** How many of the directions are summed by gridding (the others by recurrence), for tests. */
    int griddedRays() {
        return (int) java.util.Arrays.stream(rays).filter(r -> r.gridded).count();
    }

    /** Bin centres that hold at least one wave vector, in inverse length units. */
    public double[] k() {
        double[] k = new double[bins];
        int n = 0;
        for (int bin = 0; bin < bins; bin++) {
            if (vectorsInBin[bin] > 0) {
                k[n++] = (bin + 0.5) * binWidth;
            }
        }
        return java.util.Arrays.copyOf(k, n);
    }

    /** Wave vectors in each bin of {@link #k()}. */
    public int[] vectors() {
        return java.util.Arrays.stream(vectorsInBin).filter(c -> c > 0).toArray();
    }

    /** σ of the bins' units: the first sample's mean diameter (NaN before it). */
    public double contactDistance() {
        return discs < 0 ? Double.NaN : sigma;
    }

    /** Pairs of species with discs, as in {@link PartialRadialDistribution#pairs()}. */
    public int pairs() {
        return pairA.length;
    }

    public int speciesA(int p) {
        return pairA[p];
    }

    public int speciesB(int p) {
        return pairB[p];
    }

    public List<String> speciesNames() {
        return names;
    }

    /** S(k) at each of {@link #k()}, the mean over samples. */
    public double[] s() {
        return column(0, false);
    }

    /** The standard error of {@link #s()}, from block averages. */
    public double[] errors() {
        return column(0, true);
    }

    /** S_ab(k) of pair {@code p} at each of {@link #k()}. */
    public double[] partial(int p) {
        return column(1 + p, false);
    }

    /** The standard error of {@link #partial}. */
    public double[] partialErrors(int p) {
        return column(1 + p, true);
    }

    private double[] column(int block, boolean error) {
        double[] c = new double[bins];
        int n = 0;
        for (int bin = 0; bin < bins; bin++) {
            if (vectorsInBin[bin] > 0) {
                int k = block * bins + bin;
                c[n++] = error ? averages.error(k) : averages.mean(k);
            }
        }
        return java.util.Arrays.copyOf(c, n);
    }

    @Override
    public void writeRows(Writer out) throws IOException {
        double[] k = k();
        StringBuilder row = new StringBuilder(96);
        for (int block = 0; block <= pairs(); block++) {
            String a = block == 0 ? "" : CsvCells.of(names.get(pairA[block - 1]));
            String b = block == 0 ? "" : CsvCells.of(names.get(pairB[block - 1]));
            double[] s = column(block, false);
            double[] e = column(block, true);
            for (int m = 0; m < k.length; m++) {
                row.setLength(0);
                row.append(a).append(',').append(b).append(',').append(k[m]).append(',').append(s[m]).append(',')
                        .append(e[m]).append('\n');
                out.append(row);
            }
        }
    }

    @Override
    public ObservableState state() {
        StateCodec.Out out = new StateCodec.Out(LAYOUT).put(names.size());
        names.forEach(out::put);
        out.put(kMaxSigma).put(binWidthSigma).put(discs);
        if (discs >= 0) {
            out.put(width).put(height).put(contactDistance());
            census.save(out);
            averages.save(out);
        }
        return out.state(KEY);
    }

    /** The observable {@code state} was saved from ({@link #state}), continuing exactly where it stopped. */
    public static StructureFactor restore(ObservableState state) {
        StateCodec.In in = new StateCodec.In(state, KEY, LAYOUT);
        int species = in.nextSize();
        String[] names = new String[species];
        for (int a = 0; a < species; a++) {
            names[a] = in.nextString();
        }
        StructureFactor sk = new StructureFactor(List.of(names), in.nextDouble(), in.nextDouble());
        int n = in.nextInt();
        if (n >= 0) {
            double w = in.nextDouble();
            double h = in.nextDouble();
            double sigma = in.nextDouble();
            SpeciesCensus census = SpeciesCensus.restore(in);
            if (census.species() != species) {
                throw new IllegalArgumentException("S(k) state: a census of " + census.species() + " species for " + species);
            }
            sk.setUp(n, w, h, census, sigma);
            sk.averages = BlockAverages.restore(in);
            if (sk.averages.width() != (1 + sk.pairs()) * sk.bins) {
                throw new IllegalArgumentException("S(k) state: values of another geometry");
            }
        }
        in.end();
        return sk;
    }
}
