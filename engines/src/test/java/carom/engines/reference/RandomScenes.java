package carom.engines.reference;

import carom.core.scene.BoundaryKind;
import carom.core.scene.Scene;
import carom.core.scene.SceneBuilder;
import carom.core.scene.Species;
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
}
