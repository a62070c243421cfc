package carom.core.physics;

import carom.core.scene.Box;
import carom.core.state.Discs;

/**
 * What the box's edges do: reflecting walls, periodic wrap, or periodic wrap with sliding images
 * ({@link LeesEdwards}). Chosen once per scene; each run sees exactly one implementation, so the JIT
 * inlines these calls on the hot path.
 *
 * <p>Walls are numbered {@link #LEFT}, {@link #RIGHT}, {@link #BOTTOM}, {@link #TOP}; a periodic box has
 * none.
 *
 * <p>Pairs and images: the separation of a pair is taken from the raw difference of positions in the
 * box, rj - ri. Walls and periodic boxes see it through {@link #separationX} and {@link #separationY}
 * alone; where images slide, the x separation and the relative x velocity of the image depend on which
 * y image it is ({@link #imageSeparationX}, {@link #imageVelocityX}), and code that carries out or
 * predicts a pair goes through those (or {@link #timeToContact}).
 */
public abstract sealed class Boundary permits Boundary.Walls, Boundary.Periodic {
    public static final int LEFT = 0;
    public static final int RIGHT = 1;
    public static final int BOTTOM = 2;
    public static final int TOP = 3;

    public final double width;
    public final double height;

    Boundary(double width, double height) {
        this.width = width;
        this.height = height;
    }

    public static Boundary of(Box box) {
        if (box.sheared()) {
            return new LeesEdwards(box.width(), box.height(), box.shearRate());
        }
        return box.periodic() ? new Periodic(box.width(), box.height()) : new Walls(box.width(), box.height());
    }

    /** Number of walls a disc can hit (4 or 0). */
    public abstract int wallCount();

    /**
     * Time from now until a disc at (x, y) with velocity (vx, vy) and radius r, moving in a straight
     * line, touches wall {@code wall} while moving toward it; 0 if it already touches or overlaps it
     * and moves toward it; +Infinity if never.
     */
    public abstract double timeToWall(int wall, double x, double y, double vx, double vy, double r);

    /** Reverses disc i's velocity component normal to {@code wall}, scaled by restitution e. */
    public abstract void reflect(Discs d, int i, int wall, double e);

    /** Nearest-image separation along x (identity with walls). */
    public abstract double separationX(double dx);

    /** Nearest-image separation along y (identity with walls). */
    public abstract double separationY(double dy);

    /** Maps a position into the box along x (identity with walls). */
    public abstract double wrapX(double x);

    /** Maps a position into the box along y (identity with walls). */
    public abstract double wrapY(double y);

    public final boolean periodic() {
        return this instanceof Periodic;
    }

    /**
     * Time from local {@code now} until two discs in straight relative motion first touch while
     * approaching, or +Infinity: raw separation (dx, dy) = rj - ri, relative velocity (dvx, dvy) =
     * vj - vi, contact distance sigma. Here through the nearest image ({@link PairLaw#timeToContact});
     * where images slide, through every image the pair can meet.
     */
    public double timeToContact(double dx, double dy, double dvx, double dvy, double sigma, double now) {
        return PairLaw.timeToContact(separationX(dx), separationY(dy), dvx, dvy, sigma);
    }

    /**
     * The x separation from disc i to the nearest image of disc j at local {@code now}, for the raw
     * separation (dx, dy): {@link #separationX} unless images slide, where the image above or below is
     * shifted by the offset.
     */
    public double imageSeparationX(double dx, double dy, double now) {
        return separationX(dx);
    }

    /** How much faster along x the nearest image of j moves than j, for the raw y separation dy: 0 unless images slide. */
    public double imageVelocityX(double dy) {
        return 0;
    }

    /**
     * Brings disc i (its clock local {@code now}) back into the box: {@link #wrapX} and {@link #wrapY},
     * and where images slide, the shift and the change of x velocity of a crossing through the top or
     * bottom.
     */
    public void wrap(Discs d, int i, double now) {
        d.x[i] = wrapX(d.x[i]);
        d.y[i] = wrapY(d.y[i]);
    }

    /**
     * Tells a boundary whose images slide that local time 0 is absolute time {@code epoch} (engines call
     * it whenever they re-anchor clocks, and at their start); nothing elsewhere.
     */
    public void anchor(double epoch) {
    }

    /** Four reflecting walls around [0,width] x [0,height]. */
    public static final class Walls extends Boundary {
        Walls(double width, double height) {
            super(width, height);
        }

        @Override
        public int wallCount() {
            return 4;
        }

        @Override
        public double timeToWall(int wall, double x, double y, double vx, double vy, double r) {
            switch (wall) {
                case LEFT:
                    return vx < 0 ? Math.max(0, (x - r) / -vx) : Double.POSITIVE_INFINITY;
                case RIGHT:
                    return vx > 0 ? Math.max(0, (width - r - x) / vx) : Double.POSITIVE_INFINITY;
                case BOTTOM:
                    return vy < 0 ? Math.max(0, (y - r) / -vy) : Double.POSITIVE_INFINITY;
                default:
                    return vy > 0 ? Math.max(0, (height - r - y) / vy) : Double.POSITIVE_INFINITY;
            }
        }

        @Override
        public void reflect(Discs d, int i, int wall, double e) {
            if (wall == LEFT || wall == RIGHT) {
                d.vx[i] = -e * d.vx[i];
            } else {
                d.vy[i] = -e * d.vy[i];
            }
        }

        @Override
        public double separationX(double dx) {
            return dx;
        }

        @Override
        public double separationY(double dy) {
            return dy;
        }

        @Override
        public double wrapX(double x) {
            return x;
        }

        @Override
        public double wrapY(double y) {
            return y;
        }
    }

    /** Both axes wrap; separations are taken to the nearest image. */
    public static sealed class Periodic extends Boundary permits LeesEdwards {
        final double invWidth;
        final double invHeight;

        Periodic(double width, double height) {
            super(width, height);
            this.invWidth = 1 / width;
            this.invHeight = 1 / height;
        }

        @Override
        public int wallCount() {
            return 0;
        }

        @Override
        public double timeToWall(int wall, double x, double y, double vx, double vy, double r) {
            return Double.POSITIVE_INFINITY;
        }

        @Override
        public void reflect(Discs d, int i, int wall, double e) {
            throw new IllegalStateException("a periodic box has no walls");
        }

        @Override
        public double separationX(double dx) {
            return dx - width * Math.rint(dx * invWidth);
        }

        @Override
        public double separationY(double dy) {
            return dy - height * Math.rint(dy * invHeight);
        }

        @Override
        public double wrapX(double x) {
            return wrap(x, width, invWidth);
        }

        @Override
        public double wrapY(double y) {
            return wrap(y, height, invHeight);
        }

        private static double wrap(double v, double length, double invLength) {
            if (v >= 0 && v < length) {
                return v;
            }
            double w = v - length * Math.floor(v * invLength);
            // Rounding can land exactly on the far edge; the box is half-open.
            return w >= length || w < 0 ? 0 : w;
        }
    }
}
