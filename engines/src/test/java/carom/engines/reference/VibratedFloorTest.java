package carom.engines.reference;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import carom.core.BadInputException;
import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.physics.VibratingFloor;
import carom.core.scene.BoundaryKind;
import carom.core.scene.Effect;
import carom.core.scene.Effects;
import carom.core.scene.Scene;
import carom.core.scene.SceneBuilder;
import carom.core.scene.Species;
import carom.core.state.Discs;
import carom.engines.EngineCatalog;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The vibrated floor ({@code effects.vibratingFloor}) on every engine that simulates it: against the
 * brute-force judge with its own fine root search on seeded random small scenes, against hand
 * computations of one disc, and a vibrated bed of a few hundred inelastic discs under gravity with the
 * TC model (no overlap, no stall, no disc under the floor at any sample); the other engines refuse it.
 */
class VibratedFloorTest {
    /**
     * The engines take a floor contact where the gap is within {@link VibratingFloor#tolerance} (2^-46 of
     * the box) and closing, the judge where its bisection finds the gap's zero: up to tolerance / closing
     * speed apart in time, which bounces and pair collisions amplify (seed 18, e = 0.52 under g = 9.95:
     * 3e-8 after the run, the counts equal). The rough-disc contract's 1e-7 for the same reason.
     */
    private static final double SAME = 1e-7;

    static List<Engine> floorEngines() {
        return EngineCatalog.where(spec -> spec.simulates(Effect.VIBRATING_FLOOR));
    }

    /**
     * Seeded random small scenes with a vibrated floor: six to twenty discs of two species in a walled
     * box, gravity straight down (2 to 10) in three of four, none in the rest; amplitudes up to 0.9 of
     * the smallest radius and frequencies that make the floor's speed Aω 0.5 to 4; pair and wall
     * restitution 1 or in [0.5, 1), the TC model (tc = 1e-3) in half of them; horizons of 0.7 to 1.1.
     */
    static Scene randomScene(long seed) {
        SplittableRandom random = new SplittableRandom(seed * 7919 + 17);
        double width = 5 + 4 * random.nextDouble();
        double height = 5 + 4 * random.nextDouble();
        double[] radii = {0.2 + 0.1 * random.nextDouble(), 0.3 + 0.15 * random.nextDouble()};
        double g = random.nextInt(4) == 0 ? 0 : 2 + 8 * random.nextDouble();
        double amplitude = 0.9 * radii[0] * random.nextDouble(0.05, 1);
        double speed = 0.5 + 3.5 * random.nextDouble();
        double frequency = speed / (2 * Math.PI * amplitude);
        double e = random.nextInt(4) == 0 ? 1 : 0.5 + 0.5 * random.nextDouble();
        double ew = random.nextInt(4) == 0 ? 1 : 0.5 + 0.5 * random.nextDouble();
        double tc = random.nextBoolean() ? 1e-3 : 0;
        Effects effects = Effects.NONE.withGravity(0, -g).withRestitution(e, ew).withTc(tc)
                .withVibratingFloor(amplitude, frequency);
        String name = String.format("floor-%d-g%.2f-A%.3f-F%.2f-e%.2f-w%.2f-tc%s", seed, g, amplitude, frequency, e, ew, tc);
        SceneBuilder b = SceneBuilder.create(name).box(width, height, BoundaryKind.WALLS)
                .species(Species.mobile("small", radii[0], 1.0))
                .species(Species.mobile("large", radii[1], 1 + 3 * random.nextDouble()))
                .effects(effects);
        int count = 6 + random.nextInt(15);
        List<double[]> placed = new ArrayList<>();
        double gap = 0.05;
        for (int attempt = 0; placed.size() < count && attempt < 10_000; attempt++) {
            int s = random.nextInt(2);
            double r = radii[s];
            double x = r + gap + (width - 2 * r - 2 * gap) * random.nextDouble();
            double y = r + gap + (height - 2 * r - 2 * gap) * random.nextDouble();
            boolean free = true;
            for (double[] o : placed) {
                double dx = x - o[0];
                double dy = y - o[1];
                free &= dx * dx + dy * dy > (r + o[2] + gap) * (r + o[2] + gap);
            }
            if (free) {
                placed.add(new double[] {x, y, r});
                double v = 2 * random.nextDouble();
                b.disc(s, x, y, v * (2 * random.nextDouble() - 1), v * (2 * random.nextDouble() - 1));
            }
        }
        return b.until(0.7 + 0.4 * random.nextDouble()).build();
    }

    static Stream<Arguments> enginesAndSeeds() {
        return floorEngines().stream().flatMap(engine -> java.util.stream.LongStream.rangeClosed(1, 30)
                .mapToObj(seed -> Arguments.of(engine.spec().name(), seed)));
    }

    @ParameterizedTest(name = "{0}, seed {1}")
    @MethodSource("enginesAndSeeds")
    void finalStateAndCountsMatchTheJudgeWithItsFineRootSearch(String engineName, long seed) {
        Scene scene = randomScene(seed);
        RunResult actual = EngineCatalog.byName(engineName).run(scene, RunOptions.until(scene.until()));
        BruteForceReference.Result reference = BruteForceReference.run(scene, scene.until());
        String name = scene.name();
        assertThat(actual.pairCollisions()).as("%s: pair collisions", name).isEqualTo(reference.pairCollisions());
        assertThat(actual.wallCollisions()).as("%s: wall collisions", name).isEqualTo(reference.wallCollisions());
        Discs s = actual.finalState();
        Discs r = reference.state();
        for (int i = 0; i < scene.size(); i++) {
            assertThat(s.x[i]).as("%s: x of %d", name, i).isCloseTo(r.x[i], within(SAME));
            assertThat(s.y[i]).as("%s: y of %d", name, i).isCloseTo(r.y[i], within(SAME));
            assertThat(s.vx[i]).as("%s: vx of %d", name, i).isCloseTo(r.vx[i], within(SAME));
            assertThat(s.vy[i]).as("%s: vy of %d", name, i).isCloseTo(r.vy[i], within(SAME));
        }
        aboveTheFloor(scene, s, scene.until());
        Invariants.noOverlaps(name, scene.box(), s);
    }

    /** Every disc's lowest point at or above the floor (to rounding) at {@code time}. */
    static void aboveTheFloor(Scene scene, Discs d, double time) {
        VibratingFloor floor = VibratingFloor.of(scene);
        double floorY = floor.height(time);
        for (int i = 0; i < d.n; i++) {
            assertThat(d.y[i] - d.radius[i] - floorY).as("%s: disc %d's gap to the floor at t = %s", scene.name(), i, time)
                    .isGreaterThanOrEqualTo(-1e-12);
            assertThat(d.x[i] - d.radius[i]).isGreaterThanOrEqualTo(-1e-12);
            assertThat(d.x[i] + d.radius[i]).isLessThanOrEqualTo(scene.box().width() + 1e-12);
            assertThat(d.y[i] + d.radius[i]).isLessThanOrEqualTo(scene.box().height() + 1e-12);
        }
    }

    static Stream<String> floorEngineNames() {
        return floorEngines().stream().map(e -> e.spec().name());
    }

    /**
     * No gravity: a disc at rest at height y0 above a floor rising from 0 is met when A·sin(ωt*) = y0 − R,
     * t* = asin((y0 − R)/A)/ω, and leaves at v = v_w + e·v_w = (1 + e)·A·ω·cos(ωt*); then flies straight up.
     */
    @ParameterizedTest
    @MethodSource("floorEngineNames")
    void aDiscAtRestIsHitByTheRisingFloorAsComputedByHand(String engineName) {
        double r = 0.5;
        double a = 0.4;
        double f = 2;
        double e = 0.7;
        double y0 = r + 0.3;
        double omega = 2 * Math.PI * f;
        double contact = Math.asin(0.3 / a) / omega;
        double leave = (1 + e) * a * omega * Math.cos(omega * contact);
        double until = 0.5;
        Scene scene = SceneBuilder.create("rising").box(4, 10, BoundaryKind.WALLS)
                .species(Species.mobile("disc", r, 1))
                .effects(Effects.NONE.withRestitution(1, e).withVibratingFloor(a, f))
                .disc(0, 2, y0, 0, 0).until(until).build();
        RunResult result = EngineCatalog.byName(engineName).run(scene, RunOptions.until(until));
        Discs d = result.finalState();
        assertThat(result.wallCollisions()).isEqualTo(1);
        assertThat(d.vy[0]).isCloseTo(leave, within(1e-9));
        assertThat(d.y[0]).isCloseTo(y0 + leave * (until - contact), within(1e-9));
        assertThat(d.vx[0]).isZero();
    }

    /**
     * Under gravity: a disc dropped from rest at y0 = R + A + g·t*²/2 meets the floor at its top,
     * t* = 1/(4F), where the floor stands still (v_w = 0; before it, the gap A − A·sin(ωt) +
     * g·(t*² − t²)/2 is positive), at speed g·t*, and rebounds at e·g·t*; it then rises as a parabola.
     */
    @ParameterizedTest
    @MethodSource("floorEngineNames")
    void aDroppedDiscMeetsTheFloorAtItsTopAsComputedByHand(String engineName) {
        double r = 0.5;
        double a = 0.3;
        double f = 1.5;
        double g = 9.81;
        double e = 0.8;
        double contact = 1 / (4 * f);
        double y0 = r + a + 0.5 * g * contact * contact;
        double until = contact + 0.1;
        Scene scene = SceneBuilder.create("dropped").box(4, 10, BoundaryKind.WALLS)
                .species(Species.mobile("disc", r, 1))
                .effects(Effects.NONE.withGravity(0, -g).withRestitution(1, e).withVibratingFloor(a, f))
                .disc(0, 2, y0, 0, 0).until(until).build();
        RunResult result = EngineCatalog.byName(engineName).run(scene, RunOptions.until(until));
        Discs d = result.finalState();
        double up = e * g * contact;
        double dt = until - contact;
        assertThat(result.wallCollisions()).isEqualTo(1);
        assertThat(d.vy[0]).isCloseTo(up - g * dt, within(1e-9));
        assertThat(d.y[0]).isCloseTo(r + a + up * dt - 0.5 * g * dt * dt, within(1e-9));
    }

    /**
     * A vibrated bed: {@code n} inelastic discs (e = 0.9, wall 0.9, TC model) under gravity on a floor
     * shaken at Γ = Aω²/g = 3; sampled often, every sample has every disc at or above the floor and no
     * overlap; the run makes at least {@code collisions} collisions (no stall, no stuck exception).
     */
    static Scene bed(int n, double amplitudeSpeed, double until, long seed) {
        double r = 0.5;
        double g = 1;
        double a = 0.25;
        // Aω given; Γ = Aω²/g follows.
        double omega = amplitudeSpeed / a;
        double width = 40;
        double height = 120;
        SceneBuilder b = SceneBuilder.create("bed-" + n).box(width, height, BoundaryKind.WALLS)
                .species(Species.mobile("grain", r, 1))
                .effects(Effects.NONE.withGravity(0, -g).withRestitution(0.9, 0.9).withTc(1e-3)
                        .withVibratingFloor(a, omega / (2 * Math.PI)));
        SplittableRandom random = new SplittableRandom(seed);
        int perRow = (int) ((width - 1) / 1.25);
        for (int k = 0; k < n; k++) {
            double x = 1.1 + (k % perRow) * 1.25 + 0.05 * random.nextDouble();
            double y = 1.1 + (k / perRow) * 1.25 + 0.05 * random.nextDouble();
            b.disc(0, x, y, random.nextDouble(-1, 1), random.nextDouble(-1, 1));
        }
        return b.until(until).build();
    }

    static void runBed(String engineName, Scene scene, long atLeast) {
        List<String> problems = new ArrayList<>();
        double every = 0.5;
        RunOptions options = RunOptions.until(scene.until()).withSamples(every, (time, state, virial) -> {
            try {
                aboveTheFloor(scene, state, time);
                Invariants.noOverlaps(scene.name(), scene.box(), state);
            } catch (AssertionError failure) {
                if (problems.isEmpty()) {
                    problems.add("t = " + time + ": " + failure.getMessage());
                }
            }
        });
        RunResult result = EngineCatalog.byName(engineName).run(scene, options);
        assertThat(problems).isEmpty();
        assertThat(result.pairCollisions() + result.wallCollisions()).isGreaterThanOrEqualTo(atLeast);
        aboveTheFloor(scene, result.finalState(), scene.until());
        Invariants.noOverlaps(scene.name(), scene.box(), result.finalState());
    }

    /** 300 discs, 1e5 collisions and more: no overlap, no stall, nothing under the floor. */
    @ParameterizedTest
    @MethodSource("floorEngineNames")
    void aVibratedBedOfThreeHundredInelasticDiscsRunsCleanly(String engineName) {
        runBed(engineName, bed(300, 1.5, 80, 1), 100_000);
    }

    /** The judge's scenes do meet the floor: most of them, many times (so the comparison above judges it). */
    @Test
    void theRandomScenesHitTheFloor() {
        int scenesWithHits = 0;
        long hits = 0;
        for (long seed = 1; seed <= 30; seed++) {
            Scene scene = randomScene(seed);
            long[] floorHits = {0};
            EngineCatalog.byName("fast").run(scene, RunOptions.until(scene.until()).withCollisions(new carom.core.observe.CollisionObserver() {
                @Override
                public void pair(double time, int i, int k, double dx, double dy, double nx, double ny, double j) {
                }

                @Override
                public void wall(double time, int i, int wall, double j) {
                    if (wall == carom.core.physics.Boundary.BOTTOM) {
                        floorHits[0]++;
                    }
                }
            }));
            scenesWithHits += floorHits[0] > 0 ? 1 : 0;
            hits += floorHits[0];
        }
        assertThat(scenesWithHits).isGreaterThanOrEqualTo(20);
        // 192 floor hits in all when this was written.
        assertThat(hits).isGreaterThanOrEqualTo(150);
    }

    @Test
    void enginesThatDoNotSimulateTheFloorRefuseIt() {
        Scene scene = randomScene(1);
        for (Engine engine : EngineCatalog.all()) {
            if (!engine.spec().simulates(Effect.VIBRATING_FLOOR)) {
                assertThatThrownBy(() -> engine.spec().checkSupports(scene)).isInstanceOf(BadInputException.class)
                        .hasMessageStartingWith("effects.vibratingFloor: engine " + engine.spec().name()
                                + " does not simulate a vibrated floor (engines that do: ");
            }
        }
    }
}
