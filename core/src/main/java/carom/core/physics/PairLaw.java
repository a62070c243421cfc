package carom.core.physics;

import carom.core.state.Discs;

/**
 * When two discs in straight-line relative motion touch, and what their contact does to them.
 *
 * <p>Prediction follows Bannerman, Lue and Lue (2014), "Stable algorithms for event-driven molecular
 * dynamics": with r = rj - ri, v = vj - vi, b = r.v and c = r.r - sigma^2,
 * <ul>
 *   <li>b >= 0 (receding or sliding): no event, even if they overlap by rounding, so an overlapped pair
 *       separates instead of colliding forever;</li>
 *   <li>c <= 0 and b < 0 (touching or overlapped, approaching): they collide now, unless the normal
 *       speed is within rounding of a tangential slide ({@link #closing});</li>
 *   <li>otherwise t = c / (-b + sqrt(b^2 - v^2 c)) if the discriminant is positive: the form that
 *       avoids cancellation between -b and the root.</li>
 * </ul>
 * A grazing pair (discriminant exactly 0) never exchanges momentum and gets no event.
 */
public final class PairLaw {
    private PairLaw() {
    }

    /**
     * Time from now until the pair first touches, or {@code +Infinity}.
     *
     * @param dx    x separation rj - ri (nearest image)
     * @param dy    y separation
     * @param dvx   x relative velocity vj - vi
     * @param dvy   y relative velocity
     * @param sigma contact distance Ri + Rj
     */
    public static double timeToContact(double dx, double dy, double dvx, double dvy, double sigma) {
        return timeToContactBefore(dx, dy, dvx, dvy, sigma, Double.POSITIVE_INFINITY);
    }

    /**
     * {@link #timeToContact}, or +Infinity for a contact that cannot come before {@code limit}, told
     * without a square root: for a pair apart (c > 0) and closing (b < 0) the contact time
     * c / (sqrt(b² − v²c) − b) is at least c / (−2b), so c ≥ −2b·limit rules it out. A prediction's scan
     * asks with its best time so far; at high density most closing neighbours are rejected so
     * (Smallenburg's EDMD code does the same; lab note smallenburg-2d).
     */
    public static double timeToContactBefore(double dx, double dy, double dvx, double dvy, double sigma,
                                             double limit) {
        double b = dx * dvx + dy * dvy;
        if (b >= 0) {
            return Double.POSITIVE_INFINITY;
        }
        double r2 = dx * dx + dy * dy;
        double c = r2 - sigma * sigma;
        double v2 = dvx * dvx + dvy * dvy;
        if (c <= 0) {
            return closing(b, r2, v2) ? 0 : Double.POSITIVE_INFINITY;
        }
        if (c >= -2 * b * limit) {
            return Double.POSITIVE_INFINITY;
        }
        double discriminant = b * b - v2 * c;
        if (discriminant <= 0) {
            return Double.POSITIVE_INFINITY;
        }
        return c / (Math.sqrt(discriminant) - b);
    }

    /**
     * Whether a touching pair with r.v = b is really closing: its normal speed must stand out from the
     * rounding of a tangential slide ({@link #GRAZING} of the relative speed). Otherwise the impulse
     * would be lost in rounding and the same pair would "collide now" again, forever.
     */
    public static boolean closing(double b, double r2, double v2) {
        return b < 0 && b * b > GRAZING * GRAZING * r2 * v2;
    }

    /** Relative normal speed below which touching discs are taken to slide past each other. */
    public static final double GRAZING = 1e-10;

    /**
     * Applies the impulse of a collision between i and j in contact now, both at the same clock.
     * J = (1+e) u / (1/mi + 1/mj) along n, the unit vector from i to j, with u = (vi - vj).n.
     *
     * @param dx separation rj - ri at contact (nearest image)
     * @param dy separation
     * @param e  restitution in force for this collision
     * @return the collision virial J * |r| (0 if the pair was not approaching after all)
     */
    public static double collide(Discs d, int i, int j, double dx, double dy, double e) {
        return collide(d.vx, i, j, d.vy, i, j, d.invMass[i], d.invMass[j], dx, dy, e);
    }

    /**
     * {@link #collide(Discs, int, int, double, double, double)} on velocities held anywhere: disc i's
     * at {@code vx[ix]}, {@code vy[iy]}, disc j's at {@code vx[jx]}, {@code vy[jy]} (columns of
     * {@link Discs}, or one array of per-disc records), so engines that keep discs in records apply
     * the impulse in place with the same arithmetic.
     */
    public static double collide(double[] vx, int ix, int jx, double[] vy, int iy, int jy, double invMi,
                                 double invMj, double dx, double dy, double e) {
        return collide(vx, ix, jx, vy, iy, jy, invMi, invMj, dx, dy, 0, e);
    }

    /**
     * The same collision with disc j seen through an image that moves {@code imageVx} faster along x
     * than j (a sliding image, {@link Boundary#imageVelocityX}; 0 otherwise): the impulse comes from the
     * image's relative velocity and changes both discs' own velocities.
     */
    public static double collide(double[] vx, int ix, int jx, double[] vy, int iy, int jy, double invMi,
                                 double invMj, double dx, double dy, double imageVx, double e) {
        double dist = Math.sqrt(dx * dx + dy * dy);
        double nx = dx / dist;
        double ny = dy / dist;
        double u = (vx[ix] - (vx[jx] + imageVx)) * nx + (vy[iy] - vy[jy]) * ny;
        if (!(u > 0)) {
            return 0;
        }
        double impulse = (1 + e) * u / (invMi + invMj);
        vx[ix] -= impulse * invMi * nx;
        vy[iy] -= impulse * invMi * ny;
        vx[jx] += impulse * invMj * nx;
        vy[jy] += impulse * invMj * ny;
        return impulse * dist;
    }
}
