import carom.lab.report.Charts;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * The cost curve's plots from the raw rows of curve.sh: collisions a second of the engine's run and of
 * the whole command against N (log axes), and bytes a disc of the whole process, one line per code and
 * packing fraction, each point the median of its rounds; also the medians as a Markdown table.
 *
 * <p>Not part of the build: {@code java -cp lab/target/carom-lab.jar lab/notes/cost-curve/PlotCurve.java ROWS.csv OUTDIR}
 */
public final class PlotCurve {
    record Key(String code, double phi) {
    }

    public static void main(String[] args) throws IOException {
        Map<Key, Map<Long, List<double[]>>> runs = new TreeMap<>((a, b) -> a.code.equals(b.code) ? Double.compare(a.phi, b.phi)
                : a.code.compareTo(b.code));
        for (String line : Files.readAllLines(Path.of(args[0]))) {
            if (line.startsWith("#") || line.startsWith("code,") || line.isBlank()) {
                continue;
            }
            String[] f = line.split(",");
            double collisions = Double.parseDouble(f[4]);
            double[] run = {collisions / Double.parseDouble(f[5]), collisions / Double.parseDouble(f[6]), Double.parseDouble(f[8])};
            runs.computeIfAbsent(new Key(f[0], Double.parseDouble(f[2])), k -> new TreeMap<>())
                    .computeIfAbsent(Long.parseLong(f[1]), k -> new ArrayList<>()).add(run);
        }
        Path out = Path.of(args[1]);
        Files.createDirectories(out);
        String[] names = {"engine", "command", "bytes"};
        String[] titles = {"Collisions a second of the engine's run", "Collisions a second of the whole command",
            "Bytes a disc of the whole process (maximum resident set over N)"};
        String[] yTitles = {"collisions / s", "collisions / s", "bytes / disc"};
        StringBuilder table = new StringBuilder("| code | phi | N | rounds | engine M coll/s | command M coll/s | bytes/disc |\n|---|---|--:|--:|--:|--:|--:|\n");
        for (int m = 0; m < 3; m++) {
            List<Charts.Line> lines = new ArrayList<>();
            for (var e : runs.entrySet()) {
                List<Double> x = new ArrayList<>();
                List<Double> y = new ArrayList<>();
                for (var atN : e.getValue().entrySet()) {
                    x.add((double) atN.getKey());
                    y.add(median(atN.getValue(), m));
                    if (m == 0) {
                        table.append(String.format("| %s | %s | %d | %d | %.3f | %.3f | %.0f |%n", e.getKey().code, e.getKey().phi,
                                atN.getKey(), atN.getValue().size(), median(atN.getValue(), 0) / 1e6,
                                median(atN.getValue(), 1) / 1e6, median(atN.getValue(), 2)));
                    }
                }
                lines.add(Charts.Line.of(e.getKey().code + " phi " + e.getKey().phi, x, y));
            }
            Charts.Figure figure = new Charts.Figure(titles[m], "N (discs)", yTitles[m], lines, true, m < 2);
            for (var file : Charts.files("cost-" + names[m], figure).entrySet()) {
                Files.write(out.resolve(file.getKey()), file.getValue());
            }
        }
        Files.writeString(out.resolve("medians.md"), table);
    }

    private static double median(List<double[]> runs, int column) {
        double[] v = runs.stream().mapToDouble(r -> r[column]).sorted().toArray();
        return v.length % 2 == 1 ? v[v.length / 2] : (v[v.length / 2 - 1] + v[v.length / 2]) / 2;
    }
}
