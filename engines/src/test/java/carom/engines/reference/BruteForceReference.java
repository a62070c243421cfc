package carom.engines.reference;

import carom.core.engine.SimulationStuckException;
import carom.core.observe.Observables;
import carom.core.physics.Boundary;
import carom.core.physics.Flight;
import carom.core.physics.PairLaw;
import carom.core.physics.Physics;
import carom.core.physics.RestRule;
import carom.core.physics.Restitution;
import carom.core.physics.Roughness;
import carom.core.physics.VibratingFloor;
import carom.core.scene.Scene;
import carom.core.state.Discs;

/**
 * The judge of every engine on small scenes: no grid, no queue, no lazy motion. Each iteration looks
 * at every pair and every wall, advances every disc to the earliest event and resolves it. O(N^2) per
 * event, so only for a few dozen discs. Shares only the two-body laws with the engines: how a disc
 * flies and when two discs or a disc and a wall meet ({@link Flight}, {@link PairLaw}, {@link Boundary}),
 * what a contact does ({@link Roughness#pair}: {@link PairLaw#collide}'s normal impulse and, for rough
 * discs, the tangential one; {@link Boundary#reflect} and {@link Roughness#wall}) and which restitution it
 * gets ({@link Restitution}), each of which has analytic tests of its own.
 *
 * <p>Every disc's clock is the absolute time of the last event (no epochs); periodic positions are
 * wrapped after every advance. Effects: gravity through {@code physics.flight}, restitution and the TC
 * model through {@code physics.restitution}, which is told of every collision of a mobile disc, rough
 * discs through {@code physics.roughness}.
 *
 * <p>Periodic boxes: predictions see each pair's nearest image at the time they are made, so the judge
 * never looks further ahead than a pair could move before another image might come into contact; when
 * nothing happens within that window it advances every disc to its end and looks again.
 *
 * <p>Lees-Edwards boxes ({@link Sliding}): the judge tests every image a pair can meet before the end,
 * three rows (j itself, its image above shifted by the offset with the image speed added to its x
 * velocity, its image below) of x images one width apart, without the boundary law the engines use;
 * a disc that leaves through the top or bottom re-enters with the shift and the change of velocity.
 *
 * <p>Resting contact: under gravity a disc that comes to rest on a wall, a fixed disc or a sleeping
 * disc ({@link RestRule}, the law the engines share) falls asleep: velocity 0, inverse mass 0 (so the
 * laws above treat it as fixed) until a disc that stays awake hits it, which wakes it. The judge keeps
 * its own sleep bookkeeping. It stops with {@link SimulationStuckException} when more than
 * {@code max(100000, 10 N)} collisions happen at one instant.
 */
public final class BruteForceReference {
    public record Result(Discs state, long pairCollisions, long wallCollisions) {
    }

    /** Scenes judged here are small and short; more events than this means a loop, not physics. */
    private static final long MAX_EVENTS = 10_000_000;

    private BruteForceReference() {
    }

    public static Result run(Scene scene, double until) {
        Discs d = scene.newDiscs();
        Physics physics = Physics.of(scene);
        Flight flight = physics.flight;
        Boundary boundary = physics.boundary;
        Boundary.Walls walls = boundary instanceof Boundary.Walls w ? w : null;
        Restitution restitution = physics.restitution;
        Roughness roughness = physics.roughness;
        double acceleration = flight.maxAcceleration();
        RestRule rest = new RestRule(scene.box(), scene.effects());
        double gx = scene.effects().gravityX();
        double gy = scene.effects().gravityY();
        double[] awakeInvMass = d.invMass.clone();
        Sliding sliding = scene.box().sheared() ? new Sliding(scene, until) : null;
        VibratingFloor floor = physics.floor;
        FloorSearch floorSearch = floor == null ? null : new FloorSearch(floor, flight, gy);
        long stuckLimit = Math.max(100_000L, 10L * d.n);
        // Periodic: a pair can meet another image than its nearest one only after their separation changed
        // by at least half the box minus the contact distance along some axis.
        double periodicLimit = boundary.periodic()
                ? 0.5 * Math.min(boundary.width, boundary.height) - 2 * d.maxRadius() : 0;
        long pairs = 0;
        long wallHits = 0;
        double now = 0;
        double lastTime = Double.NaN;
        long atLastTime = 0;
        for (long events = 0; ; events++) {
            if (events > MAX_EVENTS) {
                throw new IllegalStateException("brute-force reference: more than " + MAX_EVENTS + " events by t = " + now);
            }
            double best = Double.POSITIVE_INFINITY;
            int bestA = -1;
            int bestB = 0;
            for (int i = 0; i < d.n; i++) {
                if (walls != null && d.invMass[i] > 0) {
                    for (int w = 0; w < 4; w++) {
                        if (w == Boundary.BOTTOM && floor != null) {
                            continue;
                        }
                        double t = flight.timeToWall(d, i, w, now, walls);
                        if (t < best) {
                            best = t;
                            bestA = i;
                            bestB = -1 - w;
                        }
                    }
                }
                for (int j = i + 1; j < d.n; j++) {
                    double t = sliding != null ? sliding.timeToContact(d, i, j, now)
                            : flight.timeToContact(d, i, j, now, until, boundary);
                    if (t < best) {
                        best = t;
                        bestA = i;
                        bestB = j;
                    }
                }
            }
            if (floorSearch != null) {
                // The moving floor last, so that its fine search looks no further than every other event.
                double horizon = Math.min(best, until - now);
                for (int i = 0; i < d.n; i++) {
                    if (d.invMass[i] > 0) {
                        double t = floorSearch.firstHit(d, i, now, horizon);
                        if (t < best) {
                            best = t;
                            horizon = t;
                            bestA = i;
                            bestB = -1 - Boundary.BOTTOM;
                        }
                    }
                }
            }
            double next = now + best;
            if (periodicLimit > 0) {
                // Predictions see each pair's nearest image at now only; never look further than a pair
                // can move before another image could come into contact.
                double window = imageWindow(d, periodicLimit, acceleration);
                if (next > now + window && now + window < until) {
                    now += window;
                    advanceAll(d, flight, boundary, sliding, now);
                    events--;
                    continue;
                }
            }
            if (bestA < 0 || next > until) {
                advanceAll(d, flight, boundary, sliding, until);
                // Sleeping discs end at rest, with their own mass.
                System.arraycopy(awakeInvMass, 0, d.invMass, 0, d.n);
                return new Result(d, pairs, wallHits);
            }
            advanceAll(d, flight, boundary, sliding, next);
            now = next;
            if (now != lastTime) {
                lastTime = now;
                atLastTime = 0;
            } else if (++atLastTime > stuckLimit) {
                throw new SimulationStuckException(String.format(
                        "brute-force reference: more than %d collisions at the single instant t = %s, the last of disc %d",
                        stuckLimit, now, bestA));
            }
            if (bestB >= 0) {
                int a = bestA;
                int b = bestB;
                double dx = boundary.separationX(d.x[b] - d.x[a]);
                double dy = boundary.separationY(d.y[b] - d.y[a]);
                double imageVx = 0;
                if (sliding != null) {
                    int row = sliding.touchingRow(d, a, b, now);
                    dx = sliding.imageDx(d, a, b, row, now);
                    dy = d.y[b] + row * sliding.height - d.y[a];
                    imageVx = row * sliding.imageSpeed;
                }
                double e = restitution.pair(a, b, now);
                boolean aMobile = d.invMass[a] > 0;
                boolean bMobile = d.invMass[b] > 0;
                pairs++;
                if (acceleration > 0 && aMobile != bMobile) {
                    int m = aMobile ? a : b;
                    int support = aMobile ? b : a;
                    double dist = Math.sqrt(dx * dx + dy * dy);
                    double sign = aMobile ? 1 : -1;
                    if (rest.rests(now, sign * dx / dist, sign * dy / dist, d.vx[m], d.vy[m], gx, gy, dist, false)) {
                        fallAsleep(d, m);
                        restitution.collided(m, now);
                        continue;
                    }
                    if (awakeInvMass[support] > 0) {
                        d.invMass[support] = awakeInvMass[support];
                        aMobile = true;
                        bMobile = true;
                    }
                }
                roughness.pair(d, a, b, dx, dy, imageVx, e);
                if (aMobile) {
                    restitution.collided(a, now);
                }
                if (bMobile) {
                    restitution.collided(b, now);
                }
            } else {
                int wall = -1 - bestB;
                double e = restitution.wall(bestA, now);
                wallHits++;
                double nx = wall == Boundary.LEFT ? -1 : (wall == Boundary.RIGHT ? 1 : 0);
                double ny = wall == Boundary.BOTTOM ? -1 : (wall == Boundary.TOP ? 1 : 0);
                if (floor != null && wall == Boundary.BOTTOM) {
                    // The floor's law: onto the floor, the rebound in its frame; nothing sleeps on it.
                    d.y[bestA] = Math.max(d.y[bestA], floor.lowestCentre(d.radius[bestA], now));
                    d.vy[bestA] = floor.rebound(d.vy[bestA], now, e);
                    roughness.wall(d.vx, bestA, d.vy, bestA, wall, d.spins, bestA);
                } else if (acceleration > 0
                        && rest.rests(now, nx, ny, d.vx[bestA], d.vy[bestA], gx, gy, Double.POSITIVE_INFINITY, false)) {
                    fallAsleep(d, bestA);
                } else {
                    boundary.reflect(d, bestA, wall, e);
                    roughness.wall(d.vx, bestA, d.vy, bestA, wall, d.spins, bestA);
                }
                restitution.collided(bestA, now);
            }
        }
    }

    /**
     * A time within which no pair's separation changes by {@code limit / 2} or more along an axis: two
     * discs at speeds up to vmax under an acceleration difference up to {@code acceleration} (a mobile
     * disc against a fixed one) drift apart by at most 2 vmax t + acceleration t^2 / 2.
     */
    private static double imageWindow(Discs d, double limit, double acceleration) {
        double vmax = d.maxSpeed();
        double distance = 0.5 * limit;
        return 2 * distance / (2 * vmax + Math.sqrt(4 * vmax * vmax + 2 * acceleration * distance));
    }

    /** Disc i, at its contact with a support, falls asleep there: at rest (not spinning) and immovable. */
    private static void fallAsleep(Discs d, int i) {
        if (d.spins != null) {
            d.spins.omega[i] = 0;
        }
        d.vx[i] = 0;
        d.vy[i] = 0;
        d.invMass[i] = 0;
    }

    /**
     * Every disc to absolute time {@code time} (its clock becomes {@code time}), periodic positions
     * wrapped (in a Lees-Edwards box, with the shift and velocity change of the top and bottom).
     */
    private static void advanceAll(Discs d, Flight flight, Boundary boundary, Sliding sliding, double time) {
        for (int i = 0; i < d.n; i++) {
            flight.advance(d, i, time);
            if (sliding != null) {
                sliding.reenter(d, i, time);
            }
            d.x[i] = boundary.wrapX(d.x[i]);
            d.y[i] = boundary.wrapY(d.y[i]);
        }
    }

    /**
     * The judge's own Lees-Edwards images: the image above j is at (xj + s t, yj + H) with x velocity
     * vxj + s, s = shearRate * height, at absolute time t (no reduction: the judge's runs are short);
     * the image below at minus that.
     */
    private static final class Sliding {
        final double width;
        final double height;
        final double imageSpeed;
        final double until;

        Sliding(Scene scene, double until) {
            this.width = scene.box().width();
            this.height = scene.box().height();
            this.imageSpeed = scene.box().shearRate() * height;
            this.until = until;
        }

        /** The earliest contact of i with any image of j before the end, from absolute time now. */
        double timeToContact(Discs d, int i, int j, double now) {
            double best = Double.POSITIVE_INFINITY;
            double sigma = d.radius[i] + d.radius[j];
            double dvy = d.vy[j] - d.vy[i];
            for (int row = -1; row <= 1; row++) {
                double dx = d.x[j] + row * imageSpeed * now - d.x[i];
                double dy = d.y[j] + row * height - d.y[i];
                double dvx = d.vx[j] + row * imageSpeed - d.vx[i];
                double reach = Math.abs(dvx) * (until - now) + sigma;
                long lo = (long) Math.floor((-dx - reach) / width) - 1;
                long hi = (long) Math.ceil((-dx + reach) / width) + 1;
                for (long m = lo; m <= hi; m++) {
                    best = Math.min(best, PairLaw.timeToContact(dx + m * width, dy, dvx, dvy, sigma));
                }
            }
            return best;
        }

        /** The y image row of j that touches i now (the nearest one). */
        int touchingRow(Discs d, int a, int b, double now) {
            int row = 0;
            double nearest = Double.POSITIVE_INFINITY;
            for (int r = -1; r <= 1; r++) {
                double dx = imageDx(d, a, b, r, now);
                double dy = d.y[b] + r * height - d.y[a];
                if (dx * dx + dy * dy < nearest) {
                    nearest = dx * dx + dy * dy;
                    row = r;
                }
            }
            return row;
        }

        /** The x separation from a to the nearest x image of b's image in {@code row}. */
        double imageDx(Discs d, int a, int b, int row, double now) {
            double dx = d.x[b] + row * imageSpeed * now - d.x[a];
            return dx - width * Math.rint(dx / width);
        }

        /** Disc i out through the top comes back at the bottom shifted back with vx - s, and the reverse. */
        void reenter(Discs d, int i, double now) {
            if (d.y[i] >= height) {
                d.y[i] -= height;
                d.x[i] -= imageSpeed * now;
                d.vx[i] -= imageSpeed;
            } else if (d.y[i] < 0) {
                d.y[i] += height;
                d.x[i] += imageSpeed * now;
                d.vx[i] += imageSpeed;
            }
        }
    }

    /**
     * The judge's own search for a disc's first contact with the vibrated floor: the gap
     * y(t) − R − A·sin(ω·t), from {@link Flight#y} and the floor's height, sampled on a fine grid of
     * {@link #SAMPLES_PER_PERIOD} points a period, the first interval where it falls from above 0 to 0 or
     * below bisected to the last bit. Discs whose lowest point stays above the floor's reach within the
     * horizon are skipped. A contact now (gap at most 0 and closing) is taken at once. No bound on the
     * gap's curvature is used: this is independent of the engines' search.
     */
    private static final class FloorSearch {
        static final int SAMPLES_PER_PERIOD = 20_000;
        final VibratingFloor floor;
        final Flight flight;
        final double gy;
        final double step;

        FloorSearch(VibratingFloor floor, Flight flight, double gy) {
            this.floor = floor;
            this.flight = flight;
            this.gy = gy;
            this.step = 2 * Math.PI / floor.omega / SAMPLES_PER_PERIOD;
        }

        double gap(Discs d, int i, double time) {
            return flight.y(d, i, time) - d.radius[i] - floor.height(time);
        }

        /** The offset from {@code now} of disc i's first floor contact within {@code horizon}, or +Infinity. */
        double firstHit(Discs d, int i, double now, double horizon) {
            double y = flight.y(d, i, now) - d.radius[i];
            double vy = flight.vy(d, i, now);
            // The lowest point of the disc's parabola within the horizon, against the floor's highest.
            double lowest = Math.min(y, y + vy * horizon + 0.5 * gy * horizon * horizon);
            if (gy > 0 && vy < 0 && -vy / gy < horizon) {
                lowest = Math.min(lowest, y - vy * vy / (2 * gy));
            }
            if (lowest > floor.amplitude) {
                return Double.POSITIVE_INFINITY;
            }
            double before = gap(d, i, now);
            if (before <= 0 && vy - floor.velocity(now) < 0) {
                return 0;
            }
            for (long k = 1; ; k++) {
                double t = Math.min(k * step, horizon);
                double g = gap(d, i, now + t);
                if (g <= 0 && before > 0) {
                    double lo = (k - 1) * step;
                    double hi = t;
                    for (int b = 0; b < 200; b++) {
                        double mid = 0.5 * (lo + hi);
                        if (mid <= lo || mid >= hi) {
                            break;
                        }
                        if (gap(d, i, now + mid) > 0) {
                            lo = mid;
                        } else {
                            hi = mid;
                        }
                    }
                    return hi;
                }
                if (t >= horizon) {
                    return Double.POSITIVE_INFINITY;
                }
                before = g;
            }
        }
    }

    public static double kineticEnergy(Result r) {
        return Observables.kineticEnergy(r.state());
    }

    /** Kinetic plus gravity's potential energy of the mobile discs (walls boxes: positions are not wrapped). */
    public static double mechanicalEnergy(Scene scene, Discs d) {
        Flight flight = Physics.of(scene).flight;
        double energy = 0;
        for (int i = 0; i < d.n; i++) {
            if (d.invMass[i] > 0) {
                energy += 0.5 * (d.vx[i] * d.vx[i] + d.vy[i] * d.vy[i]) / d.invMass[i]
                        + flight.potentialEnergy(d, i, d.t[i]);
            }
        }
        return energy;
    }
}
