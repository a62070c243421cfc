package carom.lab.bench;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Parameters;

/**
 * {@code carom bench ARGS}: JMH's own command line on the lab's benchmarks ({@link GasThroughputBenchmark},
 * {@link ThesisWorkloadBenchmark}, {@link StartupBenchmark}). Every argument goes to {@code org.openjdk.jmh.Main} as given, options
 * included ({@code -p engine=fast -f 1 -wi 1 -prof gc -rf json ...}, {@code -h} for JMH's help, {@code -l}
 * for the list): {@code LabMain} makes this command take what looks like an option as one of its
 * arguments. JMH forks its JVMs with this jar's class path and this JVM's options.
 */
@Command(name = "bench",
        description = {"Run the JMH benchmarks: every argument is JMH's (a benchmark name such as GasThroughput, "
                + "ThesisWorkload or Startup, -p key=values, -f, -wi, -i, -prof, -rf json -rff FILE; -h for JMH's help, -l for the list)."})
public final class BenchCommand implements Callable<Integer> {
    @Parameters(paramLabel = "ARGS", arity = "0..*", description = "JMH's arguments.")
    List<String> args = new ArrayList<>();

    @Override
    public Integer call() throws Exception {
        // JMH exits the JVM itself on a bad option or a failed benchmark (status 1); it returns when all went well.
        org.openjdk.jmh.Main.main(args.toArray(String[]::new));
        return 0;
    }
}
