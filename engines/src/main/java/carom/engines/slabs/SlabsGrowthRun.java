package carom.engines.slabs;

import carom.core.engine.Counter;
import carom.core.engine.ProgressListener;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.engine.SampleSchedule;
import carom.core.observe.Observables;
import carom.core.scene.Scene;
import carom.core.state.Discs;
import carom.engines.kernel.DiscTable;
import carom.engines.kernel.GrowthStages;
import carom.engines.kernel.KernelTunables;
import java.util.HashMap;
import java.util.Map;

/**
 * A run of the slabs engine with the growth effect: a sequence of {@link SlabsRun}s, one per stage of
 * {@link GrowthStages} (each on a table whose cells hold the discs until they outgrow them, its growth
 * anchored at the stage's start and re-anchored at each of its resyncs), stages also ending at every
 * sample time, where the thermostat rescales the kinetic energy to its initial value and the sample is
 * handed out. The same stage boundaries as {@code fast}'s {@code GrowthRun}, so the two agree to
 * rounding (until chaos amplifies it).
 */
final class SlabsGrowthRun {
    private final Scene scene;
    private final RunOptions options;
    private final double until;

    SlabsGrowthRun(Scene scene, RunOptions options) {
        this.scene = scene;
        this.options = options;
        this.until = options.until();
    }

    RunResult run() {
        Discs state = scene.newDiscs();
        GrowthStages plan = new GrowthStages(scene, state.maxRadius(), KernelTunables.growthCellFactor(options));
        SampleSchedule samples = SampleSchedule.of(scene, options);
        double energyStart = Observables.kineticEnergy(state);
        double[] momentumStart = Observables.momentum(state);
        double virialSum = 0;
        long pairs = 0;
        long walls = 0;
        long events = 0;
        long stages = 0;
        long rescalings = 0;
        double seconds = 0;
        Map<String, Long> counters = new HashMap<>();
        double epoch = 0;
        while (true) {
            if (samples.next() <= epoch) {
                // The thermostat first: a sample is the state the run goes on from, the last one the final state.
                GrowthStages.rescale(state, energyStart);
                rescalings++;
                Discs s = samples.state();
                copyInto(state, s);
                plan.grownRadii(state, s, epoch);
                samples.emit(virialSum);
                continue;
            }
            if (epoch >= until) {
                break;
            }
            DiscTable table = plan.table(state, epoch);
            double end = Math.min(Math.min(plan.end(table), samples.next()), until);
            double from = epoch;
            ProgressListener progress = t -> options.progress().simulatedTime(from + t);
            RunOptions stageOptions = RunOptions.until(end - epoch).withThreads(options.threads()).withProgress(progress).withTunables(options.tunables());
            RunResult stage = new SlabsRun(scene.withState(state).withUntil(end - epoch), stageOptions, table).run();
            stages++;
            pairs += stage.pairCollisions();
            walls += stage.wallCollisions();
            events += stage.events();
            seconds += stage.wallSeconds();
            if (stage.pressure() != null) {
                // Z N kT (2 t) over the stage gives back its virial sum, for the samples' pressure.
                virialSum += (stage.pressure().compressibility() - 1) * 2 * (end - epoch)
                        * 0.5 * (stage.kineticEnergyStart() + stage.kineticEnergyEnd());
            }
            stage.counters().forEach((key, value) -> counters.merge(key, value, Long::sum));
            if (stage.has(Counter.DOMAINS)) {
                counters.put(Counter.DOMAINS.key, stage.counter(Counter.DOMAINS, 1));
            }
            state = stage.finalState();
            epoch = end;
        }
        Discs out = state.copy();
        plan.grownRadii(state, out, until);
        counters.put(Counter.GROWTH_STAGES.key, stages);
        counters.put(Counter.RESCALINGS.key, rescalings);
        return RunResult.of("slabs", true, out, until)
                .collisions(pairs, walls)
                .events(events)
                .kineticEnergy(energyStart, Observables.kineticEnergy(out))
                .momentum(momentumStart, Observables.momentum(out))
                .wallSeconds(seconds)
                .counters(Map.copyOf(counters))
                .build();
    }

    private static void copyInto(Discs from, Discs to) {
        System.arraycopy(from.x, 0, to.x, 0, from.n);
        System.arraycopy(from.y, 0, to.y, 0, from.n);
        System.arraycopy(from.vx, 0, to.vx, 0, from.n);
        System.arraycopy(from.vy, 0, to.vy, 0, from.n);
    }
}
