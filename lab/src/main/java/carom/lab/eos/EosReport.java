package carom.lab.eos;

import carom.lab.report.Charts;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/** The equation-of-state study's table (CSV and Markdown) and its plot, the literature beside. */
final class EosReport {
    private EosReport() {
    }

    static String csv(List<EosPoint.Result> results) {
        StringBuilder s = new StringBuilder("phi,n,betaPSigma2,betaPSigma2Error,Z,Zerror,psi6,psi6Error,equilibrated,"
                + "extensions,collisionsPerDisc,seconds,literatureBetaPSigma2,literatureN\n");
        for (EosPoint.Result r : results) {
            EosLiterature.Point lit = EosLiterature.at(r.phi());
            s.append(String.format(Locale.ROOT, "%s,%d,%s,%s,%s,%s,%s,%s,%s,%d,%s,%s,%s,%s%n", r.phi(), r.n(),
                    r.betaPSigma2(), r.betaPSigma2Error(), r.z(), r.zError(), r.psi6(), r.psi6Error(), r.equilibrated(),
                    r.extensions(), r.collisionsPerDisc(), r.seconds(), lit == null ? "" : lit.betaPSigma2(),
                    lit == null ? "" : lit.n()));
        }
        return s.toString();
    }

    static String markdown(String header, List<EosPoint.Result> results) {
        StringBuilder s = new StringBuilder("# Equation of state of equal hard discs\n\n").append(header).append("\n\n");
        s.append("| φ | βPσ² | Z | \\|ψ6\\| | literature βPσ² (N) | difference / error | equilibrated | collisions per disc |\n");
        s.append("|---|---|---|---|---|---|---|---|\n");
        for (EosPoint.Result r : results) {
            EosLiterature.Point lit = EosLiterature.at(r.phi());
            String litText = lit == null ? "" : String.format(Locale.ROOT, "%.6f (%s)", lit.betaPSigma2(),
                    lit.n() == 0 ? "N → ∞" : Long.toString(lit.n()));
            String diff = lit == null ? "" : String.format(Locale.ROOT, "%+.1f", (r.betaPSigma2() - lit.betaPSigma2())
                    / r.betaPSigma2Error());
            s.append(String.format(Locale.ROOT, "| %.3f | %.5f ± %.5f | %.5f ± %.5f | %.3f ± %.3f | %s | %s | %s | %.0f |%n",
                    r.phi(), r.betaPSigma2(), r.betaPSigma2Error(), r.z(), r.zError(), r.psi6(), r.psi6Error(), litText,
                    diff, r.equilibrated() ? "yes" + (r.extensions() > 0 ? " (" + r.extensions() + " extended)" : "")
                            : "no, still drifting", r.collisionsPerDisc()));
        }
        s.append("\nA loop in the equation of state shows as βPσ² falling while φ rises, by more than the error bars.\n");
        return s.toString();
    }

    static Charts.Figure figure(List<EosPoint.Result> results) {
        List<Double> x = new ArrayList<>();
        List<Double> y = new ArrayList<>();
        List<Double> e = new ArrayList<>();
        for (EosPoint.Result r : results) {
            x.add(r.phi());
            y.add(r.betaPSigma2());
            e.add(r.betaPSigma2Error());
        }
        List<Double> lx = new ArrayList<>();
        List<Double> ly = new ArrayList<>();
        for (EosLiterature.Point p : EosLiterature.all()) {
            lx.add(p.phi());
            ly.add(p.betaPSigma2());
        }
        String n = results.isEmpty() ? "" : " (N = " + results.get(0).n() + ")";
        return new Charts.Figure("Equation of state of hard discs", "packing fraction φ", "βPσ²",
                List.of(new Charts.Line("carom" + n, x, y, e, false),
                        new Charts.Line("literature (Kolafa & Rottner; Engel et al. 2013)", lx, ly, null, true)),
                false, false);
    }
}
