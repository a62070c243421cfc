package carom.engines.cluster;

import akka.actor.typed.ActorRef;
import com.fasterxml.jackson.annotation.JsonSubTypes;
import com.fasterxml.jackson.annotation.JsonTypeInfo;
import carom.engines.slabs.StateBatch;
import java.util.List;

/**
 * The cluster engine's messages: commands from the coordinator ({@link ClusterRun}) to the node
 * actors ({@link NodeActor}), one slab each, and their replies. A node answers every command that
 * has a {@code replyTo} exactly once, with a {@link Failed} if it could not carry it out.
 */
public final class Protocol {
    private Protocol() {
    }

    /** What a node actor handles. */
    public sealed interface NodeCommand extends ClusterMessage {
    }

    /** What a node answers. */
    public sealed interface Reply extends ClusterMessage {
    }

    /**
     * A run begins on this JVM: host {@code count} slabs, this node and {@code count - 1} actors it
     * spawns beside it (the previous run's are stopped), each a node of its own to the coordinator.
     * {@code run} is the run's secret: every later command comes sealed with it ({@link ForRun}).
     */
    public record Host(int count, long run, ActorRef<Reply> replyTo) implements NodeCommand {
    }

    /**
     * A command of run {@code run} ({@link Host}): a node carries out only the commands of the run it
     * hosts, so that a process which can reach its port but was never told the run's number cannot
     * steer it. (Its command travels with its type's name, one of the commands listed: Jackson takes no
     * other class.)
     */
    public record ForRun(long run, @JsonTypeInfo(use = JsonTypeInfo.Id.NAME, include = JsonTypeInfo.As.WRAPPER_ARRAY)
            @JsonSubTypes({@JsonSubTypes.Type(SceneStart.class), @JsonSubTypes.Type(SceneChunk.class),
                @JsonSubTypes.Type(Recover.class), @JsonSubTypes.Type(RecoverChunk.class), @JsonSubTypes.Type(Snapshot.class),
                @JsonSubTypes.Type(Start.class), @JsonSubTypes.Type(Window.class), @JsonSubTypes.Type(Undo.class),
                @JsonSubTypes.Type(Install.class), @JsonSubTypes.Type(Emigrate.class), @JsonSubTypes.Type(Replan.class),
                @JsonSubTypes.Type(SampleAt.class), @JsonSubTypes.Type(SaveState.class),
                @JsonSubTypes.Type(RestoreState.class), @JsonSubTypes.Type(Finish.class),
                @JsonSubTypes.Type(SleepersNear.class)}) NodeCommand command) implements NodeCommand {
    }

    /** The nodes a {@link Host} made ready on one JVM, the asked one first. */
    public record Hosted(int domain, List<ActorRef<NodeCommand>> nodes) implements Reply {
    }

    /** A species as the scene file gives it. */
    public record SpeciesSpec(String name, double radius, double mass, boolean fixed) {
    }

    /**
     * A run begins: this node runs slab {@code domain} of {@code domains}; the scene's discs follow
     * in {@link SceneChunk}s ({@code discs} in all), then {@link Start}.
     */
    public record SceneStart(int domain, int domains, int domainRows, double cellFactor, double until, String name, double width,
                             double height, String boundary, List<SpeciesSpec> species, double[] effects, int discs)
            implements NodeCommand {
    }

    /** Discs {@code from..} of the scene: species index and initial motion. */
    public record SceneChunk(int from, int[] species, double[] x, double[] y, double[] vx, double[] vy)
            implements NodeCommand {
    }

    /**
     * Fault recovery: this node now runs slab {@code domain} of {@code domains} from a checkpoint taken
     * at {@code epoch} (every disc's clock there); the states follow in {@link RecoverChunk}s, then
     * {@link Start}.
     */
    public record Recover(int domain, int domains, int domainRows, double epoch) implements NodeCommand {
    }

    /** Disc states of a checkpoint, every disc's (owned here or not). */
    public record RecoverChunk(StateBatch states) implements NodeCommand {
    }

    /** A command for part {@code part} of {@code parts} of a pass over every disc ({@link Snapshot}, {@link SampleAt}, {@link Finish}). */
    @FunctionalInterface
    public interface PartCommand {
        NodeCommand make(int part, int parts, ActorRef<Reply> replyTo);
    }

    /** A checkpoint's part {@code part} of {@code parts}: the slab's discs with internal ids in that share. */
    public record Snapshot(int part, int parts, ActorRef<Reply> replyTo) implements NodeCommand {
    }

    /** First predictions; the reply carries the calendar's span and the slab's edge-cell records. */
    public record Start(ActorRef<Reply> replyTo) implements NodeCommand {
    }

    /** Run a window up to local {@code end} (events at {@code end} too if {@code inclusive}). */
    public record Window(double end, boolean inclusive, ActorRef<Reply> replyTo) implements NodeCommand {
    }

    /** Undo the window back to local {@code tStar}; the violating segment's creator stands ({@code keepDisc} -1: none here). */
    public record Undo(double tStar, int keepDisc, int keepEntry, ActorRef<Reply> replyTo) implements NodeCommand {
    }

    /** Install these states (a cross-domain collision's outcome, or an immigrant) and schedule them from {@code now}. */
    public record Install(StateBatch states, double now, ActorRef<Reply> replyTo) implements NodeCommand {
    }

    /** Disc {@code disc} crosses into a foreign slab at {@code now}: let it go, send its state. */
    public record Emigrate(int disc, double now, ActorRef<Reply> replyTo) implements NodeCommand {
    }

    /** Re-anchor local time ({@code shift} becomes 0) and rebuild the calendar. */
    public record Replan(double shift, ActorRef<Reply> replyTo) implements NodeCommand {
    }

    /**
     * A sample at local {@code local} (between windows): the slab's discs with internal ids in part
     * {@code part} of {@code parts}, as {@link Sampled}.
     */
    public record SampleAt(double local, int part, int parts, ActorRef<Reply> replyTo) implements NodeCommand {
    }

    /**
     * Part {@code part} of the node's whole state for a checkpoint file (between windows; part 0 takes
     * the state, the node keeps it until the last part is sent).
     */
    public record SaveState(int part, ActorRef<Reply> replyTo) implements NodeCommand {
    }

    /**
     * Part {@code part} of {@code parts} of a state {@link SaveState} gave, for a resumed run: the node,
     * sent its scene, takes the state up with the last part (instead of {@link Start}).
     */
    public record RestoreState(int part, int parts, byte[] bytes, ActorRef<Reply> replyTo) implements NodeCommand {
    }

    /**
     * The run is over: send the final states of the slab's discs with internal ids in part {@code part}
     * of {@code parts} (each reply under Artery's frame size), and with part 0 the counters.
     */
    public record Finish(int part, int parts, ActorRef<Reply> replyTo) implements NodeCommand {
    }

    public record Started(int domain, double span, StateBatch edge) implements Reply {
    }

    /**
     * A window's outcome: where it stopped early (a migration; +Infinity if not), changed discs' records
     * and segments, and whether the slab has put discs to sleep (resting contact under gravity).
     */
    public record WindowDone(int domain, double stopTime, int stopDisc, StateBatch changed, StateBatch segments,
                             boolean sleepers) implements Reply {
    }

    /** Discs sleep somewhere in the run: from now on, crossings re-predict in full (as in {@code slabs}). */
    public record SleepersNear(ActorRef<Reply> replyTo) implements NodeCommand {
    }

    /** A {@link SleepersNear} was taken. */
    public record Told(int domain) implements Reply {
    }

    /** After an undo: the changed discs' restored records (empty if nothing was undone). */
    public record Undone(int domain, StateBatch changed) implements Reply {
    }

    /** Installed or emigrated discs' records as the node now holds them (with its predictions). */
    public record States(int domain, StateBatch states) implements Reply {
    }

    /** A checkpoint's part, with the slab's counters and pair virial sums so far. */
    public record SnapshotPart(int domain, StateBatch states, long[] counters, double[] virial) implements Reply {
    }

    public record Replanned(int domain, double span) implements Reply {
    }

    /** Final states (scene ids; x, y, vx, vy), counters ({@code SlabNode#counters}) and pair virial sums (zeros after part 0). */
    public record Finished(int domain, StateBatch finals, long[] counters, double[] virial) implements Reply {
    }

    /** A sample's part: scene ids, then x, y, vx, vy per disc; the slab's pair virial sum so far. */
    public record Sampled(int domain, StateBatch states, double virial) implements Reply {
    }

    /** A node state's part {@code bytes} of {@code parts}, and (part 0) the slab's counters ({@code SlabNode#counters}). */
    public record SavedState(int domain, int parts, byte[] bytes, long[] counters) implements Reply {
    }

    /** A part of a state was taken (with the last, the state was taken up). */
    public record Restored(int domain) implements Reply {
    }

    /** A command the node could not carry out, and why. */
    public record Failed(int domain, String message) implements Reply {
    }
}
