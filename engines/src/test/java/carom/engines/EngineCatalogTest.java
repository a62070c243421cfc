package carom.engines;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import carom.core.BadInputException;
import carom.core.engine.Capability;
import carom.core.engine.Counter;
import carom.core.engine.Engine;
import carom.core.engine.EngineSpec;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.BoundaryKind;
import carom.core.scene.Effect;
import carom.core.scene.Effects;
import carom.core.scene.Scene;
import carom.core.scene.SceneBuilder;
import carom.core.scene.Species;
import carom.engines.reference.RandomScenes;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/** The catalog's engines say what they are in their specs, and their specs tell the truth. */
class EngineCatalogTest {
    /** Engines a test can run in this JVM (those on several JVMs start workers). */
    static Stream<Engine> inThisJvm() {
        return EngineCatalog.all().stream().filter(e -> !e.spec().can(Capability.NODES));
    }

    @Test
    void namesAreUniqueAndEveryEngineIsFoundByItsSpecsName() {
        List<String> names = EngineCatalog.all().stream().map(e -> e.spec().name()).toList();
        assertThat(new HashSet<>(names)).hasSameSizeAs(names);
        for (Engine e : EngineCatalog.all()) {
            assertThat(EngineCatalog.byName(e.spec().name())).isSameAs(e);
        }
    }

    @Test
    void anEffectAnEngineDoesNotSimulateIsRefusedNamingTheEnginesThatDo() {
        Scene growing = SceneBuilder.create("grow").box(10, 10, BoundaryKind.WALLS).species(Species.mobile("d", 0.5, 1))
                .disc(0, 3, 5, 1, 0).disc(0, 7, 5, -1, 0).effects(Effects.NONE.withGrowth(0.1)).until(1).build();
        List<String> growers = EngineCatalog.where(s -> s.simulates(Effect.GROWTH)).stream().map(Engine::name).toList();
        assertThat(growers).containsExactly("fast", "slabs");
        assertThatThrownBy(() -> EngineCatalog.byName("serial").checkSupports(growing)).isInstanceOf(BadInputException.class)
                .hasMessage("effects.growth: engine serial does not simulate growing discs (engines that do: fast, slabs)");
    }

    @Test
    void everyEngineSimulatesTheSharedPhysics() {
        for (Engine e : EngineCatalog.all()) {
            assertThat(e.spec().effects()).as(e.name()).containsAll(EngineSpec.SHARED_PHYSICS);
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("inThisJvm")
    void runsOnTheThreadsItsSpecSays(Engine engine) {
        assertThat(engine.threadsFor(3)).isEqualTo(engine.spec().can(Capability.THREADS) ? 3 : 1);
    }

    /** Every counter a run reports is a generic one or one its spec lists (families: messages.TYPE, slabK.NAME). */
    @ParameterizedTest(name = "{0}")
    @MethodSource("inThisJvm")
    void reportsOnlyTheCountersItsSpecDeclares(Engine engine) {
        Scene scene = RandomScenes.small(3);
        RunResult r = engine.run(scene, RunOptions.until(scene.until()).withThreads(2));
        Set<String> declared = new HashSet<>();
        Stream.concat(Counter.GENERIC.stream(), engine.spec().counters().stream()).forEach(c -> declared.add(c.key));
        for (String key : r.counters().keySet()) {
            String family = key.startsWith(Counter.MESSAGES.key + ".") ? Counter.MESSAGES.key
                    : key.matches("slab\\d+\\..*") ? key.substring(key.indexOf('.') + 1) : key;
            assertThat(declared).as("%s reports %s", engine.name(), key).contains(family);
        }
        for (Counter own : engine.spec().counters()) {
            assertThat(Counter.GENERIC).as("%s: %s is generic", engine.name(), own.key).doesNotContain(own);
        }
    }
}
