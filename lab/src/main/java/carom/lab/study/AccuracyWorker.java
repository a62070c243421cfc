package carom.lab.study;

import carom.lab.run.ChildJvm;
import java.io.PrintWriter;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

/**
 * {@code worker study}, the child JVM of the accuracy study ({@link ChildJvm}): reads one {@link Trial}
 * from standard input, runs it and sends its timed runs' records. Not a user command:
 * {@code carom study accuracy} starts it.
 */
@Command(name = "study", hidden = true, description = "Internal: run one engine and setting for 'carom study accuracy'.")
public final class AccuracyWorker implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        ChildJvm.readJob(System.in, Trial.class).run(r -> ChildJvm.send(out, r));
        return 0;
    }
}
