package carom.lab.eos;

import java.util.Map;
import java.util.TreeMap;

/**
 * Published equation-of-state points of equal hard discs, as βPσ² (σ = 2R) against packing fraction φ,
 * with the system size they were taken at. Z = βP A / N = βPσ² · π / (4 φ).
 *
 * <ul>
 *   <li>φ ≤ 0.65 (and 0.68 as Z = 9.8328): the values {@code FastEquationOfStateTest} uses (Kolafa and
 *       Rottner 2006 for the fluid; Bernard and Krauth 2011 at 0.68), converted to βPσ²;</li>
 *   <li>0.670 and 0.680, N = 870; 0.698 to 0.720, N = 1024²: the HistoricDisks data set of Engel et al.
 *       (2013) and Li et al. (2022), as issue 19 quotes them.</li>
 * </ul>
 */
public final class EosLiterature {
    /** A published point: βPσ² at φ, and the N it is for (0: the thermodynamic limit). */
    public record Point(double phi, double betaPSigma2, long n, String source) {
        public double compressibility() {
            return betaPSigma2 * Math.PI / (4 * phi);
        }
    }

    private static final Map<Double, Point> POINTS = new TreeMap<>();

    static {
        fromZ(0.30, 2.0633, "Kolafa & Rottner 2006");
        fromZ(0.50, 4.1069, "Kolafa & Rottner 2006");
        fromZ(0.65, 8.4078, "Kolafa & Rottner 2006");
        put(0.670, 7.986735, 870, "Engel et al. 2013 (HistoricDisks)");
        put(0.680, 8.513233, 870, "Engel et al. 2013 (HistoricDisks)");
        put(0.698, 9.169342, 1024 * 1024, "Engel et al. 2013, Li et al. 2022");
        put(0.700, 9.185405, 1024 * 1024, "Engel et al. 2013, Li et al. 2022");
        put(0.708, 9.184959, 1024 * 1024, "Engel et al. 2013, Li et al. 2022");
        put(0.716, 9.18327, 1024 * 1024, "Engel et al. 2013, Li et al. 2022");
        put(0.720, 9.23083, 1024 * 1024, "Engel et al. 2013, Li et al. 2022");
    }

    private EosLiterature() {
    }

    private static void put(double phi, double p, long n, String source) {
        POINTS.put(phi, new Point(phi, p, n, source));
    }

    private static void fromZ(double phi, double z, String source) {
        put(phi, z * 4 * phi / Math.PI, 0, source);
    }

    /** Every point, by φ. */
    public static Iterable<Point> all() {
        return POINTS.values();
    }

    /** The point at exactly {@code phi} (to 1e-9), or null. */
    public static Point at(double phi) {
        for (Point p : POINTS.values()) {
            if (Math.abs(p.phi() - phi) < 1e-9) {
                return p;
            }
        }
        return null;
    }
}
