package carom.app;

import carom.core.BadInputException;

/** The bounds the run commands' numeric options share, each with the one message it has everywhere. */
final class OptionChecks {
    private OptionChecks() {
    }

    /** {@code value} if it is a finite number above 0; bad input naming {@code option} otherwise (NaN included). */
    static double positiveFinite(String option, double value) {
        if (!(value > 0) || Double.isInfinite(value)) {
            throw new BadInputException(option + ": must be a finite number > 0, got " + value);
        }
        return value;
    }

    /** {@code --threads K}: from 1 to {@link EnginesCommand#MAX_THREADS}. */
    static int threads(int k) {
        if (k < 1 || k > EnginesCommand.MAX_THREADS) {
            throw new BadInputException("--threads: must be from 1 to " + EnginesCommand.MAX_THREADS + ", got " + k);
        }
        return k;
    }
}
