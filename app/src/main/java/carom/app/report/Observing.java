package carom.app.report;

import carom.core.BadInputException;
import carom.core.Quoted;
import carom.core.engine.Sampler;
import carom.core.observe.sample.BondOrder;
import carom.core.observe.sample.MeanSquaredDisplacement;
import carom.core.observe.sample.PressureSeries;
import carom.core.observe.sample.RadialDistribution;
import carom.core.observe.sample.Sample;
import carom.core.observe.sample.SampledObservable;
import carom.core.scene.Scene;
import carom.core.state.Discs;
import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/**
 * {@code simulate --observe LIST --report DIR}: the chosen observables fed by the run's samples as it
 * goes (no second pass over a trajectory), then one CSV and one PNG each into the report folder. The
 * pressure series takes the collision virial accumulated between samples from the sampler's running
 * sum.
 */
public final class Observing implements Sampler {
    private final Scene scene;
    private final List<SampledObservable> observables;
    private final PressureSeries pressure;
    private double lastVirialSum;

    private Observing(Scene scene, List<SampledObservable> observables) {
        this.scene = scene;
        this.observables = observables;
        this.pressure = (PressureSeries) observables.stream().filter(o -> o instanceof PressureSeries).findFirst().orElse(null);
    }

    /**
     * The observables named in {@code list} (comma-separated keys of {@link SampledObservable#KEYS}, each
     * at most once), sampled every {@code every}; bad input for an unknown or repeated name.
     */
    public static Observing of(Scene scene, String list, double every) {
        Set<String> keys = new LinkedHashSet<>();
        for (String part : list.split(",", -1)) {
            String key = part.strip();
            if (!SampledObservable.KEYS.contains(key)) {
                throw new BadInputException("--observe: unknown observable " + Quoted.of(key) + " (known: "
                        + String.join(", ", SampledObservable.KEYS) + ")");
            }
            if (!keys.add(key)) {
                throw new BadInputException("--observe: " + key + " named twice");
            }
        }
        List<SampledObservable> chosen = new ArrayList<>();
        for (String key : keys) {
            chosen.add(switch (key) {
                case RadialDistribution.KEY -> new RadialDistribution();
                case MeanSquaredDisplacement.KEY -> MeanSquaredDisplacement.mobileDiscsOf(scene.species(), every);
                case BondOrder.KEY -> new BondOrder();
                case PressureSeries.KEY -> PressureSeries.of(scene.species());
                default -> throw new IllegalStateException(key);
            });
        }
        return new Observing(scene, chosen);
    }

    /** Every observable's state so far, for a checkpoint, in the order named. */
    public List<carom.core.observe.sample.ObservableState> states() {
        return observables.stream().map(SampledObservable::state).toList();
    }

    /** The virial sum at the last sample (where the next pressure interval starts), for a checkpoint. */
    public double lastVirialSum() {
        return lastVirialSum;
    }

    /** The observables a checkpoint saved ({@link #states}), continuing exactly where they stopped. */
    public static Observing restored(Scene scene, List<carom.core.observe.sample.ObservableState> states,
                                     double lastVirialSum) {
        List<SampledObservable> kept = new ArrayList<>();
        for (carom.core.observe.sample.ObservableState state : states) {
            try {
                kept.add(SampledObservable.restore(state));
            } catch (IllegalArgumentException e) {
                throw new BadInputException("malformed checkpoint: " + e.getMessage());
            }
        }
        Observing restored = new Observing(scene, kept);
        restored.lastVirialSum = lastVirialSum;
        return restored;
    }

    @Override
    public void sample(double time, Discs state, double virialSum) {
        if (pressure != null) {
            pressure.addVirial(virialSum - lastVirialSum);
        }
        lastVirialSum = virialSum;
        Sample sample = Sample.of(time, scene.box(), state);
        for (SampledObservable o : observables) {
            o.accept(sample);
        }
    }

    /** Writes {@code KEY.csv}, {@code KEY.png} and {@code KEY.svg} of every observable into {@code folder}. */
    public void writeInto(Path folder) throws IOException {
        for (SampledObservable o : observables) {
            try (Writer w = Files.newBufferedWriter(folder.resolve(o.key() + ".csv"), StandardCharsets.UTF_8)) {
                o.writeCsv(w);
            }
            ObservablePlots.write(o, folder);
            ObservablePlots.writeVector(o, folder);
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
