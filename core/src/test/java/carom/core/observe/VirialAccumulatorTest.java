package carom.core.observe;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.scene.BoundaryKind;
import carom.core.scene.Scene;
import carom.core.scene.SceneBuilder;
import carom.core.scene.Species;
import carom.core.state.Discs;
import org.junit.jupiter.api.Test;

/** Pressure from the collision virial, and the whole-system observables. */
class VirialAccumulatorTest {
    @Test
    void compressibilityIsOnePlusVirialOverTwiceDurationTimesEnergy() {
        // Blocks of length 1 over [0, 4]; Z_b = 1 + sum_b / (2 * 1 * KE) with KE = 10.
        VirialAccumulator acc = new VirialAccumulator(0, 4, 4);
        acc.add(0.5, 20);
        acc.add(1.5, 40);
        acc.add(2.25, 20);
        acc.add(2.75, 20);
        acc.add(3.9, 60);
        Pressure p = acc.pressure(5, 10, 25);
        // Z per block: 2, 3, 3, 4; mean 3; sample variance 2/3; standard error sqrt(2/3/4).
        assertThat(p.compressibility()).isCloseTo(3, within(1e-15));
        assertThat(p.compressibilityError()).isCloseTo(Math.sqrt(2.0 / 3 / 4), within(1e-15));
        assertThat(p.blocks()).isEqualTo(4);
        // P = Z N kT / A with kT = KE / N.
        assertThat(p.pressure()).isCloseTo(3 * 10 / 25.0, within(1e-15));
        assertThat(p.pressureError()).isCloseTo(Math.sqrt(2.0 / 3 / 4) * 10 / 25.0, within(1e-15));
    }

    @Test
    void timesOutsideTheRangeCountInTheEdgeBlocksAndMergingAdds() {
        VirialAccumulator a = new VirialAccumulator(1, 3, 2);
        a.add(0.5, 4);
        a.add(3, 4);
        a.add(7, 4);
        VirialAccumulator b = new VirialAccumulator(1, 3, 2);
        b.add(1.2, 4);
        a.addAll(b);
        Pressure p = a.pressure(1, 1, 1);
        // Block 0: 8, block 1: 8 -> Z = 1 + 8 / 2 = 5 in both, error 0.
        assertThat(p.compressibility()).isCloseTo(5, within(1e-15));
        assertThat(p.compressibilityError()).isZero();
    }

    @Test
    void idealGasHasCompressibilityOneAndNoPressureWithoutEnergy() {
        VirialAccumulator acc = new VirialAccumulator(0, 1, 10);
        assertThat(acc.pressure(10, 5, 100).compressibility()).isEqualTo(1);
        assertThat(acc.pressure(0, 5, 100)).isNull();
        assertThat(acc.pressure(10, 0, 100)).isNull();
    }

    @Test
    void observablesCountOnlyMobileDiscs() {
        Discs d = new Discs(3);
        d.invMass[0] = 0.5; // mass 2
        d.vx[0] = 1;
        d.vy[0] = -2;
        d.invMass[1] = 0; // fixed
        d.invMass[2] = 1;
        d.vx[2] = 3;
        assertThat(Observables.kineticEnergy(d)).isCloseTo(0.5 * 2 * 5 + 0.5 * 9, within(1e-15));
        assertThat(Observables.momentum(d)).containsExactly(2 + 3, -4);
        assertThat(Observables.mobileCount(d)).isEqualTo(2);
    }

    @Test
    void aWalledBoxCountsTheAreaTheCentresReachWhenTheDiscsShareOneRadius() {
        Scene walls = scene(BoundaryKind.WALLS, 0.5, 0.5);
        assertThat(VirialAccumulator.pressureArea(walls, walls.newDiscs())).isEqualTo(9.0 * 4.0);
        Scene periodic = scene(BoundaryKind.PERIODIC, 0.5, 0.5);
        assertThat(VirialAccumulator.pressureArea(periodic, periodic.newDiscs())).isEqualTo(10.0 * 5.0);
        // Mixed radii have no single reachable area: the box's stands in.
        Scene mixed = scene(BoundaryKind.WALLS, 0.5, 0.25);
        assertThat(VirialAccumulator.pressureArea(mixed, mixed.newDiscs())).isEqualTo(10.0 * 5.0);
    }

    @Test
    void aFixedDiscsRadiusDoesNotChangeTheArea() {
        Scene pegged = SceneBuilder.create("pegged").box(10, 5, BoundaryKind.WALLS)
                .species(Species.mobile("ball", 0.5, 1)).species(Species.fixed("peg", 1.5))
                .disc(0, 2, 2, 1, 0).disc(1, 6, 2, 0, 0).until(1).build();
        assertThat(VirialAccumulator.pressureArea(pegged, pegged.newDiscs())).isEqualTo(9.0 * 4.0);
    }

    private static Scene scene(BoundaryKind boundary, double r0, double r1) {
        return SceneBuilder.create("two").box(10, 5, boundary)
                .species(Species.mobile("a", r0, 1)).species(Species.mobile("b", r1, 1))
                .disc(0, 2, 2, 1, 0).disc(1, 6, 2, -1, 0).until(1).build();
    }
}
