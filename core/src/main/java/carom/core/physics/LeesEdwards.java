package carom.core.physics;

import carom.core.state.Discs;

/**
 * Lees-Edwards boundaries ("sliding brick"): a periodic box whose image above moves along x with
 * velocity {@link #imageSpeed} = shearRate·height relative to it, and the image below with the
 * opposite, so that the discs are sheared at the shear rate. At absolute time t the image above is
 * shifted by the offset {@code imageSpeed·t} (reduced into [0, width)) and the one below by minus that.
 * A disc that leaves through the top re-enters at the bottom shifted back by the offset, with its x
 * velocity reduced by the image speed (the reverse through the bottom, {@link #wrap}); pairs across the
 * top and bottom collide through the shifted image, with the image's velocity ({@link #imageVelocityX}).
 *
 * <p>Time: engines keep clocks local and re-anchor them; {@link #anchor} says which absolute time local
 * 0 is. The offset at the anchor is reduced from the absolute time exactly ({@link #offsetAt}), so it
 * stays exact to the last bit of the width however long a run is, and within one anchor the offset is
 * the anchor's plus {@code imageSpeed·now}.
 *
 * <p>Contacts ({@link #timeToContact}): relative to disc i, disc j has three y images (itself, the one
 * above, the one below), each a row of x images one width apart that move together. Across the top and
 * bottom the relative x speed includes the image speed, so a pair can meet another x image than its
 * nearest one long before either disc changes its own motion; every x image the pair can reach while
 * its y separation is within contact is tried in the order they arrive, and the first contact found is
 * the earliest of that row (a later image reaches the contact zone only after the earlier one has left
 * it). Straight relative motion only: the scene builder refuses gravity and growth in such a box.
 */
public final class LeesEdwards extends Boundary.Periodic {
    /** The shear rate, velocity difference per unit height. */
    public final double shearRate;
    /** The x velocity of the image above relative to the box: shearRate·height, rounded once. */
    public final double imageSpeed;
    /** Absolute time of local time 0, and the offset then, in [0, width). */
    private double epoch;
    private double offsetAtEpoch;

    /** Images tried per row at most: a row meets its contact after at most two misses (class comment). */
    private static final int IMAGES_PER_ROW = 8;

    LeesEdwards(double width, double height, double shearRate) {
        super(width, height);
        this.shearRate = shearRate;
        this.imageSpeed = shearRate * height;
    }

    @Override
    public void anchor(double newEpoch) {
        epoch = newEpoch;
        offsetAtEpoch = offsetAt(imageSpeed, newEpoch, width);
    }

    /** Absolute time of local time 0 ({@link #anchor}). */
    public double epoch() {
        return epoch;
    }

    /**
     * The x shift of the image above at local time {@code now}: the anchor's offset plus
     * {@code imageSpeed·now}, not reduced (every use takes it to the nearest image).
     */
    public double offset(double now) {
        return offsetAtEpoch + imageSpeed * now;
    }

    /**
     * (speed·time) mod width in [0, width), to the last bit of the width: the product is split exactly
     * into a double and its rounding error (fused multiply-add), the double is reduced exactly (the
     * floating-point remainder is exact), the error added back, and the sum brought into [0, width).
     */
    public static double offsetAt(double speed, double time, double width) {
        double product = speed * time;
        double error = Math.fma(speed, time, -product);
        double r = product % width + error;
        if (r < 0) {
            r += width;
        } else if (r >= width) {
            r -= width;
        }
        return r >= width || r < 0 ? 0 : r;
    }

    @Override
    public double timeToContact(double dx, double dy, double dvx, double dvy, double sigma, double now) {
        double shift = offset(now);
        double t = firstContactInRow(dx, dy, dvx, dvy, sigma);
        // j's image above (j near the bottom, i near the top), then the one below.
        t = Math.min(t, firstContactInRow(dx + shift, dy + height, dvx + imageSpeed, dvy, sigma));
        return Math.min(t, firstContactInRow(dx - shift, dy - height, dvx - imageSpeed, dvy, sigma));
    }

    /**
     * The earliest contact with the row of x images (x0 + m·width, y0) moving at (vx, vy) relative to
     * disc i, or +Infinity.
     */
    private double firstContactInRow(double x0, double y0, double vx, double vy, double sigma) {
        // The times [enter, leave] at which |y| <= sigma, where contact is possible.
        double enter;
        double leave;
        if (vy == 0) {
            if (!(Math.abs(y0) < sigma)) {
                return Double.POSITIVE_INFINITY;
            }
            enter = 0;
            leave = Double.POSITIVE_INFINITY;
        } else {
            double a = (-sigma - y0) / vy;
            double b = (sigma - y0) / vy;
            leave = Math.max(a, b);
            if (!(leave >= 0)) {
                return Double.POSITIVE_INFINITY;
            }
            enter = Math.max(0, Math.min(a, b));
        }
        if (vx == 0) {
            return PairLaw.timeToContact(separationX(x0), y0, vx, vy, sigma);
        }
        // Along the direction of motion: the image ahead of the contact zone is the first to arrive.
        double dir = vx > 0 ? 1 : -1;
        double along = dir * (x0 + vx * enter);
        double m = Math.ceil((sigma - along) / width) - 1;
        double reach = Math.abs(vx) * (leave - enter);
        for (int k = 0; k < IMAGES_PER_ROW; k++, m--) {
            if (along + m * width + reach <= -sigma) {
                return Double.POSITIVE_INFINITY;
            }
            double t = PairLaw.timeToContact(x0 + dir * m * width, y0, vx, vy, sigma);
            if (t < Double.POSITIVE_INFINITY) {
                return t;
            }
        }
        return Double.POSITIVE_INFINITY;
    }

    /** Which y image of j is nearest i for the raw y separation dy: +1 the image above, -1 below, 0 j itself. */
    private double imageRow(double dy) {
        return -Math.rint(dy * invHeight);
    }

    @Override
    public double imageSeparationX(double dx, double dy, double now) {
        double row = imageRow(dy);
        return separationX(row == 0 ? dx : dx + row * offset(now));
    }

    @Override
    public double imageVelocityX(double dy) {
        return imageRow(dy) * imageSpeed;
    }

    @Override
    public void wrap(Discs d, int i, double now) {
        double y = d.y[i];
        if (y >= height || y < 0) {
            // Images passed: 1 or more out through the top, -1 or fewer out through the bottom (never 0
            // by rounding, so that the shift goes with the wrap).
            double passed = y >= height ? Math.max(1, Math.floor(y / height)) : Math.min(-1, Math.floor(y / height));
            d.x[i] -= passed * offset(now);
            d.vx[i] -= passed * imageSpeed;
            y -= passed * height;
        }
        d.x[i] = wrapX(d.x[i]);
        d.y[i] = wrapY(y);
    }
}
