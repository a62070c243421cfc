package carom.app;

import java.lang.management.ManagementFactory;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * The command line of a child JVM that runs part of a measurement (an experiment's engine, a study's
 * setting): this JVM's java, class path and options, minus the ones the measurement sets per child.
 *
 * <p>Why children at all: the virtual-thread scheduler reads its carrier count once per JVM, and a
 * JVM of its own keeps each engine's figures free of the others' JIT profiles, heap and leftover
 * threads.
 */
public final class ChildJava {
    private ChildJava() {
    }

    /**
     * {@code java [this JVM's inherited options] [jvmOptions] -cp [this class path] mainClass args}; the
     * caller sets the heap (else the JVM's default) and, for virtual threads, the carrier count.
     */
    public static List<String> command(List<String> jvmOptions, String mainClass, List<String> args) {
        List<String> cmd = new ArrayList<>();
        cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        for (String option : ManagementFactory.getRuntimeMXBean().getInputArguments()) {
            if (inherited(option)) {
                cmd.add(option);
            }
        }
        cmd.addAll(jvmOptions);
        cmd.add("-cp");
        cmd.add(System.getProperty("java.class.path"));
        cmd.add(mainClass);
        cmd.addAll(args);
        return cmd;
    }

    /**
     * Options of this JVM the child gets too (CAROM_JAVA_OPTS, the GC, --sun-misc-unsafe-memory-access),
     * but not the heap and carrier settings a measurement sets itself, nor debuggers, agents and
     * recordings, which would slow the child down or fight over a port.
     */
    public static boolean inherited(String option) {
        String[] notInherited = {"-Xmx", "-Xms", "-XX:MaxHeapSize", "-XX:InitialHeapSize", "-XX:MaxRAMPercentage",
            "-XX:InitialRAMPercentage", "-XX:MinRAMPercentage", "-Djdk.virtualThreadScheduler.", "-agentlib:",
            "-agentpath:", "-javaagent:", "-Xrunjdwp", "-Xdebug", "-XX:StartFlightRecording", "-XX:FlightRecorderOptions"};
        for (String prefix : notInherited) {
            if (option.startsWith(prefix)) {
                return false;
            }
        }
        return true;
    }
}
