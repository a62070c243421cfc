package carom.lab.study;

import carom.core.BadInputException;
import carom.core.scene.Scene;
import carom.core.scene.StandardScenes;
import java.util.Locale;

/**
 * One of the study's scenes: {@link StandardScenes#gas} (discs of diameter 1 and mass 1 at kT = 1), periodic
 * or walled, at packing fraction {@code phi}; walled scenes may add downward gravity.
 */
record StudyScene(boolean periodic, double phi, int discs, long seed, double gravity) {
    /** Parses {@code periodic:0.3} or {@code walls:0.3}. */
    static StudyScene parse(String spec, int discs, long seed, double gravity) {
        String[] parts = spec.split(":", -1);
        if (parts.length != 2 || !(parts[0].equals("periodic") || parts[0].equals("walls"))) {
            throw new BadInputException("--scenes: expected periodic:PHI or walls:PHI, got '" + spec + "'");
        }
        double phi;
        try {
            phi = Double.parseDouble(parts[1]);
        } catch (NumberFormatException e) {
            throw new BadInputException("--scenes: not a packing fraction: '" + parts[1] + "'");
        }
        if (!(phi > 0 && phi < 0.7)) {
            throw new BadInputException("--scenes: packing fraction must be in (0, 0.7), got " + parts[1]);
        }
        boolean periodic = parts[0].equals("periodic");
        return new StudyScene(periodic, phi, discs, seed, periodic ? 0 : gravity);
    }

    /** For tables: {@code periodic φ=0.3}. */
    String label() {
        return (periodic ? "periodic" : "walls") + " φ=" + fmt(phi) + (gravity > 0 ? " g=" + fmt(gravity) : "");
    }

    /** For CSV and file names: {@code periodic-0.3}. */
    String key() {
        return (periodic ? "periodic" : "walls") + "-" + fmt(phi) + (gravity > 0 ? "-g" + fmt(gravity) : "");
    }

    Scene scene(double until) {
        Scene s = StandardScenes.gas(discs, phi, periodic, until, seed);
        return gravity > 0 ? s.withEffects(s.effects().withGravity(0, -gravity)) : s;
    }

    /**
     * Collisions per disc per unit time (collisions over N, each collision counted once) by Enskog's theory
     * with Henderson's contact value: half a disc's collision frequency 2 n σ g(σ) sqrt(π kT / m), here with
     * σ = 1, kT = m = 1. Within about 20% of what the exact engines measure on these scenes (1.2 against
     * 1.0 at φ = 0.3, 6.2 against 6.0 at φ = 0.6); it only sets the horizons, whose real collision counts
     * the table reports.
     */
    double collisionsPerDiscPerTime() {
        double density = phi / (Math.PI / 4);
        double contact = (1 - 7 * phi / 16) / ((1 - phi) * (1 - phi));
        return density * contact * Math.sqrt(Math.PI);
    }

    /** The simulated time in which each disc collides about {@code collisionsPerDisc} times. */
    double horizon(double collisionsPerDisc) {
        return collisionsPerDisc / collisionsPerDiscPerTime();
    }

    static String fmt(double v) {
        String s = String.format(Locale.ROOT, "%.6g", v);
        if (s.contains(".") && !s.contains("e")) {
            s = s.replaceAll("0+$", "").replaceAll("\\.$", "");
        }
        return s;
    }
}
