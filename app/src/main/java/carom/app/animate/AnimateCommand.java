package carom.app.animate;

import carom.app.SceneFile;
import carom.app.AtomicOutput;
import carom.app.EnginesCommand;
import carom.app.ProgressBar;
import carom.app.render.SceneRenderer;
import carom.app.render.SceneRenderer.ColourMode;
import carom.app.report.Provenance;
import carom.core.BadInputException;
import carom.core.Quoted;
import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.engine.Sampler;
import carom.core.scene.Scene;
import carom.core.scene.SceneReader;
import carom.core.state.Discs;
import carom.engines.EngineCatalog;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.math.BigDecimal;
import java.math.MathContext;
import java.math.RoundingMode;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code carom animate}: an animated GIF of a run, one frame per sample t = 0, DT, 2 DT, ... of an
 * engine that stops at given times (the exact state at each), or one frame per frame of a trajectory
 * file carom wrote. Each frame is drawn as {@code render} draws a picture ({@link SceneRenderer}), its
 * caption the frame's time; the GIF loops forever at the chosen frame rate.
 *
 * <p>As for {@code simulate}, everything about the input is checked before the run, and the GIF is
 * written frame by frame into a temporary file that becomes the output only when it is complete
 * ({@link AtomicOutput}). Colouring by speed needs the top speed of the whole series first (as
 * {@code render} scales every picture of a series alike): the run is made twice (exact engines repeat
 * their runs to the bit) or the trajectory read twice.
 */
@Command(name = "animate", mixinStandardHelpOptions = true, sortOptions = false,
        defaultValueProvider = EnginesCommand.DefaultEngine.class,
        description = {"Draw a run as an animated GIF: a frame every DT of simulated time, drawn as 'render' draws, "
                + "with its time; or the frames of a trajectory file ('simulate --trajectory').",
                "  carom animate SCENE.json --out movie.gif [--every DT] [--fps F]",
                "  carom animate [SCENE.json] --trajectory FRAMES.xyz --out movie.gif"})
public final class AnimateCommand implements Callable<Integer> {
    /** Most frames one GIF holds: beyond that a GIF is no longer something to watch, and its file gets huge. */
    static final int MAX_FRAMES = 10_000;
    static final int DEFAULT_SIZE = 480;
    static final int MIN_SIZE = 16;
    static final int MAX_SIZE = 4000;
    /** Frames per second: a GIF's delay is in hundredths of a second, and browsers slow down delays under 2. */
    static final double MAX_FPS = 50;
    /** The longest delay a GIF can hold is 65,535 hundredths of a second (an unsigned 16-bit field). */
    static final int MAX_DELAY = 0xFFFF;
    /** Fewest frames per second: one frame per {@link #MAX_DELAY} hundredths of a second. */
    static final double MIN_FPS = 100.0 / MAX_DELAY;
    /** Frames of the default animation: DT = the end time / this. */
    static final int DEFAULT_STEPS = 100;

    @Spec
    CommandSpec spec;

    @Parameters(index = "0", arity = "0..1", paramLabel = "SCENE.json",
            description = "The scene file to run; with --trajectory, the scene the frames came from (its name, fixed discs and colours).")
    String sceneFile;

    @Option(names = "--trajectory", paramLabel = "FRAMES.xyz",
            description = "Draw the frames of this trajectory ('carom simulate --every DT --trajectory') instead of running a scene.")
    Path trajectory;

    @Option(names = "--out", required = true, paramLabel = "movie.gif", description = "The GIF to write.")
    Path out;

    @Option(names = "--engine", paramLabel = "NAME",
            description = "Engine to run (one that stops at given times, see 'carom engines'); default: ${DEFAULT-VALUE}.")
    String engineName;

    @Option(names = "--every", paramLabel = "DT",
            description = "Simulated time between frames; default: the end time / " + DEFAULT_STEPS + ".")
    Double every;

    @Option(names = "--until", paramLabel = "T", description = "Simulated end time, overriding the scene's.")
    Double until;

    @Option(names = "--fps", paramLabel = "F", defaultValue = "10",
            description = "Frames per second, from 100/65535 (a GIF holds a frame at most 655.35 s) to 50 (default ${DEFAULT-VALUE}).")
    double fps;

    @Option(names = "--size", paramLabel = "PIXELS", defaultValue = "" + DEFAULT_SIZE,
            description = "Pixels of the box's longer side, " + MIN_SIZE + " to " + MAX_SIZE + " (default ${DEFAULT-VALUE}).")
    int size;

    @Option(names = "--color", paramLabel = "species|speed|vx", defaultValue = "species",
            description = "Colour mobile discs by species (default), by speed or by x velocity, as 'render' does.")
    String color;

    /** The raw stderr, for the progress bar (which must know whether it is a terminal). */
    private final PrintStream err;

    public AnimateCommand(PrintStream err) {
        this.err = err;
    }

    @Override
    public Integer call() {
        ColourMode mode = ColourMode.parse(color);
        if (mode == null) {
            throw new BadInputException("--color: unknown colour mode " + Quoted.of(color) + " (known: species, speed, vx)");
        }
        if (!(fps >= MIN_FPS) || fps > MAX_FPS) {
            throw new BadInputException("--fps: must be a number from 100/" + MAX_DELAY + " (a GIF shows a frame at most "
                    + MAX_DELAY / 100.0 + " s) to " + (int) MAX_FPS + ", got " + fps);
        }
        if (size < MIN_SIZE || size > MAX_SIZE) {
            throw new BadInputException("--size: must be from " + MIN_SIZE + " to " + MAX_SIZE + " pixels, got " + size);
        }
        if (every != null && (!(every > 0) || Double.isInfinite(every))) {
            throw new BadInputException("--every: must be a finite number > 0, got " + every);
        }
        if (until != null && (!(until > 0) || Double.isInfinite(until))) {
            throw new BadInputException("--until: must be a finite number > 0, got " + until);
        }
        if (sceneFile == null && trajectory == null) {
            throw new BadInputException("give a scene file, or --trajectory FRAMES.xyz (and the scene it came from, for its colours)");
        }
        AtomicOutput.checkWritable(out, "--out");
        if (trajectory != null) {
            AtomicOutput.checkNotInput(out, "--out", trajectory, "the trajectory");
        }
        if (sceneFile != null) {
            SceneFile scene = new SceneFile(sceneFile);
            AtomicOutput.checkNotInput(out, "--out", scene.about(scene::path), "the scene file");
        }
        int delay = (int) Math.max(2, Math.round(100 / fps));
        String comment = Provenance.commandLine(spec.commandLine().getParseResult().originalArgs())
                + "\nmachine: " + Provenance.machine();
        // Headless unless told otherwise: nothing here needs a display, and a server has none.
        if (System.getProperty("java.awt.headless") == null) {
            System.setProperty("java.awt.headless", "true");
        }
        long frames = trajectory != null ? fromTrajectory(mode, delay, comment) : fromScene(mode, delay, comment);
        spec.commandLine().getOut().println(out + " (" + frames + (frames == 1 ? " frame" : " frames") + ")");
        return 0;
    }

    private long fromScene(ColourMode mode, int delay, String comment) {
        Engine engine = new SceneFile(sceneFile).about(() -> EnginesCommand.engineNamed(engineName));
        if (!engine.spec().can(carom.core.engine.Capability.SAMPLES)) {
            throw new BadInputException("--engine: " + engine.name() + " cannot stop at given times (engines that can: "
                    + EngineCatalog.namesThatCan(carom.core.engine.Capability.SAMPLES) + ")");
        }
        Scene fromFile = new SceneFile(sceneFile).about(() -> SceneReader.read(new SceneFile(sceneFile).path()));
        Scene scene = until == null ? fromFile : fromFile.withUntil(until);
        new SceneFile(sceneFile).about(() -> {
            engine.checkSupports(scene);
            return null;
        });
        double dt = every != null ? every : scene.until() / DEFAULT_STEPS;
        long frames = frameCount(scene.until(), dt);
        int threads = EnginesCommand.defaultThreads(engine);
        double topSpeed = 0;
        if (mode != ColourMode.SPECIES) {
            double[] top = {0};
            run(engine, scene, threads, dt, (t, d, v) -> top[0] = Math.max(top[0], d.maxSpeed()));
            topSpeed = top[0];
        }
        double colourTop = topSpeed;
        try (AtomicOutput files = new AtomicOutput()) {
            files.stageFile(out, temp -> {
                try (GifSequence gif = GifSequence.create(temp, delay, comment)) {
                    run(engine, scene, threads, dt, (t, d, v) -> addFrame(gif,
                            SceneRenderer.draw(scene, d, timeStamp(t, dt), mode, colourTop, size)));
                }
            });
            files.commit();
        }
        return frames;
    }

    private void run(Engine engine, Scene scene, int threads, double dt, Sampler sampler) {
        try (ProgressBar bar = ProgressBar.forRun(err, scene.until())) {
            RunOptions options = RunOptions.until(scene.until()).withThreads(threads).withProgress(bar).withSamples(dt, sampler);
            new SceneFile(sceneFile).about(() -> engine.run(scene, options));
        }
    }

    private long fromTrajectory(ColourMode mode, int delay, String comment) {
        var parse = spec.commandLine().getParseResult();
        for (String option : new String[] {"--engine", "--every", "--until"}) {
            if (parse.hasMatchedOption(option)) {
                throw new BadInputException(option + ": not with --trajectory (the file's frames are drawn as they are)");
            }
        }
        Scene scene = sceneFile == null ? null : new SceneFile(sceneFile).about(() -> SceneReader.read(new SceneFile(sceneFile).path()));
        // First pass: the whole file is checked before anything is written, and gives the top speed and the frame step.
        double topSpeed = 0;
        double first = 0;
        double last = 0;
        long frames = 0;
        try (XyzFrames in = XyzFrames.open(trajectory, scene)) {
            while (in.next()) {
                if (++frames > MAX_FRAMES) {
                    throw new BadInputException("--trajectory: more than " + MAX_FRAMES + " frames, more than a GIF should hold");
                }
                topSpeed = Math.max(topSpeed, in.discs().maxSpeed());
                first = frames == 1 ? in.time() : first;
                last = in.time();
            }
        }
        double step = frames > 1 ? new BigDecimal((last - first) / (frames - 1)).round(new MathContext(12)).doubleValue() : 1;
        double colourTop = topSpeed;
        long total = frames;
        try (AtomicOutput files = new AtomicOutput();
             ProgressBar bar = ProgressBar.forCount(err, total, "frames")) {
            files.stageFile(out, temp -> {
                try (GifSequence gif = GifSequence.create(temp, delay, comment);
                     XyzFrames in = XyzFrames.open(trajectory, scene)) {
                    while (in.next()) {
                        Discs d = in.discs();
                        gif.add(SceneRenderer.draw(in.subject(), d, timeStamp(in.time(), step), mode, colourTop, size));
                        bar.completed(gif.frames(), "");
                    }
                }
            });
            files.commit();
        }
        return frames;
    }

    private static void addFrame(GifSequence gif, BufferedImage frame) {
        try {
            gif.add(frame);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write the GIF: " + e.getMessage(), e);
        }
    }

    /** Frames at k·dt, k = 0, 1, ... while k·dt <= until (as the engines' samples); bad input beyond {@link #MAX_FRAMES}. */
    static long frameCount(double until, double dt) {
        double steps = Math.floor(until / dt);
        if (steps + 1 > MAX_FRAMES) {
            throw new BadInputException("--every: " + dt + " makes more than " + MAX_FRAMES + " frames up to t = " + until
                    + " (choose a larger DT or an earlier --until)");
        }
        long k = (long) steps;
        while ((k + 1) * dt <= until) {
            k++;
        }
        while (k > 0 && k * dt > until) {
            k--;
        }
        if (k + 1 > MAX_FRAMES) {
            throw new BadInputException("--every: " + dt + " makes more than " + MAX_FRAMES + " frames up to t = " + until);
        }
        return k + 1;
    }

    /**
     * The frame's time as its caption shows it: rounded to the decimals of the frame step (t = 3 × 0.1
     * shows as 0.3, not 0.30000000000000004), without trailing zeros; 0 as {@code render --at 0} shows it.
     */
    static String timeStamp(double t, double step) {
        if (t == 0) {
            return "0";
        }
        int decimals = Math.max(0, BigDecimal.valueOf(step).stripTrailingZeros().scale());
        BigDecimal rounded = new BigDecimal(t).setScale(decimals, RoundingMode.HALF_EVEN).stripTrailingZeros();
        return rounded.signum() == 0 ? "0" : rounded.toPlainString();
    }


}
