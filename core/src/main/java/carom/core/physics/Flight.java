package carom.core.physics;

import carom.core.state.Discs;

/**
 * How a disc moves between events. Motion is lazy: (x, y, vx, vy) hold at the disc's own clock
 * {@code t[i]}; {@link #advance} brings them to a later time. Chosen once per scene.
 */
public abstract sealed class Flight permits Flight.Straight {
    public static final Flight STRAIGHT = new Straight();

    /** Moves disc i to {@code time} (its clock becomes {@code time}). */
    public abstract void advance(Discs d, int i, double time);

    /** Disc i's x position at {@code time}, without moving it. */
    public abstract double x(Discs d, int i, double time);

    /** Disc i's y position at {@code time}, without moving it. */
    public abstract double y(Discs d, int i, double time);

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
    }
}
