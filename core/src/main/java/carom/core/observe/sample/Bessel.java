package carom.core.observe.sample;

/**
 * The Bessel function J₀, the average of cos(k·Δr) over the directions of k in the plane, for the
 * self-intermediate scattering function. Polynomial approximations of Abramowitz and Stegun, Handbook
 * of Mathematical Functions, 9.4.1 (|x| ≤ 3, absolute error below 5e-8) and 9.4.3 (x > 3, errors of
 * the amplitude and phase below 1.6e-8 and 7e-8): a few multiplications, one cosine beyond 3.
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
        return f * Math.cos(theta) / Math.sqrt(ax);
    }
}
