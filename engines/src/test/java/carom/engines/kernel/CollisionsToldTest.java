package carom.engines.kernel;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.observe.CollisionObserver;
import carom.core.physics.Boundary;
import carom.core.scene.BoundaryKind;
import carom.core.scene.Effects;
import carom.core.scene.Scene;
import carom.core.scene.SceneBuilder;
import carom.core.scene.Species;
import carom.engines.fast.FastEngine;
import carom.engines.fast.GrowthRun;
import carom.engines.reference.RandomScenes;
import carom.engines.serial.SerialEngine;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.SplittableRandom;
import java.util.stream.LongStream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * A {@link CollisionObserver} is told every collision of {@code fast}, {@code serial} and growth runs,
 * with the contact, the normal and the impulse the collision was resolved with, and does not change
 * the run.
 */
class CollisionsToldTest {
    static LongStream seeds() {
        return LongStream.rangeClosed(1, 12);
    }

    /** One collision as told: disc k is -1 - wall for a wall collision. */
    record Told(double time, int i, int k, double dx, double dy, double nx, double ny, double j) {
        /** The same collision with the lower id first (the contact and normal turn round). */
        Told ordered() {
            return k < 0 || i < k ? this : new Told(time, k, i, -dx, -dy, -nx, -ny, j);
        }
    }

    static final class Recorder implements CollisionObserver {
        final List<Told> told = new ArrayList<>();

        @Override
        public void pair(double time, int i, int k, double dx, double dy, double nx, double ny, double j) {
            told.add(new Told(time, i, k, dx, dy, nx, ny, j));
        }

        @Override
        public void wall(double time, int i, int wall, double j) {
            told.add(new Told(time, i, -1 - wall, 0, 0, 0, 0, j));
        }

        long pairs() {
            return told.stream().filter(t -> t.k >= 0).count();
        }
    }

    private static Recorder run(Engine engine, Scene scene, RunResult[] result) {
        Recorder recorder = new Recorder();
        result[0] = engine.run(scene, RunOptions.until(scene.until()).withCollisions(recorder));
        return recorder;
    }

    @ParameterizedTest
    @MethodSource("seeds")
    void fastTellsEveryCollisionAtContactWithAUnitNormal(long seed) {
        Scene scene = RandomScenes.small(seed);
        RunResult[] result = new RunResult[1];
        Recorder recorder = run(new FastEngine(), scene, result);
        assertThat(recorder.pairs()).isEqualTo(result[0].pairCollisions());
        assertThat(recorder.told.size() - recorder.pairs()).isEqualTo(result[0].wallCollisions());
        double[] radius = scene.newDiscs().radius;
        double previous = 0;
        for (Told t : recorder.told) {
            assertThat(t.time).isGreaterThanOrEqualTo(previous).isLessThanOrEqualTo(scene.until());
            previous = t.time;
            assertThat(t.j).isGreaterThanOrEqualTo(0);
            if (t.k >= 0) {
                double sigma = radius[t.i] + radius[t.k];
                assertThat(Math.hypot(t.dx, t.dy)).isCloseTo(sigma, within(1e-9));
                assertThat(Math.hypot(t.nx, t.ny)).isCloseTo(1, within(1e-12));
                assertThat(t.nx * t.dy - t.ny * t.dx).isCloseTo(0, within(1e-12));
                assertThat(t.nx * t.dx + t.ny * t.dy).isPositive();
            }
        }
    }

    @ParameterizedTest
    @MethodSource("seeds")
    void fastAndSerialTellTheSameCollisions(long seed) {
        Scene scene = RandomScenes.small(seed);
        RunResult[] result = new RunResult[1];
        List<Told> fast = sorted(run(new FastEngine(), scene, result).told);
        List<Told> serial = sorted(run(new SerialEngine(), scene, result).told);
        assertThat(fast).hasSameSizeAs(serial);
        for (int c = 0; c < fast.size(); c++) {
            Told f = fast.get(c);
            Told s = serial.get(c);
            assertThat(f.i).as("collision %d", c).isEqualTo(s.i);
            assertThat(f.k).as("collision %d", c).isEqualTo(s.k);
            assertThat(f.time).isCloseTo(s.time, within(1e-9));
            assertThat(f.j).isCloseTo(s.j, within(1e-8));
            assertThat(f.nx).isCloseTo(s.nx, within(1e-8));
            assertThat(f.ny).isCloseTo(s.ny, within(1e-8));
        }
    }

    /** In a walled box without fixed discs, the walls' impulses are all the momentum the discs gain. */
    @ParameterizedTest
    @MethodSource("seeds")
    void wallImpulsesAddUpToTheMomentumChange(long seed) {
        Scene scene = walledGas(seed);
        for (Engine engine : List.of(new FastEngine(), new SerialEngine())) {
            RunResult[] result = new RunResult[1];
            Recorder recorder = run(engine, scene, result);
            double px = 0;
            double py = 0;
            for (Told t : recorder.told) {
                switch (-1 - t.k) {
                    case Boundary.LEFT -> px += t.j;
                    case Boundary.RIGHT -> px -= t.j;
                    case Boundary.BOTTOM -> py += t.j;
                    case Boundary.TOP -> py -= t.j;
                    default -> {
                    }
                }
            }
            assertThat(result[0].wallCollisions()).as(engine.name()).isPositive();
            assertThat(result[0].momentumEnd()[0] - result[0].momentumStart()[0]).as(engine.name())
                    .isCloseTo(px, within(1e-9));
            assertThat(result[0].momentumEnd()[1] - result[0].momentumStart()[1]).as(engine.name())
                    .isCloseTo(py, within(1e-9));
        }
    }

    @ParameterizedTest
    @MethodSource("seeds")
    void anObserverDoesNotChangeTheRun(long seed) {
        Scene scene = RandomScenes.effects(seed);
        for (Engine engine : List.of(new FastEngine(), new SerialEngine())) {
            RunResult plain = engine.run(scene, RunOptions.until(scene.until()));
            RunResult[] told = new RunResult[1];
            run(engine, scene, told);
            assertThat(told[0].finalState().x).as(engine.name()).isEqualTo(plain.finalState().x);
            assertThat(told[0].finalState().vy).as(engine.name()).isEqualTo(plain.finalState().vy);
            assertThat(told[0].pairCollisions()).isEqualTo(plain.pairCollisions());
        }
    }

    @ParameterizedTest
    @MethodSource("seeds")
    void growthRunsTellEveryCollision(long seed) {
        Scene scene = growingGas(seed);
        Recorder recorder = new Recorder();
        RunOptions options = RunOptions.until(scene.until()).withCollisions(recorder);
        RunResult result = new GrowthRun(scene, options, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY).run();
        assertThat(recorder.pairs()).isEqualTo(result.pairCollisions()).isPositive();
        assertThat(recorder.told.size() - recorder.pairs()).isEqualTo(result.wallCollisions());
        assertThat(recorder.told).allSatisfy(t -> assertThat(t.j).isPositive());
    }

    private static List<Told> sorted(List<Told> told) {
        return told.stream().map(Told::ordered)
                .sorted(Comparator.comparingDouble(Told::time).thenComparingInt(Told::i).thenComparingInt(Told::k))
                .toList();
    }

    private static Scene walledGas(long seed) {
        return gas(seed, Effects.NONE, 3);
    }

    private static Scene growingGas(long seed) {
        return gas(seed, Effects.NONE.withGrowth(0.02), 2);
    }

    /** Twenty discs of radius 0.3 on a jittered lattice in a 10 x 10 walled box, random velocities. */
    private static Scene gas(long seed, Effects effects, double until) {
        SplittableRandom random = new SplittableRandom(seed);
        SceneBuilder b = SceneBuilder.create("told-" + seed).box(10, 10, BoundaryKind.WALLS)
                .species(Species.mobile("d", 0.3, 1 + random.nextDouble()));
        for (int c = 0; c < 20; c++) {
            double x = 1 + 2 * (c % 5) + 0.4 * random.nextDouble();
            double y = 1.5 + 2 * (c / 5) + 0.4 * random.nextDouble();
            b.disc(0, x, y, 4 * random.nextDouble() - 2, 4 * random.nextDouble() - 2);
        }
        return b.effects(effects).until(until).build();
    }
}
