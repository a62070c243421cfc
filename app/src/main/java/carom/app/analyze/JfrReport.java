package carom.app.analyze;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.util.Comparator;
import java.util.DoubleSummaryStatistics;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import jdk.jfr.consumer.RecordedEvent;
import jdk.jfr.consumer.RecordedFrame;
import jdk.jfr.consumer.RecordedMethod;
import jdk.jfr.consumer.RecordedStackTrace;
import jdk.jfr.consumer.RecordingFile;

/**
 * What {@code carom analyze} reports, gathered in one pass over a recording. Only sums are kept, since
 * a recording can hold millions of step or violation events.
 */
final class JfrReport {
    private static final int TOP = 10;

    /** Steps of one engine: collisions per step and wall-clock milliseconds per step. */
    private record Steps(DoubleSummaryStatistics collisions, DoubleSummaryStatistics millis) {
        Steps() {
            this(new DoubleSummaryStatistics(), new DoubleSummaryStatistics());
        }
    }

    /** Queue rebuilds of one engine: milliseconds and potentials per rebuild, discs. */
    private record Rebuilds(DoubleSummaryStatistics millis, DoubleSummaryStatistics potentials, Set<Integer> discs) {
        Rebuilds() {
            this(new DoubleSummaryStatistics(), new DoubleSummaryStatistics(), new HashSet<>());
        }
    }

    private Instant first;
    private Instant last;
    private long samples;
    /** Execution samples by their top frame, and by their first frame in carom's own code. */
    private final Map<String, Long> topFrames = new HashMap<>();
    private final Map<String, Long> caromFrames = new HashMap<>();
    private final DoubleSummaryStatistics gcPauseMillis = new DoubleSummaryStatistics();
    private double gcLongestMillis;
    private long sampledAllocationBytes;
    private final DoubleSummaryStatistics machineLoad = new DoubleSummaryStatistics();
    private final DoubleSummaryStatistics jvmLoad = new DoubleSummaryStatistics();
    private int hardwareThreads;
    private final Map<String, Steps> steps = new TreeMap<>();
    private final Map<String, Rebuilds> rebuilds = new TreeMap<>();
    private final DoubleSummaryStatistics violationLateBy = new DoubleSummaryStatistics();
    private final Set<String> actors = new HashSet<>();
    private long messagesIn;
    private long messagesOut;
    private long deepestMailbox = -1;
    private Duration actorsBusy = Duration.ZERO;

    static JfrReport read(Path file) throws IOException {
        JfrReport report = new JfrReport();
        try (RecordingFile recording = new RecordingFile(file)) {
            while (recording.hasMoreEvents()) {
                report.add(recording.readEvent());
            }
        }
        return report;
    }

    private void add(RecordedEvent e) {
        if (first == null || e.getStartTime().isBefore(first)) {
            first = e.getStartTime();
        }
        if (last == null || e.getEndTime().isAfter(last)) {
            last = e.getEndTime();
        }
        switch (e.getEventType().getName()) {
            case "jdk.ExecutionSample" -> addSample(e.getStackTrace());
            case "jdk.GarbageCollection" -> {
                gcPauseMillis.accept(millis(e.getDuration("sumOfPauses")));
                gcLongestMillis = Math.max(gcLongestMillis, millis(e.getDuration("longestPause")));
            }
            case "jdk.ObjectAllocationSample" -> sampledAllocationBytes += e.getLong("weight");
            case "jdk.CPULoad" -> {
                machineLoad.accept(e.getFloat("machineTotal"));
                jvmLoad.accept(e.getFloat("jvmUser") + e.getFloat("jvmSystem"));
            }
            case "jdk.CPUInformation" -> hardwareThreads = e.getInt("hwThreads");
            case "carom.TimeStep" -> {
                Steps s = steps.computeIfAbsent(engine(e), k -> new Steps());
                s.collisions().accept(e.getLong("collisions"));
                s.millis().accept(millis(e.getDuration()));
            }
            case "carom.QueueRebuild" -> {
                Rebuilds r = rebuilds.computeIfAbsent(engine(e), k -> new Rebuilds());
                r.millis().accept(millis(e.getDuration()));
                r.potentials().accept(e.getLong("potentials"));
                r.discs().add(e.getInt("discs"));
            }
            case "carom.CausalityViolation" -> violationLateBy.accept(e.getDouble("lateBy"));
            case "carom.ActorMailbox" -> {
                actors.add(engine(e) + "/" + e.getString("actor"));
                messagesIn += e.getLong("messagesIn");
                messagesOut += e.getLong("messagesOut");
                deepestMailbox = Math.max(deepestMailbox, e.getLong("maxMailboxDepth"));
                actorsBusy = actorsBusy.plus(e.getDuration("busyNanos"));
            }
            default -> {
                // Everything else in the "profile" settings is left to JDK Mission Control.
            }
        }
    }

    private void addSample(RecordedStackTrace stack) {
        if (stack == null || stack.getFrames().isEmpty()) {
            return;
        }
        samples++;
        List<RecordedFrame> frames = stack.getFrames();
        topFrames.merge(name(frames.getFirst().getMethod()), 1L, Long::sum);
        for (RecordedFrame f : frames) {
            String method = name(f.getMethod());
            if (method.startsWith("carom.")) {
                caromFrames.merge(method, 1L, Long::sum);
                break;
            }
        }
    }

    /** The engine that emitted a carom event; an emitter that left it out still gets a row. */
    private static String engine(RecordedEvent e) {
        return Objects.requireNonNullElse(e.getString("engine"), "unnamed engine");
    }

    private static String name(RecordedMethod m) {
        return m.getType().getName() + "." + m.getName();
    }

    private static double millis(Duration d) {
        return d.toNanos() * 1e-6;
    }

    void print(PrintWriter out) {
        double seconds = first == null ? 0 : millis(Duration.between(first, last)) * 1e-3;
        line(out, "recording: %.2f s", seconds);

        line(out, "%nwhere the CPU went (%d execution samples)", samples);
        printTop(out, "top frame (self time)", topFrames);
        printTop(out, "first carom frame (time in carom code and what it calls)", caromFrames);

        line(out, "%nmemory");
        if (gcPauseMillis.getCount() == 0) {
            line(out, "  GC: no collections");
        } else {
            line(out, "  GC: collections %d, pauses total %.1f ms, longest %.1f ms",
                    gcPauseMillis.getCount(), gcPauseMillis.getSum(), gcLongestMillis);
        }
        line(out, "  allocation: %.1f MB/s (estimated from allocation samples)",
                seconds > 0 ? sampledAllocationBytes / seconds * 1e-6 : 0.0);

        line(out, "%nCPU load (%d samples; share of all %s hardware threads)", machineLoad.getCount(),
                hardwareThreads > 0 ? Integer.toString(hardwareThreads) : "the");
        if (machineLoad.getCount() == 0) {
            line(out, "  none: the run was shorter than the 100 ms sampling period");
        } else {
            line(out, "  this JVM:  mean %3.0f%%, max %3.0f%%", 100 * jvmLoad.getAverage(), 100 * jvmLoad.getMax());
            line(out, "  machine:   mean %3.0f%%, max %3.0f%%", 100 * machineLoad.getAverage(), 100 * machineLoad.getMax());
            line(out, "  others:    mean %3.0f%% (machine minus this JVM: above a few percent, the machine was busy)",
                    100 * Math.max(0, machineLoad.getAverage() - jvmLoad.getAverage()));
        }

        line(out, "%ncarom events");
        printCaromEvents(out);
    }

    private void printTop(PrintWriter out, String title, Map<String, Long> counts) {
        if (counts.isEmpty()) {
            return;
        }
        line(out, "  %s:", title);
        counts.entrySet().stream()
                .sorted(Map.Entry.<String, Long>comparingByValue(Comparator.reverseOrder()).thenComparing(Map.Entry.comparingByKey()))
                .limit(TOP)
                .forEach(e -> line(out, "    %5.1f%%  %s", 100.0 * e.getValue() / samples, e.getKey()));
    }

    private void printCaromEvents(PrintWriter out) {
        if (steps.isEmpty() && rebuilds.isEmpty() && violationLateBy.getCount() == 0 && actors.isEmpty()) {
            line(out, "  none (was the run recorded with 'carom simulate --jfr'?)");
            return;
        }
        long collisions = 0;
        for (Map.Entry<String, Steps> e : steps.entrySet()) {
            Steps s = e.getValue();
            collisions += (long) s.collisions().getSum();
            line(out, "  steps (%s): %d, collisions %d; per step: collisions mean %.1f, max %.0f; "
                    + "time mean %.3f ms, max %.3f ms, total %.1f ms", e.getKey(), s.collisions().getCount(),
                    (long) s.collisions().getSum(), s.collisions().getAverage(), s.collisions().getMax(),
                    s.millis().getAverage(), s.millis().getMax(), s.millis().getSum());
        }
        for (Map.Entry<String, Rebuilds> e : rebuilds.entrySet()) {
            Rebuilds r = e.getValue();
            line(out, "  queue rebuilds (%s): %d of %s discs; per rebuild: %.0f potentials, time mean %.3f ms, "
                    + "max %.3f ms; total %.1f ms", e.getKey(), r.millis().getCount(), discs(r.discs()),
                    r.potentials().getAverage(), r.millis().getAverage(), r.millis().getMax(), r.millis().getSum());
        }
        if (violationLateBy.getCount() == 0) {
            line(out, "  causality violations: none");
        } else {
            line(out, "  causality violations: %d%s; late by (simulated time) mean %.3g, max %.3g",
                    violationLateBy.getCount(), collisions > 0
                            ? String.format(Locale.ROOT, " (%.2f%% of collisions)", 100.0 * violationLateBy.getCount() / collisions)
                            : "",
                    violationLateBy.getAverage(), violationLateBy.getMax());
        }
        if (!actors.isEmpty()) {
            line(out, "  actor mailboxes: %d actors, %d messages in, %d out, deepest mailbox %s, busy %.1f ms in total",
                    actors.size(), messagesIn, messagesOut, deepestMailbox < 0 ? "unknown" : Long.toString(deepestMailbox),
                    millis(actorsBusy));
            if (collisions > 0) {
                line(out, "  messages per collision: %.2f", (double) messagesIn / collisions);
            }
        }
    }

    /** One disc count, or the sorted list if several runs were recorded. */
    private static String discs(Set<Integer> counts) {
        return counts.size() == 1 ? counts.iterator().next().toString() : new TreeSet<>(counts).toString();
    }

    private static void line(PrintWriter out, String format, Object... args) {
        out.println(String.format(Locale.ROOT, format, args));
    }
}
