package carom.engines.fast;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.Engine;
import carom.core.engine.RunResult;
import carom.engines.reference.ExactEngineDenseScenesContract;

/**
 * The dense scenes every exact engine passes, on {@code fast}: several clock re-anchorings, every
 * counter consistent, and the memory it promises.
 */
class FastDenseScenesTest extends ExactEngineDenseScenesContract {
    @Override
    protected Engine engine() {
        return new FastEngine();
    }

    @Override
    protected void checkCounters(RunResult r) {
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
}
