package carom.core.observe.sample;

import java.io.IOException;
import java.io.Writer;

/**
 * The radial distribution function g(r) of all pairs, averaged over samples ({@code gr.csv}: {@code r,g},
 * r the bin centre in the scene's length unit).
 *
 * <p>Bins: width σ / {@code binsPerContact} (default 50, so σ/50), from r = 0, up to
 * {@code rangeInContacts} σ (default 5σ) or half the shorter side of the box, whichever is smaller, with σ
 * the first sample's {@link Sample#contactDistance()} (the diameter of equal discs). Bin k counts the
 * pairs with k w ≤ r < (k + 1) w, so for equal discs contact falls on the lower edge of bin
 * {@code binsPerContact}. Pairs are found on a cell grid, O(N) per sample.
 *
 * <p>Normalisation: each sample's count in a bin is divided by what N uniformly random points would put
 * there, the ideal-gas pair density, so that g = 1 without correlations.
 * <ul>
 * <li>Periodic box (minimum image, exact to half the shorter side): N(N-1)/2 · π(r₂² - r₁²) / (W H).</li>
 * <li>Walls: the centres can reach the rectangle W' x H' = (W - 2a) x (H - 2a), a the smallest radius;
 *     for uniform points there the separation vector (u, v) has density (W' - |u|)(H' - |v|) / (W' H')²,
 *     so the shell holds N(N-1)/2 · [F(r₂) - F(r₁)] / (W' H')² with F(r) = π W'H' r² - (4/3)(W' + H') r³
 *     + r⁴/2 (valid for r ≤ min(W', H')). A hard-disc fluid's layering at the walls remains in g.</li>
 * </ul>
 * The mean over samples is the pooled count over the pooled ideal count; {@link #errors()} gives each
 * bin's standard error from the spread of the per-sample values.
 */
public final class RadialDistribution implements SampledObservable {
    public static final String KEY = "gr";
    public static final double DEFAULT_RANGE_IN_CONTACTS = 5;
    public static final int DEFAULT_BINS_PER_CONTACT = 50;
    /** Bins beyond contact fitted by {@link #contactValue()}: 0.16σ at the default bin width. */
    public static final int DEFAULT_CONTACT_FIT_BINS = 8;
    private static final long LAYOUT = 1;

    private final double rangeInContacts;
    private final int binsPerContact;
    private final NeighbourScan scan = new NeighbourScan();
    /** All pairs in one class, for the sample's species (made at the first sample). */
    private NeighbourScan.PairBins binning;
    /** One sample's pair counts per bin (scratch). */
    private int[] sampleCounts = new int[0];

    // Geometry, fixed by the first sample.
    private int discs = -1;
    private double width;
    private double height;
    private boolean periodic;
    private double sigma;
    private double minRadius;
    private double binWidth;
    private int bins;
    private double[] idealPairs = new double[0];

    private long samples;
    private long[] counts = new long[0];
    private double[] sumG = new double[0];
    private double[] sumG2 = new double[0];

    public RadialDistribution() {
        this(DEFAULT_RANGE_IN_CONTACTS, DEFAULT_BINS_PER_CONTACT);
    }

    public RadialDistribution(double rangeInContacts, int binsPerContact) {
        if (!(rangeInContacts > 0) || binsPerContact < 1) {
            throw new IllegalArgumentException("range and bins per contact must be positive");
        }
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
            setUp(s.n, s.box.width(), s.box.height(), s.box.periodic(), s.contactDistance(), s.minRadius());
        } else if (s.n != discs || s.box.width() != width || s.box.height() != height || s.box.periodic() != periodic) {
            throw new IllegalArgumentException("g(r): a sample of other discs or another box");
        }
        if (bins == 0) {
            samples++;
            return;
        }
        int species = s.speciesCount();
        if (binning == null || binning.speciesCount() != species) {
            binning = NeighbourScan.PairBins.single(species, 1 / binWidth, bins);
        }
        java.util.Arrays.fill(sampleCounts, 0);
        scan.histogram(s, bins * binWidth, binning, sampleCounts);
        int[] c = sampleCounts;
        for (int k = 0; k < bins; k++) {
            counts[k] += c[k];
            double g = c[k] / idealPairs[k];
            sumG[k] += g;
            sumG2[k] += g * g;
        }
        samples++;
    }

    private void setUp(int n, double w, double h, boolean isPeriodic, double contact, double smallestRadius) {
        if (!(contact > 0)) {
            throw new IllegalArgumentException("g(r) needs discs of positive radius");
        }
        discs = n;
        width = w;
        height = h;
        periodic = isPeriodic;
        sigma = contact;
        minRadius = smallestRadius;
        binWidth = contact / binsPerContact;
        double reachW = periodic ? w : w - 2 * smallestRadius;
        double reachH = periodic ? h : h - 2 * smallestRadius;
        double range = Math.min(rangeInContacts * contact, 0.5 * Math.min(reachW, reachH));
        bins = n < 2 || !(range > 0) ? 0 : (int) Math.floor(range / binWidth);
        idealPairs = new double[bins];
        double pairs = 0.5 * n * (n - 1.0);
        for (int k = 0; k < bins; k++) {
            double r1 = k * binWidth;
            double r2 = (k + 1) * binWidth;
            idealPairs[k] = periodic
                    ? pairs * Math.PI * (r2 * r2 - r1 * r1) / (w * h)
                    : pairs * (wallShell(r2, reachW, reachH) - wallShell(r1, reachW, reachH)) / (reachW * reachW * reachH * reachH);
        }
        if (counts.length != bins) {
            counts = new long[bins];
            sumG = new double[bins];
            sumG2 = new double[bins];
        }
        sampleCounts = new int[bins];
    }

    /** F(r): W'H' times the probability that two uniform points of a W' x H' rectangle are closer than r. */
    private static double wallShell(double r, double w, double h) {
        return Math.PI * w * h * r * r - 4.0 / 3.0 * (w + h) * r * r * r + 0.5 * r * r * r * r;
    }

    public long samples() {
        return samples;
    }

    /** σ, the contact distance r is measured against (NaN before the first sample). */
    public double contactDistance() {
        return discs < 0 ? Double.NaN : sigma;
    }

    /** Bin centres, in the scene's length unit. */
    public double[] r() {
        double[] r = new double[bins];
        for (int k = 0; k < bins; k++) {
            r[k] = (k + 0.5) * binWidth;
        }
        return r;
    }

    /** g in each bin, the pooled count over the pooled ideal-gas count (0 before any sample). */
    public double[] g() {
        double[] g = new double[bins];
        for (int k = 0; k < bins; k++) {
            g[k] = samples == 0 ? 0 : counts[k] / (idealPairs[k] * samples);
        }
        return g;
    }

    /** Standard error of g in each bin from the spread of the per-sample values (NaN with one sample). */
    public double[] errors() {
        double[] e = new double[bins];
        for (int k = 0; k < bins; k++) {
            double mean = sumG[k] / samples;
            double var = (sumG2[k] / samples - mean * mean) * samples / (samples - 1.0);
            e[k] = samples < 2 ? Double.NaN : Math.sqrt(Math.max(0, var) / samples);
        }
        return e;
    }

    /** {@link #contactValue(int)} over {@link #DEFAULT_CONTACT_FIT_BINS} bins. */
    public double contactValue() {
        return contactValue(DEFAULT_CONTACT_FIT_BINS);
    }

    /**
     * g(σ⁺) for equal discs: a least-squares quadratic through the first {@code fitBins} bins from
     * contact, at their centres, extrapolated to r = σ (NaN if the range holds too few bins). For a
     * mixture σ is the mean diameter and the value has no such meaning.
     */
    public double contactValue(int fitBins) {
        if (fitBins < 3 || binsPerContact + fitBins > bins || samples == 0) {
            return Double.NaN;
        }
        double[] g = g();
        // Normal equations of g = a + b u + c u² in u = (r - σ) / w, a 3 x 3 system solved by Cramer's rule.
        double s0 = 0, s1 = 0, s2 = 0, s3 = 0, s4 = 0, t0 = 0, t1 = 0, t2 = 0;
        for (int k = binsPerContact; k < binsPerContact + fitBins; k++) {
            double u = k + 0.5 - binsPerContact;
            double u2 = u * u;
            s0 += 1;
            s1 += u;
            s2 += u2;
            s3 += u2 * u;
            s4 += u2 * u2;
            t0 += g[k];
            t1 += g[k] * u;
            t2 += g[k] * u2;
        }
        double det = s0 * (s2 * s4 - s3 * s3) - s1 * (s1 * s4 - s3 * s2) + s2 * (s1 * s3 - s2 * s2);
        double detA = t0 * (s2 * s4 - s3 * s3) - s1 * (t1 * s4 - s3 * t2) + s2 * (t1 * s3 - s2 * t2);
        return detA / det;
    }

    @Override
    public void writeRows(Writer out) throws IOException {
        double[] r = r();
        double[] g = g();
        StringBuilder row = new StringBuilder(64);
        for (int k = 0; k < bins; k++) {
            row.setLength(0);
            row.append(r[k]).append(',').append(g[k]).append('\n');
            out.append(row);
        }
    }

    @Override
    public ObservableState state() {
        return new StateCodec.Out(LAYOUT).put(rangeInContacts).put(binsPerContact).put(samples).put(discs)
                .put(width).put(height).put(periodic ? 1 : 0).put(sigma).put(minRadius)
                .put(bins).put(counts, bins).put(sumG, bins).put(sumG2, bins).state(KEY);
    }

    /** The observable {@code state} was saved from ({@link #state}), continuing exactly where it stopped. */
    public static RadialDistribution restore(ObservableState state) {
        StateCodec.In in = new StateCodec.In(state, KEY, LAYOUT);
        RadialDistribution gr = new RadialDistribution(in.nextDouble(), in.nextInt());
        gr.samples = in.nextLong();
        int n = in.nextInt();
        double w = in.nextDouble();
        double h = in.nextDouble();
        boolean isPeriodic = in.nextLong() == 1;
        double contact = in.nextDouble();
        double smallestRadius = in.nextDouble();
        if (n >= 0) {
            gr.setUp(n, w, h, isPeriodic, contact, smallestRadius);
        }
        int bins = in.nextSize();
        if (bins != gr.bins) {
            throw new IllegalArgumentException("g(r) state: " + bins + " bins where its geometry gives " + gr.bins);
        }
        gr.counts = in.nextLongs(bins);
        gr.sumG = in.nextDoubles(bins);
        gr.sumG2 = in.nextDoubles(bins);
        in.end();
        return gr;
    }
}
