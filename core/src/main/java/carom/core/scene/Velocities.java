package carom.core.scene;

import carom.core.BadInputException;
import carom.core.state.Discs;
import java.util.List;
import java.util.SplittableRandom;

/**
 * Draws a generate block's velocities (discs [offset, offset + count), species and masses set),
 * components disc by disc in id order; fixed discs stay at rest and draw nothing.
 *
 * <p>Maxwell: Gaussian components with variance kT/m, shifted to zero total momentum and scaled so
 * the block's kinetic energy is exactly {@code count · temperature} (count = its mobile discs). A
 * block of equal masses draws unit Gaussians and shifts by their mean, the same numbers in the same
 * order as before mixtures existed, so older scenes keep their bits.
 */
final class Velocities {
    private Velocities() {
    }

    static void draw(VelocityDistribution velocity, List<Species> species, Discs d, int offset, int count, SplittableRandom random, String path) {
        switch (velocity) {
            case VelocityDistribution.AtRest ignored -> {
            }
            case VelocityDistribution.Uniform u -> {
                for (int i = offset; i < offset + count; i++) {
                    if (!d.isFixed(i)) {
                        d.vx[i] = (2 * random.nextDouble() - 1) * u.scale();
                        d.vy[i] = (2 * random.nextDouble() - 1) * u.scale();
                    }
                }
            }
            case VelocityDistribution.Maxwell m -> maxwell(m, species, d, offset, count, random, path);
        }
    }

    private static void maxwell(VelocityDistribution.Maxwell m, List<Species> species, Discs d, int offset, int count, SplittableRandom random,
                                String path) {
        boolean equalMasses = true;
        int mobile = 0;
        double firstMass = Double.NaN;
        for (int i = offset; i < offset + count; i++) {
            if (!d.isFixed(i)) {
                double mi = species.get(d.species[i]).mass();
                firstMass = mobile == 0 ? mi : firstMass;
                equalMasses &= mi == firstMass;
                mobile++;
            }
        }
        if (mobile == 0) {
            return;
        }
        double momentumX = 0;
        double momentumY = 0;
        double mass = 0;
        for (int i = offset; i < offset + count; i++) {
            if (d.isFixed(i)) {
                continue;
            }
            // Equal masses: unit Gaussians (the velocity scale is fixed by the final rescaling anyway).
            double sd = equalMasses ? 1 : Math.sqrt(1 / species.get(d.species[i]).mass());
            d.vx[i] = random.nextGaussian() * sd;
            d.vy[i] = random.nextGaussian() * sd;
            double mi = equalMasses ? 1 : species.get(d.species[i]).mass();
            momentumX += mi * d.vx[i];
            momentumY += mi * d.vy[i];
            mass += mi;
        }
        double meanX = momentumX / mass;
        double meanY = momentumY / mass;
        double kinetic = 0;
        for (int i = offset; i < offset + count; i++) {
            if (d.isFixed(i)) {
                continue;
            }
            d.vx[i] -= meanX;
            d.vy[i] -= meanY;
            kinetic += 0.5 * species.get(d.species[i]).mass() * (d.vx[i] * d.vx[i] + d.vy[i] * d.vy[i]);
        }
        double target = mobile * m.temperature();
        if (kinetic == 0) {
            if (target == 0) {
                return;
            }
            throw new BadInputException(path + ".velocity: a maxwell block needs at least 2 discs to reach temperature "
                    + m.temperature() + " at zero momentum");
        }
        double scale = Math.sqrt(target / kinetic);
        for (int i = offset; i < offset + count; i++) {
            d.vx[i] *= scale;
            d.vy[i] *= scale;
        }
    }
}
