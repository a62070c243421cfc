package carom.core.observe.sample;

import java.io.IOException;
import java.io.Writer;
import java.util.List;

/**
 * The partial radial distribution functions g_ab(r) of every pair of species a ≤ b, each against its
 * own contact distance σ_ab = R̄_a + R̄_b (R̄ a species' mean radius in the first sample), averaged over
 * samples with block-average error bars ({@code gab.csv}: {@code a,b,sigma,r,g,error}, a and b the
 * species names, r the bin centre in the scene's length unit, error the standard error of g).
 *
 * <p>Bins of pair (a, b): width σ_ab / {@code binsPerContact} (default 50) from r = 0, up to
 * {@code rangeInContacts} σ_ab (default 5) or half the shorter side the centres can span, whichever is
 * smaller; contact falls on the lower edge of bin {@code binsPerContact}. A pair of species with no
 * pair of discs (no disc, or one disc of a species with itself) has no rows. With one species this is
 * the total g(r) of {@link RadialDistribution} (the same bins and normalisation) with block errors.
 *
 * <p>Normalisation: each sample's count in a bin over the ideal count, what uniform independent
 * centres would put there: P_ab · A_shell / (W H) in a periodic box, P_ab = N_a N_b (a ≠ b) or
 * N_a (N_a - 1) / 2; between walls P_ab times the probability that the separation of a uniform centre
 * of a in its reachable rectangle (W - 2 a_min) x (H - 2 a_min) and one of b in its own falls in the
 * shell, a_min the species' smallest radius: the separation density is the product of two trapezoids
 * (the convolution of the two rectangles' sides), integrated over the shell by quadrature (two
 * Gauss-Legendre points across the bin, 256 midpoints over a quarter turn; relative error below 1e-6).
 *
 * <p>Errors: each bin's per-sample g goes into {@link BlockAverages}, so the error is the spread of
 * block means (honest once a block spans several correlation times of the structure).
 */
public final class PartialRadialDistribution implements SampledObservable {
    public static final String KEY = "gab";
    private static final long LAYOUT = 1;
    private static final int QUARTER_TURN_POINTS = 256;

    private final List<String> names;
    private final double rangeInContacts;
    private final int binsPerContact;
    private final NeighbourScan scan = new NeighbourScan();

    // Geometry, fixed by the first sample.
    private int discs = -1;
    private double width;
    private double height;
    private boolean periodic;
    private SpeciesCensus census;
    private int[] classA = new int[0];
    private int[] classB = new int[0];
    private double[] sigma = new double[0];
    private double[] ideal = new double[0];
    private NeighbourScan.PairBins binning;
    private double cutoff;
    private int totalBins;
    private int[] sampleCounts = new int[0];
    private double[] sampleG = new double[0];
    private BlockAverages averages = new BlockAverages(0);

    /** For a scene's species, by name in index order; default bins (50 per contact, to 5 contacts). */
    public PartialRadialDistribution(List<String> speciesNames) {
        this(speciesNames, RadialDistribution.DEFAULT_RANGE_IN_CONTACTS, RadialDistribution.DEFAULT_BINS_PER_CONTACT);
    }

    public PartialRadialDistribution(List<String> speciesNames, double rangeInContacts, int binsPerContact) {
        if (!(rangeInContacts > 0) || binsPerContact < 1 || speciesNames.isEmpty()) {
            throw new IllegalArgumentException("range and bins per contact must be positive, and species named");
        }
        this.names = List.copyOf(speciesNames);
        this.rangeInContacts = rangeInContacts;
        this.binsPerContact = binsPerContact;
    }

    @Override
    public String key() {
        return KEY;
    }

    @Override
    public void accept(Sample s) {
        if (discs < 0) {
            setUp(s.n, s.box.width(), s.box.height(), s.box.periodic(), SpeciesCensus.of(s, names.size()));
            averages = new BlockAverages(totalBins);
        } else if (s.n != discs || s.box.width() != width || s.box.height() != height || s.box.periodic() != periodic) {
            throw new IllegalArgumentException("g_ab(r): a sample of other discs or another box");
        }
        java.util.Arrays.fill(sampleCounts, 0);
        if (totalBins > 0) {
            scan.histogram(s, cutoff, binning, sampleCounts);
        }
        for (int k = 0; k < totalBins; k++) {
            sampleG[k] = sampleCounts[k] / ideal[k];
        }
        averages.add(sampleG);
    }

    private void setUp(int n, double w, double h, boolean isPeriodic, SpeciesCensus c) {
        discs = n;
        width = w;
        height = h;
        periodic = isPeriodic;
        census = c;
        int species = c.species();
        int[] classOf = new int[species * species];
        int classes = 0;
        int[] a = new int[species * (species + 1) / 2];
        int[] b = new int[a.length];
        for (int i = 0; i < species; i++) {
            for (int j = i; j < species; j++) {
                if (c.counts()[i] > 0 && c.counts()[j] > 0) {
                    classOf[i * species + j] = classes;
                    classOf[j * species + i] = classes;
                    a[classes] = i;
                    b[classes++] = j;
                }
            }
        }
        classA = java.util.Arrays.copyOf(a, classes);
        classB = java.util.Arrays.copyOf(b, classes);
        sigma = new double[classes];
        double[] perWidth = new double[classes];
        int[] bins = new int[classes];
        int[] offset = new int[classes];
        totalBins = 0;
        cutoff = 0;
        for (int k = 0; k < classes; k++) {
            int i = classA[k];
            int j = classB[k];
            sigma[k] = c.meanRadius()[i] + c.meanRadius()[j];
            double pairs = i == j ? 0.5 * c.counts()[i] * (c.counts()[i] - 1.0) : (double) c.counts()[i] * c.counts()[j];
            double binWidth = sigma[k] / binsPerContact;
            double range = Math.min(rangeInContacts * sigma[k], 0.5 * Math.min(reach(w, i, j), reach(h, i, j)));
            bins[k] = pairs == 0 || !(range > 0) || !(binWidth > 0) ? 0 : (int) Math.floor(range / binWidth);
            perWidth[k] = bins[k] == 0 ? 0 : 1 / binWidth;
            offset[k] = totalBins;
            totalBins += bins[k];
            cutoff = Math.max(cutoff, bins[k] * binWidth);
        }
        binning = new NeighbourScan.PairBins(species, classOf, perWidth, bins, offset);
        ideal = new double[totalBins];
        for (int k = 0; k < classes; k++) {
            int i = classA[k];
            int j = classB[k];
            double pairs = i == j ? 0.5 * c.counts()[i] * (c.counts()[i] - 1.0) : (double) c.counts()[i] * c.counts()[j];
            double binWidth = sigma[k] / binsPerContact;
            for (int m = 0; m < bins[k]; m++) {
                double r1 = m * binWidth;
                double r2 = (m + 1) * binWidth;
                ideal[offset[k] + m] = periodic ? pairs * Math.PI * (r2 * r2 - r1 * r1) / (w * h)
                        : pairs * wallShell(r1, r2, w - 2 * c.minRadius()[i], h - 2 * c.minRadius()[i],
                                w - 2 * c.minRadius()[j], h - 2 * c.minRadius()[j]);
            }
        }
        sampleCounts = new int[totalBins];
        sampleG = new double[totalBins];
    }

    /** The side the separations of centres of species i and j can span without wrapping: the narrower reach. */
    private double reach(double side, int i, int j) {
        return periodic ? side : side - 2 * Math.max(census.minRadius()[i], census.minRadius()[j]);
    }

    /**
     * The probability that a uniform point of a w1 x h1 rectangle and one of a concentric w2 x h2 one are
     * between r1 and r2 apart (r2 at most half the smaller sides).
     */
    static double wallShell(double r1, double r2, double w1, double h1, double w2, double h2) {
        // Two-point Gauss-Legendre across [r1, r2] of r·∫f(r cos θ, r sin θ) dθ; f is even in both arguments.
        double mid = 0.5 * (r1 + r2);
        double half = 0.5 * (r2 - r1);
        double offset = half / Math.sqrt(3);
        double sum = 0;
        for (double r : new double[] {mid - offset, mid + offset}) {
            double angular = 0;
            for (int q = 0; q < QUARTER_TURN_POINTS; q++) {
                double theta = (q + 0.5) * (0.5 * Math.PI / QUARTER_TURN_POINTS);
                angular += separationDensity(r * Math.cos(theta), w1, w2) * separationDensity(r * Math.sin(theta), h1, h2);
            }
            sum += r * angular * (0.5 * Math.PI / QUARTER_TURN_POINTS) * 4;
        }
        return sum * half;
    }

    /** Density of u = x2 - x1 for x1, x2 uniform on centred intervals of lengths l1 and l2: a trapezoid. */
    private static double separationDensity(double u, double l1, double l2) {
        double overlap = Math.min(Math.min(l1, l2), 0.5 * (l1 + l2) - Math.abs(u));
        return Math.max(0, overlap) / (l1 * l2);
    }

    public long samples() {
        return averages.samples();
    }

    /** Pairs of species with rows, in order: (0, 0), (0, 1), ..., (1, 1), ... of those that have discs. */
    public int pairs() {
        return classA.length;
    }

    /** Species index a of pair {@code p}. */
    public int speciesA(int p) {
        return classA[p];
    }

    /** Species index b ≥ a of pair {@code p}. */
    public int speciesB(int p) {
        return classB[p];
    }

    /** Species names by index. */
    public List<String> speciesNames() {
        return names;
    }

    /** σ_ab of pair {@code p}, in the scene's length unit. */
    public double contactDistance(int p) {
        return sigma[p];
    }

    private int from(int p) {
        return binning.offset()[p];
    }

    private int binsOf(int p) {
        return binning.bins()[p];
    }

    /** Bin centres of pair {@code p}, in the scene's length unit. */
    public double[] r(int p) {
        double[] r = new double[binsOf(p)];
        for (int m = 0; m < r.length; m++) {
            r[m] = (m + 0.5) * (sigma[p] / binsPerContact);
        }
        return r;
    }

    /** g_ab in each bin of pair {@code p}, the mean over samples (NaN before any). */
    public double[] g(int p) {
        double[] g = new double[binsOf(p)];
        for (int m = 0; m < g.length; m++) {
            g[m] = averages.mean(from(p) + m);
        }
        return g;
    }

    /** The standard error of each bin of {@link #g}, from block averages (NaN with fewer than two blocks). */
    public double[] errors(int p) {
        double[] e = new double[binsOf(p)];
        for (int m = 0; m < e.length; m++) {
            e[m] = averages.error(from(p) + m);
        }
        return e;
    }

    @Override
    public void writeRows(Writer out) throws IOException {
        StringBuilder row = new StringBuilder(96);
        for (int p = 0; p < pairs(); p++) {
            String a = CsvCells.of(names.get(classA[p]));
            String b = CsvCells.of(names.get(classB[p]));
            double[] r = r(p);
            double[] g = g(p);
            double[] e = errors(p);
            for (int m = 0; m < r.length; m++) {
                row.setLength(0);
                row.append(a).append(',').append(b).append(',').append(sigma[p]).append(',').append(r[m]).append(',')
                        .append(g[m]).append(',').append(e[m]).append('\n');
                out.append(row);
            }
        }
    }

    @Override
    public ObservableState state() {
        StateCodec.Out out = new StateCodec.Out(LAYOUT).put(names.size());
        names.forEach(out::put);
        out.put(rangeInContacts).put(binsPerContact).put(discs);
        if (discs >= 0) {
            out.put(width).put(height).put(periodic ? 1 : 0);
            census.save(out);
            averages.save(out);
        }
        return out.state(KEY);
    }

    /** The observable {@code state} was saved from ({@link #state}), continuing exactly where it stopped. */
    public static PartialRadialDistribution restore(ObservableState state) {
        StateCodec.In in = new StateCodec.In(state, KEY, LAYOUT);
        int species = in.nextSize();
        String[] names = new String[species];
        for (int a = 0; a < species; a++) {
            names[a] = in.nextString();
        }
        PartialRadialDistribution gab = new PartialRadialDistribution(List.of(names), in.nextDouble(), in.nextInt());
        int n = in.nextInt();
        if (n >= 0) {
            double w = in.nextDouble();
            double h = in.nextDouble();
            boolean isPeriodic = in.nextLong() == 1;
            SpeciesCensus census = SpeciesCensus.restore(in);
            if (census.species() != species) {
                throw new IllegalArgumentException("g_ab state: a census of " + census.species() + " species for " + species);
            }
            gab.setUp(n, w, h, isPeriodic, census);
            gab.averages = BlockAverages.restore(in);
            if (gab.averages.width() != gab.totalBins) {
                throw new IllegalArgumentException("g_ab state: " + gab.averages.width() + " bins where its geometry gives "
                        + gab.totalBins);
            }
        }
        in.end();
        return gab;
    }
}
