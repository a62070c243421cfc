package carom.app;

import carom.core.BadInputException;
import carom.core.Quoted;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.function.Supplier;

/**
 * The scene file a command was given, and the rule that bad input found while handling it names the
 * file: {@code error: FILE: what is wrong}. Shared by every command that reads a scene.
 */
public record SceneFile(String name) {
    /** The file as a path; a name the file system cannot take is bad input. */
    public Path path() {
        try {
            return Path.of(name);
        } catch (InvalidPathException e) {
            throw new BadInputException("not a valid file name: " + Quoted.bare(e.getReason()));
        }
    }

    /** Runs {@code step}; bad input it reports gets the file's name in front. */
    public <T> T about(Supplier<T> step) {
        try {
            return step.get();
        } catch (BadInputException e) {
            throw new BadInputException(Quoted.fileName(name) + ": " + e.getMessage());
        }
    }
}
