package carom.lab.study.eos;

import java.util.List;

/**
 * Published equation-of-state points of equal hard discs, as βPσ² (σ the diameter) against packing
 * fraction, with their source and system size: what the study plots beside its own (public for the lab
 * notes' programs that plot several studies together).
 */
public final class EosLiterature {
    /** One published point. */
    public record Point(double phi, double betaPSigma2, String source) {
    }

    /** A published series: one source and system size ({@code discs}; infinite for a thermodynamic-limit fit). */
    public record Series(String name, double discs, List<Point> points) {
    }

    private EosLiterature() {
    }

    /**
     * The fluid (Kolafa and Rottner 2006, the values carom's physics tests use, given there as Z and
     * converted here), the HistoricDisks data set (Engel et al. 2013, Li et al. 2022) at N = 870, its
     * N = 128² runs of Li et al. in the box of our runs at that N (1 : √3/2, a triangular lattice's),
     * and its N = 1024² runs through the liquid-hexatic loop.
     */
    public static List<Series> all() {
        return List.of(
                new Series("fluid: Kolafa-Rottner 2006, Bernard-Krauth 2011", Double.POSITIVE_INFINITY, List.of(
                        fromZ(0.30, 2.0633, "KR2006"), fromZ(0.50, 4.1069, "KR2006"), fromZ(0.65, 8.4078, "KR2006"),
                        fromZ(0.68, 9.8328, "BK2011"))),
                new Series("HistoricDisks N = 870", 870, List.of(
                        new Point(0.670, 7.986735, "HistoricDisks N=870"), new Point(0.680, 8.513233, "HistoricDisks N=870"))),
                new Series("HistoricDisks N = 128² (Li et al. 2022, 1 : √3/2 box)", 128 * 128, List.of(
                        new Point(0.698, 9.17441, "HistoricDisks N=128^2"), new Point(0.704, 9.18700, "HistoricDisks N=128^2"),
                        new Point(0.708, 9.17512, "HistoricDisks N=128^2"), new Point(0.712, 9.16590, "HistoricDisks N=128^2"),
                        new Point(0.716, 9.1560, "HistoricDisks N=128^2"))),
                new Series("HistoricDisks N = 1024²", 1024 * 1024, List.of(
                        new Point(0.698, 9.169342, "HistoricDisks N=1024^2"), new Point(0.700, 9.185405, "HistoricDisks N=1024^2"),
                        new Point(0.708, 9.184959, "HistoricDisks N=1024^2"), new Point(0.716, 9.18327, "HistoricDisks N=1024^2"),
                        new Point(0.720, 9.23083, "HistoricDisks N=1024^2"))));
    }

    private static Point fromZ(double phi, double z, String source) {
        return new Point(phi, EosScene.betaPSigma2(z, phi), source);
    }

    /**
     * The published point at {@code phi} (to 1e-9) of the series whose size is nearest {@code discs},
     * or null where none has one. Nearest in N^-1/2, the scale of the finite-size corrections through the
     * loop (the interface's cost), so that a thermodynamic-limit fit is the nearest to a large enough N.
     */
    public static Point at(double phi, int discs) {
        Point best = null;
        double bestDistance = Double.POSITIVE_INFINITY;
        for (Series s : all()) {
            double distance = Math.abs(1 / Math.sqrt(s.discs()) - 1 / Math.sqrt(discs));
            for (Point p : s.points()) {
                if (Math.abs(p.phi() - phi) < 1e-9 && (best == null || distance < bestDistance)) {
                    best = p;
                    bestDistance = distance;
                }
            }
        }
        return best;
    }
}
