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
 *   <li><b>Gridding</b> (long rays): the phases θ_j = q·r_j mod 2π are points on a circle, and
 *       ρ(n q) = Σ_j exp(i n θ_j) is a Fourier series of them (a one-dimensional non-uniform FFT). Each
 *       phase is written θ_j = m_j h + u_j h about its nearest point m_j h of a grid of M_r points
 *       (h = 2π/M_r, M_r the power of two at least 8 (S + 1), |u_j| ≤ 1/2), and
 *       exp(i n u_j h) is expanded in powers of u_j: ρ(n q) = Σ_p (i n h)^p / p! · Σ_m exp(i n m h) U_p(m),
 *       U_p(m) = Σ_{j at m} u_j^p, the moments of each grid point (Anderson and Dahleh, "Rapid
 *       computation of the discrete Fourier transform", SIAM J. Sci. Comput. 17 (1996) 913). A disc adds P
 *       powers of its u_j (no sine, cosine or exponential); each moment's Fourier sum is an FFT of M_r
 *       points (independent of N). P is even and the first with (π S / M_r)^P / P! below 1e-15, which
 *       bounds each disc's truncation error (|n u h| ≤ π S / M_r ≤ π/8): the sums hold to about 1e-14 of
 *       N_a. A sample then costs about 2P + 10 operations a disc and ray instead of 6 S.</li>
 * </ul>
 * Plain arrays, allocated once; nothing is allocated per sample.
 */
final class RaySums {
    /** Operations a disc of a gridded ray costs besides its moments, and a disc and vector of a recurrence, as weighed to choose. */
    private static final int GRID_COST = 12;
    private static final int STEP_COST = 6;
    private static final int SINCOS_COST = 40;

    final int steps;
    private final int species;
    private final double stepX;
    private final double stepY;
    final boolean gridded;

    // Gridding (zero or null when not gridded).
    /** M_r, a power of two, and log2 of it. */
    private final int size;
    private final int bits;
    /** P, the powers of u a disc adds (even). */
    final int powers;
    /** Per species, grid point and power: U_p(m) at [(a * size + m) * powers + p]. */
    private final double[] moments;
    /** FFT work (two moments at once, as real and imaginary parts) and its twiddles exp(2πi t / M_r), t < M_r / 2. */
    private final double[] fftRe;
    private final double[] fftIm;
    private final double[] twiddleRe;
    private final double[] twiddleIm;
    private final int[] bitReversed;
    /** (n h)^p / p! at [n * powers + p]. */
    private final double[] coefficient;

    /**
     * The ray of multiples n = 1..steps of the vector (stepX, stepY) = 2π (p_x / W, p_y / H), for samples
     * of {@code discs} discs of {@code species} species; the cheaper way of the two.
     */
    static RaySums of(double stepX, double stepY, int steps, int species, int discs) {
        long recurrence = (long) discs * (steps * STEP_COST + SINCOS_COST);
        int size = gridSize(steps);
        int powers = powers(steps, size);
        long gridding = (long) discs * (GRID_COST + 2L * powers) + 5L * species * powers * size * Integer.numberOfTrailingZeros(size);
        return new RaySums(stepX, stepY, steps, species, gridding < recurrence);
    }

    RaySums(double stepX, double stepY, int steps, int species, boolean gridded) {
        this.steps = steps;
        this.species = species;
        this.stepX = stepX;
        this.stepY = stepY;
        this.gridded = gridded;
        if (!gridded) {
            size = bits = powers = 0;
            moments = fftRe = fftIm = twiddleRe = twiddleIm = coefficient = null;
            bitReversed = null;
            return;
        }
        size = gridSize(steps);
        bits = Integer.numberOfTrailingZeros(size);
        powers = powers(steps, size);
        moments = new double[species * size * powers];
        fftRe = new double[size];
        fftIm = new double[size];
        twiddleRe = new double[size / 2];
        twiddleIm = new double[size / 2];
        for (int t = 0; t < size / 2; t++) {
            twiddleRe[t] = Math.cos(2 * Math.PI * t / size);
            twiddleIm[t] = Math.sin(2 * Math.PI * t / size);
        }
        bitReversed = new int[size];
        for (int m = 0; m < size; m++) {
            bitReversed[m] = Integer.reverse(m) >>> (32 - bits);
        }
        coefficient = new double[(steps + 1) * powers];
        double h = 2 * Math.PI / size;
        for (int n = 1; n <= steps; n++) {
            double c = 1;
            for (int p = 0; p < powers; p++) {
                coefficient[n * powers + p] = c;
                c *= n * h / (p + 1);
            }
        }
    }

    /** M_r: the power of two at least 8 (S + 1). */
    static int gridSize(int steps) {
        if (steps > (1 << 26)) {
            throw new IllegalArgumentException("a ray of " + steps + " vectors");
        }
        return Integer.highestOneBit(8 * (steps + 1) - 1) << 1;
    }

    /** P: the first even number of powers whose truncation, (π S / M_r)^P / P!, is below 1e-15. */
    static int powers(int steps, int size) {
        double x = Math.PI * steps / size;
        double term = 1;
        int p = 0;
        while (true) {
            term *= x / (p + 1);
            p++;
            if (p % 2 == 0 && term < 1e-15) {
                return p;
            }
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
        double[] u = moments;
        Arrays.fill(u, 0);
        int pw = powers;
        int mask = size - 1;
        // the phase in grid steps: q = 2π t, so q·r / h = M_r t·r, reduced to [0, M_r)
        double tx = stepX / (2 * Math.PI) * size;
        double ty = stepY / (2 * Math.PI) * size;
        double turn = size;
        double perTurn = 1.0 / size; // exact: a power of two
        for (int i = 0; i < s.n; i++) {
            double g = tx * s.x[i] + ty * s.y[i];
            g -= Math.floor(g * perTurn) * turn;
            double m = Math.rint(g);
            double d = g - m;
            int base = (s.species[i] * size + ((int) m & mask)) * pw;
            double d2 = d * d;
            double even = 1;
            double odd = d;
            for (int p = 0; p < pw; p += 2) {
                u[base + p] += even;
                u[base + p + 1] += odd;
                even *= d2;
                odd *= d2;
            }
        }
        for (int a = 0; a < species; a++) {
            int v = a * stride + offset;
            for (int p = 0; p < pw; p += 2) {
                // two real moments in one complex FFT: Z = FFT(U_p + i U_{p+1})
                int o = a * size * pw;
                for (int m = 0; m < size; m++) {
                    int r = bitReversed[m];
                    fftRe[r] = u[o + m * pw + p];
                    fftIm[r] = u[o + m * pw + p + 1];
                }
                fft();
                for (int n = 1; n <= steps; n++) {
                    // F_p(n) = (Z(n) + conj Z(M_r - n)) / 2, F_{p+1}(n) = (Z(n) - conj Z(M_r - n)) / 2i
                    double zr = fftRe[n];
                    double zi = fftIm[n];
                    double wr = fftRe[size - n];
                    double wi = -fftIm[size - n];
                    double ar = 0.5 * (zr + wr);
                    double ai = 0.5 * (zi + wi);
                    double br = 0.5 * (zi - wi);
                    double bi = -0.5 * (zr - wr);
                    // times (i n h)^p / p!: i^p is 1, i, -1, -i as p mod 4 is 0..3; p is even
                    double ca = coefficient[n * pw + p];
                    double cb = coefficient[n * pw + p + 1];
                    double sign = (p & 2) == 0 ? 1 : -1;
                    // i^p ca F_p + i^(p+1) cb F_{p+1} = sign (ca F_p + i cb F_{p+1})
                    re[v + n - 1] += sign * (ca * ar - cb * bi);
                    im[v + n - 1] += sign * (ca * ai + cb * br);
                }
            }
        }
    }

    /** In place, on bit-reversed input: Z(n) = Σ_m z(m) exp(2πi n m / M_r). */
    private void fft() {
        double[] xr = fftRe;
        double[] xi = fftIm;
        for (int half = 1, stride = size / 2; half < size; half <<= 1, stride >>= 1) {
            for (int start = 0; start < size; start += 2 * half) {
                for (int k = 0; k < half; k++) {
                    double cr = twiddleRe[k * stride];
                    double ci = twiddleIm[k * stride];
                    int a = start + k;
                    int b = a + half;
                    double tr = xr[b] * cr - xi[b] * ci;
                    double ti = xr[b] * ci + xi[b] * cr;
                    xr[b] = xr[a] - tr;
                    xi[b] = xi[a] - ti;
                    xr[a] += tr;
                    xi[a] += ti;
                }
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
