package carom.engines.reference;

import carom.core.engine.Engine;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import java.util.function.Consumer;
import java.util.function.Predicate;
import java.util.function.Supplier;

/**
 * One way of running an engine under a contract: the engine (perhaps {@link Tuned}), the contracts it
 * joins, and what the contracts ask of it. Built by {@link #of} and the {@code with...} methods, each
 * returning a new variant; what a contract does not name keeps its default.
 *
 * @param label              how test names show the variant
 * @param source             makes the engine when a contract first runs it (running workers start late)
 * @param contracts          the contracts this variant joins
 * @param sweepKey           the setting the brute-force contract varies ({@code cellFactor}, {@code skin}), or null
 * @param sweep              its values: the first is compared with the judge, the others with the first
 * @param scenes             the scenes the checkpoint contract runs (an engine that refuses some effects skips them)
 * @param eachRun            what must hold of every run of the brute-force contract besides {@link Invariants}
 * @param denseCounters      what the engine's counters must say after a dense run
 * @param samplingTolerance  how far samples may move the final state (0: not a bit)
 */
public record EngineVariant(String label, Supplier<? extends Engine> source, Set<Contract> contracts, String sweepKey,
                            List<String> sweep, Predicate<Scene> scenes, Consumer<RunResult> eachRun,
                            Consumer<RunResult> denseCounters, double samplingTolerance) {
    /** {@code engine} as it comes, labelled by its name, in every contract that applies to its spec. */
    public static EngineVariant of(Engine engine) {
        return of(engine.name(), engine);
    }

    /** {@code engine} labelled {@code label}, in every contract that applies to its spec. */
    public static EngineVariant of(String label, Engine engine) {
        return lazy(label, () -> engine);
    }

    /** The engine {@code source} makes when first asked, labelled {@code label}, in every contract. */
    public static EngineVariant lazy(String label, Supplier<? extends Engine> source) {
        return new EngineVariant(label, source, EnumSet.allOf(Contract.class), null, List.of(), scene -> true,
                result -> { }, result -> { }, 0);
    }

    /** The engine under test. */
    public Engine engine() {
        return source.get();
    }

    /** This variant in these contracts only (those of them that apply to its spec). */
    public EngineVariant in(Contract first, Contract... more) {
        return new EngineVariant(label, source, EnumSet.of(first, more), sweepKey, sweep, scenes, eachRun, denseCounters,
                samplingTolerance);
    }

    /** This variant's brute-force contract varying {@code key} over {@code values}. */
    public EngineVariant sweeping(String key, String... values) {
        return new EngineVariant(label, source, contracts, key, List.of(values), scenes, eachRun, denseCounters,
                samplingTolerance);
    }

    /** This variant's checkpoint contract on the scenes {@code test} passes only. */
    public EngineVariant onScenes(Predicate<Scene> test) {
        return new EngineVariant(label, source, contracts, sweepKey, sweep, test, eachRun, denseCounters, samplingTolerance);
    }

    /** This variant's brute-force contract checking {@code check} of every run. */
    public EngineVariant checkingEachRun(Consumer<RunResult> check) {
        return new EngineVariant(label, source, contracts, sweepKey, sweep, scenes, check, denseCounters, samplingTolerance);
    }

    /** This variant's dense-scene contract checking {@code check} of every run's counters. */
    public EngineVariant checkingDenseCounters(Consumer<RunResult> check) {
        return new EngineVariant(label, source, contracts, sweepKey, sweep, scenes, eachRun, check, samplingTolerance);
    }

    /** This variant's samples contract allowing samples to move the final state by {@code tolerance}. */
    public EngineVariant withSamplingTolerance(double tolerance) {
        return new EngineVariant(label, source, contracts, sweepKey, sweep, scenes, eachRun, denseCounters, tolerance);
    }

    /** Whether this variant runs {@code contract}: it joins it and its engine's spec must hold it. */
    public boolean runs(Contract contract) {
        return contracts.contains(contract) && contract.appliesTo(engine().spec());
    }

    @Override
    public String toString() {
        return label;
    }
}
