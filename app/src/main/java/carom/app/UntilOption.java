package carom.app;

import picocli.CommandLine.Option;

/**
 * {@code --until T}: the simulated end time that overrides the scene's (or a checkpoint's). A mixin of
 * {@code simulate} and {@code resume}; {@link ResumeHelp} words it for a continued run.
 */
final class UntilOption {
    @Option(names = "--until", paramLabel = "T", descriptionKey = "until",
            description = "Simulated end time, overriding the scene's.")
    Double until;

    /** The end time given, checked to be a finite number > 0; null when none is given. */
    Double checked() {
        return until == null ? null : OptionChecks.positiveFinite("--until", until);
    }
}
