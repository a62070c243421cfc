package carom.app;

import picocli.CommandLine.Option;

/**
 * {@code --allow-long}: run even what {@link WorkBounds} would refuse as a likely mistake. A mixin of
 * {@code simulate} and {@code resume}, which apply the same bounds.
 */
final class LongRunOption {
    @Option(names = "--allow-long", descriptionKey = "allow-long",
            description = "Run even when the scene would take more than about 1e11 collisions (days at a million a second), "
                    + "or its samples and checkpoints as much work, or its trajectory more than 1e9 rows, which is otherwise "
                    + "refused as a likely mistake.")
    boolean allowed;
}
