package carom.core.observe.sample;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** J₀ against tabulated values, and its branch-free cosine against Math.cos. */
class BesselTest {
    /** Against scipy.special.j0, to the approximations' 1e-7. */
    @Test
    void j0MatchesTheTable() {
        assertThat(Bessel.j0(0)).isCloseTo(1, within(1e-7));
        assertThat(Bessel.j0(1)).isCloseTo(0.7651976866, within(1e-7));
        assertThat(Bessel.j0(-1)).isCloseTo(0.7651976866, within(1e-7));
        assertThat(Bessel.j0(2.404825558)).isCloseTo(0, within(1e-7));
        assertThat(Bessel.j0(5)).isCloseTo(-0.1775967713, within(1e-7));
        assertThat(Bessel.j0(10)).isCloseTo(-0.2459357645, within(1e-7));
        assertThat(Bessel.j0(30)).isCloseTo(-0.0863679836, within(1e-7));
        assertThat(Bessel.j0(1e4)).isCloseTo(-0.0070961604, within(1e-7)); // beyond the reduction's range
    }

    /** Within a few ulps of 1 of Math.cos from 0 to 1e5 (then Math.cos itself), every quadrant. */
    @Test
    void cosineIsMathCosToAFewUlps() {
        SplittableRandom random = new SplittableRandom(5);
        double worst = 0;
        for (int k = 0; k < 200_000; k++) {
            double x = k < 100_000 ? random.nextDouble() * 20 : random.nextDouble() * 1.2e5;
            worst = Math.max(worst, Math.abs(Bessel.cos(x) - Math.cos(x)));
        }
        for (int q = 0; q < 64; q++) { // at and next to the quadrants' edges
            double x = q * Math.PI / 4;
            worst = Math.max(worst, Math.abs(Bessel.cos(x) - Math.cos(x)));
            worst = Math.max(worst, Math.abs(Bessel.cos(Math.nextUp(x)) - Math.cos(Math.nextUp(x))));
        }
        assertThat(worst).isLessThan(4 * Math.ulp(1.0));
    }
}
