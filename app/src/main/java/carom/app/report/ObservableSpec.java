package carom.app.report;

import carom.core.observe.CollisionObserver;
import carom.core.observe.sample.ObservableState;
import carom.core.observe.sample.SampledObservable;
import carom.core.scene.Scene;
import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.function.Function;
import org.knowm.xchart.XYChart;

/**
 * Everything the command line knows of one observable, said once: its key ({@code --observe KEY}, the
 * report's {@code KEY.csv}, {@code KEY.png} and {@code KEY.svg}, the checkpoint's state), what it is
 * (one line, as the help and the docs list it), its table's columns, how it is made for a run and
 * restored from a checkpoint, its plot, and whether it also listens to the collisions themselves.
 * {@link ObservableCatalog} enrols every one.
 *
 * @param key        the name, as the observable's {@link SampledObservable#key()} gives it
 * @param meaning    what it is, one line (the docs' table of observables says the same, word for word)
 * @param columns    the header of {@code KEY.csv}; the observable writes the rows
 * @param create     a new one for a run of a scene sampled every interval
 * @param restore    the one a checkpoint's state was saved from, continuing exactly; refuses (an
 *                   {@link IllegalArgumentException}) a state of another key or layout
 * @param plot       its chart for {@code KEY.png} and {@code KEY.svg}
 * @param collisions what is told the run's collisions, or null if it reads samples only: an engine
 *                   that does not tell collisions cannot run it
 * @param <T>        the observable's class
 */
public record ObservableSpec<T extends SampledObservable>(String key, String meaning, List<String> columns,
                                                           Factory<T> create, Function<ObservableState, T> restore,
                                                           Function<T, XYChart> plot, Function<T, CollisionObserver> collisions) {
    /** Makes the observable for one run. */
    @FunctionalInterface
    public interface Factory<T> {
        /** For a run of {@code scene} sampled every {@code interval} of simulated time. */
        T create(Scene scene, double interval);
    }

    public ObservableSpec {
        columns = List.copyOf(columns);
    }

    /** A spec of an observable that reads samples only. */
    public ObservableSpec(String key, String meaning, List<String> columns, Factory<T> create,
                          Function<ObservableState, T> restore, Function<T, XYChart> plot) {
        this(key, meaning, columns, create, restore, plot, null);
    }

    /** Whether it listens to collisions, so that only an engine that tells them can run it. */
    public boolean needsCollisions() {
        return collisions != null;
    }

    /** {@code KEY.csv}: the header line of {@link #columns}, then the observable's rows. */
    public void writeCsv(T observable, Writer out) throws IOException {
        out.write(String.join(",", columns));
        out.write('\n');
        observable.writeRows(out);
    }

    /** Writes {@code KEY.csv}, {@code KEY.png} and {@code KEY.svg} of {@code observable} into {@code folder}. */
    public void writeInto(T observable, Path folder) throws IOException {
        try (Writer w = Files.newBufferedWriter(folder.resolve(key + ".csv"), StandardCharsets.UTF_8)) {
            writeCsv(observable, w);
        }
        // A chart each: rendering one need not leave it as it was.
        Files.write(folder.resolve(key + ".png"), ChartStyle.png(plot.apply(observable)));
        Files.write(folder.resolve(key + ".svg"), ChartStyle.svg(plot.apply(observable)));
    }
}
