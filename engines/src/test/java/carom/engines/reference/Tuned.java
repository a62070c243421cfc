package carom.engines.reference;

import carom.core.engine.Engine;
import carom.core.engine.EngineSpec;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * An engine run with fixed threads and settings whatever options its callers pass (the contracts build
 * their own options), for instance slabs on two domains kept to windows. Its spec is the engine's.
 *
 * @param engine   the engine
 * @param threads  the threads every run gets, or 0 to keep the caller's
 * @param settings {@code --option} settings every run gets, over the caller's
 */
public record Tuned(Engine engine, int threads, Map<String, String> settings) implements Engine {
    public Tuned {
        settings = java.util.Collections.unmodifiableMap(new LinkedHashMap<>(settings));
    }

    /** {@code engine} on {@code threads} (0: the caller's) with {@code keysAndValues} as settings. */
    public static Tuned of(Engine engine, int threads, String... keysAndValues) {
        Map<String, String> settings = new LinkedHashMap<>();
        for (int k = 0; k < keysAndValues.length; k += 2) {
            settings.put(keysAndValues[k], keysAndValues[k + 1]);
        }
        return new Tuned(engine, threads, settings);
    }

    /** {@code options} with this engine's threads and settings. */
    public RunOptions apply(RunOptions options) {
        RunOptions o = threads > 0 ? options.withThreads(threads) : options;
        for (Map.Entry<String, String> s : settings.entrySet()) {
            o = o.withTunable(s.getKey(), s.getValue());
        }
        return o;
    }

    @Override
    public EngineSpec spec() {
        return engine.spec();
    }

    @Override
    public void checkSupports(Scene scene) {
        engine.checkSupports(scene);
    }

    @Override
    public RunResult run(Scene scene, RunOptions options) {
        return engine.run(scene, apply(options));
    }

    @Override
    public RunResult resume(Scene scene, RunOptions options, byte[] saved) {
        return engine.resume(scene, apply(options), saved);
    }

    @Override
    public String toString() {
        return engine.name() + (threads > 0 ? " on " + threads : "") + (settings.isEmpty() ? "" : " " + settings);
    }
}
