package carom.app.experiment;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/** The machine an experiment ran on, as its report states it. */
record Machine(int cores, String cpu, String jvm, String os, long physicalMemoryBytes) {
    static Machine current() {
        return new Machine(Runtime.getRuntime().availableProcessors(), cpuModel(),
                System.getProperty("java.vm.name") + " " + System.getProperty("java.runtime.version")
                        + " (" + System.getProperty("java.vendor") + ")",
                System.getProperty("os.name") + " " + System.getProperty("os.version") + " " + System.getProperty("os.arch"),
                physicalMemory());
    }

    /** The one-minute load average now, NaN where the system has none (Windows). */
    static double loadAverage() {
        return ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage();
    }

    static long physicalMemory() {
        if (ManagementFactory.getOperatingSystemMXBean() instanceof com.sun.management.OperatingSystemMXBean os) {
            return os.getTotalMemorySize();
        }
        return 0;
    }

    /** Half the machine's memory, in whole GiB (at least 1): the default heap of each child JVM. */
    static String defaultHeap() {
        long gib = physicalMemory() >> 30;
        return Math.max(1, gib / 2) + "g";
    }

    /** What the report says of the machine and the run's conditions. */
    Table table(String heap, String threads, double loadBefore, double loadAfter) {
        Table t = new Table("", "this run");
        t.add("machine", cores + " cores (" + cpu + "), " + memory());
        t.add("JVM", jvm);
        t.add("OS", os);
        t.add("heap of each child JVM", "-Xmx" + heap);
        t.add("threads", threads);
        t.add("load average (1 min) before / after", Table.readable(loadBefore) + " / " + Table.readable(loadAfter));
        return t;
    }

    String memory() {
        return physicalMemoryBytes == 0 ? "unknown" : String.format(Locale.ROOT, "%.1f GiB", physicalMemoryBytes / (double) (1L << 30));
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
