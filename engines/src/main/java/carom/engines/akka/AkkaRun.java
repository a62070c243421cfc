package carom.engines.akka;

import carom.engines.actors.ActorCounters;
import carom.core.engine.Counter;
import carom.core.engine.Tunable;
import akka.actor.typed.ActorRef;
import akka.actor.typed.ActorSystem;
import akka.actor.typed.Behavior;
import akka.actor.typed.javadsl.AbstractBehavior;
import akka.actor.typed.javadsl.ActorContext;
import akka.actor.typed.javadsl.Behaviors;
import akka.actor.typed.javadsl.Receive;
import carom.core.BadInputException;
import carom.core.engine.RunOptions;
import carom.core.scene.Scene;
import carom.engines.actors.ActorRun;
import carom.engines.actors.BlockActor;
import carom.engines.actors.Protocol.ToCell;
import carom.engines.actors.Protocol.ToGrid;
import com.typesafe.config.Config;
import com.typesafe.config.ConfigFactory;
import java.util.Map;
import java.util.concurrent.TimeUnit;

/**
 * One run of the akka engine: an ActorSystem of its own whose guardian is the grid actor and whose
 * children are the block actors, all on one fork-join dispatcher of exactly {@code --threads}
 * threads (Akka's internal actors share it, so no other thread does work).
 */
final class AkkaRun extends ActorRun {
    /**
     * Messages an actor handles before it yields its thread (Akka's dispatcher "throughput"). 5 is
     * Akka's own default and was kept: no other value measurably beat it
     * ({@code lab/notes/jmh-thread-sweep/}).
     */
    static final int DEFAULT_THROUGHPUT = 5;
    static final Tunable.Whole THROUGHPUT = new Tunable.Whole("throughput", DEFAULT_THROUGHPUT, 1, 1_000_000, "messages",
            "messages an actor handles before it yields its thread (Akka's dispatcher throughput)");

    private final int throughput;
    private ActorSystem<ToGrid> system;
    @SuppressWarnings("unchecked")
    private final ActorRef<ToCell>[] cellRefs = new ActorRef[actors.length];
    private ActorRef<ToGrid> gridRef;

    AkkaRun(Scene scene, RunOptions options, BlockActor.FaultInjection faults) {
        super("akka", scene, options, faults);
        this.throughput = THROUGHPUT.intOf(options);
    }

    static Config config(int threads, int throughput) {
        return ConfigFactory.parseString("""
                akka {
                  loglevel = "OFF"
                  stdout-loglevel = "OFF"
                  log-dead-letters = off
                  log-dead-letters-during-shutdown = off
                  jvm-exit-on-fatal-error = off
                  jvm-shutdown-hooks = off
                  coordinated-shutdown.run-by-jvm-shutdown-hook = off
                  actor {
                    default-dispatcher {
                      executor = "fork-join-executor"
                      fork-join-executor {
                        parallelism-min = %d
                        parallelism-max = %d
                        parallelism-factor = 1.0
                      }
                      throughput = %d
                    }
                    internal-dispatcher = ${akka.actor.default-dispatcher}
                  }
                }
                """.formatted(threads, threads, throughput)).withFallback(ConfigFactory.defaultReference()).resolve();
    }

    @Override
    protected void start() {
        system = ActorSystem.create(Behaviors.setup(this::gridActor), "carom", config(threads, throughput));
    }

    private Behavior<ToGrid> gridActor(ActorContext<ToGrid> context) {
        gridRef = context.getSelf();
        for (int a = 0; a < actors.length; a++) {
            BlockActor logic = actors[a];
            cellRefs[a] = context.spawnAnonymous(Behaviors.setup(c -> new CellActor(c, logic)));
        }
        try {
            grid.start();
        } catch (RuntimeException | Error e) {
            failed("the grid actor", e);
        }
        return Behaviors.receive(ToGrid.class)
                .onMessage(ToGrid.class, m -> {
                    try {
                        grid.handle(m);
                    } catch (RuntimeException | Error e) {
                        failed("the grid actor", e);
                    }
                    return Behaviors.same();
                })
                .build();
    }

    private final class CellActor extends AbstractBehavior<ToCell> {
        private final BlockActor logic;

        CellActor(ActorContext<ToCell> context, BlockActor logic) {
            super(context);
            this.logic = logic;
        }

        @Override
        public Receive<ToCell> createReceive() {
            return newReceiveBuilder().onMessage(ToCell.class, this::onMessage).build();
        }

        private Behavior<ToCell> onMessage(ToCell message) {
            try {
                logic.handle(message);
                return this;
            } catch (RuntimeException | Error e) {
                failed(describe(logic.id), e);
                return Behaviors.stopped();
            }
        }
    }

    @Override
    public void toCell(int actor, ToCell message) {
        cellRefs[actor].tell(message);
    }

    @Override
    public void toGrid(ToGrid message) {
        gridRef.tell(message);
    }

    @Override
    protected void shutdown() {
        if (system == null) {
            return;
        }
        system.terminate();
        try {
            system.getWhenTerminated().toCompletableFuture().get(30, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (java.util.concurrent.ExecutionException | java.util.concurrent.TimeoutException e) {
            // Terminating is best effort after a failure; the run's own error is what the user sees.
        }
    }

    @Override
    protected Map<String, Long> engineCounters() {
        return Map.of(Counter.DISPATCHER_THREADS.key, (long) threads, ActorCounters.THROUGHPUT.key, (long) throughput);
    }
}
