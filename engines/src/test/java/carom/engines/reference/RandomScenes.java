package carom.engines.reference;

import carom.core.scene.BoundaryKind;
import carom.core.scene.Effects;
import carom.core.scene.GenerateBlock;
import carom.core.scene.Scene;
import carom.core.scene.SceneBuilder;
import carom.core.scene.Species;
import carom.core.scene.VelocityDistribution;
import java.util.SplittableRandom;

/**
 * Seeded random small scenes for judging engines against {@link BruteForceReference}: a few dozen
 * discs of two or three species (polydisperse radii and masses, sometimes fixed discs), walls or
 * periodic, placed without overlap by rejection sampling. Short horizons keep trajectories from
 * becoming chaotic, so final states can be compared to 1e-9.
 */
public final class RandomScenes {
    private RandomScenes() {
    }

    public static Scene small(long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        boolean periodic = random.nextBoolean();
        double width = 6 + 6 * random.nextDouble();
        double height = 6 + 6 * random.nextDouble();
        double[] radii = {0.2 + 0.1 * random.nextDouble(), 0.35 + 0.15 * random.nextDouble(), 0.3};
        SceneBuilder b = SceneBuilder.create("random-" + seed)
                .box(width, height, periodic ? BoundaryKind.PERIODIC : BoundaryKind.WALLS)
                .species(Species.mobile("small", radii[0], 1.0))
                .species(Species.mobile("large", radii[1], 1 + 3 * random.nextDouble()));
        boolean pegs = random.nextInt(3) == 0;
        if (pegs) {
            b.species(Species.fixed("peg", radii[2]));
        }
        int count = 8 + random.nextInt(30);
        double[] xs = new double[count];
        double[] ys = new double[count];
        double[] rs = new double[count];
        int placed = 0;
        for (int attempt = 0; placed < count && attempt < 10_000; attempt++) {
            int species = pegs && random.nextInt(6) == 0 ? 2 : random.nextInt(2);
            double r = radii[species];
            double x = r + (width - 2 * r) * random.nextDouble();
            double y = r + (height - 2 * r) * random.nextDouble();
            boolean free = true;
            for (int k = 0; k < placed && free; k++) {
                double dx = x - xs[k];
                double dy = y - ys[k];
                if (periodic) {
                    dx -= width * Math.rint(dx / width);
                    dy -= height * Math.rint(dy / height);
                }
                free = dx * dx + dy * dy > (r + rs[k] + 0.01) * (r + rs[k] + 0.01);
            }
            if (!free) {
                continue;
            }
            xs[placed] = x;
            ys[placed] = y;
            rs[placed] = r;
            placed++;
            double speed = species == 2 ? 0 : 2;
            b.disc(species, x, y, speed * (2 * random.nextDouble() - 1), speed * (2 * random.nextDouble() - 1));
        }
        return b.until(1.5 + random.nextDouble()).build();
    }

    /**
     * Seeded random small scenes with effects: gravity (mostly downward, sometimes any direction, 2 to
     * 10), pair restitution and wall restitution each 1 or in [0.5, 1), the TC model off or tc = 1e-3,
     * fixed pegs in half of them; walls in three of four, periodic otherwise. Six to twenty-five discs of
     * two mobile species placed by rejection sampling with gaps of at least 0.05 to every wall and disc,
     * so no disc starts resting on a wall or peg (SPEC). Horizons of 0.7 to 1.1 keep the runs short of
     * chaos: the serial engine must match {@link BruteForceReference} to 1e-8 on them.
     */
    public static Scene effects(long seed) {
        return effects(seed, false);
    }

    /**
     * {@link #effects}'s scene of the same seed made of rough discs: a tangential restitution β a hair
     * above −1 (barely gripping), +1 (perfectly rough) or in between, a moment of inertia q·m·R² per mobile
     * species with q in [0.2, 1], and every mobile disc spinning at up to 5 radians per time unit. The
     * rough parameters come from a stream of their own, so the discs, effects and horizon are
     * {@link #effects}'s.
     */
    public static Scene rough(long seed) {
        return effects(seed, true);
    }

    private static Scene effects(long seed, boolean rough) {
        SplittableRandom random = new SplittableRandom(seed);
        SplittableRandom spin = new SplittableRandom(~seed);
        double beta = switch (spin.nextInt(4)) {
            case 0 -> -1;
            case 1 -> 1;
            default -> spin.nextDouble(-1, 1);
        };
        boolean periodic = random.nextInt(4) == 0;
        // At least three grid cells (of twice the largest diameter, 1) per axis: see the disabled test
        // SerialEffectsTest.gravityInABoxOfAtMostTwoGridCellsPerAxisStaysFinite for smaller boxes.
        double width = 6.5 + 4.5 * random.nextDouble();
        double height = 6.5 + 4.5 * random.nextDouble();
        double[] radii = {0.2 + 0.1 * random.nextDouble(), 0.35 + 0.15 * random.nextDouble(), 0.2 + 0.2 * random.nextDouble()};
        double g = 2 + 8 * random.nextDouble();
        double angle = random.nextInt(4) == 0 ? 2 * Math.PI * random.nextDouble() : -0.5 * Math.PI + 0.5 * (random.nextDouble() - 0.5);
        double restitution = random.nextInt(4) == 0 ? 1 : 0.5 + 0.5 * random.nextDouble();
        double wallRestitution = random.nextInt(4) == 0 ? 1 : 0.5 + 0.5 * random.nextDouble();
        double tc = random.nextBoolean() ? 1e-3 : 0;
        Effects effects = Effects.NONE.withGravity(g * Math.cos(angle), g * Math.sin(angle))
                .withRestitution(restitution, wallRestitution).withTc(tc);
        String name = String.format("effects-%d-g%.2f-e%.2f-w%.2f-tc%s", seed, g, restitution, wallRestitution, tc);
        if (rough) {
            // Written -1 is smooth (nothing spins); a hair above it is rough discs that barely grip.
            effects = effects.withTangentialRestitution(beta == -1 ? -1 + 1e-12 : beta);
            name = name.replace("effects-", "rough-") + String.format("-beta%.2f", beta);
        }
        SceneBuilder b = SceneBuilder.create(name)
                .box(width, height, periodic ? BoundaryKind.PERIODIC : BoundaryKind.WALLS)
                .species(Species.mobile("small", radii[0], 1.0).withInertia(rough ? spin.nextDouble(0.2, 1) : 0.5))
                .species(Species.mobile("large", radii[1], 1 + 3 * random.nextDouble())
                        .withInertia(rough ? spin.nextDouble(0.2, 1) : 0.5))
                .effects(effects);
        boolean pegs = random.nextBoolean();
        if (pegs) {
            b.species(Species.fixed("peg", radii[2]));
        }
        double gap = 0.05;
        int count = 6 + random.nextInt(20);
        double[] xs = new double[count];
        double[] ys = new double[count];
        double[] rs = new double[count];
        int placed = 0;
        for (int attempt = 0; placed < count && attempt < 10_000; attempt++) {
            int species = pegs && random.nextInt(4) == 0 ? 2 : random.nextInt(2);
            double r = radii[species];
            double x = r + gap + (width - 2 * r - 2 * gap) * random.nextDouble();
            double y = r + gap + (height - 2 * r - 2 * gap) * random.nextDouble();
            boolean free = true;
            for (int k = 0; k < placed && free; k++) {
                double dx = x - xs[k];
                double dy = y - ys[k];
                if (periodic) {
                    dx -= width * Math.rint(dx / width);
                    dy -= height * Math.rint(dy / height);
                }
                free = dx * dx + dy * dy > (r + rs[k] + gap) * (r + rs[k] + gap);
            }
            if (!free) {
                continue;
            }
            xs[placed] = x;
            ys[placed] = y;
            rs[placed] = r;
            placed++;
            double speed = species == 2 ? 0 : 2 * random.nextDouble();
            double omega = rough && species != 2 ? spin.nextDouble(-5, 5) : 0;
            b.disc(species, x, y, speed * (2 * random.nextDouble() - 1), speed * (2 * random.nextDouble() - 1), Double.NaN, omega);
        }
        return b.until(0.7 + 0.4 * random.nextDouble()).build();
    }

    /**
     * Seeded random small scenes in a Lees-Edwards box: six to thirty discs of two species, shear rates
     * from -1.5 to 1.5 (some runs slide the images by more than a width), pair restitution 1 in half of
     * them and in [0.6, 1) otherwise (with the TC model in a quarter), some boxes only four diameters
     * high, velocities up to 2 per component, a thermostat at kT = 1 in a third of them (it acts only at
     * samples, so not in a run without). Horizons of 1 to 2.
     */
    public static Scene sheared(long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        double width = 5 + 6 * random.nextDouble();
        double height = random.nextInt(4) == 0 ? 4.2 + random.nextDouble() : 5 + 6 * random.nextDouble();
        double[] radii = {0.2 + 0.1 * random.nextDouble(), 0.35 + 0.15 * random.nextDouble()};
        double shearRate = 3 * (random.nextDouble() - 0.5);
        double restitution = random.nextBoolean() ? 1 : 0.6 + 0.4 * random.nextDouble();
        double tc = random.nextInt(4) == 0 ? 1e-3 : 0;
        SceneBuilder b = SceneBuilder.create(String.format("sheared-%d-rate%.2f-e%.2f-tc%s", seed, shearRate, restitution, tc))
                .box(width, height, BoundaryKind.LEES_EDWARDS, shearRate, seed % 3 == 0 ? 1.0 : 0)
                .species(Species.mobile("small", radii[0], 1.0))
                .species(Species.mobile("large", radii[1], 1 + 3 * random.nextDouble()))
                .effects(Effects.NONE.withRestitution(restitution, 1).withTc(tc));
        int count = 6 + random.nextInt(25);
        double[] xs = new double[count];
        double[] ys = new double[count];
        double[] rs = new double[count];
        int placed = 0;
        for (int attempt = 0; placed < count && attempt < 10_000; attempt++) {
            int species = random.nextInt(2);
            double r = radii[species];
            double x = width * random.nextDouble();
            double y = height * random.nextDouble();
            boolean free = true;
            for (int k = 0; k < placed && free; k++) {
                double dx = x - xs[k];
                double dy = y - ys[k];
                dx -= width * Math.rint(dx / width);
                dy -= height * Math.rint(dy / height);
                free = dx * dx + dy * dy > (r + rs[k] + 0.01) * (r + rs[k] + 0.01);
            }
            if (!free) {
                continue;
            }
            xs[placed] = x;
            ys[placed] = y;
            rs[placed] = r;
            placed++;
            b.disc(species, x, y, 2 * (2 * random.nextDouble() - 1), 2 * (2 * random.nextDouble() - 1));
        }
        return b.until(1 + random.nextDouble()).build();
    }

    /**
     * {@code n} equal discs (radius 0.5, mass 1) at packing fraction {@code phi} in a square box, on
     * SPEC's lattice with jitter 0.5 and Maxwell velocities at temperature 1 (kT = 1 per disc).
     * {@code n} should be a perfect square so the lattice fits up to phi = pi/4 (0.785).
     */
    public static Scene dense(int n, double phi, boolean periodic, long seed, double until) {
        double side = Math.sqrt(n * Math.PI * 0.25 / phi);
        return SceneBuilder.create(String.format("dense-%d-%s-%s-%d", n, phi, periodic ? "periodic" : "walls", seed))
                .box(side, side, periodic ? BoundaryKind.PERIODIC : BoundaryKind.WALLS)
                .species(Species.mobile("d", 0.5, 1))
                .generate(new GenerateBlock(0, n, 0.5, new VelocityDistribution.Maxwell(1), seed))
                .until(until).build();
    }

    /**
     * A small box (walls or periodic) of heavy discs (mass 1, speed 1) with a few very light ones (mass
     * 1e-3, nearly at rest): every heavy-light collision throws a light disc off at up to twice the heavy speed, far
     * beyond the step's speed budget, so the serial engine must end steps early.
     */
    public static Scene lightAmongHeavy(long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        double side = 9 + 3 * random.nextDouble();
        boolean periodic = random.nextInt(3) == 0;
        SceneBuilder b = SceneBuilder.create("light-among-heavy-" + seed)
                .box(side, side, periodic ? BoundaryKind.PERIODIC : BoundaryKind.WALLS)
                .species(Species.mobile("heavy", 0.5, 1.0))
                .species(Species.mobile("light", 0.25, 1e-3));
        int cols = (int) Math.floor(side / 1.5);
        int light = 0;
        for (int r = 0; r < cols; r++) {
            for (int c = 0; c < cols; c++) {
                double x = (c + 0.5) * side / cols + 0.2 * (random.nextDouble() - 0.5);
                double y = (r + 0.5) * side / cols + 0.2 * (random.nextDouble() - 0.5);
                if (light < 4 && random.nextInt(6) == 0) {
                    light++;
                    b.disc(1, x, y, 0.05 * (random.nextDouble() - 0.5), 0.05 * (random.nextDouble() - 0.5));
                } else {
                    double angle = 2 * Math.PI * random.nextDouble();
                    b.disc(0, x, y, Math.cos(angle), Math.sin(angle));
                }
            }
        }
        return b.until(0.8 + 0.4 * random.nextDouble()).build();
    }

    /**
     * The dense scenes every exact engine is checked on (N, packing fraction, periodic, seed, until):
     * 225-2025 discs at 0.3-0.7, walls and periodic, about 50 collisions per disc.
     */
    public static java.util.stream.Stream<org.junit.jupiter.params.provider.Arguments> denseCases() {
        return java.util.stream.Stream.of(
                org.junit.jupiter.params.provider.Arguments.of(225, 0.7, false, 1L, 2.2),
                org.junit.jupiter.params.provider.Arguments.of(400, 0.3, true, 2L, 23.0),
                org.junit.jupiter.params.provider.Arguments.of(400, 0.6, false, 3L, 4.5),
                org.junit.jupiter.params.provider.Arguments.of(900, 0.5, true, 4L, 7.5),
                org.junit.jupiter.params.provider.Arguments.of(1024, 0.45, false, 5L, 10.0),
                org.junit.jupiter.params.provider.Arguments.of(1600, 0.65, true, 6L, 3.2),
                org.junit.jupiter.params.provider.Arguments.of(2025, 0.7, true, 7L, 2.1),
                org.junit.jupiter.params.provider.Arguments.of(2025, 0.3, false, 8L, 23.0));
    }
}
