package carom.core;

/**
 * The user's input is wrong: a malformed or invalid scene, an unknown engine, an effect an engine
 * does not support. The command line turns it into one {@code error:} line and exit status 2.
 * The message names what is wrong (JSON path, particle ids) but not the file; the caller adds that.
 */
public class BadInputException extends RuntimeException {
    public BadInputException(String message) {
        super(message, null, false, false);
    }
}
