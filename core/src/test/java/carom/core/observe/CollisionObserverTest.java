package carom.core.observe;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** One observer behind several: none is null, one is itself, more are each told every collision in order. */
class CollisionObserverTest {
    /** Writes what it is told into a shared log, prefixed with its name. */
    private record Logging(String name, List<String> log) implements CollisionObserver {
        @Override
        public void pair(double time, int i, int k, double dx, double dy, double nx, double ny, double j) {
            log.add(name + " pair " + time + " " + i + " " + k + " " + dx + " " + dy + " " + nx + " " + ny + " " + j);
        }

        @Override
        public void wall(double time, int i, int wall, double j) {
            log.add(name + " wall " + time + " " + i + " " + wall + " " + j);
        }
    }

    @ParameterizedTest(name = "{0} observers")
    @ValueSource(ints = {0, 1, 2, 3})
    void tellsEveryObserverEveryCollisionInListOrder(int count) {
        List<String> log = new ArrayList<>();
        List<Logging> observers = new ArrayList<>();
        for (int o = 0; o < count; o++) {
            observers.add(new Logging("o" + o, log));
        }
        CollisionObserver all = CollisionObserver.all(observers);
        if (count == 0) {
            assertThat(all).isNull();
            return;
        }
        if (count == 1) {
            assertThat(all).isSameAs(observers.getFirst());
        }
        all.pair(1.5, 3, 4, 0.6, 0.8, 0.6, 0.8, 2.0);
        all.wall(2.5, 7, 1, 0.5);
        List<String> expected = new ArrayList<>();
        for (int o = 0; o < count; o++) {
            expected.add("o" + o + " pair 1.5 3 4 0.6 0.8 0.6 0.8 2.0");
        }
        for (int o = 0; o < count; o++) {
            expected.add("o" + o + " wall 2.5 7 1 0.5");
        }
        assertThat(log).containsExactlyElementsOf(expected);
    }
}
