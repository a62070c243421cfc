package carom.lab.study;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

/** {@code carom study}: studies that compare engines ({@code accuracy}) and physics ({@code eos}). */
@Command(name = "study", mixinStandardHelpOptions = true,
        description = "Studies comparing carom's engines (and a peer library).",
        subcommands = {AccuracyCommand.class, carom.lab.eos.EosCommand.class})
public final class StudyCommand implements Runnable {
    @Spec
    CommandSpec spec;

    @Override
    public void run() {
        throw new ParameterException(spec.commandLine(), "missing study: use 'carom study accuracy --out DIR' or 'carom study eos --out DIR'");
    }
}
