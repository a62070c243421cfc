package carom.core.physics;

/**
 * Contacts and collisions of discs whose radii grow linearly in time (the {@code growth} effect, the
 * Lubachevsky-Stillinger protocol): a pair's contact distance is sigma + sigmaRate * t from now, a
 * disc's radius r + rRate * t.
 *
 * <p>Pair contact: with r = rj - ri, v = vj - vi, |r + v t| = sigma + sigmaRate t is the quadratic
 * a t^2 + 2 b t + c = 0 with a = v.v - sigmaRate^2, b = r.v - sigma sigmaRate (half the rate at which
 * the gap's square closes now) and c = r.r - sigma^2. Its roots are taken in the forms that avoid
 * cancellation (as {@link PairLaw} does, after Bannerman, Lue and Lue 2014):
 * <ul>
 *   <li>b < 0 (the gap closing now): c <= 0 means touching or overlapped by rounding: collide now;
 *       otherwise t = c / (sqrt(b^2 - a c) - b), no event if the discriminant is not positive (only
 *       possible when a > 0: the discs pass each other faster than they grow);</li>
 *   <li>b >= 0 (opening): only growth faster than the relative speed (a < 0) closes the gap again,
 *       at the far root t = (b + sqrt(b^2 - a c)) / -a; a pair overlapped by rounding (c < 0) that is
 *       opening gets this later contact too, not the spurious near root, so it separates first.</li>
 * </ul>
 * Collisions bounce the discs off each other's growing surfaces: the approach speed u in the impulse
 * becomes u + sigmaRate, so after an elastic collision the gap opens as fast as it closed before.
 */
public final class GrowthLaw {
    private GrowthLaw() {
    }

    /**
     * Time from now until the pair first touches, or {@code +Infinity}.
     *
     * @param dx        x separation rj - ri (nearest image)
     * @param dy        y separation
     * @param dvx       x relative velocity vj - vi
     * @param dvy       y relative velocity
     * @param sigma     contact distance Ri + Rj now
     * @param sigmaRate its growth per unit time
     */
    public static double timeToContact(double dx, double dy, double dvx, double dvy, double sigma, double sigmaRate) {
        double b = dx * dvx + dy * dvy - sigma * sigmaRate;
        double c = dx * dx + dy * dy - sigma * sigma;
        double a = dvx * dvx + dvy * dvy - sigmaRate * sigmaRate;
        if (b < 0) {
            if (c <= 0) {
                return 0;
            }
            double discriminant = b * b - a * c;
            if (discriminant <= 0) {
                return Double.POSITIVE_INFINITY;
            }
            return c / (Math.sqrt(discriminant) - b);
        }
        if (a >= 0) {
            return Double.POSITIVE_INFINITY;
        }
        double discriminant = b * b - a * c;
        return discriminant < 0 ? Double.POSITIVE_INFINITY : (b + Math.sqrt(discriminant)) / -a;
    }

    /**
     * Time from now until a disc at (x, y) with velocity (vx, vy) and radius r growing at rRate touches
     * wall {@code wall} of a box [0, width] x [0, height] (its surface moving toward the wall); 0 if it
     * already touches or overlaps it so; +Infinity if never.
     */
    public static double timeToWall(int wall, double x, double y, double vx, double vy, double r, double rRate,
                                    double width, double height) {
        switch (wall) {
            case Boundary.LEFT: {
                double closing = rRate - vx;
                return closing > 0 ? Math.max(0, (x - r) / closing) : Double.POSITIVE_INFINITY;
            }
            case Boundary.RIGHT: {
                double closing = vx + rRate;
                return closing > 0 ? Math.max(0, (width - r - x) / closing) : Double.POSITIVE_INFINITY;
            }
            case Boundary.BOTTOM: {
                double closing = rRate - vy;
                return closing > 0 ? Math.max(0, (y - r) / closing) : Double.POSITIVE_INFINITY;
            }
            default: {
                double closing = vy + rRate;
                return closing > 0 ? Math.max(0, (height - r - y) / closing) : Double.POSITIVE_INFINITY;
            }
        }
    }

    /**
     * The normal velocity after a growing disc's surface bounces off wall {@code wall}: the surface's
     * speed toward the wall, v + rRate (v the component toward it), becomes -e times itself.
     *
     * @param normal the velocity component along the wall's axis (vx for left and right, vy otherwise)
     */
    public static double wallBounce(int wall, double normal, double rRate, double e) {
        boolean towardLow = wall == Boundary.LEFT || wall == Boundary.BOTTOM;
        // Toward a low wall the surface moves at -v + rRate; toward a high one at v + rRate.
        return towardLow ? -e * normal + (1 + e) * rRate : -e * normal - (1 + e) * rRate;
    }

    /**
     * Applies the impulse of a collision between growing discs i and j in contact now, both at the same
     * clock, velocities held as in {@link PairLaw#collide(double[], int, int, double[], int, int, double,
     * double, double, double, double)}: J = (1 + e)(u + sigmaRate) / (1/mi + 1/mj) along n, the unit
     * vector from i to j, with u = (vi - vj).n.
     *
     * @return the impulse J (0 if the surfaces were not approaching after all)
     */
    public static double collide(double[] vx, int ix, int jx, double[] vy, int iy, int jy, double invMi,
                                 double invMj, double dx, double dy, double e, double sigmaRate) {
        double dist = Math.sqrt(dx * dx + dy * dy);
        double nx = dx / dist;
        double ny = dy / dist;
        double w = (vx[ix] - vx[jx]) * nx + (vy[iy] - vy[jy]) * ny + sigmaRate;
        if (!(w > 0)) {
            return 0;
        }
        double impulse = (1 + e) * w / (invMi + invMj);
        vx[ix] -= impulse * invMi * nx;
        vy[iy] -= impulse * invMi * ny;
        vx[jx] += impulse * invMj * nx;
        vy[jy] += impulse * invMj * ny;
        return impulse;
    }
}
