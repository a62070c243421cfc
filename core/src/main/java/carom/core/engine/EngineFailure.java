package carom.core.engine;

/**
 * A failure of an engine itself, not of its input: an exception inside a parallel worker or actor,
 * or a run that stopped making progress. Reported as an internal failure (exit status 1), with where
 * it happened in the message.
 */
public final class EngineFailure extends RuntimeException {
    public EngineFailure(String message, Throwable cause) {
        super(message, cause);
    }

    public EngineFailure(String message) {
        super(message);
    }
}
