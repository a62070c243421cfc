package carom.core.physics;

import carom.core.scene.Effects;

/**
 * How radii change in time, chosen once per scene ({@link #of}, as {@link Physics#of} chooses every
 * law): {@link #RIGID} radii, or linear growth at rate G (the {@code growth} effect, the
 * Lubachevsky-Stillinger protocol), where a disc of radius R(0) has radius R(0) s at scale s = 1 + G t,
 * t the absolute time. Growth overrides only the primitives that see the radii move, as DynamO's
 * {@code DynCompression} overrides those of its Newtonian dynamics: a pair's contact time
 * ({@link #pairContact}), a wall's ({@link #wallContact}), the pair impulse ({@link #collidePair}) and
 * the wall bounce ({@link #bounce}). They take sizes at scale 1 (R(0), sigma0 = Ri(0) + Rj(0)) and the
 * scale now, which a run keeps on its own clock; with {@link #RIGID} they are exactly the rigid
 * primitives ({@link PairLaw}, {@link Boundary.Walls}), to the bit. An engine takes the law once and
 * each call site then sees one implementation.
 *
 * <p>The static methods are the growing primitives themselves, in the sizes and rates of now: a pair's
 * contact distance is sigma + sigmaRate * t from now, a disc's radius r + rRate * t.
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
public abstract sealed class GrowthLaw permits GrowthLaw.Rigid, GrowthLaw.Linear {
    /** Radii that never change: the rigid primitives. */
    public static final GrowthLaw RIGID = new Rigid();

    private GrowthLaw() {
    }

    /** The law {@code effects} names: {@link #linear} at its growth rate, or {@link #RIGID}. */
    public static GrowthLaw of(Effects effects) {
        return effects.grows() ? linear(effects.growth()) : RIGID;
    }

    /** Radii R(0)(1 + G t) at absolute time t, for a finite rate G > 0. */
    public static GrowthLaw linear(double rate) {
        if (!(rate > 0 && rate < Double.POSITIVE_INFINITY)) {
            throw new IllegalArgumentException("growth rate must be a finite number > 0, got " + rate);
        }
        return new Linear(rate);
    }

    /** The growth rate G (0 for {@link #RIGID}): the scale's change per unit time. */
    public abstract double rate();

    /** Whether radii change in time. */
    public final boolean grows() {
        return this instanceof Linear;
    }

    /**
     * Time from now until the pair first touches, or {@code +Infinity}: {@link #timeToContact} at
     * contact distance sigma0 * scale growing at sigma0 * rate, or {@link PairLaw#timeToContact} at sigma0.
     *
     * @param sigma0 the contact distance at scale 1, Ri(0) + Rj(0)
     * @param scale  the radii's scale now (1 when rigid)
     */
    public abstract double pairContact(double dx, double dy, double dvx, double dvy, double sigma0, double scale);

    /**
     * Time from now until a disc of radius r0 * scale at (x, y) with velocity (vx, vy) touches wall
     * {@code wall} of {@code walls} while closing on it ({@link #timeToWall}, or
     * {@link Boundary.Walls#timeToWall} at r0).
     */
    public abstract double wallContact(int wall, double x, double y, double vx, double vy, double r0, double scale,
                                       Boundary.Walls walls);

    /**
     * Applies the impulse of a pair collision, velocities held as in {@link PairLaw#collide(double[], int,
     * int, double[], int, int, double, double, double, double, double)} ({@link #collide} with sigmaRate
     * sigma0 * rate, or that rigid collision).
     *
     * @return the collision virial J * |r| (0 if the surfaces were not approaching after all)
     */
    public abstract double collidePair(double[] vx, int ix, int jx, double[] vy, int iy, int jy, double invMi,
                                       double invMj, double dx, double dy, double e, double sigma0);

    /**
     * The normal velocity after a disc of radius r0 at scale 1 bounces off wall {@code wall} with
     * restitution e ({@link #wallBounce} at rRate r0 * rate, or -e times it when rigid).
     */
    public abstract double bounce(int wall, double normal, double r0, double e);

    static final class Rigid extends GrowthLaw {
        @Override
        public double rate() {
            return 0;
        }

        @Override
        public double pairContact(double dx, double dy, double dvx, double dvy, double sigma0, double scale) {
            return PairLaw.timeToContact(dx, dy, dvx, dvy, sigma0);
        }

        @Override
        public double wallContact(int wall, double x, double y, double vx, double vy, double r0, double scale,
                                  Boundary.Walls walls) {
            return walls.timeToWall(wall, x, y, vx, vy, r0);
        }

        @Override
        public double collidePair(double[] vx, int ix, int jx, double[] vy, int iy, int jy, double invMi,
                                  double invMj, double dx, double dy, double e, double sigma0) {
            return PairLaw.collide(vx, ix, jx, vy, iy, jy, invMi, invMj, dx, dy, e);
        }

        @Override
        public double bounce(int wall, double normal, double r0, double e) {
            return -e * normal;
        }
    }

    static final class Linear extends GrowthLaw {
        private final double rate;

        private Linear(double rate) {
            this.rate = rate;
        }

        @Override
        public double rate() {
            return rate;
        }

        @Override
        public double pairContact(double dx, double dy, double dvx, double dvy, double sigma0, double scale) {
            return timeToContact(dx, dy, dvx, dvy, sigma0 * scale, sigma0 * rate);
        }

        @Override
        public double wallContact(int wall, double x, double y, double vx, double vy, double r0, double scale,
                                  Boundary.Walls walls) {
            return timeToWall(wall, x, y, vx, vy, r0 * scale, r0 * rate, walls.width, walls.height);
        }

        @Override
        public double collidePair(double[] vx, int ix, int jx, double[] vy, int iy, int jy, double invMi,
                                  double invMj, double dx, double dy, double e, double sigma0) {
            double impulse = collide(vx, ix, jx, vy, iy, jy, invMi, invMj, dx, dy, e, sigma0 * rate);
            return impulse * Math.sqrt(dx * dx + dy * dy);
        }

        @Override
        public double bounce(int wall, double normal, double r0, double e) {
            return wallBounce(wall, normal, r0 * rate, e);
        }
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
