package carom.engines.actors;

import carom.engines.actors.Protocol.Minimum;
import java.util.Arrays;

/**
 * The relaxed order of the actor protocol, for one actor: what it knows of its neighbours' next event
 * times, whether its own next event may go first ({@link #isLocalMinimum}), and what it last told each
 * neighbour, so that it sends only changes ({@link #announce}).
 *
 * <p>The thesis compares with the neighbours only. With relaying, each {@link Minimum} also carries
 * the earliest event among the sender's other neighbours, so an actor sees the actors two blocks away,
 * which can touch the same discs as it does. Ties go to the lower actor id. Single writer: only its
 * actor.
 */
final class NeighbourMinimums {
    /** Delivers one minimum message to a neighbour (the actor counts and sends it). */
    @FunctionalInterface
    interface Sender {
        void send(int neighbour, Minimum message);
    }

    private final int id;
    private final int[] neighbours;
    private final boolean relay;
    private final Sender sender;
    /** Each neighbour's next event time as last reported (-Infinity: not heard this step). */
    private final double[] neighbourMin;
    /** Each neighbour's report of the earliest event among its other neighbours, with that actor's id. */
    private final double[] neighbourOthers;
    private final int[] neighbourOthersId;
    /** What was last sent to each neighbour, so that only changes are sent. */
    private final double[] sentOwn;
    private final double[] sentOthers;
    private final int[] sentOthersId;

    /**
     * @param neighbours the neighbouring actors, ascending
     * @param relay      whether minimum messages also carry the earliest event among the sender's other
     *                   neighbours
     */
    NeighbourMinimums(int id, int[] neighbours, boolean relay, Sender sender) {
        this.id = id;
        this.neighbours = neighbours;
        this.relay = relay;
        this.sender = sender;
        this.neighbourMin = new double[neighbours.length];
        this.neighbourOthers = new double[neighbours.length];
        this.neighbourOthersId = new int[neighbours.length];
        this.sentOwn = new double[neighbours.length];
        this.sentOthers = new double[neighbours.length];
        this.sentOthersId = new int[neighbours.length];
    }

    /** A new step: nothing heard from any neighbour yet, and the first announcement goes to all. */
    void beginStep() {
        Arrays.fill(neighbourMin, Double.NEGATIVE_INFINITY);
        Arrays.fill(neighbourOthers, Double.NEGATIVE_INFINITY);
        Arrays.fill(neighbourOthersId, -1);
        Arrays.fill(sentOwn, Double.NaN);
    }

    void record(Minimum m) {
        int k = Arrays.binarySearch(neighbours, m.from());
        neighbourMin[k] = m.time();
        neighbourOthers[k] = m.othersTime();
        neighbourOthersId[k] = m.othersId();
    }

    /**
     * Sends each neighbour my next event time {@code own} and, when relaying, the earliest among my
     * other neighbours'; only what changed since the last message to that neighbour.
     */
    void announce(double own) {
        int first = -1;
        int second = -1;
        for (int k = 0; k < neighbours.length; k++) {
            if (first < 0 || earlier(neighbourMin[k], neighbours[k], neighbourMin[first], neighbours[first])) {
                second = first;
                first = k;
            } else if (second < 0 || earlier(neighbourMin[k], neighbours[k], neighbourMin[second], neighbours[second])) {
                second = k;
            }
        }
        for (int k = 0; k < neighbours.length; k++) {
            int other = k == first ? second : first;
            double othersTime = relay && other >= 0 ? neighbourMin[other] : Double.POSITIVE_INFINITY;
            int othersId = relay && other >= 0 ? neighbours[other] : -1;
            if (own != sentOwn[k] || othersTime != sentOthers[k] || othersId != sentOthersId[k]) {
                sentOwn[k] = own;
                sentOthers[k] = othersTime;
                sentOthersId[k] = othersId;
                sender.send(neighbours[k], new Minimum(id, own, othersTime, othersId));
            }
        }
    }

    /**
     * Whether my next event at t comes before every event I know of nearby (an unheard neighbour counts
     * as earlier): an event of mine may touch a neighbour's disc that another neighbour of that
     * neighbour, two blocks from me, is about to touch too, so with relaying the neighbours' neighbours
     * count as well.
     */
    boolean isLocalMinimum(double t) {
        for (int k = 0; k < neighbours.length; k++) {
            if (earlier(neighbourMin[k], neighbours[k], t, id)
                    || earlier(neighbourOthers[k], neighbourOthersId[k], t, id)) {
                return false;
            }
        }
        return true;
    }

    private static boolean earlier(double t1, int id1, double t2, int id2) {
        return t1 < t2 || (t1 == t2 && id1 < id2);
    }
}
