package carom.engines.vthreads;

import carom.core.engine.Counter;
import carom.core.engine.RunOptions;
import carom.core.scene.Scene;
import carom.engines.actors.ActorRun;
import carom.engines.actors.BlockActor;
import carom.engines.actors.Protocol.ToCell;
import carom.engines.actors.Protocol.ToGrid;
import java.util.Map;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedTransferQueue;

/**
 * One run of the vthreads engine: the same actors as the akka engine, each a virtual thread that
 * takes messages from its own mailbox (an unbounded lock-free queue) one at a time. The JDK's
 * virtual-thread scheduler runs them on its carrier threads ({@link Carriers}).
 */
final class VThreadsRun extends ActorRun {
    private final BlockingQueue<ToCell>[] mailboxes;
    private final BlockingQueue<ToGrid> gridMailbox = new LinkedTransferQueue<>();
    private final Thread[] cellThreads;
    private Thread gridThread;
    private final int carriers;

    @SuppressWarnings("unchecked")
    VThreadsRun(Scene scene, RunOptions options, BlockActor.FaultInjection faults) {
        super("vthreads", scene, options, faults);
        this.carriers = Carriers.configure(threads);
        this.mailboxes = new BlockingQueue[actors.length];
        for (int a = 0; a < actors.length; a++) {
            mailboxes[a] = new LinkedTransferQueue<>();
        }
        this.cellThreads = new Thread[actors.length];
    }

    @Override
    protected void start() {
        Thread.Builder builder = Thread.ofVirtual();
        for (int a = 0; a < actors.length; a++) {
            BlockActor logic = actors[a];
            BlockingQueue<ToCell> mailbox = mailboxes[a];
            cellThreads[a] = builder.start(() -> {
                try {
                    while (true) {
                        logic.handle(mailbox.take());
                    }
                } catch (InterruptedException stop) {
                    // the run is over
                } catch (RuntimeException | Error e) {
                    failed(describe(logic.id), e);
                }
            });
        }
        gridThread = builder.start(() -> {
            try {
                grid.start();
                while (true) {
                    grid.handle(gridMailbox.take());
                }
            } catch (InterruptedException stop) {
                // the run is over
            } catch (RuntimeException | Error e) {
                failed("the grid actor", e);
            }
        });
    }

    @Override
    public void toCell(int actor, ToCell message) {
        mailboxes[actor].add(message);
    }

    @Override
    public void toGrid(ToGrid message) {
        gridMailbox.add(message);
    }

    /** Interrupts every actor's thread and waits for them; virtual threads never keep the JVM alive. */
    @Override
    protected void shutdown() {
        if (gridThread != null) {
            gridThread.interrupt();
        }
        for (Thread t : cellThreads) {
            if (t != null) {
                t.interrupt();
            }
        }
        long deadline = System.nanoTime() + 30_000_000_000L;
        try {
            if (gridThread != null) {
                gridThread.join(java.time.Duration.ofNanos(Math.max(1, deadline - System.nanoTime())));
            }
            for (Thread t : cellThreads) {
                if (t != null && !t.join(java.time.Duration.ofNanos(Math.max(1, deadline - System.nanoTime())))) {
                    return; // a handler that ignores interrupts: give up waiting rather than hang
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    @Override
    protected Map<String, Long> engineCounters() {
        return Map.of(Counter.CARRIER_THREADS.key, (long) carriers);
    }
}
