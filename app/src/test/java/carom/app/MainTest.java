package carom.app;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** The top-level command, {@code carom engines}, help and version. */
class MainTest {
    @Test
    void enginesListsOneLinePerEngine() {
        Cli r = Cli.run("engines");

        assertThat(r.status()).isZero();
        assertThat(r.err()).isEmpty();
        assertThat(r.out().lines()).isNotEmpty().allMatch(l -> l.matches("\\S+ (exact|relaxed) \\S.*"));
        assertThat(r.out().lines()).anyMatch(l -> l.startsWith("serial exact "));
        // The default engine comes first.
        assertThat(r.out()).startsWith("serial exact ");
    }

    @Test
    void eachEngineLineNamesTheEffectsItSimulatesBesidesTheSharedOnes() {
        Cli r = Cli.run("engines");

        assertThat(r.status()).isZero();
        java.util.Map<String, String> byName = new java.util.HashMap<>();
        r.out().lines().forEach(l -> byName.put(l.substring(0, l.indexOf(' ')), l));
        for (carom.core.engine.Engine engine : carom.engines.EngineCatalog.all()) {
            java.util.List<String> own = engine.spec().effects().stream()
                    .filter(e -> !carom.core.engine.EngineSpec.SHARED_PHYSICS.contains(e)).map(e -> e.key).toList();
            String line = byName.get(engine.name());
            if (own.isEmpty()) {
                assertThat(line).as(engine.name()).doesNotContain("(effects: ");
            } else {
                assertThat(line).as(engine.name()).contains(" (effects: " + String.join(", ", own) + ")");
            }
        }
        assertThat(byName.get("fast")).contains("(effects: growth, tangentialRestitution, vibratingFloor)");
        assertThat(byName.get("stepped")).doesNotContain("(effects: ");
    }

    @Test
    void helpAndVersionSucceed() {
        for (String flag : new String[] {"--help", "-h"}) {
            Cli r = Cli.run(flag);
            assertThat(r.status()).isZero();
            assertThat(r.out()).contains("simulate").contains("engines");
        }
        Cli simulateHelp = Cli.run("simulate", "--help");
        assertThat(simulateHelp.status()).isZero();
        assertThat(simulateHelp.out()).contains("--until").contains("--engine").contains("--out")
                .contains("--summary").contains("--threads").contains("--option");

        Cli version = Cli.run("--version");
        assertThat(version.status()).isZero();
        assertThat(version.out()).startsWith("carom ");
    }

    @Test
    void noCommandIsAUsageError() {
        Cli r = Cli.run();
        assertThat(r.status()).isEqualTo(2);
        assertThat(r.firstErrorLine()).startsWith("error: missing command");
        assertThat(r.out()).isEmpty();
    }

    @Test
    void unknownCommandIsAUsageError() {
        Cli r = Cli.run("simulat", "x.json");
        assertThat(r.status()).isEqualTo(2);
        assertThat(r.firstErrorLine()).startsWith("error: Unmatched argument");
    }
}
