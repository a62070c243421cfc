package carom.app.report;

import carom.core.BadInputException;
import carom.core.Quoted;
import carom.core.observe.sample.BondOrder;
import carom.core.observe.sample.HelfandViscosity;
import carom.core.observe.sample.CollisionRates;
import carom.core.observe.sample.MeanSquaredDisplacement;
import carom.core.observe.sample.PressureSeries;
import carom.core.observe.sample.PartialRadialDistribution;
import carom.core.observe.sample.RadialDistribution;
import carom.core.observe.sample.Sample;
import carom.core.observe.sample.SpeciesDisplacement;
import carom.core.observe.sample.StructureFactor;
import carom.core.scene.Scene;
import carom.core.scene.Species;
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
            new ObservableSpec<>(PartialRadialDistribution.KEY,
                    "the partial radial distribution function g_ab(r) of each pair of species, against each pair's own "
                            + "contact distance σ_ab = R_a + R_b, averaged over the samples, with block-average errors",
                    List.of("a", "b", "sigma", "r", "g", "error"),
                    (scene, interval) -> new PartialRadialDistribution(speciesNames(scene)),
                    PartialRadialDistribution::restore, ObservablePlots::partialRadialDistribution),
            new ObservableSpec<>(SpeciesDisplacement.MSD_KEY,
                    "the mean squared displacement of each mobile species against lag, as msd, with block-average errors",
                    List.of("species", "lag", "msd", "error"),
                    (scene, interval) -> SpeciesDisplacement.meanSquared(scene.species(), interval),
                    SpeciesDisplacement::restoreMeanSquared, ObservablePlots::speciesDisplacement),
            new ObservableSpec<>(StructureFactor.KEY,
                    "the static structure factor S(k) and the partial S_ab(k) of each pair of species, direct sums over "
                            + "the periodic box's wave vectors binned by |k|, averaged over the samples, with block-average errors",
                    List.of("a", "b", "k", "S", "error"), ObservableCatalog::structureFactor,
                    StructureFactor::restore, ObservablePlots::structureFactor),
            new ObservableSpec<>(SpeciesDisplacement.FS_KEY,
                    "the self-intermediate scattering function F_s(k, t) of each mobile species against lag, at the first "
                            + "peak of the starting state's S(k), with block-average errors",
                    List.of("species", "k", "lag", "Fs", "error"),
                    (scene, interval) -> SpeciesDisplacement.selfScattering(scene.species(), interval,
                            SpeciesDisplacement.firstPeak(Sample.of(0, scene.box(), scene.newDiscs()), speciesNames(scene))),
                    SpeciesDisplacement::restoreSelfScattering, ObservablePlots::selfScattering),
            new ObservableSpec<>(StressTensor.KEY,
                    "the pressure tensor Pxx, Pyy, Pxy over each interval between consecutive samples: kinetic part "
                            + "from peculiar velocities vx − γ̇·y, collisional part from each collision's impulse "
                            + "(engines that tell collisions)",
                    List.of("t0", "t1", "Pxx", "Pyy", "Pxy"), (scene, interval) -> StressTensor.of(scene.species()),
                    StressTensor::restore, ObservablePlots::stress, stress -> stress),
            new ObservableSpec<>(HelfandViscosity.KEY,
                    "the shear viscosity of an unsheared periodic run by the Einstein-Helfand relation: the mean squared "
                            + "increment of the Helfand moments G_xy and (G_xx − G_yy)/2 against lag, collisional jumps "
                            + "through the minimum image, and the running η(t) = msd/(2 A kT t) with block-average errors "
                            + "(engines that tell collisions)",
                    List.of("lag", "msd", "eta", "error"), ObservableCatalog::viscosity,
                    HelfandViscosity::restore, ObservablePlots::viscosity, viscosity -> viscosity));

    /** The keys, in the order listed. */
    public static final List<String> KEYS = ALL.stream().map(ObservableSpec::key).toList();

    private ObservableCatalog() {
    }

    private static List<String> speciesNames(Scene scene) {
        return scene.species().stream().map(Species::name).toList();
    }

    /** S(k) of a periodic scene; bad input between walls, whose box has no wave vectors. */
    private static StructureFactor structureFactor(Scene scene, double interval) {
        if (!scene.box().periodic()) {
            throw new BadInputException("--observe " + StructureFactor.KEY + ": the structure factor needs a periodic box, "
                    + "and this scene has walls");
        }
        return new StructureFactor(speciesNames(scene));
    }

    /**
     * The Einstein-Helfand viscosity of a scene it applies to: bad input for any other (the relation
     * needs momentum changed by smooth pair collisions only, in a periodic box at rest).
     */
    private static HelfandViscosity viscosity(Scene scene, double interval) {
        String why = scene.box().sheared() ? "a sheared box (use stress: η = −Pxy/γ̇)"
                : !scene.box().periodic() ? "walls"
                : scene.box().thermostatted() ? "a thermostat"
                : scene.effects().hasGravity() ? "gravity"
                : scene.effects().grows() ? "growing discs"
                : scene.effects().rough() ? "rough discs"
                : scene.hasFixedDiscs() ? "fixed discs"
                : scene.size() < 2 ? "fewer than two discs" : null;
        if (why != null) {
            throw new BadInputException("--observe " + HelfandViscosity.KEY + ": the Einstein-Helfand viscosity needs "
                    + "an unsheared periodic box of free, smooth discs, and this scene has " + why);
        }
        return HelfandViscosity.of(scene.species(), interval);
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
            String nearest = NearestName.to(key, KEYS);
            throw new BadInputException("--observe: unknown observable " + Quoted.of(key)
                    + (nearest == null ? "" : "; did you mean " + Quoted.of(nearest) + "?")
                    + " (known: " + String.join(", ", KEYS) + ")");
        }
        return spec;
    }
}
