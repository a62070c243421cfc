package carom.core.observe.sample;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import carom.core.scene.Box;
import carom.core.state.Discs;
import org.junit.jupiter.api.Test;

class SampleTest {
    @Test
    void periodicPositionsAreWrappedIntoTheBox() {
        Box box = TestSamples.box(10, 5, true);
        Sample s = TestSamples.at(0, box, new double[] {-0.5, 10, 23, -1e-18}, new double[] {5, -5, 2.5, 0}, 0.5);
        assertThat(s.x(0)).isEqualTo(9.5);
        assertThat(s.x(1)).isEqualTo(0.0);
        assertThat(s.x(2)).isEqualTo(3.0);
        assertThat(s.x(3)).isGreaterThanOrEqualTo(0.0).isLessThan(10.0); // rounds to 10 after wrapping: 0
        assertThat(s.y(0)).isEqualTo(0.0);
        assertThat(s.y(1)).isEqualTo(0.0);
        assertThat(s.y(2)).isEqualTo(2.5);
    }

    @Test
    void wallPositionsAreKeptAndTheSampleOwnsItsArrays() {
        Discs d = new Discs(2);
        d.x[0] = 1;
        d.y[0] = 2;
        d.vx[1] = 3;
        d.radius[0] = 0.5;
        d.radius[1] = 0.25;
        d.species[1] = 1;
        Sample s = Sample.of(4, TestSamples.box(10, 10, false), d);
        d.x[0] = 7;
        d.vx[1] = 8;
        assertThat(s.x(0)).isEqualTo(1);
        assertThat(s.vx(1)).isEqualTo(3);
        assertThat(s.species(1)).isEqualTo(1);
        assertThat(s.time()).isEqualTo(4);
        assertThat(s.size()).isEqualTo(2);
        assertThat(s.contactDistance()).isEqualTo(0.75);
    }

    @Test
    void refusesArraysOfDifferentLengths() {
        assertThatThrownBy(() -> Sample.of(0, TestSamples.box(1, 1, true), new double[2], new double[2], new double[2],
                new double[1], new double[2], new int[2])).isInstanceOf(IllegalArgumentException.class);
    }
}
