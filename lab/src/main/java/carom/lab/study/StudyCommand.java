package carom.lab.study;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

/** {@code carom study}: what accuracy costs ({@code accuracy}) and the equation of state through the liquid-hexatic transition ({@code eos}). */
@Command(name = "study", mixinStandardHelpOptions = true,
        description = "Studies: what each engine's speed costs in accuracy (accuracy), and the hard-disc equation of state "
                + "through the liquid-hexatic transition (eos).",
        subcommands = {AccuracyCommand.class, carom.lab.study.eos.EosCommand.class})
public final class StudyCommand implements Runnable {
    @Spec
    CommandSpec spec;

    @Override
    public void run() {
        throw new ParameterException(spec.commandLine(), "missing study: use 'carom study accuracy --out DIR' or 'carom study eos --out DIR'");
    }
}
