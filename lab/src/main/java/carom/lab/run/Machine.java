package carom.lab.run;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/**
 * The machine a measurement ran on, as every lab report states it: cores, CPU model (from
 * /proc/cpuinfo, read once per JVM), memory, JVM and OS. The load average is read on its own, before
 * and after a measurement, because it changes while the machine works.
 */
public record Machine(int cores, String cpu, String jvm, String os, long physicalMemoryBytes) {
    /** Read once: the CPU does not change while the JVM runs. */
    private static final String CPU_MODEL = cpuModel();

    public static Machine current() {
        return new Machine(Runtime.getRuntime().availableProcessors(), CPU_MODEL,
                System.getProperty("java.vm.name") + " " + System.getProperty("java.runtime.version")
                        + " (" + System.getProperty("java.vendor") + ")",
                System.getProperty("os.name") + " " + System.getProperty("os.version") + " " + System.getProperty("os.arch"),
                physicalMemory());
    }

    /** The one-minute load average now, NaN where the system has none (Windows). */
    public static double loadAverage() {
        double load = ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage();
        return load < 0 ? Double.NaN : load;
    }

    /**
     * A one-minute load average at or above this before a measurement means another process was
     * already running: the measurement would share the cores with it.
     */
    public static final double QUIET_LOAD = 0.5;

    /**
     * Whether the load averages read before and after a measurement say that another process shared
     * the cores: already busy before it started ({@link #QUIET_LOAD} or more), or afterwards above what
     * the measurement's own {@code ownThreads} busy threads explain (plus one for the JVM's own GC and
     * JIT threads). Null when quiet; otherwise a sentence for the report. The one-minute average lags,
     * so this flags, it does not prove: a quiet verdict is necessary for trust, not sufficient.
     */
    public String sharedVerdict(double loadBefore, double loadAfter, int ownThreads) {
        double ownLoad = Math.min(cores, ownThreads) + 1;
        if (loadBefore >= QUIET_LOAD) {
            return String.format(Locale.ROOT, "shared: the load average was %.2f on %d cores before the first run, so another "
                    + "process was using them; treat the times as upper bounds and rerun on a quiet machine", loadBefore, cores);
        }
        if (loadAfter > ownLoad) {
            return String.format(Locale.ROOT, "shared: the load average was %.2f on %d cores after the last run, above the %.0f "
                    + "this measurement's own threads explain; treat the times as upper bounds", loadAfter, cores, ownLoad);
        }
        return null;
    }

    /** Half the machine's memory, in whole GiB (at least 1): the default heap of each child JVM. */
    public static String defaultHeap() {
        long gib = physicalMemory() >> 30;
        return Math.max(1, gib / 2) + "g";
    }

    /** The machine's memory, for example {@code 7.8 GiB}. */
    public String memory() {
        return physicalMemoryBytes == 0 ? "unknown" : String.format(Locale.ROOT, "%.1f GiB", physicalMemoryBytes / (double) (1L << 30));
    }

    /** One line: {@code 2 cores (AMD EPYC 7B13), 7.8 GiB, OpenJDK ... (vendor), Linux 6.8 amd64}. */
    public String describe() {
        return cores + " cores (" + cpu + "), " + memory() + ", " + jvm + ", " + os;
    }

    private static long physicalMemory() {
        if (ManagementFactory.getOperatingSystemMXBean() instanceof com.sun.management.OperatingSystemMXBean os) {
            return os.getTotalMemorySize();
        }
        return 0;
    }

    /** The CPU's model name on Linux, else "unknown". */
    private static String cpuModel() {
        try {
            return Files.readAllLines(Path.of("/proc/cpuinfo")).stream()
                    .filter(l -> l.startsWith("model name"))
                    .map(l -> l.substring(l.indexOf(':') + 1).strip())
                    .findFirst().orElse("unknown");
        } catch (IOException | RuntimeException e) {
            return "unknown";
        }
    }
}
