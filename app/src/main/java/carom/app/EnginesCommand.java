package carom.app;

import carom.core.Quoted;
import carom.core.engine.Engine;
import carom.core.engine.EngineSpec;
import carom.core.engine.Tunable;
import carom.engines.EngineCatalog;
import java.io.PrintWriter;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.IDefaultValueProvider;
import picocli.CommandLine.Model.ArgSpec;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Model.OptionSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code carom engines}: one line per engine, {@code NAME exact|relaxed DESCRIPTION}, the description
 * ending with the effects it simulates beyond the ones every engine does (gravity, restitution of pairs
 * and walls, the TC model) and with its settings and their defaults; with {@code --tunables}, every setting's type,
 * range, unit and meaning below its engine. Also how every command that runs an engine finds it by
 * name and fills in the one default engine.
 */
@Command(name = "engines", mixinStandardHelpOptions = true,
        description = "List the engines, one per line: NAME exact|relaxed DESCRIPTION (effects: KEY, ...)"
                + " (settings: NAME=DEFAULT, ...).")
public final class EnginesCommand implements Callable<Integer> {
    /**
     * Most worker threads a run may ask for: far beyond any machine's cores, and far below what breaks
     * the engines' pools (a fork-join pool takes at most 32,767).
     */
    public static final int MAX_THREADS = 4096;

    /** The threads a run of {@code engine} gets when the user names none: the engine's choice of the processors, within the bound. */
    public static int defaultThreads(Engine engine) {
        return engine.defaultThreads(Math.min(Runtime.getRuntime().availableProcessors(), MAX_THREADS));
    }

    @Spec
    CommandSpec spec;

    @Option(names = "--tunables", description = "Also list each engine's settings (--option NAME=VALUE): "
            + "default, type and range, unit and meaning.")
    boolean tunables;

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        for (Engine e : EngineCatalog.all()) {
            EngineSpec s = e.spec();
            // Single spaces, so that scripts can split each line into three fields.
            List<String> own = s.effects().stream().filter(effect -> !EngineSpec.SHARED_PHYSICS.contains(effect))
                    .map(effect -> effect.key).toList();
            String effects = own.isEmpty() ? "" : " (effects: " + String.join(", ", own) + ")";
            String settings = s.tunables().isEmpty() ? "" : " (settings: " + String.join(", ",
                    s.tunables().stream().map(t -> t.name() + "=" + (t.computedDefault() ? "auto" : t.defaultText())).toList()) + ")";
            out.println(s.name() + " " + s.exactness() + " " + s.description() + effects + settings);
            if (tunables) {
                for (Tunable<?> t : s.tunables()) {
                    out.println("    " + t.describe());
                }
            }
        }
        out.flush();
        return 0;
    }

    /**
     * The engine called {@code name}, or {@link EngineCatalog#defaultEngine()} for null; bad input
     * naming the known ones otherwise, with the name as {@link Quoted} shows it.
     */
    public static Engine engineNamed(String name) {
        if (name == null) {
            return EngineCatalog.defaultEngine();
        }
        return EngineCatalog.byName(name);
    }

    /**
     * Fills {@code --engine} with {@link EngineCatalog#defaultEngine()}'s name, so that every command
     * has the same default and its help shows it; other options keep their own defaults.
     */
    public static final class DefaultEngine implements IDefaultValueProvider {
        @Override
        public String defaultValue(ArgSpec argSpec) {
            if (argSpec instanceof OptionSpec option && option.longestName().equals("--engine")) {
                return EngineCatalog.defaultEngine().name();
            }
            return null;
        }
    }
}
