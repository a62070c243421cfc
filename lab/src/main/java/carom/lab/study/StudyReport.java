package carom.lab.study;

import java.io.IOException;
import java.io.Writer;
import java.util.List;
import java.util.Locale;

/** The study's rows as Markdown tables (one per size and scene) and as CSV (one line per row). */
final class StudyReport {
    private StudyReport() {
    }

    static void markdown(List<Row> rows, String header, Writer w) throws IOException {
        w.write(header);
        Row previous = null;
        for (Row r : rows) {
            if (previous == null || previous.scene() != r.scene()) {
                tableHead(r, rows, w);
            }
            previous = r;
            w.write(markdownLine(r));
        }
    }

    private static void tableHead(Row first, List<Row> rows, Writer w) throws IOException {
        StudyScene s = first.scene();
        String shortCollisions = rows.stream()
                .filter(r -> r.scene() == s && r.ran() && r.setting().engine().equals("serial"))
                .map(r -> String.format(Locale.ROOT, ", %.2f collisions per disc by serial",
                        r.measured().shortCollisions() / (double) s.discs()))
                .findFirst().orElse("");
        w.write(String.format(Locale.ROOT, "%n### N = %d, %s%n%nHorizon t = %s; trajectories compared at t = %s%s.%n%n",
                s.discs(), s.label(), g(first.until()), g(first.shortUntil()), shortCollisions));
        w.write("| engine, setting | threads (carriers) | wall s (mean ± sd) | collisions | Z ± err | \\|Z − Z_exact\\| "
                + "| energy drift | deepest overlap | escapes | viol. / 10⁶ coll. | traj. dev. RMS | traj. dev. max |\n");
        w.write("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    }

    private static String markdownLine(Row r) {
        String name = r.setting().label() + (r.setting().hasDt() ? " (" + g(r.dt()) + ")" : "");
        if (!r.ran()) {
            return "| " + name + " | – | not run: " + r.skipped() + " | | | | | | | | | |\n";
        }
        Measured m = r.measured();
        String threads = r.setting().threads() + (m.carriers() >= 0 ? " (" + m.carriers() + ")" : "");
        String time = m.reps() < 2 ? String.format(Locale.ROOT, "%.3g", m.meanSeconds())
                : String.format(Locale.ROOT, "%.3g ± %.2g", m.meanSeconds(), m.sdSeconds());
        String z = Double.isNaN(m.z()) ? "–" : String.format(Locale.ROOT, "%.4f ± %.4f", m.z(), m.zError());
        String dz = Double.isNaN(r.pressureError()) ? "–"
                : String.format(Locale.ROOT, "%.4f (σ %.4f)", r.pressureError(), r.zExactError());
        return "| " + String.join(" | ", name, threads, time, Long.toString(m.collisions()), z, dz, e(m.energyDrift()),
                e(m.deepestOverlap()), Long.toString(m.escapes()), String.format(Locale.ROOT, "%.4g", m.violationsPerMillion()),
                e(r.deviationRms()), e(r.deviationMax())) + " |\n";
    }

    static final String CSV_HEADER = "n,scene,periodic,phi,gravity,engine,setting,threads,carriers,dt,dt_factor,until,"
            + "short_until,skipped,reps,seconds_mean,seconds_sd,collisions,z,z_error,z_exact,z_exact_error,pressure_error,"
            + "energy_drift,deepest_overlap,final_overlap,reported_overlap,escapes,final_escapes,violations_per_million,"
            + "short_collisions,deviation_rms,deviation_max\n";

    static void csv(List<Row> rows, Writer w) throws IOException {
        w.write(CSV_HEADER);
        for (Row r : rows) {
            StudyScene s = r.scene();
            Setting st = r.setting();
            StringBuilder line = new StringBuilder();
            append(line, s.discs(), s.key(), s.periodic(), s.phi(), s.gravity(), st.engine(), st.label(), st.threads());
            Measured m = r.measured();
            if (m == null) {
                append(line, "", num(r.dt()), num(st.dtFactor()), r.until(), r.shortUntil(), r.skipped());
                line.append(",".repeat(19));
            } else {
                append(line, m.carriers() >= 0 ? Long.toString(m.carriers()) : "", num(r.dt()), num(st.dtFactor()),
                        r.until(), r.shortUntil(), "", m.reps(), m.meanSeconds(), m.sdSeconds(), m.collisions(),
                        num(m.z()), num(m.zError()), num(r.zExact()), num(r.zExactError()), num(r.pressureError()),
                        m.energyDrift(), m.deepestOverlap(), m.finalOverlap(), num(m.reportedOverlap()), m.escapes(),
                        m.finalEscapes(), m.violationsPerMillion(), m.shortCollisions(), num(r.deviationRms()),
                        num(r.deviationMax()));
            }
            line.setLength(line.length() - 1);
            w.write(line.append('\n').toString());
        }
    }

    private static void append(StringBuilder line, Object... values) {
        for (Object v : values) {
            String s = String.valueOf(v);
            line.append(s.contains(",") || s.contains("\"") ? '"' + s.replace("\"", "\"\"") + '"' : s).append(',');
        }
    }

    /** Empty for NaN, so that spreadsheets see a missing value. */
    private static String num(double v) {
        return Double.isNaN(v) ? "" : Double.toString(v);
    }

    private static String g(double v) {
        return String.format(Locale.ROOT, "%.4g", v);
    }

    private static String e(double v) {
        return Double.isNaN(v) ? "–" : v == 0 ? "0" : String.format(Locale.ROOT, "%.2e", v);
    }
}
