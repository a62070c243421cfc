import carom.lab.report.Charts;
import carom.lab.study.eos.BranchAgreement;
import carom.lab.study.eos.EosLiterature;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * Several {@code carom study eos} runs of one N in one plot of βPσ² against φ through the transition, beside
 * the published points of the HistoricDisks data set from 0.69 up (N = 128² of Li et al. 2022 and 1024²):
 * each packing fraction's accepted value (both starts agreeing as the study's {@link BranchAgreement} judges:
 * their plain mean, the error their combined one halved, as the study reports it), and each start's own value.
 *
 * <pre>java -cp lab/target/carom-lab.jar lab/notes/eos-transition/PlotBySize.java OUT_NAME RUN/eos.csv...</pre>
 *
 * writes OUT_NAME.png and OUT_NAME.svg.
 */
public class PlotBySize {
    private static final double FROM = 0.69;

    public static void main(String[] args) throws IOException {
        String name = args[0];
        // φ -> start -> {βPσ², error}
        Map<Double, Map<String, double[]>> byPhi = new TreeMap<>();
        int discs = 0;
        for (int a = 1; a < args.length; a++) {
            List<String> rows = Files.readAllLines(Path.of(args[a]));
            Map<String, Integer> col = new HashMap<>();
            String[] header = rows.getFirst().split(",", -1);
            for (int i = 0; i < header.length; i++) {
                col.put(header[i], i);
            }
            for (String row : rows.subList(1, rows.size())) {
                String[] r = row.split(",", -1);
                if (!r[col.get("status")].equals("measured")) {
                    continue;
                }
                discs = Integer.parseInt(r[col.get("n")]);
                byPhi.computeIfAbsent(Double.parseDouble(r[col.get("phi")]), k -> new HashMap<>()).put(r[col.get("start")],
                        new double[] {Double.parseDouble(r[col.get("betaP_sigma2")]), Double.parseDouble(r[col.get("betaP_sigma2_error")])});
            }
        }
        List<Charts.Line> lines = new ArrayList<>();
        List<Double> x = new ArrayList<>();
        List<Double> y = new ArrayList<>();
        List<Double> e = new ArrayList<>();
        for (var entry : byPhi.entrySet()) {
            double[] c = entry.getValue().get("crystal");
            double[] l = entry.getValue().get("fluid");
            if (c != null && l != null && BranchAgreement.of(c[0], c[1], l[0], l[1]).agree()) {
                x.add(entry.getKey());
                y.add((c[0] + l[0]) / 2);
                e.add(Math.hypot(c[1], l[1]) / 2);
            }
        }
        lines.add(new Charts.Line("carom, N = " + discs + ", accepted (both starts' mean)", x, y, e, false));
        for (String start : List.of("crystal", "fluid")) {
            List<Double> sx = new ArrayList<>();
            List<Double> sy = new ArrayList<>();
            for (var entry : byPhi.entrySet()) {
                double[] v = entry.getValue().get(start);
                if (v != null) {
                    sx.add(entry.getKey());
                    sy.add(v[0]);
                }
            }
            lines.add(new Charts.Line("carom, " + (start.equals("fluid") ? "liquid" : start) + " start", sx, sy, null, false));
        }
        for (EosLiterature.Series s : EosLiterature.all()) {
            List<EosLiterature.Point> ps = s.points().stream().filter(p -> p.phi() >= FROM).toList();
            if (!ps.isEmpty()) {
                lines.add(new Charts.Line(s.name(), ps.stream().map(EosLiterature.Point::phi).toList(),
                        ps.stream().map(EosLiterature.Point::betaPSigma2).toList(), null, true));
            }
        }
        Charts.Figure figure = new Charts.Figure("Hard discs, N = " + discs + ", beside the literature",
                "packing fraction φ", "βPσ²", lines, false, false);
        for (var file : Charts.files(name, figure).entrySet()) {
            Files.write(Path.of(file.getKey()), file.getValue());
        }
    }
}
