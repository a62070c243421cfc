package carom.app.report;

import java.util.Iterator;

/**
 * The keys {@code --observe} takes, in the order the help lists them: picocli's completion candidates
 * for that option, so that its help text ({@code ${COMPLETION-CANDIDATES}}) is made from {@link ObservableCatalog}
 * rather than written out by hand.
 */
public final class ObservableKeys implements Iterable<String> {
    @Override
    public Iterator<String> iterator() {
        return ObservableCatalog.KEYS.iterator();
    }
}
