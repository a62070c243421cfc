package carom.lab.bench;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.Engine;
import carom.engines.EngineCatalog;
import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/**
 * Smoke runs of the packaged {@code carom-lab.jar} (failsafe, after {@code package}) as
 * {@code ./carom bench} runs it ({@code java -jar carom-lab.jar bench ARGS}): every benchmark class
 * starts, with every engine, in JMH forks, and reports a score. Tiny N and one short iteration; they
 * prove the jar (shading, BenchmarkList, Akka's merged reference.conf), that {@code bench} hands every
 * argument to JMH, and the benchmarks' set-up, not any speed.
 */
class BenchmarksJarIT {
    private static final Path JAR = Path.of(System.getProperty("lab.jar", "target/carom-lab.jar"));
    private static final Path OUT = Path.of(System.getProperty("smoke.dir", "target/jmh-smoke"));
    private static final List<String> ENGINES = EngineCatalog.all().stream().map(Engine::name).toList();
    /** One fork, no warm-up, one short iteration; fail the JVM on any benchmark error. */
    private static final List<String> QUICK = List.of("-f", "1", "-wi", "0", "-i", "1", "-r", "100ms", "-foe", "true");
    private static final String UNSAFE_FLAG = "--sun-misc-unsafe-memory-access";

    /** threads = 3 matches no usual core count, so the vthreads trial shows its carriers were set. */
    @Test
    void gasThroughputRunsEveryEngine() throws Exception {
        Path csv = OUT.resolve("gas.csv");
        Jmh jmh = run("GasThroughput", "-p", "engine=" + String.join(",", ENGINES), "-p", "n=400", "-p", "threads=3",
                "-p", "cellsPerActor=perThread", "-p", "collisionsPerDisc=0.5", "-rf", "csv", "-rff", csv.toString());
        assertThat(jmh.exit).as(jmh.output).isZero();
        assertNoUnsafeWarning(jmh);
        Map<String, Double> collisionsPerSecond = scores(csv, "carom.lab.bench.GasThroughputBenchmark.run:collisions");
        assertThat(collisionsPerSecond.keySet()).as(jmh.output).containsExactlyInAnyOrderElementsOf(ENGINES);
        assertThat(collisionsPerSecond.values()).allSatisfy(score -> assertThat(score).isPositive().isFinite());
    }

    @Test
    void thesisWorkloadRunsEveryEngine() throws Exception {
        Path csv = OUT.resolve("thesis.csv");
        Jmh jmh = run("ThesisWorkload", "-p", "engine=" + String.join(",", ENGINES), "-p", "n=400", "-p", "threads=2",
                "-p", "cellsPerActor=perThread", "-rf", "csv", "-rff", csv.toString());
        assertThat(jmh.exit).as(jmh.output).isZero();
        assertNoUnsafeWarning(jmh);
        Map<String, Double> secondsPerRun = scores(csv, "carom.lab.bench.ThesisWorkloadBenchmark.run");
        assertThat(secondsPerRun.keySet()).as(jmh.output).containsExactlyInAnyOrderElementsOf(ENGINES);
        assertThat(secondsPerRun.values()).allSatisfy(score -> assertThat(score).isPositive().isFinite());
    }

    /** Every start-up phase runs, on a scene small enough for CI, and scores a time. */
    @Test
    void startupTimesEveryPhase() throws Exception {
        Path csv = OUT.resolve("startup.csv");
        Jmh jmh = run("Startup", "-p", "n=400", "-rf", "csv", "-rff", csv.toString());
        assertThat(jmh.exit).as(jmh.output).isZero();
        Map<String, Double> millis = scores(csv, "carom.lab.bench.StartupBenchmark.run", "phase");
        assertThat(millis.keySet()).as(jmh.output)
                .containsExactlyInAnyOrder("generate", "read", "table", "predict", "calendar", "check");
        assertThat(millis.values()).allSatisfy(score -> assertThat(score).isPositive().isFinite());
    }

    /**
     * An unknown phase stops the trial with one line naming the phases, as an unknown engine does, not
     * with the benchmark's stack trace (JMH's own report of the failed run, under -foe, keeps its trace).
     */
    @Test
    void startupRefusesAnUnknownPhaseInOneLine() throws Exception {
        Jmh jmh = run("Startup", "-p", "n=400", "-p", "phase=nope");
        assertThat(jmh.exit).as(jmh.output).isNotZero();
        assertThat(jmh.output).contains("phase: nope (known: generate, read, table, predict, calendar, check)")
                .doesNotContain("StartupBenchmark.prepare");
    }

    /** A -D carrier count that disagrees with threads must stop the trial, not measure other carriers. */
    @Test
    void vthreadsRefusesCarriersOtherThanThreads() throws Exception {
        Jmh jmh = run("GasThroughput", "-p", "engine=vthreads", "-p", "n=400", "-p", "threads=1",
                "-jvmArgsAppend", "-Djdk.virtualThreadScheduler.parallelism=2");
        assertThat(jmh.exit).as(jmh.output).isNotZero();
        assertThat(jmh.output).contains("jdk.virtualThreadScheduler.parallelism is 2 in this JVM but the trial asks for threads = 1");
    }

    /** GasBench passes its thread count on: the last run's counters show the slabs it got. */
    @Test
    void gasBenchRunsAParallelEngineOnTheThreadsAskedFor() throws Exception {
        Jmh bench = gasBench("slabs", "400", "0.3", "0.5", "1", "", "2", "3");
        assertThat(bench.exit).as(bench.output).isZero();
        assertThat(bench.output).contains("# engine slabs, 2 threads").contains("1 timed runs after 3 warm-up runs")
                .contains("\nslabs,400,0.3,").contains("domains=2");
    }

    @Test
    void gasBenchRejectsBadArgumentsWithAnErrorLine() throws Exception {
        for (String[] args : new String[][] {{"fast", "400", "0.3", "1", "1", "", "two"}, {"nosuch", "400", "0.3"},
                {"fast", "400", "0.3", "1", "0"}, {"fast", "400", "0.3", "1", "1", "", "1", "-1"}}) {
            Jmh bench = gasBench(args);
            assertThat(bench.exit).as(bench.output).isEqualTo(2);
            assertThat(bench.output).contains("\nerror: ").doesNotContain("Exception").doesNotContain("\tat ");
        }
    }

    private record Jmh(int exit, String output) {
    }

    private static Jmh gasBench(String... args) throws IOException, InterruptedException {
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", JAR.toString(), GasBench.class.getName()));
        command.addAll(List.of(args));
        Files.createDirectories(OUT);
        Path log = OUT.resolve("gasbench-" + System.nanoTime() + ".log");
        Process p = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(log.toFile()).start();
        if (!p.waitFor(120, TimeUnit.SECONDS)) {
            p.destroyForcibly().waitFor();
            throw new AssertionError("GasBench did not finish in 120 s: " + command + "\n" + Files.readString(log));
        }
        return new Jmh(p.exitValue(), String.join(" ", command) + "\n" + Files.readString(log));
    }

    /** Starts the jar's {@code bench} with this JVM's java; JMH's forks inherit the Unsafe flag from its command line. */
    private static Jmh run(String benchmark, String... args) throws IOException, InterruptedException {
        assertThat(JAR).as("the shaded jar (built by package)").isRegularFile();
        Files.createDirectories(OUT);
        List<String> command = new ArrayList<>();
        command.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        ManagementFactory.getRuntimeMXBean().getInputArguments().stream()
                .filter(a -> a.startsWith(UNSAFE_FLAG)).forEach(command::add);
        command.addAll(List.of("-jar", JAR.toString(), "bench", benchmark));
        command.addAll(List.of(args));
        command.addAll(QUICK);
        Path log = OUT.resolve(benchmark + "-" + System.nanoTime() + ".log");
        Process p = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(log.toFile()).start();
        if (!p.waitFor(120, TimeUnit.SECONDS)) {
            p.destroyForcibly().waitFor();
            throw new AssertionError("JMH did not finish in 120 s: " + command + "\n" + Files.readString(log));
        }
        return new Jmh(p.exitValue(), String.join(" ", command) + "\n" + Files.readString(log));
    }

    /** Forks inherit the flag, so no fork may print the JDK's warning about sun.misc.Unsafe. */
    private static void assertNoUnsafeWarning(Jmh jmh) {
        boolean flagged = ManagementFactory.getRuntimeMXBean().getInputArguments().stream()
                .anyMatch(a -> a.startsWith(UNSAFE_FLAG));
        if (flagged) {
            assertThat(jmh.output).doesNotContain("sun.misc.Unsafe");
        }
    }

    /** Score by engine of the rows of {@code benchmark} in JMH's CSV result file. */
    private static Map<String, Double> scores(Path csv, String benchmark) throws IOException {
        return scores(csv, benchmark, "engine");
    }

    /** Score by the value of parameter {@code param} of the rows of {@code benchmark} in JMH's CSV result file. */
    private static Map<String, Double> scores(Path csv, String benchmark, String param) throws IOException {
        List<String> lines = Files.readAllLines(csv, StandardCharsets.UTF_8);
        List<String> header = cells(lines.get(0));
        int score = header.indexOf("Score");
        int engine = header.indexOf("Param: " + param);
        Map<String, Double> byEngine = new TreeMap<>();
        for (String line : lines.subList(1, lines.size())) {
            List<String> row = cells(line);
            if (row.get(0).equals(benchmark)) {
                byEngine.put(row.get(engine), Double.parseDouble(row.get(score)));
            }
        }
        return byEngine;
    }

    /** JMH's CSV: comma-separated, text in double quotes; none of our values contains a comma. */
    private static List<String> cells(String line) {
        List<String> cells = new ArrayList<>();
        for (String cell : line.split(",", -1)) {
            cells.add(cell.startsWith("\"") && cell.endsWith("\"") && cell.length() >= 2
                    ? cell.substring(1, cell.length() - 1) : cell);
        }
        return cells;
    }
}
