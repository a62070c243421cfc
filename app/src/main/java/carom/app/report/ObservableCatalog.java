package carom.app.report;

import carom.core.BadInputException;
import carom.core.Quoted;
import carom.core.observe.sample.BondOrder;
import carom.core.observe.sample.CollisionRates;
import carom.core.observe.sample.MeanSquaredDisplacement;
import carom.core.observe.sample.PressureSeries;
import carom.core.observe.sample.RadialDistribution;
import carom.core.observe.sample.StressTensor;
import java.util.List;

/**
 * Every observable {@code simulate --observe} offers, one entry each, in the order the help, the docs
 * and the report list them. {@code --observe} parsing and help, the report's tables and plots, and
 * checkpoint restore are all made from this list, and a test holds the docs' table of observables to it:
 * adding an observable is its class in {@code carom.core.observe.sample}, its chart in
 * {@link ObservablePlots}, one entry here and its row in the docs.
 */
public final class ObservableCatalog {
    /** In the order listed. */
    public static final List<ObservableSpec<?>> ALL = List.of(
            new ObservableSpec<>(RadialDistribution.KEY,
                    "the radial distribution function of all pairs, averaged over the samples; r the bin centre",
                    List.of("r", "g"), (scene, interval) -> new RadialDistribution(), RadialDistribution::restore,
                    ObservablePlots::radialDistribution),
            new ObservableSpec<>(MeanSquaredDisplacement.KEY,
                    "the mean squared displacement against lag (in time units), from unwrapped positions, "
                            + "over the mobile discs and every time origin",
                    List.of("lag", "msd"), (scene, interval) -> MeanSquaredDisplacement.mobileDiscsOf(scene.species(), interval),
                    MeanSquaredDisplacement::restore, ObservablePlots::meanSquaredDisplacement),
            new ObservableSpec<>(BondOrder.KEY,
                    "the global bond-orientational order |ψ6| of each sample",
                    List.of("t", "psi6"), (scene, interval) -> new BondOrder(), BondOrder::restore, ObservablePlots::bondOrder),
            new ObservableSpec<>(PressureSeries.KEY,
                    "the reduced pressure Z over each interval between consecutive samples",
                    List.of("t0", "t1", "Z"), (scene, interval) -> PressureSeries.of(scene.species()), PressureSeries::restore,
                    ObservablePlots::pressure),
            new ObservableSpec<>(CollisionRates.KEY,
                    "the pair-collision rate per disc, 2P/(N·Δt), and the wall-collision rate over each interval "
                            + "between consecutive samples (engines that tell collisions)",
                    List.of("t0", "t1", "pairRate", "wallRate"), (scene, interval) -> new CollisionRates(),
                    CollisionRates::restore, ObservablePlots::collisionRates, rates -> rates),
            new ObservableSpec<>(StressTensor.KEY,
                    "the pressure tensor Pxx, Pyy, Pxy over each interval between consecutive samples: kinetic part "
                            + "from peculiar velocities vx − γ̇·y, collisional part from each collision's impulse "
                            + "(engines that tell collisions)",
                    List.of("t0", "t1", "Pxx", "Pyy", "Pxy"), (scene, interval) -> StressTensor.of(scene.species()),
                    StressTensor::restore, ObservablePlots::stress, stress -> stress));

    /** The keys, in the order listed. */
    public static final List<String> KEYS = ALL.stream().map(ObservableSpec::key).toList();

    private ObservableCatalog() {
    }

    /** The observable named {@code key}, or null. */
    public static ObservableSpec<?> find(String key) {
        for (ObservableSpec<?> spec : ALL) {
            if (spec.key().equals(key)) {
                return spec;
            }
        }
        return null;
    }

    /** The observable named {@code key} on the command line; bad input for a name not listed. */
    public static ObservableSpec<?> named(String key) {
        ObservableSpec<?> spec = find(key);
        if (spec == null) {
            throw new BadInputException("--observe: unknown observable " + Quoted.of(key) + " (known: "
                    + String.join(", ", KEYS) + ")");
        }
        return spec;
    }
}
