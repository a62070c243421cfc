package carom.lab.study;

import carom.engines.stepped.SteppedEngine;
import carom.core.engine.Tunables;
import carom.core.engine.Capability;
import carom.core.engine.Engine;
import carom.engines.EngineCatalog;
import carom.lab.peer.Dyn4jPeer;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

/**
 * One engine and setting of the study: an engine by name (the catalog's or the dyn4j peer), its thread
 * count, and for engines with a time step ({@code dt} tunable) the step as a multiple of the stepped
 * engine's default.
 */
record Setting(String engine, int threads, double dtFactor) {
    static final String PEER = "dyn4j";

    boolean hasDt() {
        return !Double.isNaN(dtFactor);
    }

    String label() {
        if (hasDt()) {
            return engine + " dt×" + StudyScene.fmt(dtFactor);
        }
        return onOneThread(engineNamed(engine)) ? engine : engine + " ×" + threads;
    }

    /** The engine itself: a catalog engine or the peer. */
    static Engine engineNamed(String name) {
        return name.equals(PEER) ? new Dyn4jPeer() : EngineCatalog.byName(name);
    }

    /** Every engine the study knows: the catalog's, then the peer. */
    static List<String> knownEngines() {
        return Stream.concat(EngineCatalog.all().stream().map(Engine::name), Stream.of(PEER)).toList();
    }

    /**
     * The settings for these engines: a stepping engine once per dt factor, any other engine on one
     * thread once, the rest (those that run on {@code --threads}) once per thread count.
     */
    static List<Setting> expand(List<String> engines, List<Integer> threads, List<Double> dtFactors) {
        List<Setting> settings = new ArrayList<>();
        for (String name : engines) {
            Engine engine = engineNamed(name);
            if (steps(engine)) {
                dtFactors.forEach(f -> settings.add(new Setting(name, 1, f)));
            } else if (onOneThread(engine)) {
                settings.add(new Setting(name, 1, Double.NaN));
            } else {
                threads.forEach(k -> settings.add(new Setting(name, k, Double.NaN)));
            }
        }
        return settings;
    }

    /** Whether {@code engine} advances in time steps ({@code dt}): then its settings are its steps. */
    private static boolean steps(Engine engine) {
        return Tunables.declares(engine.spec().tunables(), SteppedEngine.DT.name());
    }

    /** Whether {@code engine} has no time step and runs on one thread whatever {@code --threads} asks: then it runs once. */
    private static boolean onOneThread(Engine engine) {
        return !steps(engine) && !engine.spec().can(Capability.THREADS);
    }
}
