package carom.engines.slabs;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.Engine;
import carom.core.engine.RunResult;
import carom.engines.reference.ExactEngineDenseScenesContract;

/**
 * The dense scenes every exact engine passes, on two domains merged and split in turn: several
 * windows, clock re-anchorings in both phases (each domain rebases and rebuilds its own discs in its
 * own thread; merged, the whole domain all of them), counters consistent.
 */
class SlabsDenseScenesTest extends ExactEngineDenseScenesContract {
    @Override
    protected Engine engine() {
        return FixedDomains.alternating(2, 500);
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
