package carom.lab.bench;

import carom.core.BadInputException;
import carom.core.engine.Engine;
import carom.core.engine.RunOptions;

/** Parses a benchmark's {@code key=value;key=value} engine tunables parameter. */
final class Tunables {
    private Tunables() {
    }

    /**
     * Adds the tunables of {@code spec} to {@code options}. A key the engine does not list in
     * {@link carom.core.engine.EngineSpec#tunables()} is rejected, as on the command line: engines ignore unknown keys, so a
     * typo would otherwise measure the default silently.
     */
    static RunOptions apply(Engine engine, RunOptions options, String spec) {
        RunOptions result = options;
        for (String pair : spec.split(";")) {
            if (pair.isBlank()) {
                continue;
            }
            int eq = pair.indexOf('=');
            if (eq < 0) {
                throw new BadInputException("tunable without '=': " + pair);
            }
            result = result.withTunable(pair.substring(0, eq).trim(), pair.substring(eq + 1).trim());
        }
        carom.core.engine.Tunables.check(engine.name(), engine.spec().tunables(), result.tunables());
        return result;
    }
}
