package carom.core.observe.sample;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import carom.core.observe.CollisionObserver;
import carom.core.scene.Box;
import java.io.IOException;
import java.io.StringWriter;
import java.io.UncheckedIOException;
import java.util.Arrays;
import java.util.SplittableRandom;
import java.util.function.Function;
import java.util.function.Supplier;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/** What every observable owes a checkpoint: a saved state that continues exactly, and refusal of others'. */
class SampledObservableTest {
    private static final double DT = 0.25;

    static Stream<Arguments> observables() {
        return Stream.of(
                Arguments.of("gr", (Supplier<SampledObservable>) RadialDistribution::new,
                        (Function<ObservableState, SampledObservable>) RadialDistribution::restore),
                Arguments.of("msd", (Supplier<SampledObservable>) () -> new MeanSquaredDisplacement(DT, 4, 5, null),
                        (Function<ObservableState, SampledObservable>) MeanSquaredDisplacement::restore),
                Arguments.of("psi6", (Supplier<SampledObservable>) BondOrder::new,
                        (Function<ObservableState, SampledObservable>) BondOrder::restore),
                Arguments.of("pressure", (Supplier<SampledObservable>) () -> new PressureSeries(new double[] {1}),
                        (Function<ObservableState, SampledObservable>) PressureSeries::restore),
                Arguments.of("collisions", (Supplier<SampledObservable>) CollisionRates::new,
                        (Function<ObservableState, SampledObservable>) CollisionRates::restore));
    }

    /** Random discs taking Gaussian steps in a periodic box, with a virial and collisions between samples. */
    private static void feed(SampledObservable o, int from, int to, long seed) {
        Box box = TestSamples.box(15, 12, true);
        for (int s = from; s < to; s++) {
            SplittableRandom random = new SplittableRandom(seed + s);
            if (o instanceof CollisionObserver listener) {
                for (int c = random.nextInt(40); c > 0; c--) {
                    listener.pair(s * DT, 0, 1, 1, 0, 1, 0, 1);
                }
                for (int c = random.nextInt(4); c > 0; c--) {
                    listener.wall(s * DT, 0, 0, 1);
                }
            }
            o.accept(TestSamples.withVirial(TestSamples.idealGas(s * DT, box, 120, 0.5, random), random.nextDouble() * 100));
        }
    }

    private static String csv(SampledObservable o) {
        StringWriter w = new StringWriter();
        try {
            o.writeRows(w);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return w.toString();
    }

    /** Saved after any number of samples (none included), restored, fed the rest: the same bits as never stopped. */
    @ParameterizedTest(name = "{0}")
    @MethodSource("observables")
    void restoredStateContinuesExactly(String key, Supplier<SampledObservable> create,
                                        Function<ObservableState, SampledObservable> restore) {
        int total = 70;
        SampledObservable whole = create.get();
        feed(whole, 0, total, 17);
        assertThat(whole.key()).isEqualTo(key);
        for (int stop : new int[] {0, 1, 9, 33}) {
            SampledObservable first = create.get();
            feed(first, 0, stop, 17);
            SampledObservable resumed = restore.apply(first.state());
            assertThat(resumed.state()).isEqualTo(first.state());
            feed(resumed, stop, total, 17);
            assertThat(csv(resumed)).as("stopped after %d samples", stop).isEqualTo(csv(whole));
            assertThat(resumed.state()).isEqualTo(whole.state());
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("observables")
    void refusesTruncatedForeignAndOtherVersionStates(String key, Supplier<SampledObservable> create,
                                                      Function<ObservableState, SampledObservable> restore) {
        SampledObservable o = create.get();
        feed(o, 0, 5, 3);
        ObservableState state = o.state();
        long[] longs = state.longs();
        double[] doubles = state.doubles();
        ObservableState truncated = doubles.length > 0
                ? new ObservableState(key, longs, Arrays.copyOf(doubles, doubles.length - 1))
                : new ObservableState(key, Arrays.copyOf(longs, longs.length - 1), doubles);
        assertThatThrownBy(() -> restore.apply(truncated)).isInstanceOf(IllegalArgumentException.class);
        ObservableState longer = new ObservableState(key, longs, Arrays.copyOf(doubles, doubles.length + 1));
        assertThatThrownBy(() -> restore.apply(longer)).isInstanceOf(IllegalArgumentException.class);
        long[] otherVersion = longs.clone();
        otherVersion[0] = 99;
        assertThatThrownBy(() -> restore.apply(new ObservableState(key, otherVersion, doubles)))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("layout");
        assertThatThrownBy(() -> restore.apply(new ObservableState("nope", longs, doubles)))
                .isInstanceOf(IllegalArgumentException.class);
    }
}
