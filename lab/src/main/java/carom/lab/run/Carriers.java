package carom.lab.run;

import java.lang.management.ManagementFactory;
import javax.management.InstanceNotFoundException;
import javax.management.JMException;
import javax.management.ObjectName;

/**
 * The virtual-thread scheduler's carrier count, which the JDK reads from {@value #PARALLELISM} once
 * per JVM, when its first virtual thread starts. That is why every vthreads measurement runs in a JVM
 * of its own: a child JVM started with {@link #option}, or a JMH fork that sets the property first.
 * The lab names the property here and nowhere else.
 */
public final class Carriers {
    /** Every scheduler setting starts with this; a child JVM inherits none of them. */
    public static final String SCHEDULER_PREFIX = "jdk.virtualThreadScheduler.";
    public static final String PARALLELISM = SCHEDULER_PREFIX + "parallelism";

    private Carriers() {
    }

    /** The JVM option that gives a new JVM {@code carriers} carrier threads. */
    public static String option(int carriers) {
        return "-D" + PARALLELISM + "=" + carriers;
    }

    /** This JVM's scheduler parallelism as the JDK reports it (24+), else the property it was created from, else 0. */
    public static int current() {
        try {
            Object value = ManagementFactory.getPlatformMBeanServer()
                    .getAttribute(new ObjectName("jdk.management:type=VirtualThreadScheduler"), "Parallelism");
            return ((Number) value).intValue();
        } catch (InstanceNotFoundException olderJdk) {
            // JDK 21 to 23 have no such MBean: the property is all there is to go by.
            String given = System.getProperty(PARALLELISM);
            return given == null ? 0 : Integer.parseInt(given.trim());
        } catch (JMException e) {
            throw new IllegalStateException("cannot read the virtual thread scheduler's parallelism", e);
        }
    }
}
