package carom.core.observe.sample;

import java.util.Arrays;

/**
 * The density sums of one ray of wave vectors, ρ_a(n q) = Σ_{j of species a} exp(i n q·r_j) for
 * n = 1..S, q a vector of the periodic box's reciprocal lattice (q = 2π (p_x / W, p_y / H), whole p), for
 * every species a: what {@link StructureFactor} needs along each of its directions.
 *
 * <p>Two ways, chosen once per ray by their operation counts:
 * <ul>
 *   <li><b>Recurrence</b> (short rays, few discs): one sine and cosine per disc, then
 *       exp(i (n+1) φ) = exp(i n φ) exp(i φ), one complex multiplication per disc and vector; four
 *       discs at a time, four independent chains of multiplications. Rounding grows about linearly in
 *       n (a few ulps per step; {@code RaySumsTest} bounds it against direct sines and cosines).</li>
 *   <li><b>Gaussian gridding</b> (long rays): the phases θ_j = q·r_j mod 2π are points on a circle, and
 *       ρ(n q) = Σ_j exp(i n θ_j) is a Fourier series of them, a one-dimensional non-uniform FFT of
 *       type 1. Each disc is spread onto a grid of M_r = 2M points (M = 2S + 2) with a periodic
 *       Gaussian, 2·12 grid points a disc (fast Gaussian gridding: two exponentials a disc, then
 *       multiplications), the grid's Fourier sums are taken at n = 1..S directly (M_r · S operations,
 *       independent of N), and the Gaussian is divided out: Greengard and Lee, "Accelerating the
 *       nonuniform fast Fourier transform", SIAM Review 46 (2004) 443, with oversampling R = 2 and
 *       M_sp = 12 (τ = π M_sp / (M² R (R − 1/2))), which they give as 12 digits relative to Σ_j 1 = N_a.
 *       A sample then costs about 30 N operations per ray instead of N · S.</li>
 * </ul>
 * Plain arrays, allocated once; nothing is allocated per sample.
 */
final class RaySums {
    /** Grid points each side of a disc (Greengard-Lee's M_sp). */
    static final int SPREAD = 12;
    /** Operations per disc of a gridded ray (spreading) and per disc and vector of a recurrence, as weighed to choose. */
    private static final int GRID_COST = 4 * SPREAD + 60;
    private static final int STEP_COST = 6;

    final int steps;
    private final int species;
    private final double stepX;
    private final double stepY;
    final boolean gridded;

    // Gaussian gridding (null or zero when not gridded).
    private final int size;
    private final double h;
    private final double quarterInverseTau;
    private final double e2Scale;
    private final double[] e3;
    private final double[] grid;
    private final double[] cosTable;
    private final double[] sinTable;
    private final double[] deconvolve;

    /**
     * The ray of multiples n = 1..steps of the vector (stepX, stepY) = 2π (p_x / W, p_y / H), for samples
     * of {@code discs} discs of {@code species} species; the cheaper way of the two.
     */
    static RaySums of(double stepX, double stepY, int steps, int species, int discs) {
        long recurrence = (long) discs * steps * STEP_COST;
        long gridding = (long) discs * GRID_COST + 2L * species * steps * (4L * (steps + 1));
        return new RaySums(stepX, stepY, steps, species, steps > 2 * SPREAD && gridding < recurrence);
    }

    RaySums(double stepX, double stepY, int steps, int species, boolean gridded) {
        this.steps = steps;
        this.species = species;
        this.stepX = stepX;
        this.stepY = stepY;
        this.gridded = gridded;
        if (!gridded) {
            size = 0;
            h = quarterInverseTau = e2Scale = 0;
            e3 = grid = cosTable = sinTable = deconvolve = null;
            return;
        }
        int modes = 2 * steps + 2;
        size = 2 * modes;
        h = 2 * Math.PI / size;
        double tau = Math.PI * SPREAD / ((double) modes * modes * 2 * 1.5);
        quarterInverseTau = 1 / (4 * tau);
        e2Scale = h / (2 * tau);
        e3 = new double[SPREAD + 1];
        for (int l = 0; l <= SPREAD; l++) {
            e3[l] = Math.exp(-(l * h) * (l * h) * quarterInverseTau);
        }
        grid = new double[species * (size + 2 * SPREAD)];
        cosTable = new double[size];
        sinTable = new double[size];
        for (int q = 0; q < size; q++) {
            cosTable[q] = Math.cos(2 * Math.PI * q / size);
            sinTable[q] = Math.sin(2 * Math.PI * q / size);
        }
        deconvolve = new double[steps + 1];
        for (int n = 1; n <= steps; n++) {
            deconvolve[n] = Math.sqrt(Math.PI / tau) * Math.exp((double) n * n * tau) / size;
        }
    }

    /**
     * Adds ρ_a(n q) of the sample's discs to {@code re[a * stride + offset + n - 1]} and
     * {@code im[...]}, n = 1..steps, for every species a.
     */
    void addTo(Sample s, double[] re, double[] im, int offset, int stride) {
        if (gridded) {
            grid(s, re, im, offset, stride);
        } else {
            recurrence(s, re, im, offset, stride);
        }
    }

    private void grid(Sample s, double[] re, double[] im, int offset, int stride) {
        double[] g = grid;
        Arrays.fill(g, 0);
        int padded = size + 2 * SPREAD;
        // the phase in turns: q = 2π t, so q·r / 2π = t·r, reduced to [0, 1)
        double tx = stepX / (2 * Math.PI);
        double ty = stepY / (2 * Math.PI);
        double[] e = e3;
        for (int i = 0; i < s.n; i++) {
            double u = tx * s.x[i] + ty * s.y[i];
            u = (u - Math.floor(u)) * size;
            int m0 = (int) u;
            if (m0 >= size) { // u rounded up to a whole turn
                m0 = 0;
                u = 0;
            }
            double delta = (u - m0) * h;
            double e1 = Math.exp(-delta * delta * quarterInverseTau);
            double e2 = Math.exp(delta * e2Scale);
            double e2i = 1 / e2;
            int base = s.species[i] * padded + m0 + SPREAD;
            g[base] += e1;
            double up = e1;
            double down = e1;
            for (int l = 1; l < SPREAD; l++) {
                up *= e2;
                down *= e2i;
                g[base + l] += up * e[l];
                g[base - l] += down * e[l];
            }
            up *= e2;
            g[base + SPREAD] += up * e[SPREAD];
        }
        for (int a = 0; a < species; a++) {
            int o = a * padded;
            for (int p = 0; p < SPREAD; p++) { // grid point p - SPREAD is size + p - SPREAD
                g[o + p + size] += g[o + p];
            }
            for (int p = size + SPREAD; p < padded; p++) { // grid point p - SPREAD is p - SPREAD - size
                g[o + p - size] += g[o + p];
            }
            int v = a * stride + offset;
            for (int n = 1; n <= steps; n++) {
                double sr = 0;
                double si = 0;
                int q = 0;
                for (int m = 0; m < size; m++) {
                    double f = g[o + m + SPREAD];
                    sr += f * cosTable[q];
                    si += f * sinTable[q];
                    q += n;
                    if (q >= size) {
                        q -= size;
                    }
                }
                re[v + n - 1] += deconvolve[n] * sr;
                im[v + n - 1] += deconvolve[n] * si;
            }
        }
    }

    /**
     * Discs four at a time: one disc's recurrence is a chain of dependent multiplications, four
     * independent chains keep the multipliers busy. Each vector's sums take the discs in id order.
     */
    private void recurrence(Sample s, double[] re, double[] im, int offset, int stride) {
        double kx = stepX;
        double ky = stepY;
        int i = 0;
        for (; i + 4 <= s.n; i += 4) {
            int v0 = s.species[i] * stride + offset;
            int v1 = s.species[i + 1] * stride + offset;
            int v2 = s.species[i + 2] * stride + offset;
            int v3 = s.species[i + 3] * stride + offset;
            double p0 = kx * s.x[i] + ky * s.y[i];
            double p1 = kx * s.x[i + 1] + ky * s.y[i + 1];
            double p2 = kx * s.x[i + 2] + ky * s.y[i + 2];
            double p3 = kx * s.x[i + 3] + ky * s.y[i + 3];
            double c0 = Math.cos(p0);
            double s0 = Math.sin(p0);
            double c1 = Math.cos(p1);
            double s1 = Math.sin(p1);
            double c2 = Math.cos(p2);
            double s2 = Math.sin(p2);
            double c3 = Math.cos(p3);
            double s3 = Math.sin(p3);
            double r0 = c0;
            double q0 = s0;
            double r1 = c1;
            double q1 = s1;
            double r2 = c2;
            double q2 = s2;
            double r3 = c3;
            double q3 = s3;
            for (int j = 0; j < steps; j++) {
                re[v0] += r0;
                im[v0++] += q0;
                re[v1] += r1;
                im[v1++] += q1;
                re[v2] += r2;
                im[v2++] += q2;
                re[v3] += r3;
                im[v3++] += q3;
                double t0 = r0 * c0 - q0 * s0;
                q0 = r0 * s0 + q0 * c0;
                r0 = t0;
                double t1 = r1 * c1 - q1 * s1;
                q1 = r1 * s1 + q1 * c1;
                r1 = t1;
                double t2 = r2 * c2 - q2 * s2;
                q2 = r2 * s2 + q2 * c2;
                r2 = t2;
                double t3 = r3 * c3 - q3 * s3;
                q3 = r3 * s3 + q3 * c3;
                r3 = t3;
            }
        }
        for (; i < s.n; i++) {
            int v = s.species[i] * stride + offset;
            double phase = kx * s.x[i] + ky * s.y[i];
            double cr = Math.cos(phase);
            double ci = Math.sin(phase);
            double er = cr;
            double ei = ci;
            for (int j = 0; j < steps; j++) {
                re[v] += er;
                im[v++] += ei;
                double nr = er * cr - ei * ci;
                ei = er * ci + ei * cr;
                er = nr;
            }
        }
    }
}
