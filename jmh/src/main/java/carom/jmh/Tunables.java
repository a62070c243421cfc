package carom.jmh;

import carom.core.engine.RunOptions;

/** Parses a benchmark's {@code key=value;key=value} engine tunables parameter. */
final class Tunables {
    private Tunables() {
    }

    static RunOptions apply(RunOptions options, String spec) {
        RunOptions result = options;
        for (String pair : spec.split(";")) {
            if (pair.isBlank()) {
                continue;
            }
            int eq = pair.indexOf('=');
            if (eq < 0) {
                throw new IllegalArgumentException("tunable without '=': " + pair);
            }
            result = result.withTunable(pair.substring(0, eq).trim(), pair.substring(eq + 1).trim());
        }
        return result;
    }
}
