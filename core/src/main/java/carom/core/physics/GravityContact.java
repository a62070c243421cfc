package carom.core.physics;

/**
 * Contact times under gravity, where a disc's motion relative to a wall or a fixed disc is a
 * parabola. Robust first roots without a general polynomial solver: a quadratic in closed stable
 * form for walls; for a fixed disc the quartic distance function is split at the real roots of its
 * derivative (a cubic) into monotone pieces, and the first piece that falls through zero is bisected.
 * A dip below contact that is missed can only be one within rounding of a graze, which exchanges no
 * momentum; a contact is never reported where the function does not change sign.
 */
public final class GravityContact {
    private GravityContact() {
    }

    /**
     * First time t >= 0 at which h(t) = h0 + v t + a t^2 / 2 reaches 0 while decreasing; +Infinity if
     * never. A disc already at or past contact (h0 <= 0) and moving in, or at rest and pressed in, hits
     * now.
     */
    public static double firstWallHit(double h0, double v, double a) {
        if (h0 <= 0 && (v < 0 || (v == 0 && a < 0))) {
            return 0;
        }
        if (a == 0) {
            return v < 0 ? Math.max(0, h0 / -v) : Double.POSITIVE_INFINITY;
        }
        double discriminant = v * v - 2 * a * h0;
        if (discriminant < 0) {
            return Double.POSITIVE_INFINITY;
        }
        // Roots of (a/2) t^2 + v t + h0 without cancellation.
        double q = -0.5 * (v + Math.copySign(Math.sqrt(discriminant), v));
        double r1 = q / (0.5 * a);
        double r2 = q != 0 ? h0 / q : r1;
        double lo = Math.min(r1, r2);
        double hi = Math.max(r1, r2);
        if (lo >= 0 && v + a * lo < 0) {
            return lo;
        }
        if (hi >= 0 && v + a * hi < 0) {
            return hi;
        }
        return Double.POSITIVE_INFINITY;
    }

    /**
     * First time in [0, window] at which a disc at relative position (px, py) from a fixed disc, with
     * velocity (vx, vy) and acceleration (ax, ay), comes within {@code sigma} of it while approaching;
     * +Infinity if not within the window.
     */
    public static double firstContact(double px, double py, double vx, double vy, double ax, double ay,
                                      double sigma, double window) {
        // |p + v t + s t^2|^2 - sigma^2 with s = a/2, as c4 t^4 + c3 t^3 + c2 t^2 + c1 t + c0.
        double sx = 0.5 * ax;
        double sy = 0.5 * ay;
        double c4 = sx * sx + sy * sy;
        double c3 = 2 * (vx * sx + vy * sy);
        double c2 = vx * vx + vy * vy + 2 * (px * sx + py * sy);
        double c1 = 2 * (px * vx + py * vy);
        double c0 = px * px + py * py - sigma * sigma;
        // Touching and closing (beyond a rounding-level slide), or at rest and pressed in: now.
        double p2 = px * px + py * py;
        double v2 = vx * vx + vy * vy;
        if (c0 <= 0 && (PairLaw.closing(0.5 * c1, p2, v2) || (v2 == 0 && c2 < 0))) {
            return 0;
        }
        if (c0 <= 0 && c2 < 0 && (c1 <= 0 || c0 - c1 * c1 / (4 * c2) <= 0)) {
            // Touching within rounding and pressed in, with no room to leave first (the distance
            // function's peak, c0 - c1^2 / 4c2 near t = 0, stays at contact): collide as soon as the
            // inward normal speed stands out from rounding, instead of sinking in.
            double threshold = -2 * PairLaw.GRAZING * Math.sqrt(p2 * v2);
            double t = (threshold - c1) / (2 * c2);
            return t <= window ? Math.max(0, t) : Double.POSITIVE_INFINITY;
        }
        if (!(window > 0)) {
            return Double.POSITIVE_INFINITY;
        }
        // Critical points of the quartic inside (0, window), in increasing order.
        double[] stops = new double[5];
        int count = 0;
        stops[count++] = 0;
        double[] crit = new double[3];
        int roots = cubicRoots(4 * c4, 3 * c3, 2 * c2, c1, crit);
        java.util.Arrays.sort(crit, 0, roots);
        for (int k = 0; k < roots; k++) {
            if (crit[k] > 0 && crit[k] < window) {
                stops[count++] = crit[k];
            }
        }
        stops[count++] = window;
        double left = stops[0];
        double fLeft = quartic(c4, c3, c2, c1, c0, left);
        for (int k = 1; k < count; k++) {
            double right = stops[k];
            double fRight = quartic(c4, c3, c2, c1, c0, right);
            if (fLeft > 0 && fRight <= 0) {
                return bisect(c4, c3, c2, c1, c0, left, right);
            }
            left = right;
            fLeft = fRight;
        }
        return Double.POSITIVE_INFINITY;
    }

    private static double quartic(double c4, double c3, double c2, double c1, double c0, double t) {
        return (((c4 * t + c3) * t + c2) * t + c1) * t + c0;
    }

    /** f(lo) > 0 >= f(hi): the earliest time at which contact is reached, to the last bit. */
    private static double bisect(double c4, double c3, double c2, double c1, double c0, double lo, double hi) {
        for (int k = 0; k < 200; k++) {
            double mid = 0.5 * (lo + hi);
            if (mid <= lo || mid >= hi) {
                break;
            }
            if (quartic(c4, c3, c2, c1, c0, mid) > 0) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        return hi;
    }

    /**
     * Real roots of a t^3 + b t^2 + c t + d (a may be 0), polished by Newton steps; returns how many
     * were written to {@code out}.
     */
    static int cubicRoots(double a, double b, double c, double d, double[] out) {
        if (a == 0) {
            return quadraticRoots(b, c, d, out);
        }
        double p = b / a;
        double q = c / a;
        double r = d / a;
        // Depressed cubic t = u - p/3: u^3 + e u + f = 0.
        double shift = p / 3;
        double e = q - p * p / 3;
        double f = 2 * p * p * p / 27 - p * q / 3 + r;
        double disc = f * f / 4 + e * e * e / 27;
        int n;
        if (disc > 0) {
            double s = Math.sqrt(disc);
            out[0] = Math.cbrt(-f / 2 + s) + Math.cbrt(-f / 2 - s) - shift;
            n = 1;
        } else if (e == 0) {
            out[0] = -shift;
            n = 1;
        } else {
            double m = 2 * Math.sqrt(-e / 3);
            double arg = Math.max(-1, Math.min(1, 3 * f / (e * m)));
            double theta = Math.acos(arg) / 3;
            for (int k = 0; k < 3; k++) {
                out[k] = m * Math.cos(theta - 2 * Math.PI * k / 3) - shift;
            }
            n = 3;
        }
        for (int k = 0; k < n; k++) {
            out[k] = polish(a, b, c, d, out[k]);
        }
        return n;
    }

    private static int quadraticRoots(double a, double b, double c, double[] out) {
        if (a == 0) {
            if (b == 0) {
                return 0;
            }
            out[0] = -c / b;
            return 1;
        }
        double disc = b * b - 4 * a * c;
        if (disc < 0) {
            return 0;
        }
        double q = -0.5 * (b + Math.copySign(Math.sqrt(disc), b));
        out[0] = q / a;
        out[1] = q != 0 ? c / q : out[0];
        return 2;
    }

    private static double polish(double a, double b, double c, double d, double t) {
        for (int k = 0; k < 3; k++) {
            double value = ((a * t + b) * t + c) * t + d;
            double slope = (3 * a * t + 2 * b) * t + c;
            if (slope == 0) {
                break;
            }
            double next = t - value / slope;
            if (!Double.isFinite(next)) {
                break;
            }
            t = next;
        }
        return t;
    }
}
