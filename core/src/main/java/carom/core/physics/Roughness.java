package carom.core.physics;

import carom.core.scene.Effects;
import carom.core.state.Discs;
import carom.core.state.Spins;

/**
 * What a contact does along its tangent, chosen once per scene: {@link #SMOOTH} (frictionless discs:
 * only the normal impulse of {@link PairLaw#collide}, the rotation neither read nor kept) or rough
 * discs with a tangential restitution β (Walton's model, as Luding, Huthmann, McNamara and Zippelius,
 * Phys. Rev. E 58, 3416, 1998, use it for hard discs): the relative velocity of the two surfaces at the
 * contact point, g = (vi − vj) + (ωi Ri + ωj Rj) t with t the tangent (n rotated a quarter turn
 * counter-clockwise, n the unit vector from i to j), has its tangential part turned into −β times
 * itself, and the tangential impulse turns both discs. β = −1 leaves the surfaces sliding (smooth),
 * β = +1 reverses them (perfectly rough); both keep the kinetic energy, translational plus rotational,
 * of an elastic collision. A wall is a surface of infinite mass that does not turn.
 *
 * <p>Implementation notes. With moments Ii = qi mi Ri², the tangential impulse on i is −Jt·t with
 * Jt = (1 + β) gt / (1/mi (1 + 1/qi) + 1/mj (1 + 1/qj)) (a fixed disc's terms are 0); then
 * Δωi = −Jt/(qi mi Ri) and Δωj = −Jt/(qj mj Rj). The normal impulse is {@link PairLaw#collide}'s, with
 * gt taken before it (the normal impulse leaves gt alone). At a wall, Jt/m = (1 + β) gt q/(1 + q),
 * whatever the mass.
 */
public abstract sealed class Roughness permits Roughness.Smooth, Roughness.Rough {
    /** Frictionless discs: the normal impulse only. */
    public static final Roughness SMOOTH = new Smooth();

    /** The roughness {@code effects} names: {@link #SMOOTH} unless it has a tangential restitution above −1. */
    public static Roughness of(Effects effects) {
        return effects.rough() ? new Rough(effects.tangentialRestitution()) : SMOOTH;
    }

    /**
     * Applies the collision of discs i and j in contact now, velocities held as in
     * {@link PairLaw#collide(double[], int, int, double[], int, int, double, double, double, double, double)},
     * their rotation in {@code spins} at i and j (null for smooth discs), disc j seen through an image
     * that moves {@code imageVx} faster along x (a sliding image, {@link Boundary#imageVelocityX}; 0
     * otherwise).
     *
     * @return the collision virial Jn·|r| (0 if the pair was not approaching after all)
     */
    public abstract double pair(double[] vx, int ix, int jx, double[] vy, int iy, int jy, double invMi, double invMj,
                                double dx, double dy, double imageVx, double e, Spins spins, int i, int j);

    /** {@link #pair} on the discs of {@code d} (its {@link Discs#spins} for the rotation). */
    public final double pair(Discs d, int i, int j, double dx, double dy, double imageVx, double e) {
        return pair(d.vx, i, j, d.vy, i, j, d.invMass[i], d.invMass[j], dx, dy, imageVx, e, d.spins, i, j);
    }

    /**
     * The tangential part of disc i's collision with wall {@code wall}, its velocity at {@code vx[ix]},
     * {@code vy[iy]} and its rotation at {@code spins[i]}; the normal part is {@link Boundary#reflect}'s,
     * before or after this (neither reads the other's component).
     */
    public abstract void wall(double[] vx, int ix, double[] vy, int iy, int wall, Spins spins, int i);

    /** The tangential restitution β: −1 for smooth discs. */
    public abstract double tangentialRestitution();

    static final class Smooth extends Roughness {
        @Override
        public double pair(double[] vx, int ix, int jx, double[] vy, int iy, int jy, double invMi, double invMj,
                           double dx, double dy, double imageVx, double e, Spins spins, int i, int j) {
            return PairLaw.collide(vx, ix, jx, vy, iy, jy, invMi, invMj, dx, dy, imageVx, e);
        }

        @Override
        public void wall(double[] vx, int ix, double[] vy, int iy, int wall, Spins spins, int i) {
        }

        @Override
        public double tangentialRestitution() {
            return -1;
        }
    }

    static final class Rough extends Roughness {
        private final double beta;

        Rough(double beta) {
            this.beta = beta;
        }

        @Override
        public double tangentialRestitution() {
            return beta;
        }

        @Override
        public double pair(double[] vx, int ix, int jx, double[] vy, int iy, int jy, double invMi, double invMj,
                           double dx, double dy, double imageVx, double e, Spins spins, int i, int j) {
            double dist = Math.sqrt(dx * dx + dy * dy);
            // The tangent t = (−ny, nx); the surfaces' relative velocity along it, before the impulse.
            double tx = -dy / dist;
            double ty = dx / dist;
            double[] omega = spins.omega;
            double[] radius = spins.radius;
            double gt = (vx[ix] - (vx[jx] + imageVx)) * tx + (vy[iy] - vy[jy]) * ty + omega[i] * radius[i] + omega[j] * radius[j];
            double virial = PairLaw.collide(vx, ix, jx, vy, iy, jy, invMi, invMj, dx, dy, imageVx, e);
            if (virial == 0) {
                return 0;
            }
            double turnI = invMi / spins.inertia[i];
            double turnJ = invMj / spins.inertia[j];
            double jt = (1 + beta) * gt / (invMi + invMj + turnI + turnJ);
            vx[ix] -= jt * invMi * tx;
            vy[iy] -= jt * invMi * ty;
            vx[jx] += jt * invMj * tx;
            vy[jy] += jt * invMj * ty;
            omega[i] -= jt * turnI / radius[i];
            omega[j] -= jt * turnJ / radius[j];
            return virial;
        }

        @Override
        public void wall(double[] vx, int ix, double[] vy, int iy, int wall, Spins spins, int i) {
            // The tangent t = ẑ × n of the wall's outward normal n: left (0, −1), right (0, 1),
            // bottom (1, 0), top (−1, 0).
            boolean alongX = wall == Boundary.BOTTOM || wall == Boundary.TOP;
            double sign = wall == Boundary.LEFT || wall == Boundary.TOP ? -1 : 1;
            double q = spins.inertia[i];
            double r = spins.radius[i];
            double gt = sign * (alongX ? vx[ix] : vy[iy]) + spins.omega[i] * r;
            double change = (1 + beta) * gt / (1 + q);
            if (alongX) {
                vx[ix] -= sign * change * q;
            } else {
                vy[iy] -= sign * change * q;
            }
            spins.omega[i] -= change / r;
        }
    }
}
