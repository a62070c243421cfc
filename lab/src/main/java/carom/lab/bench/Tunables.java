package carom.lab.bench;

import carom.core.BadInputException;
import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import java.util.TreeSet;

/** Parses a benchmark's {@code key=value;key=value} engine tunables parameter. */
final class Tunables {
    private Tunables() {
    }

    /**
     * Adds the tunables of {@code spec} to {@code options}. A key the engine does not list in
     * {@link Engine#tunables()} is rejected, as on the command line: engines ignore unknown keys, so a
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
            String key = pair.substring(0, eq).trim();
            if (!engine.tunables().contains(key)) {
                String known = engine.tunables().isEmpty() ? "none" : String.join(", ", new TreeSet<>(engine.tunables()));
                throw new BadInputException("tunable " + key + ": engine " + engine.name()
                        + " has no such option (known: " + known + ")");
            }
            result = result.withTunable(key, pair.substring(eq + 1).trim());
        }
        return result;
    }
}
