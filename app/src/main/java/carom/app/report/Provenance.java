package carom.app.report;

import java.util.List;
import java.util.Locale;

/**
 * What made an output: the command line as a person would type it again, and the machine it ran on,
 * one line each. {@code simulate --report} (run.json) and {@code animate} (the GIF's comment) record
 * them; {@code carom report} shows them.
 */
public final class Provenance {
    private Provenance() {
    }

    /** {@code carom ARGS...} (the whole command line, the command first), each argument quoted for a POSIX shell when it needs to be. */
    public static String commandLine(List<String> args) {
        StringBuilder sb = new StringBuilder("carom");
        for (String a : args) {
            sb.append(' ').append(a.matches("[A-Za-z0-9_./:=,+@%-]+") ? a : "'" + a.replace("'", "'\\''") + "'");
        }
        return sb.toString();
    }

    /** Cores, memory the JVM may use, JVM and OS: {@code 2 cores, max heap 5.9 GiB, OpenJDK ... 25, Linux 6.1 amd64}. */
    public static String machine() {
        Runtime rt = Runtime.getRuntime();
        return String.format(Locale.ROOT, "%d cores, max heap %.1f GiB, %s %s, %s %s %s", rt.availableProcessors(),
                rt.maxMemory() / (double) (1L << 30), System.getProperty("java.vm.name"),
                System.getProperty("java.runtime.version", System.getProperty("java.version")),
                System.getProperty("os.name"), System.getProperty("os.version"), System.getProperty("os.arch"));
    }
}
