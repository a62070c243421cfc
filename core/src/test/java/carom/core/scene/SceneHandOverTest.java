package carom.core.scene;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.state.Discs;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * A scene hands the state it was built with to its first {@code newDiscs()} and makes the same numbers
 * again for every later call, each an owned state of its own; its figures are those of its discs.
 */
class SceneHandOverTest {
    /** 300 generated discs; with random addition also two explicit ones first, a fixed peg and a mobile disc. */
    private static Scene scene(Layout layout, boolean mixture, boolean periodic, long seed) {
        SceneBuilder b = SceneBuilder.create("hand-over").box(40, 30, periodic ? BoundaryKind.PERIODIC : BoundaryKind.WALLS)
                .species(Species.mobile("small", 0.4, 1.0)).species(Species.mobile("large", 0.6, 2.5))
                .species(Species.fixed("peg", 0.5))
                .until(1);
        if (layout == Layout.RANDOM) {
            b.disc(2, 20, 15, 0, 0).disc(0, 3.3, 4.4, 0.5, -0.25);
        }
        int[] species = mixture ? new int[] {0, 1} : new int[] {0};
        double[] fractions = mixture ? new double[] {0.3, 0.7} : new double[] {1};
        VelocityDistribution velocity = seed % 2 == 0 ? new VelocityDistribution.Maxwell(1.5) : new VelocityDistribution.Uniform(2);
        return b.generate(new GenerateBlock(layout, species, fractions, 300, 0.4, velocity, seed)).build();
    }

    @ParameterizedTest
    @CsvSource({"LATTICE, false, true, 1", "LATTICE, true, false, 2", "TRIANGULAR, true, true, 3", "TRIANGULAR, false, false, 4",
        "RANDOM, false, true, 5", "RANDOM, true, false, 6"})
    void everyCallGetsTheSameNumbersInAStateOfItsOwn(Layout layout, boolean mixture, boolean periodic, long seed) {
        Scene scene = scene(layout, mixture, periodic, seed);
        Discs first = scene.newDiscs();
        Discs kept = first.copy();
        first.x[0] += 1;
        first.vy[7] = 99;
        first.t[3] = 5;
        Discs second = scene.newDiscs();
        Discs third = scene.withUntil(2).newDiscs();
        assertThat(second).isNotSameAs(first);
        for (Discs again : new Discs[] {second, third}) {
            assertThat(again.x).isEqualTo(kept.x);
            assertThat(again.y).isEqualTo(kept.y);
            assertThat(again.vx).isEqualTo(kept.vx);
            assertThat(again.vy).isEqualTo(kept.vy);
            assertThat(again.radius).isEqualTo(kept.radius);
            assertThat(again.invMass).isEqualTo(kept.invMass);
            assertThat(again.species).isEqualTo(kept.species);
            assertThat(again.t).containsOnly(0.0);
        }
    }

    @ParameterizedTest
    @CsvSource({"LATTICE, true, true, 7", "RANDOM, true, false, 8"})
    void theFiguresAreThoseOfTheDiscsBeforeAndAfterTheHandOver(Layout layout, boolean mixture, boolean periodic, long seed) {
        Scene scene = scene(layout, mixture, periodic, seed);
        Discs d = scene.newDiscs();
        double area = 0;
        double radii = 0;
        int mobile = 0;
        double mass = 0;
        double twiceKinetic = 0;
        for (int i = 0; i < d.n; i++) {
            area += Math.PI * d.radius[i] * d.radius[i];
            radii += d.radius[i];
            if (d.invMass[i] > 0) {
                mobile++;
                mass += 1 / d.invMass[i];
                twiceKinetic += (d.vx[i] * d.vx[i] + d.vy[i] * d.vy[i]) / d.invMass[i];
            }
        }
        assertThat(scene.size()).isEqualTo(layout == Layout.RANDOM ? 302 : 300);
        assertThat(scene.packingFraction()).isEqualTo(area / scene.box().area());
        assertThat(scene.meanRadius()).isEqualTo(radii / d.n);
        assertThat(scene.mobileCount()).isEqualTo(mobile).isEqualTo(layout == Layout.RANDOM ? 301 : 300);
        assertThat(scene.rmsSpeed()).isCloseTo(Math.sqrt(twiceKinetic / mass), org.assertj.core.api.Assertions.within(1e-12));
    }

    @Test
    void aSceneWithAStateHandsOutCopiesOfIt() {
        Scene base = scene(Layout.LATTICE, false, true, 9);
        Discs state = base.newDiscs();
        state.x[5] = 1.25;
        Scene moved = base.withState(state);
        state.x[5] = 2.5;
        Discs a = moved.newDiscs();
        a.x[5] = 3.75;
        Discs b = moved.newDiscs();
        assertThat(b).isNotSameAs(a);
        assertThat(b.x[5]).isEqualTo(1.25);
    }
}
