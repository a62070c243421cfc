package carom.app.report;

import carom.core.BadInputException;
import carom.core.engine.Sampler;
import carom.core.observe.CollisionObserver;
import carom.core.observe.sample.ObservableState;
import carom.core.observe.sample.Sample;
import carom.core.observe.sample.SampledObservable;
import carom.core.scene.Scene;
import carom.core.state.Discs;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/**
 * {@code simulate --observe LIST --report DIR}: the chosen observables ({@link ObservableCatalog}) fed by
 * the run's samples as it goes (no second pass over a trajectory), and those that listen to collisions
 * by the engine's collisions ({@link #collisions()}, which the run's options must carry); then one CSV
 * and one plot each into the report folder. Each sample carries the collision virial since the previous
 * one, from the sampler's running sum.
 */
public final class Observing implements Sampler {
    /** One chosen observable with its spec, so that its table and plot are its own type's. */
    private record Chosen<T extends SampledObservable>(ObservableSpec<T> spec, T observable) {
        static <T extends SampledObservable> Chosen<T> create(ObservableSpec<T> spec, Scene scene, double interval) {
            return new Chosen<>(spec, spec.create().create(scene, interval));
        }

        static <T extends SampledObservable> Chosen<T> restore(ObservableSpec<T> spec, ObservableState state) {
            return new Chosen<>(spec, spec.restore().apply(state));
        }

        CollisionObserver collisions() {
            return spec.collisions().apply(observable);
        }

        void writeInto(Path folder) throws IOException {
            spec.writeInto(observable, folder);
        }
    }

    private final Scene scene;
    private final List<Chosen<?>> chosen;
    private final CollisionObserver collisions;
    private double lastVirialSum;

    private Observing(Scene scene, List<Chosen<?>> chosen) {
        this.scene = scene;
        this.chosen = List.copyOf(chosen);
        this.collisions = CollisionObserver.all(this.chosen.stream().filter(c -> c.spec().needsCollisions())
                .map(Chosen::collisions).toList());
    }

    /**
     * The observables named in {@code list} (comma-separated keys of {@link ObservableCatalog}, each at
     * most once), sampled every {@code every}; bad input for an unknown or repeated name.
     */
    public static Observing of(Scene scene, String list, double every) {
        Set<ObservableSpec<?>> specs = new LinkedHashSet<>();
        for (String part : list.split(",", -1)) {
            String key = part.strip();
            if (!specs.add(ObservableCatalog.named(key))) {
                throw new BadInputException("--observe: " + key + " named twice");
            }
        }
        List<Chosen<?>> chosen = new ArrayList<>();
        for (ObservableSpec<?> spec : specs) {
            chosen.add(Chosen.create(spec, scene, every));
        }
        return new Observing(scene, chosen);
    }

    /** The observables a checkpoint saved ({@link #states}), continuing exactly where they stopped. */
    public static Observing restored(Scene scene, List<ObservableState> states, double lastVirialSum) {
        List<Chosen<?>> kept = new ArrayList<>();
        for (ObservableState state : states) {
            ObservableSpec<?> spec = ObservableCatalog.find(state.key());
            try {
                if (spec == null) {
                    throw new IllegalArgumentException("unknown observable '" + state.key() + "'");
                }
                kept.add(Chosen.restore(spec, state));
            } catch (IllegalArgumentException e) {
                throw new BadInputException("malformed checkpoint: " + e.getMessage());
            }
        }
        Observing restored = new Observing(scene, kept);
        restored.lastVirialSum = lastVirialSum;
        return restored;
    }

    /** Whether an observable chosen listens to collisions: the engine must tell them. */
    public boolean needsCollisions() {
        return collisions != null;
    }

    /**
     * What the engine must tell every collision ({@code RunOptions.withCollisions}): all the chosen
     * observables that listen to collisions behind one observer; null when none does.
     */
    public CollisionObserver collisions() {
        return collisions;
    }

    /**
     * Bad input, before the run, if an observable chosen listens to collisions and {@code engine} does
     * not tell them ({@code tellsCollisions}, from its spec).
     */
    public void checkCollisionsToldBy(String engine, boolean tellsCollisions) {
        if (needsCollisions() && !tellsCollisions) {
            List<String> keys = chosen.stream().filter(c -> c.spec().needsCollisions()).map(c -> c.spec().key()).toList();
            throw new BadInputException("--observe: " + String.join(", ", keys) + " counts collisions as the engine "
                    + "carries them out, and engine " + engine + " does not tell them");
        }
    }

    /** The chosen observables, in the order named. */
    List<SampledObservable> observables() {
        return chosen.stream().<SampledObservable>map(Chosen::observable).toList();
    }

    /** Every observable's state so far, for a checkpoint, in the order named. */
    public List<ObservableState> states() {
        return chosen.stream().map(c -> c.observable().state()).toList();
    }

    /** The virial sum at the last sample (where the next interval's virial starts), for a checkpoint. */
    public double lastVirialSum() {
        return lastVirialSum;
    }

    @Override
    public void sample(double time, Discs state, double virialSum) {
        Sample sample = Sample.of(time, scene.box(), state, virialSum - lastVirialSum);
        lastVirialSum = virialSum;
        for (Chosen<?> c : chosen) {
            c.observable().accept(sample);
        }
    }

    /** Writes {@code KEY.csv}, {@code KEY.png} and {@code KEY.svg} of every observable into {@code folder}. */
    public void writeInto(Path folder) throws IOException {
        for (Chosen<?> c : chosen) {
            c.writeInto(folder);
        }
    }

    /** Both samplers, in order: a trajectory and the observables from the same samples. */
    public static Sampler both(Sampler first, Sampler second) {
        if (first == null) {
            return second;
        }
        if (second == null) {
            return first;
        }
        return (t, state, virial) -> {
            first.sample(t, state, virial);
            second.sample(t, state, virial);
        };
    }
}
