package carom.app;

import carom.core.Quoted;
import carom.core.engine.Counter;
import carom.core.engine.RunResult;
import carom.core.engine.Energy;
import carom.core.observe.Pressure;
import java.io.PrintWriter;
import java.nio.charset.Charset;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;

/**
 * What {@code simulate} prints when no output file is asked for: aligned {@code key  value} lines for a
 * person to read. Physical quantities keep full precision ({@link Double#toString}); timings are rounded.
 * The energy is the total ({@link Energy}: kinetic plus gravity's potential), with the kinetic part
 * beside it when there is gravity; its drift is the total's.
 */
final class ReadableSummary {
    private static final int KEY_WIDTH = 22;
    /** Characters of the scene's name shown. */
    private static final int NAME_CHARS = 200;
    /**
     * Pair collisions per disc after which two exact engines' collision counts differ (rounding grows
     * about fourfold per collision per disc: lab/notes/exact-engines-agreement/).
     */
    static final double CHAOS_HORIZON = 20;

    private ReadableSummary() {
    }

    static void print(FinishedRun run, PrintWriter out, Charset charset) {
        RunResult r = run.result();
        Energy energy = run.energy();
        FinalChecks checks = run.checks();
        String plusMinus = charset.newEncoder().canEncode('\u00b1') ? " \u00b1 " : " +/- ";
        // The name comes from the scene file: no control characters reach the terminal.
        line(out, "scene", Quoted.bare(run.sceneName(), NAME_CHARS));
        line(out, "engine", r.engine() + (r.exact() ? " (exact)" : " (relaxed)"));
        line(out, "discs", Integer.toString(run.discs()));
        line(out, "until", Double.toString(r.until()));
        line(out, "threads", Integer.toString(run.threads()));
        line(out, "pair collisions", Long.toString(r.pairCollisions()));
        double perDisc = run.discs() == 0 ? 0 : (double) r.pairCollisions() / run.discs();
        if (r.exact() && perDisc >= CHAOS_HORIZON) {
            // Where a user compares two engines' counts: past this horizon they differ, and both are right.
            line(out, "  per disc", String.format(Locale.ROOT, "%.3g  (past about %.0f per disc, chaos makes exact engines' "
                    + "counts and trajectories differ: compare long runs by pressure and energy)", perDisc, CHAOS_HORIZON));
        }
        line(out, "wall collisions", Long.toString(r.wallCollisions()));
        line(out, "events", Long.toString(r.events()));
        line(out, "wall seconds", String.format(Locale.ROOT, "%.3f", r.wallSeconds()));
        line(out, "collisions per second", String.format(Locale.ROOT, "%.4g", r.collisionsPerSecond()));
        boolean potential = energy.initial() != r.kineticEnergyStart() || energy.end() != r.kineticEnergyEnd();
        line(out, "energy initial", energy(energy.initial(), r.kineticEnergyStart(), potential));
        line(out, "energy final", energy(energy.end(), r.kineticEnergyEnd(), potential));
        line(out, "energy drift", Double.isNaN(energy.drift()) ? "undefined (gravity in a periodic box)"
                : String.format(Locale.ROOT, "%.3e", energy.drift())
                + (r.has(carom.core.engine.Counter.GROWTH_STAGES)
                ? "  (growth: collisions add energy, the thermostat at --every takes it out)" : ""));
        if (r.has(Counter.SLEEPS)) {
            // Resting contact: kinetic energy taken out by discs falling asleep (part of the drift).
            line(out, "energy put to rest", String.format(Locale.ROOT, "%s  (%d discs fell asleep, %d woke)",
                    r.energyPutToRest(), r.counter(Counter.SLEEPS, 0), r.counter(Counter.WAKES, 0)));
        }
        if (r.has(Counter.RESCALINGS) && !r.has(Counter.GROWTH_STAGES)) {
            line(out, "energy removed", String.format(Locale.ROOT, "%s  (thermostat, %d rescalings)",
                    r.energyRemoved(), r.counter(Counter.RESCALINGS, 0)));
        }
        line(out, "momentum initial", vector(r.momentumStart()));
        line(out, "momentum final", vector(r.momentumEnd()));
        Pressure p = r.pressure();
        if (p != null) {
            line(out, "pressure Z", String.format(Locale.ROOT, "%.6g%s%.2g  (P = %.6g%s%.2g, %d blocks)",
                    p.compressibility(), plusMinus, p.compressibilityError(),
                    p.pressure(), plusMinus, p.pressureError(), p.blocks()));
        }
        line(out, "deepest overlap", String.format(Locale.ROOT, "%.3g of a contact distance%s", checks.deepestOverlap(),
                r.exact() ? "" : " (relaxed engines can leave overlaps)"));
        if (checks.escapes() > 0) {
            line(out, "discs outside walls", Integer.toString(checks.escapes()));
        }
        Comparison c = run.comparison();
        if (c != null) {
            line(out, "against " + c.engine(), String.format(Locale.ROOT, "largest position error %.3g (rms %.3g), "
                    + "largest velocity error %.3g; its deepest overlap %.3g, its pair collisions %d",
                    c.largestPositionError(), c.rmsPositionError(), c.largestVelocityError(), c.referenceOverlap(),
                    c.referencePairCollisions()));
            line(out, "", c.chaosDominates()
                    ? String.format(Locale.ROOT, "(%.3g pair collisions per disc: past about %.0f, chaos alone parts exact "
                    + "engines this far, so these errors measure chaos, not the engine)", c.collisionsPerDisc(), CHAOS_HORIZON)
                    : String.format(Locale.ROOT, "(%.3g pair collisions per disc: short enough that the errors are the "
                    + "engine's own, not chaos)", c.collisionsPerDisc()));
        }
        line(out, "causality violations", Long.toString(r.causalityViolations()));
        if (!r.exact()) {
            line(out, "  per 10^6 collisions", String.format(Locale.ROOT, "%.1f", r.violationsPerMillionCollisions()));
        }
        if (!Double.isNaN(r.messagesPerCollision())) {
            line(out, "messages per collision", String.format(Locale.ROOT, "%.1f  (by type: counters messages.*)",
                    r.messagesPerCollision()));
        }
        Map<String, Long> counters = r.counters() == null ? Map.of() : new TreeMap<>(r.counters());
        if (!counters.isEmpty()) {
            out.println("counters");
            counters.forEach((k, v) -> line(out, "  " + k, Long.toString(v)));
        }
        out.flush();
    }

    private static void line(PrintWriter out, String key, String value) {
        StringBuilder sb = new StringBuilder(KEY_WIDTH + value.length() + 2).append(key);
        do {
            sb.append(' ');
        } while (sb.length() < KEY_WIDTH);
        out.println(sb.append(' ').append(value));
    }

    /** The total energy, with its kinetic part when they differ (under gravity). */
    private static String energy(double total, double kinetic, boolean showKinetic) {
        if (Double.isNaN(total)) {
            return "undefined (gravity in a periodic box); kinetic " + kinetic;
        }
        return showKinetic ? total + "  (kinetic " + kinetic + ")" : Double.toString(total);
    }

    private static String vector(double[] v) {
        return "(" + v[0] + ", " + v[1] + ")";
    }
}
