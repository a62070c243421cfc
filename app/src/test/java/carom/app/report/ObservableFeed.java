package carom.app.report;

import carom.core.observe.CollisionObserver;
import carom.core.physics.Boundary;
import carom.core.scene.Scene;
import carom.core.scene.StandardScenes;
import carom.core.state.Discs;
import java.util.SplittableRandom;

/**
 * A made-up run for the report's tests: random walkers in a periodic box, sampled every {@link #DT},
 * with a growing virial sum and, between samples, random pair and wall collisions told to the
 * observers that listen to them (as an engine that tells collisions would). Sample k depends on k alone,
 * so a run fed in two parts gives the same samples as one fed whole.
 */
final class ObservableFeed {
    static final double DT = 0.1;
    static final int DISCS = 500;
    static final Scene SCENE = StandardScenes.gas(DISCS, 0.4, true, 100, 1);

    private ObservableFeed() {
    }

    /** Samples {@code from} to {@code to - 1} into {@code observing}, with collisions between them. */
    static void feed(Observing observing, int from, int to) {
        CollisionObserver collisions = observing.collisions();
        Discs discs = SCENE.newDiscs();
        double width = SCENE.box().width();
        for (int s = from; s < to; s++) {
            SplittableRandom random = new SplittableRandom(1000 + s);
            double t = s * DT;
            if (collisions != null && s > 0) {
                int pairs = random.nextInt(50, 150);
                for (int c = 0; c < pairs; c++) {
                    collisions.pair(t - DT * random.nextDouble(), random.nextInt(DISCS), random.nextInt(DISCS), 0.6, 0.8,
                            0.6, 0.8, random.nextDouble());
                }
                int walls = random.nextInt(5);
                for (int c = 0; c < walls; c++) {
                    collisions.wall(t - DT * random.nextDouble(), random.nextInt(DISCS), Boundary.LEFT, random.nextDouble());
                }
            }
            for (int i = 0; i < DISCS; i++) {
                discs.x[i] = random.nextDouble() * width;
                discs.y[i] = random.nextDouble() * width;
                discs.vx[i] = random.nextDouble() - 0.5;
                discs.vy[i] = random.nextDouble() - 0.5;
            }
            observing.sample(t, discs, 100.0 * s * s);
        }
    }
}
