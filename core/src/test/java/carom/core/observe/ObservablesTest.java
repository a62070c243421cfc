package carom.core.observe;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.physics.Flight;
import carom.core.state.Discs;
import org.junit.jupiter.api.Test;

class ObservablesTest {
    /** Two discs of mass 2 and one fixed disc: the fixed one has neither kinetic nor potential energy. */
    private static Discs threeDiscs() {
        Discs d = new Discs(3);
        for (int i = 0; i < 2; i++) {
            d.invMass[i] = 0.5;
            d.radius[i] = 0.5;
        }
        d.x[0] = 1;
        d.y[0] = 3;
        d.vx[0] = 1;
        d.vy[0] = 2;
        d.x[1] = 4;
        d.y[1] = 5;
        d.vy[1] = -1;
        d.x[2] = 7;
        d.y[2] = 9;
        d.radius[2] = 1;
        return d;
    }

    @Test
    void withoutGravityTotalEnergyIsKinetic() {
        Discs d = threeDiscs();
        // 0.5 * 2 * (1 + 4) + 0.5 * 2 * 1
        assertThat(Observables.totalEnergy(d, Flight.STRAIGHT)).isEqualTo(6.0);
        assertThat(Observables.totalEnergy(d, Flight.STRAIGHT)).isEqualTo(Observables.kineticEnergy(d));
    }

    @Test
    void gravityAddsMassTimesGTimesHeightOfMobileDiscsOnly() {
        Discs d = threeDiscs();
        // g = (0, -2): potential m g y = 2 * 2 * 3 + 2 * 2 * 5 = 32; the fixed disc at y = 9 adds nothing.
        assertThat(Observables.totalEnergy(d, Flight.parabolic(0, -2))).isCloseTo(6.0 + 32.0, within(1e-12));
    }

    @Test
    void totalEnergyOfAFallingDiscStaysPut() {
        Discs d = threeDiscs();
        Flight flight = Flight.parabolic(0.3, -2);
        double before = Observables.totalEnergy(d, flight);
        flight.advance(d, 0, 0.7);
        flight.advance(d, 1, 1.3);
        assertThat(Observables.totalEnergy(d, flight)).isCloseTo(before, within(1e-12));
    }
}
