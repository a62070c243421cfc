package carom.engines.slabs;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.Engine;
import carom.core.engine.RunResult;
import carom.engines.reference.ExactEngineDenseScenesContract;

/** The dense scenes every exact engine passes, on 2 x 2 blocks merged and split in turn. */
class SlabsBlocksDenseScenesTest extends ExactEngineDenseScenesContract {
    @Override
    protected Engine engine() {
        return new FixedDomains(4, "windowEvents", Integer.toString(1 << 30), "mergeEvents", "500",
                "estimateWindows", "false", "domainRows", "2");
    }

    @Override
    protected void checkCounters(RunResult r) {
        assertThat(r.counters().get("domains")).isEqualTo(4);
        assertThat(r.counters().get("domainRows")).isEqualTo(2);
        assertThat(r.counters().get("windows")).isEqualTo(r.counters().get("commits") + r.counters().get("rollbacks"));
        assertThat(r.counters().get("crossDomainEvents") + r.counters().get("migrations")).isPositive();
        assertThat(r.events()).isEqualTo(r.counters().get("events"))
                .isGreaterThanOrEqualTo(r.collisions() + r.counters().get("cellCrossings") + r.counters().get("staleEvents"));
    }
}
