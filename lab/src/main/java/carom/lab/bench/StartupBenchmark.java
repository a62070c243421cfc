package carom.lab.bench;

import carom.core.BadInputException;
import carom.core.engine.RunOptions;
import carom.core.observe.StateChecks;
import carom.core.scene.Scene;
import carom.core.scene.SceneReader;
import carom.core.scene.StandardScenes;
import carom.core.state.Discs;
import carom.engines.kernel.CalendarQueue;
import carom.engines.kernel.CellPredictor;
import carom.engines.kernel.DiscMotion;
import carom.engines.kernel.DiscTable;
import carom.engines.kernel.KernelTunables;
import com.fasterxml.jackson.core.JsonEncoding;
import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonGenerator;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;
import org.openjdk.jmh.annotations.Warmup;

/**
 * Milliseconds of each phase before a run's first event, and of the check after its last, on the
 * thesis's workload ({@link StandardScenes#thesis}) of {@code n} discs: what a user waits for around
 * the event loop (compared with a C code's start-up in {@code lab/notes/startup-phases/}). The phases, as a
 * {@code simulate} command with {@code fast} performs them:
 * <ul>
 *   <li>{@code generate}: the scene generated and checked (a scene file's {@code generate} block);</li>
 *   <li>{@code read}: the same discs read from a scene file that lists them all ({@code particles});</li>
 *   <li>{@code table}: the records, the cells and the Morton order ({@link DiscTable});</li>
 *   <li>{@code predict}: every disc's first event ({@link CellPredictor#predictFull});</li>
 *   <li>{@code calendar}: the calendar sized and filled ({@link DiscTable#planCalendar});</li>
 *   <li>{@code check}: the deepest overlap that every summary reports ({@link StateChecks}), here of
 *       the scene's discs.</li>
 * </ul>
 * Single-shot: each measurement is one pass of its phase over state made outside the timing. The
 * cells are {@code fast}'s default for the scene.
 *
 * <p>Run ({@code ./carom bench ARGS}, see {@link GasThroughputBenchmark}):
 * <pre>
 * ./carom bench Startup -p n=1000000
 * ./carom bench Startup -p n=1000000 -p phase=read,check -wi 2 -i 5
 * </pre>
 * Lab note {@code startup-phases} has the figures and what changed them.
 */
@BenchmarkMode(Mode.SingleShotTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 3)
@Measurement(iterations = 5)
// Prepend so that a -jvmArgsAppend on the command line adds to these (see GasThroughputBenchmark).
@Fork(value = 1, jvmArgsPrepend = {"-Xmx8g", "-XX:+UseParallelGC"})
@State(Scope.Benchmark)
public class StartupBenchmark {
    @Param({"1000000"})
    public int n;
    @Param({"generate", "read", "table", "predict", "calendar", "check"})
    public String phase;

    private Scene scene;
    private Discs discs;
    private double cellFactor;
    /** The scene with its discs listed, for {@code read}. */
    private Path listed;
    /** A fresh table for {@code predict} and {@code calendar} (predicted already for the latter). */
    private DiscTable table;
    private CellPredictor predictor;
    private CalendarQueue queue;

    @Setup(Level.Trial)
    public void prepare() throws IOException {
        scene = StandardScenes.thesis(n, 42);
        discs = scene.newDiscs();
        cellFactor = KernelTunables.cellFactor(RunOptions.until(scene.until()), scene);
        switch (phase) {
            case "read" -> listed = writeListed(scene, discs);
            case "generate", "table", "predict", "calendar", "check" -> { }
            // One line, as for an unknown engine in the other benchmarks (EngineSetup), not a stack trace.
            default -> throw new BadInputException(
                    "phase: " + phase + " (known: generate, read, table, predict, calendar, check)");
        }
    }

    @Setup(Level.Invocation)
    public void freshTable() {
        if (phase.equals("predict") || phase.equals("calendar")) {
            table = new DiscTable(scene, discs, cellFactor);
            predictor = new CellPredictor(new DiscMotion(table));
            queue = table.newCalendar(n);
            if (phase.equals("calendar")) {
                predictAll();
            }
        }
    }

    @TearDown(Level.Trial)
    public void deleteListed() throws IOException {
        if (listed != null) {
            Files.deleteIfExists(listed);
        }
    }

    @Benchmark
    public Object run() {
        return switch (phase) {
            case "generate" -> StandardScenes.thesis(n, 42);
            case "read" -> SceneReader.read(listed);
            case "table" -> new DiscTable(scene, discs, cellFactor);
            case "predict" -> predictAll();
            case "calendar" -> table.planCalendar(queue, null, n, 0, scene.until());
            default -> StateChecks.deepestOverlap(discs, scene.box());
        };
    }

    /** Every mobile disc's first event, as a run starts. */
    private DiscTable predictAll() {
        table.predictFirstEvents(i -> predictor.predictFull(i, 0));
        return table;
    }

    /** The scene as a file that lists every disc (the thesis's scene has one species and walls). */
    private static Path writeListed(Scene scene, Discs d) throws IOException {
        Path file = Files.createTempFile("carom-startup-", ".json");
        try (JsonGenerator g = new JsonFactory().createGenerator(file.toFile(), JsonEncoding.UTF8)) {
            g.writeStartObject();
            g.writeStringField("name", scene.name() + "-listed");
            g.writeObjectFieldStart("box");
            g.writeNumberField("width", scene.box().width());
            g.writeNumberField("height", scene.box().height());
            g.writeStringField("boundary", "walls");
            g.writeEndObject();
            g.writeArrayFieldStart("species");
            g.writeStartObject();
            g.writeStringField("name", "disc");
            g.writeNumberField("radius", d.radius[0]);
            g.writeNumberField("mass", 1 / d.invMass[0]);
            g.writeEndObject();
            g.writeEndArray();
            g.writeArrayFieldStart("particles");
            for (int i = 0; i < d.n; i++) {
                g.writeStartObject();
                g.writeStringField("species", "disc");
                g.writeNumberField("x", d.x[i]);
                g.writeNumberField("y", d.y[i]);
                g.writeNumberField("vx", d.vx[i]);
                g.writeNumberField("vy", d.vy[i]);
                g.writeEndObject();
            }
            g.writeEndArray();
            g.writeNumberField("until", scene.until());
            g.writeEndObject();
        }
        return file;
    }
}
