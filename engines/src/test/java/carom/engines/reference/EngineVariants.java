package carom.engines.reference;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.Capability;
import carom.core.engine.Engine;
import carom.core.engine.RunResult;
import carom.engines.EngineCatalog;
import carom.engines.fast.FastEngine;
import carom.engines.serial.SerialEngine;
import carom.engines.slabs.SlabsEngine;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.params.provider.Arguments;

/**
 * The engines each contract runs on: every engine of the catalog whose spec the contract applies to
 * ({@link Contract#appliesTo}), as it comes, unless this table gives it variants of its own for that
 * contract (slabs on blocks or kept to windows, fast with neighbour lists, an energy audit, the values
 * of a setting that must not change the physics). An engine enrolled in the catalog therefore holds
 * every contract its spec calls for without a line here.
 *
 * <p>Engines that run on several JVMs ({@link Capability#NODES}) hold the contracts in their own test
 * classes, which start and stop the worker JVMs ({@code cluster/ClusterRestingContactTest},
 * {@code cluster/ClusterCheckpointTest}, the latter behind {@code -Pphysics}).
 */
public final class EngineVariants {
    private static final Engine FAST = new FastEngine();
    private static final Engine SERIAL = new SerialEngine();
    private static final Engine SLABS = new SlabsEngine();

    private static final List<EngineVariant> TABLE = List.of(
            EngineVariant.of(FAST).in(Contract.ANALYTIC, Contract.CHECKPOINTS, Contract.DENSE_SCENES,
                    Contract.EFFECTS_AGAINST_REFERENCE, Contract.EFFECTS, Contract.RESTING_CONTACT, Contract.SAMPLES)
                    .checkingDenseCounters(EngineVariants::fastCounters),
            // Cells, crossings and the Morton order change with cellFactor; the physics must not.
            EngineVariant.of("fast, energy audited", Tuned.of(FAST, 0, "auditEnergy", "true"))
                    .in(Contract.AGAINST_REFERENCE).sweeping("cellFactor", "1", "1.3", "2.5"),
            // Lists asked for in small dilute scenes, where they are not the default; they expire at other
            // times and hold other discs across skins, and the physics must not change.
            EngineVariant.of("fast with lists, energy audited", Tuned.of(FAST, 0, "auditEnergy", "true"))
                    .in(Contract.AGAINST_REFERENCE).sweeping("skin", "0.25", "0.1", "0.4")
                    .checkingEachRun(r -> assertThat(r.counters()).as("lists were used").containsKey("listRebuilds")),
            // Lists and their centres are saved with the records; lists need straight flight, no sliding images, no vibrated floor.
            EngineVariant.of("fast with lists", Tuned.of(FAST, 0, "skin", "0.3")).in(Contract.CHECKPOINTS)
                    .onScenes(scene -> !scene.effects().hasGravity() && !scene.box().sheared() && !scene.effects().vibratingFloor()),

            EngineVariant.of(SERIAL).sweeping("cellFactor", "2", "1.1", "3")
                    .checkingDenseCounters(r -> assertThat(r.counters().get("steps")).isPositive()),

            EngineVariant.of("slabs on 2 domains", Tuned.of(SLABS, 2)).in(Contract.ANALYTIC, Contract.EFFECTS),
            // Never merged: every contact across the slab edge goes through the windows' verification and rollback.
            EngineVariant.of("slabs on 2 domains, windows only", Tuned.of(SLABS, 2, "windowEvents", "0"))
                    .in(Contract.AGAINST_REFERENCE, Contract.EFFECTS_AGAINST_REFERENCE, Contract.RESTING_CONTACT)
                    .sweeping("cellFactor", "1", "1.3", "2.5"),
            EngineVariant.of("slabs on 2 domains, merged and split in turn", alternating(2, 8, 2))
                    .in(Contract.AGAINST_REFERENCE, Contract.EFFECTS_AGAINST_REFERENCE).sweeping("cellFactor", "1", "2.5"),
            // Contacts and migrations across horizontal edges and the corner where four domains meet.
            EngineVariant.of("slabs on 2 x 2 blocks, windows only",
                            Tuned.of(SLABS, 4, "windowEvents", "0", "domainRows", "2"))
                    .in(Contract.AGAINST_REFERENCE, Contract.EFFECTS_AGAINST_REFERENCE).sweeping("cellFactor", "1", "1.3"),
            EngineVariant.of("slabs on 2 domains, merged and split every 500 events", alternating(2, 500, 1))
                    .in(Contract.DENSE_SCENES).checkingDenseCounters(r -> {
                        assertThat(r.counters().get("domains")).isEqualTo(2);
                        assertThat(r.counters().get("resyncs")).as("clock re-anchorings").isPositive();
                        windowCounters(r);
                    }),
            EngineVariant.of("slabs on 2 x 2 blocks, merged and split every 500 events", alternating(4, 500, 2))
                    .in(Contract.DENSE_SCENES).checkingDenseCounters(r -> {
                        assertThat(r.counters().get("domains")).isEqualTo(4);
                        assertThat(r.counters().get("domainRows")).isEqualTo(2);
                        windowCounters(r);
                    }),
            // Checkpoints between windows (split at once), with the default policy, and merged throughout.
            EngineVariant.of("slabs on 2 domains, merged phases of 64 events", Tuned.of(SLABS, 2, "mergeEvents", "64"))
                    .in(Contract.CHECKPOINTS),
            // A parallel window ends at each sample time, which may move the final state by rounding.
            EngineVariant.of("slabs on 3 domains", Tuned.of(SLABS, 3)).in(Contract.CHECKPOINTS, Contract.SAMPLES)
                    .withSamplingTolerance(1e-9),
            EngineVariant.of("slabs on 1 domain", SLABS).in(Contract.CHECKPOINTS));

    private EngineVariants() {
    }

    /** The variants that run {@code contract}, in the catalog's order. */
    public static Stream<EngineVariant> of(Contract contract) {
        return EngineCatalog.all().stream().filter(e -> !e.spec().can(Capability.NODES)).flatMap(engine -> {
            List<EngineVariant> own = TABLE.stream()
                    .filter(v -> v.engine().name().equals(engine.name()) && v.contracts().contains(contract)).toList();
            return (own.isEmpty() ? List.of(EngineVariant.of(engine)) : own).stream();
        }).filter(v -> v.runs(contract));
    }

    /** Every variant with every case: (variant, case...) for each, the case's arguments after the variant. */
    public static Stream<Arguments> crossed(Stream<EngineVariant> variants, List<?> cases) {
        return variants.flatMap(v -> cases.stream().map(c -> {
            Object[] rest = c instanceof Arguments a ? a.get() : new Object[] {c};
            Object[] all = new Object[rest.length + 1];
            all[0] = v;
            System.arraycopy(rest, 0, all, 1, rest.length);
            return Arguments.of(all);
        }));
    }

    /**
     * Slabs on {@code domains} in {@code rows} rows, merged and split in turn as often as possible: every
     * merged phase ends in a try of the slabs, no window ever pays, and a merged phase is
     * {@code mergeEvents} events, doubling after each try.
     */
    private static Tuned alternating(int domains, int mergeEvents, int rows) {
        return Tuned.of(SLABS, domains, "windowEvents", Integer.toString(1 << 30), "mergeEvents",
                Integer.toString(mergeEvents), "estimateWindows", "false", "domainRows", Integer.toString(rows));
    }

    /** Several clock re-anchorings, every event counted, and the memory fast promises. */
    private static void fastCounters(RunResult r) {
        assertThat(r.counters().get("resyncs")).as("clock re-anchorings").isPositive();
        long listRebuilds = r.counters().getOrDefault("listRebuilds", 0L);
        assertThat(r.events()).isEqualTo(r.counters().get("events")).isGreaterThanOrEqualTo(
                r.collisions() + r.counters().get("cellCrossings") + listRebuilds + r.counters().get("staleEvents"));
        // Records of x, y, vx, vy and clock (radius and mass shared) and about 35 bytes of bookkeeping; with
        // neighbour lists (the default from packing fraction 0.65) a centre, a length and 8 or 16 list slots more.
        boolean lists = r.counters().containsKey("listRebuilds");
        assertThat(lists).as("lists from packing fraction 0.65 on").isEqualTo(r.counters().get("cellCrossings") == 0);
        assertThat(r.counters().get("bytesPerDisc")).as("bytes per disc").isBetween(60L, lists ? 200L : 100L);
    }

    /** Every window committed or rolled back, cross-domain work done, every event counted. */
    private static void windowCounters(RunResult r) {
        assertThat(r.counters().get("windows")).isEqualTo(r.counters().get("commits") + r.counters().get("rollbacks"));
        assertThat(r.counters().get("crossDomainEvents") + r.counters().get("migrations")).isPositive();
        assertThat(r.events()).isEqualTo(r.counters().get("events"))
                .isGreaterThanOrEqualTo(r.collisions() + r.counters().get("cellCrossings") + r.counters().get("staleEvents"));
    }
}
