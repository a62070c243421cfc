package carom.core.physics;

import carom.core.scene.Effects;
import carom.core.state.Discs;

/**
 * How discs move between events, and therefore when they meet each other and the walls. Motion is
 * lazy: (x, y, vx, vy) hold at the disc's own clock {@code t[i]}; {@link #advance} brings them to a
 * later time. Chosen once per scene ({@link Physics#of}): a scene without gravity runs
 * {@link Straight}, which knows nothing of gravity.
 *
 * <p>Times passed in are the engine's local times (disc clocks); times returned by the predictions
 * are offsets from {@code now}, or {@code +Infinity}.
 */
public abstract sealed class Flight permits Flight.Straight, Flight.Parabolic {
    public static final Flight STRAIGHT = new Straight();

    /** The flight {@code effects} names: {@link Parabolic} under gravity, else {@link #STRAIGHT}. */
    public static Flight of(Effects effects) {
        return effects.hasGravity() ? parabolic(effects.gravityX(), effects.gravityY()) : STRAIGHT;
    }

    public static Flight parabolic(double gx, double gy) {
        return new Parabolic(gx, gy);
    }

    /** Moves disc i to {@code time} (its clock becomes {@code time}). */
    public abstract void advance(Discs d, int i, double time);

    /** Disc i's x position at {@code time}, without moving it. */
    public abstract double x(Discs d, int i, double time);

    /** Disc i's y position at {@code time}, without moving it. */
    public abstract double y(Discs d, int i, double time);

    /** Disc i's x velocity at {@code time}. */
    public abstract double vx(Discs d, int i, double time);

    /** Disc i's y velocity at {@code time}. */
    public abstract double vy(Discs d, int i, double time);

    /** Largest acceleration any disc has between events (0 without gravity). */
    public abstract double maxAcceleration();

    /** Potential energy of disc i at {@code time} in the external field (0 without gravity). */
    public abstract double potentialEnergy(Discs d, int i, double time);

    /**
     * Time from {@code now} until discs i and j first touch while approaching, looking no further than
     * {@code horizon} (a local time); +Infinity if not by then.
     */
    public abstract double timeToContact(Discs d, int i, int j, double now, double horizon, Boundary boundary);

    /** Time from {@code now} until disc i touches {@code wall} while moving toward it, or +Infinity. */
    public abstract double timeToWall(Discs d, int i, int wall, double now, Boundary.Walls walls);

    /**
     * Time from {@code now} until disc i's centre leaves the slab lo <= x <= hi (a cell's column), or
     * +Infinity. For engines that schedule cell crossings.
     */
    public abstract double timeToLeaveX(Discs d, int i, double now, double lo, double hi);

    /** Same along y (a cell's row). */
    public abstract double timeToLeaveY(Discs d, int i, double now, double lo, double hi);

    /** Free flight without forces: r(t) = r0 + v0 (t - t0). */
    public static final class Straight extends Flight {
        private Straight() {
        }

        @Override
        public void advance(Discs d, int i, double time) {
            double dt = time - d.t[i];
            d.x[i] += d.vx[i] * dt;
            d.y[i] += d.vy[i] * dt;
            d.t[i] = time;
        }

        @Override
        public double x(Discs d, int i, double time) {
            return d.x[i] + d.vx[i] * (time - d.t[i]);
        }

        @Override
        public double y(Discs d, int i, double time) {
            return d.y[i] + d.vy[i] * (time - d.t[i]);
        }

        @Override
        public double vx(Discs d, int i, double time) {
            return d.vx[i];
        }

        @Override
        public double vy(Discs d, int i, double time) {
            return d.vy[i];
        }

        @Override
        public double maxAcceleration() {
            return 0;
        }

        @Override
        public double potentialEnergy(Discs d, int i, double time) {
            return 0;
        }

        @Override
        public double timeToContact(Discs d, int i, int j, double now, double horizon, Boundary boundary) {
            return boundary.timeToContact(x(d, j, now) - x(d, i, now), y(d, j, now) - y(d, i, now),
                    d.vx[j] - d.vx[i], d.vy[j] - d.vy[i], d.radius[i] + d.radius[j], now);
        }

        @Override
        public double timeToWall(Discs d, int i, int wall, double now, Boundary.Walls walls) {
            return walls.timeToWall(wall, x(d, i, now), y(d, i, now), d.vx[i], d.vy[i], d.radius[i]);
        }

        @Override
        public double timeToLeaveX(Discs d, int i, double now, double lo, double hi) {
            return leave(x(d, i, now), d.vx[i], lo, hi);
        }

        @Override
        public double timeToLeaveY(Discs d, int i, double now, double lo, double hi) {
            return leave(y(d, i, now), d.vy[i], lo, hi);
        }

        private static double leave(double p, double v, double lo, double hi) {
            if (v > 0) {
                return Math.max(0, (hi - p) / v);
            }
            if (v < 0) {
                return Math.max(0, (lo - p) / v);
            }
            return Double.POSITIVE_INFINITY;
        }
    }

    /**
     * Uniform gravity g on mobile discs: r(t) = r0 + v0 (t - t0) + g (t - t0)^2 / 2. Fixed discs never
     * move. Two mobile discs share the acceleration, so their relative motion stays linear; a mobile
     * disc and a fixed one, or a disc and a wall, meet at the root of a polynomial.
     */
    public static final class Parabolic extends Flight {
        private final double gx;
        private final double gy;

        private Parabolic(double gx, double gy) {
            this.gx = gx;
            this.gy = gy;
        }

        @Override
        public void advance(Discs d, int i, double time) {
            double dt = time - d.t[i];
            d.t[i] = time;
            if (d.invMass[i] == 0) {
                return;
            }
            d.x[i] += (d.vx[i] + 0.5 * gx * dt) * dt;
            d.y[i] += (d.vy[i] + 0.5 * gy * dt) * dt;
            d.vx[i] += gx * dt;
            d.vy[i] += gy * dt;
        }

        @Override
        public double x(Discs d, int i, double time) {
            double dt = time - d.t[i];
            return d.invMass[i] == 0 ? d.x[i] : d.x[i] + (d.vx[i] + 0.5 * gx * dt) * dt;
        }

        @Override
        public double y(Discs d, int i, double time) {
            double dt = time - d.t[i];
            return d.invMass[i] == 0 ? d.y[i] : d.y[i] + (d.vy[i] + 0.5 * gy * dt) * dt;
        }

        @Override
        public double vx(Discs d, int i, double time) {
            return d.invMass[i] == 0 ? 0 : d.vx[i] + gx * (time - d.t[i]);
        }

        @Override
        public double vy(Discs d, int i, double time) {
            return d.invMass[i] == 0 ? 0 : d.vy[i] + gy * (time - d.t[i]);
        }

        @Override
        public double maxAcceleration() {
            return Math.hypot(gx, gy);
        }

        @Override
        public double potentialEnergy(Discs d, int i, double time) {
            return d.invMass[i] == 0 ? 0 : -(gx * x(d, i, time) + gy * y(d, i, time)) / d.invMass[i];
        }

        @Override
        public double timeToContact(Discs d, int i, int j, double now, double horizon, Boundary boundary) {
            boolean iFixed = d.invMass[i] == 0;
            boolean jFixed = d.invMass[j] == 0;
            if (iFixed && jFixed) {
                return Double.POSITIVE_INFINITY;
            }
            double xi = x(d, i, now);
            double yi = y(d, i, now);
            double dx = boundary.separationX(x(d, j, now) - xi);
            double dy = boundary.separationY(y(d, j, now) - yi);
            double sigma = d.radius[i] + d.radius[j];
            if (!iFixed && !jFixed) {
                return PairLaw.timeToContact(dx, dy, vx(d, j, now) - vx(d, i, now), vy(d, j, now) - vy(d, i, now), sigma);
            }
            // Relative to the fixed disc, the mobile one flies a parabola.
            int mobile = iFixed ? j : i;
            double sign = iFixed ? 1 : -1;
            return GravityContact.firstContact(sign * dx, sign * dy, vx(d, mobile, now), vy(d, mobile, now), gx, gy,
                    sigma, horizon - now);
        }

        @Override
        public double timeToLeaveX(Discs d, int i, double now, double lo, double hi) {
            return d.invMass[i] == 0 ? Double.POSITIVE_INFINITY : leave(x(d, i, now), vx(d, i, now), gx, lo, hi);
        }

        @Override
        public double timeToLeaveY(Discs d, int i, double now, double lo, double hi) {
            return d.invMass[i] == 0 ? Double.POSITIVE_INFINITY : leave(y(d, i, now), vy(d, i, now), gy, lo, hi);
        }

        private static double leave(double p, double v, double a, double lo, double hi) {
            return Math.min(GravityContact.firstWallHit(hi - p, -v, -a), GravityContact.firstWallHit(p - lo, v, a));
        }

        @Override
        public double timeToWall(Discs d, int i, int wall, double now, Boundary.Walls walls) {
            if (d.invMass[i] == 0) {
                // Fixed, or asleep on the floor: gravity does not move it into a wall.
                return Double.POSITIVE_INFINITY;
            }
            double x = x(d, i, now);
            double y = y(d, i, now);
            double vx = vx(d, i, now);
            double vy = vy(d, i, now);
            double r = d.radius[i];
            // h = distance from the contact position, positive inside the box; the disc hits when h
            // falls to 0 while h' < 0.
            return switch (wall) {
                case Boundary.LEFT -> GravityContact.firstWallHit(x - r, vx, gx);
                case Boundary.RIGHT -> GravityContact.firstWallHit(walls.width - r - x, -vx, -gx);
                case Boundary.BOTTOM -> GravityContact.firstWallHit(y - r, vy, gy);
                default -> GravityContact.firstWallHit(walls.height - r - y, -vy, -gy);
            };
        }
    }
}
