package carom.app;

import carom.core.engine.Engine;
import carom.engines.EngineCatalog;
import java.io.PrintWriter;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

/** {@code carom engines}: one line per engine, {@code NAME exact|relaxed DESCRIPTION}. */
@Command(name = "engines", mixinStandardHelpOptions = true,
        description = "List the engines, one per line: NAME exact|relaxed DESCRIPTION.")
final class EnginesCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        for (Engine e : EngineCatalog.all()) {
            // Single spaces, so that scripts can split each line into three fields.
            out.println(e.name() + " " + (e.exact() ? "exact" : "relaxed") + " " + e.description());
        }
        out.flush();
        return 0;
    }
}
