package carom.core.observe.sample;

/**
 * The Bessel function J₀, the average of cos(k·Δr) over the directions of k in the plane, for the
 * self-intermediate scattering function. Polynomial approximations of Abramowitz and Stegun, Handbook
 * of Mathematical Functions, 9.4.1 (|x| ≤ 3, absolute error below 5e-8) and 9.4.3 (x > 3, errors of
 * the amplitude and phase below 1.6e-8 and 7e-8): a few multiplications, one cosine beyond 3.
 *
 * <p>That cosine is {@link #cos}, without branches: F_s(k, t) evaluates J₀ once per disc and time
 * origin, and {@code Math.cos} was most of its cost.
 */
final class Bessel {
    private Bessel() {
    }

    static double j0(double x) {
        double ax = Math.abs(x);
        if (ax <= 3) {
            double t = x * x / 9;
            return 1 + t * (-2.2499997 + t * (1.2656208 + t * (-0.3163866 + t * (0.0444479 + t * (-0.0039444
                    + t * 0.0002100)))));
        }
        double u = 3 / ax;
        double f = 0.79788456 + u * (-0.00000077 + u * (-0.00552740 + u * (-0.00009512 + u * (0.00137237
                + u * (-0.00072805 + u * 0.00014476)))));
        double theta = ax - 0.78539816 + u * (-0.04166397 + u * (-0.00003954 + u * (0.00262573 + u * (-0.00054125
                + u * (-0.00029333 + u * 0.00013558)))));
        return f * cos(theta) / Math.sqrt(ax);
    }

    /** π/2 in two parts: the first with 33 significant bits (q times it is exact for q < 2^20), then the rest (fdlibm's pio2_1, pio2_1t). */
    private static final double HALF_PI_HIGH = 1.57079632673412561417e+00;
    private static final double HALF_PI_LOW = 6.07710050650619224932e-11;
    private static final double TWO_OVER_PI = 6.36619772367581382433e-01;
    private static final double[] COS_OF_QUADRANT = {1, 0, -1, 0};
    private static final double[] SIN_OF_QUADRANT = {0, -1, 0, 1};

    /**
     * cos x for x ≥ 0, to a few ulps below 1e5 (Math.cos beyond): x = q π/2 + r with |r| ≤ π/4 (Cody-Waite reduction), then
     * fdlibm's kernel polynomials of sin r and cos r, of which the quadrant q mod 4 takes one with its
     * sign by multiplying by 0 or ±1 (exact) instead of branching.
     */
    static double cos(double x) {
        if (!(x < 1e5)) {
            return Math.cos(x);
        }
        double q = Math.rint(x * TWO_OVER_PI);
        double r = (x - q * HALF_PI_HIGH) - q * HALF_PI_LOW;
        double z = r * r;
        double c = 1 - 0.5 * z + z * z * (4.16666666666666019037e-02 + z * (-1.38888888888741095749e-03
                + z * (2.48015872894767294178e-05 + z * (-2.75573143513906633035e-07 + z * (2.08757232129817482790e-09
                + z * -1.13596475577881948265e-11)))));
        double s = r + r * z * (-1.66666666666666324348e-01 + z * (8.33333333332248946124e-03
                + z * (-1.98412698298579493134e-04 + z * (2.75573137070700676789e-06 + z * (-2.50507602534068634195e-08
                + z * 1.58969099521155010221e-10)))));
        int quadrant = (int) q & 3;
        return COS_OF_QUADRANT[quadrant] * c + SIN_OF_QUADRANT[quadrant] * s;
    }
}
