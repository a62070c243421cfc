package carom.app.render;

import carom.app.SceneFile;
import carom.app.EnginesCommand;
import carom.app.report.Provenance;
import carom.core.BadInputException;
import carom.core.Quoted;
import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.scene.Scene;
import carom.core.scene.SceneReader;
import carom.core.state.Discs;
import java.awt.image.BufferedImage;
import java.math.BigDecimal;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code carom render}: pictures of a scene at given times, one PNG each.
 *
 * <p>The state at time T comes from running the engine from t = 0 to T (T = 0 is the initial state);
 * running from scratch for each time is exact and needs nothing from the engine but its final state.
 * As for {@code simulate}, everything about the input is checked before any run, and the pictures
 * are written only once all of them are drawn, all together or not at all.
 */
@Command(name = "render", mixinStandardHelpOptions = true, sortOptions = false,
        defaultValueProvider = EnginesCommand.DefaultEngine.class,
        description = "Draw the scene's state at given times into PNG files DIR/<scene name>-t<T>.png.")
public final class RenderCommand implements Callable<Integer> {
    static final int DEFAULT_SIZE = 800;
    static final int MIN_SIZE = 16;
    static final int MAX_SIZE = 10_000;
    /** Most pictures one command draws; each runs the engine from t = 0. */
    static final int MAX_TIMES = 1000;
    /** Characters of the longest time text read; longer is no time (and would make the pattern slow). */
    private static final int MAX_TIME_CHARS = 100;

    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "SCENE.json", description = "The scene file.")
    String sceneFile;

    @Option(names = "--at", required = true, paramLabel = "T1,T2,...",
            description = "Times to draw, comma-separated, each >= 0 (0 is the initial state), at most " + MAX_TIMES + ".")
    String at;

    @Option(names = "--out", required = true, paramLabel = "DIR",
            description = "Directory for the pictures; created if its parent exists.")
    Path outDir;

    @Option(names = "--engine", paramLabel = "NAME",
            description = "Engine to run (see 'carom engines'); default: ${DEFAULT-VALUE}.")
    String engineName;

    @Option(names = "--color", paramLabel = "species|speed|vx", defaultValue = "species",
            description = "Colour mobile discs by species (default), by speed, or by x velocity.")
    String color;

    @Option(names = "--size", paramLabel = "PIXELS", defaultValue = "" + DEFAULT_SIZE,
            description = "Pixels of the box's longer side (default ${DEFAULT-VALUE}).")
    int size;

    public RenderCommand() {
    }

    @Override
    public Integer call() {
        List<Double> times = parseTimes(at);
        SceneRenderer.ColourMode mode = SceneRenderer.ColourMode.parse(color);
        if (mode == null) {
            throw new BadInputException("--color: unknown colour mode " + Quoted.of(color) + " (known: species, speed, vx)");
        }
        if (size < MIN_SIZE || size > MAX_SIZE) {
            throw new BadInputException("--size: must be between " + MIN_SIZE + " and " + MAX_SIZE + " pixels, got " + size);
        }
        Scene scene = new SceneFile(sceneFile).about(() -> SceneReader.read(new SceneFile(sceneFile).path()));
        Engine engine = new SceneFile(sceneFile).about(() -> EnginesCommand.engineNamed(engineName));
        new SceneFile(sceneFile).about(() -> {
            engine.checkSupports(scene);
            return null;
        });
        PngFiles.checkDirectory(outDir, "--out");
        String stem = fileStem(scene.name());
        Map<String, Double> byFile = new LinkedHashMap<>();
        for (double t : times) {
            byFile.put(stem + "-t" + timeLabel(t) + ".png", t);
        }
        PngFiles.checkTargets(outDir, byFile.keySet(), "--out");

        // Headless unless told otherwise: nothing here needs a display, and a server has none.
        if (System.getProperty("java.awt.headless") == null) {
            System.setProperty("java.awt.headless", "true");
        }
        List<Discs> states = new ArrayList<>();
        for (double t : byFile.values()) {
            states.add(stateAt(scene, engine, t));
        }
        double topSpeed = 0;
        for (Discs d : states) {
            topSpeed = Math.max(topSpeed, d.maxSpeed());
        }
        Map<String, byte[]> files = new LinkedHashMap<>();
        // What made the pictures, for carom report: as an animation's comment says it.
        String comment = Provenance.commandLine(spec.commandLine().getParseResult().originalArgs())
                + "\nmachine: " + Provenance.machine();
        int k = 0;
        for (Map.Entry<String, Double> f : byFile.entrySet()) {
            BufferedImage image = SceneRenderer.draw(scene, states.get(k++), timeLabel(f.getValue()), mode, topSpeed, size);
            files.put(f.getKey(), PngEncoder.encode(image, comment));
        }
        for (Path p : PngFiles.writeAll(outDir, files)) {
            spec.commandLine().getOut().println(p);
        }
        return 0;
    }

    private Discs stateAt(Scene scene, Engine engine, double t) {
        if (t == 0) {
            return scene.newDiscs();
        }
        int threads = EnginesCommand.defaultThreads(engine);
        return new SceneFile(sceneFile).about(() -> engine.run(scene.withUntil(t), RunOptions.until(t).withThreads(threads))).finalState();
    }

    /** The comma-separated times of {@code --at}, each finite and >= 0, without repeats, in the given order. */
    static List<Double> parseTimes(String list) {
        List<Double> times = new ArrayList<>();
        for (String item : list.split(",", -1)) {
            String s = item.strip();
            if (s.isEmpty()) {
                throw new BadInputException("--at: empty time in " + Quoted.of(list) + " (give times like 0,0.5,2)");
            }
            // Plain decimals only: Java would also take "1d", hex floats, "NaN" and "Infinity".
            if (s.length() > MAX_TIME_CHARS || !s.matches("[+-]?(\\d+\\.?\\d*|\\.\\d+)([eE][+-]?\\d+)?")) {
                throw new BadInputException("--at: " + Quoted.of(s) + " is not a time (a finite number >= 0)");
            }
            double t = Double.parseDouble(s);
            if (Double.isInfinite(t) || t < 0) {
                throw new BadInputException("--at: times must be finite numbers >= 0, got " + Quoted.of(s));
            }
            t = t == 0 ? 0.0 : t; // -0 is 0
            if (!times.contains(t)) {
                times.add(t);
            }
            if (times.size() > MAX_TIMES) {
                throw new BadInputException("--at: at most " + MAX_TIMES + " times, each a picture of its own");
            }
        }
        return times;
    }

    /** The time as file names and captions show it: shortest decimal, no exponent, no trailing zeros. */
    static String timeLabel(double t) {
        if (t == 0) {
            return "0";
        }
        return BigDecimal.valueOf(t).stripTrailingZeros().toPlainString();
    }

    /** The scene name made safe as part of a file name. */
    static String fileStem(String sceneName) {
        String s = sceneName.replaceAll("[^A-Za-z0-9._-]", "_");
        return s.isEmpty() || s.chars().allMatch(c -> c == '.') ? "scene" : s;
    }


}
