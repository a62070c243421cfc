package carom.engines.slabs;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.Engine;
import carom.core.engine.RunResult;
import carom.engines.reference.ExactEngineDenseScenesContract;

/**
 * The dense scenes every exact engine passes, on two domains: several windows, clock re-anchorings
 * (each domain rebases and rebuilds its own discs in its own thread), counters consistent.
 */
class SlabsDenseScenesTest extends ExactEngineDenseScenesContract {
    @Override
    protected Engine engine() {
        return new FixedDomains(2);
    }

    @Override
    protected void checkCounters(RunResult r) {
        assertThat(r.counters().get("domains")).isEqualTo(2);
        assertThat(r.counters().get("resyncs")).as("clock re-anchorings").isPositive();
        assertThat(r.counters().get("windows")).isEqualTo(r.counters().get("commits") + r.counters().get("rollbacks"));
        assertThat(r.counters().get("crossDomainEvents") + r.counters().get("migrations")).isPositive();
        assertThat(r.events()).isEqualTo(r.counters().get("events"))
                .isGreaterThanOrEqualTo(r.collisions() + r.counters().get("cellCrossings") + r.counters().get("staleEvents"));
    }
}
