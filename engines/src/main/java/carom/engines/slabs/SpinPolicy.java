package carom.engines.slabs;

import carom.core.engine.Tunable;
import carom.core.engine.RunOptions;

/**
 * How long a thread waiting at the window barrier ({@link SpinParkBarrier}) spins before it parks
 * (tunable {@code spins}). Long spins pay on large scenes with a core per domain: they span a serial
 * phase and a window's imbalance (tens of microseconds) without a park and unpark, which cost as much
 * again; at N = 1e6 on 2 cores, 2^16 spins against 2^11 took the speed-up over {@code fast} from 1.3x
 * to 1.5x. On small scenes they cost: a spinning thread holds a core that the JIT compiler needs while
 * a short run is still warming up (N = 1e4, 2 cores: 0.3 s per run against 0.06 s), so those, and
 * machines with more domains than processors, park soon.
 */
final class SpinPolicy {
    /** This machine's one-minute load average (negative where the system does not report one). */
    static double loadAverage() {
        return java.lang.management.ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage();
    }

    static final Tunable.Whole SPINS = new Tunable.Whole("spins", 1 << 11, 0, 1 << 30, "iterations",
            "busy-wait iterations at the window barrier before a thread parks",
            "2^16 from 500,000 discs when every slab has an idle processor (load average counted), else 2^11");
    static final int SPINS_LONG = 1 << 16;
    static final int SPINS_SHORT = 1 << 11;
    /** Discs from which a scene counts as large. */
    static final int LONG_SPIN_DISCS = 500_000;

    private SpinPolicy() {
    }

    /**
     * The barrier spins for a run of n discs: the {@code spins} tunable (a whole number from 0 to 2^30)
     * if given, else long spins for a large scene with an idle processor per thread, short ones
     * otherwise. Idle: the processors less the machine's load average (rounded; a negative load, where
     * the system has none, counts as 0). On a shared machine a spinning slab takes a core another
     * process wants and the run gets slower, not faster (lab note {@code slabs-speedup}).
     */
    static int spinsOf(RunOptions options, int n, int processors, double loadAverage) {
        long busy = Math.round(Math.max(0, loadAverage));
        boolean dedicated = options.threads() <= processors - busy;
        int byDefault = dedicated && n >= LONG_SPIN_DISCS ? SPINS_LONG : SPINS_SHORT;
        return SPINS.isGiven(options) ? SPINS.intOf(options) : byDefault;
    }
}
